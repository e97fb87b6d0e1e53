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
#include "vtk_output.hpp"

namespace tidewater::inspect {

namespace {

namespace fs = std::filesystem;

/// A structured grid over `grid` with the given point heights.
vtkNew<vtkStructuredGrid> make_grid(const SampleGrid& grid, const std::vector<glm::dvec3>& positions) {
    vtkNew<vtkStructuredGrid> sg;
    sg->SetDimensions(grid.nx, grid.nz, 1);
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(static_cast<vtkIdType>(positions.size()));
    for (std::size_t k = 0; k < positions.size(); ++k)
        points->SetPoint(static_cast<vtkIdType>(k), positions[k].x, positions[k].y, positions[k].z);
    sg->SetPoints(points);
    return sg;
}

void add_units(vtkStructuredGrid* sg, double time, const std::vector<std::string>& bodies) {
    vtkNew<vtkStringArray> names;
    names->SetName("body_names");  // body id k is names[k]
    for (const std::string& b : bodies) names->InsertNextValue(b);
    sg->GetFieldData()->AddArray(names);
    vtkNew<vtkStringArray> units;
    units->SetName("units");
    for (const FieldInfo& f : field_infos())
        units->InsertNextValue(fmt::format("{}: {} ({})", f.name, f.unit, f.meaning));
    sg->GetFieldData()->AddArray(units);
    vtkNew<vtkDoubleArray> t;
    t->SetName("TimeValue");
    t->InsertNextValue(time);
    sg->GetFieldData()->AddArray(t);
}

Status write(vtkStructuredGrid* sg, const fs::path& path) {
    vtkNew<vtkXMLStructuredGridWriter> writer;
    writer->SetFileName(path.c_str());
    writer->SetInputData(sg);
    // Raw appended binary with LZ4: several times faster to write than base64 + zlib.
    writer->SetDataModeToAppended();
    writer->EncodeAppendedDataOff();
    writer->SetCompressorTypeToLZ4();
    if (writer->Write() != 1)
        return Error{ErrorCode::io_error, fmt::format("{}: VTK could not write the file", path.string())};
    return {};
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

Status write_series(const fs::path& temp, const Scene& scene, const SampleGrid& grid, const std::vector<double>& times,
                    unsigned threads, const std::function<void(double)>& progress, ExportStats& stats) {
    // The terrain: a second surface.
    const std::vector<double> ground = sample_terrain(scene, grid);
    std::vector<glm::dvec3> terrain_points(grid.points());
    for (int j = 0; j < grid.nz; ++j)
        for (int i = 0; i < grid.nx; ++i) {
            const std::size_t k = grid.index(i, j);
            const glm::dvec2 p = grid.point(i, j);
            terrain_points[k] = {p.x, ground[k], p.y};
        }
    auto terrain = make_grid(grid, terrain_points);
    if (auto st = write(terrain, temp / "terrain.vts"); !st) return st;

    std::string pvd = "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n  <Collection>\n";
    for (std::size_t step = 0; step < times.size(); ++step) {
        auto t0 = std::chrono::steady_clock::now();
        auto sample = sample_field(scene, grid, times[step], threads);
        if (!sample) return sample.error();
        stats.sample_seconds += seconds_since(t0);
        t0 = std::chrono::steady_clock::now();
        auto sg = make_grid(grid, sample->surface);
        for (const FieldInfo& f : field_infos()) {
            vtkNew<vtkDoubleArray> a;
            a->SetName(f.name);
            a->SetNumberOfComponents(f.components);
            a->SetNumberOfTuples(static_cast<vtkIdType>(grid.points()));
            double* out = a->WritePointer(0, static_cast<vtkIdType>(grid.points()) * f.components);
            for (std::size_t k = 0; k < grid.points(); ++k)
                for (int c = 0; c < f.components; ++c)
                    out[k * static_cast<std::size_t>(f.components) + static_cast<std::size_t>(c)] =
                        sample->value(f.name, k, c);
            sg->GetPointData()->AddArray(a);
        }
        add_units(sg, times[step], sample->body_names);
        const std::string name = fmt::format("surface_{:04}.vts", step);
        if (auto st = write(sg, temp / name); !st) return st;
        stats.write_seconds += seconds_since(t0);
        pvd += fmt::format("    <DataSet timestep=\"{:.9g}\" part=\"0\" file=\"{}\"/>\n", times[step], name);
        if (progress) progress(static_cast<double>(step + 1) / static_cast<double>(times.size()));
    }
    pvd += "    <DataSet timestep=\"0\" part=\"1\" file=\"terrain.vts\"/>\n  </Collection>\n</VTKFile>\n";
    std::ofstream out(temp / "surface.pvd");
    out << pvd;
    out.close();
    if (!out) return Error{ErrorCode::io_error, fmt::format("{}: write failed", (temp / "surface.pvd").string())};
    return {};
}

}  // namespace

Status export_series(const fs::path& dir, const Scene& scene, const SampleGrid& grid, const std::vector<double>& times,
                     unsigned threads, const std::function<void(double)>& progress, ExportStats* stats_out) {
    if (auto st = validate_grid(grid); !st) return st;
    if (times.empty()) return Error{ErrorCode::invalid_argument, "export: the time range holds no time"};
    if (dir.empty() || !dir.has_filename()) return Error{ErrorCode::invalid_argument, "export: give a folder name"};
    ExportStats stats;
    auto st = detail::write_folder_atomically(dir, [&](const fs::path& temp) -> Status {
        if (auto written = write_series(temp, scene, grid, times, threads, progress, stats); !written) return written;
        std::error_code ec;
        for (const auto& e : fs::directory_iterator(temp, ec))
            if (e.is_regular_file(ec)) stats.bytes += e.file_size(ec);
        return {};
    });
    if (st && stats_out) *stats_out = stats;
    return st;
}

}  // namespace tidewater::inspect
