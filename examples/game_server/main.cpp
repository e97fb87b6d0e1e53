// A game server: loads a scene whose "shore" names a saved bake, then asks which body
// a few points are in and how high the water stands there, as gameplay would each tick.
//   game_server SCENE.json [X Z]...
#include <cstdio>
#include <cstdlib>
#include <string>
#include <tidewater/baked_scene.hpp>
#include <tidewater/scene.hpp>
#include <tidewater/world_query.hpp>
#include <vector>

int main(int argc, char** argv) {
    if (argc < 2 || argc % 2 != 0) {
        std::fprintf(stderr, "usage: game_server SCENE.json [X Z]...\n");
        return 2;
    }
    auto parsed = tidewater::load_scene(argv[1]);
    if (!parsed) {
        std::fprintf(stderr, "game_server: %s\n", parsed.error().message.c_str());
        return 1;
    }
    // Loading only: a scene that needs baking and names no saved bake is refused.
    auto scene = tidewater::load_scene_bake(*parsed);
    if (!scene) {
        std::fprintf(stderr, "game_server: %s\n", scene.error().message.c_str());
        return 1;
    }
    std::vector<glm::dvec2> points;
    for (int i = 2; i + 1 < argc; i += 2) points.push_back({std::atof(argv[i]), std::atof(argv[i + 1])});
    if (points.empty()) points = {{0.0, 0.0}, {-900.0, 300.0}, {250.0, -400.0}};
    std::vector<tidewater::WorldPoint> out(points.size());
    const double time = 12.5;  // s
    if (auto st = tidewater::query_world(**scene, time, points, out); !st) {
        std::fprintf(stderr, "game_server: %s\n", st.error().message.c_str());
        return 1;
    }
    std::printf("game server: scene \"%s\" loaded from its saved bake (%s) in %.2f s\n", (*scene)->name.c_str(),
                (*scene)->bake && (*scene)->bake->loaded ? "loaded" : "nothing to load",
                (*scene)->bake ? (*scene)->bake->seconds : 0.0);
    for (std::size_t i = 0; i < points.size(); ++i)
        std::printf("  (%.1f, %.1f): %s, surface %.3f m\n", points[i].x, points[i].y,
                    out[i].body.kind == tidewater::BodyKind::none
                        ? "land"
                        : std::string(tidewater::body_name(**scene, out[i].body)).c_str(),
                    out[i].surface.height);
    return 0;
}
