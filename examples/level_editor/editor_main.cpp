// tidewater-editor: a level-editor host of Tidewater on GLFW and Dear ImGui. The editor
// owns the instance, device and swapchain; Tidewater records each frame into the
// swapchain image, and ImGui draws its panels over it.
//
//   tidewater-editor [--scene S] [--size WxH] [--frames N --screenshot out.png]
//                    [--probe X,Y] [--script FILE] [--resize-at N] [--shader-dir DIR] [--no-validation]
//                    [--memory-log] [--keep-saved-bake]
//
// Panels: scene (open, save, errors), water (the ocean's preset, re-baked in the
// background), shore (breaking index, re-baked with progress), terrain (a brush), rivers
// and lakes (discharge, width, level; path points dragged in the viewport), time
// (pause, scale, scrub), view (debug views, two viewports side by side, GPU pass timings)
// and the probe.
// Viewport: right drag orbits, middle drag pans, the wheel zooms; a left click on the
// water drops a marker that bobs and tilts with hull_attitude.
// Hot reload (--shader-dir DIR, a copy of shaders/): a saved shader is compiled with
// the glslang library and swapped in without a device-wide wait; a failed compile shows
// its error (FILE:LINE) and the last good pipelines keep drawing. Each reload prints
// "shader reload: ok (N ms)" or "shader reload: FILE:LINE: message" on stderr.
// Scripted mode (--frames) draws N frames, writes the last one with its panels to
// --screenshot, prints the probe at pixel --probe, and exits (non-zero on any error or
// validation message). After a script's re-bakes it prints the memory after the first and
// at the end; --memory-log prints it after every re-bake (resident, heap in use, device).
// A scene opened from its saved bake is baked again in the background keeping its marches,
// so that its first seabed stroke re-bakes where it reaches; --keep-saved-bake leaves it
// as loaded (that stroke then re-bakes the shore in full) for a world whose second bake
// would not fit in memory.
#include <fmt/format.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_vulkan.h>
#include <malloc.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <vector>

#include "editor.hpp"

namespace tidewater::editor {

Status Editor::start(const Options& options) {
    if (auto st = window_.create(options.width, options.height, options.validation); !st) return st;
    render::RendererInitInfo init;
    init.device = window_.context();
    init.color_format = window_.color_format();
    init.depth_format = EditorWindow::kDepthFormat;
    init.frames_in_flight = EditorWindow::kFramesInFlight;
    init.wireframe = init.device.enabled_features.fillModeNonSolid;
    auto renderer = render::Renderer::create(init);
    if (!renderer) return renderer.error();
    renderer_ = std::move(renderer).value();
    ready_edits_ = options.ready_edits;
    if (auto st = load(options.scene); !st) return st;
    if (auto st = lay_out_views(window_.extent()); !st) return st;
    if (!options.shader_dir.empty()) {
        if (!std::filesystem::is_directory(options.shader_dir))
            return Error{ErrorCode::io_error, fmt::format("editor: --shader-dir {}: not a folder", options.shader_dir)};
        shader_dir_ = options.shader_dir;
        shaders_ = std::make_unique<ShaderReload>(options.shader_dir);
        shaders_->changed();  // the first look records the files
    }

    // Dear ImGui over the same device, in the editor's own render pass.
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;
    ImGui::StyleColorsDark();
    ImGui_ImplGlfw_InitForVulkan(window_.window(), true);
    const VkDescriptorPoolSize sizes[] = {{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 16}};
    VkDescriptorPoolCreateInfo pool{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    pool.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
    pool.maxSets = 16;
    pool.poolSizeCount = 1;
    pool.pPoolSizes = sizes;
    const render::DeviceContext ctx = window_.context();
    if (vkCreateDescriptorPool(ctx.device, &pool, nullptr, &imgui_pool_) != VK_SUCCESS)
        return Error{ErrorCode::device_error, "editor: cannot create ImGui's descriptor pool"};
    ImGui_ImplVulkan_InitInfo info{};
    info.Instance = ctx.instance;
    info.PhysicalDevice = ctx.physical_device;
    info.Device = ctx.device;
    info.QueueFamily = ctx.queue_family;
    info.Queue = ctx.queue;
    info.DescriptorPool = imgui_pool_;
    info.MinImageCount = 2;
    info.ImageCount = std::max(2u, window_.image_count());
    info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
    if (!ImGui_ImplVulkan_Init(&info, window_.ui_pass()))
        return Error{ErrorCode::device_error, "editor: ImGui's Vulkan backend failed"};
    // The font texture, uploaded once through a one-off command buffer.
    VkCommandPool upload_pool = VK_NULL_HANDLE;
    VkCommandPoolCreateInfo cp{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    cp.queueFamilyIndex = ctx.queue_family;
    vkCreateCommandPool(ctx.device, &cp, nullptr, &upload_pool);
    VkCommandBufferAllocateInfo ai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    ai.commandPool = upload_pool;
    ai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    ai.commandBufferCount = 1;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    vkAllocateCommandBuffers(ctx.device, &ai, &cmd);
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    vkBeginCommandBuffer(cmd, &begin);
    ImGui_ImplVulkan_CreateFontsTexture(cmd);
    vkEndCommandBuffer(cmd);
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &cmd;
    vkQueueSubmit(ctx.queue, 1, &submit, VK_NULL_HANDLE);
    vkQueueWaitIdle(ctx.queue);
    ImGui_ImplVulkan_DestroyFontUploadObjects();
    vkDestroyCommandPool(ctx.device, upload_pool, nullptr);
    return {};
}

// What the soak watches: the process's resident set (/proc/self/statm), the bytes the
// heap has handed out and not had back (glibc's mallinfo2: what a leak grows, whatever
// the fragmentation), and the device memory the renderer holds. The heap's free pages go
// back to the system first (glibc keeps them otherwise), so that the resident figure is
// what the process still uses.
Editor::MemoryMark Editor::memory_now() const {
    MemoryMark mark;
#ifdef __GLIBC__
    malloc_trim(0);
#endif
    std::uint64_t pages = 0, resident = 0;
    if (std::FILE* statm = std::fopen("/proc/self/statm", "r")) {
        if (std::fscanf(statm, "%lu %lu", &pages, &resident) == 2)
            mark.resident_bytes = resident * static_cast<std::uint64_t>(sysconf(_SC_PAGESIZE));
        std::fclose(statm);
    }
    mark.device_bytes = renderer_->stats().device_memory_bytes;
#ifdef __GLIBC__
    const struct mallinfo2 heap = mallinfo2();
    mark.heap_bytes = heap.uordblks + heap.hblkhd;
#endif
    return mark;
}

int Editor::run(const Options& options) {
    if (auto st = start(options); !st) {
        std::fprintf(stderr, "tidewater-editor: %s\n", st.error().message.c_str());
        return 1;
    }
    if (!options.script.empty())
        if (auto st = run_script(options.script); !st) {
            std::fprintf(stderr, "tidewater-editor: %s\n", st.error().message.c_str());
            return 1;
        }
    if (options.probe) script_probe_ = options.probe;
    memory_log_ = options.memory_log;
    bool ok = true;
    auto last = std::chrono::steady_clock::now();
    double frame_seconds = 0.0;
    long timed_frames = 0;
    for (long i = 0; !glfwWindowShouldClose(window_.window()) && (options.frames < 0 || i < options.frames); ++i) {
        glfwPollEvents();
        if (i == options.resize_at) glfwSetWindowSize(window_.window(), options.width * 3 / 4, options.height * 3 / 4);
        // In scripted mode a re-bake completes before the frames go on (the picture is of it).
        if (options.frames >= 0 && bake_.running()) bake_.job.wait();
        if (auto done = bake_.ready()) swap_in(std::move(*done));
        const auto frame_start = std::chrono::steady_clock::now();
        std::string step_screenshot;
        for (const ScriptLine& line : scheduled_)
            if (line.frame == i) {
                if (auto st = run_command(line, step_screenshot); !st) {
                    std::fprintf(stderr, "tidewater-editor: %s\n", st.error().message.c_str());
                    ok = false;
                }
            }
        if (shaders_ && (shaders_->changed() || force_reload_)) {
            // A saved shader: compiled and swapped in before this frame records.
            force_reload_ = false;
            shader_line_ = shaders_->reload(*renderer_);
            std::fprintf(stderr, "%s\n", shader_line_.c_str());
        }
        const auto now = std::chrono::steady_clock::now();
        clock_.advance(options.frames < 0 ? std::chrono::duration<double>(now - last).count() : 1.0 / 60.0);
        last = now;
        EditorWindow::Frame frame;
        auto begun = window_.begin_frame(frame, [&](VkExtent2D extent) { return lay_out_views(extent); });
        if (!begun) {
            std::fprintf(stderr, "tidewater-editor: %s\n", begun.error().message.c_str());
            ok = false;
            break;
        }
        if (!*begun) continue;  // the swapchain was rebuilt
        // The slot's previous frame has finished (begin_frame waited for it): its GPU times.
        if (frame.index >= EditorWindow::kFramesInFlight) {
            if (auto t = renderer_->timings(frame.index - EditorWindow::kFramesInFlight); t) timings_ = *t;
            if (second_view_)
                if (auto t = renderer_->timings(frame.index - EditorWindow::kFramesInFlight, *second_view_); t)
                    second_timings_ = *t;
        }
        ImGui_ImplVulkan_NewFrame();
        ImGui_ImplGlfw_NewFrame();
        ImGui::NewFrame();
        viewport_input();
        if (script_probe_) {
            const VkExtent2D e = viewport_rect(0, window_.extent()).extent;
            probe_ = probe_ray(*scene_, clock_.now(), camera_.position(),
                               camera_.ray(script_probe_->x, script_probe_->y, e.width, e.height));
        }
        panels();
        drag_points();
        draw_markers();
        ImGui::Render();
        render::FrameInfo info;
        info.camera = camera_.camera();
        info.time = clock_.now();
        info.frame_index = frame.index;
        info.view = render::all_debug_views()[static_cast<std::size_t>(view_)];
        float_bodies(info);
        info.clip_volumes = clip_volumes_;
        // The panels may have turned the second viewport on or off: the views follow first.
        if (auto st = lay_out_views(window_.extent()); !st) {
            std::fprintf(stderr, "tidewater-editor: %s\n", st.error().message.c_str());
            ok = false;
        }
        std::vector<render::ViewFrame> views;
        for (int which = 0; which < (second_view_ ? 2 : 1); ++which) {
            const VkRect2D rect = viewport_rect(which, window_.extent());
            render::ViewFrame v{
                which == 0 ? render::kMainView : *second_view_, info,
                render::FrameTargets{frame.color, frame.color_view, frame.depth, frame.depth_view, rect.extent}};
            v.targets.offset = rect.offset;
            if (which == 1) v.frame.camera = second_camera_.camera();
            views.push_back(v);
        }
        if (auto st = renderer_->record_views(frame.cmd, views); !st) {
            std::fprintf(stderr, "tidewater-editor: %s\n", st.error().message.c_str());
            ok = false;
        }
        VkRenderPassBeginInfo rp{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
        rp.renderPass = window_.ui_pass();
        rp.framebuffer = frame.framebuffer;
        rp.renderArea = {{0, 0}, window_.extent()};
        vkCmdBeginRenderPass(frame.cmd, &rp, VK_SUBPASS_CONTENTS_INLINE);
        ImGui_ImplVulkan_RenderDrawData(ImGui::GetDrawData(), frame.cmd);
        vkCmdEndRenderPass(frame.cmd);
        const bool last_frame = options.frames > 0 && i + 1 == options.frames;
        if (last_frame && !options.screenshot.empty()) step_screenshot = options.screenshot;
        if (auto st = window_.end_frame(frame, step_screenshot); !st) {
            std::fprintf(stderr, "tidewater-editor: %s\n", st.error().message.c_str());
            ok = false;
        }
        if (!step_screenshot.empty()) std::printf("wrote %s\n", step_screenshot.c_str());
        if (i >= 2 && !last_frame) {  // past the first frames' pipeline warm-up
            frame_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - frame_start).count();
            ++timed_frames;
        }
    }
    if (timed_frames > 0)
        std::printf("frame time: %.1f ms mean over %ld frames\n",
                    1000.0 * frame_seconds / static_cast<double>(timed_frames), timed_frames);
    if (scripted_brush_)
        std::printf("terrain at the brush (%.1f, %.1f): %.3f m, was %.3f m\n", scripted_brush_->first.x,
                    scripted_brush_->first.y, scene_->terrain.height_at(scripted_brush_->first),
                    scripted_brush_->second);
    std::printf("window %ux%u, ocean \"%s\" with%s a shore model\n", window_.extent().width, window_.extent().height,
                scene_->ocean.profile().name.c_str(), scene_->ocean.shore() ? "" : "out");
    if (second_view_) {
        const VkRect2D left = viewport_rect(0, window_.extent()), right = viewport_rect(1, window_.extent());
        std::printf("viewports: left %ux%u, right %ux%u at x %d\n", left.extent.width, left.extent.height,
                    right.extent.width, right.extent.height, right.offset.x);
    }
    if (!message_.empty()) std::printf("%s\n", message_.c_str());
    if (script_probe_ && probe_) {
        const SurfacePoint direct =
            query_world_point(*scene_, clock_.now(), {probe_->point.x, probe_->point.z}).surface;
        std::printf("probe: (%.3f, %.3f) height %.6f m, query_surface %.6f m, body \"%s\"%s\n", probe_->point.x,
                    probe_->point.z, probe_->point.y, direct.height,
                    std::string(body_name(*scene_, probe_->water.body)).c_str(), probe_->on_land ? " (land)" : "");
        std::printf("terrain at the probe: %.3f m\n", scene_->terrain.height_at({probe_->point.x, probe_->point.z}));
        std::printf("gpu: terrain %.3f ms, copy %.3f ms, water %.3f ms, total %.3f ms\n", timings_.sky_and_terrain_ms,
                    timings_.scene_copy_ms, timings_.water_ms, timings_.total_ms);
    }
    if (after_first_rebake_) {
        const MemoryMark end = memory_now(), first = *after_first_rebake_;
        const auto mib = [](std::uint64_t bytes) { return static_cast<double>(bytes) / 1048576.0; };
        std::printf(
            "memory after the first of %d re-bakes: resident %.1f MiB, heap in use %.1f MiB, renderer's device memory "
            "%.1f MiB; at the end: %.1f MiB, %.1f MiB, %.1f MiB\n",
            rebakes_, mib(first.resident_bytes), mib(first.heap_bytes), mib(first.device_bytes),
            mib(end.resident_bytes), mib(end.heap_bytes), mib(end.device_bytes));
    }
    if (bake_.running()) {
        bake_.stop.request_stop();  // closing: what it would make is dropped
        bake_.job.wait();
    }
    vkDeviceWaitIdle(window_.context().device);
    ImGui_ImplVulkan_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    vkDestroyDescriptorPool(window_.context().device, imgui_pool_, nullptr);
    renderer_.reset();
    const int messages = window_.validation_messages();
    window_.destroy();
    if (messages > 0) {
        std::fprintf(stderr, "tidewater-editor: %d validation message(s)\n", messages);
        ok = false;
    }
    return ok ? 0 : 1;
}

}  // namespace tidewater::editor

int main(int argc, char** argv) {
#ifdef __GLIBC__
    // Every re-bake allocates and frees fields of megabytes on worker threads. glibc
    // raises its mmap threshold to the largest block freed, after which such blocks come
    // from the threads' arenas and leave fragments resident, re-bake after re-bake (the
    // soak in docs/PERFORMANCE.md). A fixed threshold keeps them mapped, and unmapped
    // whole when freed.
    mallopt(M_MMAP_THRESHOLD, 256 * 1024);
#endif
    const auto options = tidewater::editor::parse(argc, argv);
    if (!options) {
        std::fprintf(stderr,
                     "usage: tidewater-editor [--scene S] [--size WxH] [--frames N --screenshot out.png] [--probe X,Y] "
                     "[--script FILE] [--resize-at N] [--shader-dir DIR] [--no-validation] [--memory-log] "
                     "[--keep-saved-bake]\n");
        return 2;
    }
    tidewater::editor::Editor editor;
    return editor.run(*options);
}
