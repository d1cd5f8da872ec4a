// The field output's pieces: which samples are frames, the nodes each bending DOF belongs to, the VTK
// series' names and refusals, and writing files into a sub-folder all together or not at all.

#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>

#include "dynamics/transient_result.hpp"
#include "fem/system.hpp"
#include "io/case_reader.hpp"
#include "io/output_files.hpp"
#include "io/vtk_series.hpp"
#include "report/field_output.hpp"
#include "support/run_command.hpp"
#include "support/test_files.hpp"

namespace vi {
namespace {

namespace fs = std::filesystem;

TEST(FieldOutput, FramesAreEveryKthSampleAndTheLast) {
    std::vector<long> frames;
    for (long i = 0; i < 11; ++i) {
        if (is_field_sample(i, 4, 11)) frames.push_back(i);
    }
    EXPECT_EQ(frames, (std::vector<long>{0, 4, 8, 10}));
    EXPECT_FALSE(is_field_sample(0, 0, 11));
}

TEST(FieldOutput, EachBendingDofLandsOnItsNode) {
    const Case c = read_case_file(test::source_path("examples/paper/free_impact_tip.toml"));
    const System s = build_system(c);
    TimeHistory h;
    h.t = {0.0, 1e-6};
    h.field_sample = {1};
    // v of node n = n, theta of node n = -n: the clamp (node 0) has no DOF and stays zero.
    std::vector<double> q(s.bending.size());
    for (std::size_t i = 0; i < q.size(); ++i) {
        const int g = s.free_dofs[static_cast<std::size_t>(s.bending[i])];
        q[i] = (g % 3 == 1 ? 1.0 : -1.0) * (g / 3);
    }
    h.field_q = {q};
    const BeamField f = beam_field(s, h);
    ASSERT_EQ(f.frames.size(), 1u);
    EXPECT_EQ(f.frames[0].t, 1e-6);
    ASSERT_EQ(f.x.size(), static_cast<std::size_t>(s.mesh.node_count()));
    for (std::size_t n = 0; n < f.x.size(); ++n) {
        EXPECT_EQ(f.frames[0].v[n], static_cast<double>(n)) << n;
        EXPECT_EQ(f.frames[0].theta[n], -static_cast<double>(n)) << n;
    }
    h.field_q = {std::vector<double>(3, 0.0)};
    EXPECT_THROW(beam_field(s, h), std::invalid_argument);
}

TEST(FieldOutput, SeriesNamesItsFramesAndRefusesAFrameOfAnotherLength) {
    const OutputFiles files = vtk_beam_series("field", {0.0, 1.0, 2.0}, {{0.0, {0, 1, 2}, {0, 0, 0}}, {1e-6, {0, 2, 4}, {0, 0, 0}}});
    EXPECT_EQ(files.size(), 3u);
    EXPECT_TRUE(files.count("field.pvd"));
    EXPECT_TRUE(files.count("field/field_00001.vtu"));
    EXPECT_NE(files.at("field.pvd").find("timestep=\"9.9999999999999995e-07\" part=\"0\" file=\"field/field_00001.vtu\""),
              std::string::npos)
        << files.at("field.pvd");
    EXPECT_THROW(vtk_beam_series("field", {0.0, 1.0}, {{0.0, {0.0}, {0.0}}}), std::invalid_argument);
}

TEST(FieldOutput, FilesInASubFolderLandTogetherOrNotAtAll) {
    const std::string dir = test::make_temp_dir() + "/out";
    write_output_files(dir, {{"a.csv", "x\n"}, {"sub/b.vtu", "y\n"}});
    EXPECT_EQ(test::read_text(dir + "/sub/b.vtu"), "y\n");
    // A file where a folder must go (written last, names in order): nothing of the second call
    // stays, neither its files nor the folder it made, and the first call's files do.
    test::write_text(dir + "/z", "file");
    EXPECT_THROW(write_output_files(dir, {{"c.csv", "z\n"}, {"new/d.vtu", "w\n"}, {"z/e.vtu", "v\n"}}), std::runtime_error);
    EXPECT_FALSE(fs::exists(dir + "/c.csv"));
    EXPECT_FALSE(fs::exists(dir + "/new"));
    EXPECT_EQ(test::read_text(dir + "/sub/b.vtu"), "y\n");
}

}  // namespace
}  // namespace vi
