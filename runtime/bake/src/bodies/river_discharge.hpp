// The river's current made to carry its discharge as a query reads it (private). The
// stream function gives h u on the texels, and its bilinear field carries Q through
// every section (bank texels hold half their faces' flux). A query, though, returns the
// bilinear depth and the texels' current weighted by their water columns (sample_river),
// whose product is the bilinear h u only where the four texels are wet: next to the
// banks, where the depth falls to zero within a texel and the bank texels' flux is not
// water the query finds, it falls short by 1.5 to 5 % on a river 8 texels wide. So the
// current is scaled, section by section along the channel, until the product
// integrates to what the h u field does.
#pragma once

#include <vector>

#include "bodies/stream_function.hpp"
#include "tidewater/detail/water_bodies.hpp"

namespace tidewater::detail {

/// What the section across the centreline `along` m from the source carries, m^3/s: by the h u field (all of
/// it) and by the query's depth times its current (where the query finds the river's
/// water and the depth is positive).
struct SectionDischarge {
    double field = 0.0, queried = 0.0;
    bool crosses_island = false;  ///< through land inside the channel (the stream problem's islands)
};
SectionDischarge section_discharge(const RiverBake& river, const std::vector<FlowCell>& cells, double along);

/// Scales `river`'s current (flow_x, flow_z) so that the queried discharge through
/// sections a quarter texel apart along the centreline is the field's (three passes, by
/// at most 10 % in all, 50 % across an island); between sections the scale is interpolated along the channel
/// (channel_s), past the mouth it is the mouth's. Needs the texels' kinds (mouths
/// marked), the depth, the h u field, the channel coordinates and the stream problem's
/// cells (its islands).
void match_queried_discharge(RiverBake& river, const std::vector<FlowCell>& cells);

}  // namespace tidewater::detail
