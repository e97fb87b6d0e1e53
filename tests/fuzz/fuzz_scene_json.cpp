// Scenes and presets as JSON (parse_scene, parse_preset): the terrain, ocean, lakes,
// rivers, boats, floats and clip volumes they hold. Any text gives a Scene or an Error.
// Files a scene names are looked up in an empty folder: the heightmap and raster readers
// have their own targets.
#include <cstddef>
#include <cstdint>

#include "fuzz_files.hpp"
#include "tidewater/scene.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text = tidewater::fuzz::as_text(data, size);
    (void)tidewater::parse_scene(text, "fuzz.json", tidewater::fuzz::scratch_folder());
    (void)tidewater::parse_preset(text, "fuzz.json");
    return 0;
}
