// The header of a netCDF classic file (CDF-1, CDF-2 and CDF-5: "CDF" and a version byte),
// walked before netCDF opens the file: netCDF's reader allocates each name and attribute
// by the length the header declares, so a 100-byte file that declares a 1.6 GB string
// would allocate 1.6 GB. Internal to the calibration's netCDF reader.
#pragma once

#include <filesystem>
#include <string>

namespace tidewater::calibration {

/// Empty when every dimension, attribute and variable the classic header of `path`
/// declares fits within the file (or the file is not a classic netCDF file: netCDF-4
/// files are HDF5's); else why not.
std::string classic_header_misfit(const std::filesystem::path& path);

}  // namespace tidewater::calibration
