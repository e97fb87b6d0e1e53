// The library's parallel loops: parallel_in_order starts its items in order whichever
// worker takes them (the shore bake relies on it to make its largest runs' memory last).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <mutex>
#include <vector>

#include "tidewater/detail/parallel.hpp"

namespace tidewater::detail {
namespace {

/// The order in which `loop` starts the items [0, count) on two workers.
///
/// The workers go in lockstep so that the order recorded is the order the items were
/// taken, however the threads are scheduled: an item, once recorded, waits until the
/// other worker has recorded its own item too. So after the first two, neither worker can
/// take a next item while the other has taken one and not yet recorded it. A loop that
/// runs on one worker only waits out a timeout once and then goes on alone.
template <typename Loop>
std::vector<std::size_t> start_order(std::size_t count, const Loop& loop) {
    std::vector<std::size_t> order;
    std::mutex lock;
    std::condition_variable recorded;
    bool alone = false;
    loop(count, 2u, [&](std::size_t i) {
        std::unique_lock guard(lock);
        order.push_back(i);
        recorded.notify_all();
        const std::size_t partner_recorded = std::min(count, order.size() + 1);
        if (alone) return;
        if (!recorded.wait_for(guard, std::chrono::seconds(2), [&] { return order.size() >= partner_recorded; }))
            alone = true;
    });
    return order;
}

/// How far the furthest item started from its place in the order of the items.
std::size_t largest_displacement(const std::vector<std::size_t>& order) {
    std::size_t most = 0;
    for (std::size_t k = 0; k < order.size(); ++k) most = std::max(most, order[k] > k ? order[k] - k : k - order[k]);
    return most;
}

TEST(Parallel, InOrderStartsEachItemAfterTheOnesBeforeIt) {
    constexpr std::size_t kCount = 64;
    const std::vector<std::size_t> in_order = start_order(kCount, parallel_in_order);
    ASSERT_EQ(in_order.size(), kCount);
    std::vector<char> seen(kCount, 0);
    for (std::size_t i : in_order) seen[i] += 1;
    for (std::size_t i = 0; i < kCount; ++i) EXPECT_EQ(seen[i], 1) << "item " << i << " runs once";
    // Taken and recorded in the same order but for the first two, which both workers take
    // at once: an item starts at most one place from its own. A split range
    // (parallel_for_each on oneTBB) starts its second half at once on the second worker,
    // 32 places out.
    EXPECT_LE(largest_displacement(in_order), 1u);
}

}  // namespace
}  // namespace tidewater::detail
