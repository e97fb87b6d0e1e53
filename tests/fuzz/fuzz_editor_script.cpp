// The level editor's script (examples/level_editor/editor_script_parse.hpp), parsed
// without a window: any text gives its commands or an Error naming the file and line.
#include <cstddef>
#include <cstdint>

#include "editor_script_parse.hpp"
#include "fuzz_files.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    (void)tidewater::editor::parse_script(tidewater::fuzz::as_text(data, size), "fuzz.script");
    return 0;
}
