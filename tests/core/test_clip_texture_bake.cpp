// Distance textures baked from closed meshes (tidewater/clip_texture_bake.hpp): a ring's
// mesh against its exact distance, the sign whichever way the mesh is wound, and the
// meshes and files that are refused by name.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include "../clip_torus.hpp"
#include "test_helpers.hpp"
#include "tidewater/clip_texture_bake.hpp"

namespace tidewater {
namespace {

TEST(ClipTextureBake, ARingsMeshGivesTheRingsDistance) {
    const test::ClipTorus ring;
    TriangleMesh mesh;
    ring.mesh(96, 32, mesh.vertices, mesh.triangles);
    const TextureBox box = texture_box(mesh, 0.5);
    EXPECT_NEAR(box.half_extents.x, ring.major + ring.minor + 0.5, 1e-9);
    EXPECT_NEAR(box.half_extents.y, ring.minor + 0.5, 1e-9);
    auto texture = bake_distance_texture(mesh, box, {40, 12, 40});
    ASSERT_TRUE(texture.ok()) << texture.error().message;
    // At every sample, the exact distance to the ring within the mesh's facets' sag
    // (1.5 m (1 - cos(pi / 32)) and 5 m (1 - cos(pi / 96)): under 1 cm).
    const glm::uvec3 size = (*texture)->size();
    const glm::dvec3 step = 2.0 * box.half_extents / (glm::dvec3(size) - 1.0);
    double worst = 0.0;
    int inside = 0;
    for (unsigned k = 0; k < size.z; ++k)
        for (unsigned j = 0; j < size.y; ++j)
            for (unsigned i = 0; i < size.x; ++i) {
                const glm::dvec3 p = box.center - box.half_extents + step * glm::dvec3(i, j, k);
                const double d = (*texture)->distances()[i + size.x * (j + size.y * k)];
                worst = std::max(worst, std::abs(d - ring.distance(p)));
                inside += d < 0.0;
            }
    std::printf("a ring's mesh of %zu triangles: %d of %u samples inside, largest error %.4f m\n",
                mesh.triangles.size(), inside, size.x * size.y * size.z, worst);
    EXPECT_LT(worst, 0.012);
    EXPECT_GT(inside, 100);
    // Wound inward, the same texture: the sign comes from the surface, not its winding.
    TriangleMesh inward = mesh;
    for (auto& t : inward.triangles) std::swap(t[1], t[2]);
    auto again = bake_distance_texture(inward, box, {40, 12, 40});
    ASSERT_TRUE(again.ok()) << again.error().message;
    EXPECT_TRUE(
        std::equal((*texture)->distances().begin(), (*texture)->distances().end(), (*again)->distances().begin()));
}

TEST(ClipTextureBake, AnOpenMeshOrABadBoxIsRefused) {
    TriangleMesh mesh;
    test::ClipTorus{}.mesh(24, 12, mesh.vertices, mesh.triangles);
    const TextureBox box = texture_box(mesh, 0.5);
    TriangleMesh open = mesh;
    open.triangles.pop_back();
    auto refused = bake_distance_texture(open, box, {16, 8, 16});
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().message.find("not closed"), std::string::npos) << refused.error().message;
    EXPECT_FALSE(bake_distance_texture(mesh, box, {1, 8, 16}).ok());
    EXPECT_FALSE(bake_distance_texture(mesh, TextureBox{{0, 0, 0}, {0, 1, 1}}, {16, 8, 16}).ok());
    TriangleMesh out_of_range = mesh;
    out_of_range.triangles[3][1] = 100000;
    auto named = bake_distance_texture(out_of_range, box, {16, 8, 16});
    ASSERT_FALSE(named.ok());
    EXPECT_NE(named.error().message.find("vertex 100000"), std::string::npos);
}

TEST(ClipTextureBake, ObjFilesAreReadOrRefusedNamingTheFile) {
    test::TempDir dir;
    {
        std::ofstream obj(dir.path / "tetra.obj");
        obj << "# a tetrahedron with a quad-free face list\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
               "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
        std::ofstream quad(dir.path / "cube.obj");
        quad << "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n"
                "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";
        std::ofstream bad(dir.path / "bad.obj");
        bad << "v 0 0 0\nv 1 0 0\nf 1 2 9\n";
        std::ofstream empty(dir.path / "empty.obj");
        empty << "v 0 0 0\n";
    }
    auto tetra = read_obj_mesh(dir.path / "tetra.obj");
    ASSERT_TRUE(tetra.ok()) << tetra.error().message;
    EXPECT_EQ(tetra->triangles.size(), 4u);
    auto cube = read_obj_mesh(dir.path / "cube.obj");
    ASSERT_TRUE(cube.ok()) << cube.error().message;
    EXPECT_EQ(cube->triangles.size(), 12u) << "quads fanned into two triangles each";
    auto texture = bake_distance_texture(*cube, texture_box(*cube, 0.5), {9, 9, 9});
    ASSERT_TRUE(texture.ok()) << texture.error().message;
    EXPECT_NEAR((*texture)->distance({0.0, 0.0, 0.0}, glm::dvec3(1.5)), -1.0, 1e-6);  // the centre, a sample
    for (const char* name : {"bad.obj", "empty.obj", "missing.obj"}) {
        auto refused = read_obj_mesh(dir.path / name);
        ASSERT_FALSE(refused.ok()) << name;
        EXPECT_NE(refused.error().message.find(name), std::string::npos) << refused.error().message;
    }
}

}  // namespace
}  // namespace tidewater
