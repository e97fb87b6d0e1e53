// The pieces of a ParaView export that the serial (vtk_export.cpp) and the MPI
// (vtk_export_mpi.cpp) writers share: structured grids over a grid or a piece of one,
// with the sampled arrays and their units, the XML writers' settings and the .pvd
// collection. Private to the inspector.
#pragma once

#include <vtkNew.h>
#include <vtkStructuredGrid.h>
#include <vtkXMLWriter.h>

#include <chrono>
#include <string>
#include <vector>

#include "field_sampler.hpp"

namespace tidewater::inspect::exporting {

/// A structured grid over `grid` (its extent the piece's place in the whole grid) with
/// the given point positions.
vtkNew<vtkStructuredGrid> make_grid(const SampleGrid& grid, const std::vector<glm::dvec3>& positions);
/// The terrain over `grid`: a second surface.
vtkNew<vtkStructuredGrid> terrain_grid(const Scene& scene, const SampleGrid& grid);
/// The displaced surface of `sample` with every field_infos() array, the body names, the
/// units and the time in its field data.
vtkNew<vtkStructuredGrid> surface_grid(const FieldSample& sample);
/// Raw appended binary with LZ4: several times faster to write than base64 + zlib.
void configure_writer(vtkXMLWriter& writer);
/// "surface_0012" for step 12.
std::string step_name(std::size_t step);
/// The .pvd collection: each step's file at its time (part 0) and the terrain's (part 1).
std::string pvd_text(const std::vector<double>& times, const std::vector<std::string>& step_files,
                     const std::string& terrain_file);

inline double seconds_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace tidewater::inspect::exporting
