#include "terrain_lod.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

namespace tidewater::render::detail {

namespace {

constexpr double kPatchQuads = gpu::kTerrainPatchQuads;

double band_gap(const TerrainLodGrid& grid, double y) {
    return y > grid.highest ? y - grid.highest : (y < grid.lowest ? grid.lowest - y : 0.0);
}

/// The frustum's side and near planes (reversed Z, infinite far) in world relative to O.
std::array<glm::vec4, 5> frustum_planes(const glm::mat4& m) {
    const glm::vec4 r0(m[0][0], m[1][0], m[2][0], m[3][0]), r1(m[0][1], m[1][1], m[2][1], m[3][1]),
        r2(m[0][2], m[1][2], m[2][2], m[3][2]), r3(m[0][3], m[1][3], m[2][3], m[3][3]);
    return {r3 + r0, r3 - r0, r3 + r1, r3 - r1, r3 - r2};
}

class Selector {
  public:
    Selector(const TerrainLodGrid& grid, const TerrainLodView& view, int levels)
        : grid_(grid), view_(view), planes_(frustum_planes(view.view_proj)), dy_(band_gap(grid, view.camera.y)) {
        for (int l = 0; l < levels; ++l)
            range_[static_cast<std::size_t>(l)] = terrain_lod_range(grid, view.pixel_angle, l);
    }

    /// Strugar's LODSelect: false when the node lies beyond its level's range (its parent
    /// draws the area instead).
    bool select(int level, glm::dvec2 corner, glm::dvec2 side) {
        if (min_distance(corner, side) > range(level)) return false;
        if (!visible(corner, side)) return true;
        if (level == 0 || min_distance(corner, side) > range(level - 1)) {
            add(0, level, corner, side);
            return true;
        }
        const glm::dvec2 half = 0.5 * side;
        for (int q = 0; q < 4; ++q) {
            const glm::dvec2 c = corner + glm::dvec2((q & 1) * half.x, (q >> 1) * half.y);
            if (!select(level - 1, c, half)) add(1 + q, level, corner, side);
        }
        return true;
    }

    /// A root beyond the last level's range: drawn whole at that level if it is in view.
    void add_whole(int level, glm::dvec2 corner, glm::dvec2 side) {
        if (visible(corner, side)) add(0, level, corner, side);
    }

    TerrainSelection finish() {
        TerrainSelection s;
        for (std::size_t g = 0; g < groups_.size(); ++g) {
            s.first[g] = static_cast<std::uint32_t>(s.nodes.size());
            s.count[g] = static_cast<std::uint32_t>(groups_[g].size());
            s.nodes.insert(s.nodes.end(), groups_[g].begin(), groups_[g].end());
        }
        s.truncated = truncated_;
        return s;
    }

  private:
    double range(int level) const { return range_[static_cast<std::size_t>(level)]; }

    double min_distance(glm::dvec2 corner, glm::dvec2 side) const {
        const glm::dvec2 cam{view_.camera.x, view_.camera.z};
        const glm::dvec2 d = glm::max(glm::max(corner - cam, cam - (corner + side)), glm::dvec2(0.0));
        return std::sqrt(d.x * d.x + d.y * d.y + dy_ * dy_);
    }

    bool visible(glm::dvec2 corner, glm::dvec2 side) const {
        const glm::vec3 lo(static_cast<float>(corner.x - view_.origin.x), static_cast<float>(grid_.lowest),
                           static_cast<float>(corner.y - view_.origin.y));
        const glm::vec3 hi =
            lo + glm::vec3(static_cast<float>(side.x), static_cast<float>(grid_.highest - grid_.lowest),
                           static_cast<float>(side.y));
        for (const glm::vec4& p : planes_) {
            // The box's corner farthest along the plane's normal.
            const glm::vec3 v(p.x >= 0 ? hi.x : lo.x, p.y >= 0 ? hi.y : lo.y, p.z >= 0 ? hi.z : lo.z);
            if (p.x * v.x + p.y * v.y + p.z * v.z + p.w < 0.0f) return false;
        }
        return true;
    }

    void add(int group, int level, glm::dvec2 corner, glm::dvec2 side) {
        if (count_ >= kMaxTerrainNodes) {
            truncated_ = true;
            return;
        }
        ++count_;
        // The morph of this level: from kTerrainMorphStart of the way between the previous
        // range and this one, to this one.
        const double end = range(level), previous = level > 0 ? range(level - 1) : 0.0;
        const double start = previous + kTerrainMorphStart * (end - previous);
        gpu::GpuTerrainNode n;
        n.rect = glm::vec4(static_cast<float>(corner.x - view_.origin.x), static_cast<float>(corner.y - view_.origin.y),
                           static_cast<float>(side.x), static_cast<float>(level));
        n.morph = glm::vec4(static_cast<float>(start), static_cast<float>(1.0 / (end - start)),
                            static_cast<float>(dy_ * dy_), static_cast<float>(side.y));
        groups_[static_cast<std::size_t>(group)].push_back(n);
    }

    const TerrainLodGrid& grid_;
    const TerrainLodView& view_;
    std::array<glm::vec4, 5> planes_;
    double dy_;
    std::array<double, kMaxTerrainLevels> range_{};
    std::array<std::vector<gpu::GpuTerrainNode>, 5> groups_;
    std::size_t count_ = 0;
    bool truncated_ = false;
};

}  // namespace

double terrain_lod_range(const TerrainLodGrid& grid, double pixel_angle, int level) {
    const double quad = std::max(grid.finest_quad.x, grid.finest_quad.y) * std::ldexp(1.0, level);
    return std::max(quad / (kTerrainQuadPixels * pixel_angle), kTerrainRangeOverNode * kPatchQuads * quad);
}

double terrain_lod_distance(const TerrainLodGrid& grid, const TerrainLodView& view, glm::dvec2 xz) {
    const double dy = band_gap(grid, view.camera.y);
    const glm::dvec2 d = xz - glm::dvec2(view.camera.x, view.camera.z);
    return std::sqrt(d.x * d.x + d.y * d.y + dy * dy);
}

glm::dvec2 terrain_vertex_xz(const gpu::GpuTerrainNode& node, glm::dvec2 grid, glm::dvec2 camera_xz) {
    const glm::dvec2 quad = glm::dvec2(node.rect.z, node.morph.w) / kPatchQuads;
    const glm::dvec2 xz = glm::dvec2(node.rect.x, node.rect.y) + grid * quad;
    const glm::dvec2 d = xz - camera_xz;
    const double distance = std::sqrt(d.x * d.x + d.y * d.y + static_cast<double>(node.morph.z));
    const double morph =
        std::clamp((distance - static_cast<double>(node.morph.x)) * static_cast<double>(node.morph.y), 0.0, 1.0);
    return xz - glm::fract(grid * 0.5) * 2.0 * quad * morph;
}

TerrainSelection select_terrain_nodes(const TerrainLodGrid& grid, const TerrainLodView& view) {
    // The coarsest level reaches the region's farthest corner (or the last level allowed).
    const glm::dvec2 cam{view.camera.x, view.camera.z};
    const glm::dvec2 far = glm::max(glm::abs(grid.region_min - cam), glm::abs(grid.region_max - cam));
    const double reach = std::sqrt(far.x * far.x + far.y * far.y + std::pow(band_gap(grid, view.camera.y), 2.0));
    int top = 0;
    while (top + 1 < kMaxTerrainLevels && terrain_lod_range(grid, view.pixel_angle, top) < reach) ++top;
    Selector selector(grid, view, top + 1);
    // Root nodes of the top level, on a world-aligned grid over the region.
    // Level 0's vertices sit on the height texture's texel centres (grid_origin + k texels).
    const glm::dvec2 side = kPatchQuads * grid.finest_quad * std::ldexp(1.0, top);
    const glm::dvec2 first = grid.grid_origin + glm::floor((grid.region_min - grid.grid_origin) / side) * side;
    for (double z = first.y; z < grid.region_max.y; z += side.y)
        for (double x = first.x; x < grid.region_max.x; x += side.x)
            if (!selector.select(top, {x, z}, side)) selector.add_whole(top, {x, z}, side);  // no coarser level
    TerrainSelection s = selector.finish();
    s.levels = top + 1;
    return s;
}

}  // namespace tidewater::render::detail
