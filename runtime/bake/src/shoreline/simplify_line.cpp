#include "simplify_line.hpp"

#include <boost/geometry/algorithms/simplify.hpp>
#include <boost/geometry/geometries/linestring.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <boost/geometry/strategies/strategies.hpp>

namespace tidewater::detail {

namespace bg = boost::geometry;
using Point = bg::model::d2::point_xy<double>;
using Linestring = bg::model::linestring<Point>;

std::vector<glm::dvec2> simplify_line(const ShoreLine& line, double tolerance) {
    if (line.points.size() < 4 || tolerance <= 0.0) return line.points;
    Linestring in, out;
    in.reserve(line.points.size() + 1);
    for (const auto& p : line.points) in.emplace_back(p.x, p.y);
    if (line.closed) in.push_back(in.front());  // the loop returns to its first vertex
    bg::simplify(in, out, tolerance);
    if (line.closed && out.size() > 1) out.pop_back();
    if (out.size() < (line.closed ? 3u : 2u)) return line.points;
    std::vector<glm::dvec2> result;
    result.reserve(out.size());
    for (const Point& p : out) result.emplace_back(p.x(), p.y());
    return result;
}

}  // namespace tidewater::detail
