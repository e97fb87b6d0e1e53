// The calibration's readers of measured data: CSV records (gauge, buoy, profile), two-
// column tank files, Datawell raw files, NDBC directional spectra and CDIP netCDF files
// (spectra, displacements, wave summaries). The first byte picks the reader, the rest is
// the file. Any file gives a record or an Error naming the file, before a large allocation.
#include <cstddef>
#include <cstdint>

#include "fuzz_files.hpp"
#include "tidewater/calibration/readers.hpp"
#include "tidewater/calibration/spectrum.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace tidewater;
    using namespace tidewater::calibration;
    if (size == 0) return 0;
    const std::uint8_t reader = data[0] % 7;
    const auto path = fuzz::scratch_file("fuzz.record", fuzz::as_text(data + 1, size - 1));
    switch (reader) {
        case 0: {
            CsvColumns gauge;
            gauge.role_to_column = {{"t", "time"}, {"z", "eta"}, {"flag", "flag"}};
            (void)read_csv_record(path, RecordKind::gauge, gauge);
            CsvColumns buoy;
            buoy.role_to_column = {{"t", "t"}, {"z", "z"}, {"east", "e"}, {"north", "n"}};
            (void)read_csv_record(path, RecordKind::buoy, buoy);
            break;
        }
        case 1:
            (void)read_two_column(path, RecordKind::gauge);
            (void)read_two_column(path, RecordKind::profile);
            break;
        case 2:
            (void)read_datawell_raw(path);
            break;
        case 3: {
            // A .data_spec and the .swdir and .swr1 read beside it, all three the input.
            const auto bytes = fuzz::as_text(data + 1, size - 1);
            for (const char* sibling : {"fuzz.swdir", "fuzz.swr1"}) (void)fuzz::scratch_file(sibling, bytes);
            (void)read_ndbc_spectra(fuzz::scratch_file("fuzz.data_spec", bytes));
            break;
        }
        case 4:
            (void)read_cdip_spectra(path);
            break;
        case 5:
            (void)read_cdip_xyz(path);
            break;
        default:
            (void)read_cdip_wave_summaries(path);
            break;
    }
    return 0;
}
