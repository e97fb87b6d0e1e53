// Per-frame GPU constants (private): camera matrices relative to the render
// origin, wave phases reduced in double, the water patch grid.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <vector>

#include "host_device.h"
#include "tidewater/render/renderer.hpp"

namespace tidewater::render::detail {

struct TerrainPlacement {
    glm::dvec2 height_rect_corner{0.0};  ///< World xz of the height texture's outer corner, m.
    glm::dvec2 height_rect_size{1.0};    ///< m along x and z
    glm::dvec2 texel{1.0};               ///< m along x and z
    double lowest_ground = 0.0;          ///< m: texel value 0
    double highest_ground = 0.0;         ///< m: texel value 65535
    double fade = 0.0;                   ///< m beyond the outermost texel centres (0: the edge extends)
    double seabed = 0.0;                 ///< m: where the fade ends
};

struct FramePlan {
    gpu::GpuFrame frame{};
    std::vector<gpu::GpuWave> waves;
    glm::dvec2 origin{0.0};  ///< The render origin O, world xz, m.
    std::uint32_t patches_per_side = 0;
    /// The open sea beyond the patch grid, out to the horizon: squares of coarser patches
    /// round it, each with a hole where the one inside draws. x, y: corner relative to O
    /// (m); z: patch size (m); w: patches per side.
    std::vector<glm::vec4> ocean_rings;
    std::vector<std::uint32_t>
        water_draws;  ///< patch instances of each water draw (the ocean, its rings, lakes, rivers)
};

/// How many rings round the ocean's patch grid (their patches per side:
/// QualitySettings::far_field_ring_patches).
inline constexpr int kOceanRings = 8;  ///< each doubles the reach: 3 km x 2^8 = 768 km

/// Reversed-Z, infinite-far perspective for Vulkan clip space (y down, z in [0, 1]).
glm::mat4 reversed_z_projection(double fov_y_deg, double aspect, double near_plane);

Status validate_camera(const Camera& camera);

/// A body's waves as the shaders read them, with their phases at world xz `origin`
/// (the render origin) at clock time `time`, reduced in double; the water draws the
/// `waves_drawn` largest in amplitude one by one (the first in order among equals; 0: all
/// of them), the others as slope variance.
std::vector<gpu::GpuWave> waves_at_origin(const WaterBody& body, double time, glm::dvec2 origin, int waves_drawn);

/// A river preset's waves at clock time `time` in the river's channel frame, riding its
/// mean speed (m/s), as the shaders read them (river_water.glsl).
std::vector<gpu::GpuRiverWave> gpu_river_waves(const WaterBody& preset, double time, double mean_speed);

/// A body's ripples for one frame (GpuBodyDraw::ripple and ripple_offset), its drift at
/// `time` and the origin reduced modulo the noise period.
void gpu_ripples(const WaterBody& body, double time, glm::dvec2 origin, glm::vec4& ripple, glm::vec4& offset);

/// A body's flow-detail settings at clock time `local_time` for shaders whose positions
/// are relative to world xz `zero` (the render origin, or a river grid's corner).
gpu::GpuFlowDetail gpu_flow_detail(const FlowDetailSpec& spec, double local_time, glm::dvec2 zero);

/// How far the swash runs up a beach and how fast, for the terrain's wet sand: the run-up
/// exceeded by 2% of the waves on a dissipative beach, R2% = 0.043 sqrt(Hs L0) (Stockdon
/// et al. 2006; L0 the deep-water wavelength of the most energetic wave), and that
/// wave's angular frequency. No waves: no swash.
struct SwashBand {
    double runup = 0.0;  ///< m above the level
    double omega = 0.0;  ///< rad/s
};
SwashBand swash_band(const WaveSet& waves);

/// `water_density`: the water's shading footprints per pixel side (1, or sqrt(samples)
/// where the water shades every sample); `quality`: the water's vertex spacing on screen
/// (GpuFrame::water_density).
FramePlan plan_frame(const FrameInfo& info, VkExtent2D extent, const WaterBody& water, const TerrainPlacement& terrain,
                     double water_half_size, bool has_scene_copy, bool linear_output, double water_density,
                     const QualitySettings& quality);

}  // namespace tidewater::render::detail
