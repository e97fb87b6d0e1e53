#include "tidewater/result.hpp"

namespace tidewater {

std::string_view to_string(ErrorCode code) noexcept {
    switch (code) {
        case ErrorCode::invalid_argument:
            return "invalid argument";
        case ErrorCode::parse_error:
            return "parse error";
        case ErrorCode::schema_error:
            return "schema error";
        case ErrorCode::io_error:
            return "I/O error";
        case ErrorCode::not_found:
            return "not found";
        case ErrorCode::fold_violation:
            return "fold violation";
        case ErrorCode::not_converged:
            return "not converged";
        case ErrorCode::no_device:
            return "no device";
        case ErrorCode::unsupported:
            return "unsupported";
        case ErrorCode::device_error:
            return "device error";
        case ErrorCode::internal:
            return "internal error";
        case ErrorCode::cancelled:
            return "cancelled";
    }
    return "unknown error";
}

}  // namespace tidewater
