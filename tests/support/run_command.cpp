#include "support/run_command.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <thread>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "support/test_files.hpp"

extern char** environ;

namespace vi::test {
namespace {

// Forks and execs argv with stdout and stderr into dir/stdout and dir/stderr, stdin from /dev/null.
// Everything the child needs is built before fork, so the child only makes system calls.
pid_t spawn(const std::vector<std::string>& args, const std::vector<std::string>& env, const std::string& dir) {
    const std::string out_path = dir + "/stdout";
    const std::string err_path = dir + "/stderr";
    std::vector<std::string> argv_store = args;
    std::vector<char*> argv;
    for (auto& a : argv_store) argv.push_back(a.data());
    argv.push_back(nullptr);
    // The extra entries replace variables of the same name.
    std::vector<std::string> env_store = env;
    for (char** e = environ; *e; ++e) {
        const std::string entry = *e;
        const std::string name = entry.substr(0, entry.find('=') + 1);
        bool replaced = false;
        for (const std::string& x : env) replaced = replaced || x.compare(0, name.size(), name) == 0;
        if (!replaced) env_store.push_back(entry);
    }
    std::vector<char*> envp;
    for (auto& e : env_store) envp.push_back(e.data());
    envp.push_back(nullptr);

    const pid_t pid = fork();
    if (pid < 0) throw std::runtime_error("fork failed");
    if (pid == 0) {
        const int fo = open(out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const int fe = open(err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const int fi = open("/dev/null", O_RDONLY);
        if (fo < 0 || fe < 0 || fi < 0) _exit(127);
        dup2(fi, 0);
        dup2(fo, 1);
        dup2(fe, 2);
        execvpe(argv[0], argv.data(), envp.data());
        _exit(127);
    }
    return pid;
}

CommandResult reap(pid_t pid, const std::string& dir) {
    int status = 0;
    waitpid(pid, &status, 0);
    CommandResult r;
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    r.out = read_text(dir + "/stdout");
    r.err = read_text(dir + "/stderr");
    return r;
}

// Waits for pid until limit_seconds have passed, then kills it; polls every 2 ms (the loop ends at the
// deadline whatever the child does).
CommandResult reap_within(pid_t pid, const std::string& dir, double limit_seconds) {
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    const auto deadline = start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(limit_seconds));
    int status = 0;
    bool done = false;
    bool killed = false;
    while (!done) {
        const pid_t r = waitpid(pid, &status, WNOHANG);
        if (r == pid || r < 0) {
            done = true;
        } else if (Clock::now() >= deadline) {
            kill(pid, SIGKILL);
            waitpid(pid, &status, 0);
            killed = true;
            done = true;
        } else {
            std::this_thread::sleep_for(std::chrono::milliseconds(2));
        }
    }
    CommandResult res;
    res.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    res.out = read_text(dir + "/stdout");
    res.err = read_text(dir + "/stderr");
    res.timed_out = killed;
    res.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    return res;
}

}  // namespace

CommandResult run_vibroimpact_limited(const std::vector<std::string>& args, double limit_seconds) {
    std::vector<std::string> argv{VI_EXE};
    argv.insert(argv.end(), args.begin(), args.end());
    const std::string dir = make_temp_dir();
    const CommandResult r = reap_within(spawn(argv, {}, dir), dir, limit_seconds);
    std::filesystem::remove_all(dir);
    return r;
}

CommandResult run_program(const std::vector<std::string>& argv, const std::vector<std::string>& env) {
    const std::string dir = make_temp_dir();
    const CommandResult r = reap(spawn(argv, env, dir), dir);
    std::filesystem::remove_all(dir);
    return r;
}

CommandResult run_vibroimpact(const std::vector<std::string>& args) {
    std::vector<std::string> argv{VI_EXE};
    argv.insert(argv.end(), args.begin(), args.end());
    return run_program(argv);
}

ChildProcess::ChildProcess(const std::vector<std::string>& argv, const std::vector<std::string>& env)
    : dir_(make_temp_dir()), pid_(spawn(argv, env, dir_)) {}

ChildProcess::~ChildProcess() {
    if (!reaped_) {
        kill(pid_, SIGKILL);
        wait();
    }
    std::filesystem::remove_all(dir_);
}

CommandResult ChildProcess::wait() {
    reaped_ = true;
    return reap(pid_, dir_);
}

std::string vibroimpact_path() { return VI_EXE; }

std::string source_path(const std::string& relative) {
    return (std::filesystem::path(VI_SOURCE_DIR) / relative).string();
}

std::string make_temp_dir() {
    std::string templ = (std::filesystem::temp_directory_path() / "vi_test_XXXXXX").string();
    if (mkdtemp(templ.data()) == nullptr) throw std::runtime_error("mkdtemp failed");
    return templ;
}

}  // namespace vi::test
