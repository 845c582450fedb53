#pragma once
#include "components.h"
#include "ids.h"
#include "transform.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace glint {

struct Node {
    NodeId id{};
    std::string name;
    NodeId parent{};              // none: a root
    std::vector<NodeId> children; // in order
    Transform local;              // parentFromLocal
    bool visible = true;
    Component component;
    nlohmann::json unknown;       // extensions/extras Glint does not interpret

    template <class T> const T* get() const { return std::get_if<T>(&component); }
    template <class T> T* get() { return std::get_if<T>(&component); }
    friend bool operator==(const Node&, const Node&) = default;
};

} // namespace glint
