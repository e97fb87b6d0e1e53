// What the fuzz targets share: readers that take a path get the input as a file in this
// process's own scratch folder (made once, under the system's temporary folder), so that
// targets run side by side and under -fork without touching each other's files.
#pragma once

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <string_view>

namespace tidewater::fuzz {

/// This process's scratch folder, made on first use and removed when the process exits
/// (a crash leaves it, beside the input that caused it).
inline const std::filesystem::path& scratch_folder() {
    // The exit handler reads the name from a buffer that outlives every static.
    static char name[4096] = {};
    static const std::filesystem::path folder = [] {
        auto f = std::filesystem::temp_directory_path() / ("tidewater-fuzz-" + std::to_string(::getpid()));
        std::filesystem::create_directories(f);
        std::snprintf(name, sizeof name, "%s", f.c_str());
        std::atexit([] {
            std::error_code ignored;
            std::filesystem::remove_all(name, ignored);
        });
        return f;
    }();
    return folder;
}

/// Writes `bytes` to `name` in the scratch folder, replacing what was there; its path.
inline std::filesystem::path scratch_file(const std::string& name, std::string_view bytes) {
    const std::filesystem::path path = scratch_folder() / name;
    std::FILE* f = std::fopen(path.c_str(), "wb");
    if (f == nullptr) std::abort();  // the scratch folder itself is broken: not the input's fault
    if (!bytes.empty() && std::fwrite(bytes.data(), 1, bytes.size(), f) != bytes.size()) std::abort();
    std::fclose(f);
    return path;
}

inline std::string_view as_text(const std::uint8_t* data, std::size_t size) {
    return {reinterpret_cast<const char*>(data), size};
}

}  // namespace tidewater::fuzz
