#pragma once
// Decoded and mip-mapped material textures kept between GPU scene builds, so that rebuilding a
// scene (a structural edit, a re-docked viewport, the next render of a batch) does not decode and
// filter every image again. Keyed by content, not by id: the encoded bytes (compared in full on a
// hit, the hash only finds the entry), the colour space (the mip filter differs) and the size cap
// (an image larger than the driver's limit is stored at its first level that fits). An entry is
// exactly what decoding would give, so a cached build is bit-identical to a fresh one.
// Bounded: least recently used entries go once the pixels and encoded bytes held exceed the
// budget. Owned by whoever owns the GPU scene (no globals); safe to share between threads.
// CPU only: no GL here.
#include "renderer/gpu_scene/texture_mips.h"

#include <compare>
#include <cstddef>
#include <cstdint>
#include <list>
#include <map>
#include <memory>
#include <mutex>
#include <span>
#include <vector>

namespace glint::renderer {

class TextureCache {
public:
    static constexpr std::size_t defaultBudgetBytes = std::size_t{512} << 20;
    explicit TextureCache(std::size_t budgetBytes = defaultBudgetBytes) : budget_(budgetBytes) {}
    TextureCache(const TextureCache&) = delete;
    TextureCache& operator=(const TextureCache&) = delete;

    // The chain stored for these bytes, colour space and size cap, or null.
    std::shared_ptr<const MipChain> find(std::span<const std::uint8_t> encoded, bool srgb, int maxSize);
    // Stores a chain (replacing one with the same key), then evicts down to the budget; a chain
    // larger than the whole budget is not kept.
    void insert(std::span<const std::uint8_t> encoded, bool srgb, int maxSize, std::shared_ptr<const MipChain> chain);
    void clear();

    std::size_t bytes() const;   // pixels of every level plus the encoded bytes kept for comparison
    std::size_t entries() const;
    std::size_t budget() const { return budget_; }

private:
    struct Key {
        std::uint64_t hash = 0;
        std::size_t size = 0;
        bool srgb = false;
        int maxSize = 0;
        friend auto operator<=>(const Key&, const Key&) = default;
    };
    struct Entry {
        Key key;
        std::vector<std::uint8_t> encoded;
        std::shared_ptr<const MipChain> chain;
        std::size_t bytes = 0;
    };
    using Lru = std::list<Entry>; // most recently used first

    static Key keyOf(std::span<const std::uint8_t> encoded, bool srgb, int maxSize);
    void evictTo(std::size_t budget);

    mutable std::mutex mutex_;
    std::size_t budget_;
    std::size_t bytes_ = 0;
    Lru lru_;
    std::multimap<Key, Lru::iterator> index_; // equal hashes of different bytes are kept apart
};

} // namespace glint::renderer
