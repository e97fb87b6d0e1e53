#include "colour_maps.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string_view>

namespace tidewater::inspect {

namespace {

struct Stop {
    double t;
    glm::dvec3 rgb;
};

// matplotlib's viridis (van der Walt and Smith, 2015) at 17 even stops.
constexpr std::array<Stop, 17> kViridis = {{
    {0.0000, {0.267004, 0.004874, 0.329415}},
    {0.0625, {0.282327, 0.094955, 0.417331}},
    {0.1250, {0.278826, 0.175490, 0.483397}},
    {0.1875, {0.258965, 0.251537, 0.524736}},
    {0.2500, {0.229739, 0.322361, 0.545706}},
    {0.3125, {0.199430, 0.387607, 0.554642}},
    {0.3750, {0.172719, 0.448791, 0.557885}},
    {0.4375, {0.149039, 0.508051, 0.557250}},
    {0.5000, {0.127568, 0.566949, 0.550556}},
    {0.5625, {0.120638, 0.625828, 0.533488}},
    {0.6250, {0.157851, 0.683765, 0.501686}},
    {0.6875, {0.246070, 0.738910, 0.452024}},
    {0.7500, {0.369214, 0.788888, 0.382914}},
    {0.8125, {0.515992, 0.831158, 0.294279}},
    {0.8750, {0.678489, 0.863742, 0.189503}},
    {0.9375, {0.845561, 0.887322, 0.099702}},
    {1.0000, {0.993248, 0.906157, 0.143936}},
}};

// Moreland's smooth cool to warm (2009), ParaView's default diverging map, at 9 stops.
constexpr std::array<Stop, 9> kCoolWarm = {{
    {0.000, {0.229806, 0.298718, 0.753683}},
    {0.125, {0.386653, 0.499779, 0.890361}},
    {0.250, {0.552561, 0.688953, 0.995517}},
    {0.375, {0.711554, 0.819278, 0.979790}},
    {0.500, {0.865003, 0.865003, 0.865003}},
    {0.625, {0.958989, 0.767603, 0.678950}},
    {0.750, {0.957247, 0.595489, 0.471668}},
    {0.875, {0.869587, 0.378104, 0.286508}},
    {1.000, {0.705673, 0.015556, 0.150233}},
}};

template <std::size_t N>
glm::dvec3 interpolate(const std::array<Stop, N>& stops, double t) {
    t = std::clamp(std::isfinite(t) ? t : 0.0, 0.0, 1.0);
    for (std::size_t i = 1; i < N; ++i)
        if (t <= stops[i].t) {
            const double w = (t - stops[i - 1].t) / (stops[i].t - stops[i - 1].t);
            return stops[i - 1].rgb + w * (stops[i].rgb - stops[i - 1].rgb);
        }
    return stops[N - 1].rgb;
}

}  // namespace

FieldColouring colouring_for(const FieldInfo& field, double water_level) {
    const std::string_view name = field.name;
    if (name == "height") return {ColourMap::diverging, water_level};
    if (field.components == 1 && (name == "shore_distance" || name == "wake")) return {ColourMap::diverging, 0.0};
    return {ColourMap::sequential, 0.0};
}

std::pair<double, double> colour_range(const FieldColouring& colouring, double lo, double hi) {
    if (colouring.map == ColourMap::sequential) return {lo, hi};
    const double half = std::max({std::abs(lo - colouring.centre), std::abs(hi - colouring.centre), 1e-9});
    return {colouring.centre - half, colouring.centre + half};
}

glm::dvec3 map_colour(ColourMap map, double t) {
    return map == ColourMap::sequential ? interpolate(kViridis, t) : interpolate(kCoolWarm, t);
}

}  // namespace tidewater::inspect
