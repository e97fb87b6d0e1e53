#include "tidewater/query.hpp"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <fmt/format.h>
#include <vector>

#include "kernel/kernel_waves.hpp"
#include "parallel.hpp"
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

/// Points per scheduled chunk: a multiple of every kernel's lane count, large enough that
/// scheduling costs nothing next to the solves.
constexpr std::size_t kPointsPerChunk = 512;

/// Runs the kernel over the points on the shared scheduler, reporting any failure as an Error.
Status run_kernel(const WaterBody& body, double time, std::span<const glm::dvec2> points, SurfacePoint* full,
                  double* heights, const QueryOptions& options) {
    try {
        const detail::PreparedWaves<float> waves =
            detail::prepare_waves<float>(body.waves(), body.local_time(time), body.level());
        detail::KernelInput in;
        in.waves = &waves;
        if (const auto& shore = body.shore(); shore && !shore->trivial()) in.shore = shore.get();
        const SolveFn solve = kernel().solve;
        detail::parallel_chunks(points.size(), kPointsPerChunk, options.threads, [&](std::size_t begin, std::size_t end) {
            solve(in, points.data() + begin, end - begin, full ? full + begin : nullptr, heights ? heights + begin : nullptr);
        });
    } catch (const std::exception& e) {
        return Error{ErrorCode::internal, fmt::format("query: could not run: {}", e.what())};
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
    return run_kernel(body, time, points, out.data(), nullptr, options);
}

Status query_heights(const WaterBody& body, double time, std::span<const glm::dvec2> points,
                     std::span<double> heights, const QueryOptions& options) {
    if (auto st = check_sizes(points.size(), heights.size()); !st) return st;
    if (points.empty()) return {};
    return run_kernel(body, time, points, nullptr, heights.data(), options);
}

SurfacePoint query_point(const WaterBody& body, double time, glm::dvec2 point) {
    SurfacePoint out;
    // One point, one thread: this cannot fail.
    (void)query_surface(body, time, std::span<const glm::dvec2>(&point, 1), std::span<SurfacePoint>(&out, 1));
    return out;
}

}  // namespace tidewater
