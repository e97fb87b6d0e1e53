#include "tidewater/detail/shore_land_edit.hpp"

#include <algorithm>
#include <cmath>
#include <variant>
#include <vector>

#include "shore/shore_edit_region.hpp"

namespace tidewater::detail {

namespace {

/// The new depths of the texels in `range`, as the bake computes them (level - height,
/// in float), when they and every texel a step around them stay dry; else nullopt.
template <typename OldDepth>
std::optional<std::vector<float>> dry_depths(const TexelRange& range, int n, double texel, glm::dvec2 corner,
                                             const Terrain& after, double water_level, const OldDepth& old_depth) {
    for (int j = std::max(0, range.j0 - 1); j <= std::min(n - 1, range.j1 + 1); ++j)
        for (int i = std::max(0, range.i0 - 1); i <= std::min(n - 1, range.i1 + 1); ++i)
            if (!(old_depth(i, j) < 0.0f)) return std::nullopt;
    ShoreField grid;  // its texel centres, the bake's own expression
    grid.resolution = n;
    grid.texel = texel;
    grid.corner = corner;
    std::vector<float> depths(static_cast<std::size_t>(range.width()) * static_cast<std::size_t>(range.height()));
    for (int j = range.j0; j <= range.j1; ++j)
        for (int i = range.i0; i <= range.i1; ++i) {
            const float d = static_cast<float>(water_level - after.height_at(grid.texel_center(i, j)));
            if (!(d < 0.0f)) return std::nullopt;
            depths[static_cast<std::size_t>(j - range.j0) * static_cast<std::size_t>(range.width()) +
                   static_cast<std::size_t>(i - range.i0)] = d;
        }
    return depths;
}

}  // namespace

std::optional<LandEdit> rebake_land_edit(const HeightmapChange& change, const Terrain& before, const Terrain& after,
                                         double water_level, const std::shared_ptr<const ShoreField>& shoreline_ptr,
                                         const std::shared_ptr<const ShoreWaves>& model_ptr) {
    if (!change) return std::nullopt;
    if (!*change) return LandEdit{shoreline_ptr, model_ptr};  // the same pixels in another image
    const WorldRect& rect = **change;
    const ShoreField& shoreline = *shoreline_ptr;
    const ShoreWaves& model = *model_ptr;
    auto field = std::make_shared<ShoreField>(shoreline);

    const int nd = shoreline.resolution;
    const TexelRange d = texels_in(nd, shoreline.texel, shoreline.corner, rect);
    if (!d.empty()) {
        const auto depths = dry_depths(d, nd, shoreline.texel, shoreline.corner, after, water_level,
                                       [&](int i, int j) { return shoreline.depth[shoreline.index(i, j)]; });
        if (!depths) return std::nullopt;
        float* depth = field->depth.write().data();  // the distances stay shared with `shoreline`
        for (int j = d.j0; j <= d.j1; ++j)
            std::copy_n(depths->data() + static_cast<std::size_t>(j - d.j0) * static_cast<std::size_t>(d.width()),
                        d.width(), depth + field->index(d.i0, j));
    }

    // A run of waves on a coarser grid stores no depth: its texel centres under the edit
    // (and a step around) must be dry before and after too, so that its fields stay as they were.
    for (const ShoreWaveLayer& layer : model.layers()) {
        const ShoreGrid& g = layer.grid;
        if (g == model.grid()) continue;
        const TexelRange r = texels_in(g.resolution, g.texel, g.corner, rect);
        if (r.empty()) continue;
        auto before_depth = [&](int i, int j) {
            return static_cast<float>(water_level -
                                      before.height_at(g.corner + g.texel * glm::dvec2(i + 0.5, j + 0.5)));
        };
        if (!dry_depths(r, g.resolution, g.texel, g.corner, after, water_level, before_depth)) return std::nullopt;
    }

    const int nm = model.resolution();
    const TexelRange m = texels_in(nm, model.texel(), model.corner(), rect);
    if (m.empty()) return LandEdit{std::move(field), model_ptr};
    const auto depths = dry_depths(m, nm, model.texel(), model.corner(), after, water_level,
                                   [&](int i, int j) { return model.texel_values(i, j).depth(); });
    if (!depths) return std::nullopt;
    return LandEdit{std::move(field), model.with_depths(m.i0, m.j0, m.width(), m.height(), *depths)};
}

}  // namespace tidewater::detail
