// The height texture's patch for an edited heightmap (no device): the texels it writes
// are those a fresh sampling of the edited terrain gives, every texel outside it is the
// same in both samplings, and edits it cannot express are sampled anew.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "terrain_mesh.hpp"

namespace tidewater {
namespace {

using render::detail::height_texture_patch;
using render::detail::sample_terrain_heights;

constexpr int kPixels = 129;

Terrain hills(std::shared_ptr<Gray16Image> image) {
    HeightmapTerrain map;
    map.size = glm::dvec2(2.0 * (kPixels - 1));  // 2 m pixels
    map.min_height = -20.0;
    map.max_height = 40.0;
    map.image = std::move(image);
    return Terrain(map);
}

std::shared_ptr<Gray16Image> hill_pixels() {
    auto image = std::make_shared<Gray16Image>();
    image->width = image->height = kPixels;
    for (int j = 0; j < kPixels; ++j)
        for (int i = 0; i < kPixels; ++i)
            image->pixels.push_back(static_cast<std::uint16_t>(30000 + 20000 * std::sin(i / 9.0) * std::cos(j / 13.0)));
    return image;
}

/// The pixels of `from` with those in [i0, i1] x [j0, j1] lowered by `by`.
std::shared_ptr<Gray16Image> dug(const Gray16Image& from, int i0, int j0, int i1, int j1, int by) {
    auto image = std::make_shared<Gray16Image>(from);
    for (int j = j0; j <= j1; ++j)
        for (int i = i0; i <= i1; ++i) image->pixels[static_cast<std::size_t>(j) * kPixels + i] -= by;
    return image;
}

/// Checks the patch from `before` to `after` sampled within `max_bytes`.
void expect_patch_is_the_fresh_sampling(const Terrain& before, const Terrain& after, std::uint64_t max_bytes) {
    const auto a = sample_terrain_heights(before, max_bytes), b = sample_terrain_heights(after, max_bytes);
    ASSERT_EQ(a.lowest, b.lowest) << "an edit inside the range keeps the encoding";
    ASSERT_EQ(a.highest, b.highest);
    const auto patch = height_texture_patch(a, before, after);
    ASSERT_TRUE(patch);
    ASSERT_GT(patch->width * patch->height, 0u);
    EXPECT_LT(patch->width * patch->height, a.width * a.height / 4) << "local";
    std::size_t changed = 0;
    for (std::uint32_t j = 0; j < a.height; ++j)
        for (std::uint32_t i = 0; i < a.width; ++i) {
            const std::size_t k = static_cast<std::size_t>(j) * a.width + i;
            const bool inside =
                i >= patch->i0 && i < patch->i0 + patch->width && j >= patch->j0 && j < patch->j0 + patch->height;
            if (inside) {
                EXPECT_EQ(patch->texels[(j - patch->j0) * patch->width + (i - patch->i0)], b.texels[k])
                    << i << "," << j;
                changed += a.texels[k] != b.texels[k];
            } else {
                EXPECT_EQ(a.texels[k], b.texels[k]) << "outside the patch " << i << "," << j;
            }
        }
    EXPECT_GT(changed, 0u);
}

TEST(HeightTexturePatch, WritesWhatAFreshSamplingGives) {
    const auto pixels = hill_pixels();
    const Terrain before = hills(pixels);
    const Terrain after = hills(dug(*pixels, 40, 50, 52, 58, 800));
    expect_patch_is_the_fresh_sampling(before, after, std::uint64_t{1} << 30);  // every pixel
    expect_patch_is_the_fresh_sampling(before, after, 2ull * 70 * 70);          // every second pixel
    // An edit at the heightmap's edge.
    expect_patch_is_the_fresh_sampling(before, hills(dug(*pixels, 0, 100, 6, kPixels - 1, 500)), 1u << 30);

    // Nothing changed (the same pixels in another image): an empty patch.
    const auto same = height_texture_patch(sample_terrain_heights(before, 1u << 30), before,
                                           hills(std::make_shared<Gray16Image>(*pixels)));
    ASSERT_TRUE(same);
    EXPECT_TRUE(same->texels.empty());
}

TEST(HeightTexturePatch, EditsItCannotExpressAreSampledAnew) {
    const auto pixels = hill_pixels();
    const Terrain before = hills(pixels);
    const auto sampled = sample_terrain_heights(before, 1u << 30);
    // Above the texture's highest height: its encoding changes.
    auto peak = std::make_shared<Gray16Image>(*pixels);
    peak->pixels[64 * kPixels + 64] = 65535;
    EXPECT_FALSE(height_texture_patch(sampled, before, hills(peak)));
    // Another heightmap size, another shape, a cut.
    auto map = std::get<HeightmapTerrain>(before.shape());
    map.size *= 2.0;
    EXPECT_FALSE(height_texture_patch(sampled, before, Terrain(map)));
    EXPECT_FALSE(height_texture_patch(sampled, before, Terrain(FlatTerrain{})));
    auto cut = std::make_shared<TerrainCut>();
    cut->nx = cut->nz = 2;
    cut->depth.assign(4, 1.0f);
    EXPECT_FALSE(height_texture_patch(sampled, before, before.with_cuts({cut})));
}

}  // namespace
}  // namespace tidewater
