// Baking a world at real scale: a procedural island on a square heightmap at 1 m pixels
// (hills to 100 m with 2 m ditches every 40 m, a wavy coast about a fifth of the side from
// the centre, a 1:20 slope to the seabed), under ocean_rolling's spectrum, baked as
// `tidewater bake` does (bake_scene, then save_scene_bake into a folder). Prints one JSON
// object: bake, save and load seconds (the load reads the index, then every tile is read
// as a renderer's first upload does), a brush stroke's re-bake on the hills and one on
// the seabed (the median of three and the slowest), the process's peak
// memory (after the save, before the stroke and the load), the folder's size and the
// shore model's tiles. One world per process, so that the peak is this world's:
//   tidewater_world_bake_benchmark SIDE_M [WAVES=24] [SEABED_M=-60] [TEXEL_M=2] [TEXELS_PER_WAVELENGTH=8] [KEEP_DIR]
// With KEEP_DIR the world stays there to be drawn: island.raw (the heightmap), bake/ (the
// saved bake) and island.json (a scene naming both: `tidewater render --scene`).
// docs/PERFORMANCE.md ("Worlds at real scale") quotes it.
#include <fmt/format.h>
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <numbers>
#include <string>
#include <variant>
#include <vector>

#include "tidewater/baked_scene.hpp"
#include "tidewater/detail/shore_waves.hpp"
#include "tidewater/scene.hpp"
#include "tidewater/scene_bake.hpp"

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

/// Ground height (m) at xz on an island in a square of side `side` m centred on the origin.
double island_height(double x, double z, double side, double seabed) {
    const double r = std::hypot(x, z), a = std::atan2(z, x);
    const double coast =
        0.2 * side *
        (1.0 + 0.12 * std::sin(3.0 * a) + 0.06 * std::sin(7.0 * a + 1.0) + 0.03 * std::sin(17.0 * a + 2.0));
    if (r > coast) return std::max(seabed, -0.05 * (r - coast));
    const double inland = coast - r;
    double h =
        2.0 + 98.0 * std::min(1.0, inland / (0.15 * side)) * (0.75 + 0.25 * std::sin(x / 310.0) * std::cos(z / 270.0));
    const double along = std::abs(std::remainder(x - 20.0, 40.0));
    if (inland > 30.0 && along < 1.0) h -= 1.5 * 0.5 * (1.0 + std::cos(std::numbers::pi * along));
    return h;
}

tidewater::Terrain island(int side, double seabed) {
    auto image = std::make_shared<tidewater::Gray16Image>();
    image->width = image->height = side;
    image->pixels.resize(static_cast<std::size_t>(side) * static_cast<std::size_t>(side));
    const double lo = seabed, hi = 110.0;
    for (int j = 0; j < side; ++j)
        for (int i = 0; i < side; ++i) {
            const double h = island_height(i - 0.5 * (side - 1), j - 0.5 * (side - 1), side, seabed);
            image->pixels[static_cast<std::size_t>(j) * static_cast<std::size_t>(side) + static_cast<std::size_t>(i)] =
                static_cast<std::uint16_t>(std::lround((h - lo) / (hi - lo) * 65535.0));
        }
    tidewater::HeightmapTerrain map;
    map.file = fmt::format("island_{}.raw", side);
    map.size = glm::dvec2(side - 1);
    map.min_height = lo;
    map.max_height = hi;
    map.image = std::move(image);
    return tidewater::Terrain(map);
}

/// Keeps the world in `keep`: its heightmap as raw 16-bit, the bake folder `bake` moved to
/// keep/bake, and a scene naming both. Returns what failed (empty: nothing).
std::string keep_world(const fs::path& keep, const fs::path& bake, const tidewater::Scene& scene, int side, int waves) {
    std::error_code ec;
    fs::create_directories(keep, ec);
    fs::remove_all(keep / "bake", ec);
    fs::copy(bake, keep / "bake", fs::copy_options::recursive, ec);
    if (ec) return fmt::format("{}: cannot keep the bake: {}", keep.string(), ec.message());
    const auto& map = std::get<tidewater::HeightmapTerrain>(scene.terrain.shape());
    {
        std::FILE* raw = std::fopen((keep / "island.raw").c_str(), "wb");
        if (!raw) return fmt::format("{}: cannot write", (keep / "island.raw").string());
        for (std::uint16_t v : map.image->pixels) {
            const unsigned char bytes[2] = {static_cast<unsigned char>(v & 0xff), static_cast<unsigned char>(v >> 8)};
            std::fwrite(bytes, 1, 2, raw);
        }
        if (std::fclose(raw) != 0) return fmt::format("{}: cannot write", (keep / "island.raw").string());
    }
    std::FILE* json = std::fopen((keep / "island.json").c_str(), "w");
    if (!json) return fmt::format("{}: cannot write", (keep / "island.json").string());
    std::fprintf(json,
                 R"({"version": 1, "name": "island %d", "water_level": 0,
 "terrain": {"heightmap": {"file": "island.raw", "size": [%d, %d], "height_range": [%.17g, %.17g],
                           "raw": {"width": %d, "height": %d}}},
 "ocean": {"spectrum": {"type": "jonswap", "wind_speed": 12.0, "fetch": 200000.0, "peak_enhancement": 3.3,
                        "direction": 20.0, "spreading": 8.0, "wave_count": %d, "seed": 11, "steepness": 0.6}},
 "shore": {"bake": "bake"}}
)",
                 side, side - 1, side - 1, map.min_height, map.max_height, side, side, waves);
    if (std::fclose(json) != 0) return fmt::format("{}: cannot write", (keep / "island.json").string());
    return {};
}

std::uintmax_t folder_bytes(const fs::path& dir) {
    std::uintmax_t bytes = 0;
    for (const auto& e : fs::recursive_directory_iterator(dir))
        if (e.is_regular_file()) bytes += e.file_size();
    return bytes;
}

/// World xz of heightmap pixel (i, j).
glm::dvec2 pixel_xz(const tidewater::Scene& scene, int i, int j) {
    const auto& map = std::get<tidewater::HeightmapTerrain>(scene.terrain.shape());
    const int side = map.image->width;
    return {map.size.x * (i / (side - 1.0) - 0.5), map.size.y * (j / (side - 1.0) - 0.5)};
}

/// WORLD_BENCH_KEEP_MARCHES=1: bake keeping what the march needs (SceneBakeOptions::
/// keep_marches, as the editor does), so that the seabed strokes re-bake where they
/// reach with diffraction on.
bool keep_marches() {
    const char* v = std::getenv("WORLD_BENCH_KEEP_MARCHES");
    return v != nullptr && std::string(v) == "1";
}

struct Stroke {
    double seconds = 0.0;
    bool local = false;  ///< re-baked where it is (a dry-land or a seabed edit)
    std::string error;
};

/// `edited` re-baked from `baked`, timed: local where the ocean's shore was kept, or
/// re-baked only where the edit reaches.
Stroke re_bake(const tidewater::Scene& edited, const std::shared_ptr<const tidewater::Scene>& baked) {
    tidewater::SceneBakeOptions options;
    options.previous = baked;
    options.keep_marches = keep_marches();
    const auto t = Clock::now();
    auto rebaked = tidewater::bake_scene(edited, options);
    Stroke out;
    out.seconds = seconds_since(t);
    if (!rebaked) {
        out.error = rebaked.error().message;
        return out;
    }
    const auto& reused = (*rebaked)->bake->reused;
    out.local = reused.ocean_shore || reused.ocean_shore_land_edit || reused.ocean_shore_water_edit;
    return out;
}

/// A brush stroke re-baked from `baked` (as an editor does after it): the heightmap raised
/// by `metres` at (ci, cj), falling off over 25 pixels.
Stroke re_bake_stroke(const tidewater::Scene& scene, const std::shared_ptr<const tidewater::Scene>& baked, int ci,
                      int cj, double metres) {
    tidewater::Scene stroke = scene;
    auto map = std::get<tidewater::HeightmapTerrain>(scene.terrain.shape());
    const int side = map.image->width;
    auto pixels = std::make_shared<tidewater::Gray16Image>(*map.image);
    const double per_metre = 65535.0 / (map.max_height - map.min_height);
    for (int j = cj - 25; j <= cj + 25; ++j)
        for (int i = ci - 25; i <= ci + 25; ++i) {
            const double r = std::hypot(i - ci, j - cj) / 25.0;
            if (r >= 1.0) continue;
            auto& px = pixels->pixels[static_cast<std::size_t>(j) * static_cast<std::size_t>(side) +
                                      static_cast<std::size_t>(i)];
            px = static_cast<std::uint16_t>(std::clamp(px + metres * per_metre * (1.0 - r * r), 0.0, 65535.0));
        }
    map.image = std::move(pixels);
    stroke.terrain = tidewater::Terrain(map);
    return re_bake(stroke, baked);
}

/// WORLD_BENCH_RIVER=1: a river runs from the hills to the sea south of the centre
/// (x = 0, between two ditches; 20 m wide, 30 m^3/s), and its discharge raised by a fifth
/// is re-baked from the bake, as an editor's Rivers panel does.
bool with_river() {
    const char* v = std::getenv("WORLD_BENCH_RIVER");
    return v != nullptr && std::string(v) == "1";
}

/// The river's scene entry for a world `side` m across.
std::string world_river(int side) {
    // From 0.16 of the side south of the centre (inland of the coast's southern bulge at
    // about 0.233) to 0.26 (in about 10 m of water), swinging gently.
    std::string path;
    for (const double z : {-0.16, -0.19, -0.22, -0.24, -0.26})
        path +=
            fmt::format("{}[{:.1f}, {:.1f}]", path.empty() ? "" : ", ", 0.004 * side * std::sin(40.0 * z), z * side);
    return fmt::format(R"(, "rivers": [{{"name": "south river", "path": [{}], "width": 20, "discharge": 30}}])", path);
}

Stroke re_bake_river(const tidewater::Scene& scene, const std::shared_ptr<const tidewater::Scene>& baked) {
    tidewater::Scene edited = scene;
    edited.rivers.front().discharge *= 1.2;
    return re_bake(edited, baked);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr,
                     "usage: %s SIDE_M [WAVES=24] [SEABED_M=-60] [TEXEL_M=2] [TEXELS_PER_WAVELENGTH=8] [KEEP_DIR]\n"
                     "  WORLD_BENCH_SEABED_STROKES=N (0..3, default 3): seabed strokes timed\n"
                     "  WORLD_BENCH_KEEP_MARCHES=1: keep what the march needs, as the editor does\n"
                     "  WORLD_BENCH_RIVER=1: a river to the sea, and its discharge edit timed (river_edit_s)\n",
                     argv[0]);
        return 2;
    }
    const int side = std::atoi(argv[1]);
    const int waves = argc > 2 ? std::atoi(argv[2]) : 24;
    const double seabed = argc > 3 ? std::atof(argv[3]) : -60.0;
    const double texel = argc > 4 ? std::atof(argv[4]) : 2.0;
    const double per_wavelength = argc > 5 ? std::atof(argv[5]) : tidewater::kDefaultShoreTexelsPerWavelength;
    if (side < 256 || side > 32768 || waves < 1 || waves > 64 || !(seabed < -1.0) || !(texel > 0.0) ||
        !(per_wavelength == 0.0 || (per_wavelength >= 4.0 && per_wavelength <= 64.0))) {
        std::fprintf(stderr,
                     "out of range: SIDE_M 256..32768, WAVES 1..64, SEABED_M < -1, TEXEL_M > 0, "
                     "TEXELS_PER_WAVELENGTH 0 or 4..64\n");
        return 2;
    }
    const auto t0 = Clock::now();
    auto parsed = tidewater::parse_scene(
        fmt::format(R"({{"version": 1, "name": "island {0}", "water_level": 0, "terrain": {{"flat": {{"height": -1}}}},
            "ocean": {{"spectrum": {{"type": "jonswap", "wind_speed": 12.0, "fetch": 200000.0, "peak_enhancement": 3.3,
                                    "direction": 20.0, "spreading": 8.0, "wave_count": {1}, "seed": 11, "steepness": 0.6}}}}{2}}})",
                    side, waves, with_river() ? world_river(side) : std::string()),
        "world_bake_benchmark");
    if (!parsed) {
        std::fprintf(stderr, "%s\n", parsed.error().message.c_str());
        return 1;
    }
    tidewater::Scene scene = std::move(parsed).value();
    scene.terrain = island(side, seabed);
    const int resolution =
        std::min(8192, static_cast<int>(std::lround(2.0 * scene.terrain.extent_half_size() / texel)));
    scene.shore.resolution = resolution;
    scene.shore.distance_resolution = resolution;
    scene.shore.texels_per_wavelength = per_wavelength;
    const double make = seconds_since(t0);

    const auto t1 = Clock::now();
    tidewater::SceneBakeOptions bake_options;
    bake_options.keep_marches = keep_marches();
    auto baked = tidewater::bake_scene(scene, bake_options);
    if (!baked) {
        std::fprintf(stderr, "%s\n", baked.error().message.c_str());
        return 1;
    }
    const double bake = seconds_since(t1);
    const fs::path dir = fs::temp_directory_path() / fmt::format("tidewater_world_{}_{}", side, ::getpid());
    const auto t2 = Clock::now();
    if (auto st = tidewater::save_scene_bake(dir, **baked); !st) {
        std::fprintf(stderr, "%s\n", st.error().message.c_str());
        return 1;
    }
    const double save = seconds_since(t2);
    const std::uintmax_t bytes = folder_bytes(dir);
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    const double peak = static_cast<double>(usage.ru_maxrss) / 1024.0;
    const tidewater::ShoreWaves& model = *(*baked)->ocean.shore();
    const double model_texel = model.texel();
    const std::size_t pages = model.shared().pages.size(), stored = model.shared().stored_tiles();
    const double model_mb = static_cast<double>(model.bytes()) / 1e6;
    const double gpu_mb = static_cast<double>(model.device_bytes()) / 1e6;
    // Each run of waves: its waves, texel and stored tiles.
    std::string runs = "[";
    for (const tidewater::ShoreWaveLayer& run : model.layers())
        runs += (runs.size() > 1 ? ", " : "") + std::string("{\"waves\": ") + std::to_string(run.count) +
                ", \"texel_m\": " + std::to_string(run.grid.texel) +
                ", \"stored_tiles\": " + std::to_string(run.tiles.stored_tiles()) + "}";
    runs += "]";
    // A brush stroke on the hills (2 m up over 25 m, a tenth of the side from the centre,
    // inland) and one on the seabed (1.5 m dug over 25 m where the water is about 8 m
    // deep, on the same line), each re-baked from the bake just made, as an editor does.
    const Stroke land = re_bake_stroke(scene, *baked, static_cast<int>(0.6 * side), side / 2, 2.0);
    int wet_i = side / 2;
    while (wet_i < side - 30 && scene.terrain.height_at(pixel_xz(scene, wet_i, side / 2)) > -8.0) ++wet_i;
    // The seabed stroke three times over (each from the bake just made): its median and
    // slowest. WORLD_BENCH_SEABED_STROKES=0 leaves it out (-1 s in the report): on the
    // largest worlds, where the longest waves feel the seabed everywhere, one takes minutes.
    const char* strokes_env = std::getenv("WORLD_BENCH_SEABED_STROKES");
    const int strokes = strokes_env ? std::clamp(std::atoi(strokes_env), 0, 3) : 3;
    Stroke water;
    water.seconds = -1.0;
    std::vector<double> water_s{-1.0};
    if (strokes > 0) {
        water = re_bake_stroke(scene, *baked, wet_i, side / 2, -1.5);
        water_s = {water.seconds};
        for (int k = 1; k < strokes && water.error.empty(); ++k)
            water_s.push_back(re_bake_stroke(scene, *baked, wet_i, side / 2, -1.5).seconds);
        std::sort(water_s.begin(), water_s.end());
        water.seconds = water_s[water_s.size() / 2];
    }
    // A stroke across the waterline (1.5 m dug over 25 m where the ground meets the sea,
    // on the same line): the shoreline moves.
    int shore_i = side / 2;
    while (shore_i < side - 30 && scene.terrain.height_at(pixel_xz(scene, shore_i, side / 2)) > 0.0) ++shore_i;
    const Stroke waterline = re_bake_stroke(scene, *baked, shore_i, side / 2, -1.5);
    Stroke river;
    river.seconds = -1.0;  // -1 s in the report: no river
    if (with_river()) river = re_bake_river(scene, *baked);
    if (!land.error.empty() || !water.error.empty() || !waterline.error.empty() || !river.error.empty()) {
        std::fprintf(stderr, "%s%s%s%s\n", land.error.c_str(), water.error.c_str(), waterline.error.c_str(),
                     river.error.c_str());
        fs::remove_all(dir);
        return 1;
    }
    baked->reset();
    // Loading the saved bake as a scene naming it does (an editor opening the world), with
    // the bake itself released.
    tidewater::Scene named = scene;
    named.shore.bake_folder = dir;
    const auto t3 = Clock::now();
    auto loaded = tidewater::load_scene_bake(named);
    if (!loaded) {
        std::fprintf(stderr, "%s\n", loaded.error().message.c_str());
        fs::remove_all(dir);
        return 1;
    }
    const double load = seconds_since(t3);
    // The load reads the index; the tiles are read on demand. Every one of them, as a
    // renderer's first upload reads them:
    const auto t4 = Clock::now();
    if (const auto& shore = (*loaded)->bake->ocean_shore)
        if (auto st = shore->read_all(); !st) {
            std::fprintf(stderr, "%s\n", st.error().message.c_str());
            fs::remove_all(dir);
            return 1;
        }
    const double read_all = seconds_since(t4);
    if (argc > 6) {
        if (auto st = keep_world(fs::path(argv[6]), dir, scene, side, waves); !st.empty()) {
            std::fprintf(stderr, "%s\n", st.c_str());
            fs::remove_all(dir);
            return 1;
        }
    }
    fs::remove_all(dir);
    std::printf(
        "{\"side_m\": %d, \"waves\": %d, \"seabed_m\": %.0f, \"model_resolution\": %d, \"texel_m\": %.3f, "
        "\"make_s\": %.2f, \"bake_s\": %.2f, \"save_s\": %.2f, \"load_s\": %.2f, \"read_all_s\": %.2f, "
        "\"land_edit_s\": %.3f, \"land_edit_local\": %s, \"water_edit_s\": %.3f, \"water_edit_max_s\": %.3f, "
        "\"water_edit_local\": %s, \"waterline_edit_s\": %.3f, \"waterline_edit_local\": %s, "
        "\"river_edit_s\": %.3f, \"river_edit_local\": %s, "
        "\"peak_rss_mb\": %.0f, "
        "\"folder_mb\": %.1f, \"tiles\": %zu, \"stored_tiles\": %zu, \"runs\": %s, \"model_mb\": %.1f, "
        "\"gpu_shore_mb\": %.1f}\n",
        side, waves, seabed, resolution, model_texel, make, bake, save, load, read_all, land.seconds,
        land.local ? "true" : "false", water.seconds, water_s.back(), water.local ? "true" : "false", waterline.seconds,
        waterline.local ? "true" : "false", river.seconds, river.local ? "true" : "false", peak,
        static_cast<double>(bytes) / 1e6, pages, stored, runs.c_str(), model_mb, gpu_mb);
    return 0;
}
