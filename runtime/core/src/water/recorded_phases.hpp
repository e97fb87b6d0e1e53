// The sines and cosines of a batch's wave phases at the evaluation each lane finished
// on (private). A full query's lagged sums (LaggedCompression) turn these phases back
// instead of forming every sine again at the solved rest position: one sine pass fewer.
#pragma once

#include <array>
#include <cstddef>

#include "tidewater/constants.hpp"
#include "tidewater/detail/water_point.hpp"

namespace tidewater::detail {

/// One batch's phases. The water writes `last` at each evaluation, and its `record` keeps
/// them (`keep`) for the lanes that finish, as Newton's result keeps their sums. Lives on the stack
/// beside the water it serves; not shared between threads.
template <typename T>
struct RecordedPhases {
    using Ops = NumberOps<T>;
    std::array<T, kMaxWaves> sin_last, cos_last, sin_kept, cos_kept;
    T ex_last = T(0.0), ez_last = T(0.0);  ///< the rest offset of the last evaluation, m
    T ex_kept = T(0.0), ez_kept = T(0.0);  ///< and of each lane's kept one

    void keep(typename Ops::Mask m, std::size_t count) {
        for (std::size_t i = 0; i < count; ++i) {
            sin_kept[i] = Ops::select(m, sin_last[i], sin_kept[i]);
            cos_kept[i] = Ops::select(m, cos_last[i], cos_kept[i]);
        }
        ex_kept = Ops::select(m, ex_last, ex_kept);
        ez_kept = Ops::select(m, ez_last, ez_kept);
    }
    /// Whether every lane's kept phases are those at rest offset (ex, ez).
    bool kept_at(const T& ex, const T& ez) const { return Ops::all(ex == ex_kept && ez == ez_kept); }
};

}  // namespace tidewater::detail
