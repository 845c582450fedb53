// The pure planning behind --animation, --frames, --fps, --shard and the job-array variables:
// names, ranges, rates, and which shard renders which frames (docs/CLI.md).
#include "app/cli/frame_pattern.h"
#include "app/cli/frame_timing.h"
#include "app/cli/shard_plan.h"

#include <QtTest>

#include <limits>

#include <map>
#include <set>

using namespace glint;
using namespace glint::cli;

namespace {

EnvLookup envOf(std::map<std::string, std::string> vars) {
    return [vars](const std::string& name) -> std::optional<std::string> {
        auto it = vars.find(name);
        return it == vars.end() ? std::nullopt : std::optional<std::string>(it->second);
    };
}

bool throwsInvalid(const std::function<void()>& f) {
    try {
        f();
    } catch (const std::invalid_argument&) {
        return true;
    }
    return false;
}

} // namespace

class TestFramePlan : public QObject {
    Q_OBJECT
private slots:
    void patternPadsAndMatches() {
        const FramePattern p = parseFramePattern("frames/shot_####.exr");
        QCOMPARE(p.frame(7).string(), std::string("frames/shot_0007.exr"));
        QCOMPARE(p.frame(12345).string(), std::string("frames/shot_12345.exr"));
        QCOMPARE(p.match("shot_0007.exr").value_or(-1), 7);
        QCOMPARE(p.match("shot_12345.exr").value_or(-1), 12345);
        QVERIFY(!p.match(".shot_0007.partial-4242.exr"));   // the temporary name of a frame
        QVERIFY(!p.match("shot_007.exr"));             // too short
        QVERIFY(!p.match("shot_00007.exr"));           // padded wider than needed
        QVERIFY(!p.match("shot_00a7.exr"));
        QVERIFY(!p.match("shot_0007.png"));
        // Even a pattern that is only digits never matches a temporary name (it starts with '.').
        QVERIFY(!parseFramePattern("####.png").match(".0003.partial-4242.png"));
    }

    void patternErrors() {
        QVERIFY(throwsInvalid([] { parseFramePattern("frames/shot.exr"); }));
        QVERIFY(throwsInvalid([] { parseFramePattern("frames/##_shot_####.exr"); }));
        QVERIFY(hasFramePlaceholder("a/b_##.png"));
        QVERIFY(!hasFramePlaceholder("a#/b.png")); // only the file name counts
    }

    void rangesAndRates() {
        QCOMPARE(parseFrameRange("3-10").first, 3);
        QCOMPARE(parseFrameRange("3-10").last, 10);
        QCOMPARE(parseFrameRange("5").count(), 1);
        for (const char* bad : {"10-3", "-3", "a-b", "3-", "", "1-2-3", "1.5-3"})
            QVERIFY2(throwsInvalid([bad] { parseFrameRange(bad); }), bad);
        QCOMPARE(parseFps("24000/1001").numerator, 24000);
        QCOMPARE(parseFps("24000/1001").denominator, 1001);
        QCOMPARE(parseFps("30").value(), 30.0);
        for (const char* bad : {"0", "24/0", "29.97", "x", "-24"}) QVERIFY2(throwsInvalid([bad] { parseFps(bad); }), bad);
    }

    // Found by fuzz_cli_options (seeds/cli/crash-frame-range-count-overflow): 0-2147483647 made
    // count() overflow, and the loops over a range's frames never end at INT_MAX.
    void frameNumbersAreBounded() {
        QCOMPARE(parseFrameRange("0-9999999").count(), kMaxFrame + 1);
        for (const char* bad : {"0-10000000", "0-2147483647", "2147483647", "0-2147483648"})
            QVERIFY2(throwsInvalid([bad] { parseFrameRange(bad); }), bad);
    }

    // Found by fuzz_cli_options (seeds/cli/crash-slurm-index-overflow): the task id minus the
    // array's minimum overflowed an int.
    void slurmIndexBeyondAnIntIsRefused() {
        QVERIFY(throwsInvalid([] {
            selectShard(std::nullopt, std::nullopt,
                        envOf({{"SLURM_ARRAY_TASK_ID", "-2147483648"}, {"SLURM_ARRAY_TASK_MIN", "1"}, {"SLURM_ARRAY_TASK_COUNT", "8"}}));
        }));
        QVERIFY(throwsInvalid([] {
            selectShard(std::nullopt, std::nullopt,
                        envOf({{"SLURM_ARRAY_TASK_ID", "2147483647"}, {"SLURM_ARRAY_TASK_MIN", "-2"}, {"SLURM_ARRAY_TASK_COUNT", "8"}}));
        }));
    }

    // The project file bounds neither the timeline's start nor its end: a default range beyond
    // kMaxFrame (or not a number) is refused, never converted to an int.
    void defaultRangeBeyondTheLastFrameIsRefused() {
        Scene scene;
        scene.settings.timeline.end = 10.0;
        QCOMPARE(defaultFrameRange(scene, Fps{24, 1}).last, 240);
        scene.settings.timeline.end = 9'999'999.0 / 24.0;
        QCOMPARE(defaultFrameRange(scene, Fps{24, 1}).last, kMaxFrame);
        for (const double end : {1e300, 9'999'999.0 / 24.0 + 1.0, std::numeric_limits<double>::infinity()}) {
            scene.settings.timeline.end = end;
            QVERIFY2(throwsInvalid([&] { defaultFrameRange(scene, Fps{24, 1}); }), qPrintable(QString::number(end)));
        }
        scene.settings.timeline.start = -1e300;
        scene.settings.timeline.end = 1.0;
        QVERIFY(throwsInvalid([&] { defaultFrameRange(scene, Fps{24, 1}); }));
        try {
            defaultFrameRange(scene, Fps{24, 1});
        } catch (const std::invalid_argument& e) {
            QVERIFY2(std::string(e.what()).find("beyond the last frame number 9999999") != std::string::npos, e.what());
        }
    }

    void frameTimesFollowFps() {
        Scene scene;
        scene.settings.timeline.start = 0.5;
        const Fps ntsc{24000, 1001};
        QCOMPARE(frameTime(scene, ntsc, 0), 0.5);
        QVERIFY(std::abs(frameTime(scene, ntsc, 24000) - (0.5 + 1001.0)) < 1e-9); // exact rational step
        QCOMPARE(frameTime(scene, Fps{24, 1}, 12), 1.0);
        QVERIFY(!hasAnimation(scene));
    }

    void shardParsingAndSelection() {
        QCOMPARE(parseShard("2/4").index, 2);
        for (const char* bad : {"4/4", "-1/4", "1/0", "1", "a/b", "1/2/3"}) QVERIFY2(throwsInvalid([bad] { parseShard(bad); }), bad);
        // Slurm: an array 4-7 is shards 0..3 of 4.
        const Shard slurm = selectShard(std::nullopt, std::nullopt,
                                        envOf({{"SLURM_ARRAY_TASK_ID", "6"}, {"SLURM_ARRAY_TASK_MIN", "4"}, {"SLURM_ARRAY_TASK_COUNT", "4"}}));
        QCOMPARE(slurm.index, 2);
        QCOMPARE(slurm.count, 4);
        // An explicit --shard wins over the environment.
        QCOMPARE(selectShard(Shard{1, 3}, std::nullopt, envOf({{"SLURM_ARRAY_TASK_ID", "6"}})).index, 1);
        // Kubernetes: the index from the environment, the count from --shards.
        const Shard k8s = selectShard(std::nullopt, 5, envOf({{"JOB_COMPLETION_INDEX", "3"}}));
        QCOMPARE(k8s.index, 3);
        QCOMPARE(k8s.count, 5);
        QVERIFY(throwsInvalid([] { selectShard(std::nullopt, std::nullopt, envOf({{"JOB_COMPLETION_INDEX", "3"}})); }));
        QVERIFY(throwsInvalid([] { selectShard(std::nullopt, 3, envOf({{"JOB_COMPLETION_INDEX", "3"}})); }));
        QVERIFY(throwsInvalid([] { selectShard(std::nullopt, 3, envOf({})); }));
        QVERIFY(throwsInvalid([] {
            selectShard(std::nullopt, std::nullopt, envOf({{"SLURM_ARRAY_TASK_ID", "x"}, {"SLURM_ARRAY_TASK_COUNT", "2"}}));
        }));
        QCOMPARE(selectShard(std::nullopt, std::nullopt, envOf({})).count, 1);
    }

    void convergedShardsInterleaveAndCoverEachFrameOnce() {
        const FrameRange range{3, 12};
        QCOMPARE(framesOfShard(range, {1, 4}), (std::vector<int>{4, 8, 12}));
        std::multiset<int> all;
        for (int i = 0; i < 4; ++i)
            for (int f : framesOfShard(range, {i, 4})) all.insert(f);
        QCOMPARE(int(all.size()), range.count());
        for (int f = range.first; f <= range.last; ++f) QCOMPARE(int(all.count(f)), 1);
        QVERIFY(framesOfShard({0, 1}, {3, 4}).empty()); // more shards than frames: idle shards
    }

    void historyChunksAreAnchoredAtFrameZero() {
        // K = 4, W = 2, frames 5..13: chunks [4..7] (from 5), [8..11], [12..13].
        const auto all = chunksOfShard({5, 13}, {0, 1}, 4, 2);
        QCOMPARE(int(all.size()), 3);
        QCOMPARE(all[0].historyStart, 2);
        QCOMPARE(all[0].firstOutput, 5);
        QCOMPARE(all[0].last, 7);
        QCOMPARE(all[1].historyStart, 6);
        QCOMPARE(all[1].firstOutput, 8);
        QCOMPARE(all[2].last, 13);
        // The first chunk has no frames before it to warm up with.
        QCOMPARE(chunksOfShard({0, 3}, {0, 1}, 4, 2)[0].historyStart, 0);
        // Shards take whole chunks, round robin, and the work is the same as in one run.
        const auto s0 = chunksOfShard({5, 13}, {0, 2}, 4, 2);
        const auto s1 = chunksOfShard({5, 13}, {1, 2}, 4, 2);
        QCOMPARE(int(s0.size()), 2);
        QCOMPARE(int(s1.size()), 1);
        QCOMPARE(s0[1].historyStart, all[2].historyStart);
        QCOMPARE(s1[0].firstOutput, all[1].firstOutput);
        // A frame's history does not depend on the range asked for.
        QCOMPARE(chunksOfShard({9, 9}, {0, 1}, 4, 2)[0].historyStart, all[1].historyStart);
        QVERIFY(throwsInvalid([] { chunksOfShard({0, 3}, {0, 1}, 0, 0); }));
    }
};

QTEST_APPLESS_MAIN(TestFramePlan)
#include "test_frame_plan.moc"
