#pragma once
// The lock of an output folder that a command keeps a journal in (sweep, optimize). While one run
// holds it, a second run into the same folder is refused, naming the process that holds it, instead
// of taking the first run's live journal for the one an interrupted run left (or, with --resume,
// computing the same points again beside it).
//
// The lock is a file in the folder holding the holder's pid, locked with flock(2): the kernel
// releases the lock when its process ends, however it ends, so the file a killed run left behind is
// taken over by the next run. A run that ends normally removes the file.

#include <string>
#include <vector>

namespace vi {

class FolderLock {
public:
    // The lock file's name inside the folder.
    static constexpr const char* kFileName = ".vibroimpact.lock";

    // Locks `dir`, creating it (and its parents) when missing. Throws InputError("DIR: in use by
    // process N (...)") when another process holds the lock, InputError("--out DIR: cannot create
    // the folder ...") when the folder cannot be made, std::runtime_error when the lock file cannot
    // be written.
    explicit FolderLock(const std::string& dir);
    // Releases the lock and removes its file; the folders this lock created that are still empty
    // (a run refused before it wrote anything) are removed too.
    ~FolderLock();
    FolderLock(const FolderLock&) = delete;
    FolderLock& operator=(const FolderLock&) = delete;

    [[nodiscard]] const std::string& path() const { return path_; }

private:
    void take(const std::string& dir);
    void remove_created_folders();

    std::string path_;
    std::vector<std::string> created_;  // folders made for this run, deepest first
    int fd_ = -1;
};

}  // namespace vi
