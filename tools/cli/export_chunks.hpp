// `tidewater inspect --export DIR --times t0:t1:dt --chunk-steps K [--task N | --status |
// --merge]`: a long export as a farmed job (farm_job.hpp, docs/scale-out.md). Chunk N
// holds steps N*K to N*K+K-1 and is one unit (a Slurm array task; under mpirun each
// chunk is exported by all the processes); the units live in DIR.job/ until the merge
// writes DIR, the same export a single run would. The job's options are kept in
// DIR.job/job.options: a task run with other options is refused.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>

#include "farm_job.hpp"
#include "tidewater/result.hpp"

namespace tidewater::cli {

struct ExportChunks {
    std::filesystem::path dir;    ///< the export's folder (DIR)
    std::size_t chunk_steps = 0;  ///< 0: not a chunked job
    int task = -1;                ///< -1: every chunk, then the merge
    bool status = false, merge = false;

    farm::JobFolder job() const { return farm::JobFolder(dir.string() + ".job"); }
    std::size_t chunks(std::size_t steps) const { return (steps + chunk_steps - 1) / chunk_steps; }
};

}  // namespace tidewater::cli
