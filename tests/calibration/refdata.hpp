// Where the measured reference data lives (../shared/refdata, see its PROVENANCE.md).
// Tests that need it skip with a clear message when it is absent.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

namespace tidewater::calibration::test {

inline std::filesystem::path refdata_dir() {
    const char* env = std::getenv("TIDEWATER_REFDATA");
    return env ? std::filesystem::path(env) : std::filesystem::path("../shared/refdata");
}

}  // namespace tidewater::calibration::test

/// Skips the test unless refdata/<sub> exists.
#define TIDEWATER_REQUIRE_REFDATA(sub)                                                                            \
    do {                                                                                                          \
        if (!std::filesystem::exists(::tidewater::calibration::test::refdata_dir() / (sub)))                      \
            GTEST_SKIP() << "reference data " << (::tidewater::calibration::test::refdata_dir() / (sub)).string() \
                         << " is absent (see ../shared/refdata/PROVENANCE.md)";                                   \
    } while (0)
