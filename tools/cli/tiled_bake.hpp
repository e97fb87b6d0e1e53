// `tidewater bake --tiles T --out DIR [--step contours|stitch|distances] [--task N | --status]
// [--merge]`: a scene's bake as a farmed job (farm_job.hpp, docs/scale-out.md, "Tiled
// bakes"), in three steps over T x T tiles of the distance field's grid
// (tiled_shore.hpp):
//   contours   an array, one unit per tile: the tile's cells of the shoreline's contour;
//   stitch     one job: the whole shoreline from every tile's cells;
//   distances  an array, one unit per tile: the tile's exact distances against the whole
//              shoreline.
// --merge then assembles the distance field, marches the shore model over it, bakes the
// lakes and rivers and writes DIR: the bake folder `"shore": {"bake": DIR}` loads (its
// shore.json indexes the model's tiles) with distance.vrt for GIS tools, the same bake a
// single `tidewater bake` writes. The steps' files live in DIR.job/; the job's options are
// kept in DIR.job/job.options and a step run with other options is refused. With no
// --step, --task, --status or --merge every step runs here in turn.
#pragma once

#include <string>

namespace tidewater::cli {

/// `tidewater bake`'s options; a bake is tiled when `tiles` > 0.
struct BakeArgs {
    std::string scene;
    std::string out;
    int tiles = 0;
    int resolution = 0;        ///< distance texels a side; 0: the scene's
    int model_resolution = 0;  ///< 0: the scene's
    double tolerance = 0.0;
    unsigned threads = 0;
    // A tiled bake's:
    std::string step;  ///< "", "contours", "stitch" or "distances"
    int task = -1;
    bool status = false, merge = false, quiet = false;
};

/// Runs what `a` asks for; returns the process's exit code (errors printed).
int run_tiled_bake(const BakeArgs& a);

}  // namespace tidewater::cli
