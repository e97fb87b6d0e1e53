// A wave's march taken up again after an edit of the seabed (shore_diffraction.hpp,
// rediffract_wave): from the rows the first march kept, over the old and the new depths
// side by side in a window round the edit whose sides are held at the first march's
// values, widened until the edit's wake stays under the tolerance next to them. Checked against a full march over the
// new depths: the first march's amplitude plus the change is within the tolerance of it at every texel, the texels it
// leaves out did not move by more, and the window visits a small part of what a full march does. A march ends a row
// after the last texel it fills, and an edit past there is marched on from the last row it kept.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>

#include "shore/march_record.hpp"
#include "shore/shore_diffraction.hpp"
#include "tidewater/constants.hpp"

namespace tidewater::detail {
namespace {

constexpr int kN = 512;
constexpr double kTexel = 2.0;  // a 1024 m square

/// A plane beach rising along +z from 12 m of water to 4 m of land, with a shoal of
/// `shoal` m (a Gaussian 8 m wide: a brush stroke) at `at` (x, z).
ShoreField beach(double shoal, glm::dvec2 at = glm::dvec2(500.0, 440.0)) {
    ShoreField f;
    f.resolution = kN;
    f.texel = kTexel;
    f.corner = glm::dvec2(0.0);
    std::vector<float>& depth = f.depth.write();
    depth.resize(static_cast<std::size_t>(kN) * kN);
    for (int j = 0; j < kN; ++j)
        for (int i = 0; i < kN; ++i) {
            const glm::dvec2 p = f.texel_center(i, j);
            const double r2 = glm::dot(p - at, p - at);
            depth[f.index(i, j)] = static_cast<float>(12.0 - 16.0 * p.y / 1024.0 - shoal * std::exp(-r2 / (8.0 * 8.0)));
        }
    return f;
}

/// A wave 40 m long in deep water, 0.4 m high, heading 20 degrees off +z: it breaks on the beach.
Wave wave() {
    Wave w;
    const double angle = 20.0 * kPi / 180.0;
    w.dir_x = std::sin(angle);
    w.dir_z = std::cos(angle);
    w.k = kTwoPi / 40.0;
    w.omega = std::sqrt(kGravity * w.k);
    w.amplitude = 0.2;
    return w;
}

/// A shoal of `shoal` m at `at` re-marched from the march over the plane beach: its change
/// added to the first march against a full march over the new depths. The points the
/// re-marches visited over what two full marches from the first row do. With
/// `held_in_half`, the first march's texels are given as the model holds them (in half
/// precision): a wide window is then the whole row, marched once.
double remarched_shoal(double shoal, glm::dvec2 at, bool held_in_half = false) {
    const ShoreField before = beach(0.0, at), after = beach(shoal, at);
    const Wave w = wave();
    const SeaState sea = sea_state(std::span<const Wave>(&w, 1));
    const auto fill_all = [](std::size_t) { return false; };
    KeptMarch kept;
    const DiffractedWave old_march = diffract_wave(w, sea, before, fill_all, nullptr, &kept);
    const auto t0 = std::chrono::steady_clock::now();
    const DiffractedWave new_march = diffract_wave(w, sea, after, fill_all);
    const auto t1 = std::chrono::steady_clock::now();
    EXPECT_GT(kept.rows(), 2u);

    // Where the shoal's depths differ from the plane's by over a millimetre.
    const WorldRect changed{at - 30.0, at + 30.0};
    const PatchedDepths patched{&before, 0, 0, kN, kN, after.depth.values()};
    Remarch how;
    if (held_in_half)
        how.marched_before = [&](std::size_t k) -> std::optional<MarchedTexel> {
            const float held = MarchedAmplitudes::held(old_march.amplitude[k]);
            return MarchedTexel{held, old_march.share[k] > 0, old_march.broken[k] != 0,
                                MarchedAmplitudes::rounding(held)};
        };
    const DiffractionChange change = rediffract_wave(w, sea, before, patched, kept, changed, fill_all, how);
    const auto t2 = std::chrono::steady_clock::now();

    std::vector<float> amplitude = old_march.amplitude;
    if (held_in_half)
        for (float& a : amplitude) a = MarchedAmplitudes::held(a);
    std::vector<std::uint8_t> share = old_march.share, broken = old_march.broken;
    for (std::size_t c = 0; c < change.texels.size(); ++c) {
        amplitude[change.texels[c]] = change.amplitude[c];
        share[change.texels[c]] = change.share[c];
        broken[change.texels[c]] = change.broken[c];
    }
    double worst = 0.0, largest_change = 0.0;
    std::size_t moved = 0, reached_differs = 0, broken_differs = 0, over = 0;
    for (std::size_t k = 0; k < amplitude.size(); ++k) {
        const double error = std::abs(amplitude[k] - new_march.amplitude[k]);
        worst = std::max(worst, error);
        over += error > 2.0 * kMarchAmplitudeTolerance ? 1 : 0;
        largest_change =
            std::max(largest_change, static_cast<double>(std::abs(new_march.amplitude[k] - old_march.amplitude[k])));
        moved += std::abs(new_march.amplitude[k] - old_march.amplitude[k]) > kMarchAmplitudeTolerance ? 1 : 0;
        reached_differs += share[k] != new_march.share[k] ? 1 : 0;
        broken_differs += broken[k] != new_march.broken[k] ? 1 : 0;
    }
    // Both depths marched in full from the first row: the frame is a square turned with the wave.
    const std::size_t full =
        2 * static_cast<std::size_t>(kept.points) * static_cast<std::size_t>(kept.points - kept.start);
    std::printf(
        "shoal %.1f m at (%.0f, %.0f): texels changed %zu (moved over the tolerance in a full march: %zu), "
        "largest change %.3f, worst error %.2e (%zu texels over twice the tolerance), windows %d, points visited %zu "
        "of %zu; %.3f s against %.3f s "
        "for a full march; kept %.1f MB\n",
        shoal, at.x, at.y, change.texels.size(), moved, largest_change, worst, over, change.windows,
        change.points_visited, full, std::chrono::duration<double>(t2 - t1).count(),
        std::chrono::duration<double>(t1 - t0).count(), static_cast<double>(kept.bytes()) / 1e6);
    EXPECT_GT(largest_change, 0.05);  // the shoal focuses the wave
    EXPECT_GT(change.texels.size(), moved / 2);
    // Within twice the tolerance (the half precision's rounding besides) but at a texel or
    // two on the breaker line, where a change far under the tolerance may move the onset
    // of breaking.
    EXPECT_LT(over, moved / 1000 + 3);
    EXPECT_LT(worst, 0.06);
    EXPECT_EQ(reached_differs, 0u);
    // Where a texel's blend sits at a half, the two marches may break a row apart.
    EXPECT_LT(broken_differs, moved / 100 + 5);
    return static_cast<double>(change.points_visited) / static_cast<double>(full);
}

TEST(ShoreRediffraction, AnEditsChangeAddedToTheFirstMarchIsTheMarchOverTheNewDepths) {
    // 2 m on 5 m of water, 290 m off the shoreline: the shoal's wake (over 1e-3) fans out
    // over most of the beach downwave, and the window with it. The march is taken up at
    // the kept row before the edit: the two marches cost under 3/4 of two in full.
    EXPECT_LT(remarched_shoal(2.0, {500.0, 440.0}), 0.75);
    // Half a metre on 1.7 m of water, 80 m off it: its wake reaches the shoreline narrow;
    // the window is widened until the new march agrees with the old next to its sides.
    EXPECT_LT(remarched_shoal(0.5, {500.0, 660.0}), 0.45);
}

TEST(ShoreRediffraction, AWideWindowIsTheWholeRowMarchedOnceOverTheNewDepths) {
    // The first march's texels as the model holds them: a window a third of the march
    // wide or more is the whole row, marched over the new depths alone and compared with
    // them. The 2 m shoal's wake widens its window to the whole row: one march from the
    // kept row before it, under half of two in full.
    EXPECT_LT(remarched_shoal(2.0, {500.0, 440.0}, true), 0.4);
    EXPECT_LT(remarched_shoal(0.5, {500.0, 660.0}, true), 0.3);
}

/// The worst difference of `march` plus `change` from `target`'s amplitude factors.
double worst_after(const DiffractedWave& march, const DiffractionChange& change, const DiffractedWave& target) {
    std::vector<float> amplitude = march.amplitude;
    for (std::size_t c = 0; c < change.texels.size(); ++c) amplitude[change.texels[c]] = change.amplitude[c];
    double worst = 0.0;
    for (std::size_t k = 0; k < amplitude.size(); ++k)
        worst = std::max(worst, static_cast<double>(std::abs(amplitude[k] - target.amplitude[k])));
    return worst;
}

TEST(ShoreRediffraction, ASecondEditTakesUpTheMarchTheFirstLeft) {
    // A stroke, then another downwave of it whose window crosses the first one's wake: the
    // second is taken up from what the first left, not from the march before both.
    const glm::dvec2 first_at{500.0, 600.0}, second_at{540.0, 680.0};
    const ShoreField plane = beach(0.0, first_at), one = beach(1.0, first_at);
    ShoreField two = one;
    {
        const ShoreField bump = beach(0.5, second_at), flat = beach(0.0, second_at);
        std::vector<float>& depth = two.depth.write();
        for (std::size_t k = 0; k < depth.size(); ++k) depth[k] += bump.depth[k] - flat.depth[k];
    }
    const Wave w = wave();
    const SeaState sea = sea_state(std::span<const Wave>(&w, 1));
    const auto fill_all = [](std::size_t) { return false; };
    KeptMarch kept;
    diffract_wave(w, sea, plane, fill_all, nullptr, &kept);
    const DiffractedWave over_one = diffract_wave(w, sea, one, fill_all);
    const DiffractedWave over_two = diffract_wave(w, sea, two, fill_all);

    KeptMarch after_one = kept;
    Remarch keeping;
    keeping.updated = &after_one;
    rediffract_wave(w, sea, plane, PatchedDepths{&plane, 0, 0, kN, kN, one.depth.values()}, kept,
                    {first_at - 30.0, first_at + 30.0}, fill_all, keeping);
    const PatchedDepths to_two{&one, 0, 0, kN, kN, two.depth.values()};
    const WorldRect second{second_at - 30.0, second_at + 30.0};
    const double taken_up =
        worst_after(over_one, rediffract_wave(w, sea, one, to_two, after_one, second, fill_all), over_two);
    // From the rows kept before the first stroke, the second's window starts from a march
    // that never saw the first.
    const double stale = worst_after(over_one, rediffract_wave(w, sea, one, to_two, kept, second, fill_all), over_two);
    std::printf(
        "a second stroke taken up from what the first left: worst error %.2e (%.2e from the rows kept before "
        "the first)\n",
        taken_up, stale);
    EXPECT_LT(taken_up, 2.0 * kMarchAmplitudeTolerance);
    EXPECT_GT(stale, 2.0 * kMarchAmplitudeTolerance);
}

TEST(ShoreRediffraction, AComponentOfARandomSeaEndsItsMarchWhereTheEditsWakeDiesOut) {
    // Half a metre on 1.7 m of water, 80 m off the shoreline, under a sea of two waves:
    // the beach's and one half as high from 10 degrees off +z the other way. Each
    // component breaks at the sea's height, marched over each depth.
    const glm::dvec2 at{500.0, 660.0};
    const auto before = std::make_shared<ShoreField>(beach(0.0, at));
    const auto after = std::make_shared<ShoreField>(beach(0.5, at));
    Wave second = wave();
    second.dir_x = -std::sin(10.0 * kPi / 180.0);
    second.dir_z = std::cos(10.0 * kPi / 180.0);
    second.amplitude = 0.1;
    const Wave waves[] = {wave(), second};
    const SeaState sea = sea_state(waves);
    ASSERT_EQ(sea.components, 2);
    const SeaHeight sea_before = march_sea(waves, sea, before), sea_after = march_sea(waves, sea, after);
    const auto fill_all = [](std::size_t) { return false; };
    // What the component's march is taken up over: the shoal's reach and where the sea's
    // height moved, a texel round it.
    WorldRect changed{at - 30.0, at + 30.0};
    std::size_t sea_moved = 0;
    for (int j = 0; j < kN; ++j)
        for (int i = 0; i < kN; ++i) {
            const std::size_t k = before->index(i, j);
            if (sea_before.height[k] == sea_after.height[k]) continue;
            ++sea_moved;
            changed.lo = glm::min(changed.lo, before->texel_center(i, j) - kTexel);
            changed.hi = glm::max(changed.hi, before->texel_center(i, j) + kTexel);
        }
    ASSERT_GT(sea_moved, 0u);

    for (const Wave& w : waves) {
        KeptMarch kept;
        const DiffractedWave first = diffract_wave(w, sea, *before, fill_all, &sea_before, &kept);
        Remarch how;
        how.sea_before = &sea_before;
        how.sea_after = &sea_after;
        how.marched_before = [&](std::size_t k) -> std::optional<MarchedTexel> {
            const float held = MarchedAmplitudes::held(first.amplitude[k]);
            return MarchedTexel{held, first.share[k] > 0, first.broken[k] != 0, MarchedAmplitudes::rounding(held)};
        };
        const PatchedDepths patched{before.get(), 0, 0, kN, kN, after->depth.values()};
        const DiffractionChange to_the_end = rediffract_wave(w, sea, *before, patched, kept, changed, fill_all, how);
        how.settles = true;
        const DiffractionChange settled = rediffract_wave(w, sea, *before, patched, kept, changed, fill_all, how);
        std::printf(
            "a component %.2f m high: %zu texels changed; points visited %zu marched to the last texel it fills, "
            "%zu ended where the wake died out\n",
            2.0 * w.amplitude, to_the_end.texels.size(), to_the_end.points_visited, settled.points_visited);
        // The wake breaks on the beach and dies out there: the march ends before the
        // shoreline, where it ends without, and leaves the same texels with the same values.
        EXPECT_GT(to_the_end.texels.size(), 0u);
        EXPECT_LT(static_cast<double>(settled.points_visited), 0.9 * static_cast<double>(to_the_end.points_visited));
        EXPECT_EQ(settled.texels, to_the_end.texels);
        EXPECT_EQ(settled.amplitude, to_the_end.amplitude);
        EXPECT_EQ(settled.broken, to_the_end.broken);
    }
}

/// Open water 12 m deep with a bank across the waves' path (6 m at its crest, z = 400 m)
/// and shoals of `shoal` m (Gaussians 8 m wide) at `at`: a march fills the water under
/// 11 m (the bank and what a shoal raises), the rest is the open sea's.
ShoreField bank(std::initializer_list<std::pair<glm::dvec2, double>> shoals) {
    ShoreField f = beach(0.0);
    std::vector<float>& depth = f.depth.write();
    for (int j = 0; j < kN; ++j)
        for (int i = 0; i < kN; ++i) {
            const glm::dvec2 p = f.texel_center(i, j);
            double h = 12.0 - 6.0 * std::exp(-(p.y - 400.0) * (p.y - 400.0) / (40.0 * 40.0));
            for (const auto& [at, shoal] : shoals) h -= shoal * std::exp(-glm::dot(p - at, p - at) / (8.0 * 8.0));
            depth[f.index(i, j)] = static_cast<float>(h);
        }
    return f;
}

TEST(ShoreRediffraction, AMarchEndsAfterTheLastTexelItFillsAndAnEditPastThereMarchesOn) {
    const glm::dvec2 on_bank{500.0, 400.0}, past_bank{500.0, 800.0};
    const ShoreField plain = bank({}), one = bank({{on_bank, 1.0}}), two = bank({{on_bank, 1.0}, {past_bank, 3.0}}),
                     three = bank({{on_bank, 1.0}, {past_bank, 3.5}});
    const Wave w = wave();
    const SeaState sea = sea_state(std::span<const Wave>(&w, 1));
    auto open_sea = [](const ShoreField& f) { return [&f](std::size_t k) { return f.depth[k] > 11.0f; }; };

    // The bank alone: the march ends a row after its last texel. Made to fill one texel
    // more at the grid's far corner, it runs on to there and leaves the bank as it was.
    KeptMarch kept, kept_far;
    const DiffractedWave over_plain = diffract_wave(w, sea, plain, open_sea(plain), nullptr, &kept);
    const std::size_t far = plain.index(kN - 1, kN - 1);
    const DiffractedWave far_too = diffract_wave(
        w, sea, plain, [&](std::size_t k) { return k != far && plain.depth[k] > 11.0f; }, nullptr, &kept_far);
    std::size_t filled = 0, differ = 0;
    for (std::size_t k = 0; k < over_plain.amplitude.size(); ++k) {
        if (k == far || over_plain.share[k] == 0) continue;
        ++filled;
        differ += over_plain.amplitude[k] != far_too.amplitude[k] || over_plain.broken[k] != far_too.broken[k] ? 1 : 0;
    }
    std::printf("the bank's march ends at row %d, the one to the far corner at row %d (from row %d)\n", kept.end(),
                kept_far.end(), kept.start);
    EXPECT_GT(filled, 1000u);
    EXPECT_EQ(differ, 0u);
    EXPECT_LT(kept.end() - kept.start, (kept_far.end() - kept.start) * 3 / 5);
    EXPECT_EQ(kept.rows(), static_cast<std::size_t>((kept.end() - kept.start) / KeptMarch::kKeptRowsEvery + 1));

    // A stroke on the bank, then a shoal raised past the march's end (water it now fills),
    // then that shoal raised further: each taken up from what the one before left, whole
    // rows against the first march's texels, and each within twice the tolerance of a
    // full march over its depths.
    auto held = [](const DiffractedWave& march) {
        return [&march](std::size_t k) -> std::optional<MarchedTexel> {
            return MarchedTexel{march.amplitude[k], march.share[k] > 0, march.broken[k] != 0, 0.0};
        };
    };
    const DiffractedWave over_one = diffract_wave(w, sea, one, open_sea(one));
    const DiffractedWave over_two = diffract_wave(w, sea, two, open_sea(two));
    const DiffractedWave over_three = diffract_wave(w, sea, three, open_sea(three));
    KeptMarch after_one = kept, after_two;
    Remarch how;
    how.updated = &after_one;
    how.marched_before = held(over_plain);
    const DiffractionChange first =
        rediffract_wave(w, sea, plain, PatchedDepths{&plain, 0, 0, kN, kN, one.depth.values()}, kept,
                        {on_bank - 30.0, on_bank + 30.0}, open_sea(one), how);
    EXPECT_LT(worst_after(over_plain, first, over_one), 2.0 * kMarchAmplitudeTolerance);
    EXPECT_EQ(after_one.end(), kept.end());

    after_two = after_one;
    how.updated = &after_two;
    how.marched_before = held(over_one);
    const PatchedDepths to_two{&one, 0, 0, kN, kN, two.depth.values()};
    const WorldRect second{past_bank - 30.0, past_bank + 30.0};
    const DiffractionChange past = rediffract_wave(w, sea, one, to_two, after_one, second, open_sea(two), how);
    // Without the first march's texels the old and the new depths are marched side by
    // side, and the change is against the old depths' march at the texels the new ones fill.
    const DiffractionChange side_by_side = rediffract_wave(w, sea, one, to_two, after_one, second, open_sea(two));
    const DiffractedWave one_filled_as_two = diffract_wave(w, sea, one, open_sea(two));
    const double past_error = worst_after(over_one, past, over_two),
                 side_by_side_error = worst_after(one_filled_as_two, side_by_side, over_two);
    std::printf(
        "a shoal past the march's end: %zu texels changed, worst error %.2e (%.2e side by side); the march "
        "now ends at row %d\n",
        past.texels.size(), past_error, side_by_side_error, after_two.end());
    EXPECT_GT(past.texels.size(), 30u);
    EXPECT_LT(past_error, 2.0 * kMarchAmplitudeTolerance);
    EXPECT_LT(side_by_side_error, 2.0 * kMarchAmplitudeTolerance);
    EXPECT_GT(after_two.end(), after_one.end());
    EXPECT_EQ(after_two.rows(),
              static_cast<std::size_t>((after_two.end() - after_two.start) / KeptMarch::kKeptRowsEvery + 1));

    // The rows the second edit added are what a third takes up.
    const DiffractionChange third = rediffract_wave(
        w, sea, two, PatchedDepths{&two, 0, 0, kN, kN, three.depth.values()}, after_two, second, open_sea(three));
    const double third_error = worst_after(over_two, third, over_three);
    std::printf("the shoal raised again: %zu texels changed, worst error %.2e\n", third.texels.size(), third_error);
    EXPECT_GT(third.texels.size(), 10u);
    EXPECT_LT(third_error, 2.0 * kMarchAmplitudeTolerance);
}

TEST(ShoreRediffraction, TheSameDepthsChangeNothing) {
    const ShoreField before = beach(0.0);
    const Wave w = wave();
    const SeaState sea = sea_state(std::span<const Wave>(&w, 1));
    // Every texel under 11 m is filled: the march starts just before them.
    const auto deep = [&](std::size_t k) { return before.depth[k] > 11.0f; };
    KeptMarch kept;
    diffract_wave(w, sea, before, deep, nullptr, &kept);
    ASSERT_GT(kept.rows(), 0u);
    const DiffractionChange change = rediffract_wave(w, sea, before, PatchedDepths{&before, 0, 0, 0, 0, {}}, kept,
                                                     WorldRect{{-1e300, -1e300}, {1e300, 1e300}}, deep);
    EXPECT_TRUE(change.texels.empty());
    EXPECT_EQ(change.windows, 1);
}

}  // namespace
}  // namespace tidewater::detail
