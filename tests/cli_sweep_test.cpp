// The sweep command end to end: the same CSV for 1 and 2 threads and 2 MPI ranks, a failing point
// that does not stop the sweep, interrupt and resume (also under MPI), bad --set forms, the
// progress line on a terminal only.

#include <gtest/gtest.h>
#include <pty.h>
#include <sched.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "model/cpu_budget.hpp"
#include "support/mpi_launch.hpp"
#include "support/run_command.hpp"
#include "support/test_files.hpp"

namespace vi {
namespace {

using test::read_text;
using test::write_text;
namespace fs = std::filesystem;
using nlohmann::json;
using test::CommandResult;
using test::run_vibroimpact;

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

std::vector<std::string> cells_of(const std::string& line) {
    std::vector<std::string> cells;
    std::string cell;
    bool quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char ch = line[i];
        if (quoted && ch == '"' && i + 1 < line.size() && line[i + 1] == '"') {
            cell += '"';
            ++i;
        } else if (ch == '"') {
            quoted = !quoted;
        } else if (ch == ',' && !quoted) {
            cells.push_back(cell);
            cell.clear();
        } else {
            cell += ch;
        }
    }
    cells.push_back(cell);
    return cells;
}

// Journal lines holding points (the four header lines left out).
std::size_t journal_points(const std::string& path) {
    const auto lines = lines_of(read_text(path));
    return lines.size() > 4 ? lines.size() - 4 : 0;
}

using test::mpi_unavailable;
using test::run_mpi;

class SweepCli : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = test::make_temp_dir();
        // The paper's free-impact example at m = 10 over 40 us: a point takes milliseconds.
        std::string text = read_text(test::source_path("examples/paper/free_impact_tip.toml"));
        for (const auto& [from, to] : {std::pair<std::string, std::string>{"elements = 50", "elements = 10"},
                                       {"horizon = \"150 us\"", "horizon = \"40 us\""}}) {
            const auto at = text.find(from);
            ASSERT_NE(at, std::string::npos) << from;
            text.replace(at, from.size(), to);
        }
        case_ = dir_ + "/small.toml";
        write_text(case_, text);
    }
    void TearDown() override { fs::remove_all(dir_); }

    [[nodiscard]] std::vector<std::string> sweep(const std::vector<std::string>& more) const {
        std::vector<std::string> args{"sweep", case_};
        args.insert(args.end(), more.begin(), more.end());
        return args;
    }

    std::string dir_;
    std::string case_;
};

const std::vector<std::string> kGrid = {"--set", "supports[0].position=0.6:1:5", "--set",
                                        "supports[0].stiffness=500,1000"};

std::vector<std::string> with(std::vector<std::string> a, const std::vector<std::string>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

TEST_F(SweepCli, CsvIsTheSameForOneTwoThreadsAndTwoMpiRanks) {
    const CommandResult one = run_vibroimpact(sweep(with(kGrid, {"--threads", "1", "--out", dir_ + "/t1"})));
    ASSERT_EQ(one.exit_code, 0) << one.err;
    EXPECT_TRUE(one.err.empty()) << "a sweep off a terminal prints no progress: " << one.err;
    const CommandResult two = run_vibroimpact(sweep(with(kGrid, {"--threads", "2", "--out", dir_ + "/t2"})));
    ASSERT_EQ(two.exit_code, 0) << two.err;
    const std::string csv = read_text(dir_ + "/t1/sweep.csv");
    EXPECT_EQ(read_text(dir_ + "/t2/sweep.csv"), csv);
    EXPECT_FALSE(fs::exists(dir_ + "/t1/sweep.journal"));

    // Grid order: the last --set varies fastest; every point ran.
    const auto lines = lines_of(csv);
    ASSERT_EQ(lines.size(), 11u);
    // The swept paths with their units (x/l and N/m), then the results.
    EXPECT_EQ(lines[0].rfind("supports[0].position_over_l,supports[0].stiffness_n_m,omega1_rad_s,impacts,episodes,T_s,", 0), 0u);
    const std::vector<std::string> header = cells_of(lines[0]);
    EXPECT_EQ(header.back(), "status");
    for (std::size_t i = 1; i < lines.size(); ++i) {
        const auto cells = cells_of(lines[i]);
        ASSERT_EQ(cells.size(), header.size()) << lines[i];
        EXPECT_NEAR(std::stod(cells[0]), 0.6 + 0.1 * static_cast<double>((i - 1) / 2), 1e-12) << i;
        EXPECT_EQ(cells[1], (i % 2 == 1) ? "500" : "1000") << i;
        EXPECT_EQ(cells.back(), "ok") << i;
    }
    const json summary = json::parse(read_text(dir_ + "/t2/sweep.json"));
    EXPECT_EQ(summary["points"], 10);
    EXPECT_EQ(summary["failed"], 0);
    EXPECT_EQ(summary["computed_this_run"], 10);
    EXPECT_EQ(summary["threads"], 2);

    // Without --out the same CSV goes to stdout.
    const CommandResult to_stdout = run_vibroimpact(sweep(with(kGrid, {"--threads", "2"})));
    ASSERT_EQ(to_stdout.exit_code, 0) << to_stdout.err;
    EXPECT_EQ(to_stdout.out, csv);

    if (const std::string why = mpi_unavailable(); !why.empty()) GTEST_SKIP() << "MPI part skipped: " << why;
    const CommandResult mpi = run_mpi(sweep(with(kGrid, {"--threads", "1", "--out", dir_ + "/mpi"})));
    ASSERT_EQ(mpi.exit_code, 0) << mpi.out << mpi.err;
    EXPECT_EQ(read_text(dir_ + "/mpi/sweep.csv"), csv);
    EXPECT_EQ(json::parse(read_text(dir_ + "/mpi/sweep.json"))["processes"], 2);
}

// --threads 0 (the default) runs as many threads as the CPUs the process may use: one under
// `taskset -c N`, and otherwise what usable_cpu_count() finds for a process started like this one
// (same affinity, same cgroup); sweep.json says how many ran.
TEST_F(SweepCli, DefaultThreadsFollowTheAllowedCpus) {
    const CommandResult free_run = run_vibroimpact(sweep(with(kGrid, {"--out", dir_ + "/all"})));
    ASSERT_EQ(free_run.exit_code, 0) << free_run.err;
    EXPECT_EQ(json::parse(read_text(dir_ + "/all/sweep.json"))["threads"], usable_cpu_count());

    const std::string taskset = test::find_on_path("taskset");
    if (taskset.empty()) GTEST_SKIP() << "taskset is not on PATH (util-linux)";
    cpu_set_t allowed;
    CPU_ZERO(&allowed);
    ASSERT_EQ(sched_getaffinity(0, sizeof allowed, &allowed), 0);
    int cpu = 0;
    while (cpu < CPU_SETSIZE - 1 && !CPU_ISSET(cpu, &allowed)) ++cpu;
    std::vector<std::string> argv{taskset, "-c", std::to_string(cpu), test::vibroimpact_path()};
    for (const std::string& a : sweep(with(kGrid, {"--out", dir_ + "/one"}))) argv.push_back(a);
    const CommandResult pinned = test::run_program(argv);
    ASSERT_EQ(pinned.exit_code, 0) << pinned.err;
    const json summary = json::parse(read_text(dir_ + "/one/sweep.json"));
    EXPECT_EQ(summary["threads"], 1);
    EXPECT_EQ(read_text(dir_ + "/one/sweep.csv"), read_text(dir_ + "/all/sweep.csv"));
}

TEST_F(SweepCli, FailingPointGetsItsStatusAndTheSweepGoesOn) {
    const CommandResult r = run_vibroimpact(sweep({"--set", "supports[0].position=0.5,1.5,0.9", "--out", dir_ + "/f"}));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("1 of 3 points failed"), std::string::npos) << r.err;
    const auto lines = lines_of(read_text(dir_ + "/f/sweep.csv"));
    ASSERT_EQ(lines.size(), 4u);
    const auto header = cells_of(lines[0]);
    const auto bad = cells_of(lines[2]);
    ASSERT_EQ(bad.size(), header.size());
    EXPECT_EQ(bad.front(), "1.5");
    EXPECT_EQ(bad.back(), "error: supports[0].position: must lie in (0, 1] (x0/l)");
    for (std::size_t k = 1; k + 1 < bad.size(); ++k) EXPECT_EQ(bad[k], "nan") << header[k];
    for (const std::size_t i : {1u, 3u}) {
        const auto good = cells_of(lines[i]);
        EXPECT_EQ(good.back(), "ok") << lines[i];
        EXPECT_FALSE(good[1].empty()) << lines[i];
    }
    const json summary = json::parse(read_text(dir_ + "/f/sweep.json"));
    EXPECT_EQ(summary["failed"], 1);
    EXPECT_EQ(summary["ok"], 2);
    ASSERT_EQ(summary["failures"].size(), 1u);
    EXPECT_EQ(summary["failures"][0]["index"], 1);
}

TEST_F(SweepCli, InterruptedSweepResumesWithoutRedoingPoints) {
    // Enough points (each well under a millisecond) that the sweep is still running when SIGINT
    // arrives, even if this process is descheduled for a while on a loaded machine.
    const std::size_t total = 2000;
    const std::vector<std::string> grid = {"--set", "supports[0].position=0.6:1:" + std::to_string(total)};
    const CommandResult ref = run_vibroimpact(sweep(with(grid, {"--threads", "2", "--out", dir_ + "/ref"})));
    ASSERT_EQ(ref.exit_code, 0) << ref.err;

    const std::string out = dir_ + "/run";
    const std::string journal = out + "/sweep.journal";
    std::vector<std::string> argv{test::vibroimpact_path()};
    for (const std::string& a : sweep(with(grid, {"--threads", "1", "--out", out}))) argv.push_back(a);
    CommandResult stopped;
    {
        test::ChildProcess child(argv);
        const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(120);
        while (journal_points(journal) < 1 && std::chrono::steady_clock::now() < give_up) {
            std::this_thread::sleep_for(std::chrono::milliseconds(2));
        }
        kill(child.pid(), SIGINT);
        stopped = child.wait();
    }
    ASSERT_EQ(stopped.exit_code, 130) << stopped.err;
    EXPECT_NE(stopped.err.find("run the same command with --resume"), std::string::npos) << stopped.err;
    EXPECT_FALSE(fs::exists(out + "/sweep.csv"));
    const std::size_t kept = journal_points(journal);
    ASSERT_GE(kept, 1u);
    ASSERT_LT(kept, total) << "the sweep finished before it could be interrupted";

    // Starting over would throw the journal away: refused.
    const std::string before = read_text(journal);
    const CommandResult again = run_vibroimpact(sweep(with(grid, {"--out", out})));
    EXPECT_EQ(again.exit_code, 2);
    EXPECT_NE(again.err.find("pass --resume to finish it"), std::string::npos) << again.err;
    EXPECT_EQ(read_text(journal), before);

    // A hard kill may leave half a line: it is dropped and that point computed again.
    const auto first_row = lines_of(before).at(4);
    write_text(journal, before + std::to_string(total - 1) + "," + first_row.substr(0, first_row.size() / 2));

    const CommandResult resumed = run_vibroimpact(sweep(with(grid, {"--threads", "2", "--out", out, "--resume"})));
    ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
    EXPECT_EQ(read_text(out + "/sweep.csv"), read_text(dir_ + "/ref/sweep.csv"));
    EXPECT_FALSE(fs::exists(journal));
    const json summary = json::parse(read_text(out + "/sweep.json"));
    EXPECT_EQ(summary["from_journal"], kept);
    EXPECT_EQ(summary["computed_this_run"], total - kept);
}

TEST_F(SweepCli, JournalOfAnotherSweepIsRefused) {
    const std::string out = dir_ + "/o";
    fs::create_directories(out);
    write_text(out + "/sweep.journal", "# vibroimpact sweep journal 1\n# fingerprint 0000000000000000\n# points 5\n"
                                       "index,supports[0].position,status\n");
    const CommandResult r = run_vibroimpact(sweep({"--set", "supports[0].position=0.6:1:5", "--out", out, "--resume"}));
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("sweep.journal: belongs to another sweep"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out + "/sweep.csv"));
}

// Resume under MPI: the root reads a journal and the ranks share only the points left.
TEST_F(SweepCli, ResumeUnderMpiFinishesTheJournal) {
    if (const std::string why = mpi_unavailable(); !why.empty()) GTEST_SKIP() << why;
    const std::vector<std::string> grid = {"--set", "supports[0].position=0.6:1:9"};
    const CommandResult ref = run_vibroimpact(sweep(with(grid, {"--out", dir_ + "/ref"})));
    ASSERT_EQ(ref.exit_code, 0) << ref.err;
    const std::string csv = read_text(dir_ + "/ref/sweep.csv");
    const std::string fingerprint = json::parse(read_text(dir_ + "/ref/sweep.json"))["fingerprint"];
    const auto lines = lines_of(csv);
    std::string journal = "# vibroimpact sweep journal 1\n# fingerprint " + fingerprint + "\n# points 9\nindex," +
                          lines[0] + "\n";
    for (const int i : {0, 4, 7}) journal += std::to_string(i) + "," + lines[static_cast<std::size_t>(i) + 1] + "\n";
    fs::create_directories(dir_ + "/mpi");
    write_text(dir_ + "/mpi/sweep.journal", journal);

    const CommandResult mpi = run_mpi(sweep(with(grid, {"--threads", "1", "--out", dir_ + "/mpi", "--resume"})));
    ASSERT_EQ(mpi.exit_code, 0) << mpi.out << mpi.err;
    EXPECT_EQ(read_text(dir_ + "/mpi/sweep.csv"), csv);
    const json summary = json::parse(read_text(dir_ + "/mpi/sweep.json"));
    EXPECT_EQ(summary["from_journal"], 3);
    EXPECT_EQ(summary["computed_this_run"], 6);
}

TEST_F(SweepCli, BadSetExitsTwoBeforeAnyPointAndWritesNothing) {
    const struct {
        std::vector<std::string> args;
        const char* message;
    } cases[] = {
        {{"--set", "supports[0].foo=0.5"}, "--set supports[0].foo=0.5: unknown key 'foo' in supports[i]"},
        {{"--set", "foo.position=0.5"}, "--set foo.position=0.5: unknown key 'foo'"},
        {{"--set", "supports[1].position=0.5"}, "supports[1]: index out of range (the case has 1 support)"},
        {{"--set", "supports[0].position="}, "--set supports[0].position=: empty range"},
        {{"--set", "supports[0].position=0.5:1:0"}, "count '0' must be a whole number"},
        {{"--set", "supports[0].position=abc"}, "'abc' is not a number"},
        {{"--set", "supports[0].position=nan"}, "'nan' is not a finite number"},
        {{"--set", "beam.elements=10.5"}, "beam.elements takes whole numbers, got 10.5"},
        {{"--set", "supports[0].position"}, "expected PATH=SPEC"},
        {{"--set", "supports[0].position=0.5", "--set", "beam.length=x"}, "--set beam.length=x: 'x' is not a number"},
        {{"--set", "supports[0].position=0.5", "--resume"}, "--resume: needs --out DIR"},
    };
    const std::string out = dir_ + "/bad";
    for (const auto& k : cases) {
        const bool resume = k.args.back() == "--resume";
        const CommandResult r = run_vibroimpact(sweep(resume ? k.args : with(k.args, {"--out", out})));
        EXPECT_EQ(r.exit_code, 2) << k.message;
        EXPECT_EQ(r.err.rfind("vibroimpact: error: ", 0), 0u) << r.err;
        EXPECT_NE(r.err.find(k.message), std::string::npos) << r.err;
        EXPECT_EQ(lines_of(r.err).size(), 1u) << r.err;
        EXPECT_TRUE(r.out.empty()) << r.out;
        EXPECT_FALSE(fs::exists(out)) << k.message;
    }
    if (const std::string why = mpi_unavailable(); !why.empty()) GTEST_SKIP() << "MPI part skipped: " << why;
    // Under MPI every rank stops with code 2 (no hang) and the problem is printed once (mpirun
    // adds its own notice that a rank returned non-zero).
    const CommandResult mpi = run_mpi(sweep({"--set", "supports[0].foo=0.5", "--out", out}));
    EXPECT_EQ(mpi.exit_code, 2) << mpi.err;
    const std::string line = "vibroimpact: error: --set supports[0].foo=0.5: unknown key 'foo'";
    const auto first = mpi.err.find(line);
    EXPECT_NE(first, std::string::npos) << mpi.err;
    EXPECT_EQ(mpi.err.find(line, first + 1), std::string::npos) << mpi.err;
    EXPECT_FALSE(fs::exists(out));
}

TEST_F(SweepCli, ModesSweepReportsFrequenciesRatiosAndNodes) {
    const CommandResult r = run_vibroimpact(
        sweep({"--analysis", "modes", "--modes", "2", "--set", "supports[0].position=0.78,1"}));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto lines = lines_of(r.out);
    ASSERT_EQ(lines.size(), 3u);
    EXPECT_EQ(lines[0], "supports[0].position_over_l,f_unsupported_1_hz,f_supported_1_hz,ratio_1,nodes_supported_1_over_l,"
                        "f_unsupported_2_hz,f_supported_2_hz,ratio_2,nodes_supported_2_over_l,status");
    for (std::size_t i = 1; i < 3; ++i) {
        const auto cells = cells_of(lines[i]);
        ASSERT_EQ(cells.size(), 10u);
        EXPECT_GT(std::stod(cells[3]), 1.0);  // a support stiffens the beam
        EXPECT_EQ(cells.back(), "ok");
    }
    // The pinned support is a nodal point of the supported shapes.
    EXPECT_NE(cells_of(lines[1])[4].find("0.78"), std::string::npos) << lines[1];
}

TEST_F(SweepCli, ProgressLineShowsOnATerminal) {
    std::vector<std::string> args{test::vibroimpact_path()};
    for (const std::string& a : sweep({"--set", "supports[0].position=0.6:1:20", "--out", dir_ + "/p"})) {
        args.push_back(a);
    }
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    int master = -1;
    const pid_t pid = forkpty(&master, nullptr, nullptr, nullptr);
    ASSERT_GE(pid, 0);
    if (pid == 0) {
        execv(argv[0], argv.data());
        _exit(127);
    }
    std::string seen;
    char buf[512];
    for (ssize_t n; (n = read(master, buf, sizeof buf)) > 0;) seen.append(buf, static_cast<std::size_t>(n));
    int status = 0;
    waitpid(pid, &status, 0);
    close(master);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 0) << seen;
    EXPECT_NE(seen.find("sweep ["), std::string::npos) << seen;
    EXPECT_NE(seen.find("20/20 points"), std::string::npos) << seen;
    EXPECT_NE(seen.find(" left "), std::string::npos) << seen;
}

}  // namespace
}  // namespace vi
