#pragma once
// A report as a list of blocks (headings, paragraphs, lists, tables, figures), rendered to one
// self-contained HTML page (images embedded, figures optionally interactive) or to Markdown (images linked beside it).

#include <map>
#include <string>
#include <vector>

namespace vi {

// One block of a report. Text is plain; `code` in backquotes is set in a fixed font.
struct ReportBlock {
    enum class Kind { heading, paragraph, list, table, figure, animation };
    Kind kind = Kind::paragraph;
    int level = 2;                           // heading level (1 = title)
    std::string text;                        // heading or paragraph text; a figure's title
    std::vector<std::string> items;          // list items; a figure's files (for links)
    std::vector<std::string> header;         // table header
    std::vector<std::vector<std::string>> rows;  // table rows
    std::string figure;                      // figure: file stem ("fig4"); the PNG is <figure>.png
    std::string caption;                     // figure caption
    std::string id;                          // anchor (headings, figures); may be empty
    int verdict_column = -1;                 // table: the column whose cells are verdicts (coloured)
    std::string data;                        // animation: its JSON (plot/beam_animation.hpp)
};

struct ReportDocument {
    std::string title;
    std::vector<ReportBlock> blocks;
    void heading(int level, std::string text, std::string id = "");
    void paragraph(std::string text);
    void list(std::vector<std::string> items);
    void table(std::vector<std::string> header, std::vector<std::vector<std::string>> rows, int verdict_column = -1);
    void figure(std::string stem, std::string title, std::string caption, std::vector<std::string> files);
    // An animated beam drawn by the page script from `data` (plot/beam_animation.hpp), no image.
    void animation(std::string id, std::string title, std::string caption, std::string data, std::vector<std::string> files);
};

// The whole page: inline CSS, figures as PNG data URIs from `png` (file stem -> bytes); a figure
// without its PNG is an error (std::invalid_argument). Opens offline in any browser. A figure with an
// entry in `charts` (file stem -> chart_json text, plot/chart_json.hpp) is also drawn interactively by
// the inlined uPlot and page script (plot/report_assets.hpp), its PNG then shown on request and in
// print; without `charts` or an animation the page has no script. An animation block is a <figure>
// of class vi-animation that the page script plays (Markdown: a paragraph pointing to report.html).
std::string render_html(const ReportDocument& doc, const std::map<std::string, std::string>& png,
                        const std::map<std::string, std::string>& charts = {});

// Markdown (GitHub flavour): figures as links to <stem>.png beside the file.
std::string render_markdown(const ReportDocument& doc);

}  // namespace vi
