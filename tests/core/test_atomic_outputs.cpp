// Outputs that appear whole or not at all, and what a killed writer leaves: the next
// writer of the same target removes the siblings of processes that are gone, puts back
// a folder its writer took away but did not replace, and leaves everything else alone.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "tidewater/detail/atomic_folder.hpp"
#include "tidewater/detail/atomic_sibling.hpp"

namespace tidewater {
namespace {

namespace fs = std::filesystem;

/// The id of a process that has exited (a child that ran and was reaped).
pid_t gone_process() {
    const pid_t child = ::fork();
    if (child == 0) ::_exit(0);
    int status = 0;
    ::waitpid(child, &status, 0);
    return child;
}

void write_text(const fs::path& file, const std::string& text) {
    std::ofstream(file) << text;
}

std::string read_text(const fs::path& file) {
    std::ifstream in(file);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

struct TempDir {
    fs::path path = fs::temp_directory_path() / fmt::format("tidewater_atomic_{}", ::getpid());
    TempDir() {
        fs::remove_all(path);
        fs::create_directories(path);
    }
    ~TempDir() { fs::remove_all(path); }
};

TEST(AtomicOutputs, TheNextWriterSweepsWhatAKilledOneLeft) {
    TempDir dir;
    const fs::path out = dir.path / "bake";
    const pid_t gone = gone_process();
    fs::create_directories(out);
    write_text(out / "shore.json", "previous");
    fs::create_directories(fmt::format("{}.tmp-{}", out.string(), gone));  // a killed bake's half
    write_text(fmt::format("{}.tmp-{}", out.string(), ::getpid()), "ours: a live writer's");
    write_text(dir.path / fmt::format("bake.csv.tmp-{}", gone), "another target's");
    write_text(dir.path / "bake.tmp-notapid", "not a writer's");
    detail::sweep_stale_siblings(out);
    EXPECT_FALSE(fs::exists(fmt::format("{}.tmp-{}", out.string(), gone)));
    EXPECT_TRUE(fs::exists(fmt::format("{}.tmp-{}", out.string(), ::getpid())));
    EXPECT_TRUE(fs::exists(dir.path / fmt::format("bake.csv.tmp-{}", gone)));
    EXPECT_TRUE(fs::exists(dir.path / "bake.tmp-notapid"));
    EXPECT_EQ(read_text(out / "shore.json"), "previous");
}

TEST(AtomicOutputs, AFolderTakenAwayButNotReplacedIsPutBack) {
    // Killed between its two renames: the previous folder waits as .old-PID, the new one
    // is still .tmp-PID. The previous complete output comes back; the half goes.
    TempDir dir;
    const fs::path out = dir.path / "export";
    const pid_t gone = gone_process();
    const fs::path old = fmt::format("{}.old-{}", out.string(), gone),
                   temp = fmt::format("{}.tmp-{}", out.string(), gone);
    fs::create_directories(old);
    write_text(old / "surface.pvd", "previous");
    fs::create_directories(temp);
    detail::sweep_stale_siblings(out);
    EXPECT_EQ(read_text(out / "surface.pvd"), "previous");
    EXPECT_FALSE(fs::exists(old));
    EXPECT_FALSE(fs::exists(temp));

    // The next atomic write replaces it and leaves no sibling.
    ASSERT_TRUE(detail::write_folder_atomically(out, [](const fs::path& into) {
        write_text(into / "surface.pvd", "new");
        return Status{};
    }));
    EXPECT_EQ(read_text(out / "surface.pvd"), "new");
    int siblings = 0;
    for (const auto& e : fs::directory_iterator(dir.path)) siblings += e.path() != out ? 1 : 0;
    EXPECT_EQ(siblings, 0);
}

}  // namespace
}  // namespace tidewater
