// Everything that includes CGAL lives in this file: the shoreline's polygons with
// holes and the AABB tree for exact distances.
#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_with_holes_2.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <atomic>
#include <boost/iterator/function_output_iterator.hpp>
#include <cmath>

#include "shore_geometry.hpp"
#include "simplify_line.hpp"
#include "tidewater/detail/parallel.hpp"

namespace tidewater::detail {

namespace {

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point2 = Epick::Point_2;
using Polygon = CGAL::Polygon_2<Epick>;
using PolygonWithHoles = CGAL::Polygon_with_holes_2<Epick>;

// CGAL 5.5's AABB tree is 3D: the shoreline lies in the plane z = 0.
using K3 = CGAL::Simple_cartesian<double>;
using Segment3 = K3::Segment_3;
using SegmentIterator = std::vector<Segment3>::const_iterator;
using Primitive = CGAL::AABB_segment_primitive<K3, SegmentIterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K3, Primitive>>;

}  // namespace

ClassifiedShore simplify_and_classify(std::vector<ShoreLine> lines, double tolerance, const SimplifyLattice& lattice,
                                      unsigned threads) {
    ClassifiedShore shore;
    // The lines are independent: simplify them in parallel.
    detail::parallel_for_each(lines.size(), threads,
                              [&](std::size_t k) { lines[k].points = simplify_line(lines[k], tolerance, lattice); });
    std::vector<Polygon> outers, holes;
    for (ShoreLine& line : lines) {
        if (line.closed && line.points.size() >= 3) {
            Polygon poly;
            for (const auto& p : line.points) poly.push_back(Point2(p.x, p.y));
            // Land on the left: a counter-clockwise loop encloses land, a clockwise one water.
            (poly.orientation() == CGAL::COUNTERCLOCKWISE ? outers : holes).push_back(std::move(poly));
        }
        shore.lines.push_back(std::move(line));
    }
    // Each enclosed water joins the smallest land polygon around it.
    std::vector<PolygonWithHoles> land;
    land.reserve(outers.size());
    for (auto& o : outers) land.emplace_back(o);
    std::vector<double> areas;
    std::vector<CGAL::Bbox_2> boxes;
    for (const auto& o : outers) {
        areas.push_back(CGAL::to_double(o.area()));
        boxes.push_back(o.bbox());
    }
    for (auto& h : holes) {
        int best = -1;
        const CGAL::Bbox_2 hb = h.bbox();
        for (std::size_t k = 0; k < outers.size(); ++k) {
            const CGAL::Bbox_2& b = boxes[k];
            if (hb.xmin() < b.xmin() || hb.xmax() > b.xmax() || hb.ymin() < b.ymin() || hb.ymax() > b.ymax()) continue;
            if (outers[k].bounded_side(h.vertex(0)) == CGAL::ON_BOUNDED_SIDE &&
                (best < 0 || areas[k] < areas[static_cast<std::size_t>(best)]))
                best = static_cast<int>(k);
        }
        if (best >= 0) land[static_cast<std::size_t>(best)].add_hole(h);  // clockwise, as CGAL expects
    }
    shore.polygons = land.size();
    shore.holes = holes.size();
    return shore;
}

struct ShoreDistance::Impl {
    std::vector<Segment3> segments;
    std::vector<Segment> flat;  // the same segments in 2D
    // Per segment: the left normals of its neighbours along the line (for the sign at vertices).
    std::vector<glm::dvec2> left_normal, prev_normal, next_normal;
    Tree tree;
};

ShoreDistance::ShoreDistance(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
ShoreDistance::~ShoreDistance() = default;

std::size_t ShoreDistance::segment_count() const {
    return impl_->segments.size();
}
const ShoreDistance::Segment& ShoreDistance::segment(std::size_t s) const {
    return impl_->flat[s];
}

std::unique_ptr<ShoreDistance> ShoreDistance::build(const std::vector<ShoreLine>& lines) {
    auto impl = std::make_unique<Impl>();
    for (const ShoreLine& line : lines) {
        const std::size_t n = line.points.size();
        const std::size_t count = line.closed ? n : n - 1;
        const std::size_t first = impl->segments.size();
        for (std::size_t k = 0; k < count; ++k) {
            const glm::dvec2 a = line.points[k], b = line.points[(k + 1) % n];
            impl->segments.emplace_back(K3::Point_3(a.x, a.y, 0.0), K3::Point_3(b.x, b.y, 0.0));
            impl->flat.push_back({a, b});
            const glm::dvec2 d = b - a;
            const double len = std::max(std::sqrt(d.x * d.x + d.y * d.y), 1e-300);
            impl->left_normal.push_back(glm::dvec2(-d.y, d.x) / len);
        }
        for (std::size_t k = 0; k < count; ++k) {
            const std::size_t prev = k > 0 ? k - 1 : (line.closed ? count - 1 : k);
            const std::size_t next = k + 1 < count ? k + 1 : (line.closed ? 0 : k);
            impl->prev_normal.push_back(impl->left_normal[first + prev]);
            impl->next_normal.push_back(impl->left_normal[first + next]);
        }
    }
    if (!impl->segments.empty()) {
        impl->tree.insert(impl->segments.cbegin(), impl->segments.cend());
        impl->tree.build();  // every query brings a neighbour's answer as a hint: no k-d tree needed
    }
    return std::unique_ptr<ShoreDistance>(new ShoreDistance(std::move(impl)));
}

ShoreDistance::Hit ShoreDistance::query(glm::dvec2 p, const Hit* hint) const {
    const Impl& m = *impl_;
    const K3::Point_3 q(p.x, p.y, 0.0);
    // The hint is a (point, primitive) pair: CGAL returns its primitive when nothing is closer.
    const auto result = hint ? m.tree.closest_point_and_primitive(
                                   q, std::make_pair(K3::Point_3(hint->closest.x, hint->closest.y, 0.0),
                                                     m.segments.cbegin() + static_cast<std::ptrdiff_t>(hint->segment)))
                             : m.tree.closest_point_and_primitive(q);
    return hit_on(p, static_cast<std::size_t>(result.second - m.segments.cbegin()));
}

void ShoreDistance::segments_within(glm::dvec2 p, double radius, std::vector<std::uint32_t>& out) const {
    const Impl& m = *impl_;
    if (m.segments.empty()) return;
    // CGAL's Sphere_3 queries test the sphere's surface, not the ball: query the ball's
    // box and keep what lies within the radius.
    const CGAL::Bbox_3 box(p.x - radius, p.y - radius, -1.0, p.x + radius, p.y + radius, 1.0);
    const auto first = m.segments.cbegin();
    const double r2 = radius * radius;
    m.tree.all_intersected_primitives(
        box, boost::make_function_output_iterator([&](SegmentIterator s) {
            const auto k = static_cast<std::size_t>(s - first);
            const glm::dvec2 a = m.flat[k].a, ab = m.flat[k].b - a;
            const double len2 = ab.x * ab.x + ab.y * ab.y;
            const double t = len2 > 0.0 ? std::clamp(((p.x - a.x) * ab.x + (p.y - a.y) * ab.y) / len2, 0.0, 1.0) : 0.0;
            const glm::dvec2 d = p - (a + t * ab);
            if (d.x * d.x + d.y * d.y <= r2) out.push_back(static_cast<std::uint32_t>(k));
        }));
}

ShoreDistance::Hit ShoreDistance::hit_on(glm::dvec2 p, std::size_t s) const {
    const Impl& m = *impl_;
    const glm::dvec2 a = m.flat[s].a, b = m.flat[s].b;
    const glm::dvec2 ab = b - a;
    const double len2 = ab.x * ab.x + ab.y * ab.y;
    const double t = len2 > 0.0 ? std::clamp(((p.x - a.x) * ab.x + (p.y - a.y) * ab.y) / len2, 0.0, 1.0) : 0.0;
    const glm::dvec2 c = a + t * ab;
    const glm::dvec2 away = p - c;
    const double dist = std::sqrt(away.x * away.x + away.y * away.y);
    // The side: the segment's left normal, or at a shared vertex the mean with its neighbour's.
    glm::dvec2 normal = m.left_normal[s];
    if (t <= 0.0) normal += m.prev_normal[s];
    if (t >= 1.0) normal += m.next_normal[s];
    const bool land = away.x * normal.x + away.y * normal.y > 0.0;
    Hit hit;
    hit.closest = c;
    hit.segment = s;
    hit.signed_distance = land ? -dist : dist;
    // On the line itself the gradient is the water-side normal: unit everywhere.
    hit.gradient = dist > 0.0 ? (land ? -1.0 : 1.0) * away / dist : -m.left_normal[s];
    return hit;
}

ShoreDistance::Hit ShoreDistance::hit_on(glm::dvec2 p, std::size_t s, bool water) const {
    Hit hit = hit_on(p, s);
    if ((hit.signed_distance > 0.0) != water) {
        hit.signed_distance = water ? std::abs(hit.signed_distance) : -std::abs(hit.signed_distance);
        hit.gradient = -impl_->left_normal[s];  // land is on the left
    }
    return hit;
}

}  // namespace tidewater::detail
