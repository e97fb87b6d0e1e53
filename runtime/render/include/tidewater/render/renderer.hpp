// Tidewater's renderer: terrain and Gerstner water drawn into a host's
// Vulkan frame with dynamic rendering.
//
// Embedding (modelled on Dear ImGui's Vulkan backend):
// - The host owns the instance, device, queue, swapchain and frame loop, and
//   lends them through RendererInitInfo, which the renderer copies.
// - The renderer only records into the host's command buffers. It never
//   presents, never owns a swapchain, and submits to the queue or waits for the
//   device only inside create / set_scene / set_water (explicit calls that wait
//   for completion). record_frame, record_views, record_in_pass, add_view,
//   remove_view and resize never submit or wait.
// - Depth is reversed-Z: clear to 0, nearer is larger (compare GREATER_OR_EQUAL).
//   Host geometry that shares a depth buffer with Tidewater must use the same.
// - record_frame() renders a whole frame into the host's images (it begins and
//   ends rendering itself, copying the opaque scene for refraction between the
//   terrain and water passes). record_in_pass() draws into a pass the host
//   has begun, without refraction of the host's geometry, after record_sky()
//   outside that pass.
// - Several views a frame (split screen, editor viewports, a reflection probe):
//   add_view() gives a view its own refraction copies, frame constants, draws and
//   timings over the scene's uploads, which every view shares; record_views()
//   records any number of them into one command buffer. The main view is there from
//   create() on; record_frame() draws it.
//
// Lifetime: destroy the Renderer before the device it was given; a
// Renderer is move-less and lives behind a unique_ptr.
// Threading: one thread at a time; record calls for frame i may overlap the
// GPU executing frame i-1 up to frames_in_flight frames (the host fences them).
// Units: metres, seconds, radians (camera field of view in degrees).
#pragma once

#include <vulkan/vulkan.h>

#include <array>
#include <cstdint>
#include <functional>
#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "tidewater/render/device_context.hpp"
#include "tidewater/render/quality.hpp"
#include "tidewater/scene.hpp"
#include "tidewater/world_query.hpp"

namespace tidewater {
struct HullMesh;
class SceneFloaters;
}  // namespace tidewater

namespace tidewater::render {

enum class DebugView : std::uint32_t {
    shaded,
    height,
    normals,
    jacobian,
    depth,
    lod,
    wireframe,
    shore,
    breaking,
    flow,
    wake,
    foam
};

/// "shaded", "height", "normals", "jacobian", "depth", "lod", "wireframe", "shore" (signed shore
/// distance), "breaking" (where waves break), "flow" (a river's current speed), "wake" (the
/// wakes' share of the height: red up, blue down), "foam" (the foam amount a pixel covers
/// on average, before its lace: 0 black to 1 white, linear).
std::string_view to_string(DebugView view);
std::optional<DebugView> parse_debug_view(std::string_view name);
std::span<const DebugView> all_debug_views();

struct Camera {
    glm::dvec3 position{0.0, 25.0, 120.0};  ///< m, world
    glm::dvec3 target{0.0, 0.0, 0.0};       ///< m, world
    double fov_y_deg = 55.0;                ///< vertical field of view, in (1, 179)
    double near_plane = 0.3;                ///< m, > 0; the far plane is at infinity (reversed-Z)
};

/// The four corners of `camera`'s near plane (world, m) for a view `aspect` wide over high:
/// bottom left, bottom right, top right, top left. With query_submersion a host learns
/// whether the near plane lies above the water, under it, or across the water line, as
/// RendererStats::camera tells what the renderer drew the frame from.
std::array<glm::dvec3, 4> near_plane_corners(const Camera& camera, double aspect);

struct RendererInitInfo {
    DeviceContext device;                              ///< Copied. Needs tessellationShader enabled.
    VkFormat color_format = VK_FORMAT_R8G8B8A8_UNORM;  ///< The host's colour attachment format.
    VkFormat depth_format = VK_FORMAT_D32_SFLOAT;      ///< The host's depth attachment format.
    /// The targets' sample count: 1, or 2, 4 or 8 for multisampled targets (antialiased
    /// wave edges), with a depth format without stencil.
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
    /// Multisampled targets only: shade the water at every sample, with its waves drawn
    /// and filtered for a sample's footprint (sqrt(samples) per pixel side), so that a
    /// grazing far field converges to the supersampled picture instead of its filtered
    /// estimate. Costs about `samples` times the water's shading, and more vertices
    /// (docs/PERFORMANCE.md). Needs sampleRateShading enabled. The same as
    /// quality_overrides.water_per_sample = true (`ultra` shades per sample where it can).
    bool shade_water_per_sample = false;
    /// How much the renderer draws (quality.hpp): a tier, and settings that replace its own
    /// (Renderer::quality() gives what was used). An override out of range fails create().
    Quality quality = Quality::high;
    QualityOverrides quality_overrides;
    std::uint32_t frames_in_flight = 2;  ///< 1 to 4.
    /// Device memory the scene's data may take, bytes (at least 16 MiB). The terrain's
    /// height texture takes at most half, the shore models' fields what it leaves: over
    /// their share the height texture is drawn from every k-th pixel, and the shore fields
    /// from every k-th texel with their full-resolution tiles nearest the camera streamed
    /// over them as frames are recorded (a bounded number of bytes per frame), never
    /// refused for memory (RendererStats::terrain_bytes, shore_bytes, shore_stride and
    /// shore_streamed_tiles say what they took).
    std::uint64_t gpu_memory_budget = std::uint64_t{1} << 30;
    /// Over the budget, bytes of full-resolution shore tiles a frame may bring in, at most
    /// (at least one tile); 0: none, the coarse level alone is drawn.
    std::uint64_t shore_stream_bytes_per_frame = std::uint64_t{8} << 20;
    bool wireframe = true;                        ///< Build the wireframe view (needs fillModeNonSolid).
    std::function<void(const std::string&)> log;  ///< Copied; default: silent.
};

/// The host's images for one frame (not owned). On entry and on return the colour
/// image is in COLOR_ATTACHMENT_OPTIMAL and the depth image in
/// DEPTH_ATTACHMENT_OPTIMAL; both need TRANSFER_SRC usage for the refraction copy.
struct FrameTargets {
    VkImage color_image = VK_NULL_HANDLE;
    VkImageView color_view = VK_NULL_HANDLE;
    VkImage depth_image = VK_NULL_HANDLE;
    VkImageView depth_view = VK_NULL_HANDLE;
    /// The view's size (px): the size its renderer view was given (resize, add_view).
    VkExtent2D extent{};
    bool clear = true;  ///< Clear colour and depth first (false: draw over the host's content).
    /// Multisampled targets: a single-sample colour image (COLOR_ATTACHMENT_OPTIMAL, the
    /// colour format) the water pass resolves the frame into; null: the host resolves.
    VkImage resolve_image = VK_NULL_HANDLE;
    VkImageView resolve_view = VK_NULL_HANDLE;
    /// Where the view's rectangle starts in the images (px): views side by side in one
    /// image (split screen) each draw their rectangle, offset to offset + extent, which
    /// must lie inside the images. Single-sample targets only; (0, 0) for multisampled ones.
    /// Last, so that a host's positional initialisers keep their meaning.
    VkOffset2D offset{};
};

/// A floating body to draw (a boat, a barrel: SceneFloaters gives the scene's): its
/// closed hull in its body frame, where it is, and its paint. Drawn opaque before the
/// water, so the water refracts and fogs what is under it. Read during record_frame only.
struct FloatDraw {
    const HullMesh* hull = nullptr;              ///< body frame, m; at most 32768 triangles over all floats
    glm::dvec3 position{0.0};                    ///< the body frame's origin, world, m
    glm::dquat orientation{1.0, 0.0, 0.0, 0.0};  ///< body to world
    glm::vec3 color{0.8f};                       ///< paint, linear RGB 0..1
    /// Body frame: where the hull keeps the water out (tidewater/clip_volume.hpp), an open
    /// hull's dry hold included; absent: nowhere. float_draws gives each scene body's.
    std::optional<ClipVolume> clip = std::nullopt;
};

/// The draws of `floaters`' bodies at their poses now (after advance_to). The hulls stay
/// theirs: the draws are valid while `floaters` lives.
std::vector<FloatDraw> float_draws(const SceneFloaters& floaters);

struct FrameInfo {
    Camera camera;
    double time = 0.0;              ///< Clock time, s; each water body adds its own offset.
    std::uint64_t frame_index = 0;  ///< Host frame counter; selects the in-flight slot.
    DebugView view = DebugView::shaded;
    glm::dvec3 sun_direction{0.35, 0.55, -0.75};  ///< Toward the sun; normalised by the renderer.
    /// The air's turbidity for the Preetham sky, in [1.7, 10]: 2 very clear, 3 clear, 6 hazy.
    double sky_turbidity = 2.5;
    /// The host's wakes (BoatWakeEmitter, splashes), drawn with the scene's boats' on the
    /// ocean and lakes; null: only the scene's. Read during record_frame only.
    const Wakes* wakes = nullptr;
    /// Boats, barrels and other floating bodies to draw; empty: none.
    std::span<const FloatDraw> floats;
    /// Where the water is removed this frame besides the scene's own and the floats'
    /// (world frame): no water surface and no light through water inside them. Pass the
    /// same to the queries (QueryOptions::clip_volumes) to get the same answer. The scene's
    /// and these together at most gpu::kMaxClipVolumes (32); the floats' take the slots
    /// left, nearest the camera first (RendererStats::clip_volumes_left_out counts the
    /// rest). Read during record_frame only.
    std::span<const ClipVolume> clip_volumes = {};
    /// The host's own geometry, drawn into the targets before record_frame or record_views
    /// (FrameTargets::clear false), lit as the terrain is where it lies under a body's
    /// surface: the sun's and the sky's light it loses to the water over it and the
    /// caustics of that water's waves (its normal taken from the depth), and from an eye
    /// under the surface the water it is seen through. False: left as the host drew it (a
    /// host that lights its geometry under the water itself). record_in_pass cannot (it
    /// draws into the host's pass, whose geometry it does not copy).
    bool light_host_geometry = true;
};

/// A view of the scene the renderer draws (Renderer::add_view): its own refraction copies,
/// frame constants, draws and timings over the scene's uploads. Ids are not reused.
struct ViewId {
    std::uint32_t value = 0;
    bool operator==(const ViewId&) const = default;
};
/// The view every renderer has from create() on (record_frame draws it).
inline constexpr ViewId kMainView{};

/// One view's part of a frame (Renderer::record_views): which view, its frame (camera,
/// time, debug view, floats, clip volumes) and its targets.
struct ViewFrame {
    ViewId view = kMainView;
    FrameInfo frame;
    FrameTargets targets;
};

/// How many times each stage ran in one pass, from a pipeline statistics query.
struct PassInvocations {
    std::uint64_t vertex = 0;                ///< vertex shader invocations
    std::uint64_t tessellation_patches = 0;  ///< tessellation control shader patches
    std::uint64_t tessellation_evaluation = 0;
    std::uint64_t primitives = 0;  ///< primitives that reached the clipper
    std::uint64_t fragment = 0;    ///< fragment shader invocations
    /// Samples that passed the depth test and were written (a precise occlusion query;
    /// PassTimings::samples_counted). Fragment invocations count what the device shaded,
    /// which depends on when it tests depth; this does not.
    std::uint64_t samples_passed = 0;
};

/// GPU time per pass of one frame, from timestamp queries (ms), and where the device
/// enabled pipelineStatisticsQuery (DeviceContext::enabled_features), how many times
/// each stage ran in the opaque pass (sky, terrain, floats) and the water's.
struct PassTimings {
    double sky_and_terrain_ms = 0.0;
    double scene_copy_ms = 0.0;
    double water_ms = 0.0;
    double total_ms = 0.0;
    bool invocations_counted = false;
    /// Where the host also enabled occlusionQueryPrecise: PassInvocations::samples_passed.
    bool samples_counted = false;
    PassInvocations opaque_invocations, water_invocations;
};

/// Renderer::stats(view): the scene's uploads, which every view shares, and what the
/// view's last frame recorded drew.
struct RendererStats {
    std::uint64_t terrain_vertices = 0;   ///< Drawn by the view's last frame (its level-of-detail nodes).
    std::uint64_t terrain_triangles = 0;  ///< Drawn by the view's last frame.
    std::uint64_t terrain_bytes = 0;      ///< Resident: the terrain's height texture and patch.
    std::uint64_t shore_bytes = 0;        ///< Resident: the shore models' fields.
    /// Every byte of device memory the renderer holds now (its buffers and images, the two
    /// above included, and those kept until the frames in flight that use them are done).
    std::uint64_t device_memory_bytes = 0;
    /// The shore fields' coarse level is every k-th texel (1: the models' own grids, all resident).
    std::uint32_t shore_stride = 1;
    /// Over the budget (shore_stride > 1): the full-resolution shore tiles drawn over the
    /// coarse level now (those nearest the camera), of the tiles that could be; and the
    /// bytes of them the last frame recorded brought in. Tiles of a saved bake that nothing
    /// has read are read from its folder on a thread of the renderer's own and drawn a frame
    /// or more later, without being kept in host memory: shore_tiles_reading of them now.
    std::uint64_t shore_streamed_tiles = 0;
    std::uint64_t shore_streamable_tiles = 0;
    std::uint64_t shore_streamed_bytes = 0;
    std::uint64_t shore_tiles_reading = 0;
    /// Bytes of height texture and shore fields the last set_scene wrote to the device: a
    /// scene re-baked after an edit of the one drawn writes only the texels and shore tiles
    /// the edit changed.
    std::uint64_t scene_upload_bytes = 0;
    /// The camera's submersion in the last frame recorded: query_submersion at its position
    /// and the frame's time (its wakes included), the answer a host gets by asking the same.
    /// Where `camera.under` the frame was drawn from under a body's surface, but for the
    /// part of the near plane above it when the water line crosses the lens (the renderer
    /// asks the near plane's corners too: near_plane_corners).
    Submersion camera;
    /// The clip volumes the last frame recorded drew with (the scene's, the host's, the
    /// floats'), and the floats' it left out for want of room (the farthest from the camera).
    std::uint32_t clip_volumes = 0, clip_volumes_left_out = 0;
    std::uint64_t water_patches = 0;  ///< Tessellated patches submitted (before culling).
    std::uint32_t waves = 0;
    double water_patch_size = 0.0;  ///< m
};

/// What the driver says of a compiled shader (VK_KHR_pipeline_executable_properties):
/// one statistic of a stage, as the driver names and describes it ("VGPRs",
/// "Instructions", "Latency", ...). They tell a shader's cost on the device's own
/// instruction set without running it.
struct ShaderStatistic {
    std::string name;
    std::string description;
    double value = 0.0;
};

/// One executable of a pipeline: a stage, or stages the driver merged ("Vertex Shader as
/// LS + Tessellation Control Shader"), with its statistics.
struct PipelineStageStatistics {
    std::string pipeline;  ///< the renderer's name for it: "sky", "terrain", "floats", "water", ...
    std::string stage;     ///< the driver's name for the executable
    std::vector<ShaderStatistic> statistics;

    /// The statistic called `name`, or `fallback` when the driver gives none by that name.
    double value(const std::string& name, double fallback = -1.0) const;
};

class Renderer {
  public:
    static Result<std::unique_ptr<Renderer>> create(const RendererInitInfo& info);
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    /// Uploads the scene's terrain and water (submits and waits). Call again after edits:
    /// a heightmap edited from the one drawn, and a shore model re-baked from the one
    /// drawn (bake_scene with SceneBakeOptions::previous), are written where they changed.
    /// The scene must be baked (bake_scene) unless its shore is disabled; an unbaked one
    /// is refused rather than drawn as open sea.
    Status set_scene(const Scene& scene);
    /// Swaps only the ocean's water (a preset change); the terrain, lakes and rivers stay.
    /// Waits for the device when a new shore model is uploaded. A body without a shore
    /// model over a scene whose ocean feels its shore is refused (the surf is never
    /// dropped silently): re-bake the scene with the new water instead
    /// (docs/embedding.md, "Preset swap"), or pass a body carrying a model baked for it.
    Status set_water(const WaterBody& water);
    /// Sizes a view's refraction copies for its targets. Call it before the view's first
    /// frame and whenever its targets change size (swapchain recreation); a frame whose
    /// targets are of another size is refused. Never waits: the old copies are destroyed
    /// once no frame in flight can read them, and the other views are untouched.
    Status resize(VkExtent2D extent, ViewId view = kMainView);
    /// A new view, its copies sized `extent`, ready for record_views. Never waits; the
    /// views already there are untouched.
    Result<ViewId> add_view(VkExtent2D extent);
    /// Removes a view (not the main view). Never waits: its buffers and copies are destroyed
    /// once no frame in flight can read them.
    Status remove_view(ViewId view);
    /// The views there now, the main view first.
    std::vector<ViewId> views() const;

    /// Records the main view's frame (record_views with it alone).
    Status record_frame(VkCommandBuffer cmd, const FrameInfo& frame, const FrameTargets& targets);
    /// Records a frame of several views into `cmd`: the sky table once, then each view's
    /// passes (opaque, scene copy, water) into its targets, in the order given. Every view
    /// at most once, with the same frame_index, sun and turbidity (one sky table); the
    /// shore tiles stream toward the nearest of their cameras. Refused as a whole, nothing
    /// recorded, when one of them is. The same views recorded one per command buffer give
    /// the same pictures.
    Status record_views(VkCommandBuffer cmd, std::span<const ViewFrame> views);
    Status record_in_pass(VkCommandBuffer cmd, const FrameInfo& frame, VkExtent2D extent, ViewId view = kMainView);
    /// Records the refresh of the sky table (the sky, less the sun's disc, that the water
    /// reflects and the fog fades to: a 256 x 256 texture drawn from `frame`'s sun and
    /// turbidity) outside any pass. record_frame does it itself; a host drawing with
    /// record_in_pass calls it before beginning its pass whenever the sun or the turbidity
    /// may have changed (every frame is fine), and record_in_pass refuses a frame whose
    /// sky the table does not hold. Never submits or waits.
    Status record_sky(VkCommandBuffer cmd, const FrameInfo& frame);

    /// SPIR-V by shader source name ("sky.vert", "sky.frag", "terrain.vert", "terrain.frag", "mesh.vert",
    /// "water.vert", "water.tesc", "water.tese", "water.frag", and "water_per_sample.frag":
    /// water.frag compiled with TW_WATER_PER_SAMPLE, drawn when the water is shaded per
    /// sample); a name left out keeps the built-in shader. The tables' shaders
    /// (sky_table.frag, foam_noise.frag) are not reloaded.
    using ShaderSpirv = std::map<std::string, std::vector<std::uint32_t>, std::less<>>;
    /// Hot reload: rebuilds the draw pipelines from `spirv`. On failure the current
    /// pipelines keep drawing and the error names the shader. On success the next
    /// recorded frame uses the new ones; the old ones are destroyed once no frame in
    /// flight can use them (no device-wide wait). The interface (bindings, push
    /// constants, vertex inputs) must stay the built-in shaders'.
    Status reload_shaders(const ShaderSpirv& spirv);

    /// Pass timings of `view`'s frame recorded with `frame_index`, once the host knows it has finished.
    Result<PassTimings> timings(std::uint64_t frame_index, ViewId view = kMainView);
    /// The scene's uploads, and what `view`'s last frame drew (zero for a view not there).
    RendererStats stats(ViewId view = kMainView) const;
    /// Every stage of the renderer's pipelines as the driver compiled them, where the device
    /// has DeviceContext::pipeline_executable_info; fails with ErrorCode::unsupported,
    /// saying so, where it has not. Reads what the pipelines captured when they were built.
    Result<std::vector<PipelineStageStatistics>> pipeline_statistics() const;
    /// The settings of RendererInitInfo::quality with its overrides applied.
    const QualitySettings& quality() const;

  private:
    struct Impl;
    explicit Renderer(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

}  // namespace tidewater::render
