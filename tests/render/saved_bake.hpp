// The default island's bake saved to a folder and loaded back lazily: what the tests of
// streaming shore tiles from a bake folder start from.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <optional>
#include <string>

#include "../baked_scene.hpp"
#include "tidewater/detail/shore_waves.hpp"
#include "tidewater/tidewater.hpp"

namespace tidewater::test {

/// The default island baked, its bake saved in a temporary folder `dir` (the test removes
/// it), and the default scene naming that folder as its bake.
struct SavedDefaultBake {
    Scene baked, named;
    std::filesystem::path dir;
};
inline std::optional<SavedDefaultBake> save_default_bake(const std::string& name) {
    auto baked = test::baked(default_scene());
    auto named = default_scene();
    if (!baked.ok() || !named.ok()) {
        ADD_FAILURE() << "the default scene: " << (baked.ok() ? named.error() : baked.error()).message;
        return std::nullopt;
    }
    SavedDefaultBake saved{*baked, *named,
                           std::filesystem::temp_directory_path() / (name + "_" + std::to_string(::getpid()))};
    std::filesystem::remove_all(saved.dir);
    if (auto st = save_scene_bake(saved.dir, saved.baked); !st) {
        ADD_FAILURE() << st.error().message;
        return std::nullopt;
    }
    saved.named.shore.bake_folder = saved.dir;
    return saved;
}

/// Slots the model's saved-bake readers have read and keep in host memory.
inline std::size_t kept_slots(const ShoreWaves& model) {
    std::size_t kept = model.shared().lazy ? model.shared().lazy->read_count() : 0;
    for (const ShoreWaveLayer& l : model.layers()) kept += l.tiles.lazy ? l.tiles.lazy->read_count() : 0;
    return kept;
}

}  // namespace tidewater::test
