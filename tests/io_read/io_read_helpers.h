#pragma once
// Building small glTF documents in code, so each bad input is one precise change to a valid file.
#include "scene/io/scene_io.h"

#include <nlohmann/json.hpp>

#include <QTest>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

namespace glint::test {

using Json = nlohmann::json;

inline std::string base64(const std::vector<std::uint8_t>& bytes)
{
    static constexpr char kDigits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        const std::uint32_t n = std::uint32_t(bytes[i]) << 16 | (i + 1 < bytes.size() ? std::uint32_t(bytes[i + 1]) << 8 : 0) |
                                (i + 2 < bytes.size() ? bytes[i + 2] : 0);
        out += kDigits[n >> 18 & 63];
        out += kDigits[n >> 12 & 63];
        out += i + 1 < bytes.size() ? kDigits[n >> 6 & 63] : '=';
        out += i + 2 < bytes.size() ? kDigits[n & 63] : '=';
    }
    return out;
}

template <class T>
void appendValues(std::vector<std::uint8_t>& bytes, const std::vector<T>& values)
{
    const std::size_t at = bytes.size();
    bytes.resize(at + values.size() * sizeof(T));
    std::memcpy(bytes.data() + at, values.data(), values.size() * sizeof(T));
    while (bytes.size() % 4) bytes.push_back(0);
}

// A glTF document under construction with one buffer; finish() embeds it as a data: URI.
struct GltfBuilder {
    Json doc = Json{{"asset", {{"version", "2.0"}}}, {"scenes", {{{"nodes", {0}}}}}, {"scene", 0}, {"nodes", {{{"mesh", 0}}}}};
    std::vector<std::uint8_t> bin;

    template <class T>
    int view(const std::vector<T>& values)
    {
        const std::size_t offset = bin.size();
        appendValues(bin, values);
        doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", values.size() * sizeof(T)}});
        return static_cast<int>(doc["bufferViews"].size() - 1);
    }

    template <class T>
    int accessor(const std::vector<T>& values, int componentType, const char* type, int components, bool normalized = false)
    {
        Json a{{"bufferView", view(values)}, {"componentType", componentType}, {"count", values.size() / static_cast<std::size_t>(components)}, {"type", type}};
        if (normalized) a["normalized"] = true;
        doc["accessors"].push_back(a);
        return static_cast<int>(doc["accessors"].size() - 1);
    }

    int positions(const std::vector<float>& xyz) { return accessor(xyz, 5126, "VEC3", 3); }
    int indices(const std::vector<std::uint16_t>& values) { return accessor(values, 5123, "SCALAR", 1); }

    Json& primitive(std::size_t mesh = 0, std::size_t index = 0) { return doc["meshes"][mesh]["primitives"][index]; }

    Json finish() const
    {
        Json out = doc;
        out["buffers"] = Json::array({{{"byteLength", bin.size()}, {"uri", "data:application/octet-stream;base64," + base64(bin)}}});
        return out;
    }
};

// One triangle (or a quad as two) in mesh 0, node 0, scene 0.
inline GltfBuilder triangle()
{
    GltfBuilder b;
    const int p = b.positions({0, 0, 0, 1, 0, 0, 0, 1, 0});
    const int i = b.indices({0, 1, 2});
    b.doc["meshes"] = Json::array({{{"primitives", {{{"attributes", {{"POSITION", p}}}, {"indices", i}}}}}});
    return b;
}

inline std::vector<std::uint8_t> bytesOf(const std::string& text) { return {text.begin(), text.end()}; }

inline LoadResult loadJson(const Json& doc, const std::filesystem::path& folder = ".", const LoadOptions& options = {})
{
    return loadGltfFromMemory(bytesOf(doc.dump()), folder, "test.gltf", options);
}

// A GLB from a JSON chunk and a BIN chunk (both padded as the format wants).
inline std::vector<std::uint8_t> makeGlb(const Json& doc, const std::vector<std::uint8_t>& bin)
{
    std::string json = doc.dump();
    while (json.size() % 4) json += ' ';
    std::vector<std::uint8_t> paddedBin = bin;
    while (paddedBin.size() % 4) paddedBin.push_back(0);
    std::vector<std::uint8_t> out;
    auto u32 = [&](std::uint32_t v) { for (int i = 0; i < 4; ++i) out.push_back(static_cast<std::uint8_t>(v >> (8 * i))); };
    const std::uint32_t total = 12 + 8 + static_cast<std::uint32_t>(json.size()) + (bin.empty() ? 0 : 8 + static_cast<std::uint32_t>(paddedBin.size()));
    u32(0x46546C67); u32(2); u32(total);
    u32(static_cast<std::uint32_t>(json.size())); u32(0x4E4F534A);
    out.insert(out.end(), json.begin(), json.end());
    if (!bin.empty()) {
        u32(static_cast<std::uint32_t>(paddedBin.size())); u32(0x004E4942);
        out.insert(out.end(), paddedBin.begin(), paddedBin.end());
    }
    return out;
}

inline void writeFile(const std::filesystem::path& file, const std::vector<std::uint8_t>& bytes)
{
    std::ofstream out(file, std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

// The FileError a call throws (code and message); fails the test when it throws none.
struct Caught {
    std::string code;
    std::string message;
    std::string file = {};
};

inline Caught errorOf(const std::function<void()>& call)
{
    try {
        call();
    } catch (const FileError& e) {
        return {e.code(), e.message(), e.file()};
    }
    return {"(no error)", ""};
}

inline bool hasWarning(const Warnings& warnings, const std::string& code)
{
    for (const Warning& w : warnings)
        if (w.code == code) return true;
    return false;
}

inline const Warning* findWarning(const Warnings& warnings, const std::string& code)
{
    for (const Warning& w : warnings)
        if (w.code == code) return &w;
    return nullptr;
}

// A PNG header (signature + IHDR) claiming the given size; no pixel data.
inline std::vector<std::uint8_t> pngHeader(std::uint32_t width, std::uint32_t height)
{
    std::vector<std::uint8_t> b = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n', 0, 0, 0, 13, 'I', 'H', 'D', 'R'};
    for (std::uint32_t v : {width, height})
        for (int i = 3; i >= 0; --i) b.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
    b.insert(b.end(), {8, 6, 0, 0, 0, 0, 0, 0, 0});
    return b;
}

} // namespace glint::test

#define GLINT_EXPECT_ERROR(call, expectedCode, messagePart)                                      \
    do {                                                                                         \
        const auto caught = glint::test::errorOf([&] { (void)(call); });                         \
        QCOMPARE(QString::fromStdString(caught.code), QStringLiteral(expectedCode));             \
        QVERIFY2(caught.message.find(messagePart) != std::string::npos, caught.message.c_str()); \
    } while (0)
