#include "body_uploads.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "frame_constants.hpp"
#include "tidewater/detail/body_finder.hpp"
#include "tidewater/detail/water_bodies.hpp"
#include "tidewater/scene_bake.hpp"

namespace tidewater::render::detail {

namespace {

namespace td = tidewater::detail;

/// The patches of an nx x nz grid (texel m, patch m) that hold a texel where `wet`,
/// grown by one patch so that displaced water at their edges is drawn.
template <typename Wet>
std::vector<std::uint32_t> wet_patches(int nx, int nz, double texel, double patch, Wet wet) {
    const int per = std::max(1, static_cast<int>(std::round(patch / texel)));
    const int px = (nx + per - 1) / per, pz = (nz + per - 1) / per;
    std::vector<std::uint8_t> hit(static_cast<std::size_t>(px) * static_cast<std::size_t>(pz), 0);
    for (int j = 0; j < nz; ++j)
        for (int i = 0; i < nx; ++i)
            if (wet(i, j)) hit[static_cast<std::size_t>(j / per) * static_cast<std::size_t>(px) + static_cast<std::size_t>(i / per)] = 1;
    std::vector<std::uint32_t> out;
    for (int b = 0; b < pz; ++b)
        for (int a = 0; a < px; ++a) {
            bool near = false;
            for (int db = -1; db <= 1 && !near; ++db)
                for (int da = -1; da <= 1 && !near; ++da) {
                    const int x = a + da, z = b + db;
                    near = x >= 0 && z >= 0 && x < px && z < pz && hit[static_cast<std::size_t>(z) * static_cast<std::size_t>(px) + static_cast<std::size_t>(x)];
                }
            if (near) out.push_back(static_cast<std::uint32_t>(a) | (static_cast<std::uint32_t>(b) << 16));
        }
    return out;
}

Result<GpuBuffer> upload(const DeviceContext& ctx, const void* data, std::size_t bytes) {
    auto made = GpuBuffer::create(ctx, std::max<std::size_t>(bytes, 16), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    if (!made) return made.error();
    if (bytes > 0) std::memcpy(made->mapped(), data, bytes);
    return made;
}

glm::vec2 rel(glm::dvec2 p, glm::dvec2 origin) {
    return glm::vec2(static_cast<float>(p.x - origin.x), static_cast<float>(p.y - origin.y));
}

}  // namespace

Result<BodyBuffers> BodyBuffers::create(const DeviceContext& ctx, const Scene& scene) {
    BodyBuffers b;
    std::vector<float> texels, masks;
    std::vector<glm::vec4> channel;
    std::vector<std::uint32_t> patches;
    const td::WaterBodiesBake* bodies = scene.bake ? scene.bake->bodies.get() : nullptr;
    if (bodies) {
        for (const td::RiverBake& r : bodies->rivers) {
            BodyLayout l;
            l.corner = r.grid.corner;
            l.texel = r.grid.texel;
            l.nx = r.grid.nx;
            l.nz = r.grid.nz;
            l.first_texel = static_cast<std::uint32_t>(channel.size());
            l.first_mask = static_cast<std::uint32_t>(masks.size());
            l.patch = std::max(8.0, 4.0 * r.grid.texel);
            texels.insert(texels.end(), r.query_texels.begin(), r.query_texels.end());
            for (std::size_t t = 0; t < r.grid.size(); ++t) {
                channel.emplace_back(r.channel_s[t], r.channel_n[t], r.flow_x[t], r.flow_z[t]);
                masks.push_back(static_cast<float>(r.texel[t]));
                if (r.texel[t] != 0) l.surface_rise = std::max(l.surface_rise, static_cast<double>(r.surface_height[t]) - r.mouth_level);
            }
            const auto list = wet_patches(r.grid.nx, r.grid.nz, r.grid.texel, l.patch,
                                          [&](int i, int j) { return r.texel[r.grid.index(i, j)] != 0; });
            l.first_patch = static_cast<std::uint32_t>(patches.size());
            l.patch_count = static_cast<std::uint32_t>(list.size());
            l.patch = std::max(1, static_cast<int>(std::round(l.patch / r.grid.texel))) * r.grid.texel;
            patches.insert(patches.end(), list.begin(), list.end());
            b.rivers.push_back(l);
        }
        for (const td::LakeBake& lake : bodies->lakes) {
            const td::FieldGrid& g = lake.grid;
            BodyLayout l;
            l.corner = g.corner;
            l.texel = g.texel;
            l.nx = g.nx;
            l.nz = g.nz;
            l.first_mask = static_cast<std::uint32_t>(masks.size());
            l.first_texel = l.first_mask;
            l.patch = std::max(16.0, 2.0 * g.texel);
            // The extent grown by a texel: the terrain hides the water above it.
            auto inside = [&](int i, int j) {
                for (int dj = -1; dj <= 1; ++dj)
                    for (int di = -1; di <= 1; ++di) {
                        const int x = i + di, z = j + dj;
                        if (x >= 0 && z >= 0 && x < g.nx && z < g.nz && lake.inside[g.index(x, z)]) return true;
                    }
                return false;
            };
            for (int j = 0; j < g.nz; ++j)
                for (int i = 0; i < g.nx; ++i) masks.push_back(inside(i, j) ? 1.0f : 0.0f);
            const auto list = wet_patches(g.nx, g.nz, g.texel, l.patch, inside);
            l.first_patch = static_cast<std::uint32_t>(patches.size());
            l.patch_count = static_cast<std::uint32_t>(list.size());
            l.patch = std::max(1, static_cast<int>(std::round(l.patch / g.texel))) * g.texel;
            patches.insert(patches.end(), list.begin(), list.end());
            b.lakes.push_back(l);
        }
    }
    auto t = upload(ctx, texels.data(), texels.size() * sizeof(float));
    if (!t) return t.error();
    auto c = upload(ctx, channel.data(), channel.size() * sizeof(glm::vec4));
    if (!c) return c.error();
    auto m = upload(ctx, masks.data(), masks.size() * sizeof(float));
    if (!m) return m.error();
    auto p = upload(ctx, patches.data(), patches.size() * sizeof(std::uint32_t));
    if (!p) return p.error();
    b.river_texels = std::move(t).value();
    b.river_channel = std::move(c).value();
    b.masks = std::move(m).value();
    b.patches = std::move(p).value();
    return b;
}

BodyDraws plan_body_draws(const Scene& scene, const BodyBuffers& bodies, double time, glm::dvec2 origin,
                          const std::vector<gpu::GpuWave>& ocean_waves, const glm::vec4& ocean_patch, std::uint32_t ocean_patches,
                          bool ocean_shore) {
    BodyDraws out;
    const float first_river = (scene.has_ocean ? 1.0f : 0.0f) + static_cast<float>(scene.lakes.size());
    const glm::vec4 rivers(first_river, static_cast<float>(scene.rivers.size()), 0.0f, 0.0f);
    // Each still body's waves: where they start in the frame's wave buffer.
    std::vector<std::uint32_t> lake_first(scene.lakes.size(), 0);
    if (scene.has_ocean) out.waves = ocean_waves;
    const std::uint32_t ocean_count = static_cast<std::uint32_t>(out.waves.size());
    for (std::size_t l = 0; l < scene.lakes.size(); ++l) {
        lake_first[l] = static_cast<std::uint32_t>(out.waves.size());
        const auto w = waves_at_origin(scene.lakes[l].body, time, origin);
        out.waves.insert(out.waves.end(), w.begin(), w.end());
    }
    auto displacement = [](const WaterBody& b) {
        return std::max(b.waves().max_elevation(), b.waves().max_horizontal_displacement());
    };
    if (scene.has_ocean) {
        gpu::GpuBodyDraw d{};
        d.patch_grid = glm::vec4(ocean_patch.z, ocean_patch.w, ocean_patch.x, ocean_patch.y);
        d.body = glm::vec4(static_cast<float>(gpu::kBodyOcean), static_cast<float>(scene.water_level()), 0.0f, static_cast<float>(ocean_count));
        d.extra = glm::vec4(ocean_shore ? 1.0f : 0.0f, 0.0f, 0.0f, static_cast<float>(displacement(scene.ocean)));
        d.rivers = rivers;
        out.draws.push_back(d);
        out.patch_counts.push_back(ocean_patches);
    }
    for (std::size_t l = 0; l < scene.lakes.size() && l < bodies.lakes.size(); ++l) {
        const BodyLayout& b = bodies.lakes[l];
        const WaterBody& lake = scene.lakes[l].body;
        gpu::GpuBodyDraw d{};
        const glm::vec2 corner = rel(b.corner, origin);
        d.patch_grid = glm::vec4(corner, static_cast<float>(b.patch), 0.0f);
        d.body = glm::vec4(static_cast<float>(gpu::kBodyLake), static_cast<float>(lake.level()), static_cast<float>(lake_first[l]),
                           static_cast<float>(lake.waves().size()));
        d.grid = glm::vec4(corner, static_cast<float>(b.texel), static_cast<float>(b.first_mask));
        d.river = glm::vec4(static_cast<float>(b.nx), static_cast<float>(b.nz), 0.0f, 0.0f);
        d.extra = glm::vec4(0.0f, static_cast<float>(b.first_patch), 0.0f, static_cast<float>(displacement(lake)));
        d.rivers = rivers;
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
        const std::uint32_t still_count = into_lake ? static_cast<std::uint32_t>(still.waves().size()) : into_ocean ? ocean_count : 0u;
        d.body = glm::vec4(static_cast<float>(gpu::kBodyRiver), static_cast<float>(river.mouth_level), static_cast<float>(still_first),
                           static_cast<float>(still_count));
        d.grid = glm::vec4(corner, static_cast<float>(b.texel), static_cast<float>(b.first_texel));
        const std::uint32_t first_wave = static_cast<std::uint32_t>(out.river_waves.size());
        double river_displacement = 0.0;
        for (const auto& w : tidewater::detail::river_waves_at(preset.waves(), preset.local_time(time), river.mean_speed)) {
            out.river_waves.push_back({glm::vec4(static_cast<float>(w.k_s), static_cast<float>(w.k_n), static_cast<float>(w.amplitude),
                                                 static_cast<float>(w.steepness)),
                                       glm::vec4(static_cast<float>(w.omega), static_cast<float>(w.offset), 0.0f, 0.0f)});
            river_displacement += w.amplitude;
        }
        d.river = glm::vec4(static_cast<float>(b.nx), static_cast<float>(b.nz), static_cast<float>(first_wave),
                            static_cast<float>(out.river_waves.size() - first_wave));
        d.extra = glm::vec4(into_ocean && ocean_shore ? 1.0f : 0.0f, static_cast<float>(b.first_patch), static_cast<float>(b.surface_rise),
                            static_cast<float>(river_displacement + (still_count > 0 ? displacement(still) : 0.0)));
        d.rivers = rivers;
        d.flow = gpu_flow_detail(preset.profile().flow, preset.local_time(time), b.corner);
        out.draws.push_back(d);
        out.patch_counts.push_back(b.patch_count);
    }
    return out;
}

}  // namespace tidewater::render::detail
