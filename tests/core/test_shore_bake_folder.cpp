// Saved shore bakes: a model survives saving and loading within its 16-bit encoding,
// and bakes that do not fit the scene are refused.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <thread>

#include "../baked_scene.hpp"
#include "test_helpers.hpp"
#include "tidewater/detail/image_io.hpp"
#include "tidewater/detail/image_write.hpp"
#include "tidewater/detail/shore_bake_folder.hpp"
#include "tidewater/detail/shore_bake_write.hpp"

namespace tidewater {
namespace {

namespace fs = std::filesystem;

using test::TempDir;

constexpr const char* kIslandScene = R"({"version": 1, "water_level": 0,
    "terrain": {"island": {"seed": 7, "radius": 300, "height": 40, "seabed": -30}},
    "ocean": "ocean_rolling", "shore": {"resolution": 96, "texels_per_wavelength": 4}})";

/// Per field row: half the 16-bit step over the row's range across the stored slots
/// (plus float rounding), and the largest difference between two models' stored slots.
struct RowCheck {
    std::vector<double> half_step, worst;
    std::size_t zeros_kept = 0, zeros_lost = 0;  // offshore residuals exactly 0 before: after?
};
RowCheck compare_stored_slots(const ShoreTiles& a, const ShoreTiles& b, std::size_t nw) {
    RowCheck c;
    const std::size_t rows = a.stride, first = gpu::kShoreFirstStoredSlot * ShoreTiles::kSlotTexels;
    const std::vector<float> fa = a.floats(), fb = b.floats();
    const std::size_t texels = fa.size() / rows;
    std::vector<double> lo(rows, 1e300), hi(rows, -1e300);
    c.worst.assign(rows, 0.0);
    for (std::size_t k = first; k < texels; ++k)
        for (std::size_t r = 0; r < rows; ++r) {
            const double va = fa[k * rows + r], vb = fb[k * rows + r];
            lo[r] = std::min(lo[r], va), hi[r] = std::max(hi[r], va);
            c.worst[r] = std::max(c.worst[r], std::abs(va - vb));
            if (r < nw && va == 0.0) (vb == 0.0 ? c.zeros_kept : c.zeros_lost) += 1;
        }
    for (std::size_t r = 0; r < rows; ++r)
        c.half_step.push_back(0.5 * (hi[r] - lo[r]) / 65534.0 + 1e-6 * std::max(std::abs(lo[r]), std::abs(hi[r])));
    return c;
}

TEST(ShoreBakeFolder, RoundTripKeepsTheModelWithinItsEncoding) {
    TempDir dir;
    auto scene = test::baked(parse_scene(kIslandScene, "island"));
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    ASSERT_TRUE(scene->ocean.shore());
    const ShoreWaves& model = *scene->ocean.shore();
    ShoreBakeContents contents;
    contents.model = &model;
    contents.waves = &scene->ocean.waves();
    contents.water_level = scene->water_level();
    contents.scene_name = "island";
    const fs::path folder = dir.path / "bake";
    ASSERT_TRUE(save_shore_bake(folder, contents).ok());
    EXPECT_TRUE(fs::exists(folder / "shore.json"));
    EXPECT_FALSE(fs::exists(folder / "shorelines.json"));  // no distance field given

    auto loaded = load_shore_bake(folder, scene->ocean.waves(), scene->water_level(), scene->terrain);
    ASSERT_TRUE(loaded.ok()) << loaded.error().message;
    const ShoreWaves& back = **loaded;
    ASSERT_EQ(back.resolution(), model.resolution());
    EXPECT_DOUBLE_EQ(back.texel(), model.texel());
    // The same layers and tiles stored, every stored value within half its row's 16-bit step.
    ASSERT_EQ(back.layers().size(), model.layers().size());
    ASSERT_GT(model.shared().stored_tiles(), 0u);
    std::size_t zeros_kept = 0, zeros_lost = 0;
    auto compare = [&](const ShoreTiles& a, const ShoreTiles& b, std::size_t residual_rows, const char* what) {
        ASSERT_EQ(b.pages, a.pages) << what;
        ASSERT_EQ(b.slot_count(), a.slot_count()) << what;
        const RowCheck rows = compare_stored_slots(a, b, residual_rows);
        for (std::size_t r = 0; r < rows.worst.size(); ++r)
            EXPECT_LE(rows.worst[r], rows.half_step[r]) << what << " row " << r;
        zeros_kept += rows.zeros_kept;
        zeros_lost += rows.zeros_lost;
        // The slots not stored are the open sea's and dry land's, the same on both sides.
        for (std::size_t slot = 0; slot < gpu::kShoreFirstStoredSlot; ++slot)
            EXPECT_TRUE(std::equal(a.slot(slot), a.slot(slot) + a.slot_floats(), b.slot(slot))) << what;
    };
    compare(model.shared(), back.shared(), 0, "shared");
    for (std::size_t l = 0; l < model.layers().size(); ++l) {
        const ShoreWaveLayer &a = model.layers()[l], &b = back.layers()[l];
        EXPECT_EQ(b.first, a.first);
        EXPECT_EQ(b.count, a.count);
        EXPECT_EQ(b.grid.resolution, a.grid.resolution);
        EXPECT_DOUBLE_EQ(b.grid.texel, a.grid.texel);
        compare(a.tiles, b.tiles, a.count, "run");
    }
    // Offshore the residual is exactly 0 before and after: no seam where the fields end.
    EXPECT_GT(zeros_kept, 0u);
    EXPECT_EQ(zeros_lost, 0u);

    // Queries over the island and its beaches agree within millimetres.
    auto body = scene->ocean.with_shore(*loaded);
    ASSERT_TRUE(body.ok());
    std::vector<glm::dvec2> points;
    for (int k = 0; k < 400; ++k)
        points.push_back({std::fmod(k * 37.3, 900.0) - 450.0, std::fmod(k * 53.9, 900.0) - 450.0});
    std::vector<SurfacePoint> original(points.size()), reloaded(points.size());
    ASSERT_TRUE(query_surface(scene->ocean, 4.2, points, original).ok());
    ASSERT_TRUE(query_surface(*body, 4.2, points, reloaded).ok());
    double worst = 0.0;
    for (std::size_t k = 0; k < points.size(); ++k)
        worst = std::max(worst, std::abs(original[k].height - reloaded[k].height));
    std::printf("saved and loaded bake: worst height difference %.3f mm over %zu points\n", worst * 1e3, points.size());
    EXPECT_LT(worst, 5e-3);
}

/// The island baked and saved into a temporary folder.
class SavedIsland : public ::testing::Test {
  protected:
    void SetUp() override {
        ASSERT_TRUE(scene.ok()) << scene.error().message;
        contents.model = scene->ocean.shore().get();
        contents.waves = &scene->ocean.waves();
        ASSERT_TRUE(save_shore_bake(folder, contents).ok());
    }
    Result<std::shared_ptr<const ShoreWaves>> load() const {
        return load_shore_bake(folder, scene->ocean.waves(), 0.0, scene->terrain);
    }
    TempDir dir;
    Result<Scene> scene = test::baked(parse_scene(kIslandScene, "island"));
    ShoreBakeContents contents;
    const fs::path folder = dir.path / "bake";
};

TEST_F(SavedIsland, RefusesBakesThatDoNotFitAndCorruptFiles) {
    // Stored tiles are read on demand: read_all reads them, as set_scene does.
    auto message = [&](const WaveSet& waves, double level, const Terrain& terrain) {
        auto r = load_shore_bake(folder, waves, level, terrain);
        if (!r) return r.error().message;
        auto read = (*r)->read_all();
        return read.ok() ? std::string("loaded") : read.error().message;
    };
    EXPECT_NE(message(scene->ocean.waves(), 0.3, scene->terrain).find("/water_level_m"), std::string::npos);
    auto lake = parse_scene(
        R"({"version": 1, "water_level": 0, "terrain": {"flat": {"height": -20}}, "ocean": "lake_rippled"})", "lake");
    ASSERT_TRUE(lake.ok());
    EXPECT_NE(message(lake->ocean.waves(), 0.0, scene->terrain).find("re-run tidewater bake"), std::string::npos);
    IslandTerrain edited = std::get<IslandTerrain>(scene->terrain.shape());
    edited.height = 45.0;  // an edit inside the same extent
    EXPECT_NE(message(scene->ocean.waves(), 0.0, Terrain(edited)).find("the terrain differs"), std::string::npos);

    // A truncated sidecar, a bake of the previous format, a missing tile and a tile of the
    // wrong size name the file; a kind of tile that does not exist names the field.
    fs::copy_file(folder / "shore.json", dir.path / "shore.json.good");
    { std::ofstream(folder / "shore.json") << R"({"version": 3, "water_level_m": )"; }
    EXPECT_NE(message(scene->ocean.waves(), 0.0, scene->terrain).find("shore.json"), std::string::npos);
    { std::ofstream(folder / "shore.json") << R"({"version": 2, "water_level_m": 0})"; }
    EXPECT_NE(message(scene->ocean.waves(), 0.0, scene->terrain).find("version"), std::string::npos);
    fs::copy_file(dir.path / "shore.json.good", folder / "shore.json", fs::copy_options::overwrite_existing);
    const ShoreTiles& tiles = scene->ocean.shore()->layers().back().tiles;
    const std::size_t first_stored =
        static_cast<std::size_t>(std::find_if(tiles.pages.begin(), tiles.pages.end(),
                                              [](std::uint32_t p) { return p >= gpu::kShoreFirstStoredSlot; }) -
                                 tiles.pages.begin());
    const std::string tile_file = shore_tile_file(
        shore_layer_folder(static_cast<int>(scene->ocean.shore()->layers().size()) - 1),
        static_cast<int>(first_stored % tiles.tiles_per_side), static_cast<int>(first_stored / tiles.tiles_per_side));
    fs::remove(folder / tile_file);
    EXPECT_NE(message(scene->ocean.waves(), 0.0, scene->terrain).find(fs::path(tile_file).filename().string()),
              std::string::npos);
    Gray16Image small;
    small.width = small.height = 8;
    small.pixels.assign(64, 0);
    ASSERT_TRUE(detail::write_png_gray16(folder / tile_file, small).ok());
    EXPECT_NE(message(scene->ocean.waves(), 0.0, scene->terrain).find("8x8"), std::string::npos);
    {
        std::string text((std::istreambuf_iterator<char>(std::ifstream(dir.path / "shore.json.good").rdbuf())),
                         std::istreambuf_iterator<char>());
        auto doc = nlohmann::json::parse(text);
        std::string kinds = doc["model"]["tiles"]["kinds"];
        kinds[0] = 'x';
        doc["model"]["tiles"]["kinds"] = kinds;
        std::ofstream(folder / "shore.json") << doc.dump();
    }
    EXPECT_NE(message(scene->ocean.waves(), 0.0, scene->terrain).find("/model/tiles/kinds"), std::string::npos);
    EXPECT_FALSE(load_shore_bake(dir.path / "nowhere", scene->ocean.waves(), 0.0, scene->terrain).ok());

    // Saving where no folder can be made fails and leaves nothing behind.
    { std::ofstream(dir.path / "plain") << "x"; }
    EXPECT_FALSE(save_shore_bake(dir.path / "plain" / "bake", contents).ok());
    for (const auto& e : fs::directory_iterator(dir.path))
        EXPECT_EQ(e.path().filename().string().find(".tmp-"), std::string::npos) << e.path();
}

/// Stored slots read so far over every layer of `model`, and how many there are.
std::pair<std::size_t, std::size_t> slots_read(const ShoreWaves& model) {
    std::size_t read = 0, stored = 0;
    auto add = [&](const ShoreTiles& t) {
        read += t.lazy ? t.lazy->read_count() : t.slot_count();
        stored += t.slot_count() - gpu::kShoreFirstStoredSlot;
    };
    add(model.shared());
    for (const ShoreWaveLayer& l : model.layers()) add(l.tiles);
    return {read, stored};
}

TEST_F(SavedIsland, ALoadedBakeReadsItsTilesWhenNeeded) {
    auto lazy = load();
    ASSERT_TRUE(lazy.ok()) << lazy.error().message;
    const auto [read_at_load, stored] = slots_read(**lazy);
    EXPECT_EQ(read_at_load, 0u);
    ASSERT_GT(stored, 20u);

    // A query on one beach reads the tiles under it, and answers what a model read whole does.
    auto eager = load();
    ASSERT_TRUE(eager.ok());
    const Status read_whole = (*eager)->read_all();
    ASSERT_TRUE(read_whole.ok()) << read_whole.error().message;
    EXPECT_EQ(slots_read(**eager).first, stored);
    std::vector<glm::dvec2> beach;
    for (int k = 0; k < 64; ++k) beach.push_back({290.0 + 0.5 * k, 3.0 * (k % 8)});
    auto heights = [&](const std::shared_ptr<const ShoreWaves>& model, std::span<const glm::dvec2> points) {
        auto body = scene->ocean.with_shore(model);
        std::vector<double> h(points.size());
        const Status st = body.ok() ? query_heights(*body, 3.0, points, h) : Status(body.error());
        return std::pair{st, h};
    };
    const auto [lazy_status, lazy_heights] = heights(*lazy, beach);
    ASSERT_TRUE(lazy_status.ok()) << lazy_status.error().message;
    EXPECT_EQ(lazy_heights, heights(*eager, beach).second);
    const std::size_t read_by_beach = slots_read(**lazy).first;
    EXPECT_GT(read_by_beach, 0u);
    EXPECT_LT(read_by_beach, stored / 2);
    std::printf("a beach's query read %zu of %zu stored tiles\n", read_by_beach, stored);

    // A tile corrupted after the load fails the query that needs it, naming the file; a
    // folder replaced since the load (the same bake saved again) reads as missing files,
    // never as the new folder's tiles.
    const ShoreTiles& shared = (*lazy)->shared();
    const std::size_t last = static_cast<std::size_t>(
        std::find(shared.pages.rbegin(), shared.pages.rend(), static_cast<std::uint32_t>(shared.slot_count() - 1)) -
        shared.pages.rbegin());
    const std::size_t tile = shared.pages.size() - 1 - last;
    const std::string file = shore_tile_file(shore_layer_folder(-1), static_cast<int>(tile % shared.tiles_per_side),
                                             static_cast<int>(tile / shared.tiles_per_side));
    ASSERT_TRUE(fs::exists(folder / file));
    { std::ofstream(folder / file, std::ios::trunc) << "not a png"; }
    std::vector<glm::dvec2> everywhere;
    for (int k = 0; k < 900; ++k) everywhere.push_back({-450.0 + (k % 30) * 31.0, -450.0 + (k / 30) * 31.0});
    const auto [corrupt_status, ignored] = heights(*lazy, everywhere);
    ASSERT_FALSE(corrupt_status.ok());
    EXPECT_NE(corrupt_status.error().message.find(fs::path(file).filename().string()), std::string::npos)
        << corrupt_status.error().message;
    EXPECT_FALSE((*lazy)->status().ok());

    auto before_save = load();
    ASSERT_TRUE(before_save.ok());
    ASSERT_TRUE(save_shore_bake(folder, contents).ok());
    const Status replaced = (*before_save)->read_all();
    ASSERT_FALSE(replaced.ok());
    EXPECT_NE(replaced.error().message.find("replaced"), std::string::npos) << replaced.error().message;
    auto after_save = load();
    ASSERT_TRUE(after_save.ok());
    EXPECT_TRUE((*after_save)->read_all().ok());
}

TEST_F(SavedIsland, ThreadsReadingTheSameTilesAtOnceGetTheSameAnswers) {
    auto eager = load(), lazy = load();
    ASSERT_TRUE(eager.ok() && lazy.ok());
    ASSERT_TRUE((*eager)->read_all().ok());
    auto eager_body = scene->ocean.with_shore(*eager), lazy_body = scene->ocean.with_shore(*lazy);
    ASSERT_TRUE(eager_body.ok() && lazy_body.ok());
    // Every thread walks the whole island in its own order: they reach the same unread
    // tiles at about the same time.
    constexpr int kThreads = 4;
    std::vector<std::vector<glm::dvec2>> points(kThreads);
    for (int t = 0; t < kThreads; ++t)
        for (int k = 0; k < 2000; ++k) {
            const int q = (k * (2 * t + 1)) % 2000;
            points[t].push_back({-450.0 + (q % 50) * 18.0, -450.0 + (q / 50) * 22.5});
        }
    std::vector<std::vector<double>> got(kThreads), want(kThreads);
    std::vector<Status> status(kThreads);
    std::vector<std::thread> workers;
    for (int t = 0; t < kThreads; ++t)
        workers.emplace_back([&, t] {
            got[t].resize(points[t].size());
            QueryOptions options;
            options.threads = 2;
            status[t] = query_heights(*lazy_body, 1.5, points[t], got[t], options);
        });
    for (auto& w : workers) w.join();
    for (int t = 0; t < kThreads; ++t) {
        ASSERT_TRUE(status[t].ok()) << status[t].error().message;
        want[t].resize(points[t].size());
        ASSERT_TRUE(query_heights(*eager_body, 1.5, points[t], want[t]).ok());
        EXPECT_EQ(got[t], want[t]) << "thread " << t;
    }
    EXPECT_EQ(slots_read(**lazy).first, slots_read(**lazy).second);  // each read once, every one reached
}

TEST(ShoreBakeFolder, ModelFromFieldsChecksSizesAndValues) {
    ShoreWaveFields f;
    f.resolution = 4;
    f.texel = 1.0;
    const std::vector<float> grid(16, 1.0f);
    f.depth = f.shore_distance = f.breaking = f.steepness_scale = grid;
    f.phase_residual = f.amplitude_factor = f.wavevector_x = f.wavevector_z = {grid};
    const std::vector<Wave> one(1), two(2);
    EXPECT_TRUE(ShoreWaves::from_fields(f, one).ok());
    EXPECT_FALSE(ShoreWaves::from_fields(f, two).ok());
    ShoreWaveFields short_grid = f;
    short_grid.depth.resize(15);
    EXPECT_NE(ShoreWaves::from_fields(short_grid, one).error().message.find("depth"), std::string::npos);
    ShoreWaveFields nan = f;
    nan.phase_residual[0][3] = std::nanf("");
    EXPECT_NE(ShoreWaves::from_fields(nan, one).error().message.find("non-finite"), std::string::npos);
}

}  // namespace
}  // namespace tidewater
