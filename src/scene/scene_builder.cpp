#include "scene/scene_builder.h"

#include "scene/mass_check.h"
#include "scene/rube_joints.h"

#include <algorithm>
#include <vector>

namespace cfx::scene_detail
{

namespace
{

// The shape of a fixture as Box2D 2.4 takes it, for `side`: the file's own side, or the back side of a
// one-sided shape (its vertices reversed, so that it collides on the other side). Returns false when the
// shape has no back side (it is two-sided).
bool MakeShape(const ShapeModel& shape, bool back, b2CircleShape& circle, b2PolygonShape& polygon,
               b2EdgeShape& edge, b2ChainShape& chain, const b2Shape*& made)
{
    switch (shape.kind)
    {
    case ShapeModel::Kind::circle:
        if (back)
        {
            return false;
        }
        circle.m_radius = shape.radius;
        circle.m_p = shape.center;
        made = &circle;
        return true;
    case ShapeModel::Kind::polygon:
        if (back)
        {
            return false;
        }
        polygon.Set(shape.vertices.data(), static_cast<int32>(shape.vertices.size()));
        made = &polygon;
        return true;
    case ShapeModel::Kind::edge:
        if (!shape.oneSided)
        {
            if (back)
            {
                return false;
            }
            edge.SetTwoSided(shape.vertex1, shape.vertex2);
        }
        else if (back)
        {
            edge.SetOneSided(shape.vertex3, shape.vertex2, shape.vertex1, shape.vertex0);
        }
        else
        {
            edge.SetOneSided(shape.vertex0, shape.vertex1, shape.vertex2, shape.vertex3);
        }
        made = &edge;
        return true;
    case ShapeModel::Kind::chain:
    {
        std::vector<b2Vec2> vertices = shape.vertices;
        if (back)
        {
            std::reverse(vertices.begin(), vertices.end());
        }
        const auto count = static_cast<int32>(vertices.size());
        if (shape.loop)
        {
            chain.CreateLoop(vertices.data(), count);
        }
        else if (back)
        {
            chain.CreateChain(vertices.data(), count, shape.nextVertex, shape.prevVertex);
        }
        else
        {
            chain.CreateChain(vertices.data(), count, shape.prevVertex, shape.nextVertex);
        }
        made = &chain;
        return true;
    }
    }
    return false;
}

// The fixture, and for a one-sided shape (a chain, an edge with ghost vertices) its back side: RUBE
// scenes are Box2D 2.3 scenes, where chains and edges collide on both sides whatever their winding, while
// Box2D 2.4 makes them one-sided. The pair of opposite one-sided shapes collides on both sides, and
// smoothly on both (a two-sided 2.4 edge would snag on the inner vertices).
SceneFixture CreateFixture(b2Body& body, int bodyIndex, const FixtureModel& model)
{
    b2FixtureDef def;
    def.friction = model.friction;
    def.restitution = model.restitution;
    // The density is set after all fixtures exist, so that Box2D updates the mass once, after it is checked.
    def.density = 0.0f;
    def.isSensor = model.sensor;
    def.filter.categoryBits = model.categoryBits;
    def.filter.maskBits = model.maskBits;
    def.filter.groupIndex = model.groupIndex;

    SceneFixture created{nullptr, nullptr, bodyIndex, model.name, model.properties};
    for (const bool back : {false, true})
    {
        b2CircleShape circle;
        b2PolygonShape polygon;
        b2EdgeShape edge;
        b2ChainShape chain;
        const b2Shape* shape = nullptr;
        if (MakeShape(model.shape, back, circle, polygon, edge, chain, shape))
        {
            def.shape = shape;
            (back ? created.backSide : created.fixture) = body.CreateFixture(&def);
        }
    }
    return created;
}

void SetUpMass(b2Body& body, const BodyModel& model, DiagnosticList& diagnostics)
{
    if (model.type != b2_dynamicBody)
    {
        return;
    }
    if (model.massData)
    {
        // RUBE saves the mass it computed; b2dJson applies it after the fixtures.
        if (auto problem = CheckSetMassData(body, *model.massData))
        {
            diagnostics.Add(JoinPath(model.path, "massData-I"), *problem);
            return;
        }
        body.SetMassData(&*model.massData);
        return;
    }
    if (auto problem = CheckResetMassData(body))
    {
        diagnostics.Add(JoinPath(model.path, "fixture"), *problem);
        return;
    }
    body.ResetMassData();
    if (body.GetMass() == 0.0f)
    {
        // Box2D 2.3, whose scenes RUBE saves, gives a dynamic body without mass a mass of 1 at its origin
        // (and no rotational inertia); 2.4.1 leaves it at 0, where gravity does not move it.
        const b2MassData unit{1.0f, b2Vec2(0.0f, 0.0f), 0.0f};
        body.SetMassData(&unit);
    }
}

b2Body* CreateBody(b2World& world, const BodyModel& model, Scene& scene, DiagnosticList& diagnostics)
{
    b2BodyDef def;
    def.type = model.type;
    def.position = model.position;
    def.angle = model.angle;
    def.linearVelocity = model.linearVelocity;
    def.angularVelocity = model.angularVelocity;
    def.linearDamping = model.linearDamping;
    def.angularDamping = model.angularDamping;
    def.gravityScale = model.gravityScale;
    def.bullet = model.bullet;
    def.allowSleep = model.allowSleep;
    def.awake = model.awake;
    def.enabled = model.enabled;
    def.fixedRotation = model.fixedRotation;
    b2Body* body = world.CreateBody(&def);

    const int bodyIndex = static_cast<int>(scene.bodies.size());
    scene.bodies.push_back(SceneBody{body, model.name, model.properties});
    const std::size_t first = scene.fixtures.size();
    for (const FixtureModel& fixtureModel : model.fixtures)
    {
        scene.fixtures.push_back(CreateFixture(*body, bodyIndex, fixtureModel));
    }
    for (std::size_t i = 0; i < model.fixtures.size(); ++i)
    {
        const SceneFixture& created = scene.fixtures[first + i];
        created.fixture->SetDensity(model.fixtures[i].density);
        if (created.backSide != nullptr)
        {
            created.backSide->SetDensity(model.fixtures[i].density);
        }
    }
    SetUpMass(*body, model, diagnostics);
    // RUBE's velocity is the velocity of the centre of mass, which moved with the mass update: set it again.
    if (body->IsAwake())
    {
        body->SetLinearVelocity(model.linearVelocity);
        body->SetAngularVelocity(model.angularVelocity);
    }
    return body;
}

b2Joint* CreateJoint(b2World& world, const JointModel& model, const Scene& scene,
                     const std::vector<b2Joint*>& created, DiagnosticList& diagnostics)
{
    JointBuild context{world, scene.bodies[static_cast<std::size_t>(model.bodyA)].body,
                       scene.bodies[static_cast<std::size_t>(model.bodyB)].body, created, diagnostics};
    const JointType& type = JointTypeOf(model.kind);
    return type.build(model, type, context);
}

} // namespace

Scene BuildScene(const RubeDocument& document, DiagnosticList& diagnostics)
{
    Scene scene;
    scene.settings = document.settings;
    scene.properties = document.properties;
    scene.world = std::make_unique<b2World>(document.gravity);
    b2World& world = *scene.world;
    world.SetAllowSleeping(document.settings.allowSleep);
    world.SetAutoClearForces(document.settings.autoClearForces);
    world.SetWarmStarting(document.settings.warmStarting);
    world.SetContinuousPhysics(document.settings.continuousPhysics);
    world.SetSubStepping(document.settings.subStepping);

    scene.bodies.reserve(document.bodies.size());
    for (const BodyModel& body : document.bodies)
    {
        CreateBody(world, body, scene, diagnostics);
    }

    // Gear joints refer to other joints: create them last.
    std::vector<b2Joint*> created(document.joints.size(), nullptr);
    for (bool gears : {false, true})
    {
        for (std::size_t i = 0; i < document.joints.size(); ++i)
        {
            const JointModel& joint = document.joints[i];
            if ((joint.kind == JointKind::gear) == gears)
            {
                created[i] = CreateJoint(world, joint, scene, created, diagnostics);
            }
        }
    }
    for (std::size_t i = 0; i < document.joints.size(); ++i)
    {
        const JointModel& joint = document.joints[i];
        scene.joints.push_back(SceneJoint{created[i], joint.name, joint.type, joint.properties});
    }
    scene.images = document.images;
    return scene;
}

} // namespace cfx::scene_detail
