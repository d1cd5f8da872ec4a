#pragma once
// The progress of a long run on stderr (or a sink given instead): a bar redrawn in place on a
// terminal, or one line every few seconds in a log (a pipe, a file, a batch job), with done of
// total, the rate and the time left.

#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <functional>
#include <mutex>
#include <string>
#include <thread>

namespace vi {

// How a run shows its progress: a bar redrawn in place, lines, or nothing.
enum class ProgressStyle { bar, lines, none };

// The environment variable that gives the progress mode's default (a batch script or a CI job sets it once).
inline constexpr const char* kProgressEnvironment = "VIBROIMPACT_PROGRESS";

// The style a mode names: "auto" is a bar when `terminal` (the output is a terminal) and lines
// otherwise; an empty mode is VIBROIMPACT_PROGRESS's, else auto. Throws InputError naming `setting`
// (or the environment variable) for a mode that is none of auto, bar, lines, none.
ProgressStyle progress_style_named(const std::string& mode, bool terminal, const std::string& setting);

// Where the report's text goes (each piece whole: a line with its newline, or a bar's redrawing);
// empty: stderr.
using ProgressSink = std::function<void(const std::string& text)>;

// A count of work done against its total, reported as it goes. Thread-safe.
class Progress {
public:
    // what: the command ("sweep"); unit: what is counted ("points"); total: of them; done: already
    // done before this run (taken over from a journal: not in the rate). An `upper_bound` total is a
    // budget the work may stop short of (then the time left is an upper bound, said "at most").
    Progress(std::string what, std::string unit, std::size_t total, std::size_t done, ProgressStyle style,
             double interval_s, bool upper_bound = false, ProgressSink sink = {});
    ~Progress();  // finish()
    Progress(const Progress&) = delete;
    Progress& operator=(const Progress&) = delete;
    // n more units done.
    void advance(std::size_t n = 1);
    // n more units done that this run did not compute (a journal's): not in the rate.
    void skip(std::size_t n = 1);
    // The total once it is known (a Progress made with total 0 shows nothing but say() until then).
    void set_total(std::size_t total);
    // A line of its own (an event of the run), written above the bar; nothing when the style is none.
    void say(const std::string& line);
    // Text shown after the counts (the slowest point, the best value so far); empty: none.
    void set_note(const std::string& note);
    // The ticker's call: redraws the bar, or writes a line once the interval has passed since the last.
    void tick();
    // The final state: the bar's last drawing and its newline; in lines, a last line when a line has
    // been written and the count moved since (a run shorter than the interval writes no line at all).
    void finish();
    [[nodiscard]] ProgressStyle style() const { return style_; }

private:
    using Clock = std::chrono::steady_clock;
    void count(std::size_t done, std::size_t computed);
    void draw_bar();    // under mutex_
    void write_line();  // under mutex_
    void emit(const std::string& text);  // under mutex_
    [[nodiscard]] std::string counts() const;  // under mutex_
    std::string what_, unit_;
    std::size_t total_, done_, computed_ = 0, shown_ = 0;
    const ProgressStyle style_;
    double interval_s_;
    bool upper_bound_;
    ProgressSink sink_;
    bool wrote_line_ = false;
    bool finished_ = false;
    bool drawn_ = false;  // the bar is on the terminal's last line
    Clock::time_point start_ = Clock::now();
    Clock::time_point last_ = start_;  // of the last drawing or line
    std::string note_;
    std::mutex mutex_;  // the workers' advance and the ticker's tick draw the same output
};

// Calls before() (if given) then progress.tick() twice a second on a thread of its own while it
// lives, so that the report moves while a slow step runs (no thread when the style is none).
class ProgressTicker {
public:
    explicit ProgressTicker(Progress& progress, std::function<void()> before = {});
    ~ProgressTicker();
    ProgressTicker(const ProgressTicker&) = delete;
    ProgressTicker& operator=(const ProgressTicker&) = delete;

private:
    std::mutex mutex_;
    std::condition_variable wake_;
    bool done_ = false;
    std::thread thread_;
};

// A duration as m:ss, or h:mm:ss from an hour on.
std::string duration_text(double seconds);

}  // namespace vi
