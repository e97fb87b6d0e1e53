#include "tidewater/detail/atomic_sibling.hpp"

#include <fmt/format.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace tidewater::detail {

namespace fs = std::filesystem;

namespace {

constexpr std::string_view kTemporary = ".tmp-", kReplaced = ".old-";

/// Whether process `pid` exists (one we may not signal exists too).
bool process_alive(long pid) {
    if (pid <= 0 || pid != static_cast<pid_t>(pid)) return false;
    return ::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM;
}

/// The writer's pid when `name` is `base` + `suffix` + digits, else -1.
long writer_of(std::string_view name, std::string_view base, std::string_view suffix) {
    if (name.size() <= base.size() + suffix.size() || name.substr(0, base.size()) != base ||
        name.substr(base.size(), suffix.size()) != suffix)
        return -1;
    const std::string_view digits = name.substr(base.size() + suffix.size());
    long pid = -1;
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), pid);
    return ec == std::errc{} && end == digits.data() + digits.size() ? pid : -1;
}

fs::path sibling(const fs::path& target, std::string_view suffix) {
    fs::path p = target;
    p += fmt::format("{}{}", suffix, ::getpid());
    return p;
}

}  // namespace

fs::path temporary_sibling(const fs::path& target) {
    return sibling(target, kTemporary);
}

fs::path replaced_sibling(const fs::path& target) {
    return sibling(target, kReplaced);
}

void sweep_stale_siblings(const fs::path& target) {
    if (!target.has_filename()) return;
    const fs::path parent = target.parent_path().empty() ? fs::path(".") : target.parent_path();
    const std::string base = target.filename().string();
    // The stale siblings first, then what to do with each: the folder is not changed
    // while it is read.
    std::vector<std::pair<fs::path, bool>> stale;  // path, whether it is a replaced folder
    std::error_code ec;
    fs::directory_iterator it(parent, ec), end;
    for (; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        const long temporary = writer_of(name, base, kTemporary), replaced = writer_of(name, base, kReplaced);
        const long writer = temporary >= 0 ? temporary : replaced;
        if (writer >= 0 && !process_alive(writer)) stale.emplace_back(it->path(), replaced >= 0);
    }
    for (const auto& [path, replaced] : stale) {
        std::error_code ignored;
        if (replaced && !fs::exists(target, ignored)) {
            fs::rename(path, target, ignored);
            if (!ignored) continue;
        }
        fs::remove_all(path, ignored);
    }
}

}  // namespace tidewater::detail
