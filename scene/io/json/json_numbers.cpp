#include "json_numbers.h"

#include <array>
#include <charconv>
#include <cmath>

namespace glint {

nlohmann::json jsonFloat(float f)
{
    if (!std::isfinite(f)) return nullptr;
    std::array<char, 32> text{};
    const auto written = std::to_chars(text.data(), text.data() + text.size(), f);
    double nearest = 0.0;
    std::from_chars(text.data(), written.ptr, nearest);
    return nearest;
}

nlohmann::json jsonFloats(std::span<const float> values)
{
    nlohmann::json array = nlohmann::json::array();
    for (float v : values) array.push_back(jsonFloat(v));
    return array;
}

namespace {

template <class Number>
void appendNumber(std::string& out, Number n)
{
    std::array<char, 32> text{};
    const auto written = std::to_chars(text.data(), text.data() + text.size(), n);
    out.append(text.data(), written.ptr);
}

void appendDouble(std::string& out, double d)
{
    if (!std::isfinite(d)) {
        out += "null";
        return;
    }
    // JSON readers parse "-0" as the integer 0: write every zero as "0" so a re-save is identical.
    appendNumber(out, d == 0.0 ? 0.0 : d);
}

// Invalid UTF-8 in a name must not abort a save: it becomes U+FFFD, the same on every save.
std::string escapedString(const std::string& s)
{
    return nlohmann::json(s).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

void appendNewline(std::string& out, int indent, int depth)
{
    if (indent < 0) return;
    out += '\n';
    out.append(static_cast<std::size_t>(indent) * static_cast<std::size_t>(depth), ' ');
}

void appendValue(std::string& out, const nlohmann::json& value, int indent, int depth);

void appendObject(std::string& out, const nlohmann::json& object, int indent, int depth)
{
    if (object.empty()) {
        out += "{}";
        return;
    }
    out += '{';
    bool first = true;
    for (const auto& [key, member] : object.items()) {
        if (!first) out += ',';
        first = false;
        appendNewline(out, indent, depth + 1);
        out += escapedString(key);
        out += indent < 0 ? ":" : ": ";
        appendValue(out, member, indent, depth + 1);
    }
    appendNewline(out, indent, depth);
    out += '}';
}

// Arrays of plain numbers stay on one line: accessor bounds, colours and transforms read better so.
bool isFlatArray(const nlohmann::json& array)
{
    for (const auto& element : array)
        if (element.is_structured()) return false;
    return true;
}

void appendArray(std::string& out, const nlohmann::json& array, int indent, int depth)
{
    if (array.empty()) {
        out += "[]";
        return;
    }
    const bool flat = isFlatArray(array);
    out += '[';
    bool first = true;
    for (const auto& element : array) {
        if (!first) out += flat && indent >= 0 ? ", " : ",";
        first = false;
        if (!flat) appendNewline(out, indent, depth + 1);
        appendValue(out, element, indent, depth + 1);
    }
    if (!flat) appendNewline(out, indent, depth);
    out += ']';
}

void appendValue(std::string& out, const nlohmann::json& value, int indent, int depth)
{
    switch (value.type()) {
    case nlohmann::json::value_t::object: appendObject(out, value, indent, depth); break;
    case nlohmann::json::value_t::array: appendArray(out, value, indent, depth); break;
    case nlohmann::json::value_t::number_float: appendDouble(out, value.get<double>()); break;
    case nlohmann::json::value_t::number_integer: appendNumber(out, value.get<std::int64_t>()); break;
    case nlohmann::json::value_t::number_unsigned: appendNumber(out, value.get<std::uint64_t>()); break;
    // Strings, booleans and null: nlohmann's own escaping, which does not depend on the locale.
    default: out += value.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace); break;
    }
}

} // namespace

void mergeUnknown(nlohmann::json& target, const nlohmann::json& unknown)
{
    if (!unknown.is_object() || !(target.is_object() || target.is_null())) return;
    for (const auto& [key, value] : unknown.items()) {
        auto it = target.find(key);
        if (it == target.end())
            target[key] = value;
        else if (it->is_object() && value.is_object())
            mergeUnknown(*it, value);
    }
}

std::string deterministicJsonText(const nlohmann::json& value, int indent)
{
    std::string out;
    appendValue(out, value, indent, 0);
    return out;
}

} // namespace glint
