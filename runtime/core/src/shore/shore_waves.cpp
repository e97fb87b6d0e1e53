#include "tidewater/detail/shore_waves.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>

#include "tidewater/constants.hpp"
#include "tidewater/detail/grid_taps.hpp"
#include "tidewater/dispersion.hpp"

namespace tidewater {

namespace {

/// Deep everywhere with nothing changed: the waves are exactly the open-ocean ones.
bool all_deep_and_unchanged(const ShoreWaveFields& f) {
    for (std::size_t k = 0; k < f.depth.size(); ++k) {
        if (!(f.depth[k] > 0.0f && f.steepness_scale[k] == 1.0f && f.breaking[k] == 0.0f)) return false;
        for (std::size_t w = 0; w < f.phase_residual.size(); ++w)
            if (f.phase_residual[w][k] != 0.0f || std::abs(f.amplitude_factor[w][k] - 1.0f) >= 1e-3f) return false;
    }
    return true;
}

}  // namespace

Result<std::shared_ptr<const ShoreWaves>> ShoreWaves::from_fields(ShoreWaveFields fields, std::size_t wave_count) {
    const int n = fields.resolution;
    if (n < 2 || n > 8192)
        return Error{ErrorCode::invalid_argument,
                     fmt::format("shore fields: resolution {} is out of range (2 to 8192)", n)};
    if (!(fields.texel > 0.0) || !std::isfinite(fields.texel) || !std::isfinite(fields.corner.x) ||
        !std::isfinite(fields.corner.y))
        return Error{ErrorCode::invalid_argument, "shore fields: the texel size and corner must be finite (texel > 0)"};
    const std::size_t count = static_cast<std::size_t>(n) * static_cast<std::size_t>(n);
    auto check = [&](const std::vector<float>& grid, const std::string& name) -> Status {
        if (grid.size() != count)
            return Error{ErrorCode::invalid_argument,
                         fmt::format("shore fields: {} has {} values, expected {}x{}", name, grid.size(), n, n)};
        for (float v : grid)
            if (!std::isfinite(v))
                return Error{ErrorCode::invalid_argument, fmt::format("shore fields: {} has a non-finite value", name)};
        return {};
    };
    const std::pair<const std::vector<std::vector<float>>*, const char*> per_wave[] = {
        {&fields.phase_residual, "phase_residual"},
        {&fields.amplitude_factor, "amplitude_factor"},
        {&fields.wavevector_x, "wavevector_x"},
        {&fields.wavevector_z, "wavevector_z"}};
    for (const auto& [grids, name] : per_wave) {
        if (grids->size() != wave_count)
            return Error{ErrorCode::invalid_argument,
                         fmt::format("shore fields: {} {} fields for {} waves", grids->size(), name, wave_count)};
        for (std::size_t w = 0; w < grids->size(); ++w)
            if (auto st = check((*grids)[w], fmt::format("wave {} {}", w, name)); !st) return st.error();
    }
    const std::pair<const std::vector<float>*, const char*> shared[] = {{&fields.depth, "depth"},
                                                                        {&fields.shore_distance, "shore_distance"},
                                                                        {&fields.breaking, "breaking"},
                                                                        {&fields.steepness_scale, "steepness_scale"}};
    for (const auto& [grid, name] : shared)
        if (auto st = check(*grid, name); !st) return st.error();
    auto out = std::make_shared<ShoreWaves>();
    out->trivial_ = all_deep_and_unchanged(fields);
    out->f_ = std::move(fields);
    out->pack_query_texels();
    return std::shared_ptr<const ShoreWaves>(std::move(out));
}

std::shared_ptr<const ShoreWaves> ShoreWaves::from_baked_fields(ShoreWaveFields fields) {
    auto out = std::make_shared<ShoreWaves>();
    out->trivial_ = all_deep_and_unchanged(fields);
    out->f_ = std::move(fields);
    out->pack_query_texels();
    return out;
}

void ShoreWaves::pack_query_texels() {
    const std::size_t nw = wave_count(), stride = query_texel_stride(nw), texels = f_.depth.size();
    query_texels_.assign(texels * stride, 0.0f);
    for (std::size_t k = 0; k < texels; ++k) {
        float* t = query_texels_.data() + k * stride;
        for (std::size_t w = 0; w < nw; ++w) {
            t[w] = f_.phase_residual[w][k];
            t[nw + w] = f_.amplitude_factor[w][k];
            t[2 * nw + w] = f_.wavevector_x[w][k];
            t[3 * nw + w] = f_.wavevector_z[w][k];
        }
        t[4 * nw] = f_.depth[k];
        t[4 * nw + 1] = f_.breaking[k];
        t[4 * nw + 2] = f_.steepness_scale[k];
        t[4 * nw + 3] = f_.shore_distance[k];
    }
}

LocalShore ShoreWaves::sample(glm::dvec2 p, std::span<LocalWave> waves) const {
    const detail::GridTaps lerp = detail::grid_taps(f_.corner, f_.texel, f_.resolution, p);
    LocalShore s;
    s.depth = lerp(f_.depth);
    s.shore_distance = lerp(f_.shore_distance);
    s.breaking = lerp(f_.breaking);
    s.steepness_scale = lerp(f_.steepness_scale);
    for (std::size_t w = 0; w < waves.size() && w < f_.phase_residual.size(); ++w) {
        waves[w].phase_residual = lerp(f_.phase_residual[w]);
        waves[w].amplitude_factor = s.depth > 0.0 ? lerp(f_.amplitude_factor[w]) : 0.0;
        waves[w].wavevector = {lerp(f_.wavevector_x[w]), lerp(f_.wavevector_z[w])};
    }
    return s;
}

}  // namespace tidewater
