#include "sweep/folder_lock.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <thread>

#include "model/input_error.hpp"

namespace vi {
namespace {

namespace fs = std::filesystem;

// How often a lock is tried again when its file changed under us (a holder releasing it between
// our open and our flock), and how long the holder's pid is waited for (written just after it
// locks): both far beyond any real interleaving, and a bound on the loop.
constexpr int kLockAttempts = 100;
constexpr int kPidReads = 20;

// The pid the holder wrote into the lock file, or "" when it cannot be told: the holder writes it
// just after it locks, so the file may for a moment be empty or still name the killed run whose
// lock it took over (a process that no longer exists).
std::string holder_pid(int fd) {
    for (int tries = 0; tries < kPidReads; ++tries) {
        char buf[32] = {};
        const ssize_t n = pread(fd, buf, sizeof buf - 1, 0);
        std::string text = n > 0 ? std::string(buf, static_cast<std::size_t>(n)) : std::string();
        while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
        const bool digits = !text.empty() && text.size() < 12 && text.find_first_not_of("0123456789") == std::string::npos;
        if (digits) {
            const pid_t pid = static_cast<pid_t>(std::stol(text));
            if (pid > 0 && (kill(pid, 0) == 0 || errno == EPERM)) return text;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return "";
}

// Whether fd is still the file at path (a releasing holder unlinks it before it unlocks).
bool still_at(int fd, const std::string& path) {
    struct stat open_file {}, named {};
    if (fstat(fd, &open_file) != 0 || stat(path.c_str(), &named) != 0) return false;
    return open_file.st_dev == named.st_dev && open_file.st_ino == named.st_ino;
}

std::runtime_error lock_failure(const std::string& path, const char* what) {
    return std::runtime_error(path + ": cannot " + what + " the lock file (" + std::strerror(errno) + ")");
}

}  // namespace

FolderLock::FolderLock(const std::string& dir) : path_((fs::path(dir) / kFileName).string()) {
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) {
        // The folders this run makes, deepest first: a refused run removes them again.
        for (fs::path p = fs::absolute(dir, ec); !p.empty() && !fs::exists(p, ec) && p != p.parent_path(); p = p.parent_path()) {
            created_.push_back(p.string());
        }
        fs::create_directories(dir, ec);
        if (ec || !fs::is_directory(dir)) {
            throw InputError("--out " + dir + ": cannot create the folder" + (ec ? " (" + ec.message() + ")" : ""));
        }
    }
    try {
        take(dir);
    } catch (...) {
        remove_created_folders();
        throw;
    }
}

void FolderLock::take(const std::string& dir) {
    for (int attempt = 0; attempt < kLockAttempts; ++attempt) {
        const int fd = open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
        if (fd < 0) throw lock_failure(path_, "create");
        if (flock(fd, LOCK_EX | LOCK_NB) != 0) {
            const int err = errno;
            const std::string pid = err == EWOULDBLOCK ? holder_pid(fd) : "";
            close(fd);
            if (err != EWOULDBLOCK) {
                errno = err;
                throw lock_failure(path_, "lock");
            }
            throw InputError(dir + ": in use by " + (pid.empty() ? std::string("another process") : "process " + pid) +
                             " (another run writes its journal here; wait for it to end, or choose another --out)");
        }
        if (!still_at(fd, path_)) {
            close(fd);
            continue;
        }
        const std::string pid = std::to_string(getpid()) + "\n";
        if (ftruncate(fd, 0) != 0 || pwrite(fd, pid.data(), pid.size(), 0) != static_cast<ssize_t>(pid.size())) {
            const int err = errno;
            unlink(path_.c_str());
            close(fd);
            errno = err;
            throw lock_failure(path_, "write");
        }
        fd_ = fd;
        return;
    }
    throw std::runtime_error(path_ + ": the lock file kept changing while it was taken; try again");
}

FolderLock::~FolderLock() {
    if (fd_ >= 0) {
        // Unlinked while still locked: a run that opened this file meanwhile finds, once it has the
        // lock, that the name no longer leads to it, and tries again on a fresh file.
        unlink(path_.c_str());
        close(fd_);
    }
    remove_created_folders();
}

void FolderLock::remove_created_folders() {
    for (const std::string& made : created_) {
        std::error_code ec;
        if (!fs::is_empty(made, ec) || ec || !fs::remove(made, ec)) break;
    }
}

}  // namespace vi
