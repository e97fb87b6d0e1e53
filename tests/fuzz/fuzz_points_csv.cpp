// Query points as CSV (`tidewater query --points`): a header naming x and z, then rows.
// Any text gives the points or an Error naming the file and line.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_files.hpp"
#include "points_csv.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    (void)tidewater::cli::parse_points_csv(std::string(tidewater::fuzz::as_text(data, size)), "fuzz.csv");
    return 0;
}
