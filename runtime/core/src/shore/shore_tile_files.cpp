// A saved bake's tiles read on demand (shore_tile_files.hpp).
#include "shore/shore_tile_files.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include "tidewater/detail/image_io.hpp"
#include "tidewater/detail/shore_bake_folder.hpp"

namespace tidewater {

Result<std::shared_ptr<const OpenBakeFolder>> OpenBakeFolder::open(const std::filesystem::path& dir) {
    const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) return Error{ErrorCode::io_error, fmt::format("{}: cannot open folder", dir.string())};
    return std::shared_ptr<const OpenBakeFolder>(new OpenBakeFolder(dir, fd));
}

OpenBakeFolder::~OpenBakeFolder() {
    ::close(fd_);
}

bool OpenBakeFolder::has_file(const std::string& relative) const {
    struct stat st {};
    return ::fstatat(fd_, relative.c_str(), &st, 0) == 0 && S_ISREG(st.st_mode);
}

std::FILE* OpenBakeFolder::open_file(const std::string& relative) const {
    const int fd = ::openat(fd_, relative.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return nullptr;
    std::FILE* f = ::fdopen(fd, "rb");
    if (!f) ::close(fd);
    return f;
}

std::string shore_depth_misfit(double depth, glm::dvec2 p, std::uint32_t page, double stored, double tolerance) {
    const bool fits = page == gpu::kShoreOpenSlot  ? depth > -tolerance
                      : page == gpu::kShoreDrySlot ? depth <= tolerance
                                                   : std::abs(depth - stored) <= tolerance;
    if (fits) return {};
    return fmt::format(
        "the terrain differs from the one baked ({:.3f} m deep at x = {:.1f}, z = {:.1f}, "
        "the bake says {}): re-run tidewater bake",
        depth, p.x, p.y,
        page == gpu::kShoreOpenSlot  ? std::string("open sea")
        : page == gpu::kShoreDrySlot ? std::string("dry land")
                                     : fmt::format("{:.3f} m", stored));
}

ShoreTileFiles::ShoreTileFiles(std::shared_ptr<const OpenBakeFolder> folder, std::string layer, int resolution,
                               std::vector<std::size_t> stored, std::vector<detail::FieldEncoding> rows,
                               std::optional<ShoreDepthCheck> depth_check)
    : folder_(std::move(folder)),
      layer_(std::move(layer)),
      shape_(ShoreTiles::open_grid(resolution, rows.size())),
      stored_(std::move(stored)),
      rows_(std::move(rows)),
      depth_check_(std::move(depth_check)) {}

std::string ShoreTileFiles::file(std::size_t slot) const {
    const std::size_t k = stored_[slot - gpu::kShoreFirstStoredSlot];
    const auto m = static_cast<std::size_t>(shape_.tiles_per_side);
    return shore_tile_file(layer_, static_cast<int>(k % m), static_cast<int>(k / m));
}

Status ShoreTileFiles::check_files() const {
    for (std::size_t s = 0; s < stored_.size(); ++s) {
        const std::string file = this->file(gpu::kShoreFirstStoredSlot + s);
        if (!folder_->has_file(file))
            return Error{ErrorCode::io_error, fmt::format("{}: cannot open file", (folder_->path() / file).string())};
    }
    return {};
}

Status ShoreTileFiles::read(std::size_t slot, float* out) const {
    const std::string relative = file(slot);
    const std::filesystem::path path = folder_->path() / relative;
    std::FILE* f = folder_->open_file(relative);
    if (!f)
        return Error{ErrorCode::io_error,
                     fmt::format("{}: cannot open file (the bake folder was replaced or changed since it was loaded)",
                                 path.string())};
    auto img = detail::read_png_gray16(f, path.string());
    if (!img) return img.error();
    const std::size_t stride = rows_.size();
    if (img->width != static_cast<int>(ShoreTiles::kSlotTexels) || img->height != static_cast<int>(stride))
        return Error{ErrorCode::invalid_argument,
                     fmt::format("{}: the image is {}x{}, a tile of this bake is {}x{}", path.string(), img->width,
                                 img->height, ShoreTiles::kSlotTexels, stride)};
    for (std::size_t r = 0; r < stride; ++r)
        for (std::size_t texel = 0; texel < ShoreTiles::kSlotTexels; ++texel)
            out[texel * stride + r] =
                static_cast<float>(rows_[r].decode(img->pixels[r * ShoreTiles::kSlotTexels + texel]));
    if (!depth_check_) return {};
    // The shared layer: every texel's depth (row 0), the apron's too, against the terrain.
    const ShoreDepthCheck& c = *depth_check_;
    const std::size_t tile = stored_[slot - gpu::kShoreFirstStoredSlot];
    const auto n = static_cast<std::size_t>(c.grid.resolution);
    for (std::size_t texel = 0; texel < ShoreTiles::kSlotTexels; ++texel) {
        const std::size_t g = shape_.grid_index(tile, texel);
        const glm::dvec2 p = c.grid.corner + c.grid.texel * (glm::dvec2(g % n, g / n) + 0.5);
        const double depth = c.water_level - c.terrain.height_at(p);
        const std::string misfit = shore_depth_misfit(depth, p, static_cast<std::uint32_t>(slot),
                                                      static_cast<double>(out[texel * stride]), c.tolerance);
        if (!misfit.empty()) return Error{ErrorCode::invalid_argument, fmt::format("{}: {}", path.string(), misfit)};
    }
    return {};
}

}  // namespace tidewater
