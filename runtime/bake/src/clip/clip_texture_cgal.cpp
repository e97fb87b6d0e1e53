// Everything of the distance-texture bake that includes CGAL: the OBJ reader, the mesh's
// closedness, and its AABB tree (distances) and side-of-mesh test (signs).
#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/IO/OBJ.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "tidewater/clip_texture_bake.hpp"
#include "tidewater/detail/parallel.hpp"

namespace tidewater {

namespace {

using K = CGAL::Simple_cartesian<double>;
using Point = K::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Primitive = CGAL::AABB_face_graph_triangle_primitive<Mesh>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;

}  // namespace

Result<TriangleMesh> read_obj_mesh(const std::filesystem::path& path) {
    const std::string name = path.string();
    if (!std::filesystem::is_regular_file(path))
        return Error{ErrorCode::io_error, fmt::format("{}: cannot open file", name)};
    std::vector<Point> points;
    std::vector<std::vector<std::size_t>> faces;
    if (!CGAL::IO::read_OBJ(name, points, faces))
        return Error{ErrorCode::parse_error, fmt::format("{}: not a readable OBJ file", name)};
    if (faces.empty()) return Error{ErrorCode::schema_error, fmt::format("{}: the OBJ file has no faces", name)};
    TriangleMesh mesh;
    for (const Point& p : points) {
        if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
            return Error{ErrorCode::schema_error,
                         fmt::format("{}: vertex {} is not finite", name, mesh.vertices.size())};
        mesh.vertices.emplace_back(p.x(), p.y(), p.z());
    }
    for (std::size_t f = 0; f < faces.size(); ++f) {
        const auto& face = faces[f];
        if (face.size() < 3)
            return Error{ErrorCode::schema_error, fmt::format("{}: face {} has {} corners", name, f, face.size())};
        for (std::size_t i : face)
            if (i >= points.size())
                return Error{ErrorCode::schema_error,
                             fmt::format("{}: face {} names vertex {} of {}", name, f, i + 1, points.size())};
        for (std::size_t k = 1; k + 1 < face.size(); ++k)
            mesh.triangles.push_back({static_cast<std::uint32_t>(face[0]), static_cast<std::uint32_t>(face[k]),
                                      static_cast<std::uint32_t>(face[k + 1])});
    }
    return mesh;
}

Result<std::shared_ptr<const DistanceTexture>> bake_distance_texture(const TriangleMesh& mesh, const TextureBox& box,
                                                                     glm::uvec3 size) {
    auto refuse = [](const std::string& what) {
        return Error{ErrorCode::invalid_argument, fmt::format("distance texture bake: {}", what)};
    };
    for (int c = 0; c < 3; ++c) {
        if (!(std::isfinite(box.half_extents[c]) && box.half_extents[c] > 0.0 && box.half_extents[c] <= 1e5) ||
            !std::isfinite(box.center[c]))
            return refuse("the box must be finite, its half extents 0 < value <= 1e5 m");
        if (size[c] < DistanceTexture::kMinSide || size[c] > DistanceTexture::kMaxSide)
            return refuse(fmt::format("{} samples along {}; each side has {} to {}", size[c], "xyz"[c],
                                      DistanceTexture::kMinSide, DistanceTexture::kMaxSide));
    }
    if (mesh.triangles.size() < 4) return refuse("a closed mesh needs at least 4 triangles");
    std::vector<Point> points;
    for (const glm::dvec3& v : mesh.vertices) points.emplace_back(v.x, v.y, v.z);
    std::vector<std::vector<std::size_t>> soup;
    for (const auto& t : mesh.triangles) {
        for (std::uint32_t i : t)
            if (i >= points.size()) return refuse(fmt::format("a triangle names vertex {} of {}", i, points.size()));
        soup.push_back({t[0], t[1], t[2]});
    }
    // Wound one way (the soup's own winding may be mixed), then a closed surface.
    namespace PMP = CGAL::Polygon_mesh_processing;
    PMP::orient_polygon_soup(points, soup);
    Mesh surface;
    PMP::polygon_soup_to_polygon_mesh(points, soup, surface);
    if (surface.number_of_faces() < 4 || !CGAL::is_closed(surface))
        return refuse("the mesh is not closed (an edge has one face, or more than two)");
    Tree tree(CGAL::faces(surface).first, CGAL::faces(surface).second, surface);
    tree.accelerate_distance_queries();
    const CGAL::Side_of_triangle_mesh<Mesh, K> side(surface);
    std::vector<float> distances(std::size_t{size.x} * size.y * size.z);
    const glm::dvec3 step = 2.0 * box.half_extents / (glm::dvec3(size) - 1.0);
    detail::parallel_for_each(size.z, 0, [&](std::size_t k) {
        for (std::uint32_t j = 0; j < size.y; ++j)
            for (std::uint32_t i = 0; i < size.x; ++i) {
                const glm::dvec3 p = box.center - box.half_extents + step * glm::dvec3(i, j, static_cast<double>(k));
                const Point q(p.x, p.y, p.z);
                const double d = std::sqrt(tree.squared_distance(q));
                const bool inside = side(q) == CGAL::ON_BOUNDED_SIDE;
                distances[i + size.x * (j + std::size_t{size.y} * k)] = static_cast<float>(inside ? -d : d);
            }
    });
    auto texture = DistanceTexture::create(size, std::move(distances));
    if (!texture) return refuse(texture.error().message);
    return texture;
}

}  // namespace tidewater
