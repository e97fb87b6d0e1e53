#include "points_csv.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string_view>

#include "tidewater/detail/json_reader.hpp"

namespace tidewater::cli {

namespace {

std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
    return s;
}

std::vector<std::string_view> split(std::string_view line) {
    std::vector<std::string_view> cells;
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = line.find(',', start);
        cells.push_back(
            trim(line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start)));
        if (comma == std::string_view::npos) break;
        start = comma + 1;
    }
    return cells;
}

}  // namespace

Result<std::vector<glm::dvec2>> parse_points_csv(const std::string& text, const std::string& source) {
    std::istringstream in(text);
    std::string line;
    std::size_t line_no = 0;
    int x_col = -1, z_col = -1;
    std::size_t columns = 0;
    std::vector<glm::dvec2> points;
    while (std::getline(in, line)) {
        ++line_no;
        const std::string_view view = trim(line);
        if (view.empty() || view.front() == '#') continue;
        const auto cells = split(view);
        if (columns == 0) {
            columns = cells.size();
            for (std::size_t i = 0; i < cells.size(); ++i) {
                if (cells[i] == "x") x_col = static_cast<int>(i);
                if (cells[i] == "z") z_col = static_cast<int>(i);
            }
            if (x_col < 0 || z_col < 0) {
                return Error{ErrorCode::parse_error,
                             fmt::format("{}: line {}: header must name columns \"x\" and \"z\" (found \"{}\")", source,
                                         line_no, view)};
            }
            continue;
        }
        if (cells.size() != columns) {
            return Error{ErrorCode::parse_error, fmt::format("{}: line {}: {} fields, the header has {}", source,
                                                             line_no, cells.size(), columns)};
        }
        glm::dvec2 p{0.0};
        for (const auto& [col, name, dest] : {std::tuple{x_col, "x", &p.x}, std::tuple{z_col, "z", &p.y}}) {
            const std::string_view cell = cells[static_cast<std::size_t>(col)];
            double v = 0.0;
            const auto res = std::from_chars(cell.data(), cell.data() + cell.size(), v);
            if (res.ec != std::errc() || res.ptr != cell.data() + cell.size() || !std::isfinite(v)) {
                return Error{ErrorCode::parse_error,
                             fmt::format("{}: line {}: column \"{}\": \"{}\" is not a finite number", source, line_no,
                                         name, cell)};
            }
            if (std::abs(v) > 1e7) {
                return Error{ErrorCode::parse_error,
                             fmt::format("{}: line {}: column \"{}\": {} is out of range (allowed: |{}| <= 1e7 m)",
                                         source, line_no, name, v, name)};
            }
            *dest = v;
        }
        points.push_back(p);
    }
    if (columns == 0)
        return Error{ErrorCode::parse_error, fmt::format("{}: empty file: expected a header \"x,z\"", source)};
    if (points.empty()) return Error{ErrorCode::parse_error, fmt::format("{}: no points after the header", source)};
    return points;
}

Result<std::vector<glm::dvec2>> read_points_csv(const std::string& path) {
    auto text = detail::read_text_file(path, detail::kMaxTextFileBytes);
    if (!text) return text.error();
    return parse_points_csv(*text, path);
}

}  // namespace tidewater::cli
