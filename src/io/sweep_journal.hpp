#pragma once
// The journal of a sweep: every finished point's CSV row, appended and flushed as it finishes, so
// that an interrupted sweep can resume without computing them again.

#include <cstddef>
#include <cstdio>
#include <map>
#include <memory>
#include <string>

namespace vi {

// The points a journal holds, by grid index.
struct JournalContents {
    std::map<std::size_t, std::string> rows;  // grid index -> CSV row (no newline); a point's last line
    std::size_t complete_bytes = 0;           // length of the file up to its last complete line
    bool torn_tail = false;                   // the file ended inside a line (a hard kill mid-write)
};

// An open journal file, appended to one line at a time.
//
// Format: three header lines "# vibroimpact sweep journal 1", "# fingerprint <hex>",
// "# points <N>", the line "index,<CSV header>", then one line "<index>,<CSV row>" per point.
class SweepJournal {
public:
    // The file name inside a sweep's output folder.
    static constexpr const char* kFileName = "sweep.journal";

    // Reads the journal at path. Throws InputError naming the file (and the line) when it is not a
    // sweep journal, belongs to another sweep (fingerprint, point count or CSV header differ), or
    // holds a malformed complete line. A last line without its newline is left out (torn_tail).
    static JournalContents read(const std::string& path, const std::string& fingerprint, std::size_t points,
                                const std::string& csv_header);

    // Starts a new journal at path (the file must not exist) with its header lines.
    static SweepJournal create(const std::string& path, const std::string& fingerprint, std::size_t points,
                               const std::string& csv_header);

    // Reopens a journal read before, cutting off a torn last line, to append to it.
    static SweepJournal reopen(const std::string& path, const JournalContents& contents);

    // Appends "<index>,<row>\n" and flushes it to the operating system (it survives a killed
    // process, not a power cut). Throws std::runtime_error when the write fails.
    void append(std::size_t index, const std::string& row);

    // Closes the file and deletes it (once the final CSV is written).
    void remove();

private:
    struct Closer {
        void operator()(std::FILE* f) const { std::fclose(f); }
    };
    SweepJournal(std::string path, std::FILE* file) : path_(std::move(path)), file_(file) {}
    std::string path_;
    std::unique_ptr<std::FILE, Closer> file_;
};

}  // namespace vi
