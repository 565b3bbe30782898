#include "scene/rube_reader.h"

#include "scene/custom_properties_json.h"
#include "scene/known_keys.h"
#include "scene/polygon_check.h"
#include "scene/rube_joints.h"
#include "scene/rube_limits.h"

#include <array>
#include <cmath>
#include <string_view>
#include <utility>

namespace cfx::scene_detail
{

namespace
{

bool IsObjectElement(const Json& value, const std::string& path, DiagnosticList& diagnostics)
{
    if (!value.is_object())
    {
        diagnostics.Add(path, "expected an object, found " + Describe(value));
        return false;
    }
    return true;
}

/// A required vertex list field; nothing after reporting.
std::optional<std::vector<b2Vec2>> RequiredVertices(const ObjectReader& reader, std::string_view key)
{
    const Json* value = reader.Find(key);
    if (value == nullptr)
    {
        reader.Diagnostics().Add(reader.FieldPath(key),
                                 "expected a vertex list {\"x\": [numbers], \"y\": [numbers]}, but the field "
                                 "is missing");
        return std::nullopt;
    }
    return ReadVertexList(*value, reader.FieldPath(key), reader.Diagnostics(), kCoordinate);
}

/// A required vector field; nothing after reporting.
std::optional<b2Vec2> RequiredVec(const ObjectReader& reader, std::string_view key)
{
    const Json* value = reader.Find(key);
    if (value == nullptr)
    {
        reader.Diagnostics().Add(reader.FieldPath(key),
                                 "expected a vector ({\"x\": number, \"y\": number} or 0), but the field is "
                                 "missing");
        return std::nullopt;
    }
    return ReadVec(*value, reader.FieldPath(key), reader.Diagnostics(), kCoordinate);
}

void ReportShape(const ObjectReader& reader, std::string_view key, const std::optional<std::string>& problem)
{
    if (problem)
    {
        reader.Diagnostics().Add(reader.FieldPath(key), *problem);
    }
}

bool ReadCircle(const ObjectReader& circle, ShapeModel& shape)
{
    shape.kind = ShapeModel::Kind::circle;
    const std::size_t before = circle.Diagnostics().Size();
    const Json* radius = circle.Find("radius");
    if (radius == nullptr)
    {
        circle.Diagnostics().Add(circle.FieldPath("radius"),
                                 "expected a number > 0, but the field is missing");
    }
    else
    {
        shape.radius = ReadFloat(*radius, circle.FieldPath("radius"), circle.Diagnostics(),
                                 NumberLimits{0.0, kMaxCoordinate, true})
                           .value_or(0.0f);
    }
    shape.center = circle.Vec("center", b2Vec2(0.0f, 0.0f), kCoordinate);
    return circle.Diagnostics().Size() == before;
}

bool ReadPolygon(const ObjectReader& polygon, ShapeModel& shape)
{
    auto vertices = RequiredVertices(polygon, "vertices");
    if (!vertices)
    {
        return false;
    }
    if (vertices->size() == 2)
    {
        // RUBE saves a two-vertex polygon for what Box2D makes an edge.
        shape.kind = ShapeModel::Kind::edge;
        shape.vertex1 = (*vertices)[0];
        shape.vertex2 = (*vertices)[1];
        shape.oneSided = false;
        auto problem = CheckEdge(shape.vertex1, shape.vertex2);
        ReportShape(polygon, "vertices", problem);
        return !problem;
    }
    shape.kind = ShapeModel::Kind::polygon;
    PolygonCheck check = CheckPolygon(*vertices);
    ReportShape(polygon, "vertices", check.error);
    for (std::string& message : check.dropped)
    {
        polygon.Diagnostics().Warn(polygon.FieldPath("vertices"), std::move(message));
    }
    shape.vertices = std::move(*vertices);
    return !check.error;
}

bool ReadEdge(const ObjectReader& edge, ShapeModel& shape)
{
    shape.kind = ShapeModel::Kind::edge;
    const std::size_t before = edge.Diagnostics().Size();
    auto vertex1 = RequiredVec(edge, "vertex1");
    auto vertex2 = RequiredVec(edge, "vertex2");
    const bool hasVertex0 = edge.Bool("hasVertex0", false);
    const bool hasVertex3 = edge.Bool("hasVertex3", false);
    std::optional<b2Vec2> vertex0;
    std::optional<b2Vec2> vertex3;
    if (hasVertex0)
    {
        vertex0 = RequiredVec(edge, "vertex0");
    }
    if (hasVertex3)
    {
        vertex3 = RequiredVec(edge, "vertex3");
    }
    if (edge.Diagnostics().Size() != before || !vertex1 || !vertex2)
    {
        return false;
    }
    shape.vertex1 = *vertex1;
    shape.vertex2 = *vertex2;
    // Box2D 2.4 has no two-sided edge with ghost vertices: an edge with either ghost vertex is one-sided, and
    // a missing ghost vertex continues the edge in a straight line.
    shape.oneSided = hasVertex0 || hasVertex3;
    shape.vertex0 = vertex0.value_or(2.0f * shape.vertex1 - shape.vertex2);
    shape.vertex3 = vertex3.value_or(2.0f * shape.vertex2 - shape.vertex1);
    auto problem = CheckEdge(shape.vertex1, shape.vertex2);
    if (problem)
    {
        edge.Diagnostics().Add(edge.Path(), *problem);
    }
    return !problem;
}

bool ReadChain(const ObjectReader& chain, ShapeModel& shape, bool legacyLoop)
{
    shape.kind = ShapeModel::Kind::chain;
    const std::size_t before = chain.Diagnostics().Size();
    auto vertices = RequiredVertices(chain, "vertices");
    bool hasPrev = false;
    bool hasNext = false;
    std::optional<b2Vec2> prev;
    std::optional<b2Vec2> next;
    if (!legacyLoop)
    {
        hasPrev = chain.Bool("hasPrevVertex", false);
        hasNext = chain.Bool("hasNextVertex", false);
        if (hasPrev)
        {
            prev = RequiredVec(chain, "prevVertex");
        }
        if (hasNext)
        {
            next = RequiredVec(chain, "nextVertex");
        }
    }
    if (chain.Diagnostics().Size() != before || !vertices)
    {
        return false;
    }
    std::vector<b2Vec2>& points = *vertices;
    // A closed chain is saved with its first vertex repeated at the end; without ghost vertices it becomes a
    // Box2D loop (CreateLoop), which connects the ends smoothly.
    const bool closed = points.size() >= 4 && points.front() == points.back();
    if (!legacyLoop && !hasPrev && !hasNext && points.size() == 3 && points.front() == points.back())
    {
        chain.Diagnostics().Warn(chain.FieldPath("vertices"),
                                 "the last vertex repeats the first, but a closed chain needs 3 distinct "
                                 "vertices: loaded as an open chain of 2 edges, there and back");
    }
    if (legacyLoop || (closed && !hasPrev && !hasNext))
    {
        if (points.size() >= 2 && points.front() == points.back())
        {
            points.pop_back();
        }
        shape.loop = true;
    }
    auto problem = CheckChain(points, shape.loop);
    ReportShape(chain, "vertices", problem);
    if (problem)
    {
        return false;
    }
    if (!shape.loop)
    {
        const std::size_t n = points.size();
        shape.prevVertex = prev.value_or(2.0f * points[0] - points[1]);
        shape.nextVertex = next.value_or(2.0f * points[n - 1] - points[n - 2]);
    }
    shape.vertices = std::move(points);
    return true;
}

void ReadShape(const ObjectReader& fixture, ShapeModel& shape)
{
    static constexpr std::array<std::string_view, 5> kShapes = {"circle", "polygon", "edge", "chain", "loop"};
    std::string_view found;
    int count = 0;
    for (std::string_view key : kShapes)
    {
        if (fixture.Has(key))
        {
            if (count == 1)
            {
                fixture.Diagnostics().Add(fixture.Path(), "expected one shape, found both \"" +
                                                              std::string(found) + "\" and \"" +
                                                              std::string(key) + "\"");
            }
            if (count == 0)
            {
                found = key;
            }
            ++count;
        }
    }
    if (count == 0)
    {
        fixture.Diagnostics().Add(fixture.Path(),
                                  "expected a shape: one of \"circle\", \"polygon\", \"edge\", "
                                  "\"chain\" or \"loop\"");
        return;
    }
    if (count > 1)
    {
        return;
    }
    const Json* value = fixture.Object(found);
    if (value == nullptr)
    {
        return;
    }
    ObjectReader reader(*value, fixture.FieldPath(found), fixture.Diagnostics());
    if (found == "circle")
    {
        ReadCircle(reader, shape);
    }
    else if (found == "polygon")
    {
        ReadPolygon(reader, shape);
    }
    else if (found == "edge")
    {
        ReadEdge(reader, shape);
    }
    else
    {
        ReadChain(reader, shape, found == "loop");
    }
}

FixtureModel ReadFixture(const ObjectReader& reader)
{
    FixtureModel fixture;
    fixture.name = reader.String("name");
    // RUBE leaves out zeros: a missing friction, restitution or density is 0, not Box2D's default.
    fixture.friction = reader.Float("friction", 0.0f, kFriction);
    fixture.restitution = reader.Float("restitution", 0.0f, kRestitution);
    fixture.density = reader.Float("density", 0.0f, kDensity);
    fixture.sensor = reader.Bool("sensor", false);
    fixture.categoryBits = static_cast<std::uint16_t>(reader.Int("filter-categoryBits", 0x0001, 0, 0xFFFF));
    fixture.maskBits = static_cast<std::uint16_t>(reader.Int("filter-maskBits", 0xFFFF, 0, 0xFFFF));
    fixture.groupIndex = static_cast<std::int16_t>(reader.Int("filter-groupIndex", 0, -32768, 32767));
    ReadShape(reader, fixture.shape);
    fixture.properties = ReadCustomProperties(reader);
    return fixture;
}

BodyModel ReadBody(const ObjectReader& reader, SceneCounts& counts)
{
    BodyModel body;
    body.path = reader.Path();
    body.name = reader.String("name");
    body.type = static_cast<b2BodyType>(reader.Int("type", 0, 0, 2));
    body.position = reader.Vec("position", b2Vec2(0.0f, 0.0f), kCoordinate);
    body.angle = reader.Float("angle", 0.0f, kCoordinate);
    body.linearVelocity = reader.Vec("linearVelocity", b2Vec2(0.0f, 0.0f), kSpeed);
    body.angularVelocity = reader.Float("angularVelocity", 0.0f, kSpeed);
    body.linearDamping = reader.Float("linearDamping", 0.0f, kDamping);
    body.angularDamping = reader.Float("angularDamping", 0.0f, kDamping);
    body.gravityScale = reader.Float("gravityScale", 1.0f, kGravityScale);
    body.bullet = reader.Bool("bullet", false);
    body.allowSleep = reader.Bool("allowSleep", true);
    body.awake = reader.Bool("awake", false);
    body.enabled = reader.Bool("active", true);
    body.fixedRotation = reader.Bool("fixedRotation", false);
    if (reader.Has("massData-mass") || reader.Has("massData-center") || reader.Has("massData-I"))
    {
        b2MassData massData;
        massData.mass = reader.Float("massData-mass", 0.0f, kMass);
        massData.center = reader.Vec("massData-center", b2Vec2(0.0f, 0.0f), kCoordinate);
        massData.I = reader.Float("massData-I", 0.0f, kInertia);
        body.massData = massData;
    }
    if (const Json* fixtures = reader.Array("fixture"))
    {
        const std::string path = reader.FieldPath("fixture");
        for (std::size_t i = 0; i < fixtures->size(); ++i)
        {
            ++counts.fixtures;
            const std::string fixturePath = IndexPath(path, i);
            if (IsObjectElement((*fixtures)[i], fixturePath, reader.Diagnostics()))
            {
                body.fixtures.push_back(
                    ReadFixture(ObjectReader((*fixtures)[i], fixturePath, reader.Diagnostics())));
            }
        }
    }
    body.properties = ReadCustomProperties(reader);
    return body;
}

std::optional<int> ReadIndex(const ObjectReader& reader, std::string_view key, int count,
                             std::string_view what, bool required)
{
    const Json* value = reader.Find(key);
    const std::string path = reader.FieldPath(key);
    if (value == nullptr)
    {
        if (required)
        {
            reader.Diagnostics().Add(path, "expected the index of a " + std::string(what) +
                                               ", but the field is missing");
        }
        return std::nullopt;
    }
    if (count == 0)
    {
        reader.Diagnostics().Add(path,
                                 "expected the index of a " + std::string(what) + ", but the file has none");
        return std::nullopt;
    }
    auto index = ReadInteger(*value, path, reader.Diagnostics(), 0, count - 1);
    if (!index)
    {
        return std::nullopt;
    }
    return static_cast<int>(*index);
}

std::optional<JointModel> ReadJoint(const ObjectReader& reader, int bodyCount)
{
    JointModel joint;
    joint.path = reader.Path();
    joint.name = reader.String("name");
    const Json* type = reader.Find("type");
    std::string typeList;
    for (const JointType& entry : JointTypes())
    {
        typeList += (typeList.empty() ? "" : ", ") + std::string(entry.name);
    }
    if (type == nullptr)
    {
        reader.Diagnostics().Add(reader.FieldPath("type"),
                                 "expected a joint type (" + typeList + "), but the field is missing");
        return std::nullopt;
    }
    const JointType* jointType = nullptr;
    if (type->is_string())
    {
        joint.type = type->get<std::string>();
        jointType = FindJointType(joint.type);
    }
    if (jointType == nullptr)
    {
        reader.Diagnostics().Add(reader.FieldPath("type"),
                                 "expected a joint type (" + typeList + "), found " + Describe(*type));
        return std::nullopt;
    }
    joint.kind = jointType->kind;
    const bool gear = joint.kind == JointKind::gear;
    auto bodyA = ReadIndex(reader, "bodyA", bodyCount, "body", !gear);
    auto bodyB = ReadIndex(reader, "bodyB", bodyCount, "body", !gear);
    joint.bodyA = bodyA.value_or(-1);
    joint.bodyB = bodyB.value_or(-1);
    if (bodyA && bodyB && *bodyA == *bodyB)
    {
        reader.Diagnostics().Add(reader.FieldPath("bodyB"),
                                 "expected a body other than bodyA, found the same "
                                 "body " +
                                     std::to_string(*bodyB));
    }
    joint.collideConnected = reader.Bool("collideConnected", false);
    joint.anchorA = reader.Vec("anchorA", b2Vec2(0.0f, 0.0f), kCoordinate);
    joint.anchorB = reader.Vec("anchorB", b2Vec2(0.0f, 0.0f), kCoordinate);
    ReadJointTypeFields(reader, *jointType, joint);
    joint.properties = ReadCustomProperties(reader);
    return joint;
}

/// Gear joints refer to other joints, which must all be read first.
void CheckGear(JointModel& gear, const ObjectReader& reader,
               const std::vector<std::optional<JointModel>>& joints, const std::vector<BodyModel>& bodies,
               int selfIndex)
{
    const int count = static_cast<int>(joints.size());
    int bodyOfJoint[2] = {-1, -1};
    bool ok = true;
    for (int which = 0; which < 2; ++which)
    {
        const char* key = which == 0 ? "joint1" : "joint2";
        auto index = ReadIndex(reader, key, count, "joint", true);
        if (!index)
        {
            ok = false;
            continue;
        }
        (which == 0 ? gear.joint1 : gear.joint2) = *index;
        const std::string path = reader.FieldPath(key);
        if (*index == selfIndex)
        {
            reader.Diagnostics().Add(path, "expected another joint, found the gear joint itself");
            ok = false;
            continue;
        }
        const auto& other = joints[static_cast<std::size_t>(*index)];
        if (!other)
        {
            ok = false; // that joint's own problem is reported already
            continue;
        }
        if (other->kind != JointKind::revolute && other->kind != JointKind::prismatic)
        {
            reader.Diagnostics().Add(path, "expected a revolute or prismatic joint, found joint[" +
                                               std::to_string(*index) + "] of type \"" + other->type + "\"");
            ok = false;
            continue;
        }
        if (other->bodyB < 0)
        {
            ok = false;
            continue;
        }
        if (bodies[static_cast<std::size_t>(other->bodyB)].type != b2_dynamicBody)
        {
            reader.Diagnostics().Add(path,
                                     "expected a joint whose bodyB is dynamic (Box2D requires it), found "
                                     "joint[" +
                                         std::to_string(*index) + "] with a " +
                                         (bodies[static_cast<std::size_t>(other->bodyB)].type == b2_staticBody
                                              ? "static"
                                              : "kinematic") +
                                         " bodyB");
            ok = false;
            continue;
        }
        bodyOfJoint[which] = other->bodyB;
    }
    if (!ok)
    {
        return;
    }
    if (gear.bodyA < 0 && gear.bodyB < 0)
    {
        gear.bodyA = bodyOfJoint[0];
        gear.bodyB = bodyOfJoint[1];
        if (gear.bodyA == gear.bodyB)
        {
            reader.Diagnostics().Add(reader.Path(),
                                     "expected joint1 and joint2 to move different bodies, found "
                                     "both moving body " +
                                         std::to_string(gear.bodyA));
        }
    }
    else if (gear.bodyA < 0 || gear.bodyB < 0)
    {
        reader.Diagnostics().Add(reader.FieldPath(gear.bodyA < 0 ? "bodyA" : "bodyB"),
                                 "expected both bodyA and bodyB or neither");
    }
}

SceneImage ReadImage(const ObjectReader& reader, int bodyCount)
{
    SceneImage image;
    image.name = reader.String("name");
    image.file = reader.String("file");
    if (const Json* body = reader.Find("body"))
    {
        auto index = ReadInteger(*body, reader.FieldPath("body"), reader.Diagnostics(), -1, bodyCount - 1);
        image.bodyIndex = index ? static_cast<int>(*index) : -1;
    }
    image.center = reader.Vec("center", b2Vec2(0.0f, 0.0f), kCoordinate);
    image.angle = reader.Float("angle", 0.0f, kCoordinate);
    image.scale = reader.Float("scale", 1.0f, kImageScale);
    image.aspectScale = reader.Float("aspectScale", 1.0f, kImageScale);
    image.flip = reader.Bool("flip", false);
    image.opacity = reader.Float("opacity", 1.0f, kUnit);
    image.filter = reader.Int("filter", 1, 0, 1 << 30);
    image.renderOrder = reader.Float("renderOrder", 0.0f, kCoordinate);
    if (const Json* tint = reader.Find("colorTint"))
    {
        const std::string path = reader.FieldPath("colorTint");
        if (!tint->is_array() || tint->size() != 4)
        {
            reader.Diagnostics().Add(path,
                                     "expected [r, g, b, a] of 4 integers 0..255, found " + Describe(*tint));
        }
        else
        {
            for (std::size_t i = 0; i < 4; ++i)
            {
                auto channel = ReadInteger((*tint)[i], IndexPath(path, i), reader.Diagnostics(), 0, 255);
                image.colorTint[i] = static_cast<float>(channel.value_or(255)) / 255.0f;
            }
        }
    }
    if (const Json* corners = reader.Find("corners"))
    {
        image.corners =
            ReadVertexList(*corners, reader.FieldPath("corners"), reader.Diagnostics(), kCoordinate)
                .value_or(std::vector<b2Vec2>{});
    }
    if (const Json* uv = reader.Find("glTexCoordPointer"))
    {
        const std::string path = reader.FieldPath("glTexCoordPointer");
        auto numbers = ReadFloatArray(*uv, path, reader.Diagnostics(), kCoordinate);
        if (numbers && numbers->size() % 2 != 0)
        {
            reader.Diagnostics().Add(path, "expected an even count of numbers (u, v pairs), found " +
                                               std::to_string(numbers->size()));
        }
        else if (numbers)
        {
            for (std::size_t i = 0; i + 1 < numbers->size(); i += 2)
            {
                image.uvCoords.emplace_back((*numbers)[i], (*numbers)[i + 1]);
            }
        }
    }
    if (const Json* elements = reader.Array("glDrawElements"))
    {
        const std::string path = reader.FieldPath("glDrawElements");
        for (std::size_t i = 0; i < elements->size(); ++i)
        {
            auto index = ReadInteger((*elements)[i], IndexPath(path, i), reader.Diagnostics(), 0, 0xFFFF);
            image.glDrawElements.push_back(static_cast<int>(index.value_or(0)));
        }
    }
    image.properties = ReadCustomProperties(reader);
    return image;
}

} // namespace

RubeDocument ReadRubeDocument(const Json& root, DiagnosticList& diagnostics)
{
    RubeDocument document;
    if (!root.is_object())
    {
        diagnostics.Add("", "expected a JSON object at the top level, found " + Describe(root));
        return document;
    }
    const std::string effectsKeys = EffectsConfigKeys(root);
    if (!effectsKeys.empty() && RubeSceneKeys(root).empty())
    {
        diagnostics.Add("", "expected a RUBE scene, found an effects config (top-level " + effectsKeys +
                                "; a scene has \"body\"): load it as an effects config (contactfx: "
                                "--effects FILE)");
        return document;
    }
    WarnUnknownRubeKeys(root, diagnostics);
    ObjectReader world(root, "", diagnostics);
    // b2dJson reads a missing gravity as (0, 0); the world flags default to Box2D's.
    document.gravity = world.Vec("gravity", b2Vec2(0.0f, 0.0f), kGravity);
    WorldSettings& settings = document.settings;
    settings.allowSleep = world.Bool("allowSleep", settings.allowSleep);
    settings.autoClearForces = world.Bool("autoClearForces", settings.autoClearForces);
    settings.warmStarting = world.Bool("warmStarting", settings.warmStarting);
    settings.continuousPhysics = world.Bool("continuousPhysics", settings.continuousPhysics);
    settings.subStepping = world.Bool("subStepping", settings.subStepping);
    settings.stepsPerSecond = world.Float("stepsPerSecond", settings.stepsPerSecond, kStepRate);
    settings.velocityIterations =
        world.Int("velocityIterations", settings.velocityIterations, 0, kMaxIterations);
    settings.positionIterations =
        world.Int("positionIterations", settings.positionIterations, 0, kMaxIterations);
    document.properties = ReadCustomProperties(world);

    if (const Json* bodies = world.Array("body"))
    {
        for (std::size_t i = 0; i < bodies->size(); ++i)
        {
            ++document.counts.bodies;
            const std::string path = IndexPath("body", i);
            if (IsObjectElement((*bodies)[i], path, diagnostics))
            {
                document.bodies.push_back(
                    ReadBody(ObjectReader((*bodies)[i], path, diagnostics), document.counts));
            }
            else
            {
                document.bodies.push_back(BodyModel{}); // keeps the indices of the following bodies
            }
        }
    }
    const int bodyCount = static_cast<int>(document.bodies.size());

    if (const Json* joints = world.Array("joint"))
    {
        std::vector<std::optional<JointModel>> read(joints->size());
        for (std::size_t i = 0; i < joints->size(); ++i)
        {
            ++document.counts.joints;
            const std::string path = IndexPath("joint", i);
            if (IsObjectElement((*joints)[i], path, diagnostics))
            {
                read[i] = ReadJoint(ObjectReader((*joints)[i], path, diagnostics), bodyCount);
            }
        }
        for (std::size_t i = 0; i < read.size(); ++i)
        {
            if (read[i] && read[i]->kind == JointKind::gear)
            {
                CheckGear(*read[i], ObjectReader((*joints)[i], read[i]->path, diagnostics), read,
                          document.bodies, static_cast<int>(i));
            }
        }
        for (auto& joint : read)
        {
            document.joints.push_back(joint ? std::move(*joint) : JointModel{});
        }
    }

    if (const Json* images = world.Array("image"))
    {
        for (std::size_t i = 0; i < images->size(); ++i)
        {
            ++document.counts.images;
            const std::string path = IndexPath("image", i);
            if (IsObjectElement((*images)[i], path, diagnostics))
            {
                document.images.push_back(
                    ReadImage(ObjectReader((*images)[i], path, diagnostics), bodyCount));
            }
        }
    }
    return document;
}

} // namespace cfx::scene_detail
