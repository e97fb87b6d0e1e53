// What the fuzz targets share: readers that take a path get the input as a file in this
// process's own scratch folder (made once, under the system's temporary folder), so that
// targets run side by side and under -fork without touching each other's files.
#pragma once

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>
#include <string_view>

namespace tidewater::fuzz {

/// This process's scratch folder, made on first use.
inline const std::filesystem::path& scratch_folder() {
    static const std::filesystem::path folder = [] {
        auto f = std::filesystem::temp_directory_path() / ("tidewater-fuzz-" + std::to_string(::getpid()));
        std::filesystem::create_directories(f);
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
