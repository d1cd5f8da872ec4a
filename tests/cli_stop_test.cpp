// SIGINT and SIGTERM stop `simulate`, `paper` and `validate` within a second:
// exit 130 / 143, "stopped by ...; nothing written", no output folder or file left behind (and an
// existing one untouched), gnuplot children ended with the command; a second signal ends even work
// that cannot see the stop, by the signal itself, while the same signal delivered twice at once
// (as `timeout` does) is one stop. Sweeps: cli_sweep_stop_test.

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "support/run_command.hpp"
#include "support/test_files.hpp"

namespace vi {
namespace {

namespace fs = std::filesystem;
using test::CommandResult;
using test::read_text;
using test::write_text;

using test::kStopBound;

std::string replaced(std::string text, const std::vector<std::pair<std::string, std::string>>& edits) {
    for (const auto& [from, to] : edits) {
        const auto at = text.find(from);
        EXPECT_NE(at, std::string::npos) << from;
        if (at != std::string::npos) text.replace(at, from.size(), to);
    }
    return text;
}

// The signal's name as main.cpp prints it.
const char* name_of(int sig) { return sig == SIGINT ? "SIGINT" : "SIGTERM"; }

void expect_stopped(const CommandResult& r, int sig, const std::string& what) {
    std::printf("%s, %s: ended %.3f s after the signal (%.2f s in all), exit code %d\n", what.c_str(), name_of(sig),
                r.after_signal, r.seconds, r.exit_code);
    EXPECT_FALSE(r.hung) << r.err;
    EXPECT_EQ(r.exit_code, 128 + sig) << r.err;
    EXPECT_EQ(r.term_signal, 0) << "killed by the signal instead of stopping";
    EXPECT_GE(r.after_signal, 0.0);
    EXPECT_LT(r.after_signal, kStopBound) << what << ": no stop within " << kStopBound << " s of the signal";
    const std::string line = std::string("vibroimpact: stopped by ") + name_of(sig) + "; nothing written\n";
    EXPECT_GE(r.err.size(), line.size());
    if (r.err.size() >= line.size()) {
        EXPECT_EQ(r.err.substr(r.err.size() - line.size()), line) << r.err;
    }
}

// The signals a running process catches (SigCgt of /proc/PID/status), as a bit mask.
unsigned long long caught_signals(pid_t pid) {
    std::istringstream in(read_text("/proc/" + std::to_string(pid) + "/status"));
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("SigCgt:", 0) == 0) return std::stoull(line.substr(7), nullptr, 16);
    }
    return 0;
}
bool catches(unsigned long long mask, int sig) { return (mask >> (sig - 1)) & 1ull; }

class StopCli : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = test::make_temp_dir();
        // The paper's free-impact example, undamped (no Rayleigh, no contact damping): it bounces for
        // the whole horizon, and 100 ms hold some 60000 contact episodes, about a minute of work for
        // the exact solver (structurally slow, whatever its speed per event).
        slow_case_ = dir_ + "/undamped.toml";
        write_text(slow_case_, replaced(read_text(test::source_path("examples/paper/free_impact_tip.toml")),
                                        {{"ratios = [0.005, 0.005]", "ratios = [0.0, 0.0]"},
                                         {"damping_ratio = 0.2", "damping_ratio = 0.0"},
                                         {"horizon = \"150 us\"", "horizon = \"100 ms\""},
                                         {"output_step = \"10 ns\"", "output_step = \"1 us\""}}));
    }
    void TearDown() override { fs::remove_all(dir_); }

    static std::vector<std::string> command(const std::vector<std::string>& args) {
        std::vector<std::string> argv{test::vibroimpact_path()};
        argv.insert(argv.end(), args.begin(), args.end());
        return argv;
    }

    // Starts the command, waits until `ready` (at most the hang limit), checks it still runs,
    // signals it and waits for the end.
    static CommandResult stop_when(test::ChildProcess& child, const std::function<bool()>& ready, int sig) {
        // A command that ends early (an error) ends the wait too, instead of the hang limit.
        test::wait_until([&] { return ready() || !child.running(); }, test::kHangLimitSeconds);
        EXPECT_TRUE(ready()) << "the command never got there";
        EXPECT_TRUE(child.running()) << "the command ended before the signal";
        child.signal(sig);
        return child.wait();
    }

    std::string dir_;
    std::string slow_case_;
};

TEST_F(StopCli, SimulateStopsOnSigintAndSigtermAndWritesNothing) {
    for (const int sig : {SIGINT, SIGTERM}) {
        SCOPED_TRACE(name_of(sig));
        const std::string out = dir_ + "/out";
        test::ChildProcess child(command({"simulate", slow_case_, "--out", out}));
        const CommandResult r = stop_when(child, [&] { return child.seconds() > 0.5; }, sig);
        expect_stopped(r, sig, "simulate (undamped, 100 ms)");
        EXPECT_TRUE(r.out.empty()) << r.out;
        EXPECT_FALSE(fs::exists(out));
    }
    // Into a folder that holds an earlier run's files: they stay as they were.
    const std::string out = dir_ + "/earlier";
    fs::create_directories(out);
    write_text(out + "/summary.json", "{\"earlier\": true}\n");
    test::ChildProcess child(command({"simulate", slow_case_, "--out", out, "--json"}));
    const CommandResult r = stop_when(child, [&] { return child.seconds() > 0.5; }, SIGTERM);
    expect_stopped(r, SIGTERM, "simulate --json into an earlier run's folder");
    EXPECT_TRUE(r.out.empty()) << r.out;
    EXPECT_EQ(read_text(out + "/summary.json"), "{\"earlier\": true}\n");
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(out)) names.push_back(e.path().filename().string());
    EXPECT_EQ(names, std::vector<std::string>{"summary.json"});
}

// Work that cannot see the stop flag (here a read blocked on a case "file" that is a pipe nobody
// writes to: the handlers restart system calls, so the first signal leaves it blocked) goes on after
// the first signal; a second one, of either kind, ends the process at once, by the signal itself.
TEST_F(StopCli, SecondSignalEndsWorkThatCannotSeeTheStop) {
    for (const auto& [first, second] : {std::pair<int, int>{SIGTERM, SIGINT}, {SIGINT, SIGINT}}) {
        SCOPED_TRACE(std::string(name_of(first)) + " then " + name_of(second));
        const std::string fifo = dir_ + "/case.toml";
        fs::remove(fifo);
        ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
        test::ChildProcess child(command({"simulate", fifo}));
        ASSERT_TRUE(test::wait_until([&] { return child.seconds() > 0.3; }, 10.0));
        child.signal(first);
        // Well past the window in which a second signal counts as the same stop (0.1 s).
        test::wait_until([] { return false; }, 0.5);
        ASSERT_TRUE(child.running()) << "the blocked read ended on the first signal";
        const auto t0 = std::chrono::steady_clock::now();
        kill(child.pid(), second);
        const CommandResult r = child.wait(60.0);
        const double after = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        std::printf("blocked read, %s then %s: ended %.3f s after the second, by signal %d\n", name_of(first),
                    name_of(second), after, r.term_signal);
        EXPECT_FALSE(r.hung);
        EXPECT_EQ(r.term_signal, second) << "exit status " << r.exit_code << ": " << r.err;
        EXPECT_LT(after, kStopBound);
    }
}

// `timeout -s TERM` signals the command and then its whole process group: the same SIGTERM comes
// twice within microseconds. That is one stop, not a stop and a kill: the command still stops
// cleanly with its message and 143 (the second copy here comes 5 ms after the first).
TEST_F(StopCli, TheSameSignalDeliveredTwiceIsOneStop) {
    test::ChildProcess child(command({"simulate", slow_case_}));
    ASSERT_TRUE(test::wait_until([&] { return child.seconds() > 0.5; }, 10.0));
    const unsigned long long mask = caught_signals(child.pid());
    EXPECT_TRUE(catches(mask, SIGINT)) << std::hex << mask;
    EXPECT_TRUE(catches(mask, SIGTERM)) << std::hex << mask;
    child.signal(SIGTERM);
    test::wait_until([] { return false; }, 0.005);
    kill(child.pid(), SIGTERM);
    const CommandResult r = child.wait();
    expect_stopped(r, SIGTERM, "simulate, SIGTERM twice 5 ms apart");
}

// gnuplot drawing the figures when the signal comes: a stand-in gnuplot that only sleeps (and
// notes its pid) makes that phase last; the command ends it and stops.
TEST_F(StopCli, PaperStopsDuringItsFiguresAndEndsGnuplot) {
    const std::string pids = dir_ + "/gnuplot.pids";
    const std::string fake = dir_ + "/gnuplot";
    write_text(fake, "#!/bin/sh\necho $$ >> '" + pids + "'\nexec sleep 300\n");
    fs::permissions(fake, fs::perms::owner_all);
    const std::string tmp = dir_ + "/tmp";
    fs::create_directories(tmp);
    const std::string out = dir_ + "/paper";
    test::ChildProcess child(command({"paper", "--out", out, "--gnuplot", fake, "--positions", "4",
                                      "--modal-positions", "4", "--prestress-points", "2"}),
                             {"TMPDIR=" + tmp});
    const CommandResult r = stop_when(child, [&] { return !read_text(pids).empty(); }, SIGINT);
    expect_stopped(r, SIGINT, "paper, in gnuplot");
    EXPECT_FALSE(fs::exists(out));
    EXPECT_TRUE(fs::is_empty(tmp)) << "the figures' temporary folder was left behind";
    std::istringstream in(read_text(pids));
    int gnuplots = 0;
    for (long pid; in >> pid; ++gnuplots) {
        const bool alive = kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH;
        EXPECT_FALSE(alive) << "gnuplot " << pid << " still runs after the command stopped";
    }
    EXPECT_GE(gnuplots, 1);
}

// The study itself (its transients): stopped as soon as its first part reports; an earlier run's
// output folder is left as it was.
TEST_F(StopCli, PaperStopsDuringItsStudyAndLeavesAnEarlierOutputAlone) {
    const std::string out = dir_ + "/paper";
    fs::create_directories(out);
    write_text(out + "/report.html", "earlier\n");
    test::ChildProcess child(command({"paper", "--out", out, "--positions", "400", "--progress", "lines"}));
    const std::string err = child.stderr_path();
    const CommandResult r =
        stop_when(child, [&] { return read_text(err).find("paper: [") != std::string::npos; }, SIGTERM);
    expect_stopped(r, SIGTERM, "paper, in its study");
    EXPECT_EQ(read_text(out + "/report.html"), "earlier\n");
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(out)) names.push_back(e.path().filename().string());
    EXPECT_EQ(names, std::vector<std::string>{"report.html"});
}

TEST_F(StopCli, ValidateStopsInAnySectionAndWritesNoDocument) {
    const std::string example = test::source_path("examples/paper/free_impact_tip.toml");
    // The sections run on worker threads, the slowest first (section 6's CVODE runs), so these
    // lines come early, middle and late while other sections still run.
    for (const auto& [sig, section] : {std::pair<int, std::string>{SIGTERM, "section 6: exact solver energy"},
                                       {SIGINT, "section 9:"}, {SIGTERM, "section 6: CVODE undamped"}}) {
        SCOPED_TRACE(section);
        const std::string out = dir_ + "/validation.md";
        test::ChildProcess child(command({"validate", "--quick", "--case", example, "--switch-case",
                                          test::source_path("examples/switch/cantilever_switch.toml"), "--out", out,
                                          "--progress", "lines"}));
        const std::string err = child.stderr_path();
        const CommandResult r =
            stop_when(child, [&] { return read_text(err).find(section) != std::string::npos; }, sig);
        expect_stopped(r, sig, "validate --quick, after '" + section + "'");
        EXPECT_FALSE(fs::exists(out));
        EXPECT_TRUE(r.out.empty()) << r.out;
    }
}

}  // namespace
}  // namespace vi
