// Saved bake folders (shore.json, bodies.json, the tiles of the shore model and the
// bodies' field images). The default scene is baked once, at a small resolution, and
// saved in the scratch folder; an input is "NAME\nBYTES": BYTES replace the folder's file
// NAME (or, where no file has that name, one picked by it) while the bake is loaded and
// every tile read, and the file is put back after. Any change gives the scene or an Error
// naming the file and field.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>
#include <vector>

#include "fuzz_files.hpp"
#include "tidewater/baked_scene.hpp"
#include "tidewater/scene_bake.hpp"

namespace {

namespace fs = std::filesystem;

struct SavedBake {
    tidewater::Scene scene;          ///< loads the folder
    std::vector<std::string> files;  ///< relative to the folder, sorted
    std::vector<std::string> bytes;  ///< as saved
    fs::path folder;
};

[[noreturn]] void fail(const std::string& what) {
    std::fprintf(stderr, "fuzz_bake_folder: %s\n", what.c_str());
    std::abort();
}

std::string read_bytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

SavedBake make_saved_bake() {
    auto scene = tidewater::default_scene();
    if (!scene) fail(scene.error().message);
    scene->shore.resolution = 64;
    auto baked = tidewater::bake_scene(*scene);
    if (!baked) fail(baked.error().message);
    SavedBake s;
    s.folder = tidewater::fuzz::scratch_folder() / "bake";
    if (auto st = tidewater::save_scene_bake(s.folder, **baked); !st) fail(st.error().message);
    for (const auto& e : fs::recursive_directory_iterator(s.folder))
        if (e.is_regular_file()) s.files.push_back(fs::relative(e.path(), s.folder).generic_string());
    std::sort(s.files.begin(), s.files.end());
    for (const std::string& f : s.files) s.bytes.push_back(read_bytes(s.folder / f));
    s.scene = *scene;
    s.scene.shore.bake_folder = s.folder;
    return s;
}

SavedBake& saved_bake() {
    static SavedBake s = make_saved_bake();
    return s;
}

void write_bytes(const fs::path& path, std::string_view bytes) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (!out) fail("cannot write " + path.string());
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    (void)saved_bake();
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    SavedBake& s = saved_bake();
    const std::string_view input = tidewater::fuzz::as_text(data, size);
    const std::size_t newline = input.find('\n');
    if (newline == std::string_view::npos) return 0;
    const std::string name(input.substr(0, newline));
    auto found = std::find(s.files.begin(), s.files.end(), name);
    const std::size_t file = found != s.files.end() ? static_cast<std::size_t>(found - s.files.begin())
                                                    : std::hash<std::string>{}(name) % s.files.size();
    write_bytes(s.folder / s.files[file], input.substr(newline + 1));
    if (auto loaded = tidewater::load_scene_bake(s.scene)) (void)tidewater::read_scene_bake_tiles(**loaded);
    write_bytes(s.folder / s.files[file], s.bytes[file]);
    return 0;
}
