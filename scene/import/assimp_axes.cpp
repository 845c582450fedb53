#include "assimp_axes.h"

#include <assimp/scene.h>

#include <cmath>
#include <optional>

namespace glint {

namespace {

std::optional<double> number(const aiMetadata& metadata, const char* key) {
    for (unsigned i = 0; i < metadata.mNumProperties; ++i) {
        if (std::string(metadata.mKeys[i].C_Str()) != key || !metadata.mValues[i].mData) continue;
        const void* data = metadata.mValues[i].mData;
        switch (metadata.mValues[i].mType) {
        case AI_BOOL: return *static_cast<const bool*>(data) ? 1.0 : 0.0;
        case AI_INT32: return *static_cast<const std::int32_t*>(data);
        case AI_UINT64: return static_cast<double>(*static_cast<const std::uint64_t*>(data));
        case AI_FLOAT: return *static_cast<const float*>(data);
        case AI_DOUBLE: return *static_cast<const double*>(data);
        default: return std::nullopt;
        }
    }
    return std::nullopt;
}

struct Axis {
    int index;
    float sign;
};

Axis axis(const aiMetadata& metadata, const char* key, const char* signKey, int fallback) {
    const int index = static_cast<int>(number(metadata, key).value_or(fallback));
    return {index, number(metadata, signKey).value_or(1.0) < 0.0 ? -1.0f : 1.0f};
}

// FBX: CoordAxis becomes +X, UpAxis +Y and FrontAxis +Z.
std::optional<glm::mat3> rotationFromAxes(const aiMetadata& metadata) {
    if (!number(metadata, "UpAxis")) return glm::mat3(1.0f);
    const Axis right = axis(metadata, "CoordAxis", "CoordAxisSign", 0);
    const Axis up = axis(metadata, "UpAxis", "UpAxisSign", 1);
    const Axis front = axis(metadata, "FrontAxis", "FrontAxisSign", 2);
    const bool valid = right.index >= 0 && right.index < 3 && up.index >= 0 && up.index < 3 && front.index >= 0 &&
                       front.index < 3 && right.index != up.index && up.index != front.index && right.index != front.index;
    if (!valid) return std::nullopt;
    glm::mat3 glintFromFile(0.0f); // glm is column-major: [file axis][glint axis]
    glintFromFile[right.index][0] = right.sign;
    glintFromFile[up.index][1] = up.sign;
    glintFromFile[front.index][2] = front.sign;
    return glintFromFile;
}

std::optional<float> metresPerUnit(const aiMetadata& metadata) {
    const double centimetres = number(metadata, "UnitScaleFactor").value_or(1.0);
    if (!std::isfinite(centimetres) || centimetres <= 0.0) return std::nullopt;
    return static_cast<float>(centimetres / 100.0);
}

} // namespace

glm::mat4 glintFromFileAxes(const aiMetadata* metadata, const std::string& file, Warnings& warnings) {
    if (!metadata || (!number(*metadata, "UnitScaleFactor") && !number(*metadata, "UpAxis"))) return glm::mat4(1.0f);
    std::optional<glm::mat3> rotation = rotationFromAxes(*metadata);
    if (!rotation) {
        warnings.push_back({file, "invalid-axes", "the file's axis settings are inconsistent; axes kept as they are"});
        rotation = glm::mat3(1.0f);
    }
    std::optional<float> scale = metresPerUnit(*metadata);
    if (!scale) {
        warnings.push_back({file, "invalid-unit", "the file's unit scale is not a positive number; 1 unit = 1 cm assumed"});
        scale = 0.01f;
    }
    return glm::mat4(*rotation * *scale);
}

} // namespace glint
