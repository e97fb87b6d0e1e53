// The editor's scene: loading it, swapping in what the bake worker made, the boats and
// floats riding it, and preset changes.
#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "editor.hpp"

namespace tidewater::editor {

Status Editor::load(const std::string& path) {
    auto parsed = path.empty() ? default_scene() : load_scene(path);
    if (!parsed) return parsed.error();
    // What the march keeps is kept: a stroke on the seabed then re-bakes where it reaches.
    SceneBakeOptions options;
    options.keep_marches = true;
    auto baked = bake_scene(*parsed, options);
    if (!baked) return baked.error();
    // A re-bake still running, and a stroke or body edit not yet baked, are edits of the
    // scene being closed: dropped, not made over the one opened.
    if (bake_.running()) {
        bake_.stop.request_stop();
        bake_.job.wait();
    }
    (void)bake_.ready();
    stroke_.reset();
    body_edit_.reset();
    scene_ = std::move(baked).value();
    floaters_.reset();
    refloat();
    scene_path_ = path;
    std::snprintf(path_field_, sizeof path_field_, "%s", path.c_str());
    breaking_index_ = static_cast<float>(scene_->shore.breaking_index);
    const auto presets = bundled_preset_names();
    const auto at = std::find(presets.begin(), presets.end(), scene_->ocean.profile().name);
    preset_ = at == presets.end() ? -1 : static_cast<int>(at - presets.begin());  // -1: the scene's own waves
    if (scene_->camera)
        camera_ = OrbitCamera::looking(scene_->camera->position, scene_->camera->target, scene_->camera->fov_y_deg);
    if (renderer_)
        if (auto st = renderer_->set_scene(*scene_); !st) return st;
    // A scene opened from its saved bake keeps no marches (its fields are the saved 16-bit
    // ones), so a stroke on its seabed would re-bake its shore in full: it is baked again
    // in the background keeping them, and the strokes wait for it, then re-bake where they
    // reach.
    if (ready_edits_ && scene_->bake && scene_->bake->loaded && scene_->bake->ocean_shore && scene_->shore.diffraction)
        bake_.start(*scene_, scene_, true);
    return {};
}

namespace {

/// What a re-bake did with the ocean's shore, for the status line.
std::string ocean_shore_summary(const SceneBake& bake) {
    if (!bake.ocean_shore) return "no ocean shore";
    if (bake.reused.ocean_shore) return "the ocean's shore reused";
    if (bake.reused.ocean_shore_land_edit) return "the ocean's shore kept but the ground under the edit";
    if (bake.reused.ocean_shore_water_edit) return "the ocean's shore re-baked where the edit reaches";
    return "the ocean's shore baked in full";
}

}  // namespace

void Editor::swap_in(Result<std::shared_ptr<const Scene>> baked) {
    const bool readied = bake_.readying;
    bake_.readying = false;
    if (!baked) {
        message_ = readied
                       ? fmt::format("strokes on the seabed will re-bake the shore in full: {}", baked.error().message)
                       : baked.error().message;
        return;
    }
    // Between frames: the renderer waits for the frames in flight and uploads.
    if (auto st = renderer_->set_scene(**baked); !st) {
        message_ = st.error().message;
        return;
    }
    scene_ = std::move(baked).value();
    ++rebakes_;
    if (rebakes_ == 1 || memory_log_) {
        const MemoryMark now = memory_now();
        if (rebakes_ == 1) after_first_rebake_ = now;
        if (memory_log_)
            std::printf("memory after re-bake %d: resident %.1f MiB, heap in use %.1f MiB, device %.1f MiB\n", rebakes_,
                        static_cast<double>(now.resident_bytes) / 1048576.0,
                        static_cast<double>(now.heap_bytes) / 1048576.0,
                        static_cast<double>(now.device_bytes) / 1048576.0);
    }
    refloat();
    const SceneBake& bake = *scene_->bake;
    message_ = readied ? fmt::format("ready for local edits: the shore baked again keeping its marches in {:.2f} s",
                                     bake.seconds)
                       : fmt::format("re-baked in {:.2f} s ({}; {} river(s) and {} lake shore(s) reused)", bake.seconds,
                                     ocean_shore_summary(bake), bake.reused.rivers, bake.reused.lake_shores);
}

// The scene's boats and floats: carried on over an edited scene with the same ones, set
// afloat again otherwise (a failure is shown, and they are not drawn).
void Editor::refloat() {
    if (scene_->boats.empty() && scene_->floats.empty()) {
        floaters_.reset();
        return;
    }
    if (floaters_ && floaters_->set_scene(scene_)) return;
    auto made = SceneFloaters::create(scene_, clock_.now());
    if (!made) {
        message_ = made.error().message;
        floaters_.reset();
        return;
    }
    floaters_ = std::move(made).value();
}

// Advances the boats and floats to the clock (set afloat again when the clock went back
// or jumped a minute ahead) and hands them to the frame.
void Editor::float_bodies(render::FrameInfo& info) {
    if (!floaters_) return;
    const double now = clock_.now();
    if (now < floaters_->time() - 1e-6 || now > floaters_->time() + 60.0) {
        floaters_.reset();
        refloat();
        if (!floaters_) return;
    }
    if (auto st = floaters_->advance_to(now); !st) {
        message_ = st.error().message;
        floaters_.reset();
        return;
    }
    float_draws_ = render::float_draws(*floaters_);
    info.floats = float_draws_;
}

void Editor::choose_preset(const std::string& name) {
    auto profile = load_preset(name);
    auto body =
        profile ? WaterBody::create(*profile, scene_->water_level(), "ocean") : Result<WaterBody>(profile.error());
    if (!body) {
        message_ = body.error().message;
        return;
    }
    // A preset change keeps the surf: the shore model is baked again in the background.
    Scene edited = *scene_;
    edited.ocean = std::move(body).value();
    bake_.start(std::move(edited), scene_);
}

// A clip sphere where the water is removed (FrameInfo::clip_volumes); the CPU's answer at
// its centre, with the same volumes, is reported.
void Editor::place_clip(glm::dvec3 at, double radius) {
    const ClipVolume sphere = ClipVolume::sphere(at, radius);
    if (auto st = validate(sphere, "clip volume"); !st) {
        message_ = st.error().message;
        return;
    }
    clip_volumes_.push_back(sphere);
    QueryOptions options;
    options.clip_volumes = clip_volumes_;
    const glm::dvec2 xz(at.x, at.z);
    WorldPoint water;
    const bool asked = query_world(*scene_, clock_.now(), std::span<const glm::dvec2>(&xz, 1),
                                   std::span<WorldPoint>(&water, 1), options)
                           .ok();
    message_ = fmt::format("clip volume {}: sphere at ({:.1f}, {:.1f}, {:.1f}) radius {:.1f} m; the surface there: {}",
                           clip_volumes_.size(), at.x, at.y, at.z, radius,
                           asked ? (water.surface.wet ? "wet 1" : "wet 0") : "not answered");
    std::printf("%s\n", message_.c_str());
}

}  // namespace tidewater::editor
