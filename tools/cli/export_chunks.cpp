#include "export_chunks.hpp"

#include <fmt/format.h>

#include <fstream>
#include <sstream>

#include "atomic_file.hpp"

namespace tidewater::cli {

Status check_job_options(const farm::JobFolder& job, const std::string& options) {
    const std::filesystem::path kept = job.out() / "job.options";
    std::ifstream in(kept);
    if (!in) {
        if (Status st = job.prepare(); !st) return st;
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
                             "options, or start a new job (another --export folder)",
                             job.out().string(), a, b)};
}

}  // namespace tidewater::cli
