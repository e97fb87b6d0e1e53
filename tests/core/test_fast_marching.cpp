// The eikonal solve behind the shore model's phase, and its re-solve round a local change
// (an editor's stroke under the water): the re-solve agrees with a full solve of the
// changed grid everywhere (bit for bit when asked to within 1e-9: the frozen texels round
// the window are taken up in the order the full march reaches them), while marching a
// window that covers the change and what lies downstream of it, not the grid. Deep
// water for a wave is told from its depth as the marches tell it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "shore/fast_marching.hpp"

namespace tidewater::detail {
namespace {

constexpr int kN = 128;

/// A beach: waves enter from deep water at the -x edge (sources up to x = 16) and slow
/// toward the shoreline at x = 112, dry land beyond; a bump of slowness `gain` over
/// `bump` (none when gain is 1).
struct Beach {
    TexelWindow bump{0, 0, 0, 0};
    double gain = 1.0;
    float slowness(int i, int j) const {
        if (i >= 112) return 0.0f;
        const double s = 0.3 + 0.7 * i / 112.0 + 0.05 * std::sin(0.2 * j);
        return static_cast<float>(bump.contains(i, j) ? s * gain : s);
    }
    double source(int i, int j) const { return i < 16 ? 0.3 * i + 0.02 * j : kUnreached; }
    std::vector<double> solved() const {
        std::vector<float> s(kN * kN);
        std::vector<double> v(kN * kN);
        for (int j = 0; j < kN; ++j)
            for (int i = 0; i < kN; ++i) {
                s[j * kN + i] = slowness(i, j);
                v[j * kN + i] = source(i, j);
            }
        fast_march(s, v, kN, 1.0);
        return v;
    }
};

struct Remarched {
    MarchWindow window;
    double largest_error = 0.0;  ///< against a full solve of the changed grid
};

Remarched remarch_after(const Beach& before, const Beach& after, double tolerance, int margin) {
    const std::vector<double> old_values = before.solved(), reference = after.solved();
    MarchChange change;
    change.n = kN;
    change.h = 1.0;
    change.slowness = [&](int i, int j) { return after.slowness(i, j); };
    change.source = [&](int i, int j) { return after.source(i, j); };
    change.before = [&](int i, int j) { return old_values[j * kN + i]; };
    change.changed = after.bump;
    change.tolerance = tolerance;
    Remarched r{remarch(change, margin), 0.0};
    for (int j = 0; j < kN; ++j)
        for (int i = 0; i < kN; ++i) {
            const double v = r.window.window.contains(i, j) ? r.window.at(i, j) : old_values[j * kN + i];
            const double ref = reference[j * kN + i];
            if (std::isinf(ref) || std::isinf(v)) {
                EXPECT_EQ(std::isinf(ref), std::isinf(v)) << i << ", " << j;
                continue;
            }
            r.largest_error = std::max(r.largest_error, std::abs(v - ref));
        }
    return r;
}

TEST(FastMarching, ARemarchAgreesWithAFullSolveAndStaysDownstream) {
    const Beach before;
    for (const double gain : {1.4, 0.7}) {  // a shoal that slows the waves, a hole that speeds them
        Beach after;
        after.bump = {60, 58, 66, 64};
        after.gain = gain;
        const Remarched r = remarch_after(before, after, 1e-9, 4);
        const TexelWindow& w = r.window.window;
        std::printf("gain %.1f: window [%d, %d) x [%d, %d) after %d solves, largest error %.2e\n", gain, w.i0, w.i1,
                    w.j0, w.j1, r.window.solves, r.largest_error);
        EXPECT_LT(r.largest_error, 1e-6) << gain;
        EXPECT_GE(w.i0, 40) << "nothing upstream of the change is marched again";
        EXPECT_GE(w.i1, 112) << "the change reaches the shoreline downstream";
        EXPECT_LT(static_cast<double>((w.i1 - w.i0) * (w.j1 - w.j0)), 0.5 * kN * kN);
    }
}

// A slight change (0.2 % slower over 4 x 4 texels) shifts the arrivals downstream by
// less than 0.01: with that tolerance its window does not grow, and the values it leaves
// stay within the tolerance; asked for 1e-9, the window follows the change to the shore.
TEST(FastMarching, ATolerantRemarchStaysWithinItsTolerance) {
    const Beach before;
    Beach after;
    after.bump = {40, 60, 44, 64};
    after.gain = 1.002;
    const Remarched exact = remarch_after(before, after, 1e-9, 2);
    const Remarched tolerant = remarch_after(before, after, 1e-2, 2);
    auto area = [](const TexelWindow& w) { return (w.i1 - w.i0) * (w.j1 - w.j0); };
    std::printf("exact: %d texels marched, tolerant: %d, its largest error %.2e\n", area(exact.window.window),
                area(tolerant.window.window), tolerant.largest_error);
    EXPECT_LT(exact.largest_error, 1e-6);
    EXPECT_LT(tolerant.largest_error, 1e-2);
    EXPECT_LT(4 * area(tolerant.window.window), area(exact.window.window));
}

TEST(FastMarching, AChangeThatChangesNothingMarchesOnlyItsWindow) {
    const Beach before;
    Beach same;
    same.bump = {60, 58, 66, 64};  // gain 1: the same slowness
    const Remarched r = remarch_after(before, same, 1e-9, 3);
    EXPECT_EQ(r.window.solves, 1);
    EXPECT_EQ(r.window.window.i0, 57);
    EXPECT_EQ(r.window.window.i1, 69);
    EXPECT_LT(r.largest_error, 1e-9);
}

TEST(FastMarching, DeepWaterIsToldFromTheDepthAsTheMarchedWavenumberTellsIt) {
    // Periods of 0.5 to 30 s; depths across a tenth either side of where k h = pi, finest
    // round it, where the shortcut hands over to the solve.
    int deep = 0, shallow = 0;
    for (double period = 0.5; period <= 30.0; period *= 1.07) {
        const double omega = 2.0 * 3.14159265358979323846 / period;
        const double threshold = kDeepKh * std::tanh(kDeepKh) * 9.81 / (omega * omega);
        for (int s = -2000; s <= 2000; ++s) {
            const double offset = s * (std::abs(s) <= 1000 ? 2e-7 : 5e-5);
            const double h = threshold * (1.0 + offset);
            const bool solved = marched_deep(marched_wavenumber(omega, h), h);
            ASSERT_EQ(marched_deep_water(omega, h), solved) << "T " << period << " s, h " << h << " m";
            (solved ? deep : shallow) += 1;
        }
        EXPECT_FALSE(marched_deep_water(omega, 0.0));
        EXPECT_FALSE(marched_deep_water(omega, -threshold));
        EXPECT_FALSE(marched_deep_water(omega, std::nan("")));
    }
    // Both answers come up, so the sweep crosses the threshold.
    EXPECT_GT(deep, 1000);
    EXPECT_GT(shallow, 1000);
}

}  // namespace
}  // namespace tidewater::detail
