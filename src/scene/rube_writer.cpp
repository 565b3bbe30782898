// SaveRubeString, SaveRubeFile: the scene's current world as RUBE JSON.
//
// Numbers are written as plain JSON numbers that read back to the same floats (not b2dJson's hex strings).
// Objects the scene knows are written in scene order with their names and custom properties; objects the
// application added to the world afterwards follow in creation order; destroyed ones are left out.
#include "contactfx/files/text_file.h"
#include "contactfx/scene/rube.h"
#include "scene/custom_properties_json.h"
#include "scene/json_writer.h"
#include "scene/rube_joints.h"

#include <algorithm>
#include <cfloat>
#include <unordered_map>
#include <unordered_set>

namespace cfx
{

namespace
{

using scene_detail::IndexPath;
using scene_detail::JoinPath;
using scene_detail::Json;

class SceneWriter
{
public:
    SceneWriter(const Scene& scene, scene_detail::DiagnosticList& diagnostics)
        : m_scene(scene), m_writer(diagnostics)
    {
    }

    Json Write();

private:
    Json Float(float value, const std::string& path) { return m_writer.Float(value, path); }
    Json Vec(b2Vec2 value, const std::string& path) { return m_writer.Vec(value, path); }

    void OrderBodies(b2World& world);
    void OrderJoints(b2World& world);
    std::vector<b2Fixture*> OrderFixtures(b2Body& body) const;

    Json WriteBody(b2Body& body, const SceneBody* entry, const std::string& path);
    Json WriteFixture(b2Fixture& fixture, const SceneFixture* entry, const std::string& path);
    Json WriteShape(const b2Shape& shape, const std::string& path, std::string& key);
    Json WriteJoint(b2Joint& joint, const SceneJoint* entry, const std::string& path);
    void WriteJointFields(const scene_detail::JointType& type, const scene_detail::JointModel& model,
                          Json& value, const std::string& path);
    Json WriteImage(const SceneImage& image, const std::string& path);

    const Scene& m_scene;
    scene_detail::JsonWriter m_writer;
    std::vector<std::pair<b2Body*, const SceneBody*>> m_bodies;
    std::unordered_map<const b2Body*, int> m_bodyIndex;
    std::unordered_map<const b2Fixture*, const SceneFixture*> m_fixtureEntries;
    std::vector<std::pair<b2Joint*, const SceneJoint*>> m_joints;
    std::unordered_map<const b2Joint*, int> m_jointIndex;
};

// Objects in file order: first those the scene remembers (in its order), then any the application
// added since, oldest first (Box2D lists the newest first). `next` walks Box2D's list; `entries` are the
// scene's records, `objectOf` gives a record's Box2D object.
template <typename T, typename Entry, typename Next, typename ObjectOf>
std::vector<std::pair<T*, const Entry*>> InFileOrder(T* first, Next next, const std::vector<Entry>& entries,
                                                     ObjectOf objectOf)
{
    std::vector<T*> listed;
    for (T* object = first; object != nullptr; object = next(object))
    {
        listed.push_back(object);
    }
    const std::unordered_set<const T*> alive(listed.begin(), listed.end());
    std::unordered_set<const T*> taken;
    std::vector<std::pair<T*, const Entry*>> ordered;
    for (const Entry& entry : entries)
    {
        T* object = objectOf(entry);
        if (object != nullptr && alive.count(object) != 0 && taken.insert(object).second)
        {
            ordered.emplace_back(object, &entry);
        }
    }
    for (auto it = listed.rbegin(); it != listed.rend(); ++it)
    {
        if (taken.insert(*it).second)
        {
            ordered.emplace_back(*it, nullptr);
        }
    }
    return ordered;
}

void SceneWriter::OrderBodies(b2World& world)
{
    m_bodies = InFileOrder(
        world.GetBodyList(), [](b2Body* body) { return body->GetNext(); }, m_scene.bodies,
        [](const SceneBody& entry) { return entry.body; });
    for (std::size_t i = 0; i < m_bodies.size(); ++i)
    {
        m_bodyIndex[m_bodies[i].first] = static_cast<int>(i);
    }
}

void SceneWriter::OrderJoints(b2World& world)
{
    m_joints = InFileOrder(
        world.GetJointList(), [](b2Joint* joint) { return joint->GetNext(); }, m_scene.joints,
        [](const SceneJoint& entry) { return entry.joint; });
    // Gear joints last, so that readers creating joints in file order find the joints a gear refers to.
    std::stable_partition(m_joints.begin(), m_joints.end(),
                          [](const auto& item) { return item.first->GetType() != e_gearJoint; });
    for (std::size_t i = 0; i < m_joints.size(); ++i)
    {
        m_jointIndex[m_joints[i].first] = static_cast<int>(i);
    }
}

std::vector<b2Fixture*> SceneWriter::OrderFixtures(b2Body& body) const
{
    // Only this body's fixtures are alive in its list, so the scene's records of others drop out. The back
    // side of a one-sided shape is not a fixture of the file: it is saved as its front's one fixture.
    std::unordered_set<const b2Fixture*> alive;
    for (const b2Fixture* fixture = body.GetFixtureList(); fixture != nullptr; fixture = fixture->GetNext())
    {
        alive.insert(fixture);
    }
    std::unordered_set<const b2Fixture*> backSides;
    for (const SceneFixture& record : m_scene.fixtures)
    {
        if (record.backSide != nullptr && alive.count(record.fixture) != 0)
        {
            backSides.insert(record.backSide);
        }
    }
    std::vector<b2Fixture*> ordered;
    for (const auto& [fixture, entry] : InFileOrder(
             body.GetFixtureList(), [](b2Fixture* fixture) { return fixture->GetNext(); }, m_scene.fixtures,
             [](const SceneFixture& record) { return record.fixture; }))
    {
        if (backSides.count(fixture) == 0)
        {
            ordered.push_back(fixture);
        }
    }
    return ordered;
}

Json SceneWriter::Write()
{
    b2World& world = *m_scene.world;
    for (const SceneFixture& entry : m_scene.fixtures)
    {
        m_fixtureEntries.emplace(entry.fixture, &entry);
    }
    OrderBodies(world);
    OrderJoints(world);

    Json root = Json::object();
    root["gravity"] = Vec(world.GetGravity(), "gravity");
    root["allowSleep"] = world.GetAllowSleeping();
    root["autoClearForces"] = world.GetAutoClearForces();
    root["warmStarting"] = world.GetWarmStarting();
    root["continuousPhysics"] = world.GetContinuousPhysics();
    root["subStepping"] = world.GetSubStepping();
    root["stepsPerSecond"] = Float(m_scene.settings.stepsPerSecond, "stepsPerSecond");
    root["velocityIterations"] = m_scene.settings.velocityIterations;
    root["positionIterations"] = m_scene.settings.positionIterations;

    Json bodies = Json::array();
    for (std::size_t i = 0; i < m_bodies.size(); ++i)
    {
        bodies.push_back(WriteBody(*m_bodies[i].first, m_bodies[i].second, IndexPath("body", i)));
    }
    root["body"] = std::move(bodies);

    Json joints = Json::array();
    for (std::size_t i = 0; i < m_joints.size(); ++i)
    {
        Json joint = WriteJoint(*m_joints[i].first, m_joints[i].second, IndexPath("joint", i));
        if (!joint.is_null())
        {
            joints.push_back(std::move(joint));
        }
    }
    root["joint"] = std::move(joints);

    Json images = Json::array();
    for (std::size_t i = 0; i < m_scene.images.size(); ++i)
    {
        images.push_back(WriteImage(m_scene.images[i], IndexPath("image", i)));
    }
    if (!images.empty())
    {
        root["image"] = std::move(images);
    }
    Json properties = scene_detail::WriteCustomProperties(m_scene.properties, m_writer, "customProperties");
    if (!properties.is_null())
    {
        root["customProperties"] = std::move(properties);
    }
    return root;
}

Json SceneWriter::WriteBody(b2Body& body, const SceneBody* entry, const std::string& path)
{
    Json value = Json::object();
    if (entry != nullptr && !entry->name.empty())
    {
        value["name"] = entry->name;
    }
    value["type"] = static_cast<int>(body.GetType());
    value["position"] = Vec(body.GetPosition(), JoinPath(path, "position"));
    value["angle"] = Float(body.GetAngle(), JoinPath(path, "angle"));
    value["linearVelocity"] = Vec(body.GetLinearVelocity(), JoinPath(path, "linearVelocity"));
    value["angularVelocity"] = Float(body.GetAngularVelocity(), JoinPath(path, "angularVelocity"));
    value["linearDamping"] = Float(body.GetLinearDamping(), JoinPath(path, "linearDamping"));
    value["angularDamping"] = Float(body.GetAngularDamping(), JoinPath(path, "angularDamping"));
    value["gravityScale"] = Float(body.GetGravityScale(), JoinPath(path, "gravityScale"));
    value["bullet"] = body.IsBullet();
    value["allowSleep"] = body.IsSleepingAllowed();
    value["awake"] = body.IsAwake();
    value["active"] = body.IsEnabled();
    value["fixedRotation"] = body.IsFixedRotation();
    if (body.GetType() == b2_dynamicBody && body.GetMass() > 0.0f)
    {
        // As b2dJson: the mass data about the body origin, applied again after the fixtures when read.
        b2MassData massData;
        body.GetMassData(&massData);
        value["massData-mass"] = Float(massData.mass, JoinPath(path, "massData-mass"));
        value["massData-center"] = Vec(massData.center, JoinPath(path, "massData-center"));
        value["massData-I"] = Float(massData.I, JoinPath(path, "massData-I"));
    }
    Json fixtures = Json::array();
    const std::vector<b2Fixture*> ordered = OrderFixtures(body);
    for (std::size_t i = 0; i < ordered.size(); ++i)
    {
        auto entryIt = m_fixtureEntries.find(ordered[i]);
        fixtures.push_back(WriteFixture(*ordered[i],
                                        entryIt == m_fixtureEntries.end() ? nullptr : entryIt->second,
                                        IndexPath(JoinPath(path, "fixture"), i)));
    }
    value["fixture"] = std::move(fixtures);
    if (entry != nullptr)
    {
        Json properties = scene_detail::WriteCustomProperties(entry->properties, m_writer,
                                                              JoinPath(path, "customProperties"));
        if (!properties.is_null())
        {
            value["customProperties"] = std::move(properties);
        }
    }
    return value;
}

Json SceneWriter::WriteFixture(b2Fixture& fixture, const SceneFixture* entry, const std::string& path)
{
    Json value = Json::object();
    if (entry != nullptr && !entry->name.empty())
    {
        value["name"] = entry->name;
    }
    value["friction"] = Float(fixture.GetFriction(), JoinPath(path, "friction"));
    value["restitution"] = Float(fixture.GetRestitution(), JoinPath(path, "restitution"));
    value["density"] = Float(fixture.GetDensity(), JoinPath(path, "density"));
    value["sensor"] = fixture.IsSensor();
    const b2Filter& filter = fixture.GetFilterData();
    value["filter-categoryBits"] = filter.categoryBits;
    value["filter-maskBits"] = filter.maskBits;
    value["filter-groupIndex"] = filter.groupIndex;
    std::string key;
    Json shape = WriteShape(*fixture.GetShape(), path, key);
    value[key] = std::move(shape);
    if (entry != nullptr)
    {
        Json properties = scene_detail::WriteCustomProperties(entry->properties, m_writer,
                                                              JoinPath(path, "customProperties"));
        if (!properties.is_null())
        {
            value["customProperties"] = std::move(properties);
        }
    }
    return value;
}

Json SceneWriter::WriteShape(const b2Shape& shape, const std::string& fixturePath, std::string& key)
{
    Json value = Json::object();
    switch (shape.GetType())
    {
    case b2Shape::e_circle:
    {
        key = "circle";
        const std::string path = JoinPath(fixturePath, key);
        const auto& circle = static_cast<const b2CircleShape&>(shape);
        value["radius"] = Float(circle.m_radius, JoinPath(path, "radius"));
        value["center"] = Vec(circle.m_p, JoinPath(path, "center"));
        break;
    }
    case b2Shape::e_polygon:
    {
        key = "polygon";
        const auto& polygon = static_cast<const b2PolygonShape&>(shape);
        value["vertices"] = m_writer.VertexList(
            std::span<const b2Vec2>(polygon.m_vertices, static_cast<std::size_t>(polygon.m_count)),
            JoinPath(JoinPath(fixturePath, key), "vertices"));
        break;
    }
    case b2Shape::e_edge:
    {
        key = "edge";
        const std::string path = JoinPath(fixturePath, key);
        const auto& edge = static_cast<const b2EdgeShape&>(shape);
        value["vertex1"] = Vec(edge.m_vertex1, JoinPath(path, "vertex1"));
        value["vertex2"] = Vec(edge.m_vertex2, JoinPath(path, "vertex2"));
        if (edge.m_oneSided)
        {
            value["hasVertex0"] = true;
            value["hasVertex3"] = true;
            value["vertex0"] = Vec(edge.m_vertex0, JoinPath(path, "vertex0"));
            value["vertex3"] = Vec(edge.m_vertex3, JoinPath(path, "vertex3"));
        }
        break;
    }
    case b2Shape::e_chain:
    {
        key = "chain";
        const std::string path = JoinPath(fixturePath, key);
        const auto& chain = static_cast<const b2ChainShape&>(shape);
        // A loop keeps its closing vertex; with the ghost vertices it reads back as the same chain.
        value["vertices"] = m_writer.VertexList(
            std::span<const b2Vec2>(chain.m_vertices, static_cast<std::size_t>(chain.m_count)),
            JoinPath(path, "vertices"));
        value["hasPrevVertex"] = true;
        value["hasNextVertex"] = true;
        value["prevVertex"] = Vec(chain.m_prevVertex, JoinPath(path, "prevVertex"));
        value["nextVertex"] = Vec(chain.m_nextVertex, JoinPath(path, "nextVertex"));
        break;
    }
    default:
        key = "circle";
        break;
    }
    return value;
}

Json SceneWriter::WriteJoint(b2Joint& joint, const SceneJoint* entry, const std::string& path)
{
    // A rope is a distance joint the scene remembers as a rope; otherwise the first type that Box2D type is.
    const bool rope = entry != nullptr && entry->type == "rope" && joint.GetType() == e_distanceJoint;
    const scene_detail::JointType* type = nullptr;
    for (const scene_detail::JointType& candidate : scene_detail::JointTypes())
    {
        if (rope ? candidate.kind == scene_detail::JointKind::rope : candidate.box2d == joint.GetType())
        {
            type = &candidate;
            break;
        }
    }
    scene_detail::JointModel model;
    if (type == nullptr || !type->extract(joint, model, scene_detail::JointExtract{m_jointIndex}))
    {
        return nullptr;
    }
    Json value = Json::object();
    value["type"] = type->name;
    if (entry != nullptr && !entry->name.empty())
    {
        value["name"] = entry->name;
    }
    value["bodyA"] = m_bodyIndex.at(joint.GetBodyA());
    value["bodyB"] = m_bodyIndex.at(joint.GetBodyB());
    value["collideConnected"] = joint.GetCollideConnected();
    WriteJointFields(*type, model, value, path);
    if (entry != nullptr)
    {
        Json properties = scene_detail::WriteCustomProperties(entry->properties, m_writer,
                                                              JoinPath(path, "customProperties"));
        if (!properties.is_null())
        {
            value["customProperties"] = std::move(properties);
        }
    }
    return value;
}

void SceneWriter::WriteJointFields(const scene_detail::JointType& type, const scene_detail::JointModel& model,
                                   Json& value, const std::string& path)
{
    for (const scene_detail::JointField& field : type.fields)
    {
        const std::string key(field.key);
        std::visit(
            [&](auto member)
            {
                using T = decltype(member);
                if constexpr (std::is_same_v<T, float scene_detail::JointModel::*>)
                {
                    value[key] = Float(model.*member, JoinPath(path, key));
                }
                else if constexpr (std::is_same_v<T, std::optional<float> scene_detail::JointModel::*>)
                {
                    if (model.*member)
                    {
                        value[key] = Float(*(model.*member), JoinPath(path, key));
                    }
                }
                else if constexpr (std::is_same_v<T, b2Vec2 scene_detail::JointModel::*>)
                {
                    value[key] = Vec(model.*member, JoinPath(path, key));
                }
                else if constexpr (std::is_same_v<T, bool scene_detail::JointModel::*> ||
                                   std::is_same_v<T, int scene_detail::JointModel::*>)
                {
                    value[key] = model.*member;
                }
                // std::monostate: a key that is read by nobody and not written
            },
            field.member);
    }
}

Json SceneWriter::WriteImage(const SceneImage& image, const std::string& path)
{
    Json value = Json::object();
    int body = -1;
    if (image.bodyIndex >= 0 && static_cast<std::size_t>(image.bodyIndex) < m_scene.bodies.size())
    {
        auto it = m_bodyIndex.find(m_scene.bodies[static_cast<std::size_t>(image.bodyIndex)].body);
        body = it == m_bodyIndex.end() ? -1 : it->second;
    }
    value["body"] = body;
    if (!image.name.empty())
    {
        value["name"] = image.name;
    }
    value["file"] = image.file;
    value["center"] = Vec(image.center, JoinPath(path, "center"));
    value["angle"] = Float(image.angle, JoinPath(path, "angle"));
    value["scale"] = Float(image.scale, JoinPath(path, "scale"));
    value["aspectScale"] = Float(image.aspectScale, JoinPath(path, "aspectScale"));
    value["flip"] = image.flip;
    value["opacity"] = Float(image.opacity, JoinPath(path, "opacity"));
    value["filter"] = image.filter;
    value["renderOrder"] = Float(image.renderOrder, JoinPath(path, "renderOrder"));
    Json tint = Json::array();
    for (float channel : image.colorTint)
    {
        tint.push_back(static_cast<int>(std::lround(std::clamp(channel, 0.0f, 1.0f) * 255.0f)));
    }
    value["colorTint"] = std::move(tint);
    value["corners"] = m_writer.VertexList(image.corners, JoinPath(path, "corners"));
    Json vertexPointer = Json::array();
    for (std::size_t i = 0; i < image.corners.size(); ++i)
    {
        vertexPointer.push_back(Float(image.corners[i].x, JoinPath(path, "corners")));
        vertexPointer.push_back(Float(image.corners[i].y, JoinPath(path, "corners")));
    }
    value["glVertexPointer"] = std::move(vertexPointer);
    Json uv = Json::array();
    for (std::size_t i = 0; i < image.uvCoords.size(); ++i)
    {
        uv.push_back(Float(image.uvCoords[i].x, IndexPath(JoinPath(path, "glTexCoordPointer"), 2 * i)));
        uv.push_back(Float(image.uvCoords[i].y, IndexPath(JoinPath(path, "glTexCoordPointer"), 2 * i + 1)));
    }
    value["glTexCoordPointer"] = std::move(uv);
    value["glDrawElements"] = image.glDrawElements;
    Json properties =
        scene_detail::WriteCustomProperties(image.properties, m_writer, JoinPath(path, "customProperties"));
    if (!properties.is_null())
    {
        value["customProperties"] = std::move(properties);
    }
    return value;
}

} // namespace

std::string SaveRubeString(const Scene& scene)
{
    if (!scene.world)
    {
        throw InputError("<api>", "world", "expected a scene with a world, found none");
    }
    scene_detail::DiagnosticList diagnostics("<api>");
    SceneWriter writer(scene, diagnostics);
    Json root = writer.Write();
    if (!diagnostics.Empty())
    {
        throw InputError(diagnostics.Take());
    }
    return root.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

void SaveRubeFile(const Scene& scene, const std::filesystem::path& path)
{
    WriteTextFileAtomically(path, SaveRubeString(scene));
}

} // namespace cfx
