#pragma once
// How late the event loop answers: a precise 10 ms timer records, at each tick, how much later
// than 10 ms it came. The viewport's rendering and preparation tests measure the same way
// (lateness of a 10 ms tick, nearest-rank percentile); this is that measure as one helper.
#include <QElapsedTimer>
#include <QTimer>

#include <algorithm>
#include <vector>

namespace glint::test {

// Nearest-rank percentile, p in [0, 1] (1 = the worst).
inline double percentile(std::vector<double> v, double p) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    return v[std::min(v.size() - 1, std::size_t(p * double(v.size() - 1) + 0.5))];
}

class EventLoopLatency {
public:
    static constexpr int kTickMs = 10;

    EventLoopLatency() {
        ticker_.setTimerType(Qt::PreciseTimer);
        QObject::connect(&ticker_, &QTimer::timeout, [this] {
            lateness_.push_back(std::max(0.0, double(sinceTick_.nsecsElapsed()) / 1e6 - kTickMs));
            sinceTick_.restart();
        });
    }
    void start() {
        lateness_.clear();
        sinceTick_.start();
        ticker_.start(kTickMs);
    }
    void stop() { ticker_.stop(); }
    std::size_t ticks() const { return lateness_.size(); }
    double percentile(double p) const { return test::percentile(lateness_, p); }

private:
    QTimer ticker_;
    QElapsedTimer sinceTick_;
    std::vector<double> lateness_;
};

} // namespace glint::test
