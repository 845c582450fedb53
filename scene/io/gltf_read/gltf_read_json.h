#pragma once
// Typed access to glTF JSON members. Every getter checks the member's type and throws
// FileError(file, "wrong-type") naming where it is, so wrong JSON types never reach the model.
#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include <initializer_list>
#include <string>
#include <string_view>

namespace glint {

using Json = nlohmann::json;

struct JsonReader {
    const std::string& file;

    const Json* member(const Json& object, const char* key) const;
    const Json& objectAt(const Json& parent, const char* key, std::size_t index, const std::string& where) const;
    float number(const Json& object, const char* key, float fallback, const std::string& where) const;
    double number64(const Json& object, const char* key, double fallback, const std::string& where) const;
    int index(const Json& object, const char* key, const std::string& where) const; // -1 when absent
    std::uint64_t unsignedNumber(const Json& object, const char* key, std::uint64_t fallback, const std::string& where) const;
    std::string string(const Json& object, const char* key, const std::string& where) const;
    bool boolean(const Json& object, const char* key, bool fallback, const std::string& where) const;
    glm::vec2 vec2(const Json& object, const char* key, glm::vec2 fallback, const std::string& where) const;
    glm::vec3 vec3(const Json& object, const char* key, glm::vec3 fallback, const std::string& where) const;
    glm::vec4 vec4(const Json& object, const char* key, glm::vec4 fallback, const std::string& where) const;
    const Json* extension(const Json& object, const char* name, const std::string& where) const;

    [[noreturn]] void wrongType(const std::string& where, const char* key, const char* expected) const;
};

// {"extensions": {the ones not in `known`}, "extras": ...} of an object; null when there is nothing.
Json unknownMembers(const Json& object, std::initializer_list<std::string_view> known = {});

// The shortest decimal that reads back as `value` (locale-independent), for messages.
std::string floatText(float value);

// Floats stay within float range: 1e39 or an overflow is as wrong as NaN (non-finite-value).
float finiteFloat(double value, const std::string& file, const std::string& where);

} // namespace glint
