// Lookups by name and by Box2D object.
#include "contactfx/scene/rube.h"

#include <algorithm>

namespace cfx
{

namespace
{

template <class Item> const Item* FirstNamed(const std::vector<Item>& items, std::string_view name)
{
    auto it = std::find_if(items.begin(), items.end(), [&](const Item& item) { return item.name == name; });
    return it == items.end() ? nullptr : &*it;
}

} // namespace

const CustomProperty* CustomProperties::Find(std::string_view name) const
{
    return FirstNamed(items, name);
}

const std::string* CustomProperties::FindString(std::string_view name) const
{
    const CustomProperty* property = Find(name);
    return property == nullptr ? nullptr : std::get_if<std::string>(&property->value);
}

const SceneBody* Scene::FindBody(std::string_view name) const
{
    return FirstNamed(bodies, name);
}

const SceneFixture* Scene::FindFixture(std::string_view name) const
{
    return FirstNamed(fixtures, name);
}

const SceneJoint* Scene::FindJoint(std::string_view name) const
{
    return FirstNamed(joints, name);
}

const SceneImage* Scene::FindImage(std::string_view name) const
{
    return FirstNamed(images, name);
}

const SceneFixture* Scene::FindFixture(const b2Fixture* fixture) const
{
    auto it = std::find_if(fixtures.begin(), fixtures.end(),
                           [&](const SceneFixture& item)
                           { return item.fixture == fixture || item.backSide == fixture; });
    return fixture == nullptr || it == fixtures.end() ? nullptr : &*it;
}

const SceneBody* Scene::FindBody(const b2Body* body) const
{
    auto it =
        std::find_if(bodies.begin(), bodies.end(), [&](const SceneBody& item) { return item.body == body; });
    return body == nullptr || it == bodies.end() ? nullptr : &*it;
}

const SceneJoint* Scene::FindJoint(const b2Joint* joint) const
{
    auto it = std::find_if(joints.begin(), joints.end(),
                           [&](const SceneJoint& item) { return item.joint == joint; });
    return joint == nullptr || it == joints.end() ? nullptr : &*it;
}

} // namespace cfx
