// The library's parallel loops: parallel_in_order starts its items in order whichever
// worker takes them (the shore bake relies on it to make its largest runs' memory last).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <mutex>
#include <thread>
#include <vector>

#include "tidewater/detail/parallel.hpp"

namespace tidewater::detail {
namespace {

/// The order in which `loop` starts the items [0, count) on two workers, each item taking
/// a little while.
template <typename Loop>
std::vector<std::size_t> start_order(std::size_t count, const Loop& loop) {
    std::vector<std::size_t> order;
    std::mutex lock;
    loop(count, 2u, [&](std::size_t i) {
        {
            const std::lock_guard guard(lock);
            order.push_back(i);
        }
        std::this_thread::sleep_for(std::chrono::microseconds(200));
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
    // Two workers: an item starts at most one place from its own (its neighbour was taken
    // first and recorded later). A split range (parallel_for_each) starts its second half
    // at once on the second worker, 32 places out.
    EXPECT_LE(largest_displacement(in_order), 1u);
}

}  // namespace
}  // namespace tidewater::detail
