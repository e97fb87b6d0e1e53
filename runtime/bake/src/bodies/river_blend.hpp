// Where a river meets still water (a lake or the ocean), its waves hand over to the
// still water's within one blend width, so the surface has no seam at the mouth or
// along the shore beside it (private).
#pragma once

#include <cstdint>
#include <vector>

#include "tidewater/detail/water_bodies.hpp"

namespace tidewater::detail {

/// From the river's texels (RiverTexel) and which texels are the still water it runs into,
/// the weights of the river's waves (1 in its water, falling to 0 over `blend_width` m of
/// still water) and of the still water's own (1 - that, on still water only; 0 on land
/// and in the river). Still texels within the blend become plume texels; river texels
/// within two texels of still water become mouth texels (their evaluation blends too).
void blend_with_still_water(const FieldGrid& grid, const std::vector<std::uint8_t>& still, double blend_width,
                            std::vector<std::uint8_t>& texel, std::vector<float>& river_weight,
                            std::vector<float>& still_weight);

}  // namespace tidewater::detail
