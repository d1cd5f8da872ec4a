// The keys of [[supports]]: the motion limiters, with their adhesion.

#include "model/case_schema_bind.hpp"
#include "model/case_schema_builtin.hpp"
#include "model/run_estimate.hpp"

namespace vi::schema {
namespace {

// Which of gap and prestress sets a support's surface: the key the file used, or (for a support
// built in code) the one the surface's sign stands for, zero counting as a gap.
bool surface_is_gap(const Support& s) {
    return s.surface_key == "gap" || (s.surface_key.empty() && !(s.surface > 0.0));
}

void set_surface(Support& s, const char* key, double surface) {
    s.surface = surface;
    s.surface_key = key;
}

// gap and prestress are two views of one surface height: setting one replaces the other.
void add_surface_keys(SectionSpec& s) {
    KeySpec& gap = s.add_key(number_key("gap", Dimension::length)).in(non_negative());
    gap.means("distance from the beam's unloaded axis to the support surface (surface = -gap)");
    gap.default_text = "0 (with neither key the surface touches the unloaded beam)";
    gap.get_number = [](const Case& c, std::size_t i, std::size_t) { return 0.0 - c.supports[i].surface; };
    gap.set_number = [](Case& c, std::size_t i, std::size_t, double v) { set_surface(c.supports[i], "gap", -v); };
    gap.is_set = [](const Case& c, std::size_t i) { return surface_is_gap(c.supports[i]); };
    gap.set_refuses_out_of_range = true;
    KeySpec& pre = s.add_key(number_key("prestress", Dimension::length)).in(non_negative());
    pre.means("how far the surface is pushed into the beam's unloaded position (surface = +prestress)");
    pre.default_text = "-";
    pre.get_number = [](const Case& c, std::size_t i, std::size_t) { return c.supports[i].surface; };
    pre.set_number = [](Case& c, std::size_t i, std::size_t, double v) { set_surface(c.supports[i], "prestress", v); };
    pre.is_set = [](const Case& c, std::size_t i) { return !surface_is_gap(c.supports[i]); };
    pre.set_refuses_out_of_range = true;
}

// The keys of the built-in linear law (Kc, Cc, adhesion): a law a force family registers
// (supports[i].law) brings its own.
KeyCondition linear_law() {
    return when<Support>([](const Support& x) { return x.linear_law(); }, {"law"},
                         "only with $.law = \"kelvin-voigt\" (the linear contact)", "",
                         "`law = \"kelvin-voigt\"` (the default)");
}

// damping and damping_ratio give Cc two ways: setting one clears the other.
void add_damper_keys(SectionSpec& s) {
    KeySpec& d = s.add_key(number_key("damping", Dimension::damping)).otherwise(0.0).in(non_negative()).only(linear_law()).means("Cc");
    d.get_number = [](const Case& c, std::size_t i, std::size_t) { return c.supports[i].damping; };
    d.set_number = [](Case& c, std::size_t i, std::size_t, double v) {
        c.supports[i].damping = v;
        c.supports[i].damping_ratio.reset();
    };
    d.is_set = [](const Case& c, std::size_t i) { return !c.supports[i].damping_ratio.has_value(); };
    KeySpec& z = s.add_key(number_key("damping_ratio", Dimension::dimensionless)).in(non_negative()).only(linear_law());
    z.means("Cc given as a damping ratio zeta_c instead (below)");
    z.default_text = "unset";
    bind_optional<Support>(z, [](Support& x) -> std::optional<double>& { return x.damping_ratio; });
    z.set_number = [](Case& c, std::size_t i, std::size_t, double v) {
        c.supports[i].damping_ratio = v;
        c.supports[i].damping = 0.0;
    };
}

void add_adhesion_keys(SectionSpec& s) {
    KeySpec& law = s.add_key(choice_key("adhesion", {"none", "dmt", "jkr"})).otherwise(std::string("none")).only(linear_law());
    law.means("the contact's adhesion law: `\"none\"`, `\"dmt\"` (F_po = 2 pi R w) or `\"jkr\"` (F_po = 1.5 pi R w); "
              "[adhesion.md](adhesion.md)");
    bind_choice<Support>(law, [](Support& x) -> Adhesion& { return x.adhesion; },
                         std::vector<Adhesion>{Adhesion::none, Adhesion::dmt, Adhesion::jkr});
    const KeyCondition adhesive =
        when<Support>([](const Support& x) { return x.adhesion != Adhesion::none; }, {"adhesion"},
                      "only with $.adhesion = \"dmt\" or \"jkr\"",
                      "only for a support with adhesion (give its adhesion = \"dmt\" or \"jkr\")");
    bind_member(s.add_key(number_key("work_of_adhesion", Dimension::surface_energy)).require().in(positive())
                    .only(adhesive).means("w"),
                &Support::work_of_adhesion);
    bind_member(s.add_key(number_key("contact_radius", Dimension::length)).require().in(positive()).only(adhesive)
                    .means("R of the contacting asperity or sphere"),
                &Support::contact_radius);
    bind_member(s.add_key(number_key("adhesion_range", Dimension::length)).otherwise(kDefaultAdhesionRange, "2 nm")
                    .in(positive()).only(adhesive)
                    .means("separation over which the pull-off force falls to 0 once the surfaces part"),
                &Support::adhesion_range);
}

}  // namespace

SectionSpec supports_section() {
    SectionSpec s = array_section<Support>("supports", "support", &Case::supports, kMaxSupports);
    s.exclusive = {{"gap", "prestress"}, {"damping", "damping_ratio"}};
    s.params = [](Case& c, std::size_t i) { return i < c.supports.size() ? &c.supports[i].params : nullptr; };
    bind_member(s.add_key(number_key("position", Dimension::dimensionless, "x/l")).require()
                    .in(interval(0, true, 1, false, " (x0/l)")).means("x0 / l"),
                &Support::position);
    bind_choice<Support>(s.add_key(choice_key("side", {"below", "above"})).otherwise(std::string("below"))
                             .means("`\"below\"` pushes the beam up (+v), `\"above\"` pushes it down"),
                         [](Support& x) -> Side& { return x.side; }, std::vector<Side>{Side::below, Side::above});
    add_surface_keys(s);
    bind_member(s.add_key(number_key("stiffness", Dimension::stiffness)).require().in(positive()).only(linear_law()).means("Kc"),
                &Support::stiffness);
    add_damper_keys(s);
    add_adhesion_keys(s);
    // The law lives with its section; each law a force family brings adds its option
    // (register_option) and its own keys. Its value is read by those families alone.
    KeySpec& law = s.add_key(choice_key("law", {"kelvin-voigt"})).otherwise(std::string("kelvin-voigt"));
    law.means("the contact's force law: `\"kelvin-voigt\"` (linear, Kc and Cc)");
    bind_to_params(law, "supports");
    return s;
}

}  // namespace vi::schema
