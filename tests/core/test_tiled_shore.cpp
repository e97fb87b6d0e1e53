// The shoreline bake in tiles (tiled_shore.hpp), as a farm runs it: each tile's contour,
// the stitched shoreline and each tile's distances against it give the whole bake's field
// value for value, whatever the tiling and the order the tiles come in; the shore model
// marched on the assembled field is the whole bake's; contours that are not a tile's are
// refused; and the saved distance field reads in GDAL, in metres, through distance.vrt.
#include <gdal.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "../shore_model_compare.hpp"
#include "../small_island.hpp"
#include "test_helpers.hpp"
#include "tidewater/detail/shore_bake.hpp"
#include "tidewater/detail/shore_bake_folder.hpp"
#include "tidewater/detail/tiled_shore.hpp"
#include "tidewater/scene_bake.hpp"

namespace tidewater {
namespace {

namespace fs = std::filesystem;

constexpr int kDistanceResolution = 256;

Scene small_island() {
    auto scene = parse_scene(test::kSmallIsland, "s.json");
    EXPECT_TRUE(scene.ok()) << scene.error().message;
    scene->shore.distance_resolution = kDistanceResolution;
    return std::move(scene).value();
}

/// The three steps and the assembly over `tiles` x `tiles` tiles, the tiles' contours
/// handed to the stitch in reverse order.
ShoreField tiled_field(const Terrain& terrain, int tiles) {
    auto tiling = tiled::ShoreTiling::over(terrain, kDistanceResolution, tiles);
    EXPECT_TRUE(tiling.ok()) << tiling.error().message;
    std::vector<tiled::TileContour> contours;
    for (int t = tiling->count() - 1; t >= 0; --t) {
        auto c = tiled::extract_tile_contour(terrain, 0.0, *tiling, t, 2);
        EXPECT_TRUE(c.ok()) << c.error().message;
        contours.push_back(std::move(c).value());
    }
    auto stitched = tiled::stitch_shoreline(*tiling, std::move(contours), 0.0, 2);
    EXPECT_TRUE(stitched.ok()) << stitched.error().message;
    std::vector<tiled::TileDistances> distances;
    for (int t = 0; t < tiling->count(); ++t) {
        auto d = tiled::bake_tile_distances(terrain, 0.0, *tiling, t, *stitched, 2);
        EXPECT_TRUE(d.ok()) << d.error().message;
        distances.push_back(std::move(d).value());
    }
    auto field = tiled::assemble_shore_field(*tiling, std::move(stitched).value(), [&](int t) {
        return Result<tiled::TileDistances>(std::move(distances[static_cast<std::size_t>(t)]));
    });
    EXPECT_TRUE(field.ok()) << field.error().message;
    return std::move(field).value();
}

bool same_lines(const std::vector<ShoreLine>& a, const std::vector<ShoreLine>& b) {
    return std::ranges::equal(
        a, b, [](const ShoreLine& x, const ShoreLine& y) { return x.closed == y.closed && x.points == y.points; });
}

TEST(TiledShore, EveryTilingGivesTheWholeBakesFieldValueForValue) {
    const Scene scene = small_island();
    const Terrain terrain = scene.terrain.with_cuts({});
    BakeOptions options;
    options.resolution = kDistanceResolution;
    auto whole = bake_shore(terrain, 0.0, options);
    ASSERT_TRUE(whole.ok()) << whole.error().message;
    ASSERT_GT(whole->segment_count, 20u);
    for (int tiles : {1, 2, 4, 8}) {
        SCOPED_TRACE(tiles);
        const ShoreField field = tiled_field(terrain, tiles);
        EXPECT_TRUE(same_lines(field.shorelines, whole->shorelines));
        EXPECT_EQ(field.segment_count, whole->segment_count);
        EXPECT_EQ(field.polygons, whole->polygons);
        EXPECT_EQ(field.holes, whole->holes);
        EXPECT_EQ(field.simplify_tolerance, whole->simplify_tolerance);
        EXPECT_EQ(field.signed_distance.values(), whole->signed_distance.values());
        EXPECT_EQ(field.gradient.codes(), whole->gradient.codes());
        EXPECT_EQ(field.depth.values(), whole->depth.values());
    }
}

TEST(TiledShore, TheShoreModelOnTheAssembledFieldIsTheWholeBakes) {
    const Scene scene = small_island();
    auto whole = bake_scene(scene);
    ASSERT_TRUE(whole.ok()) << whole.error().message;
    auto terrain = tiled::shore_terrain(scene);
    ASSERT_TRUE(terrain.ok()) << terrain.error().message;
    auto field = std::make_shared<const ShoreField>(tiled_field(*terrain, 4));
    auto tiled_scene = tiled::bake_scene_on_shoreline(scene, {}, field);
    ASSERT_TRUE(tiled_scene.ok()) << tiled_scene.error().message;
    EXPECT_TRUE(test::same_tiles(*(*whole)->bake->ocean_shore, *(*tiled_scene)->bake->ocean_shore));
    EXPECT_EQ((*tiled_scene)->bake->shoreline, field);
    // A field for another grid is refused, naming the scene's shore.
    SceneBakeOptions finer;
    finer.distance_resolution = 2 * kDistanceResolution;
    auto refused = tiled::bake_scene_on_shoreline(scene, finer, field);
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().message.find("is not the one the scene's terrain and distance resolution"),
              std::string::npos)
        << refused.error().message;
}

TEST(TiledShore, RefusesContoursThatAreNotATilesOwn) {
    const Scene scene = small_island();
    const Terrain terrain = scene.terrain.with_cuts({});
    auto tiling = tiled::ShoreTiling::over(terrain, kDistanceResolution, 2);
    ASSERT_TRUE(tiling.ok());
    EXPECT_FALSE(tiled::ShoreTiling::over(terrain, kDistanceResolution, 3).ok());  // 256 is not a multiple of 96
    EXPECT_FALSE(tiled::ShoreTiling::over(terrain, kDistanceResolution, 0).ok());
    std::vector<tiled::TileContour> contours;
    for (int t = 0; t < 4; ++t) contours.push_back(tiled::extract_tile_contour(terrain, 0.0, *tiling, t, 1).value());
    ASSERT_FALSE(contours[0].cells.empty());
    auto expect_refused = [&](tiled::TileContour c, const char* needle) {
        const Status st = tiled::check_tile_contour(*tiling, c);
        ASSERT_FALSE(st.ok()) << needle;
        EXPECT_NE(st.error().message.find(needle), std::string::npos) << st.error().message;
    };
    tiled::TileContour moved = contours[0];
    moved.cells[0].i += tiling->block();  // the next tile's cell
    expect_refused(moved, "tile 0: piece 0");
    tiled::TileContour outside = contours[0];
    outside.cells[0].to.x += 2.0;  // out of its cell
    expect_refused(outside, "tile 0: piece 0");
    tiled::TileContour edge = contours[0];
    edge.cells[0].from_edge = 4;
    expect_refused(edge, "tile 0: piece 0");
    tiled::TileContour many = contours[0];
    many.mixed_cells = 0;
    expect_refused(many, "tile 0: ");
    // The stitch wants every tile once.
    auto missing = contours;
    missing.pop_back();
    auto st = tiled::stitch_shoreline(*tiling, missing, 0.0, 1);
    ASSERT_FALSE(st.ok());
    EXPECT_NE(st.error().message.find("tile 3: its contour is missing"), std::string::npos) << st.error().message;
    auto twice = contours;
    twice[3] = contours[2];
    st = tiled::stitch_shoreline(*tiling, twice, 0.0, 1);
    ASSERT_FALSE(st.ok());
    EXPECT_NE(st.error().message.find("tile 2: given twice"), std::string::npos) << st.error().message;
}

TEST(DistanceVrt, GdalReadsTheDistanceFieldInMetresWhereItLies) {
    const Scene scene = small_island();
    auto baked = bake_scene(scene);
    ASSERT_TRUE(baked.ok()) << baked.error().message;
    const test::TempDir dir("distance_vrt");
    ASSERT_TRUE(save_scene_bake(dir.path / "bake", **baked).ok());
    const ShoreField& field = *(*baked)->bake->shoreline;
    GDALAllRegister();
    GDALDatasetH ds = GDALOpen((dir.path / "bake" / kDistanceVrt).c_str(), GA_ReadOnly);
    ASSERT_NE(ds, nullptr) << CPLGetLastErrorMsg();
    const int n = field.resolution;
    EXPECT_EQ(GDALGetRasterXSize(ds), n);
    EXPECT_EQ(GDALGetRasterYSize(ds), n);
    ASSERT_EQ(GDALGetRasterCount(ds), 4);
    double gt[6];
    ASSERT_EQ(GDALGetGeoTransform(ds, gt), CE_None);
    // North-up, x east, z south: pixel (i, r) centres at x = corner + (i + 0.5) texel, z = -y.
    EXPECT_DOUBLE_EQ(gt[0], field.corner.x);
    EXPECT_DOUBLE_EQ(gt[1], field.texel);
    EXPECT_DOUBLE_EQ(gt[3], -field.corner.y);
    EXPECT_DOUBLE_EQ(gt[5], -field.texel);
    // The gradient's two components, as its angles hold them.
    std::vector<float> gradient_x, gradient_z;
    for (std::size_t k = 0; k < field.gradient.size(); ++k) {
        gradient_x.push_back(field.gradient[k].x);
        gradient_z.push_back(field.gradient[k].y);
    }
    const std::vector<float>* grids[] = {&field.signed_distance.values(), &gradient_x, &gradient_z,
                                         &field.depth.values()};
    const char* names[] = {"signed_distance", "gradient_x", "gradient_z", "depth"};
    for (int b = 0; b < 4; ++b) {
        SCOPED_TRACE(names[b]);
        GDALRasterBandH band = GDALGetRasterBand(ds, b + 1);
        EXPECT_STREQ(GDALGetDescription(band), names[b]);
        const double scale = GDALGetRasterScale(band, nullptr), offset = GDALGetRasterOffset(band, nullptr);
        std::vector<double> raw(static_cast<std::size_t>(n) * n);
        ASSERT_EQ(GDALRasterIO(band, GF_Read, 0, 0, n, n, raw.data(), n, n, GDT_Float64, 0, 0), CE_None);
        double worst = 0.0;
        for (int r = 0; r < n; ++r)
            for (int i = 0; i < n; ++i) {
                const double metres = raw[static_cast<std::size_t>(r) * n + i] * scale + offset;
                worst = std::max(worst, std::abs(metres - (*grids[b])[field.index(i, r)]));
            }
        // Within half the PNG's step (its quantisation), plus rounding.
        EXPECT_LE(worst, 0.5 * scale * (1.0 + 1e-6));
    }
    GDALClose(ds);
}

}  // namespace
}  // namespace tidewater
