#include "figure_output.hpp"

#include <stdexcept>

#include "io/text_file.hpp"
#include "model/run_control.hpp"
#include "stop_signals.hpp"

namespace vi::cli {

std::string require_gnuplot(const std::string& requested, const std::string& what) {
    const auto found = find_gnuplot(requested);
    if (!found) {
        throw std::runtime_error("gnuplot: '" + requested + "' not found; it draws " + what +
                                 " (Debian: apt-get install gnuplot-nox, or bash scripts/install-deps)");
    }
    return *found;
}

std::optional<std::string> write_with_figures(const std::string& dir, OutputFiles files, const std::vector<FigureSpec>& figures,
                                              const std::string& gnuplot) {
    std::optional<std::string> failure;
    try {
        for (auto& [name, text] : figure_files(figures, render_figures(gnuplot, figures, 1))) files[name] = std::move(text);
    } catch (const std::runtime_error& e) {
        // The numbers were computed at a cost a picture must not throw away: they are written
        // without the images, with each figure's data and script (gnuplot NAME.gp in the folder
        // draws it), and the caller says what failed.
        failure = one_line(e.what());
        for (const FigureSpec& f : figures) {
            for (const auto& [name, text] : f.data) files[name] = text;
            files[f.name + ".gp"] = gnuplot_script(f);
        }
    }
    check_run();
    const CommitSection commit;
    write_output_files(dir, files);
    return failure;
}

}  // namespace vi::cli
