#include "tidewater/terrain.hpp"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>

#include "tidewater/constants.hpp"
#include "tidewater/detail/overloaded.hpp"
#include "tidewater/ripples.hpp"

namespace tidewater {

namespace {

using detail::Overloaded;

double sample_heightmap(const HeightmapTerrain& t, glm::dvec2 p) {
    const Gray16Image& img = *t.image;
    // Pixel centres span the extent: u = 0 at the first centre, width-1 at the last.
    const double u = ((p.x - t.center.x) / t.size.x + 0.5) * (img.width - 1);
    const double v = ((p.y - t.center.y) / t.size.y + 0.5) * (img.height - 1);
    const double cu = std::clamp(u, 0.0, static_cast<double>(img.width - 1));
    const double cv = std::clamp(v, 0.0, static_cast<double>(img.height - 1));
    const int i0 = std::min(static_cast<int>(cu), img.width - 2), j0 = std::min(static_cast<int>(cv), img.height - 2);
    const double fu = cu - i0, fv = cv - j0;
    auto at = [&](int i, int j) {
        return static_cast<double>(img.pixels[static_cast<std::size_t>(j) * static_cast<std::size_t>(img.width) +
                                              static_cast<std::size_t>(i)]);
    };
    const double raw = (1 - fv) * ((1 - fu) * at(i0, j0) + fu * at(i0 + 1, j0)) +
                       fv * ((1 - fu) * at(i0, j0 + 1) + fu * at(i0 + 1, j0 + 1));
    const double h = t.min_height + (t.max_height - t.min_height) * raw / 65535.0;
    // Beyond the pixel centres: the edge value eased to the seabed.
    const glm::dvec2 outside = glm::max(glm::abs(p - t.center) - 0.5 * t.size, glm::dvec2(0.0));
    const double beyond = std::sqrt(outside.x * outside.x + outside.y * outside.y);
    if (beyond <= 0.0) return h;
    const HeightmapEdgeFade fade = heightmap_edge_fade(t);
    const double s = std::clamp(beyond / fade.distance, 0.0, 1.0);
    return h + (fade.seabed - h) * s * s * (3.0 - 2.0 * s);
}

}  // namespace

HeightmapEdgeFade heightmap_edge_fade(const HeightmapTerrain& t) {
    return {std::max(t.size.x, t.size.y) / 16.0, t.min_height};
}

namespace {

double fbm(glm::dvec2 p, std::uint32_t seed, int octaves) {
    double sum = 0.0, amp = 0.5;
    for (int i = 0; i < octaves; ++i) {
        sum += amp * gradient_noise(p, seed + static_cast<std::uint32_t>(i) * 101u).value;
        p *= 2.03;
        amp *= 0.5;
    }
    return sum;
}

double sample_island(const IslandTerrain& t, glm::dvec2 p) {
    const glm::dvec2 d = p - t.center;
    const double r = std::sqrt(d.x * d.x + d.y * d.y);
    const glm::dvec2 dir = r > 1e-9 ? d / r : glm::dvec2(1.0, 0.0);
    // The coastline radius wobbles with direction; cliffs stand where a second noise is high.
    const double coast = t.radius * (1.0 + 0.45 * fbm(dir * 1.8 + 10.0, t.seed, 4));
    const double cliff = std::clamp(4.0 * fbm(dir * 0.9 + 40.0, t.seed + 17u, 2), 0.0, 1.0);
    const double s = r - coast;  // signed distance to the coast along the ray, > 0 offshore
    double h;
    if (s > 0.0) {
        // Underwater: a gentle shelf off beaches, a steep drop under cliffs, then the seabed.
        const double slope = 0.04 + (1.2 - 0.04) * cliff;
        h = t.seabed * (1.0 - std::exp(slope * s / t.seabed));
    } else {
        const double inland = -s;
        const double beach = std::min(0.05 * inland, 3.0);                         // ~3 degrees, up to 3 m
        const double cliff_step = cliff * 25.0 * (1.0 - std::exp(-inland / 6.0));  // a 25 m wall
        const double hills = t.height * (0.7 + 1.2 * fbm(p / 450.0, t.seed + 3u, 4));
        const double ramp = std::clamp((inland - 40.0) / 310.0, 0.0, 1.0);
        h = beach + cliff_step + std::max(0.0, hills) * ramp * ramp * (3.0 - 2.0 * ramp) +
            5.0 * fbm(p / 70.0, t.seed + 5u, 3) * std::min(1.0, inland / 60.0);
    }
    // An enclosed lagoon inland: a basin below the water level, ringed by land.
    const double angle = 2.0 * kPi * static_cast<double>(t.seed % 360u) / 360.0;
    const glm::dvec2 lagoon = t.center + 0.3 * t.radius * glm::dvec2(std::cos(angle), std::sin(angle));
    const double rl = 0.3 * t.radius * (1.0 + 0.25 * fbm(p / 120.0, t.seed + 9u, 2));
    const glm::dvec2 dl = p - lagoon;
    const double ql = std::sqrt(dl.x * dl.x + dl.y * dl.y) / rl;
    if (ql < 1.0) {
        const double w = 1.0 - ql * ql;
        const double blend = w * w * (3.0 - 2.0 * w);
        h = h * (1.0 - blend) + (-8.0 + 2.0 * ql) * blend;
    }
    for (const Knoll& k : t.knolls) {
        const glm::dvec2 dk = p - k.at;
        const double q = (dk.x * dk.x + dk.y * dk.y) / (k.radius * k.radius);
        if (q < 1.0) h += k.height * (1.0 - q) * (1.0 - q);
    }
    return h;
}

}  // namespace

double TerrainCut::depth_at(glm::dvec2 p) const {
    const double u = (p.x - corner.x) / texel - 0.5, v = (p.y - corner.y) / texel - 0.5;
    // Half a texel of zero cut rings the grid, so the cut fades to nothing at its edge.
    if (!(u > -1.0 && v > -1.0 && u < nx && v < nz)) return 0.0;
    const int i0 = static_cast<int>(std::floor(u)), j0 = static_cast<int>(std::floor(v));
    const double fu = u - i0, fv = v - j0;
    auto at = [&](int i, int j) -> double {
        if (i < 0 || j < 0 || i >= nx || j >= nz) return 0.0;
        return static_cast<double>(
            depth[static_cast<std::size_t>(j) * static_cast<std::size_t>(nx) + static_cast<std::size_t>(i)]);
    };
    return (1 - fv) * ((1 - fu) * at(i0, j0) + fu * at(i0 + 1, j0)) +
           fv * ((1 - fu) * at(i0, j0 + 1) + fu * at(i0 + 1, j0 + 1));
}

double Terrain::height_at(glm::dvec2 p) const {
    double cut = 0.0;
    for (const auto& c : cuts_) cut = std::max(cut, c->depth_at(p));
    return shape_height_at(p) - cut;
}

Terrain Terrain::with_cuts(std::vector<std::shared_ptr<const TerrainCut>> cuts) const {
    Terrain t = *this;
    t.cuts_ = std::move(cuts);
    return t;
}

double Terrain::shape_height_at(glm::dvec2 p) const {
    return std::visit(Overloaded{[](const FlatTerrain& f) { return f.height; },
                                 [&](const PlaneTerrain& s) { return s.height + s.slope.x * p.x + s.slope.y * p.y; },
                                 [&](const HeightmapTerrain& h) { return sample_heightmap(h, p); },
                                 [&](const IslandTerrain& i) { return sample_island(i, p); }},
                      shape_);
}

const char* Terrain::kind_name() const {
    return std::visit(
        Overloaded{[](const FlatTerrain&) { return "flat"; }, [](const PlaneTerrain&) { return "plane"; },
                   [](const HeightmapTerrain&) { return "heightmap"; }, [](const IslandTerrain&) { return "island"; }},
        shape_);
}

glm::dvec2 Terrain::extent_center() const {
    return std::visit(
        Overloaded{[](const FlatTerrain&) { return glm::dvec2(0.0); },
                   [](const PlaneTerrain&) { return glm::dvec2(0.0); },
                   [](const HeightmapTerrain& h) { return h.center; }, [](const IslandTerrain& i) { return i.center; }},
        shape_);
}

double Terrain::extent_half_size() const {
    return std::visit(
        Overloaded{[](const FlatTerrain& f) { return f.half_size; }, [](const PlaneTerrain& p) { return p.half_size; },
                   [](const HeightmapTerrain& h) {
                       // The heightmap and its fade to the seabed: the ground a bake must see.
                       return 0.5 * std::max(h.size.x, h.size.y) + heightmap_edge_fade(h).distance;
                   },
                   [](const IslandTerrain& i) { return 2.5 * i.radius; }},
        shape_);
}

}  // namespace tidewater
