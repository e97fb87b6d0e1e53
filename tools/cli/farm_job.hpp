// A farmed job's output folder (docs/scale-out.md). A manifest lists units of work; each
// unit is one plain `tidewater VERB --manifest M --out DIR --task N` command, so that the
// same job runs under Slurm (sbatch --array), GNU parallel or a studio's farm. Unit N
// writes DIR/units/N/ whole or not at all, or, when it fails, DIR/units/N.failed with its
// error; a unit already done is skipped, so running a job again is safe. A merge reads
// every unit's folder once all are done. Threading: units of one job may run at once in
// separate processes (each writes only its own paths); one object is not shared between
// threads.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "tidewater/result.hpp"

namespace tidewater::cli::farm {

enum class UnitState { done, failed, missing };

struct UnitStatus {
    UnitState state = UnitState::missing;
    std::string error;  ///< the failure file's text (failed units)
};

class JobFolder {
  public:
    explicit JobFolder(std::filesystem::path out) : out_(std::move(out)) {}

    const std::filesystem::path& out() const { return out_; }
    /// DIR/units/N: the unit's output, whole once it exists.
    std::filesystem::path unit_folder(std::size_t task) const;
    /// DIR/units/N.failed: the error of the unit's last failed run.
    std::filesystem::path failure_file(std::size_t task) const;
    UnitStatus status(std::size_t task) const;

    /// Runs unit `task`: `work` fills a temporary folder that becomes the unit's folder when
    /// it succeeds (and the failure file goes); when it fails, the failure file is written
    /// with its error and the error is returned. A unit already done is not run again
    /// (`skipped` tells).
    Status run_unit(std::size_t task, const std::function<Status(const std::filesystem::path&)>& work,
                    bool& skipped) const;

    /// For units that write their folder themselves (whole or not at all): makes the units'
    /// parent folder, before the unit runs.
    Status prepare() const;
    /// Keeps a unit's outcome: on success its failure file goes; on failure the failure
    /// file gets the error, which is returned (with the failure file's own, if any).
    Status record_outcome(std::size_t task, const Status& outcome) const;

  private:
    std::filesystem::path out_;
};

/// What `--status` prints for a job of `units` units named by `describe(task)`: a line for
/// each unit not done (missing or failed, with its error), then "done: D of U", then
/// "todo: " and the tasks to submit again in sbatch --array's form ("2,5"), or "none".
std::string status_report(const JobFolder& job, std::size_t units,
                          const std::function<std::string(std::size_t)>& describe);

/// The tasks of `units` that are not done, as sbatch --array writes them ("0-3,7"), or "".
std::string array_spec(const std::vector<std::size_t>& tasks);

/// Fails naming every unit that is not done (for the merge), or succeeds.
Status require_all_done(const JobFolder& job, std::size_t units,
                        const std::function<std::string(std::size_t)>& describe);

/// Keeps the options that define the job (`options`, one line each) in job.options, or
/// checks them against the ones kept there; names the first that differs and says how to
/// start a new job (`new_job`, e.g. "another --export folder").
Status check_job_options(const JobFolder& job, const std::string& options, const std::string& new_job);

}  // namespace tidewater::cli::farm
