#include "support/run_command.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "support/test_files.hpp"

extern char** environ;

namespace vi::test {
namespace {

// Forks and execs argv with stdout and stderr into dir/stdout and dir/stderr, stdin from /dev/null.
// Everything the child needs is built before fork, so the child only makes system calls.
pid_t spawn(const std::vector<std::string>& args, const std::vector<std::string>& env, const std::string& dir,
            bool own_group) {
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
        if (own_group) setpgid(0, 0);
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

double now_s() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

constexpr auto kPoll = std::chrono::milliseconds(2);

}  // namespace

bool wait_until(const std::function<bool()>& ready, double limit_s) {
    const double give_up = now_s() + limit_s;
    // Bounded by the limit: one poll every few milliseconds.
    while (!ready()) {
        if (now_s() > give_up) return ready();
        std::this_thread::sleep_for(kPoll);
    }
    return true;
}

CommandResult run_program(const std::vector<std::string>& argv, const std::vector<std::string>& env,
                          double limit_s) {
    // Its own process group, so that a hang is killed with whatever it started (mpirun's ranks).
    ChildProcess child(argv, env, true);
    return child.wait(limit_s);
}

CommandResult run_vibroimpact(const std::vector<std::string>& args, double limit_s) {
    std::vector<std::string> argv{VI_EXE};
    argv.insert(argv.end(), args.begin(), args.end());
    return run_program(argv, {}, limit_s);
}

ChildProcess::ChildProcess(const std::vector<std::string>& argv, const std::vector<std::string>& env,
                           bool own_group)
    : dir_(make_temp_dir()), own_group_(own_group), started_(now_s()) {
    pid_ = spawn(argv, env, dir_, own_group);
}

ChildProcess::~ChildProcess() {
    if (!reaped_) {
        if (own_group_) kill(-pid_, SIGKILL);
        kill(pid_, SIGKILL);
        wait();
    }
    std::filesystem::remove_all(dir_);
}

double ChildProcess::seconds() const { return now_s() - started_; }

void ChildProcess::signal(int sig) {
    if (signalled_ < 0.0) signalled_ = now_s();
    kill(pid_, sig);
}

void ChildProcess::signal_group(int sig) {
    if (signalled_ < 0.0) signalled_ = now_s();
    kill(-pid_, sig);
}

bool ChildProcess::running() {
    if (reaped_) return false;
    const pid_t got = waitpid(pid_, &status_, WNOHANG);
    if (got == pid_ || got < 0) {
        reaped_ = true;
        ended_ = now_s();
    }
    return !reaped_;
}

CommandResult ChildProcess::wait(double limit_s) {
    CommandResult r;
    if (!wait_until([this] { return !running(); }, limit_s)) {
        r.hung = true;
        if (own_group_) kill(-pid_, SIGKILL);
        kill(pid_, SIGKILL);
        waitpid(pid_, &status_, 0);
        reaped_ = true;
        ended_ = now_s();
    }
    r.exit_code = WIFEXITED(status_) ? WEXITSTATUS(status_) : 128 + WTERMSIG(status_);
    r.out = read_text(dir_ + "/stdout");
    r.err = read_text(dir_ + "/stderr");
    if (r.hung) {
        r.err += "\n[test: killed after " + std::to_string(limit_s) + " s: counted as a hang]\n";
    }
    r.seconds = ended_ - started_;
    if (signalled_ >= 0.0) r.after_signal = ended_ - signalled_;
    return r;
}

std::string find_on_path(const std::string& name) {
    const char* path = std::getenv("PATH");
    std::istringstream dirs(path ? path : "");
    for (std::string dir; std::getline(dirs, dir, ':');) {
        const std::filesystem::path p = std::filesystem::path(dir) / name;
        if (!dir.empty() && access(p.c_str(), X_OK) == 0) return p.string();
    }
    return "";
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
