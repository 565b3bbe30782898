#include "scene/custom_properties_json.h"

#include <array>
#include <limits>
#include <string_view>
#include <type_traits>

namespace cfx::scene_detail
{

namespace
{

constexpr std::array<std::string_view, 6> kTypes = {"int", "float", "string", "bool", "vec2", "color"};

std::optional<Rgba8> ReadColor(const Json& value, const std::string& path, DiagnosticList& diagnostics)
{
    if (!value.is_array() || value.size() != 4)
    {
        diagnostics.Add(path,
                        "expected a color [r, g, b, a] of 4 integers 0..255, found " +
                            (value.is_array() ? "an array of " + std::to_string(value.size()) + " values"
                                              : Describe(value)));
        return std::nullopt;
    }
    std::uint8_t channels[4] = {};
    bool ok = true;
    for (std::size_t i = 0; i < 4; ++i)
    {
        auto channel = ReadInteger(value[i], IndexPath(path, i), diagnostics, 0, 255);
        ok = ok && channel.has_value();
        channels[i] = static_cast<std::uint8_t>(channel.value_or(0));
    }
    if (!ok)
    {
        return std::nullopt;
    }
    return Rgba8{channels[0], channels[1], channels[2], channels[3]};
}

std::optional<CustomProperty> ReadProperty(const Json& value, const std::string& path,
                                           DiagnosticList& diagnostics)
{
    if (!value.is_object())
    {
        diagnostics.Add(path, "expected a custom property object, found " + Describe(value));
        return std::nullopt;
    }
    ObjectReader reader(value, path, diagnostics);
    CustomProperty property;
    property.name = reader.String("name");

    std::string_view type;
    int typeCount = 0;
    for (std::string_view candidate : kTypes)
    {
        if (reader.Has(candidate))
        {
            if (typeCount == 1)
            {
                diagnostics.Add(path, "expected one value type, found both \"" + std::string(type) +
                                          "\" and \"" + std::string(candidate) + "\"");
            }
            if (typeCount == 0)
            {
                type = candidate;
            }
            ++typeCount;
        }
    }
    if (typeCount == 0)
    {
        diagnostics.Add(path,
                        "expected a value: one of \"int\", \"float\", \"string\", \"bool\", \"vec2\" or "
                        "\"color\"");
        return std::nullopt;
    }
    if (typeCount > 1)
    {
        return std::nullopt;
    }
    const Json& field = *reader.Find(type);
    const std::string fieldPath = reader.FieldPath(type);
    if (type == "int")
    {
        auto number = ReadInteger(field, fieldPath, diagnostics, std::numeric_limits<int>::min(),
                                  std::numeric_limits<int>::max());
        if (!number)
        {
            return std::nullopt;
        }
        property.value = static_cast<int>(*number);
    }
    else if (type == "float")
    {
        auto number = ReadFloat(field, fieldPath, diagnostics);
        if (!number)
        {
            return std::nullopt;
        }
        property.value = *number;
    }
    else if (type == "string")
    {
        auto text = ReadString(field, fieldPath, diagnostics);
        if (!text)
        {
            return std::nullopt;
        }
        property.value = std::move(*text);
    }
    else if (type == "bool")
    {
        auto flag = ReadBool(field, fieldPath, diagnostics);
        if (!flag)
        {
            return std::nullopt;
        }
        property.value = *flag;
    }
    else if (type == "vec2")
    {
        auto vec = ReadVec(field, fieldPath, diagnostics);
        if (!vec)
        {
            return std::nullopt;
        }
        property.value = *vec;
    }
    else
    {
        auto color = ReadColor(field, fieldPath, diagnostics);
        if (!color)
        {
            return std::nullopt;
        }
        property.value = *color;
    }
    return property;
}

} // namespace

CustomProperties ReadCustomProperties(const ObjectReader& owner)
{
    CustomProperties properties;
    const Json* list = owner.Array("customProperties");
    if (list == nullptr)
    {
        return properties;
    }
    const std::string path = owner.FieldPath("customProperties");
    for (std::size_t i = 0; i < list->size(); ++i)
    {
        auto property = ReadProperty((*list)[i], IndexPath(path, i), owner.Diagnostics());
        if (property)
        {
            properties.items.push_back(std::move(*property));
        }
    }
    return properties;
}

Json WriteCustomProperties(const CustomProperties& properties, JsonWriter& writer, const std::string& path)
{
    if (properties.items.empty())
    {
        return nullptr;
    }
    Json list = Json::array();
    for (std::size_t i = 0; i < properties.items.size(); ++i)
    {
        const CustomProperty& property = properties.items[i];
        const std::string itemPath = IndexPath(path, i);
        Json item = Json::object();
        item["name"] = property.name;
        std::visit(
            [&](const auto& value)
            {
                using T = std::decay_t<decltype(value)>;
                if constexpr (std::is_same_v<T, int>)
                {
                    item["int"] = value;
                }
                else if constexpr (std::is_same_v<T, float>)
                {
                    item["float"] = writer.Float(value, JoinPath(itemPath, "float"));
                }
                else if constexpr (std::is_same_v<T, std::string>)
                {
                    item["string"] = value;
                }
                else if constexpr (std::is_same_v<T, bool>)
                {
                    item["bool"] = value;
                }
                else if constexpr (std::is_same_v<T, b2Vec2>)
                {
                    item["vec2"] = writer.Vec(value, JoinPath(itemPath, "vec2"));
                }
                else
                {
                    item["color"] = Json::array({value.r, value.g, value.b, value.a});
                }
            },
            property.value);
        list.push_back(std::move(item));
    }
    return list;
}

} // namespace cfx::scene_detail
