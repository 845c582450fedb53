#pragma once
// What glint-import-worker writes to its standard output, and how the parent reads it back.
// Layout (little-endian): "GLINTIMP", u32 version, u32 header length, header JSON
// ({"error": {"code", "message"}} or {"warnings": [{"code", "message"}, ...]}), u64 GLB length, GLB.
#include "scene/core/diagnostics.h"

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace glint {

struct WorkerReply {
    std::string errorCode; // empty: success, and glb holds the scene
    std::string errorMessage;
    Warnings warnings;     // `file` is filled in by the parent
    std::vector<std::uint8_t> glb;
};

std::vector<std::uint8_t> encodeWorkerReply(const WorkerReply& reply);

// nullopt when the bytes are not a complete, well-formed reply.
std::optional<WorkerReply> decodeWorkerReply(std::span<const std::uint8_t> bytes);

} // namespace glint
