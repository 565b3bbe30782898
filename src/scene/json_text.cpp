#include "scene/json_text.h"

#include <string>
#include <utility>
#include <vector>

namespace cfx::scene_detail
{

namespace
{

/// Builds the document like nlohmann's own DOM parser, but keeps the position of a parse error (nlohmann's
/// exceptions for number overflow carry none) and reports a key repeated in one object under its JSON path
/// (nlohmann keeps the last value: the first would silently do nothing).
class DomBuilder
{
public:
    DomBuilder(Json& root, DiagnosticList& diagnostics) : m_root(root), m_diagnostics(diagnostics) {}

    bool null() { return Put(Json(nullptr)); }
    bool boolean(bool value) { return Put(Json(value)); }
    bool number_integer(Json::number_integer_t value) { return Put(Json(value)); }
    bool number_unsigned(Json::number_unsigned_t value) { return Put(Json(value)); }
    bool number_float(Json::number_float_t value, const Json::string_t&) { return Put(Json(value)); }
    bool string(Json::string_t& value) { return Put(Json(std::move(value))); }
    bool binary(Json::binary_t& value) { return Put(Json::binary(std::move(value))); }

    bool start_object(std::size_t)
    {
        Open(Json(Json::value_t::object));
        return true;
    }
    bool key(Json::string_t& name)
    {
        if (m_stack.back().node->contains(name))
        {
            m_diagnostics.Add(JoinPath(PathOfOpen(), name),
                              "duplicate key \"" + name + "\": each key may appear once in an object");
        }
        m_key = std::move(name);
        return true;
    }
    bool end_object()
    {
        m_stack.pop_back();
        return true;
    }
    bool start_array(std::size_t)
    {
        Open(Json(Json::value_t::array));
        return true;
    }
    bool end_array()
    {
        m_stack.pop_back();
        return true;
    }

    template <class Exception>
    bool parse_error(std::size_t position, const std::string&, const Exception& error)
    {
        m_failed = true;
        m_position = position;
        m_message = error.what();
        return false;
    }

    bool Failed() const { return m_failed; }
    std::size_t Position() const { return m_position; }
    const std::string& Message() const { return m_message; }

private:
    bool Put(Json value)
    {
        Insert(std::move(value));
        return true;
    }

    // An object or array being filled, and where it is in its parent: the key, or the index when the parent
    // is an array (the paths are only built for a message).
    struct OpenContainer
    {
        Json* node = nullptr;
        std::string key;
        std::size_t index = 0;
    };

    void Open(Json container)
    {
        OpenContainer open;
        if (!m_stack.empty())
        {
            if (m_stack.back().node->is_array())
            {
                open.index = m_stack.back().node->size();
            }
            else
            {
                open.key = m_key;
            }
        }
        open.node = Insert(std::move(container));
        m_stack.push_back(std::move(open));
    }

    // The JSON path of the innermost open container ("" for the root).
    std::string PathOfOpen() const
    {
        std::string path;
        for (std::size_t level = 1; level < m_stack.size(); ++level)
        {
            path = m_stack[level - 1].node->is_array() ? IndexPath(path, m_stack[level].index)
                                                       : JoinPath(path, m_stack[level].key);
        }
        return path;
    }

    Json* Insert(Json value)
    {
        if (m_stack.empty())
        {
            m_root = std::move(value);
            return &m_root;
        }
        Json& container = *m_stack.back().node;
        if (container.is_array())
        {
            container.push_back(std::move(value));
            return &container.back();
        }
        Json& slot = container[m_key];
        slot = std::move(value);
        return &slot;
    }

    Json& m_root;
    DiagnosticList& m_diagnostics;
    std::vector<OpenContainer> m_stack;
    std::string m_key;
    bool m_failed = false;
    std::size_t m_position = 0;
    std::string m_message;
};

/// "[json.exception.parse_error.101] parse error at line 1, column 2: syntax error ..." -> "syntax error
/// ...".
std::string CleanMessage(const std::string& message)
{
    std::string text = message;
    if (!text.empty() && text.front() == '[')
    {
        auto end = text.find("] ");
        if (end != std::string::npos)
        {
            text.erase(0, end + 2);
        }
    }
    if (text.rfind("parse error", 0) == 0)
    {
        auto colon = text.find(": ");
        if (colon != std::string::npos)
        {
            text.erase(0, colon + 2);
        }
    }
    return text;
}

} // namespace

TextPosition PositionOfOffset(std::string_view text, std::size_t offset)
{
    if (offset > text.size())
    {
        offset = text.size();
    }
    TextPosition position;
    std::size_t lineStart = 0;
    for (std::size_t i = 0; i < offset; ++i)
    {
        if (text[i] == '\n')
        {
            ++position.line;
            lineStart = i + 1;
        }
    }
    position.column = static_cast<int>(offset - lineStart) + 1;
    return position;
}

std::optional<Json> ParseJsonText(std::string_view text, DiagnosticList& diagnostics)
{
    // nlohmann stops at a NUL byte as at the end of a C string; JSON text has none.
    if (const std::size_t nul = text.find('\0'); nul != std::string_view::npos)
    {
        const TextPosition position = PositionOfOffset(text, nul);
        diagnostics.AddAt(position.line, position.column, "malformed JSON: NUL byte");
        return std::nullopt;
    }
    Json root;
    DomBuilder builder(root, diagnostics);
    bool ok = false;
    try
    {
        ok = Json::sax_parse(text.begin(), text.end(), &builder);
    }
    catch (const Json::exception& error)
    {
        diagnostics.Add("", "malformed JSON: " + CleanMessage(error.what()));
        return std::nullopt;
    }
    if (!ok || builder.Failed())
    {
        // nlohmann counts the bytes read, the offending one included.
        const std::size_t offset = builder.Position() > 0 ? builder.Position() - 1 : 0;
        const TextPosition position = PositionOfOffset(text, offset);
        diagnostics.AddAt(position.line, position.column,
                          "malformed JSON: " + CleanMessage(builder.Message()));
        return std::nullopt;
    }
    return root;
}

} // namespace cfx::scene_detail
