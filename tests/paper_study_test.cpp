// Pieces of the paper study and its report: minima of sampled curves, the scan grid, the built-in
// cases, base64, and the report's HTML and Markdown.

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "study/paper/curve_features.hpp"
#include "study/paper/cases.hpp"
#include "study/paper/examples.hpp"
#include "study/paper/study.hpp"
#include "model/input_error.hpp"
#include "plot/base64.hpp"
#include "plot/report_document.hpp"
#include "support/run_command.hpp"

namespace vi {
namespace {

std::vector<std::optional<double>> values(const std::vector<double>& x, double (*f)(double)) {
    std::vector<std::optional<double>> y;
    for (double v : x) y.push_back(f(v));
    return y;
}

TEST(CurveFeatures, MinimaOfAKnownCurveAreRefinedToTheVertex) {
    // y = (x - 0.37)^2 (x - 0.8)^2 + 0.1 x: two minima; near each the parabola through three
    // samples is close to the curve, so the refined position beats the grid step.
    std::vector<double> x;
    for (int i = 0; i <= 50; ++i) x.push_back(i / 50.0);
    const auto y = values(x, [](double v) { return std::pow(v - 0.37, 2) * std::pow(v - 0.8, 2) * 40.0 + 0.1 * v; });
    const auto m = local_minima(x, y);
    ASSERT_EQ(m.size(), 2u);
    // Where the derivative vanishes (bisection): 0.36353, 0.79289; the grid step is 0.02.
    EXPECT_NEAR(m[0].x, 0.36353, 1e-3);
    EXPECT_NEAR(m[1].x, 0.79289, 1e-3);
    EXPECT_GT(m[0].prominence, 0.0);
    // An exact parabola is located exactly, even on an uneven grid.
    const std::vector<double> xu = {0.0, 0.1, 0.35, 0.5, 0.9};
    const auto yu = values(xu, [](double v) { return 3.0 * (v - 0.3) * (v - 0.3) + 1.0; });
    const auto mu = local_minima(xu, yu);
    ASSERT_EQ(mu.size(), 1u);
    EXPECT_NEAR(mu[0].x, 0.3, 1e-12);
    EXPECT_NEAR(mu[0].y, 1.0, 1e-12);
    EXPECT_EQ(mu[0].index, 2u);
}

TEST(CurveFeatures, GapsEndsAndFlatBottoms) {
    const std::vector<double> x = {0, 1, 2, 3, 4, 5, 6, 7, 8};
    // Ends are never minima; a gap next to a low sample hides it; a flat bottom counts once.
    const std::vector<std::optional<double>> y = {0.0, 5.0, 1.0, std::nullopt, 4.0, 2.0, 2.0, 3.0, 9.0};
    const auto m = local_minima(x, y);
    ASSERT_EQ(m.size(), 1u);
    EXPECT_EQ(m[0].index, 5u);
    EXPECT_DOUBLE_EQ(m[0].x, 5.0);
    EXPECT_DOUBLE_EQ(m[0].prominence, 2.0);  // rises to 4 on the left before the gap, to 9 on the right
    EXPECT_EQ(nearest_minimum(m, 7.0)->index, 5u);
    EXPECT_FALSE(nearest_minimum({}, 1.0));
    EXPECT_EQ(*smallest_sample(y), 0u);
    EXPECT_FALSE(smallest_sample({std::nullopt, std::nullopt}));
    EXPECT_THROW(local_minima({0, 1}, {1.0}), std::invalid_argument);
}

TEST(PaperStudy, ScanPositionsHoldTheParticularPoints) {
    const std::vector<double> x = scan_positions(50, 0.3);
    EXPECT_EQ(x.size(), 53u);
    EXPECT_DOUBLE_EQ(x.front(), 0.3);
    EXPECT_DOUBLE_EQ(x.back(), 1.0);
    EXPECT_TRUE(std::is_sorted(x.begin(), x.end()));
    for (double p : {0.67, 0.78, 0.87}) {
        EXPECT_EQ(std::count_if(x.begin(), x.end(), [&](double v) { return std::abs(v - p) < 1e-12; }), 1) << p;
    }
    // A grid that already holds them gets no duplicates.
    EXPECT_EQ(scan_positions(71, 0.3).size(), 71u);
}

TEST(PaperStudy, BuiltInExamplesAreTheFilesAndRead) {
    for (const char* name : {kCantileverFile, kFreeImpactFile, kPrestressFile}) {
        bool found = false;
        for (const EmbeddedFile& f : paper_example_files()) {
            if (f.name != name) continue;
            found = true;
            std::ifstream in(test::source_path(std::string("examples/paper/") + name), std::ios::binary);
            std::ostringstream ss;
            ss << in.rdbuf();
            EXPECT_EQ(std::string(f.text), ss.str()) << name;
        }
        EXPECT_TRUE(found) << name;
    }
    const PaperCases c = load_paper_cases("");
    EXPECT_EQ(c.free_impact.origin.file, "examples/paper/free_impact_tip.toml");
    EXPECT_DOUBLE_EQ(c.free_impact.supports.at(0).position, 1.0);
    EXPECT_NEAR(c.prestress.supports.at(0).surface, 1.17e-6, 1e-15);
    EXPECT_EQ(c.cantilever.beam.elements, 50);
    EXPECT_THROW(load_paper_cases(test::make_temp_dir()), InputError);
}

TEST(ReportPieces, Base64KnownVectors) {
    EXPECT_EQ(base64_encode(""), "");
    EXPECT_EQ(base64_encode("f"), "Zg==");
    EXPECT_EQ(base64_encode("fo"), "Zm8=");
    EXPECT_EQ(base64_encode("foo"), "Zm9v");
    EXPECT_EQ(base64_encode("foobar"), "Zm9vYmFy");
    EXPECT_EQ(base64_encode(std::string("\xff\x00\x10", 3)), "/wAQ");
}

TEST(ReportPieces, HtmlEscapesAndEmbedsMarkdownLinks) {
    ReportDocument d;
    d.title = "a <title> & more";
    d.heading(1, d.title);
    d.paragraph("run `vibroimpact paper` with <b> & \"quotes\"");
    d.table({"x", "verdict"}, {{"|v| < 1", "agrees"}, {"2", "disagrees"}}, 1);
    d.figure("fig9", "Fig. 9: t", "caption", {"fig9.csv"});
    EXPECT_THROW(render_html(d, {}), std::invalid_argument);
    const std::string html = render_html(d, {{"fig9", "PNGDATA"}});
    EXPECT_NE(html.find("<title>a &lt;title&gt; &amp; more</title>"), std::string::npos);
    EXPECT_NE(html.find("<code>vibroimpact paper</code> with &lt;b&gt; &amp; &quot;quotes&quot;"), std::string::npos);
    EXPECT_NE(html.find("<td class=\"agrees\">agrees</td>"), std::string::npos);
    EXPECT_NE(html.find("<td class=\"disagrees\">disagrees</td>"), std::string::npos);
    EXPECT_NE(html.find("src=\"data:image/png;base64," + base64_encode("PNGDATA") + "\""), std::string::npos);
    const std::string md = render_markdown(d);
    EXPECT_NE(md.find("# a <title> & more"), std::string::npos);
    EXPECT_NE(md.find("| \\|v\\| < 1 | **agrees** |"), std::string::npos);
    EXPECT_NE(md.find("![Fig. 9: t](fig9.png)"), std::string::npos);
}

}  // namespace
}  // namespace vi
