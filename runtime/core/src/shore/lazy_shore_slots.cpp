// Shore slots read on demand (tidewater/detail/lazy_shore_slots.hpp).
#include "tidewater/detail/lazy_shore_slots.hpp"

#include <algorithm>

namespace tidewater {

LazyShoreSlots::LazyShoreSlots(std::unique_ptr<const ShoreSlotSource> source, std::size_t slot_count,
                               std::size_t slot_floats)
    : source_(std::move(source)),
      slot_floats_(slot_floats),
      failed_slot_(std::make_unique<float[]>(slot_floats)),
      ready_(std::make_unique<std::atomic<const float*>[]>(slot_count)),
      storage_(slot_count) {
    for (std::size_t s = 0; s < slot_count; ++s) ready_[s].store(nullptr, std::memory_order_relaxed);
}

const float* LazyShoreSlots::read(std::size_t slot) const {
    std::lock_guard lock(locks_[slot % kLocks]);
    if (const float* ready = ready_[slot].load(std::memory_order_relaxed)) return ready;
    auto floats = std::make_unique_for_overwrite<float[]>(slot_floats_);
    const float* result = floats.get();
    if (Status st = source_->read(slot, floats.get()); st) {
        storage_[slot] = std::move(floats);
    } else {
        result = failed_slot_.get();
        keep_error(st.error());
    }
    read_count_.fetch_add(1, std::memory_order_relaxed);
    ready_[slot].store(result, std::memory_order_release);
    return result;
}

bool LazyShoreSlots::copy(std::size_t slot, float* out) const {
    if (const float* ready = ready_[slot].load(std::memory_order_acquire)) {
        std::copy_n(ready, slot_floats_, out);
        return ready != failed_slot_.get();
    }
    if (Status st = source_->read(slot, out); !st) {
        std::fill_n(out, slot_floats_, 0.0f);
        keep_error(st.error());
        return false;
    }
    return true;
}

void LazyShoreSlots::keep_error(const Error& error) const {
    std::lock_guard error_lock(error_lock_);
    if (!error_) error_ = error;
    failed_.store(true, std::memory_order_release);
}

Status LazyShoreSlots::status() const {
    if (!failed_.load(std::memory_order_acquire)) return {};
    std::lock_guard lock(error_lock_);
    return *error_;
}

}  // namespace tidewater
