#pragma once
// URIs in glTF: relative paths (percent-encoded) and base64 `data:` URIs.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace glint {

bool isDataUri(const std::string& uri);

struct DataUri {
    std::string mimeType;
    std::vector<std::uint8_t> bytes;
};

// "data:<mime>;base64,<payload>" decoded; nothing when it is not exactly that (bad base64 included).
std::optional<DataUri> parseDataUri(const std::string& uri);

// "%20" -> " ". A malformed escape is kept as it is written.
std::string percentDecoded(const std::string& uri);

} // namespace glint
