// What loading and baking a scene share (internal): the error prefix of the scene's
// "shore" entry, and the last step, which puts the bake's models into a new scene.
#pragma once

#include <chrono>
#include <memory>

#include "tidewater/baked_scene.hpp"

namespace tidewater::detail {

/// `e` under the scene's "shore" entry.
Error in_shore(const Scene& scene, Error e);

/// A new scene: `scene` with the bake's lake and ocean shore models in its bodies,
/// `bake->terrain` as its terrain, and `bake` (its inputs and wall-clock time since
/// `start` recorded) attached.
Result<std::shared_ptr<const Scene>> finish_scene_bake(const Scene& scene, std::shared_ptr<SceneBake> bake,
                                                       std::chrono::steady_clock::time_point start);

}  // namespace tidewater::detail
