// One scheduler for every parallel loop of the library (private): oneTBB's. Nested
// and concurrent callers share its workers, so a query inside a host's own TBB task,
// or two threads querying while a third bakes, never oversubscribe the machine.
#pragma once

#include <cstddef>
#include <functional>

namespace tidewater::detail {

/// Calls body(begin, end) over disjoint chunks covering [0, count), chunks of at least
/// `grain` items, on at most `threads` workers (0: the scheduler's default; 1: inline
/// on the caller's thread). Returns when every chunk is done. An exception thrown by
/// `body` is rethrown here: the public entry points catch and report it as an Error.
void parallel_chunks(std::size_t count, std::size_t grain, unsigned threads,
                     const std::function<void(std::size_t begin, std::size_t end)>& body);

/// parallel_chunks one item at a time: body(i) for each i in [0, count).
void parallel_for_each(std::size_t count, unsigned threads, const std::function<void(std::size_t)>& body);

/// body(i) for each i in [0, count), started in the order of i: each worker takes the next
/// item when it is free. parallel_for_each splits the range, so a second worker starts
/// half-way through it; here the items meant to go first (the bake's largest, or those
/// whose memory should be made last) do.
void parallel_in_order(std::size_t count, unsigned threads, const std::function<void(std::size_t)>& body);

/// Workers a call with `threads` gets (0: the scheduler's default concurrency).
unsigned worker_count(unsigned threads);

}  // namespace tidewater::detail
