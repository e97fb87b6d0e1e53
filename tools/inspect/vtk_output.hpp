// The inspector's VTK side: ParaView files and offscreen pictures of sampled fields.
// VTK is included only by the vtk_*.cpp files; MPI only by vtk_export_mpi.cpp.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "field_sampler.hpp"
#include "probe.hpp"

namespace tidewater::inspect {

/// Where an export's time went (for the benchmark figures).
struct ExportStats {
    double sample_seconds = 0.0;  ///< Queries.
    double write_seconds = 0.0;   ///< Building VTK data and writing it.
    std::uintmax_t bytes = 0;     ///< Size of the folder written.
};

/// Which part of a longer export to write (a chunk of a farmed export): its steps are
/// numbered from `first_step`; the terrain and the .pvd are written only when asked.
struct ExportPart {
    std::size_t first_step = 0;
    bool terrain = true, collection = true;
};

/// Writes `dir` whole or not at all: surface_NNNN.vts per time (a structured grid of
/// the displaced surface with every field_infos() array and their units in the field
/// data), terrain.vts, and surface.pvd, the time collection ParaView opens.
Status export_series(const std::filesystem::path& dir, const Scene& scene, const SampleGrid& grid,
                     const std::vector<double>& times, unsigned threads,
                     const std::function<void(double)>& progress = {}, ExportStats* stats = nullptr,
                     const ExportPart& part = {});

/// The export of `times` from its chunks' folders (each written by export_series or
/// export_series_mpi with ExportPart{first step, terrain in the first only, no .pvd}), in
/// order: every file linked (or copied) into `dir`, and surface.pvd listing the steps.
/// `dir` appears whole or not at all; the chunks' folders are left as they were.
Status merge_export_chunks(const std::filesystem::path& dir, const std::vector<std::filesystem::path>& chunks,
                           const std::vector<double>& times);

/// Whether an MPI launcher (mpirun, mpiexec, srun) started this process among others.
bool started_by_mpi();

/// MPI in a process an MPI launcher started: initialised on construction, finalised on
/// destruction. One per process, alive while its parallel exports run (MPI cannot be
/// initialised twice). Not copyable; used from one thread.
class MpiProcesses {
  public:
    MpiProcesses();
    ~MpiProcesses();
    MpiProcesses(const MpiProcesses&) = delete;
    MpiProcesses& operator=(const MpiProcesses&) = delete;
    int rank() const;
    int ranks() const;
    struct Session;
    Session& session() const { return *session_; }

  private:
    std::unique_ptr<Session> session_;
};

/// export_series over the processes an MPI launcher started, every one calling it with
/// the same arguments: each samples its band of the grid (VTK's block split) and writes
/// it as a piece; per time step surface_NNNN.pvts joins the pieces surface_NNNN_R.vts,
/// terrain.pvts the terrain's, and surface.pvd lists them. Read back (ParaView, VTK's
/// parallel reader) it equals the serial export, array for array. `dir` appears whole
/// or not at all (process 0 renames it into place once every piece is written; the
/// folder must be on a file system every process sees). A process's `stats` are its
/// own share; process 0's `bytes` is the whole folder's.
Status export_series_mpi(const MpiProcesses& mpi, const std::filesystem::path& dir, const Scene& scene,
                         const SampleGrid& grid, const std::vector<double>& times, unsigned threads,
                         const std::function<void(double)>& progress = {}, ExportStats* stats = nullptr,
                         const ExportPart& part = {});

struct ScreenshotOptions {
    std::string field = "height";
    int width = 1280, height = 720;
    bool glyphs = false;            ///< Arrows of the current (field "flow") or else the velocity.
    std::vector<glm::dvec2> track;  ///< A path (x, z) drawn on the water, such as a drift track, m.
};

/// The viewer's picture of `field` at `time`, offscreen, to a PNG (written whole or not
/// at all): the warped surface coloured by the field with its legend (name and unit),
/// the terrain and the shoreline. Needs an X display (xvfb-run without one).
Status screenshot(const Scene& scene, const SampleGrid& grid, double time, const ScreenshotOptions& options,
                  const std::filesystem::path& png);

/// The probe chart: height against time beside its spectrum, offscreen, to a PNG.
Status probe_chart(const ProbeSeries& probe, const std::filesystem::path& png, int width = 1200, int height = 420);

/// A measured record and a model's prediction at the same place on one chart, to a PNG.
Status overlay_chart(const std::vector<double>& axis, const std::vector<double>& measured,
                     const std::vector<double>& model, const std::string& title, const std::string& x_title,
                     const std::filesystem::path& png, int width = 1200, int height = 420);

}  // namespace tidewater::inspect
