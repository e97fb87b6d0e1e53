// A saved bake's stored tiles of one layer, read on demand (a ShoreSlotSource): tile
// files tiles/<layer>/xNNN_zNNN.png, one 16-bit image each whose row r is field row r at
// the slot's texels (shore_bake_folder.hpp). The shared layer's reader also checks each
// tile's depths against the terrain it is loaded over.
// The bake folder is held open from the load on: a tile is read from the folder that was
// loaded, and a folder replaced since (a new bake saved over it) reads as missing files,
// never as another bake's tiles.
// Threading: read() from any thread.
#pragma once

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tidewater/detail/bake_files.hpp"
#include "tidewater/detail/lazy_shore_slots.hpp"
#include "tidewater/detail/shore_tiles.hpp"
#include "tidewater/terrain.hpp"

namespace tidewater {

/// A bake folder held open (its directory, not a path to it).
class OpenBakeFolder {
  public:
    static Result<std::shared_ptr<const OpenBakeFolder>> open(const std::filesystem::path& dir);
    ~OpenBakeFolder();
    OpenBakeFolder(const OpenBakeFolder&) = delete;
    OpenBakeFolder& operator=(const OpenBakeFolder&) = delete;

    const std::filesystem::path& path() const { return path_; }
    /// Whether `relative` is a regular file in the folder.
    bool has_file(const std::string& relative) const;
    /// `relative` opened for reading (null when it cannot be).
    std::FILE* open_file(const std::string& relative) const;

  private:
    OpenBakeFolder(std::filesystem::path path, int fd) : path_(std::move(path)), fd_(fd) {}
    std::filesystem::path path_;
    int fd_ = -1;
};

/// What the shared layer's depths must fit: the terrain under the model's grid at the
/// water level, within `tolerance` m (the depth row's encoding).
struct ShoreDepthCheck {
    Terrain terrain;
    ShoreGrid grid;
    double water_level = 0.0;
    double tolerance = 0.0;
};

/// Depth `depth` of the terrain at `p` against what the bake says there (`stored`: a value,
/// or the open sea's or dry land's page): an error message, empty when it fits.
std::string shore_depth_misfit(double depth, glm::dvec2 p, std::uint32_t page, double stored, double tolerance);

class ShoreTileFiles final : public ShoreSlotSource {
  public:
    /// The stored tiles of a layer on a grid of `resolution`² texels with `rows.size()` field
    /// rows, in folder `layer` of bake `folder`: `stored[s]` is the tile (rows along +z) of
    /// slot kShoreFirstStoredSlot + s.
    ShoreTileFiles(std::shared_ptr<const OpenBakeFolder> folder, std::string layer, int resolution,
                   std::vector<std::size_t> stored, std::vector<detail::FieldEncoding> rows,
                   std::optional<ShoreDepthCheck> depth_check);

    /// The file of stored slot `slot`, within the folder.
    std::string file(std::size_t slot) const;
    /// Fails, naming the file, unless every stored slot's file is there.
    Status check_files() const;
    Status read(std::size_t slot, float* out) const override;

  private:
    std::shared_ptr<const OpenBakeFolder> folder_;
    std::string layer_;
    ShoreTiles shape_;  // pages and sizes only (no slots): where each slot's texels lie
    std::vector<std::size_t> stored_;
    std::vector<detail::FieldEncoding> rows_;
    std::optional<ShoreDepthCheck> depth_check_;
};

}  // namespace tidewater
