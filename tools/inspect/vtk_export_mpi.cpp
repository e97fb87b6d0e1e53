// The ParaView export over the processes an MPI launcher started (mpirun, srun): each
// samples its band of the grid (VTK's extent split), VTK's MPI controller gathers the
// pieces' extents, and vtkXMLPStructuredGridWriter writes a piece per process plus one
// .pvts per step, which the .pvd lists. The one translation unit that uses MPI.
#include <fmt/format.h>
#include <vtkCommunicator.h>
#include <vtkExtentTranslator.h>
#include <vtkMPIController.h>
#include <vtkNew.h>
#include <vtkTrivialProducer.h>
#include <vtkXMLPStructuredGridWriter.h>

#include <cstdlib>
#include <fstream>
#include <string>

#include "tidewater/detail/atomic_folder.hpp"
#include "vtk_export_parts.hpp"
#include "vtk_output.hpp"

namespace tidewater::inspect {

namespace {

namespace fs = std::filesystem;
using namespace exporting;

/// Whether every process succeeded: each gives its own status, all learn the worst. A
/// process that failed keeps its own error; the others report that one failed.
Status agree(vtkMultiProcessController* c, const Status& mine, const char* what) {
    const int ok = mine ? 1 : 0;
    int all = 0;
    c->AllReduce(&ok, &all, 1, vtkCommunicator::MIN_OP);
    if (!mine) return mine;
    if (all == 0)
        return Error{ErrorCode::internal,
                     fmt::format("export: another MPI process failed {} (its error is above)", what)};
    return {};
}

/// Writes this process's piece of `sg` and, from process 0, the .pvts that joins them.
Status write_piece(vtkMPIController* c, vtkStructuredGrid* sg, const SampleGrid& whole, const fs::path& pvts) {
    vtkNew<vtkTrivialProducer> producer;
    producer->SetOutput(sg);
    producer->SetWholeExtent(0, whole.nx - 1, 0, whole.nz - 1, 0, 0);
    vtkNew<vtkXMLPStructuredGridWriter> writer;
    writer->SetController(c);
    writer->SetNumberOfPieces(c->GetNumberOfProcesses());
    writer->SetStartPiece(c->GetLocalProcessId());
    writer->SetEndPiece(c->GetLocalProcessId());
    writer->SetFileName(pvts.c_str());
    writer->SetInputConnection(producer->GetOutputPort());
    configure_writer(*writer);
    if (writer->Write() != 1 || writer->GetErrorCode() != 0)
        return Error{ErrorCode::io_error,
                     fmt::format("{}: VTK could not write piece {}", pvts.string(), c->GetLocalProcessId())};
    return {};
}

/// Every process's part of the export into `temp`, step by step in lockstep.
Status write_pieces(vtkMPIController* c, const fs::path& temp, const Scene& scene, const SampleGrid& whole,
                    const SampleGrid& piece, const std::vector<double>& times, unsigned threads,
                    const std::function<void(double)>& progress, ExportStats& stats, const ExportPart& part) {
    if (part.terrain)
        if (auto st = agree(c, write_piece(c, terrain_grid(scene, piece), whole, temp / "terrain.pvts"),
                            "writing the terrain");
            !st)
            return st;
    std::vector<std::string> files;
    for (std::size_t step = 0; step < times.size(); ++step) {
        auto t0 = std::chrono::steady_clock::now();
        auto sample = sample_field(scene, piece, times[step], threads);
        if (auto st = agree(c, sample ? Status{} : Status{sample.error()}, "sampling"); !st) return st;
        stats.sample_seconds += seconds_since(t0);
        t0 = std::chrono::steady_clock::now();
        files.push_back(step_name(part.first_step + step) + ".pvts");
        if (auto st = agree(c, write_piece(c, surface_grid(*sample), whole, temp / files.back()), "writing"); !st)
            return st;
        stats.write_seconds += seconds_since(t0);
        if (progress && c->GetLocalProcessId() == 0)
            progress(static_cast<double>(step + 1) / static_cast<double>(times.size()));
    }
    if (c->GetLocalProcessId() != 0 || !part.collection) return {};
    std::ofstream out(temp / "surface.pvd");
    out << pvd_text(times, files, "terrain.pvts");
    out.close();
    if (!out) return Error{ErrorCode::io_error, fmt::format("{}: write failed", (temp / "surface.pvd").string())};
    return {};
}

/// Sends process 0's `text` to every process.
std::string broadcast(vtkMultiProcessController* c, std::string text) {
    int length = static_cast<int>(text.size());
    c->Broadcast(&length, 1, 0);
    text.resize(static_cast<std::size_t>(length));
    if (length > 0) c->Broadcast(text.data(), length, 0);
    return text;
}

}  // namespace

struct MpiProcesses::Session {
    vtkNew<vtkMPIController> controller;
};

MpiProcesses::MpiProcesses() : session_(std::make_unique<Session>()) {
    session_->controller->Initialize(nullptr, nullptr);
    vtkMultiProcessController::SetGlobalController(session_->controller);
}

MpiProcesses::~MpiProcesses() {
    vtkMultiProcessController::SetGlobalController(nullptr);
    session_->controller->Finalize();
}

int MpiProcesses::rank() const {
    return session_->controller->GetLocalProcessId();
}

int MpiProcesses::ranks() const {
    return session_->controller->GetNumberOfProcesses();
}

bool started_by_mpi() {
    auto more_than_one = [](const char* name) {
        const char* v = std::getenv(name);
        return v != nullptr && std::atoi(v) > 1;
    };
    // Open MPI's mpirun and Hydra (MPICH) name the processes' count; Slurm's srun names its
    // step's tasks (a batch script's own process, or srun of one task, is not among others).
    return more_than_one("OMPI_COMM_WORLD_SIZE") || more_than_one("PMI_SIZE") ||
           ((std::getenv("PMIX_RANK") != nullptr || std::getenv("PMI_RANK") != nullptr) &&
            more_than_one("SLURM_STEP_NUM_TASKS"));
}

Status export_series_mpi(const MpiProcesses& mpi, const fs::path& dir, const Scene& scene, const SampleGrid& whole,
                         const std::vector<double>& times, unsigned threads,
                         const std::function<void(double)>& progress, ExportStats* stats_out, const ExportPart& part) {
    if (auto st = validate_grid(whole); !st) return st;
    if (times.empty()) return Error{ErrorCode::invalid_argument, "export: the time range holds no time"};
    if (dir.empty() || !dir.has_filename()) return Error{ErrorCode::invalid_argument, "export: give a folder name"};
    vtkMPIController* c = mpi.session().controller;
    int whole_extent[6] = {0, whole.nx - 1, 0, whole.nz - 1, 0, 0}, extent[6] = {};
    vtkNew<vtkExtentTranslator> split;
    split->PieceToExtentThreadSafe(mpi.rank(), mpi.ranks(), 0, whole_extent, extent, vtkExtentTranslator::BLOCK_MODE,
                                   0);
    const SampleGrid piece = whole.piece(extent[0], extent[1], extent[2], extent[3]);
    ExportStats stats;
    Status result;
    if (mpi.rank() == 0) {
        // Process 0 makes the temporary folder, tells the others where it is, and renames it
        // onto `dir` once every piece is in it; an empty path tells them there is none.
        bool told = false;
        result = detail::write_folder_atomically(dir, [&](const fs::path& temp) -> Status {
            broadcast(c, temp.string());
            told = true;
            if (auto st = write_pieces(c, temp, scene, whole, piece, times, threads, progress, stats, part); !st)
                return st;
            std::error_code ec;
            for (const auto& e : fs::directory_iterator(temp, ec))
                if (e.is_regular_file(ec)) stats.bytes += e.file_size(ec);
            return {};
        });
        if (!told) broadcast(c, "");
        const int ok = result ? 1 : 0;
        int all = ok;
        c->Broadcast(&all, 1, 0);
    } else {
        const std::string temp = broadcast(c, "");
        if (temp.empty()) {
            result = Error{ErrorCode::io_error,
                           fmt::format("{}: MPI process 0 could not make the export's folder", dir.string())};
        } else {
            result = write_pieces(c, temp, scene, whole, piece, times, threads, progress, stats, part);
            int all = 0;
            c->Broadcast(&all, 1, 0);
            if (result && all == 0)
                result = Error{ErrorCode::io_error,
                               fmt::format("{}: MPI process 0 could not finish the export", dir.string())};
        }
    }
    if (result && stats_out) *stats_out = stats;
    return result;
}

}  // namespace tidewater::inspect
