#include "gltf_read_json.h"

#include "scene/core/diagnostics.h"

#include <charconv>
#include <cmath>
#include <limits>

namespace glint {

namespace {

std::string at(const std::string& where, const char* key) { return where + "." + key; }

template <int N>
glm::vec<N, float> floats(const JsonReader& r, const Json& object, const char* key, glm::vec<N, float> fallback, const std::string& where)
{
    const Json* value = r.member(object, key);
    if (!value) return fallback;
    if (!value->is_array() || value->size() != N) r.wrongType(where, key, ("an array of " + std::to_string(N) + " numbers").c_str());
    glm::vec<N, float> out;
    for (int i = 0; i < N; ++i) {
        const Json& item = (*value)[static_cast<std::size_t>(i)];
        if (!item.is_number()) r.wrongType(where, key, ("an array of " + std::to_string(N) + " numbers").c_str());
        out[i] = finiteFloat(item.get<double>(), r.file, at(where, key));
    }
    return out;
}

} // namespace

const Json* JsonReader::member(const Json& object, const char* key) const
{
    if (!object.is_object()) return nullptr;
    auto it = object.find(key);
    return it == object.end() ? nullptr : &*it;
}

const Json& JsonReader::objectAt(const Json& parent, const char* key, std::size_t index, const std::string& where) const
{
    const Json& item = parent.at(key).at(index);
    if (!item.is_object()) throw FileError(file, "wrong-type", where + " must be an object");
    return item;
}

void JsonReader::wrongType(const std::string& where, const char* key, const char* expected) const
{
    throw FileError(file, "wrong-type", at(where, key) + " must be " + expected);
}

double JsonReader::number64(const Json& object, const char* key, double fallback, const std::string& where) const
{
    const Json* value = member(object, key);
    if (!value) return fallback;
    if (!value->is_number()) wrongType(where, key, "a number");
    return value->get<double>();
}

float JsonReader::number(const Json& object, const char* key, float fallback, const std::string& where) const
{
    const Json* value = member(object, key);
    if (!value) return fallback;
    if (!value->is_number()) wrongType(where, key, "a number");
    return finiteFloat(value->get<double>(), file, at(where, key));
}

int JsonReader::index(const Json& object, const char* key, const std::string& where) const
{
    const Json* value = member(object, key);
    if (!value) return -1;
    if (!value->is_number_unsigned() || value->get<std::uint64_t>() > static_cast<std::uint64_t>(std::numeric_limits<int>::max()))
        wrongType(where, key, "an index (a non-negative integer)");
    return value->get<int>();
}

std::uint64_t JsonReader::unsignedNumber(const Json& object, const char* key, std::uint64_t fallback, const std::string& where) const
{
    const Json* value = member(object, key);
    if (!value) return fallback;
    if (!value->is_number_unsigned()) wrongType(where, key, "a non-negative integer");
    return value->get<std::uint64_t>();
}

std::string JsonReader::string(const Json& object, const char* key, const std::string& where) const
{
    const Json* value = member(object, key);
    if (!value) return {};
    if (!value->is_string()) wrongType(where, key, "a string");
    return value->get<std::string>();
}

bool JsonReader::boolean(const Json& object, const char* key, bool fallback, const std::string& where) const
{
    const Json* value = member(object, key);
    if (!value) return fallback;
    if (!value->is_boolean()) wrongType(where, key, "true or false");
    return value->get<bool>();
}

glm::vec2 JsonReader::vec2(const Json& o, const char* key, glm::vec2 fallback, const std::string& where) const { return floats<2>(*this, o, key, fallback, where); }
glm::vec3 JsonReader::vec3(const Json& o, const char* key, glm::vec3 fallback, const std::string& where) const { return floats<3>(*this, o, key, fallback, where); }
glm::vec4 JsonReader::vec4(const Json& o, const char* key, glm::vec4 fallback, const std::string& where) const { return floats<4>(*this, o, key, fallback, where); }

const Json* JsonReader::extension(const Json& object, const char* name, const std::string& where) const
{
    const Json* extensions = member(object, "extensions");
    if (!extensions) return nullptr;
    if (!extensions->is_object()) wrongType(where, "extensions", "an object");
    const Json* value = member(*extensions, name);
    if (value && !value->is_object()) wrongType(where + ".extensions", name, "an object");
    return value;
}

Json unknownMembers(const Json& object, std::initializer_list<std::string_view> known)
{
    Json out;
    if (!object.is_object()) return out;
    if (auto it = object.find("extensions"); it != object.end() && it->is_object()) {
        for (const auto& [name, value] : it->items()) {
            bool isKnown = false;
            for (std::string_view k : known) isKnown = isKnown || name == k;
            if (!isKnown) out["extensions"][name] = value;
        }
    }
    if (auto it = object.find("extras"); it != object.end()) out["extras"] = *it;
    return out;
}

std::string floatText(float value)
{
    char text[32];
    const auto end = std::to_chars(text, text + sizeof text, value).ptr;
    return std::string(text, end);
}

float finiteFloat(double value, const std::string& file, const std::string& where)
{
    if (!std::isfinite(value) || std::abs(value) > static_cast<double>(std::numeric_limits<float>::max()))
    {
        char text[32];
        const auto end = std::to_chars(text, text + sizeof text, value).ptr;
        throw FileError(file, "non-finite-value", where + " is " + std::string(text, end) + ", outside the range of a float");
    }
    return static_cast<float>(value);
}

} // namespace glint
