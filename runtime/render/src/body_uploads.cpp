#include "body_uploads.hpp"

#include <algorithm>
#include <cmath>

#include "frame_constants.hpp"
#include "tidewater/baked_scene.hpp"
#include "tidewater/detail/body_finder.hpp"
#include "tidewater/detail/water_bodies.hpp"
#include "tidewater/world_query.hpp"

namespace tidewater::render::detail {

namespace {

namespace td = tidewater::detail;

/// The patches of `per` x `per` texels of an nx x nz grid that hold a texel where `wet`
/// (nx * nz flags), grown by one patch so that displaced water at their edges is drawn.
std::vector<std::uint32_t> wet_patches(int nx, int nz, int per, const std::vector<std::uint8_t>& wet) {
    const int px = (nx + per - 1) / per, pz = (nz + per - 1) / per;
    auto at = [](int i, int j, int row) {
        return static_cast<std::size_t>(j) * static_cast<std::size_t>(row) + static_cast<std::size_t>(i);
    };
    std::vector<std::uint8_t> hit(at(0, pz, px), 0);
    for (int j = 0; j < nz; ++j)
        for (int i = 0; i < nx; ++i)
            if (wet[at(i, j, nx)]) hit[at(i / per, j / per, px)] = 1;
    std::vector<std::uint32_t> out;
    for (int b = 0; b < pz; ++b)
        for (int a = 0; a < px; ++a) {
            bool near = false;
            for (int z = std::max(b - 1, 0); z <= std::min(b + 1, pz - 1) && !near; ++z)
                for (int x = std::max(a - 1, 0); x <= std::min(a + 1, px - 1) && !near; ++x)
                    near = hit[at(x, z, px)] != 0;
            if (near) out.push_back(static_cast<std::uint32_t>(a) | (static_cast<std::uint32_t>(b) << 16));
        }
    return out;
}

/// A lake's extent grown by one texel: the terrain hides the water above it.
std::vector<std::uint8_t> grown_extent(const td::LakeBake& lake) {
    const td::FieldGrid& g = lake.grid;
    std::vector<std::uint8_t> out(g.size(), 0);
    for (int j = 0; j < g.nz; ++j)
        for (int i = 0; i < g.nx; ++i) {
            if (!lake.inside[g.index(i, j)]) continue;
            for (int z = std::max(j - 1, 0); z <= std::min(j + 1, g.nz - 1); ++z)
                for (int x = std::max(i - 1, 0); x <= std::min(i + 1, g.nx - 1); ++x) out[g.index(x, z)] = 1;
        }
    return out;
}

glm::vec2 rel(glm::dvec2 p, glm::dvec2 origin) {
    return glm::vec2(static_cast<float>(p.x - origin.x), static_cast<float>(p.y - origin.y));
}

/// A body's layout on `grid` with patches of about `patch` m, its texels from `first`.
BodyLayout layout_on(const td::FieldGrid& grid, double patch, std::size_t first, const std::vector<std::uint8_t>& wet,
                     std::vector<std::uint32_t>& patches) {
    BodyLayout l;
    l.corner = grid.corner;
    l.texel = grid.texel;
    l.nx = grid.nx;
    l.nz = grid.nz;
    l.first_texel = static_cast<std::uint32_t>(first);
    const int per = std::max(1, static_cast<int>(std::round(patch / grid.texel)));
    l.patch = per * grid.texel;
    const auto list = wet_patches(grid.nx, grid.nz, per, wet);
    l.first_patch = static_cast<std::uint32_t>(patches.size());
    l.patch_count = static_cast<std::uint32_t>(list.size());
    patches.insert(patches.end(), list.begin(), list.end());
    return l;
}

}  // namespace

void append_river_fields(const td::RiverBake& river, std::vector<float>& texels, std::vector<glm::vec4>& channel) {
    texels.insert(texels.end(), river.query_texels.begin(), river.query_texels.end());
    for (std::size_t t = 0; t < river.grid.size(); ++t)
        channel.emplace_back(river.channel_s[t], river.channel_n[t], river.flow_x[t], river.flow_z[t]);
}

Result<BodyBuffers> BodyBuffers::create(const Device& ctx, const Scene& scene) {
    BodyBuffers b;
    std::vector<float> texels, masks;
    std::vector<glm::vec4> channel;
    std::vector<std::uint32_t> patches;
    const td::WaterBodiesBake* bodies = scene.bake ? scene.bake->bodies.get() : nullptr;
    if (bodies) {
        for (const td::RiverBake& r : bodies->rivers) {
            std::vector<std::uint8_t> wet(r.texel.size());
            for (std::size_t t = 0; t < wet.size(); ++t) wet[t] = r.texel[t] != 0;
            BodyLayout l = layout_on(r.grid, std::max(8.0, 4.0 * r.grid.texel), masks.size(), wet, patches);
            append_river_fields(r, texels, channel);
            for (std::size_t t = 0; t < r.grid.size(); ++t) {
                masks.push_back(static_cast<float>(r.texel[t]));
                if (wet[t])
                    l.surface_rise = std::max(l.surface_rise, static_cast<double>(r.surface_height[t]) - r.mouth_level);
            }
            b.rivers.push_back(l);
        }
        for (const td::LakeBake& lake : bodies->lakes) {
            const std::vector<std::uint8_t> extent = grown_extent(lake);
            b.lakes.push_back(
                layout_on(lake.grid, std::max(16.0, 2.0 * lake.grid.texel), masks.size(), extent, patches));
            for (std::uint8_t v : extent) masks.push_back(static_cast<float>(v));
        }
    }
    auto t = GpuBuffer::storage_with(ctx, texels.data(), texels.size() * sizeof(float));
    if (!t) return t.error();
    auto c = GpuBuffer::storage_with(ctx, channel.data(), channel.size() * sizeof(glm::vec4));
    if (!c) return c.error();
    auto m = GpuBuffer::storage_with(ctx, masks.data(), masks.size() * sizeof(float));
    if (!m) return m.error();
    auto p = GpuBuffer::storage_with(ctx, patches.data(), patches.size() * sizeof(std::uint32_t));
    if (!p) return p.error();
    b.river_texels = std::move(t).value();
    b.river_channel = std::move(c).value();
    b.masks = std::move(m).value();
    b.patches = std::move(p).value();
    return b;
}

BodyDraws plan_body_draws(const Scene& scene, const BodyBuffers& bodies, double time, const FramePlan& plan,
                          const ShoreBuffers& shores, int waves_drawn) {
    BodyDraws out;
    const glm::dvec2 origin = plan.origin;
    // A draw's still water reads shore model `slot` of `shores` (0: the ocean's, 1 + l: lake l's).
    auto use_shore = [&](gpu::GpuBodyDraw& d, std::size_t slot) {
        const ShorePlacement p = shores.placement(slot);
        if (!p.model) return;
        d.shore = glm::vec4(rel(p.corner, origin), static_cast<float>(p.texel), static_cast<float>(p.resolution));
        d.shore_base = glm::uvec4(p.layers, 0u, 0u, 0u);
    };
    auto use_optics = [&](gpu::GpuBodyDraw& d, BodyKind kind, std::size_t index) {
        const WaterOptics optics = optics_of(scene, BodyRef{kind, static_cast<int>(index)});
        d.optics_extinction = glm::vec4(glm::vec3(optics.extinction), 0.0f);
        d.optics_color = glm::vec4(glm::vec3(optics.color), 0.0f);
    };
    const std::size_t ocean_draws = scene.has_ocean ? 1 + plan.ocean_rings.size() : 0;
    const float first_river = static_cast<float>(ocean_draws + scene.lakes.size());
    const glm::vec4 rivers(first_river, static_cast<float>(scene.rivers.size()), static_cast<float>(ocean_draws), 0.0f);
    // Each still body's waves: where they start in the frame's wave buffer.
    std::vector<std::uint32_t> lake_first(scene.lakes.size(), 0);
    if (scene.has_ocean) out.waves = plan.waves;
    const std::uint32_t ocean_count = static_cast<std::uint32_t>(out.waves.size());
    for (std::size_t l = 0; l < scene.lakes.size(); ++l) {
        lake_first[l] = static_cast<std::uint32_t>(out.waves.size());
        const auto w = waves_at_origin(scene.lakes[l].body, time, origin, waves_drawn);
        out.waves.insert(out.waves.end(), w.begin(), w.end());
    }
    auto displacement = [](const WaterBody& b) {
        return std::max(b.waves().max_elevation(), b.waves().max_horizontal_displacement());
    };
    if (scene.has_ocean) {
        gpu::GpuBodyDraw d{};
        const glm::vec4& grid = plan.frame.water_patch;  // size, per side, corner
        d.patch_grid = glm::vec4(grid.z, grid.w, grid.x, grid.y);
        d.body = glm::vec4(static_cast<float>(gpu::kBodyOcean), static_cast<float>(scene.water_level()), 0.0f,
                           static_cast<float>(ocean_count));
        d.extra = glm::vec4(static_cast<float>(scene.ocean.whitecap_jacobian()), 0.0f, 0.0f,
                            static_cast<float>(displacement(scene.ocean)));
        d.lod.x = static_cast<float>(scene.ocean.waves().mean_square_slope());
        d.rivers = rivers;
        use_shore(d, 0);
        use_optics(d, BodyKind::ocean, 0);
        gpu_ripples(scene.ocean, time, origin, d.ripple, d.ripple_offset);
        out.draws.push_back(d);
        out.patch_counts.push_back(plan.patches_per_side * plan.patches_per_side);
        // The rings beyond, each skipping the square the one inside covers (grid: that
        // square's corner and side).
        glm::vec4 inner = d.patch_grid;
        for (const glm::vec4& ring : plan.ocean_rings) {
            gpu::GpuBodyDraw r = d;
            r.patch_grid = ring;
            r.grid = glm::vec4(inner.x, inner.y, inner.z * inner.w, 0.0f);
            out.draws.push_back(r);
            out.patch_counts.push_back(static_cast<std::uint32_t>(ring.w * ring.w));
            inner = ring;
        }
    }
    for (std::size_t l = 0; l < scene.lakes.size() && l < bodies.lakes.size(); ++l) {
        const BodyLayout& b = bodies.lakes[l];
        const WaterBody& lake = scene.lakes[l].body;
        gpu::GpuBodyDraw d{};
        const glm::vec2 corner = rel(b.corner, origin);
        d.patch_grid = glm::vec4(corner, static_cast<float>(b.patch), 0.0f);
        d.body = glm::vec4(static_cast<float>(gpu::kBodyLake), static_cast<float>(lake.level()),
                           static_cast<float>(lake_first[l]), static_cast<float>(lake.waves().size()));
        d.grid = glm::vec4(corner, static_cast<float>(b.texel), static_cast<float>(b.first_texel));
        d.river = glm::vec4(static_cast<float>(b.nx), static_cast<float>(b.nz), 0.0f, 0.0f);
        d.extra = glm::vec4(static_cast<float>(lake.whitecap_jacobian()), static_cast<float>(b.first_patch), 0.0f,
                            static_cast<float>(displacement(lake)));
        d.lod.x = static_cast<float>(lake.waves().mean_square_slope());
        d.rivers = rivers;
        use_shore(d, 1 + l);
        use_optics(d, BodyKind::lake, l);
        gpu_ripples(lake, time, origin, d.ripple, d.ripple_offset);
        out.draws.push_back(d);
        out.patch_counts.push_back(b.patch_count);
    }
    const auto* baked = scene.bake ? scene.bake->bodies.get() : nullptr;
    for (std::size_t r = 0; baked && r < scene.rivers.size() && r < bodies.rivers.size(); ++r) {
        const BodyLayout& b = bodies.rivers[r];
        const tidewater::detail::RiverBake& river = baked->rivers[r];
        const WaterBody& preset = scene.rivers[r].body;
        const bool into_lake = river.end == tidewater::detail::RiverEnd::lake;
        const bool into_ocean = river.end == tidewater::detail::RiverEnd::ocean && scene.has_ocean;
        const WaterBody& still = tidewater::detail::still_body(scene, river);
        gpu::GpuBodyDraw d{};
        const glm::vec2 corner = rel(b.corner, origin);
        d.patch_grid = glm::vec4(corner, static_cast<float>(b.patch), 0.0f);
        const std::uint32_t still_first = into_lake ? lake_first[static_cast<std::size_t>(river.receiver)] : 0u;
        const std::uint32_t still_count = into_lake    ? static_cast<std::uint32_t>(still.waves().size())
                                          : into_ocean ? ocean_count
                                                       : 0u;
        d.body = glm::vec4(static_cast<float>(gpu::kBodyRiver), static_cast<float>(river.mouth_level),
                           static_cast<float>(still_first), static_cast<float>(still_count));
        d.grid = glm::vec4(corner, static_cast<float>(b.texel), static_cast<float>(b.first_texel));
        const std::uint32_t first_wave = static_cast<std::uint32_t>(out.river_waves.size());
        const auto river_waves = gpu_river_waves(preset, time, river.mean_speed);
        out.river_waves.insert(out.river_waves.end(), river_waves.begin(), river_waves.end());
        d.river = glm::vec4(static_cast<float>(b.nx), static_cast<float>(b.nz), static_cast<float>(first_wave),
                            static_cast<float>(out.river_waves.size() - first_wave));
        d.extra = glm::vec4(static_cast<float>(preset.whitecap_jacobian()), static_cast<float>(b.first_patch),
                            static_cast<float>(b.surface_rise),
                            static_cast<float>(displacement(preset) + (still_count > 0 ? displacement(still) : 0.0)));
        d.lod.x = static_cast<float>(preset.waves().mean_square_slope() +
                                     (still_count > 0 ? still.waves().mean_square_slope() : 0.0));
        d.rivers = rivers;
        d.rivers.w = static_cast<float>(tidewater::detail::river_bank_ramp_depth(preset.waves()));
        if (into_ocean) use_shore(d, 0);
        if (into_lake) use_shore(d, 1 + static_cast<std::size_t>(river.receiver));
        d.flow = gpu_flow_detail(preset.profile().flow, preset.local_time(time), b.corner);
        use_optics(d, BodyKind::river, r);
        out.draws.push_back(d);
        out.patch_counts.push_back(b.patch_count);
    }
    return out;
}

}  // namespace tidewater::render::detail
