// What the shore bake keeps of each wave's march until the cap (shore/march_record.hpp):
// sums and amplitudes held in blocks made only where a march leaves something, so that a
// large world's long waves, which store most tiles, do not take memory for the short
// waves that feel the bottom in a narrow band.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <optional>

#include "shore/march_record.hpp"

namespace tidewater::detail {
namespace {

TEST(MarchRecord, EnergyTakesMemoryOnlyInTheTilesAMarchReached) {
    constexpr int n = 8 * ShoreTiles::kTile;
    MarchedEnergy sums(n, 0.5);
    EXPECT_EQ(sums.bytes(), 0u);
    const auto index = [](int i, int j) { return static_cast<std::size_t>(j) * n + static_cast<std::size_t>(i); };
    sums.add(index(3, 4), 10, false);
    sums.add(index(5, 4), 6, true);
    const std::size_t one_tile = sums.bytes();
    EXPECT_GT(one_tile, 0u);
    sums.add(index(n - 1, n - 1), 2, false);
    EXPECT_EQ(sums.bytes(), 2 * one_tile);
    EXPECT_DOUBLE_EQ(sums.at(3, 4).marched, 5.0);
    EXPECT_DOUBLE_EQ(sums.at(3, 4).breaking, 0.0);
    EXPECT_DOUBLE_EQ(sums.at(5, 4).breaking, 3.0);
    EXPECT_DOUBLE_EQ(sums.at(n - 1, n - 1).marched, 1.0);
    EXPECT_DOUBLE_EQ(sums.at(n / 2, n / 2).marched, 0.0);  // a tile no march reached
    sums.add(index(3, 4), 0xFFFFFFFFu, true);              // saturates rather than wraps
    EXPECT_DOUBLE_EQ(sums.at(3, 4).marched, 0.5 * 0xFFFFFFFFu);
}

TEST(MarchRecord, AmplitudesKeepHalfPrecisionPerWaveAndNothingWhereTheMarchDidNotHold) {
    MarchedAmplitudes record(3, 2);
    const std::size_t texel = ShoreTiles::kSlotTexels + 17;  // stored slot 1
    record.set(texel, 0, 0, 1.5f, false);                    // not reached: no block
    EXPECT_EQ(record.share(texel, 0), 0);
    EXPECT_EQ(record.amplitude(texel, 0), 0.0f);
    EXPECT_FALSE(record.reached(texel, 0));
    record.set(texel, 1, 200, 1.2345f);
    EXPECT_EQ(record.share(texel, 1), 200);
    EXPECT_NEAR(record.amplitude(texel, 1), 1.2345f, 1.2345f * std::ldexp(1.0f, -11));
    EXPECT_EQ(record.share(texel, 0), 0);  // the other wave of the same slot
    EXPECT_EQ(record.share(texel + 1, 1), 0);
    EXPECT_EQ(record.share(2 * ShoreTiles::kSlotTexels + 17, 1), 0);  // the next slot
    EXPECT_TRUE(record.reached(texel, 1));
    EXPECT_FALSE(record.broken(texel, 1));
}

TEST(MarchRecord, ARecordForTheCapAloneKeepsSharesAndAmplitudesOnly) {
    // A bake that keeps no marches for edits reads only the shares and amplitudes: its
    // blocks are three quarters of an edit's, and where the march reached and broke is not
    // kept.
    MarchedAmplitudes for_edits(2, 1), for_cap(2, 1, false);
    EXPECT_EQ(for_cap.bytes(), 0u);
    EXPECT_TRUE(for_edits.keeps_reach());
    EXPECT_FALSE(for_cap.keeps_reach());
    for (MarchedAmplitudes* record : {&for_edits, &for_cap}) {
        record->set(5, 0, 255, 1.0f, true, true);
        record->set(ShoreTiles::kSlotTexels + 5, 0, 0, 0.5f, false);  // not reached: no block
    }
    EXPECT_EQ(for_cap.share(5, 0), 255);
    EXPECT_EQ(for_cap.amplitude(5, 0), 1.0f);
    EXPECT_FALSE(for_cap.reached(5, 0));
    EXPECT_FALSE(for_cap.broken(5, 0));
    EXPECT_TRUE(for_edits.reached(5, 0));
    EXPECT_TRUE(for_edits.broken(5, 0));
    EXPECT_LE(for_cap.bytes(), 3 * ShoreTiles::kSlotTexels + 1);  // a byte of padding at most
    EXPECT_EQ(for_edits.bytes() - for_cap.bytes(), ShoreTiles::kSlotTexels);
    // A copy writes its own blocks, flags included.
    MarchedAmplitudes copy = for_edits;
    copy.set(5, 0, 10, 2.0f, true, false);
    EXPECT_TRUE(for_edits.broken(5, 0));
    EXPECT_FALSE(copy.broken(5, 0));
    EXPECT_EQ(for_edits.share(5, 0), 255);
}

TEST(MarchRecord, ACopySharesItsBlocksUntilWritten) {
    MarchedAmplitudes record(2, 1);
    record.set(5, 0, 255, 1.0f, true, true);
    MarchedAmplitudes copy = record;
    copy.set(5, 0, 100, 2.0f, true, false);
    EXPECT_EQ(record.share(5, 0), 255);
    EXPECT_EQ(record.amplitude(5, 0), 1.0f);
    EXPECT_TRUE(record.broken(5, 0));
    EXPECT_EQ(copy.share(5, 0), 100);
    EXPECT_EQ(copy.amplitude(5, 0), 2.0f);
    EXPECT_FALSE(copy.broken(5, 0));
    // Reached at an angle the march does not hold: no share, but its amplitude is kept.
    copy.set(6, 0, 0, 1.5f, true, false);
    EXPECT_EQ(copy.share(6, 0), 0);
    EXPECT_EQ(copy.amplitude(6, 0), 1.5f);

    MarchedEnergy sums(2 * ShoreTiles::kTile, 1.0);
    sums.add(3, 7, true);
    MarchedEnergy energy_copy = sums;
    energy_copy.assign(3, 0, 2, 1);
    EXPECT_DOUBLE_EQ(sums.at(3, 0).marched, 7.0);
    EXPECT_DOUBLE_EQ(energy_copy.at(3, 0).marched, 2.0);
    EXPECT_DOUBLE_EQ(energy_copy.at(3, 0).breaking, 1.0);
}

TEST(MarchRecord, CapRatiosAreSharedUntilWritten) {
    CapRatios ratios(3);
    ratios.fill(ShoreTiles::kSlotTexels + 4, 1.25f);
    CapRatios copy = ratios;
    copy.set(ShoreTiles::kSlotTexels + 4, 0.5f);
    EXPECT_EQ(ratios.at(ShoreTiles::kSlotTexels + 4), 1.25f);
    EXPECT_EQ(copy.at(ShoreTiles::kSlotTexels + 4), 0.5f);
    EXPECT_EQ(copy.slots(), 3u);
}

TEST(MarchRecord, TheRaysUnderABlendAreFoundAgainButWhereTheMarchHeldItWhole) {
    // A texel where only the march moved is blended again from what the model holds: the
    // rays' capped amplitude is found under the old blend, to float rounding over 1 - s.
    for (int share = 0; share <= 255; share += 15) {
        const auto s = static_cast<std::uint8_t>(share);
        const float rays = 0.8125f, march = 1.375f;
        const float blended = march_blend(s, march, rays, 2.0);
        const std::optional<float> found = rays_under_blend(s, march, blended, 2.0);
        if (share == 255) {
            EXPECT_FALSE(found.has_value());
            continue;
        }
        ASSERT_TRUE(found.has_value()) << share;
        EXPECT_NEAR(*found, rays, 1e-6 * 255.0 / (255.0 - share)) << share;
    }
    // Dry land and no share: the rays' alone, as they are.
    EXPECT_EQ(march_blend(255, 1.5f, 0.25f, 0.0), 0.25f);
    EXPECT_EQ(rays_under_blend(255, 1.5f, 0.25f, -1.0), 0.25f);
    EXPECT_EQ(rays_under_blend(0, 1.5f, 0.25f, 3.0), 0.25f);
}

}  // namespace
}  // namespace tidewater::detail
