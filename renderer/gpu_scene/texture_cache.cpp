#include "renderer/gpu_scene/texture_cache.h"

#include <algorithm>

namespace glint::renderer {
namespace {

// FNV-1a, 64 bits: only finds the entry, whose bytes are then compared in full.
std::uint64_t fnv1a(std::span<const std::uint8_t> bytes) {
    std::uint64_t h = 0xcbf29ce484222325ull;
    for (const std::uint8_t b : bytes) h = (h ^ b) * 0x100000001b3ull;
    return h;
}

std::size_t chainBytes(const MipChain& chain) {
    std::size_t n = 0;
    for (const TextureLevel& level : chain) n += level.rgba.size();
    return n;
}

} // namespace

TextureCache::Key TextureCache::keyOf(std::span<const std::uint8_t> encoded, bool srgb, int maxSize) {
    return Key{fnv1a(encoded), encoded.size(), srgb, maxSize};
}

std::shared_ptr<const MipChain> TextureCache::find(std::span<const std::uint8_t> encoded, bool srgb, int maxSize) {
    const Key key = keyOf(encoded, srgb, maxSize);
    const std::lock_guard lock(mutex_);
    const auto [first, last] = index_.equal_range(key);
    for (auto it = first; it != last; ++it) {
        const Lru::iterator entry = it->second;
        if (!std::equal(encoded.begin(), encoded.end(), entry->encoded.begin(), entry->encoded.end())) continue;
        lru_.splice(lru_.begin(), lru_, entry);
        return entry->chain;
    }
    return nullptr;
}

void TextureCache::insert(std::span<const std::uint8_t> encoded, bool srgb, int maxSize, std::shared_ptr<const MipChain> chain) {
    if (!chain) return;
    const Key key = keyOf(encoded, srgb, maxSize);
    const std::size_t size = chainBytes(*chain) + encoded.size();
    const std::lock_guard lock(mutex_);
    const auto [first, last] = index_.equal_range(key);
    for (auto it = first; it != last; ++it)
        if (std::equal(encoded.begin(), encoded.end(), it->second->encoded.begin(), it->second->encoded.end())) {
            bytes_ -= it->second->bytes;
            lru_.erase(it->second);
            index_.erase(it);
            break;
        }
    if (size > budget_) return;
    lru_.push_front(Entry{key, {encoded.begin(), encoded.end()}, std::move(chain), size});
    index_.emplace(key, lru_.begin());
    bytes_ += size;
    evictTo(budget_);
}

void TextureCache::evictTo(std::size_t budget) {
    while (bytes_ > budget && !lru_.empty()) {
        const Entry& oldest = lru_.back();
        const auto [first, last] = index_.equal_range(oldest.key);
        for (auto it = first; it != last; ++it)
            if (it->second == std::prev(lru_.end())) {
                index_.erase(it);
                break;
            }
        bytes_ -= oldest.bytes;
        lru_.pop_back();
    }
}

void TextureCache::clear() {
    const std::lock_guard lock(mutex_);
    evictTo(0);
}

std::size_t TextureCache::bytes() const {
    const std::lock_guard lock(mutex_);
    return bytes_;
}

std::size_t TextureCache::entries() const {
    const std::lock_guard lock(mutex_);
    return lru_.size();
}

} // namespace glint::renderer
