// Writing a VTK render window to a PNG whole or not at all (private to the inspector).
#pragma once

#include <filesystem>

#include "tidewater/result.hpp"

class vtkRenderWindow;

namespace tidewater::inspect {

/// Renders `window`, writes its pixels beside `png`, then renames onto it.
Status save_window_png(vtkRenderWindow* window, const std::filesystem::path& png);

}  // namespace tidewater::inspect
