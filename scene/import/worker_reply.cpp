#include "worker_reply.h"

#include <nlohmann/json.hpp>

#include <cstring>

namespace glint {

namespace {

constexpr char kMagic[8] = {'G', 'L', 'I', 'N', 'T', 'I', 'M', 'P'};
constexpr std::uint32_t kVersion = 1;

void putLittleEndian(std::vector<std::uint8_t>& out, std::uint64_t value, int bytes) {
    for (int i = 0; i < bytes; ++i) out.push_back(static_cast<std::uint8_t>(value >> (8 * i)));
}

// Reads forward through the reply; every read is bounds-checked.
struct Cursor {
    std::span<const std::uint8_t> bytes;
    std::size_t at = 0;

    bool has(std::uint64_t n) const { return n <= bytes.size() - at; }
    std::optional<std::uint64_t> integer(int width) {
        if (!has(static_cast<std::uint64_t>(width))) return std::nullopt;
        std::uint64_t v = 0;
        for (int i = 0; i < width; ++i) v |= std::uint64_t(bytes[at + static_cast<std::size_t>(i)]) << (8 * i);
        at += static_cast<std::size_t>(width);
        return v;
    }
    std::optional<std::span<const std::uint8_t>> take(std::uint64_t n) {
        if (!has(n)) return std::nullopt;
        auto part = bytes.subspan(at, static_cast<std::size_t>(n));
        at += static_cast<std::size_t>(n);
        return part;
    }
};

nlohmann::json headerJson(const WorkerReply& reply) {
    nlohmann::json header = nlohmann::json::object();
    if (!reply.errorCode.empty()) header["error"] = {{"code", reply.errorCode}, {"message", reply.errorMessage}};
    nlohmann::json warnings = nlohmann::json::array();
    for (const Warning& w : reply.warnings) warnings.push_back({{"code", w.code}, {"message", w.message}});
    header["warnings"] = std::move(warnings);
    return header;
}

// A string member of `object`, `fallback` when absent; nullopt when it is there but not a string.
std::optional<std::string> stringMember(const nlohmann::json& object, const char* key, const std::string& fallback) {
    const auto it = object.find(key);
    if (it == object.end()) return fallback;
    if (!it->is_string()) return std::nullopt;
    return it->get<std::string>();
}

// Anything not shaped as the worker writes it refuses the reply (the worker may have been replaced
// or died mid-write): an error or warning that is not an object, a code or message that is not a
// string. An error always has a code, so it can never read as success.
bool readHeader(const nlohmann::json& header, WorkerReply& reply) {
    if (!header.is_object()) return false;
    if (auto e = header.find("error"); e != header.end()) {
        if (!e->is_object()) return false;
        const auto code = stringMember(*e, "code", "import-failed");
        const auto message = stringMember(*e, "message", "");
        if (!code || !message) return false;
        reply.errorCode = code->empty() ? "import-failed" : *code;
        reply.errorMessage = *message;
    }
    auto list = header.find("warnings");
    if (list == header.end() || !list->is_array()) return false;
    for (const auto& w : *list) {
        if (!w.is_object()) return false;
        const auto code = stringMember(w, "code", "");
        const auto message = stringMember(w, "message", "");
        if (!code || !message) return false;
        reply.warnings.push_back({"", *code, *message});
    }
    return true;
}

} // namespace

std::vector<std::uint8_t> encodeWorkerReply(const WorkerReply& reply) {
    const std::string header = headerJson(reply).dump();
    std::vector<std::uint8_t> out(std::begin(kMagic), std::end(kMagic));
    putLittleEndian(out, kVersion, 4);
    putLittleEndian(out, header.size(), 4);
    out.insert(out.end(), header.begin(), header.end());
    putLittleEndian(out, reply.glb.size(), 8);
    out.insert(out.end(), reply.glb.begin(), reply.glb.end());
    return out;
}

std::optional<WorkerReply> decodeWorkerReply(std::span<const std::uint8_t> bytes) {
    Cursor in{bytes};
    auto magic = in.take(sizeof kMagic);
    if (!magic || std::memcmp(magic->data(), kMagic, sizeof kMagic) != 0) return std::nullopt;
    auto version = in.integer(4);
    auto headerLength = in.integer(4);
    if (!version || *version != kVersion || !headerLength) return std::nullopt;
    auto headerBytes = in.take(*headerLength);
    if (!headerBytes) return std::nullopt;
    nlohmann::json header = nlohmann::json::parse(headerBytes->begin(), headerBytes->end(), nullptr, false);
    WorkerReply reply;
    if (header.is_discarded() || !readHeader(header, reply)) return std::nullopt;
    auto glbLength = in.integer(8);
    if (!glbLength) return std::nullopt;
    auto glb = in.take(*glbLength);
    if (!glb || in.at != bytes.size()) return std::nullopt;
    reply.glb.assign(glb->begin(), glb->end());
    return reply;
}

} // namespace glint
