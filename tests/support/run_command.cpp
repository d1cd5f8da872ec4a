#include "support/run_command.hpp"

#include <fcntl.h>
#include <poll.h>
#include <pty.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <vector>

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
    // The extra entries replace variables of the same name. A command's progress report is off
    // unless the test asks for it (--progress, or this variable among the extra entries): a run
    // that happens to last longer than the report's interval on a loaded machine must not change
    // what the test reads on stderr.
    std::vector<std::string> extra = env;
    const std::string progress = "VIBROIMPACT_PROGRESS=";
    bool progress_given = false;
    for (const std::string& x : env) progress_given = progress_given || x.compare(0, progress.size(), progress) == 0;
    if (!progress_given) extra.push_back(progress + "none");
    std::vector<std::string> env_store = extra;
    for (char** e = environ; *e; ++e) {
        const std::string entry = *e;
        const std::string name = entry.substr(0, entry.find('=') + 1);
        bool replaced = false;
        for (const std::string& x : extra) replaced = replaced || x.compare(0, name.size(), name) == 0;
        if (!replaced) env_store.push_back(entry);
    }
    std::vector<char*> envp;
    for (auto& e : env_store) envp.push_back(e.data());
    envp.push_back(nullptr);

    const pid_t pid = fork();
    if (pid < 0) throw std::runtime_error("fork failed");
    if (pid == 0) {
        if (own_group) setpgid(0, 0);
        // The child starts with SIGINT and SIGTERM at their defaults, whatever this process inherited
        // (a test runner started in the background has SIGINT ignored).
        signal(SIGINT, SIG_DFL);
        signal(SIGTERM, SIG_DFL);
        sigset_t none;
        sigemptyset(&none);
        sigprocmask(SIG_SETMASK, &none, nullptr);
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

int ChildProcess::signal_children(int sig) {
    if (signalled_ < 0.0) signalled_ = now_s();
    std::vector<pid_t> kids;
    for (const auto& entry : std::filesystem::directory_iterator("/proc")) {
        const std::string name = entry.path().filename().string();
        if (name.empty() || name.find_first_not_of("0123456789") != std::string::npos) continue;
        // /proc/<pid>/stat: "pid (comm) state ppid ..."; comm may hold spaces, so read after the ')'.
        const std::string stat = read_text(entry.path().string() + "/stat");
        const std::size_t close = stat.rfind(')');
        if (close == std::string::npos) continue;
        std::istringstream rest(stat.substr(close + 1));
        std::string state;
        long ppid = 0;
        rest >> state >> ppid;
        if (ppid == pid_) kids.push_back(static_cast<pid_t>(std::stol(name)));
    }
    for (const pid_t k : kids) kill(k, sig);
    return static_cast<int>(kids.size());
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
    r.term_signal = WIFSIGNALED(status_) ? WTERMSIG(status_) : 0;
    r.out = read_text(dir_ + "/stdout");
    r.err = read_text(dir_ + "/stderr");
    if (r.hung) {
        r.err += "\n[test: killed after " + std::to_string(limit_s) + " s: counted as a hang]\n";
    }
    r.seconds = ended_ - started_;
    if (signalled_ >= 0.0) r.after_signal = ended_ - signalled_;
    return r;
}

CommandResult run_on_terminal(const std::vector<std::string>& argv, double limit_s) {
    std::vector<std::string> store = argv;
    std::vector<char*> args;
    for (auto& a : store) args.push_back(a.data());
    args.push_back(nullptr);
    const double start = now_s();
    int master = -1;
    const pid_t pid = forkpty(&master, nullptr, nullptr, nullptr);
    if (pid < 0) throw std::runtime_error("forkpty failed");
    if (pid == 0) {
        signal(SIGINT, SIG_DFL);
        signal(SIGTERM, SIG_DFL);
        // What a user's terminal shows: the progress report at its default.
        unsetenv("VIBROIMPACT_PROGRESS");
        execvp(args[0], args.data());
        _exit(127);
    }
    CommandResult r;
    char buf[4096];
    // Read until the terminal closes (EIO once the child and its children are gone) or the limit.
    for (;;) {
        const double left = start + limit_s - now_s();
        if (left <= 0.0) {
            r.hung = true;
            kill(pid, SIGKILL);
            break;
        }
        pollfd p{master, POLLIN, 0};
        const int ready = poll(&p, 1, static_cast<int>(std::min(left, 1.0) * 1000.0) + 1);
        if (ready < 0 && errno != EINTR) break;
        if (ready <= 0) continue;
        const ssize_t n = read(master, buf, sizeof buf);
        if (n <= 0) break;
        r.out.append(buf, static_cast<std::size_t>(n));
    }
    int status = 0;
    waitpid(pid, &status, 0);
    close(master);
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    r.term_signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
    r.seconds = now_s() - start;
    if (r.hung) r.out += "\n[test: killed after " + std::to_string(limit_s) + " s: counted as a hang]\n";
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
