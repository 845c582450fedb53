#pragma once
// Reads what glint wrote the way another tool would (OpenImageIO): pixels, channel names and
// header attributes, so tests compare pixels rather than bytes (EXR headers carry a render time).
#include <OpenImageIO/imageio.h>

#include <QString>

#include <algorithm>
#include <map>
#include <string>
#include <vector>

struct ProbedImage {
    bool ok = false;
    int width = 0;
    int height = 0;
    std::vector<std::string> channels;
    std::vector<float> pixels;
    std::map<std::string, std::string> attributes; // string attributes only
};

inline ProbedImage probeImage(const QString& file) {
    ProbedImage p;
    auto in = OIIO::ImageInput::open(file.toStdString());
    if (!in) {
        (void)OIIO::geterror();
        return p;
    }
    const OIIO::ImageSpec& spec = in->spec();
    p.width = spec.width;
    p.height = spec.height;
    p.channels = spec.channelnames;
    for (const auto& a : spec.extra_attribs)
        if (a.type() == OIIO::TypeDesc::STRING) p.attributes[a.name().string()] = a.get_string();
    p.pixels.resize(spec.image_pixels() * std::size_t(spec.nchannels));
    p.ok = in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, p.pixels.data());
    if (!p.ok) (void)in->geterror();
    return p;
}

// EXR keeps channels sorted by name (readers put R, G, B, A first): compare them as a set.
inline std::vector<std::string> sorted(std::vector<std::string> names) {
    std::sort(names.begin(), names.end());
    return names;
}

// A `glint:` string attribute of the header, or empty.
inline QString glintAttr(const ProbedImage& image, const char* key) {
    auto it = image.attributes.find(std::string("glint:") + key);
    return it == image.attributes.end() ? QString() : QString::fromStdString(it->second);
}
