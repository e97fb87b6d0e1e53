// What every elevation raster goes through: nodata filled, raw 16-bit files read,
// heights quantised into the heightmap Tidewater samples.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>

#include "tidewater/detail/elevation_raster.hpp"

namespace tidewater::detail {

std::size_t fill_invalid(int width, int height, std::vector<float>& values, const std::vector<std::uint8_t>& invalid,
                         bool& any_valid) {
    // A breadth-first flood from every valid pixel at once: each invalid pixel takes the
    // value of the valid pixel whose flood reaches it first.
    const std::size_t n = values.size();
    const auto invalid_count = static_cast<std::size_t>(std::count(invalid.begin(), invalid.end(), 1));
    any_valid = invalid_count < n;
    if (!any_valid || invalid_count == 0) return 0;
    std::vector<std::uint32_t> queue;
    queue.reserve(n);
    std::vector<std::uint8_t> done(n);
    for (std::size_t i = 0; i < n; ++i) {
        done[i] = invalid[i] ? 0 : 1;
        if (!invalid[i]) queue.push_back(static_cast<std::uint32_t>(i));
    }
    std::size_t filled = 0;
    for (std::size_t head = 0; head < queue.size(); ++head) {
        const std::uint32_t p = queue[head];
        const int i = static_cast<int>(p % static_cast<std::uint32_t>(width));
        const int j = static_cast<int>(p / static_cast<std::uint32_t>(width));
        const auto visit = [&](int ni, int nj) {
            if (ni < 0 || nj < 0 || ni >= width || nj >= height) return;
            const std::size_t q =
                static_cast<std::size_t>(nj) * static_cast<std::size_t>(width) + static_cast<std::size_t>(ni);
            if (done[q]) return;
            done[q] = 1;
            values[q] = values[p];
            ++filled;
            queue.push_back(static_cast<std::uint32_t>(q));
        };
        visit(i - 1, j);
        visit(i + 1, j);
        visit(i, j - 1);
        visit(i, j + 1);
    }
    return filled;
}

Result<Gray16Image> read_raw16(const std::filesystem::path& path, int width, int height, bool big_endian,
                               std::int64_t max_pixels) {
    const std::string name = path.string();
    if (width < 2 || height < 2 || static_cast<std::int64_t>(width) * height > max_pixels)
        return Error{ErrorCode::schema_error, fmt::format("{}: {}x{} pixels is out of range (2x2 to {} pixels)", name,
                                                          width, height, max_pixels)};
    std::error_code ec;
    const auto bytes = std::filesystem::file_size(path, ec);
    if (ec) return Error{ErrorCode::io_error, fmt::format("{}: cannot open file", name)};
    const std::uintmax_t expected = static_cast<std::uintmax_t>(width) * static_cast<std::uintmax_t>(height) * 2u;
    if (bytes != expected)
        return Error{ErrorCode::schema_error,
                     fmt::format("{}: {} bytes, but {}x{} 16-bit pixels take {}: check its width and height", name,
                                 bytes, width, height, expected)};
    std::ifstream in(path, std::ios::binary);
    if (!in) return Error{ErrorCode::io_error, fmt::format("{}: cannot open file", name)};
    Gray16Image img;
    img.width = width;
    img.height = height;
    img.pixels.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
    std::vector<unsigned char> row(static_cast<std::size_t>(width) * 2u);
    for (int j = 0; j < height; ++j) {
        if (!in.read(reinterpret_cast<char*>(row.data()), static_cast<std::streamsize>(row.size())))
            return Error{ErrorCode::io_error, fmt::format("{}: read failed at row {}", name, j)};
        std::uint16_t* out = img.pixels.data() + static_cast<std::size_t>(j) * static_cast<std::size_t>(width);
        for (int i = 0; i < width; ++i) {
            const unsigned lo = row[2 * static_cast<std::size_t>(i)], hi = row[2 * static_cast<std::size_t>(i) + 1];
            out[i] = static_cast<std::uint16_t>(big_endian ? (lo << 8) | hi : (hi << 8) | lo);
        }
    }
    return img;
}

HeightmapTerrain quantise_heightmap(const ElevationGrid& grid, std::string file, glm::dvec2 size, glm::dvec2 center) {
    const auto [lo_it, hi_it] = std::minmax_element(grid.heights.begin(), grid.heights.end());
    const double lo = static_cast<double>(*lo_it);
    // A flat raster still needs a range to map onto.
    const double hi = *hi_it > *lo_it ? static_cast<double>(*hi_it) : lo + 1.0;
    auto image = std::make_shared<Gray16Image>();
    image->width = grid.width;
    image->height = grid.height;
    image->pixels.resize(grid.heights.size());
    const double to_code = 65535.0 / (hi - lo);
    for (std::size_t i = 0; i < grid.heights.size(); ++i)
        image->pixels[i] =
            static_cast<std::uint16_t>(std::lround((static_cast<double>(grid.heights[i]) - lo) * to_code));
    HeightmapTerrain t;
    t.file = std::move(file);
    t.size = size;
    t.center = center;
    t.min_height = lo;
    t.max_height = hi;
    t.image = std::move(image);
    return t;
}

}  // namespace tidewater::detail
