#include "plot/report_document.hpp"

#include <algorithm>
#include <sstream>
#include <stdexcept>

#include "plot/base64.hpp"
#include "plot/report_assets.hpp"

namespace vi {
namespace {

std::string escape_html(const std::string& s) {
    std::string out;
    for (char c : s) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            default: out += c;
        }
    }
    return out;
}

// Escaped text with `code` spans.
std::string inline_html(const std::string& s) {
    std::string out;
    bool code = false;
    std::string run;
    for (char c : s) {
        if (c == '`') {
            if (code) out += "<code>";
            out += escape_html(run);
            if (code) out += "</code>";
            run.clear();
            code = !code;
        } else {
            run += c;
        }
    }
    if (code) out += '`';  // an unpaired backquote stays as it is
    out += escape_html(run);
    return out;
}

// A Markdown table cell: bars escaped, line breaks removed.
std::string md_cell(const std::string& s) {
    std::string out;
    for (char c : s) {
        if (c == '|') out += '\\';
        out += c == '\n' ? ' ' : c;
    }
    return out;
}

std::string verdict_class(const std::string& v) {
    if (v == "agrees") return "agrees";
    if (v == "partly") return "partly";
    if (v == "disagrees") return "disagrees";
    return "none";
}

constexpr const char* kStyle = R"css(
body { font-family: "DejaVu Sans", Verdana, Arial, sans-serif; max-width: 1180px; margin: 2em auto; padding: 0 1.2em;
       color: #222; line-height: 1.45; background: #fff; }
h1 { font-size: 1.7em; margin-bottom: 0.2em; }
h2 { font-size: 1.35em; margin-top: 2em; border-bottom: 1px solid #ccc; padding-bottom: 0.2em; }
h3 { font-size: 1.1em; margin-top: 1.6em; }
table { border-collapse: collapse; margin: 0.8em 0; font-size: 0.9em; width: 100%; }
th, td { border: 1px solid #ccc; padding: 0.35em 0.55em; text-align: left; vertical-align: top; }
th { background: #f2f2f2; }
tr:nth-child(even) td { background: #fafafa; }
td.agrees { background: #dff0d8 !important; font-weight: bold; }
td.partly { background: #fcf0cf !important; font-weight: bold; }
td.disagrees { background: #f6d5d5 !important; font-weight: bold; }
figure { margin: 1em 0 2em 0; }
figure img { max-width: 100%; height: auto; border: 1px solid #ddd; }
figcaption { font-size: 0.92em; color: #333; margin-top: 0.4em; }
code { font-family: "DejaVu Sans Mono", monospace; font-size: 0.92em; background: #f4f4f4; padding: 0 0.2em; }
.files { font-size: 0.85em; color: #555; }
)css";

// The interactive figures: the chart replaces the PNG on screen once drawn (a button shows it again);
// on paper the PNG, which also carries gnuplot's annotations.
constexpr const char* kChartStyle = R"css(
.vi-chart { margin: 0.4em 0; }
.vi-panel { margin-bottom: 0.6em; }
.vi-chart .u-title { font-size: 0.95em; font-weight: normal; }
.vi-chart .u-legend { font-size: 0.82em; width: auto; margin: 0 auto; }
.vi-chart .u-legend th, .vi-chart .u-legend td { border: none; background: none !important; padding: 0 0.3em; }
.vi-toggle { font-size: 0.8em; margin: 0.2em 0 0.6em 0; }
figure.vi-drawn:not(.vi-show-png) img.vi-png { display: none; }
#vi-errors { display: none; }
.vi-beam svg { width: 100%; height: auto; background: #fff; }
.vi-beam .vi-controls { font-size: 0.85em; margin: 0.3em 0; }
.vi-beam input[type=range] { width: 60%; vertical-align: middle; }
@media print { .vi-chart { display: none; } figure img.vi-png { display: block !important; } }
)css";

}  // namespace

void ReportDocument::heading(int level, std::string text, std::string id) {
    ReportBlock b;
    b.kind = ReportBlock::Kind::heading;
    b.level = level;
    b.text = std::move(text);
    b.id = std::move(id);
    blocks.push_back(std::move(b));
}

void ReportDocument::paragraph(std::string text) {
    ReportBlock b;
    b.text = std::move(text);
    blocks.push_back(std::move(b));
}

void ReportDocument::list(std::vector<std::string> items) {
    ReportBlock b;
    b.kind = ReportBlock::Kind::list;
    b.items = std::move(items);
    blocks.push_back(std::move(b));
}

void ReportDocument::table(std::vector<std::string> header, std::vector<std::vector<std::string>> rows, int verdict_column) {
    ReportBlock b;
    b.kind = ReportBlock::Kind::table;
    b.header = std::move(header);
    b.rows = std::move(rows);
    b.verdict_column = verdict_column;
    blocks.push_back(std::move(b));
}

void ReportDocument::figure(std::string stem, std::string title, std::string caption, std::vector<std::string> files) {
    ReportBlock b;
    b.kind = ReportBlock::Kind::figure;
    b.figure = stem;
    b.id = std::move(stem);
    b.text = std::move(title);
    b.caption = std::move(caption);
    b.items = std::move(files);
    blocks.push_back(std::move(b));
}

void ReportDocument::animation(std::string id, std::string title, std::string caption, std::string data,
                               std::vector<std::string> files) {
    ReportBlock b;
    b.kind = ReportBlock::Kind::animation;
    b.id = std::move(id);
    b.text = std::move(title);
    b.caption = std::move(caption);
    b.data = std::move(data);
    b.items = std::move(files);
    blocks.push_back(std::move(b));
}

std::string render_html(const ReportDocument& doc, const std::map<std::string, std::string>& png,
                        const std::map<std::string, std::string>& charts) {
    const bool interactive = !charts.empty() || std::any_of(doc.blocks.begin(), doc.blocks.end(), [](const ReportBlock& b) {
        return b.kind == ReportBlock::Kind::animation;
    });
    std::ostringstream s;
    s << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>" << escape_html(doc.title)
      << "</title>\n<style>" << kStyle;
    if (interactive) s << kChartStyle << "</style>\n<style>" << report_asset("uPlot.min.css");
    s << "</style>\n</head>\n<body>\n";
    for (const ReportBlock& b : doc.blocks) {
        const std::string id = b.id.empty() ? "" : " id=\"" + escape_html(b.id) + "\"";
        switch (b.kind) {
            case ReportBlock::Kind::heading:
                s << "<h" << b.level << id << ">" << inline_html(b.text) << "</h" << b.level << ">\n";
                break;
            case ReportBlock::Kind::paragraph: s << "<p>" << inline_html(b.text) << "</p>\n"; break;
            case ReportBlock::Kind::list:
                s << "<ul>\n";
                for (const std::string& i : b.items) s << "<li>" << inline_html(i) << "</li>\n";
                s << "</ul>\n";
                break;
            case ReportBlock::Kind::table:
                s << "<table>\n<tr>";
                for (const std::string& h : b.header) s << "<th>" << inline_html(h) << "</th>";
                s << "</tr>\n";
                for (const auto& r : b.rows) {
                    s << "<tr>";
                    for (std::size_t c = 0; c < r.size(); ++c) {
                        const bool v = static_cast<int>(c) == b.verdict_column;
                        s << (v ? "<td class=\"" + verdict_class(r[c]) + "\">" : std::string("<td>")) << inline_html(r[c]) << "</td>";
                    }
                    s << "</tr>\n";
                }
                s << "</table>\n";
                break;
            case ReportBlock::Kind::figure: {
                const auto it = png.find(b.figure);
                if (it == png.end()) throw std::invalid_argument("report: no image for figure " + b.figure);
                s << "<figure" << id << ">\n<h3>" << inline_html(b.text) << "</h3>\n";
                const auto chart = charts.find(b.figure);
                if (chart != charts.end()) {
                    // chart_json escapes '<', so the JSON cannot close this element early.
                    s << "<div class=\"vi-chart\"></div>\n<script type=\"application/json\" class=\"vi-chart-data\">"
                      << chart->second << "</script>\n";
                }
                s << "<img class=\"vi-png\" alt=\"" << escape_html(b.text) << "\" src=\"data:image/png;base64,"
                  << base64_encode(it->second) << "\">\n<figcaption>"
                  << inline_html(b.caption) << "</figcaption>\n<p class=\"files\">Files beside this report:";
                for (const std::string& f : b.items) s << " <a href=\"" << escape_html(f) << "\">" << escape_html(f) << "</a>";
                s << "</p>\n</figure>\n";
                break;
            }
            case ReportBlock::Kind::animation:
                if (b.data.find('<') != std::string::npos) throw std::invalid_argument("report: animation data holds '<'");
                s << "<figure" << id << " class=\"vi-animation\">\n<h3>" << inline_html(b.text) << "</h3>\n"
                  << "<div class=\"vi-beam\"></div>\n<script type=\"application/json\" class=\"vi-animation-data\">" << b.data
                  << "</script>\n<figcaption>" << inline_html(b.caption) << "</figcaption>\n<p class=\"files\">Files beside this report:";
                for (const std::string& f : b.items) s << " <a href=\"" << escape_html(f) << "\">" << escape_html(f) << "</a>";
                s << "</p>\n</figure>\n";
                break;
        }
    }
    if (interactive) {
        // The page script first, so that it records an error in uPlot's script too.
        s << "<pre id=\"vi-errors\"></pre>\n<script>\n" << report_asset("report_charts.js") << "</script>\n<script>\n"
          << report_asset("uPlot.iife.min.js") << "</script>\n";
    }
    s << "</body>\n</html>\n";
    return s.str();
}

std::string render_markdown(const ReportDocument& doc) {
    std::ostringstream s;
    for (const ReportBlock& b : doc.blocks) {
        switch (b.kind) {
            case ReportBlock::Kind::heading: s << std::string(static_cast<std::size_t>(b.level), '#') << ' ' << b.text << "\n\n"; break;
            case ReportBlock::Kind::paragraph: s << b.text << "\n\n"; break;
            case ReportBlock::Kind::list:
                for (const std::string& i : b.items) s << "- " << i << "\n";
                s << "\n";
                break;
            case ReportBlock::Kind::table:
                s << '|';
                for (const std::string& h : b.header) s << ' ' << md_cell(h) << " |";
                s << "\n|";
                for (std::size_t i = 0; i < b.header.size(); ++i) s << "---|";
                s << "\n";
                for (const auto& r : b.rows) {
                    s << '|';
                    for (std::size_t c = 0; c < r.size(); ++c) {
                        const bool v = static_cast<int>(c) == b.verdict_column;
                        s << ' ' << (v ? "**" + md_cell(r[c]) + "**" : md_cell(r[c])) << " |";
                    }
                    s << "\n";
                }
                s << "\n";
                break;
            case ReportBlock::Kind::figure:
                s << "### " << b.text << "\n\n![" << b.text << "](" << b.figure << ".png)\n\n" << b.caption << "\n\nFiles:";
                for (const std::string& f : b.items) s << " [" << f << "](" << f << ")";
                s << "\n\n";
                break;
            case ReportBlock::Kind::animation:
                s << "### " << b.text << "\n\nAn animation: open report.html. " << b.caption << "\n\nFiles:";
                for (const std::string& f : b.items) s << " [" << f << "](" << f << ")";
                s << "\n\n";
                break;
        }
    }
    return s.str();
}

}  // namespace vi
