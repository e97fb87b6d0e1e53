// Folders that appear whole or not at all (bakes, exports). Internal: not part of the API.
// Threading: reentrant. The temporary folder is named after the target and the process
// (atomic_sibling.hpp), and what killed writers left beside the target is swept first.
#pragma once

#include <filesystem>
#include <functional>

#include "tidewater/result.hpp"

namespace tidewater::detail {

/// Creates a temporary sibling of `dir`, lets `fill` write into it, and only when that
/// succeeds renames it onto `dir` (an existing `dir` is replaced, and survives any
/// failure). The temporary folder is removed on failure.
Status write_folder_atomically(const std::filesystem::path& dir,
                               const std::function<Status(const std::filesystem::path&)>& fill);

}  // namespace tidewater::detail
