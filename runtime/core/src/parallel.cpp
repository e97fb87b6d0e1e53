#include "tidewater/detail/parallel.hpp"

#include <tbb/blocked_range.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#if TIDEWATER_THREAD_SANITIZER
#include <thread>
#include <vector>
#endif

namespace tidewater::detail {

namespace {

#if TIDEWATER_THREAD_SANITIZER
// The ThreadSanitizer build (TidewaterCompileOptions.cmake): the chunks go to plain
// threads, whose start and join TSan sees, instead of oneTBB's uninstrumented scheduler.
void run_chunks(std::size_t count, std::size_t grain, unsigned threads,
                const std::function<void(std::size_t, std::size_t)>& body) {
    const std::size_t chunks = (count + grain - 1) / grain;
    const std::size_t workers = std::min<std::size_t>(chunks, worker_count(threads));
    std::atomic<std::size_t> next{0};
    const auto work = [&] {
        for (std::size_t c = next++; c < chunks; c = next++) body(c * grain, std::min(count, (c + 1) * grain));
    };
    std::vector<std::jthread> helpers;
    for (std::size_t w = 1; w < workers; ++w) helpers.emplace_back(work);
    work();
}
#else
void run_chunks(std::size_t count, std::size_t grain, unsigned threads,
                const std::function<void(std::size_t, std::size_t)>& body) {
    auto run = [&] {
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, grain),
                          [&](const tbb::blocked_range<std::size_t>& r) { body(r.begin(), r.end()); });
    };
    if (threads == 0 || static_cast<int>(threads) >= tbb::this_task_arena::max_concurrency()) {
        run();
    } else {
        // A narrower arena caps this call's workers; its threads come from the same pool.
        tbb::task_arena arena(static_cast<int>(threads));
        arena.execute(run);
    }
}
#endif

}  // namespace

unsigned worker_count(unsigned threads) {
    const unsigned all = static_cast<unsigned>(std::max(1, tbb::this_task_arena::max_concurrency()));
    return threads == 0 ? all : threads;
}

void parallel_chunks(std::size_t count, std::size_t grain, unsigned threads,
                     const std::function<void(std::size_t, std::size_t)>& body) {
    if (count == 0) return;
    grain = std::max<std::size_t>(grain, 1);
    if (threads == 1 || count <= grain) {
        body(0, count);
        return;
    }
    run_chunks(count, grain, threads, body);
}

void parallel_for_each(std::size_t count, unsigned threads, const std::function<void(std::size_t)>& body) {
    parallel_chunks(count, 1, threads, [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) body(i);
    });
}

void parallel_in_order(std::size_t count, unsigned threads, const std::function<void(std::size_t)>& body) {
    const std::size_t workers = std::min<std::size_t>(count, worker_count(threads));
    std::atomic<std::size_t> next{0};
    parallel_for_each(workers, threads, [&](std::size_t) {
        for (std::size_t i = next++; i < count; i = next++) body(i);
    });
}

}  // namespace tidewater::detail
