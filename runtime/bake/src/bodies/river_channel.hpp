// A river's channel on its own grid (private): which texels are its water, the surface
// and carved bed there, and the current from the stream function.
#pragma once

#include "bodies/river_profile.hpp"

namespace tidewater::detail {

/// A tributary joining this river: its water enters over `width` around `along`.
struct Inflow {
    double along = 0.0;      ///< m along this river
    double width = 0.0;      ///< the tributary's width there, m
    double discharge = 0.0;  ///< m^3/s
    int side = -1;           ///< +1: from the left (n > 0), -1: from the right
    /// The part of its discharge that has entered by `at` m along this river: it enters
    /// evenly over its width.
    double entered(double at) const {
        const double ramp = (at - (along - 0.5 * width)) / width;
        return discharge * (ramp < 0.0 ? 0.0 : ramp > 1.0 ? 1.0 : ramp);
    }
};

struct ChannelInputs {
    const Terrain* terrain = nullptr;  ///< with the cuts of the rivers baked before
    double texel = 1.0;                ///< m
    bool carve = true;
    std::vector<double> centre_depth;  ///< carved h_c per sample (bake_profile)
    double psi_left = 0.0;             ///< psi on the left bank at the source, m^3/s
    std::vector<Inflow> inflows;
    /// Beyond a lake or ocean mouth the current fades out over this length, m (0: none).
    double plume_length = 0.0;
    /// Still water of the body the river runs into, for the plume (null: none).
    std::function<bool(glm::dvec2, double terrain_height)> in_receiver;
    /// Water of the river it runs into: this river's texels there are not its own.
    const RiverBake* receiver_river = nullptr;
};

/// psi on the left (+1) or right (-1) bank at `along`.
double bank_psi(const ChannelInputs& in, double own_discharge, double along, int side);

/// Fills `river`'s grid fields from its centreline (bake_profile) and `in`.
Status bake_channel(const ChannelInputs& in, RiverBake& river);

}  // namespace tidewater::detail
