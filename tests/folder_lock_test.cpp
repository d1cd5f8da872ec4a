// The lock of a folder that a sweep or an optimisation keeps its journal in (sweep/folder_lock): a
// second run into a folder in use is refused naming the process that holds it (not taken for an
// interrupted run, not computing the same points beside it); the lock goes with its run, a killed
// run's lock is taken over, and a refused run leaves nothing behind.

#include <gtest/gtest.h>

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "model/input_error.hpp"
#include "support/run_command.hpp"
#include "support/test_files.hpp"
#include "sweep/folder_lock.hpp"

namespace vi {
namespace {

namespace fs = std::filesystem;

std::string refusal_of(const std::string& dir) {
    try {
        const FolderLock second(dir);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(FolderLock, HeldByOneAtATimeAndGoneWithItsHolder) {
    const std::string dir = test::make_temp_dir();
    const std::string out = dir + "/a/b";
    {
        const FolderLock lock(out);
        EXPECT_TRUE(fs::exists(out + "/" + FolderLock::kFileName));
        EXPECT_EQ(test::read_text(lock.path()), std::to_string(getpid()) + "\n");
        // flock(2) locks conflict between two opens even in one process: the second is refused.
        EXPECT_EQ(refusal_of(out), out + ": in use by process " + std::to_string(getpid()) +
                                       " (another run writes its journal here; wait for it to end, or choose another --out)");
    }
    // Released: the lock file is gone, and the folders it made, still empty, with it.
    EXPECT_FALSE(fs::exists(dir + "/a"));
    // A folder that was there stays, and so does what the run wrote into it.
    fs::create_directories(out);
    {
        const FolderLock lock(out);
        test::write_text(out + "/result.csv", "x\n");
    }
    EXPECT_TRUE(fs::exists(out + "/result.csv"));
    EXPECT_FALSE(fs::exists(out + "/" + FolderLock::kFileName));
    // A lock file a killed run left (its pid, no lock held) is taken over.
    test::write_text(out + "/" + FolderLock::kFileName, "999999\n");
    {
        const FolderLock lock(out);
        EXPECT_EQ(test::read_text(lock.path()), std::to_string(getpid()) + "\n");
    }
    fs::remove_all(dir);
}

// The paper's free-impact example at m = 10, undamped, over 0.1 s: some 20000 impacts, seconds of
// work (tests/cli_sweep_stop_test.cpp uses the same slow point).
std::string slow_case(const std::string& dir) {
    std::string text = test::read_text(test::source_path("examples/paper/free_impact_tip.toml"));
    for (const auto& [from, to] : std::vector<std::pair<std::string, std::string>>{{"elements = 50", "elements = 10"},
                                                                                  {"horizon = \"150 us\"", "horizon = \"0.1 s\""},
                                                                                  {"ratios = [0.005, 0.005]", "ratios = [0.0, 0.0]"},
                                                                                  {"damping_ratio = 0.2", "damping_ratio = 0.0"}}) {
        const auto at = text.find(from);
        EXPECT_NE(at, std::string::npos) << from;
        if (at != std::string::npos) text.replace(at, from.size(), to);
    }
    test::write_text(dir + "/slow.toml", text);
    return dir + "/slow.toml";
}

std::size_t lines_in(const std::string& text) { return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')); }

TEST(FolderLock, ASecondRunIntoAFolderInUseIsRefusedNamingTheProcess) {
    const std::string dir = test::make_temp_dir();
    const std::string slow = slow_case(dir);
    const std::string out = dir + "/out";
    const std::vector<std::string> sweep{test::vibroimpact_path(), "sweep", slow, "--set", "supports[0].position=0.9,0.95,1",
                                         "--threads", "1", "--point-timeout", "0", "--out", out};
    test::ChildProcess first(sweep);
    ASSERT_TRUE(test::wait_until([&] { return fs::exists(out + "/sweep.journal"); }, 60.0)) << "the first sweep did not start";
    const std::string in_use = out + ": in use by process " + std::to_string(first.pid());
    std::vector<std::vector<std::string>> seconds;
    seconds.push_back({sweep.begin() + 1, sweep.end()});
    seconds.back().push_back("--resume");
    seconds.push_back({sweep.begin() + 1, sweep.end()});
    seconds.push_back({"optimize", slow, "--vary", "supports[0].position=0.5:1", "--minimize", "z_max", "--out", out});
    for (const auto& args : seconds) {
        const auto r = test::run_vibroimpact(args);
        EXPECT_EQ(r.exit_code, 2) << args[0] << ": " << r.err;
        EXPECT_EQ(r.err.rfind("vibroimpact: error: " + in_use + " (", 0), 0u) << r.err;
        EXPECT_EQ(lines_in(r.err), 1u) << r.err;
    }
    EXPECT_TRUE(first.running()) << "a refused run disturbed the first";
    // The first, stopped, keeps its journal and lets go of the folder; a resume then finishes it.
    first.signal(SIGINT);
    const auto stopped = first.wait();
    EXPECT_EQ(stopped.exit_code, 130) << stopped.err;
    EXPECT_FALSE(fs::exists(out + "/" + FolderLock::kFileName));
    EXPECT_TRUE(fs::exists(out + "/sweep.journal"));

    // A run killed outright leaves its lock file behind; the next run takes it over.
    std::vector<std::string> resume = sweep;
    resume.push_back("--resume");
    const std::string lock = out + "/" + FolderLock::kFileName;
    const auto holds = [&](const test::ChildProcess& c) { return test::read_text(lock) == std::to_string(c.pid()) + "\n"; };
    {
        test::ChildProcess killed(resume);
        ASSERT_TRUE(test::wait_until([&] { return holds(killed); }, 60.0));
        killed.signal(SIGKILL);
        EXPECT_EQ(killed.wait().term_signal, SIGKILL);
    }
    EXPECT_TRUE(fs::exists(lock));
    test::ChildProcess next(resume);
    ASSERT_TRUE(test::wait_until([&] { return holds(next); }, 60.0)) << "the stale lock was not taken over";
    // Two resumes at once: the second is refused, not computing the grid beside the first.
    const auto twice = test::run_vibroimpact({resume.begin() + 1, resume.end()});
    EXPECT_EQ(twice.exit_code, 2) << twice.err;
    EXPECT_EQ(twice.err.rfind("vibroimpact: error: " + out + ": in use by process " + std::to_string(next.pid()) + " (", 0), 0u)
        << twice.err;
    EXPECT_TRUE(next.running()) << "the refused resume disturbed the first";
    next.signal(SIGINT);
    const auto r = next.wait();
    EXPECT_EQ(r.exit_code, 130) << r.err;
    EXPECT_NE(r.err.find("sweep interrupted"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(lock));
    fs::remove_all(dir);
}

}  // namespace
}  // namespace vi
