#pragma once
// Shared assets (meshes, materials, textures, ...) keyed by stable id. Ordered by id, so every
// walk over a table (saving, uploading, listing) is deterministic.
#include <map>
#include <stdexcept>
#include <string>

namespace glint {

template <class IdT, class T>
class AssetTable {
public:
    IdT add(T value) {
        IdT id{next_++};
        items_.emplace(id, std::move(value));
        return id;
    }
    // Re-insert under a known id (undo of a removal, loading a file that saved ids).
    void insert(IdT id, T value) {
        if (!id.valid() || items_.count(id)) throw std::logic_error("AssetTable::insert: id taken or invalid");
        items_.emplace(id, std::move(value));
        if (id.value >= next_) next_ = id.value + 1;
    }
    T remove(IdT id) {
        auto it = items_.find(id);
        if (it == items_.end()) throw std::out_of_range("AssetTable::remove: no such id");
        T value = std::move(it->second);
        items_.erase(it);
        return value;
    }
    const T* find(IdT id) const { auto it = items_.find(id); return it == items_.end() ? nullptr : &it->second; }
    T* find(IdT id) { auto it = items_.find(id); return it == items_.end() ? nullptr : &it->second; }
    const T& at(IdT id) const { return items_.at(id); }
    T& at(IdT id) { return items_.at(id); }
    bool contains(IdT id) const { return items_.count(id) != 0; }
    std::size_t size() const { return items_.size(); }
    bool empty() const { return items_.empty(); }
    void clear() { items_.clear(); next_ = 1; }

    auto begin() const { return items_.begin(); }
    auto end() const { return items_.end(); }
    auto begin() { return items_.begin(); }
    auto end() { return items_.end(); }

    // Equal content and ids; the next free id is bookkeeping, not content.
    friend bool operator==(const AssetTable& a, const AssetTable& b) { return a.items_ == b.items_; }

private:
    std::map<IdT, T> items_;
    std::uint32_t next_ = 1;
};

} // namespace glint
