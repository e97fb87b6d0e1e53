#include "farm_job.hpp"

#include <fmt/format.h>

#include <fstream>
#include <sstream>

#include "atomic_file.hpp"
#include "tidewater/detail/atomic_folder.hpp"

namespace tidewater::cli::farm {

namespace fs = std::filesystem;

fs::path JobFolder::unit_folder(std::size_t task) const {
    return out_ / "units" / fmt::format("{:05d}", task);
}

fs::path JobFolder::failure_file(std::size_t task) const {
    return out_ / "units" / fmt::format("{:05d}.failed", task);
}

UnitStatus JobFolder::status(std::size_t task) const {
    std::error_code ec;
    if (fs::is_directory(unit_folder(task), ec)) return {UnitState::done, {}};
    std::ifstream in(failure_file(task));
    if (!in) return {UnitState::missing, {}};
    std::stringstream text;
    text << in.rdbuf();
    std::string error = text.str();
    while (!error.empty() && (error.back() == '\n' || error.back() == '\r')) error.pop_back();
    return {UnitState::failed, error};
}

Status JobFolder::prepare() const {
    std::error_code ec;
    fs::create_directories(out_ / "units", ec);
    if (ec)
        return Error{ErrorCode::io_error,
                     fmt::format("{}: cannot create the job's folder: {}", (out_ / "units").string(), ec.message())};
    return {};
}

Status JobFolder::record_outcome(std::size_t task, const Status& outcome) const {
    if (outcome) {
        std::error_code ec;
        fs::remove(failure_file(task), ec);
        return {};
    }
    AtomicFile failure(failure_file(task));
    if (Status st = failure.write_and_commit(outcome.error().message + "\n"); !st)
        return Error{outcome.error().code,
                     fmt::format("{} (and its failure file: {})", outcome.error().message, st.error().message)};
    return outcome;
}

Status JobFolder::run_unit(std::size_t task, const std::function<Status(const fs::path&)>& work, bool& skipped) const {
    skipped = status(task).state == UnitState::done;
    if (skipped) return {};
    if (Status st = prepare(); !st) return st;
    return record_outcome(task, detail::write_folder_atomically(unit_folder(task), work));
}

std::string array_spec(const std::vector<std::size_t>& tasks) {
    std::string spec;
    for (std::size_t i = 0; i < tasks.size();) {
        std::size_t j = i;
        while (j + 1 < tasks.size() && tasks[j + 1] == tasks[j] + 1) ++j;
        if (!spec.empty()) spec += ',';
        spec += j == i ? fmt::format("{}", tasks[i]) : fmt::format("{}-{}", tasks[i], tasks[j]);
        i = j + 1;
    }
    return spec;
}

std::string status_report(const JobFolder& job, std::size_t units,
                          const std::function<std::string(std::size_t)>& describe) {
    std::string out;
    std::vector<std::size_t> todo;
    for (std::size_t t = 0; t < units; ++t) {
        const UnitStatus s = job.status(t);
        if (s.state == UnitState::done) continue;
        todo.push_back(t);
        out += s.state == UnitState::failed ? fmt::format("unit {} ({}): failed: {}\n", t, describe(t), s.error)
                                            : fmt::format("unit {} ({}): missing\n", t, describe(t));
    }
    out += fmt::format("done: {} of {}\n", units - todo.size(), units);
    out += fmt::format("todo: {}\n", todo.empty() ? "none" : array_spec(todo));
    return out;
}

Status require_all_done(const JobFolder& job, std::size_t units,
                        const std::function<std::string(std::size_t)>& describe) {
    std::vector<std::string> not_done;
    for (std::size_t t = 0; t < units; ++t) {
        const UnitStatus s = job.status(t);
        if (s.state == UnitState::done) continue;
        not_done.push_back(
            fmt::format("unit {} ({}) {}", t, describe(t), s.state == UnitState::failed ? "failed" : "is missing"));
    }
    if (not_done.empty()) return {};
    std::string list;
    for (const std::string& s : not_done) list += (list.empty() ? "" : "; ") + s;
    return Error{ErrorCode::invalid_argument,
                 fmt::format("{}: {} of {} units are not done ({}): run them first (--status lists them)",
                             job.out().string(), not_done.size(), units, list)};
}

Status check_job_options(const JobFolder& job, const std::string& options, const std::string& new_job) {
    const std::filesystem::path kept = job.out() / "job.options";
    std::ifstream in(kept);
    if (!in) {
        std::error_code ec;
        fs::create_directories(job.out(), ec);
        if (ec)
            return Error{ErrorCode::io_error,
                         fmt::format("{}: cannot create the job's folder: {}", job.out().string(), ec.message())};
        AtomicFile out(kept);
        return out.write_and_commit(options);
    }
    std::stringstream text;
    text << in.rdbuf();
    if (text.str() == options) return {};
    std::istringstream was(text.str()), now(options);
    std::string a, b;
    while (std::getline(was, a) && std::getline(now, b))
        if (a != b) break;
    return Error{ErrorCode::invalid_argument,
                 fmt::format("{}: the job was started with {} where this run gives {}: run every task with the same "
                             "options, or start a new job ({})",
                             job.out().string(), a, b, new_job)};
}

}  // namespace tidewater::cli::farm
