#include "tidewater/query.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <exception>
#include <vector>

#include "kernel/kernel_select.hpp"
#include "tidewater/detail/parallel.hpp"
#include "tidewater/detail/shore_waves.hpp"
#include "tidewater/wakes.hpp"
#include "water/shore_order.hpp"

namespace tidewater {

namespace {

using detail::SolveFn;

/// Points per scheduled chunk: a multiple of every kernel's lane count, large enough that
/// scheduling costs nothing next to the solves.
constexpr std::size_t kPointsPerChunk = 512;

/// Solves the points tile by tile over the shore grid (detail::shore_tile_order) and
/// writes each result back to its caller's index.
void solve_in_shore_order(const detail::KernelInput& in, SolveFn solve, std::span<const glm::dvec2> points,
                          SurfacePoint* full, double* heights, const QueryOptions& options) {
    const std::vector<std::uint32_t> order = detail::shore_tile_order(*in.shore, points);
    std::vector<glm::dvec2> sorted(points.size());
    for (std::size_t k = 0; k < order.size(); ++k) sorted[k] = points[order[k]];
    detail::parallel_chunks(points.size(), kPointsPerChunk, options.threads, [&](std::size_t begin, std::size_t end) {
        const std::size_t n = end - begin;
        if (full) {
            std::vector<SurfacePoint> chunk(n);
            solve(in, sorted.data() + begin, n, chunk.data(), nullptr);
            for (std::size_t k = 0; k < n; ++k) full[order[begin + k]] = chunk[k];
        } else {
            std::vector<double> chunk(n);
            solve(in, sorted.data() + begin, n, nullptr, chunk.data());
            for (std::size_t k = 0; k < n; ++k) heights[order[begin + k]] = chunk[k];
        }
    });
}

/// Runs the kernel over the points on the shared scheduler, reporting any failure as an Error.
Status run_kernel(const WaterBody& body, double time, std::span<const glm::dvec2> points, SurfacePoint* full,
                  double* heights, const QueryOptions& options) {
    try {
        const detail::PreparedWaves<float> waves = detail::prepare_body_waves<float>(body, time);
        detail::KernelInput in;
        in.waves = &waves;
        detail::PreparedWakes<float> wakes;
        if (options.wakes != nullptr) {
            if (auto st = options.wakes->validate("query: wakes"); !st) return st;
            wakes = detail::prepare_wakes<float>(*options.wakes, time, options.exclude_emitter);
            in.wakes = &wakes;
        }
        if (const auto& shore = body.shore(); shore && !shore->trivial()) in.shore = shore.get();
        const SolveFn solve = detail::query_kernel().solve;
        if (in.shore != nullptr && points.size() >= detail::kShoreOrderMinPoints && points.size() <= UINT32_MAX) {
            solve_in_shore_order(in, solve, points, full, heights, options);
        } else {
            detail::parallel_chunks(points.size(), kPointsPerChunk, options.threads,
                                    [&](std::size_t begin, std::size_t end) {
                                        solve(in, points.data() + begin, end - begin, full ? full + begin : nullptr,
                                              heights ? heights + begin : nullptr);
                                    });
        }
        // A saved bake's tile that could not be read (it was read as zeros) fails the query.
        if (in.shore != nullptr) return in.shore->status();
    } catch (const std::exception& e) {
        return Error{ErrorCode::internal, fmt::format("query: could not run: {}", e.what())};
    }
    return {};
}

Status check_sizes(std::size_t points, std::size_t out) {
    if (points != out) {
        return Error{ErrorCode::invalid_argument, fmt::format("query: {} points but room for {} results", points, out)};
    }
    return {};
}

}  // namespace

const char* query_kernel_name() {
    return detail::query_kernel().name;
}

Status query_surface(const WaterBody& body, double time, std::span<const glm::dvec2> points,
                     std::span<SurfacePoint> out, const QueryOptions& options) {
    if (auto st = check_sizes(points.size(), out.size()); !st) return st;
    if (points.empty()) return {};
    return run_kernel(body, time, points, out.data(), nullptr, options);
}

Status query_heights(const WaterBody& body, double time, std::span<const glm::dvec2> points, std::span<double> heights,
                     const QueryOptions& options) {
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
