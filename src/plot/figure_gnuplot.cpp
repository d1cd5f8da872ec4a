#include "plot/figure_gnuplot.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "model/parallel_for.hpp"
#include "io/text_file.hpp"
#include "model/run_control.hpp"
#include "model/number_format.hpp"

namespace vi {
namespace {

namespace fs = std::filesystem;

bool executable(const fs::path& p) {
    std::error_code ec;
    return fs::is_regular_file(p, ec) && access(p.c_str(), X_OK) == 0;
}

// A file gnuplot wrote; empty when it wrote none (the caller says which).
std::string slurp(const fs::path& p) {
    std::string reason;
    return file_text(p.string(), reason).value_or(std::string());
}

// An image gnuplot wrote, read back; throws std::runtime_error saying why when there is none or it
// cannot be read (larger than the readers' limit: a figure of too many points).
std::string read_image(const fs::path& p, const std::string& script) {
    std::string reason;
    std::error_code ec;
    if (!fs::exists(p, ec)) throw std::runtime_error(script + ": gnuplot wrote no image " + p.filename().string());
    std::optional<std::string> bytes = file_text(p.string(), reason);
    if (!bytes || bytes->empty()) {
        throw std::runtime_error(script + ": the image gnuplot wrote, " + p.filename().string() + ", cannot be read back (" +
                                 (bytes ? std::string("empty") : reason) + ")");
    }
    return std::move(*bytes);
}

void put(const fs::path& p, const std::string& text) {
    std::ofstream out(p, std::ios::binary);
    out << text;
    if (!out) throw std::runtime_error(p.string() + ": cannot write");
}

// How long one gnuplot process may take to draw its share of the figures: far above the second or
// two the paper's figures take, and a bound on the wait.
constexpr std::chrono::seconds kGnuplotLimit{600};

// Runs `program script` in `dir` with output to files there; returns the exit status (127: not run).
// A stop request kills gnuplot and throws StopRequested; gnuplot past kGnuplotLimit is killed and
// std::runtime_error thrown.
int run_in(const std::string& program, const std::string& script, const fs::path& dir) {
    const std::string out = (dir / ("." + script + ".out")).string();
    const std::string dir_s = dir.string();
    std::vector<std::string> args{program, script};
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    const pid_t pid = fork();
    if (pid < 0) return 127;
    if (pid == 0) {
        // Only async-signal-safe calls between fork and exec (the parent has threads).
        if (chdir(dir_s.c_str()) != 0) _exit(127);
        const int fo = open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const int fi = open("/dev/null", O_RDONLY);
        if (fo < 0 || fi < 0) _exit(127);
        dup2(fi, 0);
        dup2(fo, 1);
        dup2(fo, 2);
        execv(argv[0], argv.data());
        _exit(127);
    }
    // Polled rather than waited for, so that a stop (a signal, model/run_control.hpp) ends gnuplot
    // too and is honoured within milliseconds; bounded by kGnuplotLimit.
    int status = 0;
    const auto give_up = std::chrono::steady_clock::now() + kGnuplotLimit;
    for (;;) {
        const pid_t got = waitpid(pid, &status, WNOHANG);
        if (got == pid) break;
        if (got < 0 && errno != EINTR) return 127;
        const bool stop = stop_flag().load();
        const bool late = std::chrono::steady_clock::now() > give_up;
        if (stop || late) {
            kill(pid, SIGKILL);
            // Reaped at once (SIGKILL cannot be caught); a few retries only if a signal interrupts the wait.
            for (int tries = 0; tries < 100 && waitpid(pid, &status, 0) < 0 && errno == EINTR; ++tries) {
            }
            if (stop) check_run();  // throws StopRequested
            throw std::runtime_error("gnuplot: no end after " +
                                     std::to_string(std::chrono::duration_cast<std::chrono::seconds>(kGnuplotLimit).count()) +
                                     " s; killed");
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128;
}

std::string first_line(const std::string& text) {
    std::istringstream in(text);
    std::string line, last;
    while (std::getline(in, line)) {
        if (line.find_first_not_of(" \t^") == std::string::npos) continue;
        // gnuplot echoes the offending command before its message; the message says more.
        last = line;
        if (line.find("line ") != std::string::npos || line.find("rror") != std::string::npos) return line;
    }
    return last.empty() ? "no output" : last;
}

// A unique fresh folder under the system temp folder.
fs::path temp_folder() {
    std::string templ = (fs::temp_directory_path() / "vibroimpact_figures_XXXXXX").string();
    if (mkdtemp(templ.data()) == nullptr) throw std::runtime_error("cannot create a temporary folder for gnuplot");
    return templ;
}

}  // namespace

std::string gp_quote(const std::string& s) {
    std::string out = "'";
    for (char c : s) {
        out += c;
        if (c == '\'') out += '\'';
    }
    return out + "'";
}

std::string gp_number(double v) {
    if (!std::isfinite(v)) return "NaN";
    return significant(v, 10);
}

std::optional<std::string> find_gnuplot(const std::string& requested) {
    const std::string name = requested.empty() ? "gnuplot" : requested;
    if (name.find('/') != std::string::npos) {
        if (executable(name)) return fs::absolute(name).string();
        return std::nullopt;
    }
    const char* path = std::getenv("PATH");
    std::istringstream dirs(path ? path : "/usr/bin:/bin");
    std::string dir;
    while (std::getline(dirs, dir, ':')) {
        if (dir.empty()) continue;
        const fs::path candidate = fs::path(dir) / name;
        if (executable(candidate)) return candidate.string();
    }
    return std::nullopt;
}

std::string gnuplot_script(const FigureSpec& f) {
    // The terminals' font and line widths; the defaults (11 pt, width 1) are those of the paper's figures.
    std::ostringstream term;
    term << " font 'DejaVu Sans," << std::lround(11.0 * f.scale) << "'";
    if (f.scale != 1.0) term << " linewidth " << f.scale;
    std::ostringstream s;
    s << "# " << f.title << "\n# Drawn by vibroimpact from ";
    for (std::size_t i = 0; i < f.data.size(); ++i) s << (i ? ", " : "") << f.data[i].first;
    s << "; rerun in this folder with: gnuplot " << f.name << ".gp\n"
      << "reset\nset encoding utf8\nset datafile separator comma\n";
    if (f.animation_delay > 0) {
        // libgd's gif terminal (in gnuplot-nox): one image per plot command, looped.
        s << "set terminal gif animate delay " << f.animation_delay << " loop 0 optimize size " << f.width << ","
          << f.height << term.str() << "\nset output " << gp_quote(f.name + ".gif") << "\n"
          << f.plot << "\nunset output\nreset\n";
        return s.str();
    }
    s << "# The pngcairo terminal: anti-aliased PNG, DejaVu Sans (fonts-dejavu-core).\n"
      << "set terminal pngcairo size " << f.width << "," << f.height << term.str() << " enhanced\n"
      << "set output " << gp_quote(f.name + ".png") << "\n"
      << f.plot << "\nunset output\nreset\nset datafile separator comma\n"
      << "set terminal svg size " << f.width << "," << f.height << term.str() << " enhanced background rgb 'white'\n"
      << "set output " << gp_quote(f.name + ".svg") << "\n"
      << f.plot << "\nunset output\nreset\n";
    return s.str();
}

std::vector<RenderedFigure> render_figures(const std::string& gnuplot, const std::vector<FigureSpec>& figures, int threads) {
    const fs::path dir = temp_folder();
    std::vector<RenderedFigure> out(figures.size());
    try {
        for (std::size_t i = 0; i < figures.size(); ++i) {
            const FigureSpec& f = figures[i];
            for (const auto& [name, text] : f.data) put(dir / name, text);
            out[i].script = gnuplot_script(f);
            put(dir / (f.name + ".gp"), out[i].script);
        }
        // gnuplot's start (fonts, cairo) costs more than most figures: one process per thread, each
        // loading its share of the figures' scripts.
        const std::size_t batches = std::min<std::size_t>(figures.size(), static_cast<std::size_t>(resolve_thread_count(threads)));
        parallel_for(batches, threads, [&](std::size_t b) {
            std::string batch;
            for (std::size_t i = b; i < figures.size(); i += batches) batch += "load " + gp_quote(figures[i].name + ".gp") + "\n";
            const std::string name = ".batch" + std::to_string(b) + ".gp";
            put(dir / name, batch);
            const int status = run_in(gnuplot, name, dir);
            const std::string log = slurp(dir / ("." + name + ".out"));
            if (status != 0) {
                throw std::runtime_error("gnuplot " + (status == 127 ? "could not be run (" + gnuplot + ")" : "failed: " + first_line(log)));
            }
            // gnuplot reports some problems (a column that does not exist) as warnings and carries on.
            if (log.find("warning") != std::string::npos) throw std::runtime_error("gnuplot: " + first_line(log));
        });
        for (std::size_t i = 0; i < figures.size(); ++i) {
            if (figures[i].animation_delay > 0) {
                out[i].png = read_image(dir / (figures[i].name + ".gif"), figures[i].name + ".gp");
                continue;
            }
            out[i].png = read_image(dir / (figures[i].name + ".png"), figures[i].name + ".gp");
            out[i].svg = read_image(dir / (figures[i].name + ".svg"), figures[i].name + ".gp");
        }
    } catch (...) {
        std::error_code ec;
        fs::remove_all(dir, ec);
        throw;
    }
    std::error_code ec;
    fs::remove_all(dir, ec);
    return out;
}

std::map<std::string, std::string> figure_files(const std::vector<FigureSpec>& figures,
                                                const std::vector<RenderedFigure>& rendered,
                                                std::map<std::string, std::string>* png) {
    std::map<std::string, std::string> files;
    for (std::size_t i = 0; i < figures.size() && i < rendered.size(); ++i) {
        if (figures[i].animation_delay > 0) {
            files[figures[i].name + ".gif"] = rendered[i].png;
        } else {
            files[figures[i].name + ".png"] = rendered[i].png;
            files[figures[i].name + ".svg"] = rendered[i].svg;
        }
        files[figures[i].name + ".gp"] = rendered[i].script;
        for (const auto& [name, text] : figures[i].data) files[name] = text;
        if (png) (*png)[figures[i].name] = rendered[i].png;
    }
    return files;
}

}  // namespace vi
