#include "tidewater/detail/atomic_folder.hpp"

#include <fmt/format.h>

#include "tidewater/detail/atomic_sibling.hpp"

namespace tidewater::detail {

namespace fs = std::filesystem;

Status write_folder_atomically(const fs::path& dir, const std::function<Status(const fs::path&)>& fill) {
    if (dir.empty() || !dir.has_filename()) return Error{ErrorCode::invalid_argument, "give a folder name"};
    sweep_stale_siblings(dir);
    const fs::path temp = temporary_sibling(dir);
    std::error_code ec;
    fs::remove_all(temp, ec);
    fs::create_directories(temp, ec);
    if (ec) return Error{ErrorCode::io_error, fmt::format("{}: cannot create folder: {}", temp.string(), ec.message())};
    struct Cleanup {
        fs::path path;
        bool keep = false;
        ~Cleanup() {
            std::error_code ignored;
            if (!keep) fs::remove_all(path, ignored);
        }
    } cleanup{temp};
    if (auto st = fill(temp); !st) return st;
    // Swap the finished folder into place; an old one survives any failure.
    const fs::path old = replaced_sibling(dir);
    const bool had = fs::exists(dir, ec);
    if (had) fs::rename(dir, old, ec);
    if (!ec) fs::rename(temp, dir, ec);
    if (ec) {
        std::error_code ignored;
        if (had && !fs::exists(dir, ignored)) fs::rename(old, dir, ignored);
        return Error{ErrorCode::io_error, fmt::format("{}: cannot replace folder: {}", dir.string(), ec.message())};
    }
    cleanup.keep = true;
    if (had) fs::remove_all(old, ec);
    return {};
}

}  // namespace tidewater::detail
