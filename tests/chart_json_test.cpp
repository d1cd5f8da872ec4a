// The interactive figures' data (plot/chart_json) and their place in report.html: columns read as
// the chart description says, clouds and curves that turn back split into parts a chart can draw,
// bad descriptions refused, and the page inlining uPlot only when it has charts. That the page draws
// them in a browser is tests/browser/check_report.sh.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include "plot/chart_json.hpp"
#include "plot/report_assets.hpp"
#include "plot/report_document.hpp"

namespace vi {
namespace {

using json = nlohmann::json;

FigureSpec spec(const std::string& csv, ChartSeries s) {
    FigureSpec f;
    f.name = "figx";
    f.data = {{"figx.csv", csv}};
    ChartPanel p;
    p.x_label = "x [m]";
    p.series = {std::move(s)};
    f.charts = {p};
    return f;
}

ChartSeries column_pair(const std::string& x, const std::string& y, ChartSeries::Style style = ChartSeries::Style::lines) {
    ChartSeries s;
    s.label = "a <b> & c";
    s.x = x;
    s.y = y;
    s.style = style;
    return s;
}

TEST(ChartJson, ReadsTheNamedColumnsOfTheRowsThatMatchScaledWithGapsForUndefinedValues) {
    ChartSeries s = column_pair("t_us", "f_uN");
    s.where = {{"kind", "Y"}};
    s.y_scale = 10.0;
    s.abs_y = true;
    const json j = json::parse(chart_json(spec("kind,t_us,f_uN\nY,1,-2\nPhi,1.5,7\nY,2,nan\nY,3,4.5\n", s)));
    ASSERT_EQ(j["panels"].size(), 1u);
    const json& series = j["panels"][0]["series"];
    ASSERT_EQ(series.size(), 1u);
    EXPECT_EQ(series[0]["x"], json::parse("[1, 2, 3]"));
    EXPECT_EQ(series[0]["y"], json::parse("[20, null, 45]"));
    EXPECT_EQ(series[0]["label"], "a <b> & c");
    EXPECT_EQ(j["panels"][0]["xLabel"], "x [m]");
}

TEST(ChartJson, EscapesWhatCouldEndItsScriptElement) {
    const std::string text = chart_json(spec("x,y\n1,2\n", column_pair("x", "y")));
    EXPECT_EQ(text.find('<'), std::string::npos);
    EXPECT_EQ(text.find('>'), std::string::npos);
    EXPECT_NE(text.find("\\u003cb\\u003e"), std::string::npos);
}

TEST(ChartJson, SplitsACloudOfPointsIntoPartsWithOnePointPerXThatShareALegendEntry) {
    const json j = json::parse(chart_json(spec("x,y\n1,10\n1,11\n2,20\n1,12\n", column_pair("x", "y", ChartSeries::Style::points))));
    const json& series = j["panels"][0]["series"];
    ASSERT_EQ(series.size(), 3u);
    EXPECT_EQ(series[0]["x"], json::parse("[1, 2]"));
    EXPECT_EQ(series[0]["y"], json::parse("[10, 20]"));
    EXPECT_EQ(series[1]["y"], json::parse("[11]"));
    EXPECT_EQ(series[2]["y"], json::parse("[12]"));
    EXPECT_FALSE(series[0]["group"].get<std::string>().empty());
    EXPECT_EQ(series[0]["group"], series[2]["group"]);
}

TEST(ChartJson, CutsACurveThatTurnsBackInXAtItsTurningPointAndWhereXIsMissing) {
    // Up 0..2, back down to 1 (turning at 2), then after a row without x a new run from 5.
    const json j = json::parse(chart_json(spec("x,y\n0,0\n1,1\n2,2\n1,3\nnan,9\n5,5\n6,6\n", column_pair("x", "y"))));
    const json& series = j["panels"][0]["series"];
    ASSERT_EQ(series.size(), 3u);
    EXPECT_EQ(series[0]["x"], json::parse("[0, 1, 2]"));
    EXPECT_EQ(series[1]["x"], json::parse("[2, 1]"));
    EXPECT_EQ(series[1]["y"], json::parse("[2, 3]"));
    EXPECT_EQ(series[2]["x"], json::parse("[5, 6]"));
    EXPECT_EQ(series[0]["group"], series[2]["group"]);
}

TEST(ChartJson, LeavesValuesALogAxisCannotShowAsGaps) {
    FigureSpec f = spec("x,y\n1,10\n2,0\n3,-1\n4,100\n", column_pair("x", "y"));
    f.charts[0].log_y = true;
    const json j = json::parse(chart_json(f));
    EXPECT_EQ(j["panels"][0]["series"][0]["y"], json::parse("[10, null, null, 100]"));
}

TEST(ChartJson, RefusesAColumnOrFileTheFigureDoesNotHaveNamingBoth) {
    try {
        (void)chart_json(spec("x,y\n1,2\n", column_pair("x", "z")));
        FAIL() << "no error";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("figx"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("'z'"), std::string::npos) << e.what();
    }
    ChartSeries s = column_pair("x", "y");
    s.file = "other.csv";
    EXPECT_THROW((void)chart_json(spec("x,y\n1,2\n", s)), std::invalid_argument);
}

// Bars from x to x_to (a histogram's bins), or bar_width about x moved by x_offset (bars side by
// side), with interval bars from the y_low and y_high columns, and labelled ticks on x.
TEST(ChartJson, BarsWithTheirSpansIntervalsAndCategoryTicks) {
    ChartSeries bins = column_pair("from", "n", ChartSeries::Style::bars);
    bins.x_to = "to";
    const json h = json::parse(chart_json(spec("from,to,n\n0,0.5,3\n0.5,1,7\n", bins)));
    const json& hs = h["panels"][0]["series"];
    ASSERT_EQ(hs.size(), 1u);
    EXPECT_EQ(hs[0]["style"], "bars");
    EXPECT_EQ(hs[0]["x"], json::parse("[0, 0.5]"));
    EXPECT_EQ(hs[0]["xTo"], json::parse("[0.5, 1]"));
    EXPECT_EQ(hs[0]["y"], json::parse("[3, 7]"));
    EXPECT_FALSE(hs[0].contains("yLow"));

    ChartSeries first = column_pair("position", "s", ChartSeries::Style::bars);
    first.x_offset = -0.2;
    first.bar_width = 0.35;
    first.y_low = "s_low";
    first.y_high = "s_high";
    FigureSpec f = spec("input,s,s_low,s_high,position\nb,0.6,0.5,nan,0\na,0.3,0.1,0.4,1\n", first);
    f.charts[0].x_ticks = {{0.0, "b"}, {1.0, "a <x>"}};
    const json j = json::parse(chart_json(f));
    const json& s = j["panels"][0]["series"][0];
    EXPECT_EQ(s["x"], json::parse("[-0.2, 0.8]"));
    EXPECT_EQ(s["barWidth"], 0.35);
    EXPECT_FALSE(s.contains("xTo"));
    EXPECT_EQ(s["yLow"], json::parse("[0.5, 0.1]"));
    EXPECT_EQ(s["yHigh"], json::parse("[null, 0.4]"));  // an interval the data cannot give: a gap
    EXPECT_EQ(j["panels"][0]["xTicks"], json::parse(R"([[0, "b"], [1, "a <x>"]])"));
    // Bars are never joined as a curve is; two at one x are split as a cloud is, one per x in each part.
    const json same = json::parse(chart_json(spec("x,y\n0,1\n0,2\n1,3\n", column_pair("x", "y", ChartSeries::Style::bars))));
    EXPECT_EQ(same["panels"][0]["series"].size(), 2u);
    EXPECT_EQ(same["panels"][0]["series"][0]["x"], json::parse("[0, 1]"));
    bins.y_low = "missing";
    EXPECT_THROW(chart_json(spec("from,to,n\n0,1,2\n", bins)), std::invalid_argument);
}

TEST(ChartJson, FigureChartsHoldsOnlyTheFiguresThatHaveCharts) {
    FigureSpec plain;
    plain.name = "png_only";
    const auto charts = figure_charts({plain, spec("x,y\n1,2\n", column_pair("x", "y"))});
    ASSERT_EQ(charts.size(), 1u);
    EXPECT_EQ(charts.begin()->first, "figx");
}

TEST(ReportHtml, InlinesUplotThePageScriptAndEachChartOnlyWhenThePageHasCharts) {
    ReportDocument d;
    d.title = "t";
    d.figure("figx", "Fig. X", "caption", {"figx.csv"});
    const std::string plain = render_html(d, {{"figx", "PNGDATA"}});
    EXPECT_EQ(plain.find("<script"), std::string::npos);
    const std::string chart = chart_json(spec("x,y\n1,2\n", column_pair("x", "y")));
    const std::string html = render_html(d, {{"figx", "PNGDATA"}}, {{"figx", chart}});
    EXPECT_NE(html.find("<script type=\"application/json\" class=\"vi-chart-data\">" + chart + "</script>"), std::string::npos);
    EXPECT_NE(html.find(std::string(report_asset("uPlot.iife.min.js"))), std::string::npos);
    EXPECT_NE(html.find(std::string(report_asset("uPlot.min.css"))), std::string::npos);
    EXPECT_NE(html.find(std::string(report_asset("report_charts.js"))), std::string::npos);
    // The page script comes first, so that it sees an error in uPlot's.
    EXPECT_LT(html.find("report.html's page script"), html.find("var uPlot="));
    // The PNG stays in the page: for print, and for a browser without scripts.
    EXPECT_NE(html.find("class=\"vi-png\""), std::string::npos);
    EXPECT_THROW((void)report_asset("missing.js"), std::logic_error);
}

}  // namespace
}  // namespace vi
