#include "camera_path_hermite.h"

#include <algorithm>

namespace glint {

PathSegment findPathSegment(const std::vector<CameraKey>& keys, double t) {
    const std::size_t lastSegment = keys.size() - 2;
    const auto after = std::upper_bound(keys.begin() + 1, keys.end() - 1, t,
                                        [](double time, const CameraKey& key) { return time < key.time; });
    const std::size_t index = std::min(std::size_t(after - keys.begin()) - 1, lastSegment);
    const double duration = keys[index + 1].time - keys[index].time;
    const double u = std::clamp((t - keys[index].time) / duration, 0.0, 1.0);
    return {index, u, duration};
}

} // namespace glint
