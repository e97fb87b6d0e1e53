// Shore models compared layer by layer, tile for tile (tests).
#pragma once

#include <gtest/gtest.h>

#include "tidewater/detail/shore_waves.hpp"

namespace tidewater::test {

/// True when `a` and `b` hold the same layers on the same grids with the same pages and
/// every slot bit for bit.
inline bool same_tiles(const ShoreWaves& a, const ShoreWaves& b) {
    if (!(a.grid() == b.grid()) || a.shared().pages != b.shared().pages || a.shared().floats() != b.shared().floats() ||
        a.layers().size() != b.layers().size())
        return false;
    for (std::size_t l = 0; l < a.layers().size(); ++l) {
        const ShoreWaveLayer &x = a.layers()[l], &y = b.layers()[l];
        if (!(x.grid == y.grid) || x.first != y.first || x.count != y.count || x.tiles.pages != y.tiles.pages ||
            x.tiles.floats() != y.tiles.floats())
            return false;
    }
    return true;
}

}  // namespace tidewater::test
