// Saved lakes and rivers: the default scene's tarn, brook and rill survive saving and
// loading within their 16-bit encodings (the brook still carries its discharge within
// 1% and the queries agree within millimetres), the saved folder is loaded by the scene
// that names it, and bakes that no longer fit the bodies or the terrain are refused
// with the file and field.
#include <filesystem>
#include <fstream>

#include "../baked_scene.hpp"
#include "test_helpers.hpp"
#include "tidewater/detail/bodies_bake_folder.hpp"
#include "tidewater/detail/water_bodies.hpp"
#include "tidewater/scene_bake.hpp"
#include "tidewater/world_query.hpp"

namespace tidewater {
namespace {

namespace fs = std::filesystem;
using detail::RiverBake;

/// Flux of the discharge field across the section at centreline sample k, m^3/s.
double discharge_through(const RiverBake& r, std::size_t k) {
    const glm::dvec2 p = r.centreline[k];
    const glm::dvec2 d = r.centreline[k + 1] - r.centreline[k - 1];
    const glm::dvec2 t = d / std::hypot(d.x, d.y), n{-t.y, t.x};
    const double reach = 0.5 * r.width[k] + 4.0 * r.grid.texel, step = r.grid.texel / 16.0;
    double q = 0.0;
    for (double s = -reach; s <= reach; s += step) {
        const glm::dvec2 x = p + s * n;
        q += (r.grid.sample(r.discharge_x, x) * t.x + r.grid.sample(r.discharge_z, x) * t.y) * step;
    }
    return q;
}

std::string refusal(const Scene& scene) {
    auto loaded = bake_scene(scene);
    return loaded ? std::string("(loaded)") : loaded.error().message;
}

/// The default scene with its shore model at a small resolution (a quick bake), baked
/// and saved to a temporary folder; `named` is the parsed scene naming that bake.
class BodiesBakeFolder : public ::testing::Test {
  protected:
    void SetUp() override {
        auto scene = default_scene();
        ASSERT_TRUE(scene.ok());
        parsed = std::move(scene).value();
        parsed.shore.resolution = 96;
        auto made = bake_scene(parsed);
        ASSERT_TRUE(made.ok()) << made.error().message;
        baked = std::move(made).value();
        folder = dir.path / "bake";
        ASSERT_TRUE(save_scene_bake(folder, *baked).ok());
        named = parsed;
        named.shore.bake_folder = folder;
    }
    test::TempDir dir{"tidewater_bodies_test_"};
    Scene parsed, named;
    std::shared_ptr<const Scene> baked;
    fs::path folder;
};

TEST_F(BodiesBakeFolder, SavedLakesAndRiversLoadWithinTheirEncodingAndKeepTheDischarge) {
    EXPECT_TRUE(fs::exists(folder / "shore.json"));
    EXPECT_TRUE(fs::exists(folder / "bodies.json"));
    EXPECT_TRUE(fs::exists(folder / "lake_00" / "shore.json"));
    auto loaded = bake_scene(named);
    ASSERT_TRUE(loaded.ok()) << loaded.error().message;
    EXPECT_TRUE((*loaded)->bake->loaded);
    EXPECT_TRUE((*loaded)->baked());
    const auto& before = *baked->bake->bodies;
    const auto& after = *(*loaded)->bake->bodies;
    ASSERT_EQ(after.rivers.size(), before.rivers.size());
    ASSERT_EQ(after.lakes.size(), before.lakes.size());
    EXPECT_EQ(after.lakes[0].texels, before.lakes[0].texels);
    EXPECT_EQ(after.lakes[0].inside, before.lakes[0].inside);
    for (std::size_t r = 0; r < before.rivers.size(); ++r) {
        const RiverBake &a = before.rivers[r], &b = after.rivers[r];
        EXPECT_EQ(b.texel, a.texel) << a.name;
        EXPECT_EQ(b.end, a.end);
        EXPECT_EQ(b.receiver, a.receiver);
        EXPECT_EQ(b.islands, a.islands);
        EXPECT_EQ(b.surface, a.surface) << "the centreline profile is stored exactly";
        ASSERT_EQ(b.query_texels.size(), a.query_texels.size());
        double worst_surface = 0.0, worst_flow = 0.0;
        for (std::size_t t = 0; t < a.surface_height.size(); ++t) {
            worst_surface =
                std::max(worst_surface, std::abs(double(a.surface_height[t]) - double(b.surface_height[t])));
            worst_flow = std::max({worst_flow, std::abs(double(a.flow_x[t]) - double(b.flow_x[t])),
                                   std::abs(double(a.flow_z[t]) - double(b.flow_z[t]))});
        }
        EXPECT_LT(worst_surface, 1e-3) << a.name;
        EXPECT_LT(worst_flow, 1e-3) << a.name;
        // Water is still conserved after storage quantisation: Q within 1% at five sections.
        for (const double f : {0.15, 0.3, 0.45, 0.6, 0.75}) {
            const auto k = static_cast<std::size_t>(f * static_cast<double>(b.centreline.size()));
            const double own = b.discharge;  // below the tributaries; above them, the source's
            const double q = discharge_through(b, k);
            const double expected = std::abs(q - own) < std::abs(q - b.own_discharge) ? own : b.own_discharge;
            EXPECT_NEAR(q / expected, 1.0, 0.01) << a.name << " at sample " << k;
        }
    }
    // Queries on the loaded scene agree with the baked one within millimetres, and their
    // currents within millimetres a second (the bake weighs the current by the depth as saved).
    double worst = 0.0, worst_current = 0.0;
    for (const glm::dvec2 p : {glm::dvec2(20.0, -360.0), glm::dvec2(40.0, -470.0), glm::dvec2(120.0, -460.0),
                               glm::dvec2(60.0, -240.0), glm::dvec2(44.0, -530.0), glm::dvec2(300.0, -700.0)}) {
        const WorldPoint a = query_world_point(*baked, 4.0, p), b = query_world_point(**loaded, 4.0, p);
        EXPECT_EQ(a.body, b.body) << p.x << ", " << p.y;
        worst = std::max(worst, std::abs(a.surface.height - b.surface.height));
        worst_current = std::max({worst_current, std::abs(a.flow.x - b.flow.x), std::abs(a.flow.y - b.flow.y)});
    }
    EXPECT_LT(worst, 2e-3);
    EXPECT_LT(worst_current, 2e-3);
}

// An inland scene (no ocean) loaded from its bake takes the shore settings its lakes'
// models were baked with, as a scene with an ocean takes the ocean's.
TEST_F(BodiesBakeFolder, AnInlandSceneTakesItsLakesShoreSettings) {
    Scene inland = parsed;
    inland.has_ocean = false;
    inland.rivers.clear();  // they end in the sea
    inland.shore.breaking_index = 0.7;
    auto made = bake_scene(inland);
    ASSERT_TRUE(made.ok()) << made.error().message;
    const fs::path inland_folder = dir.path / "inland";
    ASSERT_TRUE(save_scene_bake(inland_folder, **made).ok());
    Scene inland_named = inland;
    inland_named.shore = SceneShore{};
    inland_named.shore.bake_folder = inland_folder;
    auto loaded = bake_scene(inland_named);
    ASSERT_TRUE(loaded.ok()) << loaded.error().message;
    EXPECT_EQ((*loaded)->shore.resolution, 96);
    EXPECT_EQ((*loaded)->shore.breaking_index, 0.7);
    EXPECT_TRUE((*loaded)->baked());
}

TEST_F(BodiesBakeFolder, ABakeThatNoLongerFitsIsRefusedWithTheFileAndField) {
    Scene more_water = named;
    more_water.rivers[0].discharge *= 2.0;
    EXPECT_NE(refusal(more_water).find("bodies.json: /rivers/0/discharge_m3_s"), std::string::npos)
        << refusal(more_water);
    Scene moved = named;
    moved.rivers[1].path[0].x += 5.0;
    EXPECT_NE(refusal(moved).find("bodies.json: /rivers/1/path_m"), std::string::npos) << refusal(moved);
    Scene higher = named;
    auto lake = WaterBody::create(higher.lakes[0].body.profile(), 25.0, "tarn");
    ASSERT_TRUE(lake.ok());
    higher.lakes[0].body = std::move(lake).value();
    EXPECT_NE(refusal(higher).find("bodies.json: /lakes/0/level_m"), std::string::npos) << refusal(higher);
    Scene fewer = named;
    fewer.rivers.pop_back();
    EXPECT_NE(refusal(fewer).find("bodies.json: /rivers"), std::string::npos) << refusal(fewer);
    // A knoll moved in the brook: the terrain under the river differs.
    Scene reshaped = named;
    auto island = std::get<IslandTerrain>(reshaped.terrain.shape());
    island.knolls[0].at.x += 3.0;
    reshaped.terrain = Terrain(island);
    const std::string reshaped_error = refusal(reshaped);
    EXPECT_NE(reshaped_error.find("the terrain differs"), std::string::npos) << reshaped_error;
    EXPECT_NE(reshaped_error.find("bodies.json"), std::string::npos) << reshaped_error;
    // A scene without bodies refuses a bake that has them.
    Scene dry = named;
    dry.lakes.clear();
    dry.rivers.clear();
    EXPECT_NE(refusal(dry).find("holds lakes or rivers the scene does not have"), std::string::npos) << refusal(dry);
    // A corrupt field names its file.
    { std::ofstream(folder / "river_00_psi.png", std::ios::trunc) << "not a png"; }
    EXPECT_NE(refusal(named).find("river_00_psi.png"), std::string::npos) << refusal(named);
    // No bodies in the folder at all.
    fs::remove(folder / "bodies.json");
    EXPECT_NE(refusal(named).find("bodies.json: missing"), std::string::npos) << refusal(named);
}

}  // namespace
}  // namespace tidewater
