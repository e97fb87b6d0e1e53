// ParaView export: .vts per time step and a .pvd collection (VTK's XML writers).
#include <fmt/format.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkStringArray.h>
#include <vtkStructuredGrid.h>
#include <vtkXMLStructuredGridWriter.h>

#include <chrono>
#include <fstream>

#include "tidewater/detail/atomic_folder.hpp"
#include "vtk_export_parts.hpp"
#include "vtk_output.hpp"

namespace tidewater::inspect {

namespace exporting {

vtkNew<vtkStructuredGrid> make_grid(const SampleGrid& grid, const std::vector<glm::dvec3>& positions) {
    vtkNew<vtkStructuredGrid> sg;
    sg->SetExtent(grid.first_i, grid.first_i + grid.nx - 1, grid.first_j, grid.first_j + grid.nz - 1, 0, 0);
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(static_cast<vtkIdType>(positions.size()));
    for (std::size_t k = 0; k < positions.size(); ++k)
        points->SetPoint(static_cast<vtkIdType>(k), positions[k].x, positions[k].y, positions[k].z);
    sg->SetPoints(points);
    return sg;
}

vtkNew<vtkStructuredGrid> terrain_grid(const Scene& scene, const SampleGrid& grid) {
    const std::vector<double> ground = sample_terrain(scene, grid);
    std::vector<glm::dvec3> positions(grid.points());
    for (int j = 0; j < grid.nz; ++j)
        for (int i = 0; i < grid.nx; ++i) {
            const std::size_t k = grid.index(i, j);
            const glm::dvec2 p = grid.point(i, j);
            positions[k] = {p.x, ground[k], p.y};
        }
    return make_grid(grid, positions);
}

vtkNew<vtkStructuredGrid> surface_grid(const FieldSample& sample) {
    const SampleGrid& grid = sample.grid;
    auto sg = make_grid(grid, sample.surface);
    for (const FieldInfo& f : field_infos()) {
        vtkNew<vtkDoubleArray> a;
        a->SetName(f.name);
        a->SetNumberOfComponents(f.components);
        a->SetNumberOfTuples(static_cast<vtkIdType>(grid.points()));
        double* out = a->WritePointer(0, static_cast<vtkIdType>(grid.points()) * f.components);
        for (std::size_t k = 0; k < grid.points(); ++k)
            for (int c = 0; c < f.components; ++c)
                out[k * static_cast<std::size_t>(f.components) + static_cast<std::size_t>(c)] =
                    sample.value(f.name, k, c);
        sg->GetPointData()->AddArray(a);
    }
    vtkNew<vtkStringArray> names;
    names->SetName("body_names");  // body id k is names[k]
    for (const std::string& b : sample.body_names) names->InsertNextValue(b);
    sg->GetFieldData()->AddArray(names);
    vtkNew<vtkStringArray> units;
    units->SetName("units");
    for (const FieldInfo& f : field_infos())
        units->InsertNextValue(fmt::format("{}: {} ({})", f.name, f.unit, f.meaning));
    sg->GetFieldData()->AddArray(units);
    vtkNew<vtkDoubleArray> t;
    t->SetName("TimeValue");
    t->InsertNextValue(sample.time);
    sg->GetFieldData()->AddArray(t);
    return sg;
}

void configure_writer(vtkXMLWriter& writer) {
    writer.SetDataModeToAppended();
    writer.EncodeAppendedDataOff();
    writer.SetCompressorTypeToLZ4();
}

std::string step_name(std::size_t step) {
    return fmt::format("surface_{:04}", step);
}

std::string pvd_text(const std::vector<double>& times, const std::vector<std::string>& step_files,
                     const std::string& terrain_file) {
    std::string pvd = "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n  <Collection>\n";
    for (std::size_t step = 0; step < times.size(); ++step)
        pvd +=
            fmt::format("    <DataSet timestep=\"{:.9g}\" part=\"0\" file=\"{}\"/>\n", times[step], step_files[step]);
    pvd += fmt::format("    <DataSet timestep=\"0\" part=\"1\" file=\"{}\"/>\n  </Collection>\n</VTKFile>\n",
                       terrain_file);
    return pvd;
}

}  // namespace exporting

namespace {

namespace fs = std::filesystem;
using namespace exporting;

Status write(vtkStructuredGrid* sg, const fs::path& path) {
    vtkNew<vtkXMLStructuredGridWriter> writer;
    writer->SetFileName(path.c_str());
    writer->SetInputData(sg);
    configure_writer(*writer);
    if (writer->Write() != 1)
        return Error{ErrorCode::io_error, fmt::format("{}: VTK could not write the file", path.string())};
    return {};
}

Status write_series(const fs::path& temp, const Scene& scene, const SampleGrid& grid, const std::vector<double>& times,
                    unsigned threads, const std::function<void(double)>& progress, ExportStats& stats,
                    const ExportPart& part) {
    if (part.terrain)
        if (auto st = write(terrain_grid(scene, grid), temp / "terrain.vts"); !st) return st;
    std::vector<std::string> files;
    for (std::size_t step = 0; step < times.size(); ++step) {
        auto t0 = std::chrono::steady_clock::now();
        auto sample = sample_field(scene, grid, times[step], threads);
        if (!sample) return sample.error();
        stats.sample_seconds += seconds_since(t0);
        t0 = std::chrono::steady_clock::now();
        files.push_back(step_name(part.first_step + step) + ".vts");
        if (auto st = write(surface_grid(*sample), temp / files.back()); !st) return st;
        stats.write_seconds += seconds_since(t0);
        if (progress) progress(static_cast<double>(step + 1) / static_cast<double>(times.size()));
    }
    if (!part.collection) return {};
    std::ofstream out(temp / "surface.pvd");
    out << pvd_text(times, files, "terrain.vts");
    out.close();
    if (!out) return Error{ErrorCode::io_error, fmt::format("{}: write failed", (temp / "surface.pvd").string())};
    return {};
}

}  // namespace

Status export_series(const fs::path& dir, const Scene& scene, const SampleGrid& grid, const std::vector<double>& times,
                     unsigned threads, const std::function<void(double)>& progress, ExportStats* stats_out,
                     const ExportPart& part) {
    if (auto st = validate_grid(grid); !st) return st;
    if (times.empty()) return Error{ErrorCode::invalid_argument, "export: the time range holds no time"};
    if (dir.empty() || !dir.has_filename()) return Error{ErrorCode::invalid_argument, "export: give a folder name"};
    ExportStats stats;
    auto st = detail::write_folder_atomically(dir, [&](const fs::path& temp) -> Status {
        if (auto written = write_series(temp, scene, grid, times, threads, progress, stats, part); !written)
            return written;
        std::error_code ec;
        for (const auto& e : fs::directory_iterator(temp, ec))
            if (e.is_regular_file(ec)) stats.bytes += e.file_size(ec);
        return {};
    });
    if (st && stats_out) *stats_out = stats;
    return st;
}

Status merge_export_chunks(const fs::path& dir, const std::vector<fs::path>& chunks, const std::vector<double>& times) {
    if (dir.empty() || !dir.has_filename()) return Error{ErrorCode::invalid_argument, "export: give a folder name"};
    return detail::write_folder_atomically(dir, [&](const fs::path& temp) -> Status {
        for (const fs::path& chunk : chunks) {
            std::error_code ec;
            for (const auto& e : fs::directory_iterator(chunk, ec)) {
                if (!e.is_regular_file(ec)) continue;
                const fs::path to = temp / e.path().filename();
                // A hard link costs no copy; across file systems the file is copied.
                fs::create_hard_link(e.path(), to, ec);
                if (ec) fs::copy_file(e.path(), to, ec);
                if (ec)
                    return Error{ErrorCode::io_error, fmt::format("{}: cannot link or copy it into {}: {}",
                                                                  e.path().string(), dir.string(), ec.message())};
            }
            if (ec) return Error{ErrorCode::io_error, fmt::format("{}: cannot read: {}", chunk.string(), ec.message())};
        }
        auto present = [&](const std::string& stem) -> Result<std::string> {
            for (const char* ext : {".pvts", ".vts"})
                if (fs::exists(temp / (stem + ext))) return stem + ext;
            return Error{ErrorCode::not_found,
                         fmt::format("{}: no {}.vts or .pvts among the chunks' files", dir.string(), stem)};
        };
        std::vector<std::string> files;
        for (std::size_t step = 0; step < times.size(); ++step) {
            auto file = present(step_name(step));
            if (!file) return file.error();
            files.push_back(*file);
        }
        auto terrain = present("terrain");
        if (!terrain) return terrain.error();
        std::ofstream out(temp / "surface.pvd");
        out << pvd_text(times, files, *terrain);
        out.close();
        if (!out) return Error{ErrorCode::io_error, fmt::format("{}: write failed", (temp / "surface.pvd").string())};
        return {};
    });
}

}  // namespace tidewater::inspect
