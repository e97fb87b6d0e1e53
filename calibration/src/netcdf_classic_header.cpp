// The netCDF classic header's grammar (Unidata, "NetCDF File Format Specification"):
//   header   = "CDF" VERSION numrecs dim_list gatt_list var_list
//   *_list   = ABSENT (two zeros) | TAG nelems [item ...]
//   dim      = name dim_length
//   attr     = name nc_type nelems [values, padded to 4 bytes]
//   var      = name nelems [dimid ...] vatt_list nc_type vsize begin
//   name     = nelems [chars, padded to 4 bytes]
// Counts and lengths are 4 bytes (8 in CDF-5), big-endian; begin is 4 bytes in CDF-1.
#include "netcdf_classic_header.hpp"

#include <fmt/format.h>

#include <cstdint>
#include <fstream>
#include <optional>

namespace tidewater::calibration {

namespace {

class HeaderWalk {
  public:
    HeaderWalk(std::ifstream& in, std::uint64_t size, int version) : in_(in), size_(size), version_(version) {}

    /// Why the header does not fit; empty when it does.
    std::string walk() {
        if (!skip(4)) return truncated();  // magic
        if (!count()) return truncated();  // numrecs (or STREAMING)
        for (const std::uint32_t tag : {kDimension, kAttribute}) {
            if (auto why = list(tag); !why.empty()) return why;
        }
        return list(kVariable);
    }

  private:
    static constexpr std::uint32_t kDimension = 0x0A, kVariable = 0x0B, kAttribute = 0x0C;

    std::string truncated() const { return fmt::format("its header ends past the end of the file at byte {}", at_); }

    bool skip(std::uint64_t bytes) {
        if (bytes > size_ - at_) return false;
        at_ += bytes;
        in_.seekg(static_cast<std::streamoff>(at_));
        return true;
    }
    std::optional<std::uint64_t> big_endian(int bytes) {
        if (static_cast<std::uint64_t>(bytes) > size_ - at_) return std::nullopt;
        unsigned char b[8] = {};
        if (!in_.read(reinterpret_cast<char*>(b), bytes)) return std::nullopt;
        at_ += static_cast<std::uint64_t>(bytes);
        std::uint64_t v = 0;
        for (int i = 0; i < bytes; ++i) v = (v << 8) | b[i];
        return v;
    }
    std::optional<std::uint64_t> count() { return big_endian(version_ == 5 ? 8 : 4); }

    /// Skips `n` items of `bytes` each, padded to 4 bytes, if they fit.
    std::string values(std::uint64_t n, std::uint64_t bytes, const char* what) {
        const std::uint64_t left = size_ - at_;
        if (bytes != 0 && n > left / bytes)
            return fmt::format("its header declares {} {} at byte {}, past the end of the file", n, what, at_);
        const std::uint64_t padded = (n * bytes + 3) / 4 * 4;
        if (!skip(padded > left ? left : padded)) return truncated();
        return {};
    }
    std::string name() {
        const auto n = count();
        if (!n) return truncated();
        return values(*n, 1, "characters of a name");
    }
    static std::uint64_t type_size(std::uint64_t type) {
        switch (type) {
            case 1:
            case 2:
            case 7:
                return 1;  // byte, char, ubyte
            case 3:
            case 8:
                return 2;  // short, ushort
            case 4:
            case 5:
            case 9:
                return 4;  // int, float, uint
            case 6:
            case 10:
            case 11:
                return 8;  // double, int64, uint64
            default:
                return 0;
        }
    }
    std::string dimension() {
        if (auto why = name(); !why.empty()) return why;
        return count() ? std::string() : truncated();  // its length
    }
    std::string attribute() {
        if (auto why = name(); !why.empty()) return why;
        const auto type = big_endian(4);
        const auto n = count();
        if (!type || !n) return truncated();
        const std::uint64_t bytes = type_size(*type);
        if (bytes == 0) return fmt::format("its header names an unknown type {} at byte {}", *type, at_);
        return values(*n, bytes, "attribute values");
    }
    std::string variable() {
        if (auto why = name(); !why.empty()) return why;
        const auto dims = count();
        if (!dims) return truncated();
        if (auto why = values(*dims, version_ == 5 ? 8 : 4, "dimensions of a variable"); !why.empty()) return why;
        if (auto why = list(kAttribute); !why.empty()) return why;
        // nc_type, vsize, begin.
        if (!big_endian(4) || !count() || !big_endian(version_ == 1 ? 4 : 8)) return truncated();
        return {};
    }
    std::string list(std::uint32_t expected) {
        const auto tag = big_endian(4);
        const auto n = count();
        if (!tag || !n) return truncated();
        if (*tag == 0 && *n == 0) return {};  // ABSENT
        if (*tag != expected)
            return fmt::format("its header has tag {} where {} belongs, at byte {}", *tag, expected, at_);
        // Each item takes at least 4 bytes: a count bounded by the bytes left is checked
        // before the items are walked one by one.
        if (*n > (size_ - at_) / 4)
            return fmt::format("its header declares {} entries at byte {}, past the end of the file", *n, at_);
        for (std::uint64_t i = 0; i < *n; ++i) {
            const std::string why = expected == kDimension   ? dimension()
                                    : expected == kAttribute ? attribute()
                                                             : variable();
            if (!why.empty()) return why;
        }
        return {};
    }

    std::ifstream& in_;
    std::uint64_t size_;
    int version_;
    std::uint64_t at_ = 0;
};

}  // namespace

std::string classic_header_misfit(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    char magic[4] = {};
    if (!in.read(magic, 4) || magic[0] != 'C' || magic[1] != 'D' || magic[2] != 'F') return {};
    const int version = magic[3];
    if (version != 1 && version != 2 && version != 5) return {};  // netCDF names it unknown
    std::error_code ec;
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec) return "its size cannot be read";
    in.seekg(0);
    return HeaderWalk(in, size, version).walk();
}

}  // namespace tidewater::calibration
