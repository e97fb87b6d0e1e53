// Full-resolution shore tiles streamed by view (private). Over the renderer's memory
// budget each shore model is drawn from a coarse level that is always resident; each of
// its layers also has a pool of full-resolution slots, and the tiles nearest the camera
// are packed into it a bounded number of bytes per frame. A tile's page names its pool
// slot while it is resident and kShoreNotResident otherwise, which sends the shaders to
// the coarse level (shore_fields.glsl). Every frame in flight reads its own copy of the
// pages, so a pool slot given up at frame F is written again only once the frames that
// could still read it are done. A tile in host memory is packed at once; one a saved bake
// holds on disk is read on a thread of its own (ShoreSlotReader) and packed a frame or more
// later, not kept in host memory.
// Threading: one thread (the renderer's).
#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>
#include <span>
#include <vector>

#include "shore_slot_reader.hpp"
#include "tidewater/detail/shore_tiles.hpp"

namespace tidewater::render::detail {

/// One layer of a model (its shared fields, or a run of waves) whose full-resolution
/// tiles stream into a pool.
struct StreamedLayer {
    const ShoreTiles* tiles = nullptr;  ///< the full-resolution layer; its model is kept alive by the caller
    ShoreGrid grid;                     ///< its grid, world xz
    bool shared = false;                ///< the shared fields' (else a run of waves')
    std::uint32_t first_page = 0;       ///< its first page in the pages
    std::size_t first_element = 0;      ///< its pool's slot 0 (the open sea's) in its buffer, vec4s
    std::size_t pool_slots = 0;         ///< slots for streamed tiles, after the open-sea and dry-land ones
};

class ShoreStream {
  public:
    /// Starts over with `layers`, none of their tiles resident.
    void reset(std::vector<StreamedLayer> layers);

    /// Frame `frame` looks from `cameras` (world xz, m; its views'): each layer's pool is to
    /// hold its stored tiles nearest any of them. Tiles that are wanted and not resident are packed,
    /// nearest first, into pool slots no frame in flight can read, into `shared_out` or
    /// `per_wave_out` (the mapped buffers), until `max_bytes` are written (at least one
    /// tile); resident tiles no longer wanted give their slots up when the wanted ones
    /// need them. `pages` (every model's, as packed) are updated. Returns the bytes written.
    std::uint64_t step(std::span<const glm::dvec2> cameras, std::uint64_t frame, std::uint32_t frames_in_flight,
                       std::uint64_t max_bytes, std::span<std::uint32_t> pages, glm::vec4* shared_out,
                       glm::vec4* per_wave_out);

    /// After an edit re-baked the models into ones laid out alike: layer i reads `tiles[i]`
    /// from now on, and its resident tiles whose slot changed are packed again. No GPU work
    /// may be reading the pools. Returns the bytes written.
    std::uint64_t refresh(const std::vector<const ShoreTiles*>& tiles, glm::vec4* shared_out, glm::vec4* per_wave_out);

    std::size_t resident_tiles() const;
    /// Tiles asked of the bake folder and not packed yet (being read, or read and waiting).
    std::size_t reading_tiles() const { return reader_.pending() + read_.size(); }
    /// Stored tiles of every layer: what the pools would hold with room for all.
    std::size_t streamable_tiles() const;
    const std::vector<StreamedLayer>& layers() const { return layers_; }

  private:
    /// What a pool slot was packed from: a slot of the tiles (its allocation, or its reader).
    struct Source {
        const void* floats = nullptr;
        std::size_t slot = 0;
        bool operator==(const Source&) const = default;
    };
    static Source source_of(const ShoreTiles& tiles, std::size_t slot);
    struct Pool {
        std::vector<std::uint32_t> candidates;  ///< the layer's tiles with a stored slot
        std::vector<std::int64_t> tile;         ///< per pool slot: the tile it holds, -1 none
        std::vector<Source> source;             ///< per pool slot: what was packed into it
        std::vector<std::uint64_t> free_from;   ///< per pool slot: the first frame that may write it
        std::vector<std::int64_t> slot_of;      ///< per tile: its pool slot, -1 none
        std::vector<char> reading;              ///< per tile: asked of the reader
        std::vector<char> unreadable;           ///< per tile: its file could not be read (the coarse level stays)
    };
    /// Packs tile `t` of layer `l` (its slot's floats `floats`) into pool slot `p`; its bytes.
    std::uint64_t pack(std::size_t l, std::size_t p, std::uint32_t t, const float* floats, glm::vec4* shared_out,
                       glm::vec4* per_wave_out);

    std::vector<StreamedLayer> layers_;
    std::vector<Pool> pools_;
    std::vector<ShoreSlotReader::Read> read_;  ///< read from disk, not packed yet
    ShoreSlotReader reader_;
};

}  // namespace tidewater::render::detail
