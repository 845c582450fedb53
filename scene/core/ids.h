#pragma once
// Stable identifiers. Everything in a Scene refers to everything else by id, never by pointer,
// so commands, undo and files can name things that may be removed and re-created.
#include <cstdint>
#include <functional>

namespace glint {

// A strong typedef: ids of different kinds cannot be mixed up. Value 0 means "none".
template <class Tag>
struct Id {
    std::uint32_t value = 0;
    constexpr Id() = default;
    constexpr explicit Id(std::uint32_t v) : value(v) {}
    constexpr bool valid() const { return value != 0; }
    constexpr explicit operator bool() const { return valid(); }
    friend constexpr auto operator<=>(Id, Id) = default;
};

using NodeId = Id<struct NodeTag>;
using MeshId = Id<struct MeshTag>;
using MaterialId = Id<struct MaterialTag>;
using TextureId = Id<struct TextureTag>;
using ImageId = Id<struct ImageTag>;
using SamplerId = Id<struct SamplerTag>;
using AnimationId = Id<struct AnimationTag>;

} // namespace glint

template <class Tag>
struct std::hash<glint::Id<Tag>> {
    std::size_t operator()(glint::Id<Tag> id) const noexcept { return id.value; }
};
