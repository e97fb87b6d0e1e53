// Writing saved lakes and rivers (internal to Tidewater::bake): the `bodies.json` sidecar,
// their 16-bit PNG fields and each lake's shore model in `lake_NN/`, loaded by
// bodies_bake_folder.hpp. Threading: reentrant.
#pragma once

#include <filesystem>

#include "tidewater/detail/bodies_bake_folder.hpp"
#include "tidewater/scene.hpp"

namespace tidewater {

/// Writes the baked scene's lakes and rivers and their lakes' shore models into the
/// existing folder `dir` (the caller writes the folder atomically).
Status write_bodies_bake_into(const std::filesystem::path& dir, const Scene& baked);

}  // namespace tidewater
