// Fuzzes how the parent reads glint-import-worker's reply (scene/import/worker_reply.h): the
// worker may crash mid-write, be replaced, or print anything, so the bytes are untrusted. A reply
// either decodes or is refused (nullopt); what decodes must encode back to the same bytes' meaning.
#include "scene/import/worker_reply.h"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto reply = glint::decodeWorkerReply(std::span<const std::uint8_t>(data, size));
    if (!reply) return 0;
    const auto again = glint::decodeWorkerReply(glint::encodeWorkerReply(*reply));
    if (!again || again->errorCode != reply->errorCode || again->errorMessage != reply->errorMessage ||
        again->glb != reply->glb || again->warnings.size() != reply->warnings.size())
        std::abort();
    for (std::size_t i = 0; i < reply->warnings.size(); ++i)
        if (again->warnings[i].code != reply->warnings[i].code || again->warnings[i].message != reply->warnings[i].message)
            std::abort();
    return 0;
}
