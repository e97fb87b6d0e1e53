// Result<T>: a value or an Error. Errors cross Tidewater's API as values;
// no exception escapes a public function.
#pragma once

#include <cassert>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <variant>

namespace tidewater {

enum class ErrorCode {
    invalid_argument,  ///< A caller-supplied value is out of range or inconsistent.
    parse_error,       ///< A file or string is not well-formed JSON/CSV.
    schema_error,      ///< Well-formed input with a wrong key, type or value.
    io_error,          ///< A file could not be opened, read or written.
    not_found,         ///< A named preset, scene or resource does not exist.
    fold_violation,    ///< A wave set breaks the fold-free rule sum(Q*k*A) <= 1.
    not_converged,     ///< An iterative solve did not reach its tolerance.
    no_device,         ///< No Vulkan device fits; the message lists what was found.
    unsupported,       ///< A format or feature the device lacks; the message names it.
    device_error,      ///< A Vulkan call failed; the message names the call and VkResult.
    internal,          ///< Work failed inside the library (out of memory, a worker's exception).
    cancelled,         ///< The caller cancelled the work (a bake's stop token); nothing was kept.
};

std::string_view to_string(ErrorCode code) noexcept;

/// An error code plus a message meant for a person: it names the file, the
/// JSON path or line, the offending value and the allowed range.
struct Error {
    ErrorCode code = ErrorCode::invalid_argument;
    std::string message;
    /// For device_error: the VkResult the failing Vulkan call returned (a VkResult value,
    /// kept as an integer so the core needs no Vulkan headers); 0 (VK_SUCCESS) otherwise.
    std::int32_t vk_result = 0;
};

template <typename T>
class [[nodiscard]] Result {
  public:
    Result(T value) : state_(std::in_place_index<0>, std::move(value)) {}      // NOLINT: implicit by design
    Result(Error error) : state_(std::in_place_index<1>, std::move(error)) {}  // NOLINT

    bool ok() const noexcept { return state_.index() == 0; }
    explicit operator bool() const noexcept { return ok(); }

    T& value() & {
        assert(ok());
        return std::get<0>(state_);
    }
    const T& value() const& {
        assert(ok());
        return std::get<0>(state_);
    }
    T&& value() && {
        assert(ok());
        return std::get<0>(std::move(state_));
    }
    T* operator->() { return &value(); }
    const T* operator->() const { return &value(); }
    T& operator*() & { return value(); }
    const T& operator*() const& { return value(); }

    const Error& error() const& {
        assert(!ok());
        return std::get<1>(state_);
    }
    Error&& error() && {
        assert(!ok());
        return std::get<1>(std::move(state_));
    }

  private:
    std::variant<T, Error> state_;
};

/// Result<void>: success or an Error.
class [[nodiscard]] Status {
  public:
    Status() = default;
    Status(Error error) : error_(std::move(error)), failed_(true) {}  // NOLINT: implicit by design

    bool ok() const noexcept { return !failed_; }
    explicit operator bool() const noexcept { return ok(); }
    const Error& error() const& {
        assert(failed_);
        return error_;
    }

  private:
    Error error_;
    bool failed_ = false;
};

}  // namespace tidewater
