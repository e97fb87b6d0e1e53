#include "tiled_bake_files.hpp"

#include <fmt/format.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "atomic_file.hpp"
#include "tidewater/detail/json_reader.hpp"

namespace tidewater::cli::tiled_files {

namespace {

namespace fs = std::filesystem;

static_assert(std::endian::native == std::endian::little, "the tiled bake's files are little-endian");

constexpr std::uint32_t kVersion = 1;
constexpr char kContourMagic[4] = {'T', 'W', 'C', 'C'};
constexpr char kShorelineMagic[4] = {'T', 'W', 'S', 'L'};
constexpr char kDistancesMagic[4] = {'T', 'W', 'T', 'D'};
/// The most a stitched shoreline may hold (bake_shore refuses more segments than this).
constexpr std::uint64_t kMaxShorelinePoints = 8'000'000;

/// Bytes appended in the machine's (little-endian) layout.
class Writer {
  public:
    template <typename T>
    void put(const T& v) {
        const auto* p = reinterpret_cast<const char*>(&v);
        bytes_.insert(bytes_.end(), p, p + sizeof(T));
    }
    void magic(const char (&m)[4]) { bytes_.insert(bytes_.end(), m, m + 4); }
    template <typename T>
    void array(const std::vector<T>& v) {
        const auto* p = reinterpret_cast<const char*>(v.data());
        bytes_.insert(bytes_.end(), p, p + v.size() * sizeof(T));
    }
    Status save(const fs::path& path) const {
        AtomicFile out(path);
        if (!out.status()) return out.status();
        return out.write_and_commit(std::string_view(bytes_.data(), bytes_.size()));
    }

  private:
    std::vector<char> bytes_;
};

/// Reads what Writer wrote, failing (naming the file) instead of reading past the end.
class Reader {
  public:
    static Result<Reader> open(const fs::path& path, std::uintmax_t max_bytes) {
        if (auto st = detail::check_file_size(path, max_bytes, "a tiled bake's file"); !st) return st.error();
        std::ifstream in(path, std::ios::binary);
        if (!in) return Error{ErrorCode::io_error, fmt::format("{}: cannot open it", path.string())};
        Reader r(path);
        r.bytes_.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
        return r;
    }
    template <typename T>
    Status get(T& v) {
        if (bytes_.size() - at_ < sizeof(T)) return truncated();
        std::memcpy(&v, bytes_.data() + at_, sizeof(T));
        at_ += sizeof(T);
        return {};
    }
    template <typename T>
    Status array(std::vector<T>& v, std::uint64_t count) {
        if (count > (bytes_.size() - at_) / sizeof(T)) return truncated();
        v.resize(count);
        if (count > 0) std::memcpy(v.data(), bytes_.data() + at_, count * sizeof(T));
        at_ += count * sizeof(T);
        return {};
    }
    /// The magic word, the version and the tile.
    Status header(const char (&magic)[4], int tile) {
        char m[4];
        std::uint32_t version = 0;
        std::int32_t t = 0;
        if (auto st = get(m); !st) return st;
        if (std::memcmp(m, magic, 4) != 0) return error("not a tiled bake's file of this kind");
        if (auto st = get(version); !st) return st;
        if (version != kVersion) return error(fmt::format("version {}, this tidewater reads {}", version, kVersion));
        if (auto st = get(t); !st) return st;
        if (t != tile) return error(fmt::format("it holds tile {}, not tile {}", t, tile));
        return {};
    }
    Status end() const { return at_ == bytes_.size() ? Status{} : error("it goes on past its end"); }
    Error error(const std::string& why) const {
        return Error{ErrorCode::parse_error, fmt::format("{}: {}", path_.string(), why)};
    }

  private:
    explicit Reader(fs::path path) : path_(std::move(path)) {}
    Error truncated() const { return error("it is truncated"); }
    fs::path path_;
    std::vector<char> bytes_;
    std::size_t at_ = 0;
};

/// A record of one contour cell as written.
struct CellRecord {
    std::int32_t i, j, from_edge, to_edge;
    double fx, fz, tx, tz;
};

std::uintmax_t cells_in_tile(const tiled::ShoreTiling& tiling) {
    return static_cast<std::uintmax_t>(tiling.block()) * static_cast<std::uintmax_t>(tiling.block());
}

}  // namespace

Status write_contour(const fs::path& path, const tiled::TileContour& contour) {
    Writer w;
    w.magic(kContourMagic);
    w.put(kVersion);
    w.put(static_cast<std::int32_t>(contour.tile));
    w.put(static_cast<std::uint64_t>(contour.mixed_cells));
    w.put(static_cast<std::uint64_t>(contour.cells.size()));
    for (const detail::ContourCell& c : contour.cells)
        w.put(CellRecord{c.i, c.j, c.from_edge, c.to_edge, c.from.x, c.from.y, c.to.x, c.to.y});
    return w.save(path);
}

Result<tiled::TileContour> read_contour(const fs::path& path, const tiled::ShoreTiling& tiling, int tile) {
    // At most two pieces a cell.
    auto r = Reader::open(path, 64 + 2 * cells_in_tile(tiling) * sizeof(CellRecord));
    if (!r) return r.error();
    if (auto st = r->header(kContourMagic, tile); !st) return st.error();
    tiled::TileContour contour;
    contour.tile = tile;
    std::uint64_t mixed = 0, count = 0;
    if (auto st = r->get(mixed); !st) return st.error();
    if (auto st = r->get(count); !st) return st.error();
    std::vector<CellRecord> records;
    if (auto st = r->array(records, count); !st) return st.error();
    if (auto st = r->end(); !st) return st.error();
    contour.mixed_cells = mixed;
    contour.cells.reserve(records.size());
    for (const CellRecord& c : records)
        contour.cells.push_back({c.i, c.j, c.from_edge, c.to_edge, {c.fx, c.fz}, {c.tx, c.tz}});
    if (auto st = tiled::check_tile_contour(tiling, contour); !st) return r->error(st.error().message);
    return contour;
}

Status write_shoreline(const fs::path& path, const ShoreField& stitched) {
    Writer w;
    w.magic(kShorelineMagic);
    w.put(kVersion);
    w.put(std::int32_t{-1});  // every tile's
    w.put(static_cast<std::int32_t>(stitched.resolution));
    w.put(stitched.simplify_tolerance);
    w.put(static_cast<std::uint64_t>(stitched.polygons));
    w.put(static_cast<std::uint64_t>(stitched.holes));
    w.put(static_cast<std::uint64_t>(stitched.segment_count));
    w.put(static_cast<std::uint64_t>(stitched.shorelines.size()));
    for (const ShoreLine& line : stitched.shorelines) {
        w.put(static_cast<std::uint8_t>(line.closed ? 1 : 0));
        w.put(static_cast<std::uint64_t>(line.points.size()));
        for (const glm::dvec2& p : line.points) w.put(p);
    }
    return w.save(path);
}

Result<ShoreField> read_shoreline(const fs::path& path, const tiled::ShoreTiling& tiling) {
    auto r = Reader::open(path, 64 + kMaxShorelinePoints * (sizeof(glm::dvec2) + 9));
    if (!r) return r.error();
    if (auto st = r->header(kShorelineMagic, -1); !st) return st.error();
    std::int32_t resolution = 0;
    if (auto st = r->get(resolution); !st) return st.error();
    if (resolution != tiling.resolution)
        return r->error(fmt::format("stitched over {} texels, not {}", resolution, tiling.resolution));
    ShoreField field = tiling.grid();
    std::uint64_t polygons = 0, holes = 0, segments = 0, lines = 0, points = 0;
    if (auto st = r->get(field.simplify_tolerance); !st) return st.error();
    if (!(field.simplify_tolerance > 0.0) || !std::isfinite(field.simplify_tolerance))
        return r->error("its simplification tolerance is not a finite length > 0");
    if (auto st = r->get(polygons); !st) return st.error();
    if (auto st = r->get(holes); !st) return st.error();
    if (auto st = r->get(segments); !st) return st.error();
    if (auto st = r->get(lines); !st) return st.error();
    field.polygons = polygons;
    field.holes = holes;
    // A line takes at least 9 bytes: the count bounds the loop.
    if (lines > kMaxShorelinePoints) return r->error(fmt::format("{} lines", lines));
    const double half = 0.5 * tiling.texel * tiling.resolution;
    const glm::dvec2 centre = tiling.corner + glm::dvec2(half);
    for (std::uint64_t l = 0; l < lines; ++l) {
        ShoreLine line;
        std::uint8_t closed = 0;
        std::uint64_t count = 0;
        if (auto st = r->get(closed); !st) return st.error();
        if (auto st = r->get(count); !st) return st.error();
        points += count;
        if (closed > 1 || count < 2 || points > kMaxShorelinePoints)
            return r->error(fmt::format("line {} is not a shoreline ({} points)", l, count));
        line.closed = closed == 1;
        if (auto st = r->array(line.points, count); !st) return st.error();
        for (const glm::dvec2& p : line.points)
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || std::abs(p.x - centre.x) > half ||
                std::abs(p.y - centre.y) > half)
                return r->error(fmt::format("line {} leaves the grid", l));
        field.shorelines.push_back(std::move(line));
    }
    if (auto st = r->end(); !st) return st.error();
    // The distance tree's count (a line's degenerate segments are not in it): at most the lines' own.
    if (segments > points) return r->error(fmt::format("{} segments in {} points", segments, points));
    field.segment_count = segments;
    return field;
}

Status write_distances(const fs::path& path, const tiled::TileDistances& tile) {
    Writer w;
    w.magic(kDistancesMagic);
    w.put(kVersion);
    w.put(static_cast<std::int32_t>(tile.tile));
    w.put(static_cast<std::uint64_t>(tile.depth.size()));
    w.array(tile.signed_distance);
    w.array(tile.gradient_x);
    w.array(tile.gradient_z);
    w.array(tile.depth);
    return w.save(path);
}

Result<tiled::TileDistances> read_distances(const fs::path& path, const tiled::ShoreTiling& tiling, int tile) {
    const std::uint64_t texels = cells_in_tile(tiling);
    auto r = Reader::open(path, 64 + 4 * texels * sizeof(float));
    if (!r) return r.error();
    if (auto st = r->header(kDistancesMagic, tile); !st) return st.error();
    std::uint64_t count = 0;
    if (auto st = r->get(count); !st) return st.error();
    if (count != texels) return r->error(fmt::format("{} texels, not the tile's {}", count, texels));
    tiled::TileDistances out;
    out.tile = tile;
    std::vector<float>* grids[] = {&out.signed_distance, &out.gradient_x, &out.gradient_z, &out.depth};
    for (std::vector<float>* g : grids) {
        if (auto st = r->array(*g, count); !st) return st.error();
        for (float v : *g)
            if (!std::isfinite(v)) return r->error("a value is not finite");
    }
    if (auto st = r->end(); !st) return st.error();
    return out;
}

}  // namespace tidewater::cli::tiled_files
