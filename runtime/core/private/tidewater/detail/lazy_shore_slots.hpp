// A layer of the shore model whose stored slots are read on demand (a saved bake's tile
// files, DESIGN.md "Worlds at real scale"): loading a bake reads its index, and each
// tile's fields are decoded the first time a query, the renderer or an edit needs them,
// then kept. A slot that cannot be read (a file gone or corrupt since the load, or
// fields that do not fit the terrain) reads as zeros (no wave, no depth) and its error is kept:
// the query, set_scene or save that needed it fails with the file's name.
// Internal to ShoreTiles. Threading: get() and status() from any number of threads.
#pragma once

#include <array>
#include <atomic>
#include <cstddef>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

#include "tidewater/result.hpp"

namespace tidewater {

/// Where a lazily read layer's stored slots come from.
class ShoreSlotSource {
  public:
    virtual ~ShoreSlotSource() = default;
    /// Writes slot `slot`'s floats (ShoreTiles::slot_floats of them) to `out`; an error
    /// names the file. Called from any thread, for distinct slots or the same one at once.
    virtual Status read(std::size_t slot, float* out) const = 0;
};

class LazyShoreSlots {
  public:
    /// `slot_count` slots of `slot_floats` floats from `source` (a slot that fails reads as zeros).
    LazyShoreSlots(std::unique_ptr<const ShoreSlotSource> source, std::size_t slot_count, std::size_t slot_floats);

    /// Slot `slot`'s floats, read from the source the first time.
    const float* get(std::size_t slot) const {
        const float* ready = ready_[slot].load(std::memory_order_acquire);
        return ready ? ready : read(slot);
    }
    /// Slot `slot`'s floats copied into `out` (slot_floats of them) without keeping them:
    /// from what get() kept, else read from the source again (a renderer streaming tiles
    /// it does not keep in host memory). A slot that cannot be read writes zeros and keeps
    /// its error, as get() does; returns whether it was read.
    bool copy(std::size_t slot, float* out) const;
    /// Whether get() has read slot `slot` and keeps it.
    bool kept(std::size_t slot) const { return ready_[slot].load(std::memory_order_acquire) != nullptr; }
    /// The first slot's error, if any slot failed; ok otherwise.
    Status status() const;
    /// Slots read and kept so far (failed ones included); copy() counts none.
    std::size_t read_count() const { return read_count_.load(std::memory_order_relaxed); }
    std::size_t slot_count() const { return storage_.size(); }

  private:
    const float* read(std::size_t slot) const;
    void keep_error(const Error& error) const;

    static constexpr std::size_t kLocks = 64;  // slots share locks: slot % kLocks
    std::unique_ptr<const ShoreSlotSource> source_;
    std::size_t slot_floats_;
    std::unique_ptr<float[]> failed_slot_;  // zeros
    mutable std::unique_ptr<std::atomic<const float*>[]> ready_;
    mutable std::vector<std::unique_ptr<float[]>> storage_;  // each written once, under its lock
    mutable std::array<std::mutex, kLocks> locks_;
    mutable std::atomic<std::size_t> read_count_{0};
    mutable std::atomic<bool> failed_{false};
    mutable std::mutex error_lock_;
    mutable std::optional<Error> error_;
};

}  // namespace tidewater
