#include "scene/scene_builder.h"

#include "scene/mass_check.h"

#include <cfloat>
#include <cmath>

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

/// Stiffness and damping from RUBE's frequency and damping ratio; false (after reporting) when they overflow.
bool Stiffness(const JointModel& model, bool angular, b2Body* bodyA, b2Body* bodyB, float& stiffness,
               float& damping, DiagnosticList& diagnostics)
{
    if (angular)
    {
        b2AngularStiffness(stiffness, damping, model.frequency, model.dampingRatio, bodyA, bodyB);
    }
    else
    {
        b2LinearStiffness(stiffness, damping, model.frequency, model.dampingRatio, bodyA, bodyB);
    }
    if (!std::isfinite(stiffness) || !std::isfinite(damping))
    {
        const char* key = model.kind == JointKind::wheel ? "springFrequency" : "frequency";
        diagnostics.Add(JoinPath(model.path, key),
                        "the spring is too stiff for the masses it connects: stiffness or damping overflows");
        return false;
    }
    return true;
}

b2Joint* CreateJoint(b2World& world, const JointModel& model, const Scene& scene,
                     const std::vector<b2Joint*>& created, DiagnosticList& diagnostics)
{
    b2Body* bodyA = scene.bodies[static_cast<std::size_t>(model.bodyA)].body;
    b2Body* bodyB = scene.bodies[static_cast<std::size_t>(model.bodyB)].body;
    auto finish = [&](b2JointDef& def) -> b2Joint*
    {
        def.bodyA = bodyA;
        def.bodyB = bodyB;
        def.collideConnected = model.collideConnected;
        return world.CreateJoint(&def);
    };
    switch (model.kind)
    {
    case JointKind::revolute:
    {
        b2RevoluteJointDef def;
        def.localAnchorA = model.anchorA;
        def.localAnchorB = model.anchorB;
        def.referenceAngle = model.referenceAngle;
        def.enableLimit = model.enableLimit;
        def.lowerAngle = model.lowerLimit;
        def.upperAngle = model.upperLimit;
        def.enableMotor = model.enableMotor;
        def.motorSpeed = model.motorSpeed;
        def.maxMotorTorque = model.maxMotorTorque;
        return finish(def);
    }
    case JointKind::prismatic:
    {
        b2PrismaticJointDef def;
        def.localAnchorA = model.anchorA;
        def.localAnchorB = model.anchorB;
        def.localAxisA = model.localAxisA;
        def.referenceAngle = model.referenceAngle;
        def.enableLimit = model.enableLimit;
        def.lowerTranslation = model.lowerLimit;
        def.upperTranslation = model.upperLimit;
        def.enableMotor = model.enableMotor;
        def.motorSpeed = model.motorSpeed;
        def.maxMotorForce = model.maxMotorForce;
        return finish(def);
    }
    case JointKind::distance:
    {
        b2DistanceJointDef def;
        def.localAnchorA = model.anchorA;
        def.localAnchorB = model.anchorB;
        def.length = model.length;
        if (!Stiffness(model, false, bodyA, bodyB, def.stiffness, def.damping, diagnostics))
        {
            return nullptr;
        }
        // Box2D 2.3's distance joint was rigid at `length` unless it had a spring, which had no limits.
        if (model.frequency > 0.0f)
        {
            def.minLength = 0.0f;
            def.maxLength = FLT_MAX;
        }
        else
        {
            def.minLength = model.length;
            def.maxLength = model.length;
        }
        def.minLength = model.minLength.value_or(def.minLength);
        def.maxLength = model.maxLength.value_or(def.maxLength);
        return finish(def);
    }
    case JointKind::rope:
    {
        // Box2D 2.4 has no rope joint: a distance joint without spring, slack up to its maximum length.
        b2DistanceJointDef def;
        def.localAnchorA = model.anchorA;
        def.localAnchorB = model.anchorB;
        def.length = model.length;
        def.minLength = 0.0f;
        def.maxLength = model.length;
        def.stiffness = 0.0f;
        def.damping = 0.0f;
        return finish(def);
    }
    case JointKind::pulley:
    {
        b2PulleyJointDef def;
        def.groundAnchorA = model.groundAnchorA;
        def.groundAnchorB = model.groundAnchorB;
        def.localAnchorA = model.anchorA;
        def.localAnchorB = model.anchorB;
        def.lengthA = model.lengthA;
        def.lengthB = model.lengthB;
        def.ratio = model.ratio;
        return finish(def);
    }
    case JointKind::mouse:
    {
        b2MouseJointDef def;
        // b2dJson saves the grabbed point (world) as anchorB and the point it is pulled to as target.
        def.target = model.mouseAnchor.value_or(model.target);
        def.maxForce = model.maxForce;
        if (!Stiffness(model, false, bodyA, bodyB, def.stiffness, def.damping, diagnostics))
        {
            return nullptr;
        }
        b2Joint* joint = finish(def);
        static_cast<b2MouseJoint*>(joint)->SetTarget(model.target);
        return joint;
    }
    case JointKind::gear:
    {
        b2GearJointDef def;
        def.joint1 = created[static_cast<std::size_t>(model.joint1)];
        def.joint2 = created[static_cast<std::size_t>(model.joint2)];
        if (def.joint1 == nullptr || def.joint2 == nullptr)
        {
            return nullptr; // the problem of that joint is reported already
        }
        def.ratio = model.ratio;
        return finish(def);
    }
    case JointKind::wheel:
    {
        b2WheelJointDef def;
        def.localAnchorA = model.anchorA;
        def.localAnchorB = model.anchorB;
        def.localAxisA = model.localAxisA;
        def.enableLimit = model.enableLimit;
        def.lowerTranslation = model.lowerLimit;
        def.upperTranslation = model.upperLimit;
        def.enableMotor = model.enableMotor;
        def.motorSpeed = model.motorSpeed;
        def.maxMotorTorque = model.maxMotorTorque;
        if (!Stiffness(model, false, bodyA, bodyB, def.stiffness, def.damping, diagnostics))
        {
            return nullptr;
        }
        return finish(def);
    }
    case JointKind::weld:
    {
        b2WeldJointDef def;
        def.localAnchorA = model.anchorA;
        def.localAnchorB = model.anchorB;
        def.referenceAngle = model.referenceAngle;
        if (!Stiffness(model, true, bodyA, bodyB, def.stiffness, def.damping, diagnostics))
        {
            return nullptr;
        }
        return finish(def);
    }
    case JointKind::friction:
    {
        b2FrictionJointDef def;
        def.localAnchorA = model.anchorA;
        def.localAnchorB = model.anchorB;
        def.maxForce = model.maxForce;
        def.maxTorque = model.maxTorque;
        return finish(def);
    }
    case JointKind::motor:
    {
        b2MotorJointDef def;
        def.linearOffset = model.linearOffset;
        def.angularOffset = model.referenceAngle;
        def.maxForce = model.maxForce;
        def.maxTorque = model.maxTorque;
        def.correctionFactor = model.correctionFactor;
        return finish(def);
    }
    }
    return nullptr;
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
