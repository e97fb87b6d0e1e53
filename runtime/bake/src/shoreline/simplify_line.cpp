#include "simplify_line.hpp"

#include <boost/geometry/algorithms/simplify.hpp>
#include <boost/geometry/geometries/linestring.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <boost/geometry/strategies/strategies.hpp>
#include <cmath>
#include <glm/common.hpp>

namespace tidewater::detail {

namespace bg = boost::geometry;
using Point = bg::model::d2::point_xy<double>;
using Linestring = bg::model::linestring<Point>;

namespace {

/// Douglas-Peucker over points[first, last] of `points`, taken cyclically (last may wrap
/// past the end); appends the result to `out` but for its last point.
void simplify_piece(const std::vector<glm::dvec2>& points, std::size_t first, std::size_t last, double tolerance,
                    std::vector<glm::dvec2>& out) {
    const std::size_t n = points.size();
    Linestring in, simplified;
    for (std::size_t k = first;; ++k) {
        const glm::dvec2& p = points[k % n];
        in.emplace_back(p.x, p.y);
        if (k == last) break;
    }
    bg::simplify(in, simplified, tolerance);
    for (std::size_t k = 0; k + 1 < simplified.size(); ++k) out.emplace_back(simplified[k].x(), simplified[k].y());
}

}  // namespace

std::vector<glm::dvec2> simplify_line(const ShoreLine& line, double tolerance, const SimplifyLattice& lattice) {
    const std::vector<glm::dvec2>& points = line.points;
    const std::size_t n = points.size();
    if (n < 4 || tolerance <= 0.0) return points;
    // The vertices just past a lattice line: where the pieces start.
    std::vector<std::size_t> anchors;
    if (lattice.spacing > 0.0) {
        auto cell = [&](const glm::dvec2& p) { return glm::floor((p - lattice.corner) / lattice.spacing); };
        for (std::size_t k = line.closed ? 0 : 1; k < n; ++k)
            if (cell(points[k]) != cell(points[(k + n - 1) % n])) anchors.push_back(k);
    }
    std::vector<glm::dvec2> result;
    if (!line.closed) {
        // From the first vertex to the last, through each anchor.
        std::size_t from = 0;
        for (const std::size_t a : anchors) {
            simplify_piece(points, from, a, tolerance, result);
            from = a;
        }
        simplify_piece(points, from, n - 1, tolerance, result);
        result.push_back(points[n - 1]);
    } else if (anchors.empty()) {
        // Within one cell of the lattice: the loop returns to its first vertex.
        simplify_piece(points, 0, n, tolerance, result);
    } else {
        // From the first anchor round the loop back to it.
        for (std::size_t a = 0; a < anchors.size(); ++a) {
            const std::size_t to = a + 1 < anchors.size() ? anchors[a + 1] : anchors[0] + n;
            simplify_piece(points, anchors[a], to, tolerance, result);
        }
    }
    if (result.size() < (line.closed ? 3u : 2u)) return points;
    return result;
}

}  // namespace tidewater::detail
