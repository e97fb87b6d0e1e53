// The shore bake against exact geometry: a circular island and a ring-shaped
// lagoon from heightmaps, within one texel plus the simplification tolerance;
// degenerate terrains bake with documented results; noisy shores are refused.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "../baked_scene.hpp"
#include "shoreline/simplify_line.hpp"
#include "test_helpers.hpp"
#include "tidewater/detail/reference.hpp"
#include "tidewater/detail/shore_bake.hpp"
#include "tidewater/ripples.hpp"

namespace tidewater {
namespace {

/// A heightmap of height(r) over a square of side `size` m centred on the origin.
template <typename Profile>
Terrain radial_heightmap(int pixels, double size, double lo, double hi, const Profile& height) {
    auto img = std::make_shared<Gray16Image>();
    img->width = img->height = pixels;
    img->pixels.resize(static_cast<std::size_t>(pixels * pixels));
    for (int j = 0; j < pixels; ++j)
        for (int i = 0; i < pixels; ++i) {
            const double x = (i / double(pixels - 1) - 0.5) * size, z = (j / double(pixels - 1) - 0.5) * size;
            const double h = std::clamp(height(std::hypot(x, z)), lo, hi);
            img->pixels[static_cast<std::size_t>(j * pixels + i)] =
                static_cast<std::uint16_t>(std::lround((h - lo) / (hi - lo) * 65535.0));
        }
    HeightmapTerrain t;
    t.size = {size, size};
    t.min_height = lo;
    t.max_height = hi;
    t.image = img;
    return Terrain(t);
}

struct Worst {
    double error = 0.0;
    double gradient_error = 0.0;  // against the ideal circle, not the simplified polygon
    double unit_error = 0.0;      // | |gradient| - 1 |
};

/// Largest distance error everywhere; largest gradient error away from the shore and
/// from the medial axis (where the nearest shore point jumps and either side is right).
template <typename Exact, typename NearAxis>
Worst compare(const ShoreField& f, const Exact& exact, const NearAxis& near_medial_axis) {
    Worst w;
    for (int j = 0; j < f.resolution; ++j)
        for (int i = 0; i < f.resolution; ++i) {
            const glm::dvec2 p = f.texel_center(i, j);
            const auto [d, g] = exact(p);
            w.error = std::max(w.error, std::abs(f.signed_distance[f.index(i, j)] - d));
            const glm::dvec2 grad(f.gradient[f.index(i, j)]);
            if (std::abs(d) > 1e-3) w.unit_error = std::max(w.unit_error, std::abs(glm::length(grad) - 1.0));
            if (std::abs(d) > 3 * f.texel && !near_medial_axis(p))
                w.gradient_error = std::max(w.gradient_error, glm::length(grad - g));
        }
    return w;
}

// Island: a cone crossing the water level at r0 = 200 m. Exact: d = r - r0 (water outside).
// The distance gradient is held as its angle in 16 bits: every code reads back as itself,
// a unit vector within half a step (4.8e-5 rad) of what was encoded, and a zero vector
// (no shoreline) as zero.
TEST(ShoreBake, GradientDirectionsKeepTheirAngleToHalfAStep) {
    const double half_step = std::numbers::pi / 65535.0;
    for (std::uint32_t c = 0; c < SharedDirections::kNone; ++c) {
        const auto code = static_cast<std::uint16_t>(c);
        const glm::vec2 v = SharedDirections::decode(code);
        ASSERT_NEAR(glm::length(glm::dvec2(v)), 1.0, 1e-6) << c;
        ASSERT_EQ(SharedDirections::encode(v), code) << c;
    }
    double worst = 0.0;
    for (int k = 0; k < 100000; ++k) {
        const double angle = -3.2 + 6.4 * k / 99999.0;
        const glm::dvec2 v{std::cos(angle), std::sin(angle)};
        const glm::dvec2 back(SharedDirections::decode(SharedDirections::encode(v)));
        worst = std::max(worst, std::abs(std::atan2(v.x * back.y - v.y * back.x, glm::dot(v, back))));
    }
    EXPECT_LE(worst, half_step * (1.0 + 1e-3));
    EXPECT_EQ(SharedDirections::encode(glm::dvec2(0.0)), SharedDirections::kNone);
    EXPECT_EQ(SharedDirections::decode(SharedDirections::kNone), glm::vec2(0.0f));
    EXPECT_EQ(SharedDirections::encode(glm::dvec2(std::nan(""), 1.0)), SharedDirections::kNone);
}

TEST(ShoreBake, CircularIslandMatchesExactDistance) {
    const double r0 = 200.0;
    const Terrain t = radial_heightmap(513, 1000.0, -40.0, 40.0, [&](double r) { return 0.2 * (r0 - r); });
    BakeOptions o;
    o.resolution = 256;
    auto f = bake_shore(t, 0.0, o);
    ASSERT_TRUE(f.ok()) << f.error().message;
    EXPECT_EQ(f->polygons, 1u);
    EXPECT_EQ(f->holes, 0u);
    const Worst w = compare(
        *f,
        [&](glm::dvec2 p) {
            const double r = glm::length(p);
            return std::pair{r - r0, r > 0 ? p / r : glm::dvec2(0.0)};
        },
        [&](glm::dvec2 p) { return glm::length(p) < 0.2 * r0; });
    std::printf("circular island: texel %.3f m, tolerance %.3f m, %zu segments: max |error| %.3f m, gradient %.4f\n",
                f->texel, f->simplify_tolerance, f->segment_count, w.error, w.gradient_error);
    EXPECT_LE(w.error, f->texel + f->simplify_tolerance);
    // The gradient is exact for the simplified polygon (33 sides here), whose edge normals
    // lean up to about 13 degrees from the circle's radial direction near its spokes.
    EXPECT_LT(w.gradient_error, 0.25);
    EXPECT_LT(w.unit_error, 1e-5);
}

// The shoreline is simplified piece by piece between the lattice's crossings (the shore
// tiles' edges): a change to a stretch of coast changes the simplified line only in the
// lattice cells it touches and their neighbours, where the whole loop simplified at once
// may move vertices anywhere on it.
TEST(ShoreBake, AnEditChangesTheSimplifiedShorelineOnlyNearIt) {
    // A loop of radius 500 m with points 1 m apart and a gentle swell on it, and the same
    // with a notch 3 m deep and 40 m wide at angle 0.
    auto loop = [](double notch) {
        ShoreLine line;
        const int n = 3142;
        for (int k = 0; k < n; ++k) {
            const double a = 2.0 * std::numbers::pi * k / n;
            const double s = 500.0 * std::remainder(a, 2.0 * std::numbers::pi);
            const double r = 500.0 + 4.0 * std::sin(7.0 * a) - notch * std::exp(-s * s / (20.0 * 20.0));
            line.points.push_back(r * glm::dvec2(std::cos(a), std::sin(a)));
        }
        return line;
    };
    const ShoreLine before = loop(0.0), after = loop(3.0);
    const detail::SimplifyLattice lattice{glm::dvec2(-1024.0), 64.0};
    // The notch's cells (x 440..512, z -64..64 about it) and their neighbours.
    auto near_notch = [](glm::dvec2 p) { return p.x > 384.0 - 1e-9 && std::abs(p.y) < 128.0; };
    auto far_vertices = [&](const std::vector<glm::dvec2>& v) {
        std::vector<glm::dvec2> far;
        for (const glm::dvec2& p : v)
            if (!near_notch(p)) far.push_back(p);
        std::sort(far.begin(), far.end(),
                  [](glm::dvec2 a, glm::dvec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
        return far;
    };
    const auto pieces_before = detail::simplify_line(before, 1.0, lattice),
               pieces_after = detail::simplify_line(after, 1.0, lattice);
    EXPECT_NE(pieces_before, pieces_after);
    EXPECT_EQ(far_vertices(pieces_before), far_vertices(pieces_after));
    // Within the tolerance of the line it simplifies, as the whole loop's is.
    const auto whole_before = detail::simplify_line(before, 1.0), whole_after = detail::simplify_line(after, 1.0);
    std::printf("a notch simplified: %zu and %zu vertices piece by piece, %zu and %zu whole\n", pieces_before.size(),
                pieces_after.size(), whole_before.size(), whole_after.size());
    EXPECT_LT(pieces_before.size(), before.points.size() / 4);
    EXPECT_NE(far_vertices(whole_before), far_vertices(whole_after)) << "the whole loop's vertices moved far away";
}

// Ring-shaped land around a lagoon: land for 150 < r < 300. Exact: water outside and
// inside, land between; one land polygon with one hole.
TEST(ShoreBake, RingLagoonMatchesExactDistance) {
    const double a = 150.0, b = 300.0, mid = 0.5 * (a + b), half_width = 0.5 * (b - a);
    const Terrain t =
        radial_heightmap(513, 1000.0, -40.0, 40.0, [&](double r) { return 0.2 * (half_width - std::abs(r - mid)); });
    BakeOptions o;
    o.resolution = 256;
    auto f = bake_shore(t, 0.0, o);
    ASSERT_TRUE(f.ok()) << f.error().message;
    EXPECT_EQ(f->polygons, 1u);
    EXPECT_EQ(f->holes, 1u);
    const Worst w = compare(
        *f,
        [&](glm::dvec2 p) {
            const double r = glm::length(p);
            const glm::dvec2 out = r > 0 ? p / r : glm::dvec2(0.0);
            if (r < a) return std::pair{a - r, -out};                                     // lagoon water
            if (r > b) return std::pair{r - b, out};                                      // open sea
            return r - a < b - r ? std::pair{-(r - a), -out} : std::pair{-(b - r), out};  // land
        },
        [&](glm::dvec2 p) { return glm::length(p) < 0.2 * a || std::abs(glm::length(p) - mid) < 0.2 * half_width; });
    std::printf("ring lagoon: max |error| %.3f m (texel %.3f m + tolerance %.3f m), gradient %.4f\n", w.error, f->texel,
                f->simplify_tolerance, w.gradient_error);
    EXPECT_LE(w.error, f->texel + f->simplify_tolerance);
    EXPECT_LT(w.gradient_error, 0.25);
    EXPECT_LT(w.unit_error, 1e-5);
}

TEST(ShoreBake, CgalDistanceEqualsBruteForce) {
    auto scene = test::baked(default_scene());
    ASSERT_TRUE(scene.ok());
    BakeOptions o;
    o.resolution = 128;
    auto f = bake_shore(scene->terrain, scene->water_level(), o);
    ASSERT_TRUE(f.ok()) << f.error().message;
    EXPECT_GT(f->segment_count, 30u);
    for (int j = 0; j < f->resolution; j += 7)
        for (int i = 0; i < f->resolution; i += 5) {
            const double brute = reference::brute_force_shore_distance(*f, f->texel_center(i, j));
            ASSERT_NEAR(std::abs(f->signed_distance[f->index(i, j)]), brute, 1e-3 + 1e-6 * brute) << i << "," << j;
        }
    // Depth is the water column.
    const glm::dvec2 p = f->texel_center(3, 3);
    EXPECT_NEAR(f->depth[f->index(3, 3)], scene->water_level() - scene->terrain.height_at(p), 1e-3);
}

/// Hundreds of islands from fractal noise: a coast with every kind of curvature.
Terrain noisy_archipelago(int pixels, double size) {
    auto img = std::make_shared<Gray16Image>();
    img->width = img->height = pixels;
    img->pixels.resize(static_cast<std::size_t>(pixels * pixels));
    for (int j = 0; j < pixels; ++j)
        for (int i = 0; i < pixels; ++i) {
            glm::dvec2 q = glm::dvec2(i - pixels / 2, j - pixels / 2) * (size / pixels) / 150.0;
            double h = 0.0, a = 30.0;
            for (int o = 0; o < 5; ++o, q *= 2.3, a *= 0.6)
                h += a * gradient_noise(q, 7u + static_cast<std::uint32_t>(o)).value;
            img->pixels[static_cast<std::size_t>(j * pixels + i)] =
                static_cast<std::uint16_t>(std::clamp((h + 60.0) / 120.0 * 65535.0, 0.0, 65535.0));
        }
    HeightmapTerrain t;
    t.size = {size, size};
    t.min_height = -60.0;
    t.max_height = 60.0;
    t.image = img;
    return Terrain(t);
}

// The bake answers by blocks of texels sharing candidate lists; every texel must still
// get its exact nearest segment, at any resolution (partial blocks) and thread count.
TEST(ShoreBake, EveryTexelIsExactAndThreadCountDoesNotMatter) {
    const Terrain terrain = noisy_archipelago(512, 1200.0);
    for (int resolution : {203, 256}) {
        BakeOptions o;
        o.resolution = resolution;
        o.threads = 1;
        auto one = bake_shore(terrain, 0.0, o);
        ASSERT_TRUE(one.ok()) << one.error().message;
        EXPECT_GT(one->segment_count, 500u);
        EXPECT_GT(one->polygons, 10u);
        double worst = 0.0;
        for (int j = 0; j < resolution; ++j)
            for (int i = 0; i < resolution; ++i) {
                const std::size_t k = one->index(i, j);
                const double brute = reference::brute_force_shore_distance(*one, one->texel_center(i, j));
                worst = std::max(worst,
                                 std::abs(std::abs(double(one->signed_distance[k])) - brute) / (1e-4 + 1e-6 * brute));
                // The sign is the texel's side of the water level, even within the simplification
                // tolerance and beyond an open line's end along the domain edge (0 on the line).
                if (one->signed_distance[k] != 0.0f) {
                    ASSERT_EQ(one->signed_distance[k] > 0.0f, one->depth[k] > 0.0f) << i << "," << j;
                }
                const double g = glm::length(glm::dvec2(one->gradient[k]));
                ASSERT_NEAR(g, 1.0, 1e-5) << i << "," << j;
            }
        EXPECT_LT(worst, 1.0) << "distance error in units of (0.1 mm + 1e-6 d) at resolution " << resolution;
        o.threads = 3;
        auto three = bake_shore(terrain, 0.0, o);
        ASSERT_TRUE(three.ok());
        EXPECT_EQ(one->signed_distance, three->signed_distance);
        EXPECT_EQ(one->gradient, three->gradient);
        EXPECT_EQ(one->segment_count, three->segment_count);
    }
}

// Degenerate terrains: all water, all land, a one-texel island, touching islands (a
// saddle), a shore that leaves the domain. Documented results in shore_bake.hpp.
TEST(ShoreBake, DegenerateTerrainsBake) {
    BakeOptions o;
    o.resolution = 64;
    auto water = bake_shore(Terrain(FlatTerrain{-10.0}), 0.0, o);
    ASSERT_TRUE(water.ok());
    EXPECT_EQ(water->segment_count, 0u);
    EXPECT_GT(water->signed_distance[0], 0.0f);
    auto land = bake_shore(Terrain(FlatTerrain{10.0}), 0.0, o);
    ASSERT_TRUE(land.ok());
    EXPECT_LT(land->signed_distance[0], 0.0f);

    auto pixel_map = [](std::vector<std::pair<int, int>> land_pixels) {
        auto img = std::make_shared<Gray16Image>();
        img->width = img->height = 16;
        img->pixels.assign(256, 0);
        for (auto [i, j] : land_pixels) img->pixels[static_cast<std::size_t>(j * 16 + i)] = 65535;
        HeightmapTerrain t;
        t.size = {160.0, 160.0};
        t.min_height = -5;
        t.max_height = 5;
        t.image = img;
        return Terrain(t);
    };
    auto single = bake_shore(pixel_map({{8, 8}}), 0.0, o);
    ASSERT_TRUE(single.ok()) << single.error().message;
    EXPECT_EQ(single->polygons, 1u);
    EXPECT_LT(single->distance_at({5.0, 5.0}), 0.0);  // the island's pixel centre is land
    auto touching = bake_shore(pixel_map({{5, 5}, {6, 6}, {9, 9}, {10, 10}}), 0.0, o);
    ASSERT_TRUE(touching.ok()) << touching.error().message;
    EXPECT_GE(touching->polygons, 2u);

    // h = -10 + 0.02 x: the shore is the line x = 500, leaving the domain at both ends.
    PlaneTerrain plane;
    plane.height = -10.0;
    plane.slope = {0.02, 0.0};
    auto edge = bake_shore(Terrain(plane), 0.0, o);
    ASSERT_TRUE(edge.ok());
    ASSERT_FALSE(edge->shorelines.empty());
    EXPECT_FALSE(edge->shorelines[0].closed);
    for (int i = 0; i < 64; i += 9) {
        const glm::dvec2 p = edge->texel_center(i, 20);
        EXPECT_NEAR(edge->signed_distance[edge->index(i, 20)], 500.0 - p.x, edge->texel) << p.x;
    }
}

TEST(ShoreBake, BadInputIsRefused) {
    BakeOptions o;
    o.resolution = 4;
    EXPECT_FALSE(bake_shore(Terrain(FlatTerrain{-1.0}), 0.0, o).ok());
    o.resolution = 64;
    EXPECT_FALSE(bake_shore(Terrain(FlatTerrain{-1.0}), std::nan(""), o).ok());
    // Non-finite terrain heights name where.
    PlaneTerrain nan_plane;
    nan_plane.height = std::nan("");
    auto bad = bake_shore(Terrain(nan_plane), 0.0, o);
    ASSERT_FALSE(bad.ok());
    EXPECT_NE(bad.error().message.find("not finite at x ="), std::string::npos) << bad.error().message;
    // A checkerboard at the water level: every cell crosses the shore.
    auto img = std::make_shared<Gray16Image>();
    img->width = img->height = 512;
    img->pixels.resize(512 * 512);
    for (int j = 0; j < 512; ++j)
        for (int i = 0; i < 512; ++i) img->pixels[static_cast<std::size_t>(j * 512 + i)] = ((i + j) & 1) ? 65535 : 0;
    HeightmapTerrain noisy;
    noisy.size = {512.0, 512.0};
    noisy.image = img;
    o.resolution = 512;
    auto refused = bake_shore(Terrain(noisy), 0.0, o);
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().message.find("too noisy"), std::string::npos) << refused.error().message;
}

}  // namespace
}  // namespace tidewater
