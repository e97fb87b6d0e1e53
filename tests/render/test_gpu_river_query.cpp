// CPU/GPU parity of world queries on a river scene, on lavapipe under the validation
// layer: a bending river whose width changes, falling to the sea, with the preset's
// waves riding its current and its flow detail. Heights within 1 mm, normals within
// 0.5 degrees, velocity (current + orbital) and current alone within 1 mm/s, the same body at every point,
// and the shader's flow-mapped detail against its CPU twin (tidewater::flow_detail).
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <random>

#include "../baked_scene.hpp"
#include "tidewater/constants.hpp"
#include "tidewater/render/gpu_query.hpp"
#include "tidewater/tidewater.hpp"
#include "vulkan_fixture.hpp"

namespace tidewater {
namespace {

class GpuRiverQueryTest : public test::VulkanTest {
  protected:
    void release() override { query_.reset(); }
    std::unique_ptr<render::GpuQuery> query_;
};

/// A river on a plane falling 4 m per km, bending and widening on its way to the sea
/// (the coast at x = 2500), with a lake-free world around it; the sea has its shore model.
const char* kRiverScene = R"({
  "version": 1, "name": "gpu-river", "water_level": 0.0,
  "terrain": { "plane": { "height": 10.0, "slope": [-0.004, 0.0] } },
  "ocean": "ocean_rolling",
  "shore": { "enabled": true, "resolution": 128 },
  "rivers": [ { "name": "bend", "path": [[-1500, 0], [-600, 120], [200, -80], [1200, 60], [2900, 40]],
                "width": [18, 24, 30, 36, 44], "discharge": 35.0, "manning": 0.032 } ]
})";

TEST_F(GpuRiverQueryTest, MatchesCpuWorldQueriesInARiverAndAtItsMouth) {
    auto q = render::GpuQuery::create(context());
    ASSERT_TRUE(q.ok()) << q.error().message;
    query_ = std::move(q).value();
    auto scene = test::baked(parse_scene(kRiverScene, "gpu-river.json"));
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    ASSERT_EQ(scene->rivers.size(), 1u);

    // Points along the centreline and across the channel, at the mouth, in the sea and on land.
    std::mt19937_64 rng(17);
    auto u = [&] { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
    const auto& path = scene->rivers[0].path;
    std::vector<glm::dvec2> pts;
    for (int i = 0; i < 6000; ++i) {
        const double f = u() * static_cast<double>(path.size() - 1);
        const auto seg = std::min(static_cast<std::size_t>(f), path.size() - 2);
        const glm::dvec2 a = path[seg], b = path[seg + 1];
        const glm::dvec2 t = glm::normalize(b - a);
        const glm::dvec2 across{-t.y, t.x};
        pts.push_back(a + (b - a) * (f - static_cast<double>(seg)) + across * (u() - 0.5) * 70.0);
    }
    for (int i = 0; i < 1500; ++i) pts.push_back({2300.0 + 500.0 * u(), -250.0 + 500.0 * u()});

    std::size_t bodies_in_river = 0, compared = 0, unconverged = 0;
    double height = 0.0, normal_deg = 0.0, velocity = 0.0, flow = 0.0, detail = 0.0, depth = 0.0, foam = 0.0;
    const FlowDetailSpec& spec = scene->rivers[0].body.profile().flow;
    for (double time : {3.0, 4321.5}) {
        std::vector<WorldPoint> cpu(pts.size()), dev(pts.size());
        std::vector<glm::dvec2> dev_detail(pts.size());
        ASSERT_TRUE(query_world(*scene, time, pts, cpu).ok());
        const Status st = query_->query_world(*scene, time, pts, dev, dev_detail);
        ASSERT_TRUE(st.ok()) << st.error().message;
        for (std::size_t i = 0; i < pts.size(); ++i) {
            ASSERT_EQ(cpu[i].body, dev[i].body) << i;
            flow = std::max(flow, glm::length(cpu[i].flow - dev[i].flow));
            if (cpu[i].body.kind == BodyKind::river) {
                ++bodies_in_river;
                const FlowDetailSample twin =
                    flow_detail(spec, pts[i], cpu[i].flow, scene->rivers[0].body.local_time(time));
                detail = std::max(detail, glm::length(twin.slope - dev_detail[i]));
            }
            const SurfacePoint &c = cpu[i].surface, &d = dev[i].surface;
            if (std::isfinite(c.depth)) depth = std::max(depth, std::abs(c.depth - d.depth));
            if (!c.converged || !d.converged) {
                ++unconverged;
                continue;
            }
            ++compared;
            height = std::max(height, std::abs(c.height - d.height));
            normal_deg =
                std::max(normal_deg, std::acos(std::clamp(glm::dot(c.normal, d.normal), -1.0, 1.0)) * 180.0 / kPi);
            velocity = std::max(velocity, glm::length(c.velocity - d.velocity));
            foam =
                std::max(foam, std::abs(c.foam - d.foam));  // the plume's lingering foam fades in with its still water
        }
    }
    std::printf(
        "river CPU/GPU parity on %s: %zu points compared (%zu unconverged, %zu in the river): max |dh| = %.3g m, "
        "max normal angle = %.3g deg, max |dv| = %.3g m/s, max |d flow| = %.3g m/s, max |d detail slope| = %.3g, "
        "max |d depth| = %.3g m, max |d foam| = %.3g\n",
        device_->device_name().c_str(), compared, unconverged, bodies_in_river, height, normal_deg, velocity, flow,
        detail, depth, foam);
    EXPECT_LE(foam, 0.01);
    EXPECT_GT(bodies_in_river, 4000u);
    EXPECT_LE(unconverged, pts.size() / 200);
    EXPECT_LE(height, 1e-3);
    EXPECT_LE(normal_deg, 0.5);
    EXPECT_LE(velocity, 1e-3);
    EXPECT_LE(flow, 1e-3);  // positions reach the shader in float: 0.25 mm at 4 km from the grid corner
    EXPECT_LE(depth, 1e-3);
    EXPECT_LE(detail, 1e-3 * spec.strength * spec.tiling * 10.0);  // 1% of the detail's slope scale
}

TEST_F(GpuRiverQueryTest, RefusesAnUnbakedRiverScene) {
    auto q = render::GpuQuery::create(context());
    ASSERT_TRUE(q.ok()) << q.error().message;
    query_ = std::move(q).value();
    auto scene = parse_scene(kRiverScene, "gpu-river.json");
    ASSERT_TRUE(scene.ok());
    std::vector<glm::dvec2> pts{{0.0, 0.0}};
    std::vector<WorldPoint> out(1);
    const Status st = query_->query_world(*scene, 0.0, pts, out);
    ASSERT_FALSE(st.ok());
    EXPECT_NE(st.error().message.find("bake_scene"), std::string::npos) << st.error().message;
}

}  // namespace
}  // namespace tidewater
