// Stopping and resuming a sweep on a grid with one slow point: SIGINT and
// SIGTERM end it within a second with 130 / 143, the journal intact (every finished point, its row
// byte for byte, no torn line), and --resume completes it into the CSV of an uninterrupted run; the
// same under `mpirun -n 2` (signal to mpirun, and to every rank at once as Slurm's --signal does).
// --point-timeout marks a slow point 'timeout: ...' and the sweep goes on; --resume keeps failed
// points unless --retry-failed; the progress line names the slowest running point.
//
// The slow point is slow for a structural reason, not a solver's speed: an undamped beam (no
// Rayleigh, no contact damping) bounces for ever, and a 0.1 s horizon holds some 20000 impacts
// (about 8 s at m = 10 in Release on the 2-core development machine). The fast points (40-60 us)
// take milliseconds. The tests check that the slow point is still running when the signal is
// sent, and say so if a faster solver ever makes it too short.

#include <gtest/gtest.h>
#include <signal.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "support/mpi_launch.hpp"
#include "support/run_command.hpp"
#include "support/test_files.hpp"

namespace vi {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test::CommandResult;
using test::read_text;
using test::write_text;

using test::kStopBound;

// Grid index of the slow point (the last: under MPI, rank 1 takes it after its fast points).
constexpr std::size_t kSlow = 5;
// The slow point's horizon [s]. Under the sanitizers (VI_SHORT_TESTS) half of it, some 10000
// impacts, still runs for more than the 2 s the progress line waits before naming it; each test here
// runs the slow point twice (the reference and the resume), which made this file's tests the longest
// of that run.
#if VI_SHORT_TESTS
const std::string kSlowHorizon = "0.05";
#else
const std::string kSlowHorizon = "0.2";  // 0.1 ran under 2 s at times once the exact solver sped up
#endif
const std::vector<std::string> kGrid = {"--set", "solver.horizon=4e-5,4.5e-5,5e-5,5.5e-5,6e-5," + kSlowHorizon};

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

// Cells of a CSV line ("..." quoting as the sweep writes it).
std::size_t cell_count(const std::string& line) {
    std::size_t n = 1;
    bool quoted = false;
    for (const char ch : line) {
        if (ch == '"') quoted = !quoted;
        if (ch == ',' && !quoted) ++n;
    }
    return n;
}

// The journal's points by grid index, after checking its form: the four header lines, the CSV
// header of the sweep, and only complete lines (the file ends with a newline, every line has the
// header's cell count plus the index). Fails the test on any torn or damaged line.
std::map<std::size_t, std::string> journal_rows(const std::string& path, const std::string& csv_header) {
    const std::string text = read_text(path);
    std::map<std::size_t, std::string> rows;
    EXPECT_FALSE(text.empty()) << path;
    if (text.empty()) return rows;
    EXPECT_EQ(text.back(), '\n') << "the journal ends inside a line";
    const auto lines = lines_of(text);
    EXPECT_GE(lines.size(), 4u);
    if (lines.size() < 4) return rows;
    EXPECT_EQ(lines[0], "# vibroimpact sweep journal 1");
    EXPECT_EQ(lines[3], "index," + csv_header);
    for (std::size_t i = 4; i < lines.size(); ++i) {
        const std::size_t comma = lines[i].find(',');
        EXPECT_NE(comma, std::string::npos) << lines[i];
        if (comma == std::string::npos) continue;
        const std::size_t index = std::stoul(lines[i].substr(0, comma));
        const std::string row = lines[i].substr(comma + 1);
        EXPECT_EQ(cell_count(row), cell_count(csv_header)) << "torn line: " << lines[i];
        EXPECT_EQ(rows.count(index), 0u) << "point " << index << " twice";
        rows[index] = row;
    }
    return rows;
}

class SweepStop : public ::testing::Test {
protected:
    // The undamped case and the uninterrupted sweep, computed once for every test here.
    static void SetUpTestSuite() {
        dir_ = new std::string(test::make_temp_dir());
        // The paper's free-impact example at m = 10, undamped: it bounces for the whole horizon (its
        // slow point runs for seconds: solver.max_steps well above the default that would end it).
        std::string text = read_text(test::source_path("examples/paper/free_impact_tip.toml"));
        for (const auto& [from, to] : {std::pair<std::string, std::string>{"elements = 50", "elements = 10"},
                                       {"horizon = \"150 us\"", "horizon = \"40 us\"\nmax_steps = 50000000"},
                                       {"ratios = [0.005, 0.005]", "ratios = [0.0, 0.0]"},
                                       {"damping_ratio = 0.2", "damping_ratio = 0.0"}}) {
            const auto at = text.find(from);
            ASSERT_NE(at, std::string::npos) << from;
            text.replace(at, from.size(), to);
        }
        case_ = new std::string(*dir_ + "/undamped.toml");
        write_text(*case_, text);
        const CommandResult ref = test::run_vibroimpact(args({"--out", *dir_ + "/reference"}));
        ASSERT_EQ(ref.exit_code, 0) << ref.err;
        std::printf("uninterrupted sweep (the slow point included): %.2f s\n", ref.seconds);
        reference_ = new std::string(read_text(*dir_ + "/reference/sweep.csv"));
    }
    static void TearDownTestSuite() {
        fs::remove_all(*dir_);
        delete dir_;
        delete case_;
        delete reference_;
    }
    void SetUp() override {
        ASSERT_NE(reference_, nullptr);
        ASSERT_EQ(lines_of(*reference_).size(), 7u) << *reference_;
        out_ = test::make_temp_dir() + "/out";
    }
    void TearDown() override { fs::remove_all(fs::path(out_).parent_path()); }

    // `vibroimpact sweep CASE <kGrid> more...` (without the executable). Without a limit of its own
    // the slow point gets none (--point-timeout 0): a wall-clock limit would make the rows compared
    // here depend on the machine's load (under the sanitizers the slow point takes over a minute).
    static std::vector<std::string> args(const std::vector<std::string>& more) {
        std::vector<std::string> a{"sweep", *case_};
        a.insert(a.end(), kGrid.begin(), kGrid.end());
        a.insert(a.end(), more.begin(), more.end());
        if (std::find(more.begin(), more.end(), "--point-timeout") == more.end()) {
            a.insert(a.end(), {"--point-timeout", "0"});
        }
        return a;
    }
    static std::vector<std::string> command(const std::vector<std::string>& more) {
        std::vector<std::string> argv{test::vibroimpact_path()};
        for (const std::string& a : args(more)) argv.push_back(a);
        return argv;
    }
    static std::string csv_header() { return lines_of(*reference_).at(0); }
    static std::string reference_row(std::size_t index) { return lines_of(*reference_).at(index + 1); }
    [[nodiscard]] std::string journal() const { return out_ + "/sweep.journal"; }

    // Waits until the journal holds the five fast points (the slow one is then running), sends the
    // signal (to the child, or with to_children to the processes it started: mpirun's ranks) and
    // waits for the end.
    CommandResult interrupt(test::ChildProcess& child, int sig, bool to_children = false) {
        const bool fast_done = test::wait_until(
            [&] { return lines_of(read_text(journal())).size() >= 4 + kSlow; }, test::kHangLimitSeconds);
        EXPECT_TRUE(fast_done) << "the fast points never reached the journal";
        EXPECT_TRUE(child.running()) << "the sweep ended before the signal: the slow point is no longer slow";
        if (to_children) {
            EXPECT_EQ(child.signal_children(sig), 2) << "mpirun -n 2 should have started 2 ranks";
        } else {
            child.signal(sig);
        }
        return child.wait();
    }

    // The journal of a stopped sweep holds exactly the five fast points, each row as in the
    // uninterrupted run; then --resume computes only the slow point and the CSV is the reference.
    void expect_intact_then_resume(const std::vector<std::string>& resume_launcher = {}) {
        const auto rows = journal_rows(journal(), csv_header());
        EXPECT_EQ(rows.size(), kSlow) << read_text(journal());
        for (const auto& [index, row] : rows) {
            EXPECT_LT(index, kSlow) << "the slow point was journaled: it was not stopped";
            if (index < kSlow) {
                EXPECT_EQ(row, reference_row(index)) << index;
            }
        }
        EXPECT_FALSE(fs::exists(out_ + "/sweep.csv"));
        EXPECT_FALSE(fs::exists(out_ + "/sweep.json"));

        std::vector<std::string> argv = resume_launcher;
        if (argv.empty()) {
            argv = command({"--out", out_, "--resume"});
        } else {
            for (const std::string& a : args({"--threads", "1", "--out", out_, "--resume"})) argv.push_back(a);
        }
        const CommandResult resumed =
            resume_launcher.empty() ? test::run_program(argv) : test::run_program(argv, test::mpi_env());
        ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
        EXPECT_EQ(read_text(out_ + "/sweep.csv"), *reference_) << "resumed CSV differs from the uninterrupted one";
        EXPECT_FALSE(fs::exists(journal()));
        const json summary = json::parse(read_text(out_ + "/sweep.json"));
        EXPECT_EQ(summary["from_journal"], kSlow);
        EXPECT_EQ(summary["computed_this_run"], 1);
    }

    static std::string* dir_;
    static std::string* case_;
    static std::string* reference_;
    std::string out_;
};

std::string* SweepStop::dir_ = nullptr;
std::string* SweepStop::case_ = nullptr;
std::string* SweepStop::reference_ = nullptr;

void expect_stopped_in_time(const CommandResult& r, const char* what) {
    std::printf("%s: ended %.3f s after the signal (%.2f s in all), exit code %d\n", what, r.after_signal, r.seconds,
                r.exit_code);
    EXPECT_FALSE(r.hung) << r.err;
    EXPECT_GE(r.after_signal, 0.0);
    EXPECT_LT(r.after_signal, kStopBound) << what << ": no stop within " << kStopBound << " s of the signal";
}

TEST_F(SweepStop, SigintStopsWithin1sKeepsTheJournalAndResumesIdentically) {
    test::ChildProcess child(command({"--threads", "2", "--out", out_}));
    const CommandResult r = interrupt(child, SIGINT);
    expect_stopped_in_time(r, "sweep, SIGINT");
    EXPECT_EQ(r.exit_code, 130) << r.err;
    EXPECT_EQ(r.term_signal, 0) << "killed by the signal instead of stopping";
    EXPECT_NE(r.err.find("sweep interrupted: 5 of 6 points done, kept in " + journal() +
                         "; run the same command with --resume to finish it"),
              std::string::npos)
        << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
    expect_intact_then_resume();
}

TEST_F(SweepStop, SigtermStopsWithin1sKeepsTheJournalAndResumesIdentically) {
    test::ChildProcess child(command({"--threads", "2", "--out", out_}));
    const CommandResult r = interrupt(child, SIGTERM);
    expect_stopped_in_time(r, "sweep, SIGTERM");
    EXPECT_EQ(r.exit_code, 143) << r.err;
    EXPECT_EQ(r.term_signal, 0) << "killed by the signal instead of stopping";
    EXPECT_NE(r.err.find("run the same command with --resume to finish it"), std::string::npos) << r.err;
    expect_intact_then_resume();
}

// As a user would run it: `timeout -s TERM 5 vibroimpact sweep ...` exits within 6 s with the journal
// intact (here with a 2 s timeout, the same shape sooner: the slow point runs for about 8 s).
TEST_F(SweepStop, TimeoutCommandEndsTheSweepWithItsJournal) {
    const std::string timeout = test::find_on_path("timeout");
    if (timeout.empty()) GTEST_SKIP() << "timeout (coreutils) is not on PATH";
    std::vector<std::string> argv{timeout, "-s", "TERM", "2"};
    for (const std::string& a : command({"--out", out_})) argv.push_back(a);
    const CommandResult r = test::run_program(argv);
    std::printf("timeout -s TERM 2 vibroimpact sweep: %.2f s in all, exit code %d\n", r.seconds, r.exit_code);
    EXPECT_FALSE(r.hung);
    EXPECT_LT(r.seconds, 2.0 + kStopBound);
    EXPECT_EQ(r.exit_code, 124) << "timeout reports 124 when it had to signal the command: " << r.err;
    EXPECT_NE(r.err.find("run the same command with --resume"), std::string::npos) << r.err;
    const auto rows = journal_rows(journal(), csv_header());
    EXPECT_EQ(rows.size(), kSlow);
    for (const auto& [index, row] : rows) {
        if (index < kSlow) {
            EXPECT_EQ(row, reference_row(index)) << index;
        }
    }
}

// Ctrl-C in mpirun's terminal (the ranks are in process groups of their own, so only mpirun gets
// it), or `kill` to mpirun: mpirun passes the signal on to the ranks (about
// 1 s later with Open MPI 4.1), rank 0 keeps the journal and prints how to resume; mpirun reports
// the job as aborted with its own exit code (1). A stopped rank does not wait for MPI_Finalize past
// 0.3 s (mpirun no longer answers it), so mpirun ends soon after.
TEST_F(SweepStop, SigtermAndSigintToMpirunKeepTheJournalAndResumeIdentically) {
    if (const std::string why = test::mpi_unavailable(); !why.empty()) GTEST_SKIP() << why;
    for (const int sig : {SIGTERM, SIGINT}) {
        SCOPED_TRACE(sig == SIGTERM ? "SIGTERM" : "SIGINT");
        fs::remove_all(out_);
        std::vector<std::string> argv = test::mpi_argv(args({"--threads", "1", "--out", out_}));
        test::ChildProcess child(argv, test::mpi_env(), true);
        const CommandResult r = interrupt(child, sig);
        expect_stopped_in_time(r, sig == SIGTERM ? "mpirun -n 2 sweep, SIGTERM to mpirun"
                                                 : "mpirun -n 2 sweep, SIGINT to mpirun");
        EXPECT_NE(r.exit_code, 0) << r.err;
        EXPECT_NE(r.err.find("sweep interrupted: 5 of 6 points done"), std::string::npos) << r.err;
        expect_intact_then_resume();
    }
}

// With Open MPI's odls_base_sigkill_timeout at 0, mpirun sends SIGCONT, SIGTERM and SIGKILL to the
// ranks at once after its own SIGTERM and ends without waiting (docs/sweeps.md): the ranks are killed,
// not stopped, so nothing says how to resume, but every journaled point is whole and --resume
// finishes the sweep as an uninterrupted run would.
TEST_F(SweepStop, MpirunWithoutSigkillTimeoutKillsTheRanksAndTheJournalStillResumes) {
    if (const std::string why = test::mpi_unavailable(); !why.empty()) GTEST_SKIP() << why;
    std::vector<std::string> env = test::mpi_env();
    env.push_back("OMPI_MCA_odls_base_sigkill_timeout=0");
    test::ChildProcess child(test::mpi_argv(args({"--threads", "1", "--out", out_})), env, true);
    const CommandResult r = interrupt(child, SIGTERM);
    expect_stopped_in_time(r, "mpirun -n 2 sweep, odls_base_sigkill_timeout 0, SIGTERM to mpirun");
    EXPECT_NE(r.exit_code, 0) << r.err;
    expect_intact_then_resume();
}

// Slurm's --signal=TERM@T (and `kill` of every rank) signals each rank at once, not through mpirun:
// every rank stops, rank 0 keeps the journal, the ranks exit with 143 (which mpirun then reports);
// resumed under MPI as a requeued job would be.
TEST_F(SweepStop, SigtermToEveryMpiRankKeepsTheJournal) {
    if (const std::string why = test::mpi_unavailable(); !why.empty()) GTEST_SKIP() << why;
    test::ChildProcess child(test::mpi_argv(args({"--threads", "1", "--out", out_})), test::mpi_env(), true);
    const CommandResult r = interrupt(child, SIGTERM, true);
    expect_stopped_in_time(r, "mpirun -n 2 sweep, SIGTERM to every rank");
    EXPECT_EQ(r.exit_code, 143) << r.err;
    EXPECT_NE(r.err.find("sweep interrupted: 5 of 6 points done"), std::string::npos) << r.err;
    std::vector<std::string> mpirun = test::mpi_argv({});
    expect_intact_then_resume(mpirun);
}

TEST_F(SweepStop, PointTimeoutMarksTheSlowPointAndTheSweepGoesOn) {
    const CommandResult r = test::run_vibroimpact(args({"--point-timeout", "0.5", "--out", out_}));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    std::printf("sweep with --point-timeout 0.5: %.2f s in all\n", r.seconds);
    EXPECT_LT(r.seconds, 0.5 + kStopBound) << "the slow point was not stopped at its limit";
    EXPECT_NE(r.err.find("1 of 6 points failed (the status column says why)"), std::string::npos) << r.err;
    const auto lines = lines_of(read_text(out_ + "/sweep.csv"));
    ASSERT_EQ(lines.size(), 7u);
    for (std::size_t i = 0; i < kSlow; ++i) EXPECT_EQ(lines[i + 1], reference_row(i)) << i;
    const std::string value = reference_row(kSlow).substr(0, reference_row(kSlow).find(','));
    // Every result the point did not reach is the missing-value marker.
    std::string missing;
    for (std::size_t k = 2; k < cell_count(csv_header()); ++k) missing += ",nan";
    // The status says what the point was doing: where the exact solver had got to, its last piece
    // and the closest contact gap (no comma: the cell needs no quotes).
    const std::string timed_out = value + missing + ",timeout: more than 0.5 s of wall time (raise --point-timeout); "
                                                    "the exact solver had reached t = ";
    EXPECT_EQ(lines[kSlow + 1].substr(0, timed_out.size()), timed_out) << lines[kSlow + 1];
    EXPECT_NE(lines[kSlow + 1].find(" s of " + kSlowHorizon + " s in "), std::string::npos) << lines[kSlow + 1];
    EXPECT_NE(lines[kSlow + 1].find(" pieces; last piece "), std::string::npos) << lines[kSlow + 1];
    EXPECT_NE(lines[kSlow + 1].find("; closest contact gap "), std::string::npos) << lines[kSlow + 1];
    const json summary = json::parse(read_text(out_ + "/sweep.json"));
    EXPECT_EQ(summary["failed"], 1);
    ASSERT_EQ(summary["failures"].size(), 1u);
    EXPECT_EQ(summary["failures"][0]["index"], kSlow);
}

// The same slow point integrated by CVODE: its timeout says the time CVODE had reached, its steps,
// its last step and the closest contact gap.
TEST_F(SweepStop, PointTimeoutInCvodeSaysWhereTheIntegratorWas) {
    std::string text = read_text(*case_);
    const std::string method = "method = \"exact\"";
    const auto at = text.find(method);
    ASSERT_NE(at, std::string::npos);
    text.replace(at, method.size(), "method = \"cvode\"");
    // CVODE's sweep points keep their samples: one every 1 us over 0.1 s stays within the history's limit.
    const std::string step = "output_step = \"10 ns\"";
    ASSERT_NE(text.find(step), std::string::npos);
    text.replace(text.find(step), step.size(), "output_step = \"1 us\"");
    write_text(*dir_ + "/undamped_cvode.toml", text);
    const CommandResult r = test::run_vibroimpact({"sweep", *dir_ + "/undamped_cvode.toml", "--set", "solver.horizon=0.1",
                                                   "--point-timeout", "0.5", "--threads", "1"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto lines = lines_of(r.out);
    ASSERT_EQ(lines.size(), 2u) << r.out;
    const std::string status = lines[1].substr(lines[1].find(",timeout: ") + 1);
    std::printf("%s\n", status.c_str());
    EXPECT_EQ(status.rfind("timeout: more than 0.5 s of wall time (raise --point-timeout); CVODE had reached t = ", 0), 0u)
        << status;
    EXPECT_NE(status.find(" s of 0.1 s in "), std::string::npos) << status;
    EXPECT_NE(status.find(" steps; last step "), std::string::npos) << status;
    EXPECT_NE(status.find("; closest contact gap "), std::string::npos) << status;
}

// A journal whose slow point timed out: --resume keeps it as it is and computes only the points
// missing; --retry-failed computes it again (here without a limit), and the CSV is then the one of
// an uninterrupted run.
TEST_F(SweepStop, ResumeKeepsFailedPointsUnlessRetryFailed) {
    const CommandResult timed = test::run_vibroimpact(args({"--point-timeout", "0.5", "--out", out_ + "-timed"}));
    ASSERT_EQ(timed.exit_code, 0) << timed.err;
    const auto timed_lines = lines_of(read_text(out_ + "-timed/sweep.csv"));
    const std::string fingerprint = json::parse(read_text(out_ + "-timed/sweep.json"))["fingerprint"];
    fs::remove_all(out_ + "-timed");
    ASSERT_EQ(timed_lines.size(), 7u);
    // Points 0, 2 and the timed-out 5 are in the journal; 1, 3 and 4 are not.
    std::string text = "# vibroimpact sweep journal 1\n# fingerprint " + fingerprint + "\n# points 6\nindex," +
                       csv_header() + "\n";
    for (const std::size_t i : {0u, 2u, 5u}) text += std::to_string(i) + "," + timed_lines[i + 1] + "\n";
    fs::create_directories(out_);
    write_text(journal(), text);

    // The same sweep without --retry-failed: the timeout stays, only 1, 3 and 4 run.
    const std::string saved = out_ + "-saved";
    fs::copy(out_, saved, fs::copy_options::recursive);
    const CommandResult kept = test::run_vibroimpact(args({"--point-timeout", "0", "--out", out_, "--resume"}));
    ASSERT_EQ(kept.exit_code, 0) << kept.err;
    const auto kept_lines = lines_of(read_text(out_ + "/sweep.csv"));
    ASSERT_EQ(kept_lines.size(), 7u);
    EXPECT_EQ(kept_lines[kSlow + 1], timed_lines[kSlow + 1]) << "a failed point was retried without --retry-failed";
    json summary = json::parse(read_text(out_ + "/sweep.json"));
    EXPECT_EQ(summary["from_journal"], 3);
    EXPECT_EQ(summary["computed_this_run"], 3);
    EXPECT_EQ(summary["failed"], 1);

    // With --retry-failed the slow point is computed again, to the end this time.
    fs::remove_all(out_);
    fs::rename(saved, out_);
    const CommandResult retried =
        test::run_vibroimpact(args({"--point-timeout", "0", "--out", out_, "--resume", "--retry-failed"}));
    ASSERT_EQ(retried.exit_code, 0) << retried.err;
    EXPECT_EQ(read_text(out_ + "/sweep.csv"), *reference_);
    summary = json::parse(read_text(out_ + "/sweep.json"));
    EXPECT_EQ(summary["from_journal"], 2);
    EXPECT_EQ(summary["computed_this_run"], 4);
    EXPECT_EQ(summary["failed"], 0);
}

TEST_F(SweepStop, RetryFailedWithoutResumeIsBadInput) {
    const CommandResult r = test::run_vibroimpact(args({"--retry-failed", "--out", out_}));
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_EQ(r.err, "vibroimpact: error: --retry-failed: goes with --resume (failed points of a journal)\n");
    EXPECT_FALSE(fs::exists(out_));
}

// On a terminal the progress line is redrawn twice a second while a point runs and names the one
// running longest once it passes 2 s (here the slow point, stopped by its 4 s limit).
TEST_F(SweepStop, ProgressLineNamesTheSlowestRunningPoint) {
    const CommandResult r = test::run_on_terminal(command({"--point-timeout", "4", "--threads", "2", "--out", out_}));
    ASSERT_FALSE(r.hung) << r.out;
    EXPECT_EQ(r.exit_code, 0) << r.out;
    // "slowest: point 5, 0:0N running" with N from 2 to 4 (the line is drawn every 0.5 s).
    EXPECT_NE(r.out.find("slowest: point 5, 0:0"), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("slowest: point 5, 0:01"), std::string::npos) << "shown before 2 s: " << r.out;
    EXPECT_NE(r.out.find("6/6 points"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace vi
