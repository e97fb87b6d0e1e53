// Opening a record file for reading, with its size bounded (private to the readers).
#pragma once

#include <filesystem>
#include <fstream>

#include "tidewater/result.hpp"

namespace tidewater::calibration {

/// The largest record file read (a year of a 1.28 Hz buoy is about 1 GB of CSV).
inline constexpr std::uintmax_t kMaxRecordFileBytes = std::uintmax_t{1} << 30;

/// Opens `path` as text; a file over kMaxRecordFileBytes is refused before a line of it
/// is read. Errors name the path.
Result<std::ifstream> open_record_file(const std::filesystem::path& path);

}  // namespace tidewater::calibration
