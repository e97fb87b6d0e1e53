// Readers refuse what they cannot use, naming the file: a netCDF file without an XYZ
// group, and CSV missing values and flags are skipped and counted.
#include <gtest/gtest.h>
#include <netcdf.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "tidewater/calibration/readers.hpp"
#include "tidewater/calibration/spectrum.hpp"

namespace tidewater::calibration {
namespace {

namespace fs = std::filesystem;

fs::path temp_path(const std::string& name) {
    return fs::temp_directory_path() / ("tidewater_readers_" + std::to_string(::getpid()) + "_" + name);
}

TEST(Readers, NetcdfWithoutXyzGroupIsRefused) {
    const fs::path path = temp_path("no_xyz.nc");
    int nc = 0, meta = 0;
    ASSERT_EQ(nc_create(path.c_str(), NC_NETCDF4 | NC_CLOBBER, &nc), NC_NOERR);
    ASSERT_EQ(nc_def_grp(nc, "Meta", &meta), NC_NOERR);
    ASSERT_EQ(nc_close(nc), NC_NOERR);
    auto r = read_cdip_xyz(path);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().message.find("no XYZ group"), std::string::npos) << r.error().message;
    EXPECT_NE(r.error().message.find(path.string()), std::string::npos);
    fs::remove(path);
}

TEST(Readers, AClassicNetcdfHeaderPastItsFileIsRefusedBeforeNetcdfReadsIt) {
    // netCDF's classic reader allocates a name by the length its header declares: here
    // 1.6 GB for a 28-byte file (what fuzzing found). A classic file written by netCDF
    // itself still reads.
    const fs::path path = temp_path("classic_bomb.nc");
    {
        std::ofstream out(path, std::ios::binary);
        const unsigned char header[] = {'C', 'D', 'F',  1, 0, 0, 0,   0,   0,   0,   0, 0x0A, 0, 0,
                                        0,   1,   0x60, 0, 0, 0, 'a', 'b', 'c', 'd', 0, 0,    0, 4};
        out.write(reinterpret_cast<const char*>(header), sizeof header);
    }
    auto r = read_cdip_spectra(path);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().message.find(path.string() + ": not a readable netCDF file"), std::string::npos)
        << r.error().message;
    EXPECT_NE(r.error().message.find("past the end of the file"), std::string::npos) << r.error().message;

    const fs::path classic = temp_path("classic.nc");
    int nc = 0, dim = 0, var = 0;
    ASSERT_EQ(nc_create(classic.c_str(), NC_CLOBBER, &nc), NC_NOERR);
    ASSERT_EQ(nc_def_dim(nc, "waveFrequency", 3, &dim), NC_NOERR);
    ASSERT_EQ(nc_def_var(nc, "waveEnergyDensity", NC_FLOAT, 1, &dim, &var), NC_NOERR);
    ASSERT_EQ(nc_put_att_text(nc, NC_GLOBAL, "title", 5, "tests"), NC_NOERR);
    ASSERT_EQ(nc_close(nc), NC_NOERR);
    auto opened = read_cdip_spectra(classic);  // refused for what it lacks, not for its header
    ASSERT_FALSE(opened.ok());
    EXPECT_EQ(opened.error().message.find("not a readable netCDF file"), std::string::npos) << opened.error().message;
    fs::remove(path);
    fs::remove(classic);
}

TEST(Readers, AnNdbcSpectrumOfOneBandOrUnorderedBandsIsRefusedByLine) {
    // One band read its neighbour past the end of the row (what fuzzing found).
    const fs::path path = temp_path("one_band.data_spec");
    for (const auto& [line, expected] :
         {std::pair<std::string, std::string>{"2020 06 08 03 50 0.2 0.500 (0.033)", ":2: a spectrum needs two"},
          {"2020 06 08 03 50 0.2 0.5 (0.05) 0.7 (0.04)", ":2: the frequencies do not increase"}}) {
        {
            std::ofstream out(path);
            out << "#YY  MM DD hh mm Sep_Freq  < spec_1 (freq_1) ... >\n" << line << "\n";
        }
        auto r = read_ndbc_spectra(path);
        ASSERT_FALSE(r.ok()) << line;
        EXPECT_NE(r.error().message.find(path.string() + expected), std::string::npos) << r.error().message;
    }
    fs::remove(path);
}

TEST(Readers, CsvSkipsAndCountsMissingAndFlaggedSamples) {
    const fs::path path = temp_path("gauge.csv");
    {
        std::ofstream out(path);
        out << "time_s,eta_cm,qc\n";
        for (int k = 0; k < 20; ++k) {
            const char* value = k == 3 ? "" : k == 5 ? "NaN" : k == 7 ? "-999.99" : nullptr;
            out << k * 0.5 << "," << (value ? value : std::to_string(10.0 * std::sin(0.7 * k))) << ","
                << (k == 9 ? 4 : 0) << "\n";
        }
    }
    CsvColumns columns;
    columns.role_to_column = {{"t", "time_s"}, {"z", "eta_cm"}, {"flag", "qc"}};
    columns.scale = {{"z", 0.01}};
    auto r = read_csv_record(path, RecordKind::gauge, columns);
    ASSERT_TRUE(r.ok()) << r.error().message;
    EXPECT_EQ(r->size(), 16u);
    EXPECT_EQ(r->skipped_missing, 3u);
    EXPECT_EQ(r->skipped_flagged, 1u);
    EXPECT_NEAR(r->z[1], 0.1 * std::sin(0.7), 1e-7);  // cm to m (6 digits in the file)
    fs::remove(path);
}

TEST(Readers, ARecordOverAGigabyteIsRefusedBeforeItIsRead) {
    const fs::path path = temp_path("huge.csv");
    std::ofstream(path) << "t,z\n";
    fs::resize_file(path, (std::uintmax_t{1} << 30) + 1);  // sparse: nothing is written
    CsvColumns columns;
    auto r = read_csv_record(path, RecordKind::gauge, columns);
    fs::remove(path);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().message,
              path.string() + ": 1073741825 bytes, at most 1073741824 read: not a record this reads");
}

TEST(Readers, SpectraThatAskForTooMuchAreRefusedBeforeTheyAreRead) {
    // An NDBC spectral file over a gigabyte (sparse: nothing is written).
    const fs::path ndbc = temp_path("huge.data_spec");
    std::ofstream(ndbc) << "#YY  MM DD hh mm\n";
    fs::resize_file(ndbc, (std::uintmax_t{1} << 30) + 1);
    auto spectra = read_ndbc_spectra(ndbc);
    fs::remove(ndbc);
    ASSERT_FALSE(spectra.ok());
    EXPECT_EQ(spectra.error().message,
              ndbc.string() + ": 1073741825 bytes, at most 1073741824 read: not a record this reads");
    // A CDIP file whose header sizes a variable at 2^28 values (none written: chunked, the
    // file stays small).
    const fs::path cdip = temp_path("huge.nc");
    int nc = 0, dim = 0, var = 0;
    ASSERT_EQ(nc_create(cdip.c_str(), NC_NETCDF4 | NC_CLOBBER, &nc), NC_NOERR);
    ASSERT_EQ(nc_def_dim(nc, "waveFrequency", std::size_t{1} << 28, &dim), NC_NOERR);
    ASSERT_EQ(nc_def_var(nc, "waveFrequency", NC_DOUBLE, 1, &dim, &var), NC_NOERR);
    const std::size_t chunk = 1024;
    ASSERT_EQ(nc_def_var_chunking(nc, var, NC_CHUNKED, &chunk), NC_NOERR);
    ASSERT_EQ(nc_close(nc), NC_NOERR);
    EXPECT_LT(fs::file_size(cdip), std::uintmax_t{1} << 20);
    auto cdip_spectra = read_cdip_spectra(cdip);
    fs::remove(cdip);
    ASSERT_FALSE(cdip_spectra.ok());
    EXPECT_EQ(cdip_spectra.error().message,
              cdip.string() + ": /waveFrequency holds more than 134217728 values: not a record this reads");
}

}  // namespace
}  // namespace tidewater::calibration
