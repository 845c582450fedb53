#pragma once
// Add, remove and set shared assets (meshes, materials, textures, images, samplers) by id.
// SetAsset is the generic property edit of an asset: the whole value, old and new; edits of one
// asset within one interaction merge (a material slider drag is one undo step).
#include "asset_kinds.h"
#include "asset_usage.h"
#include "command.h"
#include "memory_estimate.h"
#include "value_json.h"

#include <memory>
#include <stdexcept>
#include <string>

namespace glint {

template <class T>
class SetAsset;

// Adds an asset. An id of 0 takes a fresh id on the first apply; later applies reuse it. Within one
// interaction a following edit of the new asset merges into the addition (a drag that creates an
// animation key track and then moves the key is one undo step).
template <class T>
class AddAsset final : public Command {
public:
    using Kind = AssetKind<T>;
    using IdT = typename Kind::IdT;

    explicit AddAsset(T value, IdT id = {}) : value_(std::move(value)), id_(id) {}

    ChangeSet apply(Scene& scene) override {
        auto& table = Kind::table(scene);
        if (id_) table.insert(id_, value_);
        else id_ = table.add(value_);
        return changes();
    }
    ChangeSet revert(Scene& scene) override {
        Kind::table(scene).remove(id_);
        return changes();
    }
    std::string label() const override { return std::string("Add ") + Kind::name; }
    std::string typeName() const override { return std::string("add_") + Kind::name; }
    // SetAsset's key for the asset once it has its id: the edits that merge into the addition.
    std::string mergeKey() const override { return id_ ? std::string("set_") + Kind::name + ":" + std::to_string(id_.value) : std::string(); }
    bool mergeWith(const Command& next) override {
        const auto* edit = dynamic_cast<const SetAsset<T>*>(&next);
        if (!edit || edit->id() != id_) return false;
        value_ = edit->value();
        return true;
    }
    std::size_t memoryBytes() const override { return sizeof(*this) + approxBytes(value_); }
    nlohmann::json toJson() const override { return {{"id", id_}, {"value", value_}}; }
    static CommandPtr fromJson(const nlohmann::json& j) {
        return std::make_unique<AddAsset>(j.at("value").get<T>(), j.at("id").get<IdT>());
    }
    IdT id() const { return id_; }

private:
    ChangeSet changes() const {
        ChangeSet c;
        c.add(Change::Assets);
        Kind::touch(c, id_);
        return c;
    }

    T value_;
    IdT id_;
};

// Removes an asset nothing refers to (std::invalid_argument otherwise); revert restores its id.
template <class T>
class RemoveAsset final : public Command {
public:
    using Kind = AssetKind<T>;
    using IdT = typename Kind::IdT;

    explicit RemoveAsset(IdT id) : id_(id) {}

    ChangeSet apply(Scene& scene) override {
        if (isInUse(scene, id_))
            throw std::invalid_argument(std::string("cannot remove ") + Kind::name + " " + std::to_string(id_.value) +
                                        ": still in use");
        removed_ = Kind::table(scene).remove(id_);
        return changes();
    }
    ChangeSet revert(Scene& scene) override {
        Kind::table(scene).insert(id_, removed_);
        return changes();
    }
    std::string label() const override { return std::string("Remove ") + Kind::name; }
    std::string typeName() const override { return std::string("remove_") + Kind::name; }
    std::size_t memoryBytes() const override { return sizeof(*this) + approxBytes(removed_); }
    nlohmann::json toJson() const override { return {{"id", id_}}; }
    static CommandPtr fromJson(const nlohmann::json& j) { return std::make_unique<RemoveAsset>(j.at("id").get<IdT>()); }

private:
    ChangeSet changes() const {
        ChangeSet c;
        c.add(Change::Assets);
        Kind::touch(c, id_);
        return c;
    }

    IdT id_;
    T removed_{};
};

template <class T>
class SetAsset final : public Command {
public:
    using Kind = AssetKind<T>;
    using IdT = typename Kind::IdT;

    SetAsset(IdT id, T value) : id_(id), new_(std::move(value)) {}

    ChangeSet apply(Scene& scene) override {
        T& stored = Kind::table(scene).at(id_);
        old_ = stored;
        stored = new_;
        return changes();
    }
    ChangeSet revert(Scene& scene) override {
        Kind::table(scene).at(id_) = old_;
        return changes();
    }
    std::string label() const override { return std::string("Edit ") + Kind::name; }
    std::string typeName() const override { return std::string("set_") + Kind::name; }
    std::string mergeKey() const override { return typeName() + ":" + std::to_string(id_.value); }
    bool mergeWith(const Command& next) override {
        const auto* same = dynamic_cast<const SetAsset*>(&next);
        if (!same || same->id_ != id_) return false;
        new_ = same->new_;
        return true;
    }
    std::size_t memoryBytes() const override { return sizeof(*this) + approxBytes(old_) + approxBytes(new_); }
    nlohmann::json toJson() const override { return {{"id", id_}, {"value", new_}}; }
    static CommandPtr fromJson(const nlohmann::json& j) {
        return std::make_unique<SetAsset>(j.at("id").get<IdT>(), j.at("value").get<T>());
    }
    IdT id() const { return id_; }
    const T& value() const { return new_; }

private:
    ChangeSet changes() const {
        ChangeSet c;
        c.add(Kind::contentChange);
        Kind::touch(c, id_);
        return c;
    }

    IdT id_;
    T new_;
    T old_{};
};

using SetMaterial = SetAsset<Material>;

} // namespace glint
