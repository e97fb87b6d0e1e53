#include "tidewater/query.hpp"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <fmt/format.h>
#include <thread>
#include <vector>

#include "kernel/kernel_waves.hpp"
#include "shore/shore_query.hpp"
#include "tidewater/shore_waves.hpp"

namespace tidewater {

namespace {

using detail::SolveFn;

struct Kernel {
    SolveFn solve;
    const char* name;
};

/// Picks the widest kernel this CPU runs. TIDEWATER_QUERY_KERNEL=sse2 forces
/// the baseline (tests compare the two).
Kernel select_kernel() {
    const char* forced = std::getenv("TIDEWATER_QUERY_KERNEL");
    const bool want_baseline = forced != nullptr && std::strcmp(forced, "sse2") == 0;
#if defined(TIDEWATER_HAVE_AVX2_KERNEL)
    if (!want_baseline && __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma")) {
        return {&detail::kernel_avx2::solve, detail::kernel_avx2::name()};
    }
#else
    (void)want_baseline;
#endif
    return {&detail::kernel_sse2::solve, detail::kernel_sse2::name()};
}

const Kernel& kernel() {
    static const Kernel k = select_kernel();
    return k;
}

/// Below this many points per thread, spawning threads costs more than it saves.
constexpr std::size_t kMinPointsPerThread = 2048;

template <typename Work>
Status run_parallel(std::size_t n, unsigned requested, const Work& work) {
    unsigned threads = requested == 0 ? std::max(1u, std::thread::hardware_concurrency()) : requested;
    threads = static_cast<unsigned>(std::min<std::size_t>(threads, std::max<std::size_t>(1, n / kMinPointsPerThread)));
    try {
        if (threads <= 1) {
            work(std::size_t{0}, n);
            return {};
        }
        std::vector<std::thread> pool;
        pool.reserve(threads - 1);
        const std::size_t chunk = (n + threads - 1) / threads;
        for (unsigned t = 1; t < threads; ++t) {
            const std::size_t begin = std::min(n, t * chunk), end = std::min(n, begin + chunk);
            pool.emplace_back([&work, begin, end] { work(begin, end); });
        }
        work(std::size_t{0}, std::min(n, chunk));
        for (std::thread& th : pool) th.join();
    } catch (const std::exception& e) {
        return Error{ErrorCode::invalid_argument, fmt::format("query: could not run: {}", e.what())};
    }
    return {};
}

Status check_sizes(std::size_t points, std::size_t out) {
    if (points != out) {
        return Error{ErrorCode::invalid_argument,
                     fmt::format("query: {} points but room for {} results", points, out)};
    }
    return {};
}

}  // namespace

const char* query_kernel_name() { return kernel().name; }

Status query_surface(const WaterBody& body, double time, std::span<const glm::dvec2> points,
                     std::span<SurfacePoint> out, const QueryOptions& options) {
    if (auto st = check_sizes(points.size(), out.size()); !st) return st;
    if (points.empty()) return {};
    if (const auto& shore = body.shore(); shore && !shore->trivial()) {
        return run_parallel(points.size(), options.threads, [&](std::size_t begin, std::size_t end) {
            detail::solve_points_shore(body, *shore, body.local_time(time), points.data() + begin, end - begin,
                                       out.data() + begin, nullptr);
        });
    }
    const detail::KernelWaves waves =
        detail::prepare_kernel_waves(body.waves(), body.local_time(time), body.level());
    const SolveFn solve = kernel().solve;
    return run_parallel(points.size(), options.threads, [&](std::size_t begin, std::size_t end) {
        solve(waves, points.data() + begin, end - begin, out.data() + begin, nullptr);
        for (std::size_t i = begin; i < end; ++i) out[i].foam = crest_foam(out[i].jacobian);
    });
}

Status query_heights(const WaterBody& body, double time, std::span<const glm::dvec2> points,
                     std::span<double> heights, const QueryOptions& options) {
    if (auto st = check_sizes(points.size(), heights.size()); !st) return st;
    if (points.empty()) return {};
    if (const auto& shore = body.shore(); shore && !shore->trivial()) {
        return run_parallel(points.size(), options.threads, [&](std::size_t begin, std::size_t end) {
            detail::solve_points_shore(body, *shore, body.local_time(time), points.data() + begin, end - begin, nullptr,
                                       heights.data() + begin);
        });
    }
    const detail::KernelWaves waves =
        detail::prepare_kernel_waves(body.waves(), body.local_time(time), body.level());
    const SolveFn solve = kernel().solve;
    return run_parallel(points.size(), options.threads, [&](std::size_t begin, std::size_t end) {
        solve(waves, points.data() + begin, end - begin, nullptr, heights.data() + begin);
    });
}

SurfacePoint query_point(const WaterBody& body, double time, glm::dvec2 point) {
    SurfacePoint out;
    // One point, one thread: this cannot fail.
    (void)query_surface(body, time, std::span<const glm::dvec2>(&point, 1), std::span<SurfacePoint>(&out, 1));
    return out;
}

}  // namespace tidewater
