#include "frame_constants.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <numeric>

#include "drawn_table.hpp"
#include "phase_cells.hpp"
#include "tidewater/constants.hpp"
#include "tidewater/detail/water_bodies.hpp"
#include "tidewater/gerstner.hpp"

namespace tidewater::render::detail {

namespace {

double positive_mod(double v, double period) {
    const double m = std::fmod(v, period);
    return m < 0.0 ? m + period : m;
}

}  // namespace

glm::mat4 reversed_z_projection(double fov_y_deg, double aspect, double near_plane) {
    const double f = 1.0 / std::tan(0.5 * fov_y_deg * kPi / 180.0);
    glm::mat4 p(0.0f);
    p[0][0] = static_cast<float>(f / aspect);
    p[1][1] = static_cast<float>(-f);  // Vulkan clip y points down
    p[2][2] = 0.0f;
    p[2][3] = -1.0f;                           // w = -z_view
    p[3][2] = static_cast<float>(near_plane);  // depth = near / -z_view: 1 at the near plane, 0 at infinity
    return p;
}

Status validate_camera(const Camera& c) {
    auto finite3 = [](const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); };
    if (!finite3(c.position) || !finite3(c.target))
        return Error{ErrorCode::invalid_argument, "camera: position and target must be finite"};
    if (glm::length(c.target - c.position) < 1e-6)
        return Error{ErrorCode::invalid_argument, "camera: target equals position"};
    const glm::dvec3 dir = glm::normalize(c.target - c.position);
    if (std::abs(dir.y) > 0.99999)
        return Error{ErrorCode::invalid_argument, "camera: looking straight up or down is not supported (y is up)"};
    if (!(c.fov_y_deg > 1.0 && c.fov_y_deg < 179.0))
        return Error{ErrorCode::invalid_argument,
                     fmt::format("camera: fov_y {} is out of range (1 to 179 degrees)", c.fov_y_deg)};
    if (!(c.near_plane > 0.0 && c.near_plane < 1e4))
        return Error{ErrorCode::invalid_argument,
                     fmt::format("camera: near plane {} is out of range (0 to 1e4 m)", c.near_plane)};
    return {};
}

SwashBand swash_band(const WaveSet& waves) {
    SwashBand band;
    const Wave* peak = nullptr;
    for (const Wave& w : waves.waves())
        if (!peak || w.amplitude > peak->amplitude) peak = &w;
    if (!peak || !(peak->k > 0.0)) return band;
    // Stockdon et al. (2006), dissipative beaches: R2% = 0.043 sqrt(H0 L0).
    band.runup = 0.043 * std::sqrt(waves.significant_wave_height() * 2.0 * kPi / peak->k);
    band.omega = peak->omega;
    return band;
}

FramePlan plan_frame(const FrameInfo& info, VkExtent2D extent, const WaterBody& water, const TerrainPlacement& terrain,
                     double water_half_size, bool has_scene_copy, bool linear_output, double water_density,
                     const QualitySettings& quality) {
    FramePlan plan;
    const Camera& cam = info.camera;
    // The render origin: the camera snapped to the phase-cell grid, in double.
    plan.origin = {std::floor(cam.position.x / kPhaseCellSize) * kPhaseCellSize,
                   std::floor(cam.position.z / kPhaseCellSize) * kPhaseCellSize};
    const glm::dvec3 origin3{plan.origin.x, 0.0, plan.origin.y};
    const glm::vec3 eye = glm::vec3(cam.position - origin3);
    const glm::vec3 at = glm::vec3(cam.target - origin3);
    const glm::mat4 view = glm::lookAt(eye, at, glm::vec3(0.0f, 1.0f, 0.0f));
    const double aspect = static_cast<double>(extent.width) / static_cast<double>(extent.height);
    const glm::mat4 view_proj = reversed_z_projection(cam.fov_y_deg, aspect, cam.near_plane) * view;

    gpu::GpuFrame& f = plan.frame;
    f.view_proj = view_proj;
    f.inv_view_proj = glm::inverse(view_proj);
    const double local_time = water.local_time(info.time);
    f.camera = glm::vec4(eye, static_cast<float>(positive_mod(local_time, 3600.0)));
    const glm::dvec3 sun = glm::normalize(info.sun_direction);
    f.sun = glm::vec4(glm::vec3(sun), 1.0f);
    // Projection scale: pixels per metre across the view at 1 m from the camera.
    const double tan_half = std::tan(0.5 * cam.fov_y_deg * kPi / 180.0);
    const double projection_scale = static_cast<double>(extent.height) / (2.0 * tan_half);
    f.params =
        glm::vec4(static_cast<float>(water.level()), static_cast<float>(water.waves().size()),
                  static_cast<float>(projection_scale), static_cast<float>(static_cast<std::uint32_t>(info.view)));
    f.terrain_rect =
        glm::vec4(static_cast<float>(terrain.height_rect_corner.x - plan.origin.x),
                  static_cast<float>(terrain.height_rect_corner.y - plan.origin.y),
                  static_cast<float>(terrain.height_rect_size.x), static_cast<float>(terrain.height_rect_size.y));
    f.terrain_heights = glm::vec4(static_cast<float>(terrain.highest_ground), static_cast<float>(terrain.lowest_ground),
                                  static_cast<float>(terrain.highest_ground - terrain.lowest_ground),
                                  static_cast<float>(terrain.seabed));
    f.terrain_lod = glm::vec4(static_cast<float>(terrain.fade), static_cast<float>(terrain.texel.x),
                              static_cast<float>(terrain.texel.y), static_cast<float>(terrain.lowest_ground));
    f.viewport = glm::vec4(static_cast<float>(extent.width), static_cast<float>(extent.height),
                           1.0f / static_cast<float>(extent.width), 1.0f / static_cast<float>(extent.height));

    const SwashBand swash = swash_band(water.waves());
    f.options = glm::vec4(has_scene_copy ? 1.0f : 0.0f, linear_output ? 1.0f : 0.0f, static_cast<float>(swash.runup),
                          static_cast<float>(swash.omega));
    f.origin_mod = glm::vec4(static_cast<float>(positive_mod(plan.origin.x, 2048.0)),
                             static_cast<float>(positive_mod(plan.origin.y, 2048.0)), 0.0f, 0.0f);
    f.water_density = glm::vec4(static_cast<float>(water_density), static_cast<float>(quality.water_pixels_per_vertex),
                                0.0f, static_cast<float>(quality.water_max_foreshortening));
    f.sky = gpu_sky(info.sun_direction, info.sky_turbidity);

    // The water patch grid: world-aligned, following the camera in whole patches.
    const double patch = std::max(32.0, 2.0 * water_half_size / 160.0);
    plan.patches_per_side = static_cast<std::uint32_t>(std::ceil(2.0 * water_half_size / patch));
    const glm::dvec2 corner{std::floor((cam.position.x - water_half_size) / patch) * patch,
                            std::floor((cam.position.z - water_half_size) / patch) * patch};
    f.water_patch =
        glm::vec4(static_cast<float>(patch), static_cast<float>(plan.patches_per_side),
                  static_cast<float>(corner.x - plan.origin.x), static_cast<float>(corner.y - plan.origin.y));

    // Rings of coarser patches out to the horizon, each snapped to its own patch size.
    // From 400 m up the last ring's edge lies 0.03 degrees under the horizon.
    double half = 0.5 * patch * plan.patches_per_side;
    for (int k = 0; k < kOceanRings; ++k) {
        half *= 2.0;
        const double size = 2.0 * half / quality.far_field_ring_patches;
        const glm::dvec2 ring{std::floor((cam.position.x - half) / size) * size,
                              std::floor((cam.position.z - half) / size) * size};
        plan.ocean_rings.push_back(glm::vec4(static_cast<float>(ring.x - plan.origin.x),
                                             static_cast<float>(ring.y - plan.origin.y), static_cast<float>(size),
                                             static_cast<float>(quality.far_field_ring_patches)));
    }

    plan.waves = waves_at_origin(water, info.time, plan.origin, quality.waves_drawn);
    return plan;
}

std::vector<gpu::GpuWave> waves_at_origin(const WaterBody& body, double time, glm::dvec2 origin, int waves_drawn) {
    std::vector<gpu::GpuWave> out = gpu_waves(body.waves());
    std::vector<double> offsets(body.waves().size());
    phase_offsets_at(body.waves(), body.local_time(time), offsets);
    const auto ws = body.waves().waves();
    for (std::size_t i = 0; i < ws.size(); ++i) {
        const double phase = ws[i].k * (ws[i].dir_x * origin.x + ws[i].dir_z * origin.y) + offsets[i];
        out[i].steep_omega.z = static_cast<float>(wrap_angle(phase));
    }
    const std::size_t drawn = static_cast<std::size_t>(std::max(waves_drawn, 0));
    if (drawn > 0 && drawn < ws.size()) {
        // The waves stay in their order (the shore model's runs follow it); a flag says
        // which are drawn one by one.
        std::vector<std::size_t> by_amplitude(ws.size());
        std::iota(by_amplitude.begin(), by_amplitude.end(), std::size_t{0});
        std::stable_sort(by_amplitude.begin(), by_amplitude.end(),
                         [&](std::size_t a, std::size_t b) { return ws[a].amplitude > ws[b].amplitude; });
        for (std::size_t r = drawn; r < ws.size(); ++r) out[by_amplitude[r]].steep_omega.w = 0.0f;
    }
    return out;
}

std::vector<gpu::GpuRiverWave> gpu_river_waves(const WaterBody& preset, double time, double mean_speed) {
    std::vector<gpu::GpuRiverWave> out;
    for (const auto& w : tidewater::detail::river_waves_at(preset.waves(), preset.local_time(time), mean_speed))
        out.push_back({glm::vec4(static_cast<float>(w.k_s), static_cast<float>(w.k_n), static_cast<float>(w.amplitude),
                                 static_cast<float>(w.steepness)),
                       glm::vec4(static_cast<float>(w.omega), static_cast<float>(w.offset), 0.0f, 0.0f)});
    return out;
}

void gpu_ripples(const WaterBody& body, double time, glm::dvec2 origin, glm::vec4& ripple, glm::vec4& offset) {
    const RippleSpec& rs = body.ripples().spec();
    const double drift = std::fmod(body.local_time(time) * rs.speed / rs.wavelength, 256.0);
    const double rad = rs.direction_deg * kPi / 180.0;
    ripple =
        glm::vec4(static_cast<float>(body.ripples().enabled() ? rs.amplitude : 0.0),
                  static_cast<float>(1.0 / rs.wavelength), static_cast<float>(rs.octaves), static_cast<float>(rs.seed));
    const double period = 256.0 * rs.wavelength;
    offset = glm::vec4(static_cast<float>(drift * std::cos(rad)), static_cast<float>(drift * std::sin(rad)),
                       static_cast<float>(positive_mod(origin.x, period)),
                       static_cast<float>(positive_mod(origin.y, period)));
}

gpu::GpuFlowDetail gpu_flow_detail(const FlowDetailSpec& spec, double local_time, glm::dvec2 zero) {
    const FlowDetailClock clock = flow_detail_clock(spec, local_time);
    // Both noises repeat over the coarser one's period: reduce the zero modulo it.
    const double period =
        static_cast<double>(gpu::kFlowNoisePeriod) / (spec.tiling * static_cast<double>(gpu::kFlowOffsetScale));
    gpu::GpuFlowDetail d{};
    d.params = glm::vec4(static_cast<float>(spec.tiling), static_cast<float>(spec.speed),
                         static_cast<float>(spec.strength), static_cast<float>(spec.offset));
    d.clock = glm::vec4(static_cast<float>(spec.period), static_cast<float>(clock.cycle_fraction),
                        static_cast<float>(spec.jump.x), static_cast<float>(spec.jump.y));
    d.jump = glm::vec4(static_cast<float>(clock.jump_base.x), static_cast<float>(clock.jump_base.y),
                       static_cast<float>(spec.seed), 0.0f);
    d.origin = glm::vec4(static_cast<float>(positive_mod(zero.x, period)),
                         static_cast<float>(positive_mod(zero.y, period)), 0.0f, 0.0f);
    return d;
}

}  // namespace tidewater::render::detail

namespace tidewater::render {

std::array<glm::dvec3, 4> near_plane_corners(const Camera& camera, double aspect) {
    const glm::dvec3 forward = glm::normalize(camera.target - camera.position);
    glm::dvec3 right = glm::cross(forward, glm::dvec3(0.0, 1.0, 0.0));
    // Straight up or down: the view's right is +x, as for a camera turned from there.
    right = glm::length(right) > 1e-12 ? glm::normalize(right) : glm::dvec3(1.0, 0.0, 0.0);
    const glm::dvec3 up = glm::cross(right, forward);
    const double half_h = camera.near_plane * std::tan(0.5 * camera.fov_y_deg * kPi / 180.0);
    const glm::dvec3 centre = camera.position + forward * camera.near_plane;
    const glm::dvec3 across = right * (half_h * aspect), over = up * half_h;
    return {centre - across - over, centre + across - over, centre + across + over, centre - across + over};
}

}  // namespace tidewater::render
