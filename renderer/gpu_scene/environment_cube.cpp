#include "renderer/gpu_scene/environment_cube.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace glint::renderer {

namespace {

enum Face { PosX, NegX, PosY, NegY, PosZ, NegZ };

// Where a face's top-left corner is, in face units, and whether it is stored upside down.
struct FacePlace {
    int column = 0, row = 0;
    bool rotated180 = false;
};

FacePlace placeOf(CubeLayout layout, int face) {
    switch (layout) {
    case CubeLayout::HorizontalCross: {
        static constexpr std::array<FacePlace, 6> places{{{2, 1}, {0, 1}, {1, 0}, {1, 2}, {1, 1}, {3, 1}}};
        return places[std::size_t(face)];
    }
    case CubeLayout::VerticalCross: {
        static constexpr std::array<FacePlace, 6> places{{{2, 1}, {0, 1}, {1, 0}, {1, 2}, {1, 1}, {1, 3, true}}};
        return places[std::size_t(face)];
    }
    case CubeLayout::HorizontalStrip: return {face, 0};
    case CubeLayout::VerticalStrip: return {0, face};
    }
    return {};
}

int faceSideOf(CubeLayout layout, int width) {
    switch (layout) {
    case CubeLayout::HorizontalCross: return width / 4;
    case CubeLayout::VerticalCross: return width / 3;
    case CubeLayout::HorizontalStrip: return width / 6;
    case CubeLayout::VerticalStrip: return width;
    }
    return 0;
}

// OpenGL's cube-map face selection (major axis, then s and t from the left and top of the face)
// for a direction in the cube's frame. That frame is left-handed, as cube maps are named: the
// world's with z mirrored (c = (x, y, -z)), so every face reads unmirrored from inside.
void faceAndCoords(double x, double y, double z, int& face, double& s, double& t) {
    const double ax = std::abs(x), ay = std::abs(y), az = std::abs(z);
    double sc, tc, ma;
    if (ax >= ay && ax >= az) {
        face = x > 0.0 ? PosX : NegX;
        sc = x > 0.0 ? -z : z;
        tc = -y;
        ma = ax;
    } else if (ay >= az) {
        face = y > 0.0 ? PosY : NegY;
        sc = x;
        tc = y > 0.0 ? z : -z;
        ma = ay;
    } else {
        face = z > 0.0 ? PosZ : NegZ;
        sc = z > 0.0 ? x : -x;
        tc = -y;
        ma = az;
    }
    s = 0.5 * (sc / ma + 1.0);
    t = 0.5 * (tc / ma + 1.0);
}

struct FaceSampler {
    const EnvironmentImage& image;
    CubeLayout layout;
    int side;

    float texel(int face, int i, int j, int c) const {
        const FacePlace place = placeOf(layout, face);
        i = std::clamp(i, 0, side - 1);
        j = std::clamp(j, 0, side - 1);
        if (place.rotated180) {
            i = side - 1 - i;
            j = side - 1 - j;
        }
        const std::size_t x = std::size_t(place.column * side + i), y = std::size_t(place.row * side + j);
        return image.rgb[(y * std::size_t(image.width) + x) * 3 + std::size_t(c)];
    }

    // Bilinear within the face, clamped at its edges.
    void sample(int face, double s, double t, float* rgb) const {
        const double fx = s * side - 0.5, fy = t * side - 0.5;
        const int i = int(std::floor(fx)), j = int(std::floor(fy));
        const double wx = fx - i, wy = fy - j;
        for (int c = 0; c < 3; ++c) {
            const double top = (1.0 - wx) * texel(face, i, j, c) + wx * texel(face, i + 1, j, c);
            const double bottom = (1.0 - wx) * texel(face, i, j + 1, c) + wx * texel(face, i + 1, j + 1, c);
            rgb[c] = float((1.0 - wy) * top + wy * bottom);
        }
    }
};

} // namespace

std::optional<CubeLayout> cubeLayoutOf(int width, int height) {
    if (width <= 0 || height <= 0) return std::nullopt;
    if (width * 3 == height * 4 && width % 4 == 0) return CubeLayout::HorizontalCross;
    if (width * 4 == height * 3 && width % 3 == 0) return CubeLayout::VerticalCross;
    if (width == height * 6) return CubeLayout::HorizontalStrip;
    if (height == width * 6) return CubeLayout::VerticalStrip;
    return std::nullopt;
}

int cubeFaceSide(CubeLayout layout, int width) { return faceSideOf(layout, width); }

EnvironmentImage equirectFromCube(const EnvironmentImage& cube, CubeLayout layout) {
    const FaceSampler faces{cube, layout, faceSideOf(layout, cube.width)};
    EnvironmentImage out;
    out.width = 4 * faces.side;
    out.height = 2 * faces.side;
    out.rgb.resize(std::size_t(out.width) * std::size_t(out.height) * 3);
    for (int row = 0; row < out.height; ++row) {
        // docs/UNITS.md: u = 0.5 + atan2(z, x) / 2pi, v = acos(y) / pi, at the texel's centre.
        const double theta = (row + 0.5) / out.height * std::numbers::pi;
        for (int column = 0; column < out.width; ++column) {
            const double phi = ((column + 0.5) / out.width - 0.5) * 2.0 * std::numbers::pi;
            const double x = std::sin(theta) * std::cos(phi), y = std::cos(theta), z = std::sin(theta) * std::sin(phi);
            int face = 0;
            double s = 0.0, t = 0.0;
            faceAndCoords(x, y, -z, face, s, t);
            faces.sample(face, s, t, &out.rgb[(std::size_t(row) * std::size_t(out.width) + std::size_t(column)) * 3]);
        }
    }
    return out;
}

} // namespace glint::renderer
