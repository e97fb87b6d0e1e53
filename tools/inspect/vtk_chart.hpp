// The probe chart as a VTK view (private to the inspector: the viewer shows it in a window).
#pragma once

#include <vtkContextView.h>
#include <vtkSmartPointer.h>

#include "probe.hpp"

namespace tidewater::inspect {

/// Height against time beside its spectrum, in a view of its own window.
vtkSmartPointer<vtkContextView> probe_view(const ProbeSeries& probe, int width, int height, bool offscreen);

}  // namespace tidewater::inspect
