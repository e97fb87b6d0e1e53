// The editor's bake worker: a bake on a worker thread, with its progress, while the last
// good scene keeps drawing; the result is swapped in between frames.
#pragma once

#include <atomic>
#include <chrono>
#include <future>
#include <memory>
#include <mutex>
#include <optional>
#include <stop_token>
#include <string>
#include <string_view>
#include <tidewater/scene_bake.hpp>

namespace tidewater::editor {

/// A bake running on a worker thread while the last good scene keeps drawing.
struct BackgroundBake {
    std::future<Result<std::shared_ptr<const Scene>>> job;
    std::atomic<double> fraction{0.0};
    std::mutex lock;
    std::string stage;
    /// Whether the running job readies a scene opened from its saved bake for local edits
    /// (the same scene, baked keeping its marches) rather than bakes an edit.
    bool readying = false;
    std::stop_source stop;  ///< asks the running job to stop (its result is then an error)

    bool running() const { return job.valid(); }
    /// Bakes `edited`, what the editor made of `previous` (`readies`: the same scene). A
    /// saved bake the scene names describes it as it was loaded, not as edited: the edit is
    /// baked, not loaded. Not while running(): the job before would be waited for and its
    /// result dropped.
    void start(Scene edited, std::shared_ptr<const Scene> previous, bool readies = false) {
        edited.shore.bake_folder.clear();
        fraction = 0.0;
        readying = readies;
        stop = std::stop_source();
        job = std::async(std::launch::async,
                         [this, edited = std::move(edited), previous = std::move(previous), token = stop.get_token()] {
                             SceneBakeOptions o;
                             o.previous = previous;
                             o.cancel = token;
                             o.keep_marches = true;  // the next stroke on the seabed re-bakes where it reaches
                             o.progress = [this](std::string_view s, double f) {
                                 fraction = f;
                                 const std::lock_guard<std::mutex> g(lock);
                                 stage = std::string(s);
                             };
                             return bake_scene(edited, o);
                         });
    }
    /// The result once it is ready (the job is then over).
    std::optional<Result<std::shared_ptr<const Scene>>> ready() {
        if (!job.valid() || job.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return std::nullopt;
        return job.get();
    }
};

}  // namespace tidewater::editor
