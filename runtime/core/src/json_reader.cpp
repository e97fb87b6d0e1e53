#include "tidewater/detail/json_reader.hpp"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <vector>

namespace tidewater::detail {

Result<nlohmann::json> parse_json_text(std::string_view text, const std::string& source) {
    // nlohmann keeps the last of duplicate keys; a repeated key is almost always
    // an editing mistake, so it is an error here (with the enclosing object's keys tracked).
    std::vector<std::set<std::string>> keys_in_object;
    std::string duplicate, limit;
    const auto track_keys = [&](int depth, nlohmann::json::parse_event_t event, nlohmann::json& parsed) {
        using Event = nlohmann::json::parse_event_t;
        if ((event == Event::object_start || event == Event::array_start) && depth >= kMaxJsonDepth && limit.empty())
            limit = fmt::format("nested deeper than {} objects and arrays", kMaxJsonDepth);
        if ((event == Event::key || event == Event::value) && parsed.is_string() &&
            parsed.get_ref<const std::string&>().size() > kMaxJsonString && limit.empty())
            limit = fmt::format("a string of {} bytes (at most {})", parsed.get_ref<const std::string&>().size(),
                                kMaxJsonString);
        if (event == Event::object_start) {
            keys_in_object.emplace_back();
        } else if (event == Event::object_end && !keys_in_object.empty()) {
            keys_in_object.pop_back();
        } else if (event == Event::key && !keys_in_object.empty()) {
            const auto key = parsed.get<std::string>();
            if (!keys_in_object.back().insert(key).second && duplicate.empty()) duplicate = key;
        }
        return true;
    };
    try {
        nlohmann::json doc = nlohmann::json::parse(text.begin(), text.end(), track_keys);
        if (!limit.empty()) return Error{ErrorCode::parse_error, fmt::format("{}: {}", source, limit)};
        if (!duplicate.empty()) {
            return Error{
                ErrorCode::schema_error,
                fmt::format("{}: duplicate key \"{}\" (each key may appear once per object)", source, duplicate)};
        }
        return doc;
    } catch (const nlohmann::json::exception& e) {
        std::string what = e.what();
        // Drop nlohmann's "[json.exception.parse_error.101] " tag; keep its line/column text.
        if (const auto pos = what.find("] "); what.rfind("[json.exception", 0) == 0 && pos != std::string::npos)
            what = what.substr(pos + 2);
        return Error{ErrorCode::parse_error, fmt::format("{}: malformed JSON: {}", source, what)};
    }
}

Status check_file_size(const std::filesystem::path& path, std::uintmax_t max_bytes, const char* what) {
    std::error_code ec;
    if (const std::uintmax_t size = std::filesystem::file_size(path, ec); !ec && size > max_bytes)
        return Error{ErrorCode::invalid_argument,
                     fmt::format("{}: {} bytes, at most {} read: not {}", path.string(), size, max_bytes, what)};
    return {};
}

Result<std::string> read_text_file(const std::string& path, std::uintmax_t max_bytes) {
    if (auto fits = check_file_size(path, max_bytes, "a file this reads"); !fits) return fits.error();
    std::ifstream in(path, std::ios::binary);
    if (!in) return Error{ErrorCode::io_error, fmt::format("{}: cannot open file", path)};
    std::ostringstream ss;
    ss << in.rdbuf();
    if (in.bad()) return Error{ErrorCode::io_error, fmt::format("{}: read failed", path)};
    return ss.str();
}

std::string json_type_name(const nlohmann::json& v) {
    if (v.is_number()) return "number";
    return v.type_name();
}

Result<ObjectReader> ObjectReader::open(const nlohmann::json& value, const std::string& source, std::string path) {
    if (!value.is_object()) {
        return Error{ErrorCode::schema_error, fmt::format("{}: {}: expected an object, found {}", source,
                                                          path.empty() ? "/" : path, json_type_name(value))};
    }
    return ObjectReader(value, source, std::move(path));
}

Status ObjectReader::allow_only(std::initializer_list<std::string_view> allowed) const {
    for (const auto& item : value_->items()) {
        bool known = false;
        for (std::string_view a : allowed) known = known || item.key() == a;
        if (!known) {
            std::string list;
            for (std::string_view a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
            return Error{ErrorCode::schema_error,
                         fmt::format("{}: unknown key (allowed here: {})", context(item.key()), list)};
        }
    }
    return {};
}

bool ObjectReader::has(std::string_view key) const {
    return value_->contains(key);
}

const nlohmann::json& ObjectReader::at(std::string_view key) const {
    return value_->at(std::string(key));
}

std::string ObjectReader::child_path(std::string_view key) const {
    return fmt::format("{}/{}", path_, key);
}

std::string ObjectReader::context(std::string_view key) const {
    if (key.empty()) return fmt::format("{}: {}", source_, path_.empty() ? "/" : path_);
    return fmt::format("{}: {}", source_, child_path(key));
}

Error ObjectReader::error(std::string_view key, const std::string& message) const {
    return Error{ErrorCode::schema_error, fmt::format("{}: {}", context(key), message)};
}

Status ObjectReader::number(std::string_view key, double& out, bool required) const {
    if (!has(key)) return required ? Status(error(key, "required number is missing")) : Status();
    const auto& v = at(key);
    if (!v.is_number()) return error(key, fmt::format("expected a number, found {}", json_type_name(v)));
    const double d = v.get<double>();
    if (!std::isfinite(d)) return error(key, "must be a finite number");
    out = d;
    return {};
}

Status ObjectReader::integer(std::string_view key, std::int64_t& out, std::int64_t lo, std::int64_t hi,
                             bool required) const {
    if (!has(key)) return required ? Status(error(key, "required integer is missing")) : Status();
    const auto& v = at(key);
    if (!v.is_number_integer()) return error(key, fmt::format("expected an integer, found {}", json_type_name(v)));
    std::int64_t i = 0;
    if (v.is_number_unsigned()) {
        const auto u = v.get<std::uint64_t>();
        if (u > static_cast<std::uint64_t>(hi)) {
            return error(key, fmt::format("{} is out of range (allowed: {} to {})", u, lo, hi));
        }
        i = static_cast<std::int64_t>(u);
    } else {
        i = v.get<std::int64_t>();
    }
    if (i < lo || i > hi) return error(key, fmt::format("{} is out of range (allowed: {} to {})", i, lo, hi));
    out = i;
    return {};
}

Status ObjectReader::string(std::string_view key, std::string& out, bool required) const {
    if (!has(key)) return required ? Status(error(key, "required string is missing")) : Status();
    const auto& v = at(key);
    if (!v.is_string()) return error(key, fmt::format("expected a string, found {}", json_type_name(v)));
    out = v.get<std::string>();
    return {};
}

}  // namespace tidewater::detail
