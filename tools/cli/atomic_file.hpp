// Output files that appear whole or not at all: text goes to a temporary file
// beside the target and is renamed over it only when commit() succeeds.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include "tidewater/result.hpp"

namespace tidewater::cli {

class AtomicFile {
  public:
    /// Opens a temporary file next to `target`; check ok() before writing.
    explicit AtomicFile(std::filesystem::path target);
    ~AtomicFile();  ///< Removes the temporary file unless committed.
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    Status status() const { return status_; }
    std::ofstream& stream() { return out_; }
    /// Flushes, closes and renames onto the target.
    Status commit();
    /// Writes `text`, then commits.
    Status write_and_commit(std::string_view text);

  private:
    std::filesystem::path target_;
    std::filesystem::path temp_;
    std::ofstream out_;
    Status status_;
    bool committed_ = false;
};

}  // namespace tidewater::cli
