#include "atomic_file.hpp"

#include <fmt/format.h>

#include "tidewater/detail/atomic_sibling.hpp"

namespace tidewater::cli {

AtomicFile::AtomicFile(std::filesystem::path target) : target_(std::move(target)) {
    detail::sweep_stale_siblings(target_);
    temp_ = detail::temporary_sibling(target_);
    out_.open(temp_, std::ios::binary | std::ios::trunc);
    if (!out_) status_ = Error{ErrorCode::io_error, fmt::format("{}: cannot create file", target_.string())};
}

AtomicFile::~AtomicFile() {
    if (!committed_) {
        out_.close();
        std::error_code ignored;
        std::filesystem::remove(temp_, ignored);
    }
}

Status AtomicFile::commit() {
    if (!status_) return status_;
    out_.flush();
    const bool good = static_cast<bool>(out_);
    out_.close();
    if (!good) return Error{ErrorCode::io_error, fmt::format("{}: write failed", target_.string())};
    std::error_code ec;
    std::filesystem::rename(temp_, target_, ec);
    if (ec)
        return Error{ErrorCode::io_error, fmt::format("{}: cannot replace file: {}", target_.string(), ec.message())};
    committed_ = true;
    return {};
}

Status AtomicFile::write_and_commit(std::string_view text) {
    if (!status_) return status_;
    out_.write(text.data(), static_cast<std::streamsize>(text.size()));
    return commit();
}

}  // namespace tidewater::cli
