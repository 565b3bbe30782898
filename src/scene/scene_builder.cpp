#include "scene/scene_builder.h"

#include "scene/mass_check.h"
#include "scene/rube_joints.h"

namespace cfx::scene_detail
{

namespace
{

b2Fixture* CreateFixture(b2Body& body, const FixtureModel& model)
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

    const ShapeModel& shape = model.shape;
    b2Fixture* fixture = nullptr;
    switch (shape.kind)
    {
    case ShapeModel::Kind::circle:
    {
        b2CircleShape circle;
        circle.m_radius = shape.radius;
        circle.m_p = shape.center;
        def.shape = &circle;
        fixture = body.CreateFixture(&def);
        break;
    }
    case ShapeModel::Kind::polygon:
    {
        b2PolygonShape polygon;
        polygon.Set(shape.vertices.data(), static_cast<int32>(shape.vertices.size()));
        def.shape = &polygon;
        fixture = body.CreateFixture(&def);
        break;
    }
    case ShapeModel::Kind::edge:
    {
        b2EdgeShape edge;
        if (shape.oneSided)
        {
            edge.SetOneSided(shape.vertex0, shape.vertex1, shape.vertex2, shape.vertex3);
        }
        else
        {
            edge.SetTwoSided(shape.vertex1, shape.vertex2);
        }
        def.shape = &edge;
        fixture = body.CreateFixture(&def);
        break;
    }
    case ShapeModel::Kind::chain:
    {
        b2ChainShape chain;
        const auto count = static_cast<int32>(shape.vertices.size());
        if (shape.loop)
        {
            chain.CreateLoop(shape.vertices.data(), count);
        }
        else
        {
            chain.CreateChain(shape.vertices.data(), count, shape.prevVertex, shape.nextVertex);
        }
        def.shape = &chain;
        fixture = body.CreateFixture(&def);
        break;
    }
    }
    return fixture;
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
    std::vector<b2Fixture*> created;
    for (const FixtureModel& fixtureModel : model.fixtures)
    {
        b2Fixture* fixture = CreateFixture(*body, fixtureModel);
        created.push_back(fixture);
        scene.fixtures.push_back(
            SceneFixture{fixture, bodyIndex, fixtureModel.name, fixtureModel.properties});
    }
    for (std::size_t i = 0; i < created.size(); ++i)
    {
        created[i]->SetDensity(model.fixtures[i].density);
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
