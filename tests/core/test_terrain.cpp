// Terrains: heightmap loading and sampling, bad heightmaps, the procedural island.
#include <cmath>
#include <filesystem>
#include <fstream>

#include "test_helpers.hpp"
#include "tidewater/detail/image_io.hpp"
#include "tidewater/detail/image_write.hpp"

namespace tidewater {
namespace {

namespace fs = std::filesystem;

fs::path temp_dir(const char* name) {
    const fs::path dir = fs::temp_directory_path() / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

/// A 16-bit heightmap of a cone: height 20 m at the centre falling to -20 m at the edge.
Gray16Image cone(int n) {
    Gray16Image img;
    img.width = img.height = n;
    img.pixels.resize(static_cast<std::size_t>(n * n));
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            const double u = (i / double(n - 1)) * 2.0 - 1.0, v = (j / double(n - 1)) * 2.0 - 1.0;
            const double h = 20.0 - 40.0 * std::min(1.0, std::sqrt(u * u + v * v));  // in [-20, 20]
            img.pixels[static_cast<std::size_t>(j * n + i)] =
                static_cast<std::uint16_t>(std::lround((h + 20.0) / 40.0 * 65535.0));
        }
    }
    return img;
}

// A heightmap written as 16-bit PNG and loaded through a scene samples back within
// the 16-bit quantisation (40 m / 65535 = 0.6 mm) at pixel centres.
// A 16-bit PNG written a row at a time reads back sample for sample (both bytes of each
// sample differ across the image, so a byte order mix-up shows), and a write that cannot
// happen leaves no file.
TEST(Terrain, PngRowsRoundTripExactly) {
    const fs::path dir = temp_dir("tidewater_png_rows_test");
    auto sample = [](int i, int j) { return static_cast<std::uint16_t>((i * 2654435761u + j * 40503u) & 0xffffu); };
    ASSERT_TRUE(detail::write_png_gray16_rows(dir / "rows.png", 37, 23, [&](int j, std::uint16_t* row) {
                    for (int i = 0; i < 37; ++i) row[i] = sample(i, j);
                }).ok());
    auto back = detail::read_png_gray16(dir / "rows.png");
    ASSERT_TRUE(back.ok()) << back.error().message;
    ASSERT_EQ(back->width, 37);
    ASSERT_EQ(back->height, 23);
    for (int j = 0; j < 23; ++j)
        for (int i = 0; i < 37; ++i) ASSERT_EQ(back->pixels[static_cast<std::size_t>(j) * 37 + i], sample(i, j));
    const auto missing = detail::write_png_gray16_rows(dir / "no_such_folder" / "rows.png", 4, 4,
                                                       [](int, std::uint16_t* row) { std::fill_n(row, 4, 0); });
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error().message.find("no_such_folder"), std::string::npos);
    EXPECT_FALSE(detail::write_png_gray16_rows(dir / "empty.png", 0, 4, [](int, std::uint16_t*) {}).ok());
    EXPECT_FALSE(fs::exists(dir / "empty.png"));
}

// A baked grid's rows (written with the Up filter at zlib level 4) read back sample for
// sample; a PNG whose first IDAT chunk is empty is refused by name before stb reads it.
TEST(Terrain, SmoothPngRowsRoundTripAndEmptyImageDataIsRefused) {
    const fs::path dir = temp_dir("tidewater_png_smooth_test");
    auto sample = [](int i, int j) { return static_cast<std::uint16_t>(30000 + 37 * i - 11 * j + (i * j) % 7); };
    ASSERT_TRUE(detail::write_png_gray16_rows(
                    dir / "smooth.png", 41, 29,
                    [&](int j, std::uint16_t* row) {
                        for (int i = 0; i < 41; ++i) row[i] = sample(i, j);
                    },
                    true)
                    .ok());
    auto back = detail::read_png_gray16(dir / "smooth.png");
    ASSERT_TRUE(back.ok()) << back.error().message;
    for (int j = 0; j < 29; ++j)
        for (int i = 0; i < 41; ++i) ASSERT_EQ(back->pixels[static_cast<std::size_t>(j) * 41 + i], sample(i, j));
    // An empty IDAT chunk (its CRC included) put before the image's first.
    std::ifstream in(dir / "smooth.png", std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::size_t idat = bytes.find("IDAT");
    ASSERT_NE(idat, std::string::npos);
    const char empty_idat[12] = {0, 0, 0, 0, 'I', 'D', 'A', 'T', '\x35', '\xaf', '\x06', '\x1e'};
    bytes.insert(idat - 4, empty_idat, sizeof empty_idat);
    std::ofstream(dir / "empty_idat.png", std::ios::binary) << bytes;
    auto refused = detail::read_png_gray16(dir / "empty_idat.png");
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().message.find("empty_idat.png: corrupt PNG (an empty IDAT chunk"), std::string::npos)
        << refused.error().message;
}

TEST(Terrain, HeightmapRoundTripsThroughPng) {
    const fs::path dir = temp_dir("tidewater_heightmap_test");
    ASSERT_TRUE(detail::write_png_gray16(dir / "cone.png", cone(65)).ok());
    std::ofstream(dir / "scene.json") << R"({"version": 1, "water_level": 0,
        "terrain": {"heightmap": {"file": "cone.png", "size": [640, 640], "height_range": [-20, 20], "center": [100, 0]}},
        "ocean": "pool_calm"})";
    auto scene = load_scene(dir / "scene.json");
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    const Terrain& t = scene->terrain;
    EXPECT_STREQ(t.kind_name(), "heightmap");
    EXPECT_NEAR(t.height_at({100.0, 0.0}), 20.0, 1e-3);                         // centre pixel
    EXPECT_NEAR(t.height_at({100.0 + 320.0, 0.0}), -20.0, 1e-3);                // edge
    EXPECT_NEAR(t.height_at({100.0 + 160.0, 0.0}), 0.0, 1e-3);                  // half way: 20 - 40 * 0.5
    EXPECT_NEAR(t.height_at({5000.0, 0.0}), t.height_at({420.0, 0.0}), 1e-12);  // edge extends
    EXPECT_DOUBLE_EQ(t.extent_half_size(), 320.0 + 40.0);                       // with its fade to the seabed
    fs::remove_all(dir);
}

// Beyond its pixel centres a heightmap's edge value eases down to its lowest height over
// a sixteenth of its larger side, so that land at the edge of the data does not stand as a
// wall or a plateau to the horizon.
TEST(Terrain, AHeightmapFadesToItsSeabedBeyondItsEdge) {
    auto image = std::make_shared<Gray16Image>();
    image->width = image->height = 3;
    image->pixels.assign(9, 65535);  // all at the highest: 30 m
    image->pixels[4] = 0;            // the centre at the lowest: -10 m
    HeightmapTerrain map;
    map.size = {400.0, 200.0};
    map.min_height = -10.0;
    map.max_height = 30.0;
    map.image = image;
    const Terrain t(map);
    EXPECT_NEAR(t.height_at({200.0, 0.0}), 30.0, 1e-9);  // the east edge's centre pixel
    const HeightmapEdgeFade fade = heightmap_edge_fade(map);
    EXPECT_DOUBLE_EQ(fade.distance, 25.0);
    EXPECT_DOUBLE_EQ(fade.seabed, -10.0);
    EXPECT_DOUBLE_EQ(t.extent_half_size(), 225.0);
    EXPECT_NEAR(t.height_at({212.5, 0.0}), 30.0 - 40.0 * 0.5, 1e-9);  // half way: smoothstep(0.5) = 0.5
    EXPECT_NEAR(t.height_at({225.0, 0.0}), -10.0, 1e-9);
    EXPECT_NEAR(t.height_at({5000.0, -3000.0}), -10.0, 1e-9);
    // Continuous at the edge, and easing in: 0.25 m beyond it the ground has dropped 1.2 cm.
    EXPECT_NEAR(t.height_at({200.25, 0.0}), 30.0 - 40.0 * (3e-4 - 2e-6), 1e-9);
}

TEST(Terrain, BadHeightmapsNameTheFile) {
    const fs::path dir = temp_dir("tidewater_bad_heightmap_test");
    std::ofstream(dir / "garbage.png") << "this is not a png";
    const std::vector<std::uint8_t> rgba(4 * 4 * 4, 200);
    ASSERT_TRUE(detail::write_png_rgba8(dir / "colour.png", 4, 4, rgba).ok());
    auto scene_text = [](const char* file) {
        return std::string(R"({"version": 1, "water_level": 0, "terrain": {"heightmap": {"file": ")") + file +
               R"(", "size": [100, 100], "height_range": [-5, 5]}}, "ocean": "pool_calm"})";
    };
    struct Case {
        const char* file;
        const char* expected;
    };
    for (const Case& c : {Case{"missing.png", "cannot open"}, Case{"garbage.png", "not a readable image"},
                          Case{"colour.png", "16-bit greyscale"}}) {
        auto scene = parse_scene(scene_text(c.file), "s.json", dir);
        ASSERT_FALSE(scene.ok()) << c.file;
        EXPECT_NE(scene.error().message.find("s.json: /terrain/heightmap/file"), std::string::npos)
            << scene.error().message;
        EXPECT_NE(scene.error().message.find(c.file), std::string::npos) << scene.error().message;
        EXPECT_NE(scene.error().message.find(c.expected), std::string::npos) << scene.error().message;
    }
    auto bad_range =
        parse_scene(R"({"version": 1, "water_level": 0, "terrain": {"heightmap": {"file": "x.png", "size": [100, 0],
        "height_range": [-5, 5]}}, "ocean": "pool_calm"})",
                    "s.json", dir);
    ASSERT_FALSE(bad_range.ok());
    EXPECT_NE(bad_range.error().message.find("/terrain/heightmap/size"), std::string::npos);
    fs::remove_all(dir);
}

// A knoll adds height (1 - (r/R)^2)^2 to the island and nothing beyond its radius.
TEST(Terrain, AKnollRisesFromTheIslandAndEndsAtItsRadius) {
    IslandTerrain plain;
    IslandTerrain knolled = plain;
    knolled.knolls.push_back({{100.0, -50.0}, 12.0, 4.0});
    const Terrain a(plain), b(knolled);
    EXPECT_NEAR(b.height_at({100.0, -50.0}) - a.height_at({100.0, -50.0}), 4.0, 1e-9);
    EXPECT_NEAR(b.height_at({106.0, -50.0}) - a.height_at({106.0, -50.0}), 4.0 * 0.75 * 0.75, 1e-9);  // r/R = 1/2
    EXPECT_EQ(b.height_at({112.5, -50.0}), a.height_at({112.5, -50.0}));
    EXPECT_FALSE(a == b);
}

// The island: land in the middle, the seabed far out, both gentle beaches and
// steep cliffs at the waterline, and an enclosed lagoon below the water level.
TEST(Terrain, ProceduralIslandHasBeachesCliffsAndLagoon) {
    IslandTerrain spec;
    const Terrain t(spec);
    EXPECT_NEAR(t.height_at({5000.0, 0.0}), spec.seabed, 1.0);
    int land = 0;
    double gentlest = 1e9, steepest = 0.0;
    for (int a = 0; a < 720; ++a) {
        const double ang = a * kPi / 360.0;
        const glm::dvec2 dir{std::cos(ang), std::sin(ang)};
        // Find the waterline along the ray by bisection between 0.3 R and 2 R.
        double lo = 0.3 * spec.radius, hi = 2.0 * spec.radius;
        if (t.height_at(dir * lo) <= 0.0) continue;  // the ray starts in the lagoon
        ++land;
        for (int i = 0; i < 60; ++i) {
            const double mid = 0.5 * (lo + hi);
            (t.height_at(dir * mid) > 0.0 ? lo : hi) = mid;
        }
        const double slope = (t.height_at(dir * (lo - 1.0)) - t.height_at(dir * (lo + 1.0))) / 2.0;
        gentlest = std::min(gentlest, slope);
        steepest = std::max(steepest, slope);
    }
    EXPECT_GT(land, 600);
    EXPECT_LT(gentlest, 0.1);  // a beach: under about 6 degrees
    EXPECT_GT(steepest, 0.7);  // a cliff: over 35 degrees
    // Water inland: the lagoon basin sits within 0.6 R of the centre, enclosed by land.
    int inland_water = 0;
    for (int i = 0; i < 400; ++i)
        for (int j = 0; j < 400; ++j) {
            const glm::dvec2 p{(i - 200) * 3.0, (j - 200) * 3.0};
            if (glm::length(p) < 0.6 * spec.radius && t.height_at(p) < -2.0) ++inland_water;
        }
    EXPECT_GT(inland_water, 500);
}

}  // namespace
}  // namespace tidewater
