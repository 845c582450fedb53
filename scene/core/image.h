#pragma once
#include "ids.h"
#include "shared_array.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace glint {

// An image as the file holds it. The encoded bytes are kept so that saving never re-encodes.
struct Image {
    std::string name;
    std::string uri;      // relative to the scene folder; empty when embedded
    std::string mimeType; // "image/png", "image/jpeg", ...
    SharedArray<std::uint8_t> encoded; // shared between copies until written (shared_array.h)
    int width = 0;        // from the header, 0 if unknown or undecodable
    int height = 0;
    bool missing = false; // file not found / not decodable: renderers show a placeholder
    nlohmann::json unknown;

    friend bool operator==(const Image&, const Image&) = default;
};

// glTF sampler enums (the GL values glTF uses).
enum class Filter : int { Unset = 0, Nearest = 9728, Linear = 9729, NearestMipmapNearest = 9984,
                          LinearMipmapNearest = 9985, NearestMipmapLinear = 9986, LinearMipmapLinear = 9987 };
enum class Wrap : int { Repeat = 10497, ClampToEdge = 33071, MirroredRepeat = 33648 };

struct Sampler {
    std::string name;
    Filter magFilter = Filter::Unset;
    Filter minFilter = Filter::Unset;
    Wrap wrapS = Wrap::Repeat;
    Wrap wrapT = Wrap::Repeat;
    nlohmann::json unknown;

    friend bool operator==(const Sampler&, const Sampler&) = default;
};

struct Texture {
    std::string name;
    ImageId image{};
    SamplerId sampler{};
    nlohmann::json unknown;

    friend bool operator==(const Texture&, const Texture&) = default;
};

} // namespace glint
