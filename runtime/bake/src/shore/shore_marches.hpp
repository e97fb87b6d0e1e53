// What a shore bake with the parabolic march keeps so that a stroke on the seabed can be
// re-baked where it reaches (shore_water_edit.cpp) instead of in full: per run of waves,
// its grid's depths, the march's records (what the cap blended into the amplitudes and
// the foam summed) and each wave's kept march (shore_diffraction.hpp); the random sea's
// march, whose height every component breaks at; and the cap's ratio per texel of the
// shared tiles, from which the foam is made again where only a march moved. Kept when asked
// (SceneBakeOptions::keep_marches: an editor's), about 100 MB for 24 waves on an 8 km
// island. Immutable once made; an edit makes a new one that shares what it did not
// change. Private to the bake.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

#include "shore/march_record.hpp"
#include "shore/shore_diffraction.hpp"
#include "tidewater/detail/shore_bake.hpp"
#include "tidewater/waves.hpp"

namespace tidewater::detail {

/// One run of waves (a layer of the model, in its order).
struct RunMarches {
    std::shared_ptr<const ShoreField> field;             ///< the run's grid and its depths
    MarchedAmplitudes marched;                           ///< per stored texel and wave
    MarchedEnergy energy;                                ///< per texel of the grid
    std::vector<std::shared_ptr<const KeptMarch>> kept;  ///< per wave of the run
    std::vector<double> spacing;                         ///< per wave, its march's spacing (m)
};

/// The random sea marched as one wave, on run `run`'s grid.
struct SeaMarch {
    Wave whole;
    std::size_t run = 0;
    SeaHeight height;
    std::shared_ptr<const KeptMarch> kept;
};

struct ShoreMarches {
    SeaState sea;
    std::vector<RunMarches> runs;
    std::optional<SeaMarch> sea_march;
    CapRatios ratios;  ///< per stored texel of the shared tiles
};

}  // namespace tidewater::detail
