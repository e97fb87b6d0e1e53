#include "bodies/river_discharge.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace tidewater::detail {

namespace {

/// Points a texel across a section: fine against the bilinear fields' texel.
inline constexpr double kSamplesPerTexel = 8.0;
/// How far past the half width a section reaches (the wet edge wanders a texel or so).
inline constexpr double kReachTexels = 3.0;
/// The most a section's scale may change the current, over all passes: more says the
/// section is not a clean crossing (a confluence, an island's tip, a sheet of water a
/// millimetre deep on a steep reach), and it is left nearer as it was.
inline constexpr double kMostScale = 1.1;
/// A section across an island crosses four waterlines, not two, each next to ground as
/// steep as the island's sides: it may be scaled further.
inline constexpr double kMostScaleAcrossIsland = 1.5;
/// Sections a texel along the channel: a texel's current weighs in the sections within
/// a texel of it, so the scales are taken finer than that.
inline constexpr double kSectionsPerTexel = 4.0;
/// Passes of scaling: each section's scale moves its neighbours' too; three settle them.
inline constexpr int kPasses = 3;

}  // namespace

SectionDischarge section_discharge(const RiverBake& river, const std::vector<FlowCell>& cells, double along) {
    const FieldGrid& g = river.grid;
    const std::vector<double>& a = river.along;
    const auto above = static_cast<std::size_t>(std::clamp<std::ptrdiff_t>(
        std::lower_bound(a.begin(), a.end(), along) - a.begin(), 1, static_cast<std::ptrdiff_t>(a.size()) - 1));
    const double w = std::clamp((along - a[above - 1]) / std::max(a[above] - a[above - 1], 1e-12), 0.0, 1.0);
    const glm::dvec2 p0 = river.centreline[above - 1] + w * (river.centreline[above] - river.centreline[above - 1]);
    const glm::dvec2 d = river.centreline[above] - river.centreline[above - 1];
    const double length = std::hypot(d.x, d.y);
    SectionDischarge out;
    if (!(length > 0.0)) return out;
    const glm::dvec2 t = d / length, n{-t.y, t.x};
    const double width = river.width[above - 1] + w * (river.width[above] - river.width[above - 1]);
    const double reach = 0.5 * width + kReachTexels * g.texel, step = g.texel / kSamplesPerTexel;
    const auto count = static_cast<int>(std::ceil(2.0 * reach / step));
    for (int m = 0; m <= count; ++m) {
        const glm::dvec2 p = p0 + (-reach + m * step) * n;
        if (!g.contains(p)) continue;
        out.field += (g.sample(river.discharge_x, p) * t.x + g.sample(river.discharge_z, p) * t.y) * step;
        int i = 0, j = 0;
        g.texel_of(p, i, j);
        if (cells[g.index(i, j)] == FlowCell::island) out.crosses_island = true;
        if (!river_water(river.texel[g.index(i, j)])) continue;
        const RiverSample at = sample_river(river, p);  // what the query reads
        if (at.depth > 0.0) out.queried += at.depth * (at.flow_x * t.x + at.flow_z * t.y) * step;
    }
    return out;
}

namespace {

/// Scales the current by each section's field over queried discharge, interpolated
/// along the channel between sections, `first` + `spacing` m apart; `total` holds each
/// section's scale so far, which stays within kMostScale of 1 over every pass
/// (kMostScaleAcrossIsland where the section crosses an island).
void scale_once(RiverBake& river, const std::vector<FlowCell>& cells, double first, double spacing,
                std::vector<double>& total) {
    const std::size_t stations = total.size();
    const double last = river.along.back();
    std::vector<double> scale(stations, 1.0);
    for (std::size_t m = 0; m < stations; ++m) {
        const SectionDischarge q =
            section_discharge(river, cells, std::min(first + static_cast<double>(m) * spacing, last));
        if (!(q.field > 0.0 && q.queried > 0.0)) continue;
        const double most = q.crosses_island ? kMostScaleAcrossIsland : kMostScale;
        const double wanted = std::clamp(total[m] * q.field / q.queried, 1.0 / most, most);
        scale[m] = wanted / total[m];
        total[m] = wanted;
    }
    for (std::size_t t = 0; t < river.flow_x.size(); ++t) {
        if (river.flow_x[t] == 0.0f && river.flow_z[t] == 0.0f) continue;
        const double x = std::clamp((static_cast<double>(river.channel_s[t]) - first) / spacing, 0.0,
                                    static_cast<double>(stations - 1));
        const auto m = std::min(static_cast<std::size_t>(x), stations - 1);
        const double w = x - static_cast<double>(m);
        const double f = m + 1 < stations ? (1.0 - w) * scale[m] + w * scale[m + 1] : scale[m];
        river.flow_x[t] = static_cast<float>(static_cast<double>(river.flow_x[t]) * f);
        river.flow_z[t] = static_cast<float>(static_cast<double>(river.flow_z[t]) * f);
    }
}

}  // namespace

void match_queried_discharge(RiverBake& river, const std::vector<FlowCell>& cells) {
    const std::size_t samples = river.centreline.size();
    if (samples < 2 || river.along.size() != samples) return;
    const double first = river.along.front(), last = river.along.back();
    const double spacing = river.grid.texel / kSectionsPerTexel;
    std::vector<double> total(static_cast<std::size_t>(std::ceil((last - first) / spacing)) + 1, 1.0);
    for (int pass = 0; pass < kPasses; ++pass) scale_once(river, cells, first, spacing, total);
}

}  // namespace tidewater::detail
