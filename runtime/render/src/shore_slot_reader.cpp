#include "shore_slot_reader.hpp"

#include <utility>

namespace tidewater::render::detail {

ShoreSlotReader::~ShoreSlotReader() {
    if (thread_.joinable()) {
        thread_.request_stop();
        wake_.notify_all();
        thread_.join();
    }
}

void ShoreSlotReader::request(std::size_t layer, std::uint32_t tile, std::shared_ptr<const LazyShoreSlots> slots,
                              std::size_t slot, std::size_t floats) {
    {
        const std::lock_guard guard(lock_);
        queue_.push_back({layer, tile, std::move(slots), slot, floats, generation_});
    }
    if (!thread_.joinable()) thread_ = std::jthread([this](std::stop_token stop) { run(stop); });
    wake_.notify_one();
}

std::vector<ShoreSlotReader::Read> ShoreSlotReader::take() {
    const std::lock_guard guard(lock_);
    return std::exchange(done_, {});
}

void ShoreSlotReader::forget() {
    const std::lock_guard guard(lock_);
    queue_.clear();
    done_.clear();
    ++generation_;
}

std::size_t ShoreSlotReader::pending() const {
    const std::lock_guard guard(lock_);
    return queue_.size() + reading_ + done_.size();
}

void ShoreSlotReader::run(std::stop_token stop) {
    std::unique_lock guard(lock_);
    for (;;) {
        if (!wake_.wait(guard, stop, [this] { return !queue_.empty(); })) return;
        Request r = std::move(queue_.front());
        queue_.pop_front();
        ++reading_;
        guard.unlock();
        Read read{r.layer, r.tile, false, std::vector<float>(r.floats)};
        read.ok = r.slots->copy(r.slot, read.floats.data());
        r.slots.reset();  // the model may be gone: its reader goes with the last request
        guard.lock();
        --reading_;
        if (r.generation == generation_) done_.push_back(std::move(read));
    }
}

}  // namespace tidewater::render::detail
