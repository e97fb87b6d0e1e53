// Typed, path-aware reading of JSON objects (private). Every error names the
// source file, the JSON pointer path and what was expected.
#pragma once

#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "tidewater/result.hpp"

namespace tidewater::detail {

/// The most a JSON document may nest (objects and arrays within each other): the
/// deepest a scene, preset or sidecar goes is 6.
inline constexpr int kMaxJsonDepth = 32;
/// The longest string a JSON document may hold (a name, a path, a description), bytes.
inline constexpr std::size_t kMaxJsonString = 65536;
/// The largest JSON file read (scenes, presets, sidecars; a 16 km bake's is 3 MB).
inline constexpr std::uintmax_t kMaxJsonFileBytes = std::uintmax_t{64} << 20;
/// The largest other text file read whole (points CSV), bytes.
inline constexpr std::uintmax_t kMaxTextFileBytes = std::uintmax_t{1} << 30;

/// Parses text as JSON; a syntax error reports line and column. Deeper nesting than
/// kMaxJsonDepth and strings longer than kMaxJsonString are refused.
Result<nlohmann::json> parse_json_text(std::string_view text, const std::string& source);

/// Refuses a file over `max_bytes` before it is read: "PATH: N bytes, at most M read: not
/// WHAT". Ok where its size cannot be read (opening it then says why).
Status check_file_size(const std::filesystem::path& path, std::uintmax_t max_bytes, const char* what);

/// Reads text from a file; errors name the path. A file over `max_bytes` is refused
/// before it is read.
Result<std::string> read_text_file(const std::string& path, std::uintmax_t max_bytes = kMaxJsonFileBytes);

class ObjectReader {
  public:
    /// Fails unless `value` is a JSON object.
    static Result<ObjectReader> open(const nlohmann::json& value, const std::string& source, std::string path);

    /// Fails on the first key not in `allowed`, listing the allowed keys.
    Status allow_only(std::initializer_list<std::string_view> allowed) const;

    bool has(std::string_view key) const;
    const nlohmann::json& at(std::string_view key) const;

    /// Readers leave `out` untouched when the key is absent and not required.
    Status number(std::string_view key, double& out, bool required = false) const;
    Status integer(std::string_view key, std::int64_t& out, std::int64_t lo, std::int64_t hi,
                   bool required = false) const;
    Status string(std::string_view key, std::string& out, bool required = false) const;

    /// "<source>: <path>/<key>" for messages and nested readers.
    std::string context(std::string_view key = {}) const;
    std::string child_path(std::string_view key) const;
    const std::string& source() const { return source_; }
    Error error(std::string_view key, const std::string& message) const;

  private:
    ObjectReader(const nlohmann::json& v, const std::string& source, std::string path)
        : value_(&v), source_(source), path_(std::move(path)) {}
    const nlohmann::json* value_;
    std::string source_;
    std::string path_;
};

/// JSON type name for messages ("number", "string", ...).
std::string json_type_name(const nlohmann::json& v);

}  // namespace tidewater::detail
