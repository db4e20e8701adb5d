// volren bench's front: the Pareto rows per picture, and the rows that beat the default beyond
// the run's noise (what `volren bench --check-front` fails on).
#include "BenchFront.h"

#include <gtest/gtest.h>

#include <set>

namespace volren::app {
namespace {

BenchRow row(const std::string& config, double ms, double rmse, double noise = 1.0, const std::string& truth = "lit")
{
    BenchRow r;
    r.dataset = "ct";
    r.config = config;
    r.truth = truth;
    r.width = r.height = 64;
    r.frameMs = ms;
    r.frameNoiseMs = noise;
    r.error.rmse = rmse;
    return r;
}

TEST(BenchFront, ARowBetterOnOneAxisAndNotWorseOnTheOtherBeyondTheNoiseBeatsIt)
{
    std::vector<BenchRow> rows = {row("default", 100, 0.010),
                                  row("fast-and-good", 80, 0.008),     // beats it on both axes
                                  row("same-error", 80, 0.010),        // faster at the same error (weak)
                                  row("as-fast", 98, 0.008, 1.5),      // 2 ms faster (margin 5 ms), 20 % better
                                  row("barely-better", 97, 0.0097),    // 3 ms (margin 4 ms), RMSE 3 % lower
                                  row("faster-worse", 70, 0.0102),     // 2 % less accurate
                                  row("slower", 120, 0.002),
                                  row("other-picture", 50, 0.001, 1.0, "unlit"),
                                  row("slow-twin", 130, 0.010),        // the default beats it: faster, as accurate
                                  row("worse-twin", 101, 0.012)};      // and as fast, more accurate
    const std::vector<const BenchRow*> beaten = markRowsBeatingTheDefault(rows);
    ASSERT_EQ(beaten.size(), 3u);
    const std::set<std::string> beats = {"fast-and-good", "same-error", "as-fast"};
    const std::set<std::string> beatenByDefault = {"slow-twin", "worse-twin"};
    for (const BenchRow& r : rows) {
        EXPECT_EQ(r.beatsDefault, beats.count(r.config) == 1) << r.config;
        EXPECT_EQ(r.beatenByDefault, beatenByDefault.count(r.config) == 1) << r.config;
    }

    markPareto(rows);
    auto front = [&](const std::string& name) {
        for (const BenchRow& r : rows)
            if (r.config == name) return r.pareto;
        return false;
    };
    EXPECT_FALSE(front("default"));
    EXPECT_TRUE(front("fast-and-good"));
    EXPECT_TRUE(front("slower"));
    EXPECT_FALSE(front("as-fast")) << "fast-and-good is faster and as accurate";
    EXPECT_FALSE(front("same-error")) << "fast-and-good is as fast and more accurate";
    EXPECT_TRUE(front("other-picture")) << "alone with its own picture";
}

TEST(BenchFront, NothingBeatsADefaultOnTheFront)
{
    std::vector<BenchRow> rows = {row("default", 100, 0.005), row("coarse", 50, 0.02), row("fine", 200, 0.003),
                                  row("noisy-twin", 99, 0.00499, 2.0), row("twin", 100, 0.005)};
    EXPECT_TRUE(markRowsBeatingTheDefault(rows).empty());
}

}  // namespace
}  // namespace volren::app
