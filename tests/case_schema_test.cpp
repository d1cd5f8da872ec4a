// The case schema: every key described once, the key tables of docs/case-files.md generated from
// it (a stale page fails here), the structs' defaults equal to the documented ones, and a section and
// a law's keys registered at run time read, checked, swept, resolved and documented like built-in ones.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "io/case_reader.hpp"
#include "io/case_writer.hpp"
#include "case_text_fixture.hpp"
#include "model/case_checks.hpp"
#include "model/case_schema.hpp"
#include "model/case_schema_docs.hpp"
#include "model/input_error.hpp"
#include "sweep/case_paths.hpp"

namespace vi {
namespace {

std::string read_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::string error_of(const std::string& text) {
    try {
        read_case_text(text, "toy.toml");
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(CaseSchemaDocs, KeyTablesOfCaseFilesAreGeneratedFromTheSchema) {
    const std::string path = std::string(VI_SOURCE_DIR) + "/docs/case-files.md";
    const std::string page = read_file(path);
    ASSERT_FALSE(page.empty()) << path;
    EXPECT_TRUE(undocumented_sections(page, case_schema()).empty())
        << "a section of the schema has no <!-- case-keys:NAME --> block in docs/case-files.md: "
        << undocumented_sections(page, case_schema()).front();
    const std::string fresh = with_case_key_tables(page, case_schema());
    if (fresh == page) return;
    if (std::getenv("VI_UPDATE_DOCS") != nullptr) {
        std::ofstream(path, std::ios::binary) << fresh;
        GTEST_SKIP() << "rewrote the key tables of " << path;
    }
    ADD_FAILURE() << "the key tables of docs/case-files.md differ from the schema (src/model/case_keys_*.cpp); "
                     "regenerate them with: VI_UPDATE_DOCS=1 ./build/tests/vi_tests "
                     "--gtest_filter='CaseSchemaDocs.*'";
}

TEST(CaseSchemaDocs, TablesShowEveryKeyWithItsRangeAndCondition) {
    const std::string beam = case_key_table(*builtin_case_schema().section("beam"));
    EXPECT_NE(beam.find("| `length` | l | length | required | > 0 | - |"), std::string::npos) << beam;
    EXPECT_NE(beam.find("| `elements` |"), std::string::npos);
    EXPECT_NE(beam.find("[1, 2000]"), std::string::npos);
    const std::string loads = case_key_table(*builtin_case_schema().section("loads"));
    EXPECT_NE(loads.find("| `t_on` | step time | time | required | >= 0 | `kind = \"step\"` |"), std::string::npos)
        << loads;
}

// The defaults the docs give are the structs' own, so that a case without a table ([solver], say)
// and one with an empty table are the same case. One exception: an electrode built in code has a
// "given" waveform (its g(t) set directly), one read from a file the documented "constant".
TEST(CaseSchema, DocumentedDefaultsAreTheStructsDefaults) {
    int checked = 0;
    for (const SectionSpec& s : builtin_case_schema().sections) {
        Case c;
        if (s.array || s.count(c) == 0) s.add(c);  // the struct as constructed, no schema default set
        const std::size_t i = s.count(c) - 1;
        for (const KeySpec& k : s.keys) {
            SCOPED_TRACE(s.name + "." + k.name);
            if (s.name == "electrodes" && k.name == "waveform") {
                EXPECT_EQ(c.electrodes[i].waveform.kind, Waveform::Kind::given);
                continue;
            }
            for (std::size_t e = 0; e < k.default_numbers.size(); ++e) {
                EXPECT_EQ(k.get_number(c, i, e), k.default_numbers[e]);
                ++checked;
            }
            if (k.default_choice.empty()) continue;
            if (k.kind == KeyKind::flag) {
                EXPECT_EQ(k.get_number(c, i, 0), k.default_choice == "true" ? 1.0 : 0.0);
            } else {
                EXPECT_EQ(k.get_text(c, i), k.default_choice);
            }
            ++checked;
        }
    }
    EXPECT_GT(checked, 40);
}

// Every key has what the reader, the checks, the paths, the writers and the docs need: the built-in
// ones and those the element families register.
TEST(CaseSchema, EveryKeyIsCompletelyDescribed) {
    std::size_t keys = 0;
    for (const SectionSpec& s : case_schema().sections) {
        ASSERT_TRUE(s.count && s.add) << s.name;
        for (const KeySpec& k : s.keys) {
            SCOPED_TRACE(s.name + "." + k.name);
            ++keys;
            EXPECT_FALSE(k.meaning.empty());
            EXPECT_FALSE(k.unit.empty());
            if (is_numeric(k.kind) || k.kind == KeyKind::flag) {
                EXPECT_TRUE(k.get_number && k.set_number);
            } else if (k.kind == KeyKind::layer_stack) {
                EXPECT_TRUE(k.layers);
            } else if (k.kind == KeyKind::hole_array) {
                EXPECT_TRUE(k.holes);
            } else {
                EXPECT_TRUE(k.get_text && k.set_text);
            }
            if (k.kind == KeyKind::choice) {
                EXPECT_FALSE(k.options.empty());
            }
            if (k.kind == KeyKind::table_file) {
                EXPECT_TRUE(k.table && !k.column.empty());
            }
            if (k.when.holds) {
                EXPECT_FALSE(k.when.file_text.empty());
            }
            for (const std::string& on : k.when.on) EXPECT_NE(s.key(on), nullptr) << on;
            if (!k.needs.empty()) {
                EXPECT_NE(s.key(k.needs), nullptr);
            }
            EXPECT_FALSE(k.required && !k.default_numbers.empty());
        }
    }
    EXPECT_GE(keys, 89u);
}

// case_to_toml of every example reads back to a case that writes the same text (every key in
// effect, bit for bit in its numbers).
TEST(CaseSchema, WrittenCaseReadsBackToTheSameCase) {
    for (const char* example : {"paper/free_impact_tip.toml", "paper/free_impact_prestress.toml",
                                "switch/cantilever_switch_air.toml", "switch/capacitive_stiction.toml",
                                "switch/bridge_switch.toml", "devices/impact_sensor.toml", "switch/shaped_drive.toml"}) {
        SCOPED_TRACE(example);
        const Case c = read_case_file(std::string(VI_SOURCE_DIR) + "/examples/" + example);
        const std::string text = case_to_toml(c);
        const Case back = read_case_text(text, "back.toml");
        EXPECT_EQ(case_to_toml(back), text);
        EXPECT_EQ(case_to_json(back), case_to_json(c));
    }
}

// A toy section ([[springs]]) and a selector of [[supports]] (toy_law = "toy" with its own key), registered
// here as an element family would register them from its own file: read, checked (the range, the
// magnitude window, the section's own rule), swept by path, resolved and documented.
class ToyRegistration : public ::testing::Test {
protected:
    void SetUp() override {
        sections_before_ = case_schema().sections.size();
        SectionSpec springs;
        springs.name = "springs";
        springs.array = true;
        springs.entry_word = "spring";
        KeySpec position = number_key("position", Dimension::dimensionless, "x/l");
        position.require().in(interval(0, true, 1, false, " (x/l)")).means("where the spring acts");
        KeySpec stiffness = number_key("stiffness", Dimension::stiffness);
        stiffness.require().in(positive()).means("its stiffness");
        KeySpec law = choice_key("law", {"linear", "cubic"});
        law.otherwise(std::string("linear")).means("its force law");
        KeySpec cubic = number_key("cubic_coefficient", Dimension::dimensionless);
        cubic.require().in(non_negative()).only(when_chosen("springs", "law", {"cubic"})).means("k3 / k");
        KeySpec damped = flag_key("damped");
        damped.otherwise(std::string("true")).means("whether it dissipates");
        springs.keys = {position, stiffness, law, cubic, damped};
        springs.check = [](std::vector<CaseProblem>& out, const Case& c) {
            const auto it = c.sections.find("springs");
            if (it == c.sections.end()) return;
            for (std::size_t i = 1; i < it->second.size(); ++i) {
                if (it->second[i].number("position") == it->second[0].number("position")) {
                    out.push_back({"springs[" + std::to_string(i) + "].position", "at the place of springs[0]"});
                }
            }
        };
        section_ = register_section(std::move(springs));

        KeySpec support_law = choice_key("toy_law", {"none", "toy"});
        support_law.otherwise(std::string("none")).means("the toy's force law");
        KeySpec exponent = number_key("toy_exponent", Dimension::dimensionless);
        exponent.otherwise(1.5).in(positive()).only(when_chosen("supports", "toy_law", {"toy"})).means("the toy law's power");
        law_ = register_keys("supports", {support_law, exponent});
    }

    SchemaRegistration section_;
    SchemaRegistration law_;
    std::size_t sections_before_ = 0;  // the built-in sections and those the element families keep
};

const std::string kToySupport = "[[supports]]\nposition = 1.0\nstiffness = \"50 N/m\"\ntoy_law = \"toy\"\ntoy_exponent = 2.5\n";
const std::string kSprings = "[[springs]]\nposition = 0.5\nstiffness = \"2 kN/m\"\n"    // lines 16-18
                             "[[springs]]\nposition = 0.25\nstiffness = 7\nlaw = \"cubic\"\ncubic_coefficient = 0.1\n";

TEST_F(ToyRegistration, RegisteredKeysAreReadAndChecked) {
    const Case c = read_case_text(test::kBaseCase + kToySupport + kSprings, "toy.toml");
    ASSERT_EQ(c.sections.at("springs").size(), 2u);
    EXPECT_EQ(c.sections.at("springs")[0].number("stiffness"), 2000.0);
    EXPECT_EQ(c.sections.at("springs")[0].text("law"), "linear");
    EXPECT_EQ(c.sections.at("springs")[1].number("cubic_coefficient"), 0.1);
    EXPECT_EQ(c.sections.at("springs")[0].number("damped"), 1.0);
    EXPECT_EQ(c.supports[0].params.text("toy_law"), "toy");
    // An entry built in code, without the schema's defaults set, reads them through the keys.
    Case code;
    code.sections["springs"].emplace_back();
    const SectionSpec& springs = *case_schema().section("springs");
    EXPECT_EQ(springs.key("damped")->get_number(code, 0, 0), 1.0);
    EXPECT_EQ(springs.key("law")->get_text(code, 0), "linear");
    EXPECT_EQ(c.supports[0].params.number("toy_exponent"), 2.5);

    const std::string base = test::kBaseCase + kToySupport;  // springs start at line 16
    EXPECT_EQ(error_of(base + "[[springs]]\nposition = 0.5\nstifness = 1\n"),
              "toy.toml:18: springs[0].stifness: unknown key 'stifness' (did you mean 'stiffness'?)");
    EXPECT_EQ(error_of(base + "[[springs]]\nposition = 0.5\nstiffness = \"-1 N/m\"\n"),
              "toy.toml:18: springs[0].stiffness: must be positive");
    EXPECT_EQ(error_of(base + "[[springs]]\nposition = 0.5\nstiffness = 1e300\n").rfind("toy.toml:18: springs[0].stiffness: 1e+300 is outside", 0),
              0u);
    EXPECT_EQ(error_of(base + "[[springs]]\nposition = 0.5\nstiffness = 1\ncubic_coefficient = 1\n"),
              "toy.toml:19: springs[0].cubic_coefficient: only with springs[0].law = \"cubic\"");
    EXPECT_EQ(error_of(base + "[[springs]]\nposition = 0.5\nstiffness = 1\nlaw = \"cubic\"\n"),
              "toy.toml:16: springs[0].cubic_coefficient: missing required key");
    EXPECT_EQ(error_of(base + "[[springs]]\nposition = 0.5\nstiffness = 1\n[[springs]]\nposition = 0.5\nstiffness = 2\n"),
              "toy.toml:20: springs[1].position: at the place of springs[0]");
    EXPECT_EQ(error_of(test::kBaseCase + "[[supports]]\nposition = 1.0\nstiffness = 1\ntoy_exponent = 2\n"),
              "toy.toml:14: supports[0].toy_exponent: only with supports[0].toy_law = \"toy\"");
    EXPECT_EQ(error_of(test::kBaseCase + "[[supports]]\nposition = 1.0\nstiffness = 1\ntoy_law = \"toy\"\ntoy_exponent = 0\n"),
              "toy.toml:15: supports[0].toy_exponent: must be positive");
}

TEST_F(ToyRegistration, RegisteredKeysAreSweptResolvedAndDocumented) {
    const Case c = read_case_text(test::kBaseCase + kToySupport + kSprings, "toy.toml");
    Case d = c;
    const CasePath stiffness = resolve_case_path("springs[1].stiffness", d);
    EXPECT_EQ(case_path_unit(stiffness), "N/m");
    EXPECT_EQ(case_path_column(stiffness), "springs[1].stiffness_n_m");
    set_case_value(d, stiffness, 9.0);
    EXPECT_EQ(get_case_value(d, stiffness), 9.0);
    EXPECT_EQ(d.sections.at("springs")[1].number("stiffness"), 9.0);
    set_case_value(d, resolve_case_path("supports[0].toy_exponent", d), 3.0);
    EXPECT_EQ(d.supports[0].params.number("toy_exponent"), 3.0);
    set_case_value(d, stiffness, -1.0);
    ASSERT_FALSE(check_case(d).empty());
    EXPECT_EQ(check_case(d)[0].key, "springs[1].stiffness");
    const auto refused = [&](const std::string& path) {
        try {
            resolve_case_path(path, c);
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_EQ(refused("springs[2].stiffness"), "springs[2]: index out of range (the case has 2 springs)");
    EXPECT_EQ(refused("springs[0].cubic_coefficient"), "springs[0].cubic_coefficient: only with springs[0].law = \"cubic\"");
    EXPECT_NE(refused("springs[0].stifness").find("did you mean 'stiffness'"), std::string::npos);
    bool listed = false;
    for (const std::string& form : case_path_forms()) listed = listed || form == "springs[i].cubic_coefficient";
    EXPECT_TRUE(listed);

    const nlohmann::json j = case_to_json(c);
    EXPECT_EQ(j["springs"][0]["stiffness"], 2000.0);
    EXPECT_EQ(j["springs"][1]["law"], "cubic");
    EXPECT_FALSE(j["springs"][0].contains("cubic_coefficient"));
    EXPECT_EQ(j["supports"][0]["toy_exponent"], 2.5);
    const std::string toml = case_to_toml(c);
    EXPECT_NE(toml.find("[[springs]]\nposition = 0.5  # x/l\nstiffness = 2000.0  # N/m\nlaw = \"linear\"\n"),
              std::string::npos)
        << toml;
    EXPECT_EQ(case_to_toml(read_case_text(toml, "back.toml")), toml);

    const std::string table = case_key_table(*case_schema().section("springs"));
    EXPECT_NE(table.find("| `cubic_coefficient` | k3 / k | dimensionless | required | >= 0 | `law = \"cubic\"` |"),
              std::string::npos)
        << table;
    EXPECT_NE(case_key_table(*case_schema().section("supports")).find("| `toy_exponent` |"), std::string::npos);
}

// A registered section is documented on the page without a block of its own: its heading, paragraph
// and table fill the block of registered sections.
TEST_F(ToyRegistration, RegisteredSectionIsDocumentedWithoutEditingThePage) {
    const std::string page = "# Keys\n<!-- registered-sections -->\nold text\n<!-- /registered-sections -->\nend\n";
    const auto lists_springs = [](const std::vector<std::string>& names) {
        return std::find(names.begin(), names.end(), "springs") != names.end();
    };
    EXPECT_FALSE(lists_springs(undocumented_sections(page, case_schema())));
    EXPECT_TRUE(lists_springs(undocumented_sections("# Keys\n", case_schema())));
    const std::string fresh = with_case_key_tables(page, case_schema());
    EXPECT_EQ(fresh.find("old text"), std::string::npos) << fresh;
    EXPECT_NE(fresh.find("\n### `[[springs]]`\n\n| Key |"), std::string::npos) << fresh;
    EXPECT_NE(fresh.find("| `cubic_coefficient` | k3 / k |"), std::string::npos) << fresh;
    EXPECT_EQ(with_case_key_tables(fresh, case_schema()), fresh);
    EXPECT_THROW((void)with_case_key_tables("<!-- registered-sections -->\n", case_schema()), std::invalid_argument);
}

// A law brings its option to a choice that lives with its section (supports' law), without the file
// of another law: read, refused where misspelt, documented, and gone with its handle.
TEST(RegisteredOption, ALawAddsItsOptionToTheChoiceOfItsSection) {
    const std::string support = "[[supports]]\nposition = 1.0\nlaw = \"toy\"\n";
    EXPECT_NE(error_of(test::kBaseCase + support).find("supports[0].law"), std::string::npos);
    {
        SchemaRegistration toy = register_option("supports", "law", "toy", "a toy law");
        const KeySpec* law = case_schema().section("supports")->key("law");
        ASSERT_NE(law, nullptr);
        EXPECT_EQ(law->options.back(), "toy");
        EXPECT_NE(law->meaning.find(" or `\"toy\"` (a toy law)"), std::string::npos) << law->meaning;
        const Case c = read_case_text(test::kBaseCase + support, "toy.toml");
        EXPECT_EQ(c.supports[0].params.text("law"), "toy");
        EXPECT_FALSE(c.supports[0].linear_law());
        EXPECT_THROW((void)register_option("supports", "law", "toy", "again"), std::invalid_argument);
        EXPECT_THROW((void)register_option("supports", "position", "toy", "not a choice"), std::invalid_argument);
    }
    const KeySpec* law = case_schema().section("supports")->key("law");
    EXPECT_EQ(std::count(law->options.begin(), law->options.end(), "toy"), 0);
    EXPECT_EQ(law->meaning.find("toy"), std::string::npos);
    EXPECT_NE(error_of(test::kBaseCase + support).find("supports[0].law"), std::string::npos);
}

TEST_F(ToyRegistration, RegistrationEndsWithItsHandle) {
    section_ = SchemaRegistration();
    law_ = SchemaRegistration();
    EXPECT_EQ(case_schema().section("springs"), nullptr);
    EXPECT_EQ(case_schema().section("supports")->key("toy_exponent"), nullptr);
    EXPECT_EQ(error_of(test::kBaseCase + kSprings).rfind("toy.toml:11: springs: unknown key", 0), 0u);
    EXPECT_EQ(case_schema().sections.size(), sections_before_);
    EXPECT_THROW((void)register_section(SectionSpec{}), std::invalid_argument);
}

}  // namespace
}  // namespace vi
