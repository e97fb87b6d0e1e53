#include "tidewater/render/renderer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <numbers>
#include <optional>
#include <span>
#include <vector>

#include "body_uploads.hpp"
#include "clip_uploads.hpp"
#include "descriptor_sets.hpp"
#include "drawn_table.hpp"
#include "float_uploads.hpp"
#include "frame_constants.hpp"
#include "frame_timer.hpp"
#include "gpu_memory.hpp"
#include "pipeline_statistics.hpp"
#include "render_pipelines.hpp"
#include "scene_copies.hpp"
#include "scene_uploads.hpp"
#include "target_formats.hpp"
#include "terrain_lod.hpp"
#include "tidewater/constants.hpp"
#include "tidewater/detail/shore_waves.hpp"
#include "vk_util.hpp"
#include "wake_uploads.hpp"

namespace tidewater::render {

using detail::GpuBuffer;

namespace {

// The debug views: the enum's values are the shaders' (host_device.h's kView*), each
// named once here.
struct NamedView {
    DebugView view;
    std::uint32_t shader_value;
    std::string_view name;
};
constexpr std::array<NamedView, gpu::kViewCount> kNamedViews = {{
    {DebugView::shaded, gpu::kViewShaded, "shaded"},
    {DebugView::height, gpu::kViewHeight, "height"},
    {DebugView::normals, gpu::kViewNormals, "normals"},
    {DebugView::jacobian, gpu::kViewJacobian, "jacobian"},
    {DebugView::depth, gpu::kViewDepth, "depth"},
    {DebugView::lod, gpu::kViewLod, "lod"},
    {DebugView::wireframe, gpu::kViewWireframe, "wireframe"},
    {DebugView::shore, gpu::kViewShore, "shore"},
    {DebugView::breaking, gpu::kViewBreaking, "breaking"},
    {DebugView::flow, gpu::kViewFlow, "flow"},
    {DebugView::wake, gpu::kViewWake, "wake"},
    {DebugView::foam, gpu::kViewFoam, "foam"},
}};
constexpr bool views_match_shaders() {
    for (std::size_t i = 0; i < kNamedViews.size(); ++i)
        if (static_cast<std::uint32_t>(kNamedViews[i].view) != i || kNamedViews[i].shader_value != i) return false;
    return true;
}
static_assert(views_match_shaders(),
              "DebugView, its names and host_device.h's kView* must list the views in one order");
constexpr std::array<DebugView, gpu::kViewCount> kViews = [] {
    std::array<DebugView, gpu::kViewCount> views{};
    for (std::size_t i = 0; i < views.size(); ++i) views[i] = kNamedViews[i].view;
    return views;
}();

}  // namespace

std::string_view to_string(DebugView view) {
    return kNamedViews[static_cast<std::size_t>(view)].name;
}

std::optional<DebugView> parse_debug_view(std::string_view name) {
    for (const NamedView& v : kNamedViews)
        if (v.name == name) return v.view;
    return std::nullopt;
}

std::span<const DebugView> all_debug_views() {
    return kViews;
}

// The renderer is its parts: pipelines (render_pipelines), the scene's GPU data
// (scene_uploads, shared with the GPU queries and by every view), each view's copies of
// the opaque scene and passes (scene_copies), frame buffers and timestamps (frame_timer).
// This file holds the views and their in-flight slots, and the public calls that tie
// them together.
struct Renderer::Impl {
    detail::Device device;  // the host's, with the functions loaded for it
    RendererInitInfo info;
    QualitySettings quality;  // info.quality with its overrides

    detail::DrawOptions draw_options() const { return detail::draw_options_for(info, quality); }
    const detail::ColorTarget* color_target = nullptr;  // entries of the format table
    const detail::DepthTarget* depth_target = nullptr;
    const detail::Device& ctx() const { return device; }
    const detail::VulkanFunctions& vk() const { return device.vk(); }

    detail::FramePipelines pipelines;
    detail::OwnedCommandPool upload_pool;
    detail::PlaceholderCopies placeholders;  // what a pass without a scene copy samples
    detail::SkyTable sky;                    // what the water reflects and the fog fades to
    detail::DrawnTable foam_noise;

    /// Per frame in flight of a view: what the CPU writes for it, and its descriptor set.
    struct Slot {
        GpuBuffer frame, waves, draws, river_waves, wake_points, float_vertices, terrain_nodes;
        GpuBuffer shore_pages;    // the shore pages as this frame reads them (tiles stream between frames)
        GpuBuffer clip_textures;  // the distance textures' samples (eFrameClipTextures)
        std::vector<std::shared_ptr<const DistanceTexture>> clip_textures_held;  // what clip_textures holds
        std::vector<detail::FloatUpload::Draw> float_draws;                      // this frame's, into float_vertices
        std::array<std::uint32_t, 5> terrain_first{}, terrain_count{};           // this frame's, into terrain_nodes
        VkDescriptorSet set = VK_NULL_HANDLE;
        std::uint64_t recorded_frame = ~0ull;
    };
    /// A view: its slots, their descriptor sets, its timestamps and its copies of the opaque
    /// scene, and what its last frame drew. The scene's uploads are the renderer's.
    struct View {
        std::vector<Slot> slots;
        detail::OwnedDescriptorPool descriptor_pool;
        detail::FrameTimer timer;
        std::optional<detail::SceneCopies> copies;                               // none until the view is sized
        std::uint64_t patches = 0, terrain_vertices = 0, terrain_triangles = 0;  // its last frame's
        Submersion camera;
        std::uint32_t clips = 0, clips_left_out = 0;
    };
    std::map<std::uint32_t, std::unique_ptr<View>> views;  // by ViewId; the main view is 0
    std::uint32_t next_view = 1;
    /// The slots' buffers hold this many body draws, waves and river waves (set_scene).
    std::size_t slot_draws = 1, slot_waves = kMaxWaves, slot_river_waves = 1;

    /// What was replaced or removed without a wait (pipelines by reload_shaders, a view's
    /// copies by resize, a view by remove_view), kept until no frame in flight can use it:
    /// what was retired before frame `until` is destroyed when frame `until` +
    /// frames_in_flight records.
    struct Retired {
        detail::DrawPipelines draws;
        std::optional<detail::SceneCopies> copies;
        std::unique_ptr<View> view;
        std::uint64_t until = 0;
    };
    std::vector<Retired> retired;
    std::uint64_t next_frame = 0;  // one past the last frame index recorded

    std::optional<detail::TerrainUpload> terrain;  // set by set_scene
    detail::ShoreBuffers shore;
    detail::BodyBuffers bodies;           // lakes and rivers (placeholders without)
    Scene scene;                          // as set; its ocean is replaced by set_water
    std::uint64_t last_upload_bytes = 0;  // written by the last set_scene
    std::uint64_t shore_written = 0;      // by the last use_shores
    std::uint64_t shore_streamed = 0;     // by the last frame recorded

    Impl() = default;
    Impl(const Impl&) = delete;
    Impl& operator=(const Impl&) = delete;
    ~Impl() {
        // Every member destroys its own handles; none may be in use by the GPU then. A lost
        // device has finished all its work: the handles go all the same, and the host hears.
        if (const VkResult r = vk().DeviceWaitIdle(ctx().device); r != VK_SUCCESS)
            log(detail::vk_error(r, "vkDeviceWaitIdle (destroying the renderer)").message);
    }

    void log(const std::string& message) const {
        if (info.log) info.log(message);
    }
    View* find_view(ViewId id) const {
        const auto it = views.find(id.value);
        return it == views.end() ? nullptr : it->second.get();
    }
    /// A view with its slots sized for the scene, and its copies when `extent` is given.
    /// Makes buffers and sets; no GPU work, no wait.
    Result<std::unique_ptr<View>> make_view(std::optional<VkExtent2D> extent) const;
    Status size_slots(View& view) const;
    /// Uploads the ocean's shore model (slot 0; null without an ocean) and each lake's after
    /// it, within the budget the terrain's `terrain_bytes` leave.
    Status use_shores(const WaterBody* ocean, const std::vector<SceneLake>& lakes, std::uint64_t terrain_bytes);
    void write_descriptors(const View& view, Slot& slot, bool with_scene_copy);
    /// A frame's recording, in three steps: its inputs checked, its plan (what it draws,
    /// from the frame and the scene), and the plan written into its view's in-flight slot.
    struct Planned {
        detail::FramePlan plan;
        detail::BodyDraws draws;
        detail::WakeUpload wakes;
        detail::FloatUpload floats;
        detail::TerrainSelection terrain;
        Submersion camera;  // where the camera is: above every surface, or under a body's
        detail::FrameClips clips;
    };
    Status validate_frame(const FrameInfo& frame, VkExtent2D extent) const;
    Status validate_view_frame(const ViewFrame& v) const;
    Result<Planned> plan_frame(const FrameInfo& frame, VkExtent2D extent, VkOffset2D offset, bool scene_copy) const;
    Status upload(View& view, Slot& slot, Planned& planned, bool scene_copy);
    Slot& take_slot(View& view, std::uint64_t frame_index);
    /// Over the budget, the full-resolution shore tiles nearest `cameras` come in.
    void stream_shores(std::span<const glm::dvec2> cameras, std::uint64_t frame_index);
    Status prepare_slot(View& view, const FrameInfo& frame, VkExtent2D extent, VkOffset2D offset, bool scene_copy,
                        Slot*& slot, detail::FramePlan& plan);
    /// One view's passes into its targets: opaque, the scene copy, water.
    void record_passes(VkCommandBuffer cmd, View& view, const Slot& slot, const detail::FramePlan& plan,
                       const FrameInfo& frame, const FrameTargets& targets);
    /// The host's geometry already in the targets, lit under the water where it lies (host_light.frag).
    void light_host_geometry(VkCommandBuffer cmd, View& view, const Slot& slot, const FrameTargets& targets);
    void draw_opaque(VkCommandBuffer cmd, const Slot& slot, VkRect2D area, DebugView view);
    void draw_water(VkCommandBuffer cmd, View& view, const Slot& slot, const detail::FramePlan& plan, VkRect2D area,
                    DebugView debug_view);
};

Result<std::unique_ptr<Renderer::Impl::View>> Renderer::Impl::make_view(std::optional<VkExtent2D> extent) const {
    auto view = std::make_unique<View>();
    const std::uint32_t n = info.frames_in_flight;
    TW_VK_TRY(detail::make_descriptor_pool(ctx(), detail::kFrameSetRows, n, view->descriptor_pool));
    view->slots.resize(n);
    const VkDescriptorSetLayout set_layout = pipelines.set_layout.get();
    for (Slot& s : view->slots) {
        auto frame = GpuBuffer::create(ctx(), sizeof(gpu::GpuFrame), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
        if (!frame) return frame.error();
        s.frame = std::move(frame).value();
        auto wake_points = GpuBuffer::create(ctx(), detail::wake_buffer_bytes(gpu::kMaxWakePoints),
                                             VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
        if (!wake_points) return wake_points.error();
        s.wake_points = std::move(wake_points).value();
        auto float_vertices = GpuBuffer::create(ctx(), sizeof(detail::FloatVertex) * detail::kMaxFloatVertices,
                                                VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
        if (!float_vertices) return float_vertices.error();
        s.float_vertices = std::move(float_vertices).value();
        auto terrain_nodes = GpuBuffer::create(ctx(), sizeof(gpu::GpuTerrainNode) * detail::kMaxTerrainNodes,
                                               VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
        if (!terrain_nodes) return terrain_nodes.error();
        s.terrain_nodes = std::move(terrain_nodes).value();
        VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
        alloc.descriptorPool = view->descriptor_pool.get();
        alloc.descriptorSetCount = 1;
        alloc.pSetLayouts = &set_layout;
        TW_VK_TRY(vk().AllocateDescriptorSets(ctx().device, &alloc, &s.set));
    }
    if (auto st = size_slots(*view); !st) return st.error();
    auto timer = detail::FrameTimer::create(ctx(), n);
    if (!timer) return timer.error();
    view->timer = std::move(timer).value();
    if (extent) {
        auto copies = detail::SceneCopies::create(ctx(), *color_target, *depth_target, info.samples, *extent);
        if (!copies) return copies.error();
        view->copies = std::move(copies).value();
    }
    return view;
}

// Per-frame buffers sized for the scene's draws: grown while no frame in flight uses the
// view (set_scene and set_water wait for the device first; a new view has none).
Status Renderer::Impl::size_slots(View& view) const {
    for (Slot& s : view.slots) {
        for (auto [buffer, bytes] :
             {std::pair{&s.waves, sizeof(gpu::GpuWave) * std::max<std::size_t>(slot_waves, 1)},
              std::pair{&s.draws, sizeof(gpu::GpuBodyDraw) * std::max<std::size_t>(slot_draws, 1)},
              std::pair{&s.river_waves, sizeof(gpu::GpuRiverWave) * std::max<std::size_t>(slot_river_waves, 1)}}) {
            if (buffer->handle() && buffer->size() >= bytes) continue;
            auto made = GpuBuffer::create(ctx(), bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
            if (!made) return made.error();
            *buffer = std::move(made).value();
        }
    }
    return {};
}

Status Renderer::Impl::use_shores(const WaterBody* ocean, const std::vector<SceneLake>& lakes,
                                  std::uint64_t terrain_bytes) {
    detail::ShoreBuffers::Models models{ocean ? ocean->shore() : nullptr};
    for (const SceneLake& lake : lakes) models.push_back(lake.body.shore());
    shore_written = 0;
    if (shore.holds(models)) return {};
    TW_VK_TRY(vk().DeviceWaitIdle(ctx().device));  // frames in flight may read the old fields
    // The shore fields may take what the terrain leaves (at least half the budget).
    const std::uint64_t budget = info.gpu_memory_budget - std::min(terrain_bytes, info.gpu_memory_budget / 2);
    auto uploaded = shore.upload(ctx(), models, budget);
    if (!uploaded) return uploaded.error();
    shore_written = shore.rewritten_bytes();
    return {};
}

void Renderer::Impl::write_descriptors(const View& view, Slot& slot, bool with_scene_copy) {
    using detail::bound_buffer;
    using detail::bound_texture;
    const bool copied = with_scene_copy && view.copies;
    std::array<detail::BoundResource, gpu::eFrameBindingCount> r;
    r[gpu::eFrameConstants] = bound_buffer(slot.frame.handle());
    r[gpu::eFrameWaves] = bound_buffer(slot.waves.handle());
    r[gpu::eFrameTerrainHeight] = bound_texture(pipelines.linear.get(), terrain->heights.view());
    r[gpu::eFrameSceneColor] =
        bound_texture(pipelines.linear.get(), copied ? view.copies->color_view() : placeholders.color.view());
    r[gpu::eFrameSceneDepth] =
        bound_texture(pipelines.nearest.get(), copied ? view.copies->depth_view() : placeholders.depth.view());
    r[gpu::eFrameShoreWaves] = bound_buffer(shore.per_wave());
    r[gpu::eFrameShoreShared] = bound_buffer(shore.shared());
    r[gpu::eFrameShorePages] = bound_buffer(slot.shore_pages.handle());
    r[gpu::eFrameShoreLayers] = bound_buffer(shore.layers());
    r[gpu::eFrameBodyDraws] = bound_buffer(slot.draws.handle());
    r[gpu::eFrameRiverTexels] = bound_buffer(bodies.river_texels.handle());
    r[gpu::eFrameRiverChannel] = bound_buffer(bodies.river_channel.handle());
    r[gpu::eFrameBodyMasks] = bound_buffer(bodies.masks.handle());
    r[gpu::eFrameRiverWaves] = bound_buffer(slot.river_waves.handle());
    r[gpu::eFramePatchList] = bound_buffer(bodies.patches.handle());
    r[gpu::eFrameWakePoints] = bound_buffer(slot.wake_points.handle());
    r[gpu::eFrameSkyTable] = bound_texture(pipelines.linear.get(), sky.view());
    r[gpu::eFrameFoamNoise] = bound_texture(pipelines.linear_repeat.get(), foam_noise.view());
    r[gpu::eFrameClipTextures] = bound_buffer(slot.clip_textures.handle());
    detail::write_set(ctx(), slot.set, detail::kFrameSetRows, r);
}

namespace {
Status validate_sky(const FrameInfo& frame) {
    if (!std::isfinite(frame.sun_direction.x) || !std::isfinite(frame.sun_direction.y) ||
        !std::isfinite(frame.sun_direction.z) || glm::length(frame.sun_direction) < 1e-9)
        return Error{ErrorCode::invalid_argument, "renderer: sun_direction must be finite and non-zero"};
    if (!(frame.sky_turbidity >= 1.7 && frame.sky_turbidity <= 10.0))
        return Error{ErrorCode::invalid_argument,
                     fmt::format("renderer: sky_turbidity {} is out of range (1.7 to 10)", frame.sky_turbidity)};
    return {};
}
}  // namespace

Status Renderer::Impl::validate_frame(const FrameInfo& frame, VkExtent2D extent) const {
    if (!terrain) return Error{ErrorCode::invalid_argument, "renderer: no scene; call set_scene first"};
    if (extent.width == 0 || extent.height == 0 || extent.width > 16384 || extent.height > 16384)
        return Error{ErrorCode::invalid_argument,
                     fmt::format("renderer: extent {}x{} is out of range (1 to 16384)", extent.width, extent.height)};
    if (auto st = detail::validate_camera(frame.camera); !st) return st;
    if (!std::isfinite(frame.time) || std::abs(frame.time) > 1e9)
        return Error{ErrorCode::invalid_argument,
                     fmt::format("renderer: time {} is out of range (finite, |t| <= 1e9 s)", frame.time)};
    if (auto st = validate_sky(frame); !st) return st;
    if (frame.view == DebugView::wireframe && !pipelines.draws.water_wire)
        return Error{ErrorCode::unsupported,
                     "renderer: the wireframe view needs fillModeNonSolid (RendererInitInfo::wireframe)"};
    return {};
}

// A view's frame for record_views: a view that is there, sized for its targets.
Status Renderer::Impl::validate_view_frame(const ViewFrame& v) const {
    const FrameTargets& t = v.targets;
    const View* view = find_view(v.view);
    if (!view)
        return Error{ErrorCode::invalid_argument,
                     fmt::format("renderer: view {} is not there (removed, or never added)", v.view.value)};
    if (!t.color_image || !t.color_view || !t.depth_image || !t.depth_view)
        return Error{
            ErrorCode::invalid_argument,
            fmt::format("renderer: view {}: a frame needs the colour and depth images and views", v.view.value)};
    const VkExtent2D sized = view->copies ? view->copies->extent() : VkExtent2D{};
    if (t.extent.width != sized.width || t.extent.height != sized.height)
        return Error{ErrorCode::invalid_argument,
                     fmt::format("renderer: view {}: the frame's targets are {}x{} but the view is sized for {}x{}: "
                                 "call resize() for the view whenever its targets change size (recording never waits)",
                                 v.view.value, t.extent.width, t.extent.height, sized.width, sized.height)};
    if (t.offset.x < 0 || t.offset.y < 0 || t.offset.x > 16384 || t.offset.y > 16384)
        return Error{ErrorCode::invalid_argument,
                     fmt::format("renderer: view {}: offset ({}, {}) is out of range (0 to 16384)", v.view.value,
                                 t.offset.x, t.offset.y)};
    if ((t.offset.x != 0 || t.offset.y != 0) && info.samples != VK_SAMPLE_COUNT_1_BIT)
        return Error{ErrorCode::unsupported,
                     fmt::format("renderer: view {}: multisampled targets draw from offset (0, 0) only (their depth "
                                 "resolves into a copy the view's size)",
                                 v.view.value)};
    return validate_frame(v.frame, t.extent);
}

Renderer::Impl::Slot& Renderer::Impl::take_slot(View& view, std::uint64_t frame_index) {
    Slot& slot = view.slots[frame_index % view.slots.size()];
    // Frames up to frame_index - frames_in_flight have finished: what was retired may go.
    std::erase_if(retired, [&](const Retired& r) { return r.until + info.frames_in_flight <= frame_index; });
    next_frame = std::max(next_frame, frame_index + 1);
    slot.recorded_frame = frame_index;
    return slot;
}

void Renderer::Impl::stream_shores(std::span<const glm::dvec2> cameras, std::uint64_t frame_index) {
    shore_streamed = info.shore_stream_bytes_per_frame == 0
                         ? 0
                         : shore.stream(cameras, frame_index, info.frames_in_flight, info.shore_stream_bytes_per_frame);
}

// What the frame draws, from the frame and the scene; nothing is written yet.
Result<Renderer::Impl::Planned> Renderer::Impl::plan_frame(const FrameInfo& frame, VkExtent2D extent, VkOffset2D offset,
                                                           bool scene_copy) const {
    const double water_density = quality.water_per_sample ? std::sqrt(static_cast<double>(info.samples)) : 1.0;
    Planned p;
    p.plan = detail::plan_frame(frame, extent, scene.ocean, terrain->placement, terrain->water_half_size, scene_copy,
                                color_target->linear_output, water_density, quality);
    p.plan.frame.water_density.z = scene_copy && info.samples == VK_SAMPLE_COUNT_1_BIT ? 1.0f : 0.0f;
    p.plan.frame.view_corner = glm::vec4(static_cast<float>(offset.x), static_cast<float>(offset.y), 0.0f, 0.0f);
    // Where the water is removed: the scene's, the host's and the floats' clip volumes.
    auto clips = detail::gather_clip_volumes(scene, frame.clip_volumes, frame.floats, frame.camera.position);
    if (!clips) return clips.error();
    p.clips = std::move(clips).value();
    detail::pack_clip_volumes(scene, p.clips, p.plan.origin, p.plan.frame);
    // Above or under the water: the CPU's answer for the camera and for the corners of its
    // near plane (with the same clip volumes), so a host that asks query_submersion the same
    // switches with the picture. The surface across the near plane (a fraction of a metre) is
    // taken as bilinear between its corners: the water line drawn on the lens.
    QueryOptions one_thread;
    one_thread.threads = 1;
    one_thread.wakes = frame.wakes;
    one_thread.clip_volumes = p.clips.host_and_floats;
    const auto corners = near_plane_corners(frame.camera, static_cast<double>(extent.width) / extent.height);
    // The eye, then the image's top left, top right, bottom right and bottom left.
    const std::array<glm::dvec3, 5> asked{frame.camera.position, corners[3], corners[2], corners[1], corners[0]};
    std::array<Submersion, 5> answers{};
    if (!query_submersion(scene, frame.time, asked, answers, one_thread))
        answers = {};  // a scene the queries cannot answer is drawn from above
    p.camera = answers[0];
    // The water the camera looks through: the body over the eye (or over a corner of the near
    // plane when only the lens dips in), the ocean's above every surface.
    const auto wet = std::find_if(answers.begin(), answers.end(), [](const Submersion& s) { return s.under; });
    const WaterOptics water = optics_of(scene, wet != answers.end() ? wet->body : BodyRef{BodyKind::ocean, -1});
    p.plan.frame.water_extinction = glm::vec4(glm::vec3(water.extinction), 0.0f);
    p.plan.frame.water_color = glm::vec4(glm::vec3(water.color), 0.0f);
    if (std::any_of(answers.begin(), answers.end(), [](const Submersion& s) { return s.under; })) {
        // A corner with no water over it (over land) counts as above the water.
        auto depth = [](const Submersion& s) {
            return static_cast<float>(s.under ? s.depth : std::min(s.depth, -1e-3));
        };
        p.plan.frame.underwater = glm::vec4(1.0f, static_cast<float>(std::max(p.camera.depth, 0.0)),
                                            static_cast<float>(frame.camera.position.y + p.camera.depth), 0.0f);
        p.plan.frame.near_plane_depths =
            glm::vec4(depth(answers[1]), depth(answers[2]), depth(answers[3]), depth(answers[4]));
    }
    p.draws = detail::plan_body_draws(scene, bodies, frame.time, p.plan, shore, quality.waves_drawn);
    auto wakes = detail::pack_wakes(scene, frame.wakes, frame.time, p.plan.origin);
    if (!wakes) return wakes.error();
    p.wakes = std::move(wakes).value();
    p.plan.frame.wakes = glm::vec4(static_cast<float>(p.wakes.points.size()), static_cast<float>(p.wakes.turbulent),
                                   static_cast<float>(p.wakes.boxes.size()), 0.0f);
    for (std::size_t b = 0; b < p.wakes.boxes.size(); ++b) p.plan.frame.wake_boxes[b] = p.wakes.boxes[b];
    auto floats = detail::pack_floats(frame.floats, p.plan.origin);
    if (!floats) return floats.error();
    p.floats = std::move(floats).value();
    p.plan.water_draws = p.draws.patch_counts;
    detail::TerrainLodView lod_view;
    lod_view.camera = frame.camera.position;
    lod_view.origin = p.plan.origin;
    lod_view.view_proj = p.plan.frame.view_proj;
    lod_view.pixel_angle =
        2.0 * std::tan(0.5 * frame.camera.fov_y_deg * std::numbers::pi / 180.0) / static_cast<double>(extent.height);
    p.terrain = detail::select_terrain_nodes(terrain->lod, lod_view);
    return p;
}

// The plan into the slot's mapped buffers and its descriptor set.
Status Renderer::Impl::upload(View& view, Slot& slot, Planned& p, bool scene_copy) {
    // The shore pages as they are now: tiles streamed in since the slot's last frame.
    const std::span<const std::uint32_t> pages = shore.pages_now();
    if (!slot.shore_pages.handle() || slot.shore_pages.size() < pages.size_bytes()) {
        auto made = GpuBuffer::create(ctx(), pages.size_bytes(), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
        if (!made) return made.error();
        slot.shore_pages = std::move(made).value();
    }
    std::memcpy(slot.shore_pages.mapped(), pages.data(), pages.size_bytes());
    // The distance textures, copied only when the frame's are not the slot's last ones.
    if (!slot.clip_textures.handle() || slot.clip_textures_held != p.clips.textures) {
        const std::size_t bytes = std::max<std::size_t>(sizeof(float) * detail::texture_samples(p.clips.textures), 16);
        if (!slot.clip_textures.handle() || slot.clip_textures.size() < bytes) {
            auto made = GpuBuffer::create(ctx(), bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
            if (!made) return made.error();
            slot.clip_textures = std::move(made).value();
        }
        detail::write_texture_samples(p.clips.textures, static_cast<float*>(slot.clip_textures.mapped()));
        slot.clip_textures_held = p.clips.textures;
    }
    detail::write_wake_buffer(p.wakes, slot.wake_points.mapped());
    if (!p.floats.vertices.empty())
        std::memcpy(slot.float_vertices.mapped(), p.floats.vertices.data(),
                    sizeof(detail::FloatVertex) * p.floats.vertices.size());
    slot.float_draws = std::move(p.floats.draws);
    if (!p.terrain.nodes.empty())
        std::memcpy(slot.terrain_nodes.mapped(), p.terrain.nodes.data(),
                    sizeof(gpu::GpuTerrainNode) * p.terrain.nodes.size());
    slot.terrain_first = p.terrain.first;
    slot.terrain_count = p.terrain.count;
    const std::uint64_t patch_vertices = (gpu::kTerrainPatchQuads + 1) * (gpu::kTerrainPatchQuads + 1);
    view.terrain_vertices = view.terrain_triangles = 0;
    for (std::size_t g = 0; g < 5; ++g) {
        view.terrain_vertices += slot.terrain_count[g] * patch_vertices;
        view.terrain_triangles +=
            slot.terrain_count[g] * (g == 0 ? terrain->index_count : terrain->quadrant_index_count) / 3;
    }
    std::memcpy(slot.frame.mapped(), &p.plan.frame, sizeof(p.plan.frame));
    const detail::BodyDraws& draws = p.draws;
    if (!draws.waves.empty())
        std::memcpy(slot.waves.mapped(), draws.waves.data(), sizeof(gpu::GpuWave) * draws.waves.size());
    if (!draws.draws.empty())
        std::memcpy(slot.draws.mapped(), draws.draws.data(), sizeof(gpu::GpuBodyDraw) * draws.draws.size());
    if (!draws.river_waves.empty())
        std::memcpy(slot.river_waves.mapped(), draws.river_waves.data(),
                    sizeof(gpu::GpuRiverWave) * draws.river_waves.size());
    write_descriptors(view, slot, scene_copy);
    return {};
}

Status Renderer::Impl::prepare_slot(View& view, const FrameInfo& frame, VkExtent2D extent, VkOffset2D offset,
                                    bool scene_copy, Slot*& slot, detail::FramePlan& plan) {
    slot = &take_slot(view, frame.frame_index);
    auto planned = plan_frame(frame, extent, offset, scene_copy);
    if (!planned) return planned.error();
    if (auto st = upload(view, *slot, *planned, scene_copy); !st) return st;
    view.camera = planned->camera;
    view.clips = planned->clips.total;
    view.clips_left_out = planned->clips.left_out;
    plan = std::move(planned->plan);
    return {};
}

void Renderer::Impl::light_host_geometry(VkCommandBuffer cmd, View& view, const Slot& slot, const FrameTargets& t) {
    const detail::VulkanFunctions& vk = this->vk();
    view.copies->record_host_copy(vk, cmd, t);
    detail::FramePasses pass(t, depth_target->attachment_layout, VK_NULL_HANDLE);
    pass.color.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
    pass.rendering.pDepthAttachment = nullptr;  // the pass reads the depth's copy
    vk.CmdBeginRendering(cmd, &pass.rendering);
    detail::set_viewport(vk, cmd, {t.offset, t.extent});
    vk.CmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines.layout.get(), 0, 1, &slot.set, 0, nullptr);
    vk.CmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines.draws.host_light.get());
    vk.CmdDraw(cmd, 3, 1, 0, 0);
    vk.CmdEndRendering(cmd);
    // The opaque pass draws over what this one wrote.
    constexpr VkPipelineStageFlags kColorStage = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    detail::transition(vk, cmd, t.color_image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                       VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, kColorStage, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
                       kColorStage, VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT);
}

void Renderer::Impl::record_passes(VkCommandBuffer cmd, View& view, const Slot& slot, const detail::FramePlan& plan,
                                   const FrameInfo& frame, const FrameTargets& t) {
    const detail::VulkanFunctions& vk = this->vk();
    const auto slot_index = static_cast<std::uint32_t>(&slot - view.slots.data());
    const VkRect2D area{t.offset, t.extent};
    const DebugView debug_view = frame.view;
    detail::SceneCopies& copies = *view.copies;
    detail::FrameTimer& timer = view.timer;
    timer.begin(vk, cmd, slot_index);
    // What the host drew before the frame is lit under the water before Tidewater draws over it.
    if (!t.clear && frame.light_host_geometry && debug_view == DebugView::shaded)
        light_host_geometry(cmd, view, slot, t);

    const bool msaa = copies.multisampled();
    detail::FramePasses passes(t, depth_target->attachment_layout, msaa ? copies.depth_resolve_view() : VK_NULL_HANDLE);
    if (msaa) copies.depth_to_resolve(vk, cmd);
    timer.begin_pass(vk, cmd, slot_index, detail::FrameTimer::opaque_pass);
    vk.CmdBeginRendering(cmd, &passes.rendering);
    draw_opaque(cmd, slot, area, debug_view);
    vk.CmdEndRendering(cmd);
    timer.end_pass(vk, cmd, slot_index, detail::FrameTimer::opaque_pass);
    if (msaa) copies.depth_resolved(vk, cmd);
    timer.mark(vk, cmd, slot_index, detail::FrameTimer::opaque_done, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT);

    copies.record_copy(vk, cmd, t);  // the opaque scene, for refraction and reflection
    timer.mark(vk, cmd, slot_index, detail::FrameTimer::copy_done, VK_PIPELINE_STAGE_TRANSFER_BIT);

    passes.load_for_water(t);
    timer.begin_pass(vk, cmd, slot_index, detail::FrameTimer::water_pass);
    vk.CmdBeginRendering(cmd, &passes.rendering);
    draw_water(cmd, view, slot, plan, area, debug_view);
    vk.CmdEndRendering(cmd);
    timer.end_pass(vk, cmd, slot_index, detail::FrameTimer::water_pass);
    timer.mark(vk, cmd, slot_index, detail::FrameTimer::water_done, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT);
}

void Renderer::Impl::draw_opaque(VkCommandBuffer cmd, const Slot& slot, VkRect2D area, DebugView view) {
    const detail::VulkanFunctions& vk = this->vk();
    detail::set_viewport(vk, cmd, area);
    const VkPipelineLayout layout = pipelines.layout.get();
    vk.CmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 0, 1, &slot.set, 0, nullptr);
    vk.CmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS,
                       (view == DebugView::wireframe ? pipelines.draws.terrain_wire : pipelines.draws.terrain).get());
    // The terrain's nodes: whole patches, then the patches drawn by one quadrant each.
    const VkBuffer terrain_buffers[2] = {terrain->vertices.handle(), slot.terrain_nodes.handle()};
    const VkDeviceSize terrain_offsets[2] = {0, 0};
    vk.CmdBindVertexBuffers(cmd, 0, 2, terrain_buffers, terrain_offsets);
    vk.CmdBindIndexBuffer(cmd, terrain->indices.handle(), 0, VK_INDEX_TYPE_UINT32);
    for (std::uint32_t g = 0; g < 5; ++g) {
        if (slot.terrain_count[g] == 0) continue;
        const std::uint32_t count = g == 0 ? terrain->index_count : terrain->quadrant_index_count;
        const std::uint32_t first_index = g == 0 ? 0 : (g - 1) * terrain->quadrant_index_count;
        vk.CmdDrawIndexed(cmd, count, slot.terrain_count[g], first_index, 0, slot.terrain_first[g]);
    }
    const VkDeviceSize offset = 0;
    if (!slot.float_draws.empty()) {
        vk.CmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines.draws.floats.get());
        const VkBuffer fb = slot.float_vertices.handle();
        vk.CmdBindVertexBuffers(cmd, 0, 1, &fb, &offset);
        for (const detail::FloatUpload::Draw& d : slot.float_draws) {
            const glm::vec4 mesh_origin(0.0f);  // positions are relative to O already
            const glm::vec4 paint(d.color, 1.0f);
            vk.CmdPushConstants(cmd, layout, VK_SHADER_STAGE_ALL_GRAPHICS, gpu::kPushMeshOrigin, sizeof(mesh_origin),
                                &mesh_origin);
            vk.CmdPushConstants(cmd, layout, VK_SHADER_STAGE_ALL_GRAPHICS, gpu::kPushFloatPaint, sizeof(paint), &paint);
            vk.CmdDraw(cmd, d.count, 1, d.first, 0);
        }
    }
    // The sky last: it only fills pixels nothing else covered (depth still at the far plane).
    vk.CmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines.draws.sky.get());
    vk.CmdDraw(cmd, 3, 1, 0, 0);
}

void Renderer::Impl::draw_water(VkCommandBuffer cmd, View& view, const Slot& slot, const detail::FramePlan& plan,
                                VkRect2D area, DebugView debug_view) {
    const detail::VulkanFunctions& vk = this->vk();
    detail::set_viewport(vk, cmd, area);
    vk.CmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines.layout.get(), 0, 1, &slot.set, 0, nullptr);
    vk.CmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS,
                       (debug_view == DebugView::wireframe ? pipelines.draws.water_wire : pipelines.draws.water).get());
    // One draw per body: the ocean, each lake, each river (water_draw.glsl).
    std::uint64_t patches = 0;
    for (std::uint32_t i = 0; i < plan.water_draws.size(); ++i) {
        if (plan.water_draws[i] == 0) continue;
        vk.CmdPushConstants(cmd, pipelines.layout.get(), VK_SHADER_STAGE_ALL_GRAPHICS, gpu::kPushDrawIndex, sizeof(i),
                            &i);
        vk.CmdDraw(cmd, 4, plan.water_draws[i], 0, 0);
        patches += plan.water_draws[i];
    }
    view.patches = patches;
}

Renderer::Renderer(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Renderer::~Renderer() = default;

namespace {

/// Multisampled targets: a count the device renders colour and depth at, and a depth
/// format without stencil (the depth resolve writes only the depth aspect).
Status check_samples(const detail::Device& c, VkSampleCountFlagBits samples, const detail::DepthTarget& depth) {
    if (samples == VK_SAMPLE_COUNT_1_BIT) return {};
    if (samples != VK_SAMPLE_COUNT_2_BIT && samples != VK_SAMPLE_COUNT_4_BIT && samples != VK_SAMPLE_COUNT_8_BIT)
        return Error{ErrorCode::invalid_argument,
                     fmt::format("renderer: sample count {} is not 1, 2, 4 or 8", static_cast<int>(samples))};
    VkPhysicalDeviceProperties p;
    c.vk().GetPhysicalDeviceProperties(c.physical_device, &p);
    const VkSampleCountFlags both = p.limits.framebufferColorSampleCounts & p.limits.framebufferDepthSampleCounts;
    if ((both & static_cast<VkSampleCountFlags>(samples)) == 0)
        return Error{ErrorCode::unsupported,
                     fmt::format("renderer: this device cannot render colour and depth at {} samples",
                                 static_cast<int>(samples))};
    if (depth.aspects != VK_IMAGE_ASPECT_DEPTH_BIT)
        return Error{ErrorCode::unsupported,
                     fmt::format("renderer: multisampling needs a depth format without stencil (D32 or D16), not {}",
                                 depth.name)};
    return {};
}

}  // namespace

Result<std::unique_ptr<Renderer>> Renderer::create(const RendererInitInfo& info) {
    if (!info.device.instance || !info.device.physical_device || !info.device.device || !info.device.queue)
        return Error{ErrorCode::invalid_argument,
                     "renderer: RendererInitInfo.device needs instance, physical device, device and queue"};
    if (info.frames_in_flight < 1 || info.frames_in_flight > 4)
        return Error{ErrorCode::invalid_argument,
                     fmt::format("renderer: frames_in_flight {} is out of range (1 to 4)", info.frames_in_flight)};
    if (info.gpu_memory_budget < (std::uint64_t{16} << 20))
        return Error{
            ErrorCode::invalid_argument,
            fmt::format("renderer: gpu_memory_budget {} bytes is under the 16 MiB minimum", info.gpu_memory_budget)};
    auto device = detail::load_device(info.device);
    if (!device) return device.error();
    const detail::Device& c = *device;
    const detail::ColorTarget* color_target = detail::find_color_target(info.color_format);
    if (!color_target)
        return Error{ErrorCode::unsupported,
                     fmt::format("renderer: colour format {} is not supported (accepted {})",
                                 detail::format_name(info.color_format), detail::accepted_formats())};
    const detail::DepthTarget* depth_target = detail::find_depth_target(info.depth_format);
    if (!depth_target)
        return Error{ErrorCode::unsupported,
                     fmt::format("renderer: depth format {} is not supported (accepted {})",
                                 detail::format_name(info.depth_format), detail::accepted_formats())};
    // The features the host says it enabled (DeviceContext), not merely what the device has.
    auto missing = [](const char* feature, const char* why) {
        return Error{ErrorCode::unsupported,
                     fmt::format("renderer: the device feature {} is not enabled ({}): enable it in "
                                 "vkCreateDevice and say so in DeviceContext",
                                 feature, why)};
    };
    if (!c.dynamic_rendering)
        return missing("dynamicRendering (VkPhysicalDeviceVulkan13Features)", "every pass uses it");
    if (!c.enabled_features.tessellationShader) return missing("tessellationShader", "the water's level of detail");
    if (info.wireframe && !c.enabled_features.fillModeNonSolid)
        return missing("fillModeNonSolid", "the wireframe view; or set RendererInitInfo::wireframe = false");
    auto check_format = [&](VkFormat f, VkFormatFeatureFlags need, const char* what) -> Status {
        VkFormatProperties p;
        c.vk().GetPhysicalDeviceFormatProperties(c.physical_device, f, &p);
        if ((p.optimalTilingFeatures & need) != need)
            return Error{ErrorCode::unsupported,
                         fmt::format("renderer: {} format {} lacks the needed features on this device", what,
                                     detail::format_name(f))};
        return {};
    };
    if (auto st = check_format(info.color_format,
                               VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT | VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT |
                                   VK_FORMAT_FEATURE_TRANSFER_DST_BIT,
                               "colour");
        !st)
        return st.error();
    if (auto st = check_format(info.depth_format,
                               VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT |
                                   VK_FORMAT_FEATURE_TRANSFER_DST_BIT,
                               "depth");
        !st)
        return st.error();
    if (auto st = check_format(VK_FORMAT_R32_SFLOAT, VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT,
                               "height texture (R32_SFLOAT)");
        !st)
        return st.error();
    if (auto st = check_samples(c, info.samples, *depth_target); !st) return st.error();
    auto quality = detail::drawn_quality(info, c);
    if (!quality) return quality.error();
    auto impl = std::make_unique<Impl>();
    impl->device = c;
    impl->info = info;
    impl->quality = *quality;
    auto pipelines = detail::FramePipelines::create(c, impl->draw_options());
    if (!pipelines) return pipelines.error();
    impl->pipelines = std::move(pipelines).value();
    VkCommandPoolCreateInfo cp{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    cp.queueFamilyIndex = c.queue_family;
    cp.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
    TW_VK_TRY(detail::make_owned(c, impl->upload_pool, [&](VkCommandPool* out) {
        return c.vk().CreateCommandPool(c.device, &cp, c.allocator, out);
    }));
    impl->color_target = color_target;
    impl->depth_target = depth_target;
    auto main_view = impl->make_view(std::nullopt);  // sized by resize()
    if (!main_view) return main_view.error();
    impl->views.emplace(kMainView.value, std::move(main_view).value());
    auto placeholders = detail::PlaceholderCopies::create(c, impl->upload_pool.get(), *color_target, *depth_target);
    if (!placeholders) return placeholders.error();
    impl->placeholders = std::move(placeholders).value();
    auto sky = detail::SkyTable::create(c, impl->upload_pool.get());
    if (!sky) return sky.error();
    impl->sky = std::move(sky).value();
    auto foam_noise = detail::make_foam_noise_table(c, impl->upload_pool.get());
    if (!foam_noise) return foam_noise.error();
    impl->foam_noise = std::move(foam_noise).value();
    return std::unique_ptr<Renderer>(new Renderer(std::move(impl)));
}

Status Renderer::set_scene(const Scene& scene) {
    Impl& m = *impl_;
    if (!scene.baked())
        return Error{ErrorCode::invalid_argument,
                     fmt::format("renderer: {} has a shore but is not baked, or was edited "
                                 "since its bake: pass it through bake_scene (or disable its shore) "
                                 "before set_scene",
                                 scene_label(scene))};
    std::size_t waves = scene.has_ocean ? scene.ocean.waves().size() : 0, river_waves = 0;
    for (const SceneLake& lake : scene.lakes) waves += lake.body.waves().size();
    for (const SceneRiver& river : scene.rivers) river_waves += river.body.waves().size();
    TW_VK_TRY(m.vk().DeviceWaitIdle(m.ctx().device));  // the old terrain may be in use by frames in flight
    auto bodies = detail::BodyBuffers::create(m.ctx(), scene);
    if (!bodies) return bodies.error();
    m.slot_draws = 1 + detail::kOceanRings + scene.lakes.size() + scene.rivers.size();
    m.slot_waves = waves;
    m.slot_river_waves = river_waves;
    for (auto& [id, view] : m.views)
        if (auto st = m.size_slots(*view); !st) return st;
    // A terrain edited from the one drawn (a brush stroke): its changed texels written in
    // place. Otherwise a new upload, whose height texture may take half the budget; the
    // shore fields and bodies the rest. A failure after the texture was written leaves no
    // terrain: the next set_scene uploads it whole.
    bool in_place = false;
    if (m.terrain) {
        auto updated = m.terrain->update(m.ctx(), m.upload_pool.get(), m.scene.terrain, scene.terrain);
        if (!updated) {
            m.terrain.reset();
            return updated.error();
        }
        in_place = *updated;
    }
    std::optional<detail::TerrainUpload> fresh;
    if (!in_place) {
        auto made =
            detail::TerrainUpload::create(m.ctx(), m.upload_pool.get(), scene.terrain, m.info.gpu_memory_budget / 2);
        if (!made) return made.error();
        fresh = std::move(made).value();
    }
    const detail::TerrainUpload& terrain = in_place ? *m.terrain : *fresh;
    if (auto st = m.use_shores(scene.has_ocean ? &scene.ocean : nullptr, scene.lakes, terrain.resident_bytes); !st) {
        if (in_place) m.terrain.reset();
        return st;
    }
    m.last_upload_bytes = terrain.written_bytes + m.shore_written;
    if (fresh) m.terrain = std::move(fresh);
    m.bodies = std::move(bodies).value();
    m.scene = scene;
    m.log(
        fmt::format("tidewater: scene \"{}\" uploaded: a {}x{} terrain height texture ({:.2f} m texels), {} waves, "
                    "{} lakes, {} rivers",
                    scene.name, m.terrain->heights.extent().width, m.terrain->heights.extent().height,
                    m.terrain->lod.finest_quad.x, scene.ocean.waves().size(), scene.lakes.size(), scene.rivers.size()));
    return {};
}

Status Renderer::resize(VkExtent2D extent, ViewId id) {
    Impl& m = *impl_;
    Impl::View* view = m.find_view(id);
    if (!view)
        return Error{ErrorCode::invalid_argument,
                     fmt::format("renderer: resize: view {} is not there (removed, or never added)", id.value)};
    if (view->copies && view->copies->extent().width == extent.width && view->copies->extent().height == extent.height)
        return {};
    auto copies = detail::SceneCopies::create(m.ctx(), *m.color_target, *m.depth_target, m.info.samples, extent);
    if (!copies) return copies.error();
    // No wait: frames in flight may still read the old copies, which go once they are done.
    if (view->copies) m.retired.push_back({{}, std::move(view->copies), nullptr, m.next_frame});
    view->copies = std::move(copies).value();
    m.log(fmt::format("tidewater: view {}'s refraction copies sized {}x{}", id.value, extent.width, extent.height));
    return {};
}

Result<ViewId> Renderer::add_view(VkExtent2D extent) {
    Impl& m = *impl_;
    auto view = m.make_view(extent);
    if (!view) return view.error();
    const ViewId id{m.next_view++};
    m.views.emplace(id.value, std::move(view).value());
    return id;
}

Status Renderer::remove_view(ViewId id) {
    Impl& m = *impl_;
    if (id == kMainView) return Error{ErrorCode::invalid_argument, "renderer: the main view cannot be removed"};
    const auto it = m.views.find(id.value);
    if (it == m.views.end())
        return Error{ErrorCode::invalid_argument,
                     fmt::format("renderer: remove_view: view {} is not there (removed, or never added)", id.value)};
    // No wait: its buffers and copies go once the frames in flight are done.
    m.retired.push_back({{}, std::nullopt, std::move(it->second), m.next_frame});
    m.views.erase(it);
    return {};
}

std::vector<ViewId> Renderer::views() const {
    std::vector<ViewId> ids;
    for (const auto& entry : impl_->views) ids.push_back(ViewId{entry.first});
    return ids;
}

Status Renderer::set_water(const WaterBody& water) {
    if (!impl_->terrain) return Error{ErrorCode::invalid_argument, "renderer: set_scene before set_water"};
    if (water.waves().size() > kMaxWaves) return Error{ErrorCode::invalid_argument, "renderer: too many waves"};
    const Scene& scene = impl_->scene;
    if (scene.has_ocean && water.level() != scene.water_level())
        return Error{
            ErrorCode::invalid_argument,
            fmt::format(
                "renderer: set_water: the body's level {} m is not the scene's water level {} m: change the level "
                "in the scene and bake it (bake_scene), then set_scene",
                water.level(), scene.water_level())};
    // The surf is never dropped silently: a body without a shore model over a scene whose
    // ocean feels its shore is refused, with the recipe.
    if (impl_->shore.placement(0).model && !water.shore())
        return Error{
            ErrorCode::invalid_argument,
            "renderer: set_water: the new water has no shore model, and the scene's ocean feels its shore: the surf "
            "would be lost. Put the water in a copy of the scene (scene.ocean = water), bake it with bake_scene "
            "(SceneBakeOptions::previous = the current scene re-bakes only the shore) and call set_scene; or give a "
            "body whose with_shore() model was baked for these waves"};
    // Wave data is written per frame into the in-flight slot; only a new shore model is uploaded.
    if (auto st = impl_->use_shores(&water, impl_->scene.lakes, impl_->terrain ? impl_->terrain->resident_bytes : 0);
        !st)
        return st;
    if (water.waves().size() > impl_->scene.ocean.waves().size()) {
        // The frame's wave buffers hold the ocean's waves first: make room.
        std::size_t waves = water.waves().size();
        for (const SceneLake& lake : impl_->scene.lakes) waves += lake.body.waves().size();
        TW_VK_TRY(impl_->vk().DeviceWaitIdle(impl_->ctx().device));
        impl_->slot_waves = waves;
        for (auto& [id, view] : impl_->views)
            if (auto st = impl_->size_slots(*view); !st) return st;
    }
    impl_->scene.ocean = water;
    return {};
}

Status Renderer::record_frame(VkCommandBuffer cmd, const FrameInfo& frame, const FrameTargets& targets) {
    const ViewFrame main{kMainView, frame, targets};
    return record_views(cmd, std::span<const ViewFrame>(&main, 1));
}

Status Renderer::record_views(VkCommandBuffer cmd, std::span<const ViewFrame> views) {
    Impl& m = *impl_;
    if (!cmd) return Error{ErrorCode::invalid_argument, "renderer: record_views needs a command buffer"};
    if (views.empty()) return Error{ErrorCode::invalid_argument, "renderer: record_views needs at least one view"};
    // Every view checked before any is written: a refusal records nothing.
    std::vector<glm::dvec2> cameras;
    for (std::size_t i = 0; i < views.size(); ++i) {
        const ViewFrame& v = views[i];
        if (auto st = m.validate_view_frame(v); !st) return st;
        const FrameInfo& first = views[0].frame;
        for (std::size_t j = 0; j < i; ++j)
            if (views[j].view == v.view)
                return Error{ErrorCode::invalid_argument,
                             fmt::format("renderer: record_views: view {} is given twice", v.view.value)};
        if (v.frame.frame_index != first.frame_index)
            return Error{ErrorCode::invalid_argument,
                         fmt::format("renderer: record_views: view {} has frame_index {}, the first view {}: one "
                                     "frame's views share its index",
                                     v.view.value, v.frame.frame_index, first.frame_index)};
        if (v.frame.sun_direction != first.sun_direction || v.frame.sky_turbidity != first.sky_turbidity)
            return Error{ErrorCode::invalid_argument,
                         fmt::format("renderer: record_views: view {} has another sun or turbidity than the first: "
                                     "one frame's views share the sky table (record them in frames of their own)",
                                     v.view.value)};
        cameras.emplace_back(v.frame.camera.position.x, v.frame.camera.position.z);
    }
    m.stream_shores(cameras, views[0].frame.frame_index);
    struct Prepared {
        Impl::View* view = nullptr;
        Impl::Slot* slot = nullptr;
        detail::FramePlan plan;
    };
    std::vector<Prepared> prepared(views.size());
    for (std::size_t i = 0; i < views.size(); ++i) {
        const ViewFrame& v = views[i];
        prepared[i].view = m.find_view(v.view);
        if (auto st = m.prepare_slot(*prepared[i].view, v.frame, v.targets.extent, v.targets.offset, true,
                                     prepared[i].slot, prepared[i].plan);
            !st)
            return st;
    }
    // One sky table for every view: a 256-texel square, cheaper redrawn than tracked across frames.
    m.sky.record(m.vk(), cmd, prepared[0].plan.frame.sky);
    for (std::size_t i = 0; i < views.size(); ++i)
        m.record_passes(cmd, *prepared[i].view, *prepared[i].slot, prepared[i].plan, views[i].frame, views[i].targets);
    return {};
}

Status Renderer::record_in_pass(VkCommandBuffer cmd, const FrameInfo& frame, VkExtent2D extent, ViewId id) {
    Impl& m = *impl_;
    if (!cmd) return Error{ErrorCode::invalid_argument, "renderer: record_in_pass needs a command buffer"};
    Impl::View* view = m.find_view(id);
    if (!view)
        return Error{ErrorCode::invalid_argument,
                     fmt::format("renderer: record_in_pass: view {} is not there (removed, or never added)", id.value)};
    // Refused before the frame takes its slot: nothing of it is written.
    if (auto st = m.validate_frame(frame, extent); !st) return st;
    if (!m.sky.holds(detail::gpu_sky(frame.sun_direction, frame.sky_turbidity)))
        return Error{ErrorCode::invalid_argument,
                     "renderer: the sky table holds another sun or turbidity than this frame's: call "
                     "record_sky(cmd, frame) before the pass begins"};
    const glm::dvec2 camera(frame.camera.position.x, frame.camera.position.z);
    m.stream_shores(std::span<const glm::dvec2>(&camera, 1), frame.frame_index);
    Impl::Slot* slot = nullptr;
    detail::FramePlan plan;
    if (auto st = m.prepare_slot(*view, frame, extent, VkOffset2D{}, false, slot, plan); !st) return st;
    const VkRect2D area{{0, 0}, extent};
    m.draw_opaque(cmd, *slot, area, frame.view);
    m.draw_water(cmd, *view, *slot, plan, area, frame.view);
    return {};
}

Status Renderer::record_sky(VkCommandBuffer cmd, const FrameInfo& frame) {
    Impl& m = *impl_;
    if (!cmd) return Error{ErrorCode::invalid_argument, "renderer: record_sky needs a command buffer"};
    if (auto st = validate_sky(frame); !st) return st;
    m.sky.record(m.vk(), cmd, detail::gpu_sky(frame.sun_direction, frame.sky_turbidity));
    return {};
}

Status Renderer::reload_shaders(const ShaderSpirv& spirv) {
    Impl& m = *impl_;
    for (const auto& [name, words] : spirv)
        if (words.empty() || words[0] != 0x07230203u)
            return Error{ErrorCode::invalid_argument, fmt::format("renderer: reload_shaders: {} is not SPIR-V", name)};
    const detail::ShaderLookup lookup = [&spirv](std::string_view name) -> std::span<const std::uint32_t> {
        const auto it = spirv.find(name);
        return it == spirv.end() ? std::span<const std::uint32_t>() : std::span<const std::uint32_t>(it->second);
    };
    auto draws = m.pipelines.make_draws(m.ctx(), m.draw_options(), lookup);
    if (!draws) return draws.error();  // the current pipelines keep drawing
    // No device-wide wait: the old pipelines live until the frames in flight are done.
    m.retired.push_back({std::move(m.pipelines.draws), std::nullopt, nullptr, m.next_frame});
    m.pipelines.draws = std::move(draws).value();
    return {};
}

Result<PassTimings> Renderer::timings(std::uint64_t frame_index, ViewId id) {
    Impl& m = *impl_;
    const Impl::View* view = m.find_view(id);
    if (!view)
        return Error{ErrorCode::not_found,
                     fmt::format("renderer: timings: view {} is not there (removed, or never added)", id.value)};
    const std::size_t s = frame_index % view->slots.size();
    if (view->timer.available() && view->slots[s].recorded_frame != frame_index)
        return Error{ErrorCode::not_found,
                     fmt::format("renderer: frame {} is not the last recorded in its slot", frame_index)};
    return view->timer.read(m.ctx(), static_cast<std::uint32_t>(s));
}

Result<std::vector<PipelineStageStatistics>> Renderer::pipeline_statistics() const {
    return detail::draw_pipeline_statistics(impl_->ctx(), impl_->pipelines.draws);
}

const QualitySettings& Renderer::quality() const {
    return impl_->quality;
}

RendererStats Renderer::stats(ViewId id) const {
    RendererStats s;
    s.terrain_bytes = impl_->terrain ? impl_->terrain->resident_bytes : 0;
    s.shore_bytes = impl_->shore.bytes();
    s.device_memory_bytes = impl_->vk().device_memory_bytes.load();
    s.shore_stride = static_cast<std::uint32_t>(impl_->shore.stride());
    s.shore_streamed_tiles = impl_->shore.streamed_tiles();
    s.shore_streamable_tiles = impl_->shore.streamable_tiles();
    s.shore_streamed_bytes = impl_->shore_streamed;
    s.shore_tiles_reading = impl_->shore.reading_tiles();
    s.scene_upload_bytes = impl_->last_upload_bytes;
    s.waves = static_cast<std::uint32_t>(impl_->scene.ocean.waves().size());
    if (const Impl::View* view = impl_->find_view(id)) {
        s.terrain_vertices = view->terrain_vertices;
        s.terrain_triangles = view->terrain_triangles;
        s.camera = view->camera;
        s.clip_volumes = view->clips;
        s.clip_volumes_left_out = view->clips_left_out;
        s.water_patches = view->patches;
    }
    return s;
}

}  // namespace tidewater::render
