// Shore slots read from a saved bake's folder on a thread of its own (private). Over the
// memory budget the renderer streams full-resolution shore tiles; those a saved bake holds
// on disk, and nothing has read yet, are asked for here and packed a frame or more later,
// so that decoding a tile never stalls a frame, and the model keeps none of them in host
// memory (LazyShoreSlots::copy).
// Threading: request(), take(), forget() and pending() from one thread (the renderer's);
// the reads on the reader's own thread, started by the first request and joined by the
// destructor.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <stop_token>
#include <thread>
#include <vector>

#include "tidewater/detail/lazy_shore_slots.hpp"

namespace tidewater::render::detail {

class ShoreSlotReader {
  public:
    /// A slot read: the layer and tile it was asked for, and its floats (zeros when it
    /// could not be read; the reader keeps the error, LazyShoreSlots::status).
    struct Read {
        std::size_t layer = 0;
        std::uint32_t tile = 0;
        bool ok = false;
        std::vector<float> floats;
    };

    ShoreSlotReader() = default;
    ShoreSlotReader(const ShoreSlotReader&) = delete;
    ShoreSlotReader& operator=(const ShoreSlotReader&) = delete;
    ~ShoreSlotReader();

    /// Asks for slot `slot` of `slots` (`floats` of them), for tile `tile` of layer `layer`.
    /// The reader is shared, so it outlives a model dropped while the read is in flight.
    void request(std::size_t layer, std::uint32_t tile, std::shared_ptr<const LazyShoreSlots> slots, std::size_t slot,
                 std::size_t floats);
    /// The reads finished since the last call, for requests made since the last forget().
    std::vector<Read> take();
    /// Drops every request not read yet; what is being read is dropped when it finishes.
    void forget();
    /// Requests not yet taken.
    std::size_t pending() const;

  private:
    struct Request {
        std::size_t layer = 0;
        std::uint32_t tile = 0;
        std::shared_ptr<const LazyShoreSlots> slots;
        std::size_t slot = 0, floats = 0;
        std::uint64_t generation = 0;
    };
    void run(std::stop_token stop);

    mutable std::mutex lock_;
    std::condition_variable_any wake_;
    std::deque<Request> queue_;
    std::vector<Read> done_;
    std::size_t reading_ = 0;       // taken off the queue, not yet in done_
    std::uint64_t generation_ = 0;  // forget() starts a new one
    std::jthread thread_;           // last: stopped and joined before the rest goes
};

}  // namespace tidewater::render::detail
