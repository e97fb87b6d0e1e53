// The river's current made to carry its discharge as a query reads it (private). The
// stream function gives h u on the texels, and its bilinear field carries Q through
// every section (bank texels hold half their faces' flux). A query, though, returns the
// bilinear depth and the texels' current weighted by their water columns (sample_river),
// whose product is the bilinear h u only where the four texels are wet: next to the
// banks, where the depth falls to zero within a texel and the bank texels' flux is not
// water the query finds, it falls short by 1.5 to 5 % on a river 8 texels wide, and by
// 15 % on a tight bend of a steep reach. So each texel's current is scaled until the
// product carries the river's discharge through every section.
#pragma once

#include <span>
#include <vector>

#include "bodies/river_channel.hpp"
#include "bodies/stream_function.hpp"
#include "tidewater/detail/water_bodies.hpp"

namespace tidewater::detail {

/// Scales `river`'s current (flow_x, flow_z), texel by texel, so that the queried
/// discharge through sections a quarter texel apart along the centreline is the river's
/// (its own, and each tributary's once joined; the h u field's within a tributary's
/// mouth): the least-squares change of the texels' factors, the smallest that matches
/// every section, each factor within [1/4, 1.5] (one past a bound is held there
/// and the others solved again). Past a lake or sea mouth the sections
/// run on into the plume, where the query reads the river's current in the still water:
/// its points count with the river's, and past the mouth the h u field's flux is matched.
/// A section the query misses by more than 20 % (50 % across an island) is not a clean
/// crossing (a tributary's last texel) and is left out. Needs the texels' kinds (mouths and plume marked), the
/// depth, the h u field and the stream problem's cells (its islands).
void match_queried_discharge(RiverBake& river, const std::vector<FlowCell>& cells, std::span<const Inflow> inflows);

}  // namespace tidewater::detail
