#include "bodies/river_blend.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tidewater::detail {

namespace {

double smoothstep01(double t) {
    t = std::clamp(t, 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

/// Distance from each texel to the nearest river texel, m: a two-pass 8-neighbour
/// chamfer (within 8% of the Euclidean distance, plenty for a blend).
std::vector<float> distance_to_river(const FieldGrid& g, const std::vector<std::uint8_t>& texel) {
    const float inf = std::numeric_limits<float>::infinity();
    const auto straight = static_cast<float>(g.texel), diagonal = static_cast<float>(g.texel * std::sqrt(2.0));
    std::vector<float> d(g.size(), inf);
    for (std::size_t t = 0; t < g.size(); ++t)
        if (texel[t] == static_cast<std::uint8_t>(RiverTexel::river)) d[t] = 0.0f;
    auto relax = [&](int i, int j, int di, int dj, float step) {
        const int a = i + di, b = j + dj;
        if (a < 0 || b < 0 || a >= g.nx || b >= g.nz) return;
        float& here = d[g.index(i, j)];
        here = std::min(here, d[g.index(a, b)] + step);
    };
    for (int j = 0; j < g.nz; ++j)
        for (int i = 0; i < g.nx; ++i) {
            relax(i, j, -1, 0, straight);
            relax(i, j, 0, -1, straight);
            relax(i, j, -1, -1, diagonal);
            relax(i, j, 1, -1, diagonal);
        }
    for (int j = g.nz - 1; j >= 0; --j)
        for (int i = g.nx - 1; i >= 0; --i) {
            relax(i, j, 1, 0, straight);
            relax(i, j, 0, 1, straight);
            relax(i, j, 1, 1, diagonal);
            relax(i, j, -1, 1, diagonal);
        }
    return d;
}

}  // namespace

void blend_with_still_water(const FieldGrid& g, const std::vector<std::uint8_t>& still, double blend_width,
                            std::vector<std::uint8_t>& texel, std::vector<float>& river_weight,
                            std::vector<float>& still_weight) {
    river_weight.assign(g.size(), 0.0f);
    still_weight.assign(g.size(), 0.0f);
    const std::vector<float> d = distance_to_river(g, texel);
    for (std::size_t t = 0; t < g.size(); ++t) {
        if (texel[t] == static_cast<std::uint8_t>(RiverTexel::river)) {
            river_weight[t] = 1.0f;
            continue;
        }
        if (!still[t]) continue;
        const double w = 1.0 - smoothstep01(static_cast<double>(d[t]) / blend_width);
        river_weight[t] = static_cast<float>(w);
        still_weight[t] = static_cast<float>(1.0 - w);
        if (w > 0.0) texel[t] = static_cast<std::uint8_t>(RiverTexel::plume);
    }
    // River water that blends: still water within two texels (the rest position of a
    // point moves by far less than a texel, and bilinear taps reach one texel).
    std::vector<std::uint8_t> mouth(g.size(), 0);
    for (int j = 0; j < g.nz; ++j)
        for (int i = 0; i < g.nx; ++i) {
            if (texel[g.index(i, j)] != static_cast<std::uint8_t>(RiverTexel::river)) continue;
            for (int b = std::max(j - 2, 0); b <= std::min(j + 2, g.nz - 1) && !mouth[g.index(i, j)]; ++b)
                for (int a = std::max(i - 2, 0); a <= std::min(i + 2, g.nx - 1); ++a)
                    if (still_weight[g.index(a, b)] > 0.0f) {
                        mouth[g.index(i, j)] = 1;
                        break;
                    }
        }
    for (std::size_t t = 0; t < g.size(); ++t)
        if (mouth[t]) texel[t] = static_cast<std::uint8_t>(RiverTexel::mouth);
}

}  // namespace tidewater::detail
