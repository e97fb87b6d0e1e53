// Wavefront OBJ meshes (a clip volume's "mesh" baked to a distance texture): any file
// gives a closed triangle mesh or an Error naming the file and line.
#include <cstddef>
#include <cstdint>

#include "fuzz_files.hpp"
#include "tidewater/clip_texture_bake.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace tidewater;
    (void)read_obj_mesh(fuzz::scratch_file("fuzz.obj", fuzz::as_text(data, size)));
    return 0;
}
