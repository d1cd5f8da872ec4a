// The keys of [air], [[films]] and [solver].

#include "model/case_schema_bind.hpp"
#include "model/case_schema_builtin.hpp"
#include "model/run_estimate.hpp"

namespace vi::schema {
namespace {

using Settings = SolverSettings;

// A whole-number setting of the solver in [lo, hi]; a path may set any value its field holds (the
// range check then names the bound).
template <class Int>
KeySpec& bounded_count(SectionSpec& s, const char* name, double dflt, double lo, double hi, Int Settings::*m) {
    KeySpec& k = s.add_key(integer_key(name)).otherwise(dflt).in(interval(lo, false, hi, false));
    k.whole_limit = static_cast<double>(std::numeric_limits<Int>::max());
    return bind_member(k, m);
}

void add_impact_rules(SectionSpec& s) {
    KeySpec& gap = s.add_key(number_key("group_gap", Dimension::time)).otherwise(0.0).in(non_negative());
    gap.default_text = "a quarter of the first natural period of the beam without supports";
    gap.means("contact episodes separated by flights shorter than this form one impact; 0 means the default");
    gap.only(when<Settings>([](const Settings& x) { return x.grouping == Settings::Grouping::flights; }, {"grouping"},
                            "only with $.grouping = \"flights\" (with \"none\" no episodes are joined)",
                            "the case sets solver.grouping = \"none\"", "`grouping = \"flights\"`"));
    bind_member(gap, &Settings::group_gap);
    bind_choice<Settings>(s.add_key(choice_key("grouping", {"flights", "none"})).otherwise(std::string("flights"))
                              .means("how contact episodes form impacts: `\"flights\"` joins episodes of one support "
                                     "separated by flights shorter than `group_gap`; `\"none\"` makes every episode an "
                                     "impact of its own"),
                          [](Settings& x) -> Settings::Grouping& { return x.grouping; },
                          std::vector<Settings::Grouping>{Settings::Grouping::flights, Settings::Grouping::none});
    KeySpec& tol = s.add_key(number_key("settle_tolerance", Dimension::dimensionless)).otherwise(0.01);
    tol.in(interval(0, true, 1, true)).means("impacts whose peak penetration is below this fraction of the first "
                                             "impact's end the transient process T_p");
    tol.only(when<Settings>([](const Settings& x) { return x.settle_rule == Settings::SettleRule::penetration; },
                            {"settle_rule"}, "only with $.settle_rule = \"penetration\" (the velocity rule uses settle_velocity)",
                            "the case sets solver.settle_rule = \"velocity\"", "`settle_rule = \"penetration\"`"));
    bind_member(tol, &Settings::settle_tolerance);
    bind_choice<Settings>(s.add_key(choice_key("settle_rule", {"penetration", "velocity"}))
                              .otherwise(std::string("penetration"))
                              .means("what ends T_p: `\"penetration\"` (the last impact above `settle_tolerance`) or "
                                     "`\"velocity\"` (the last impact whose approach speed reaches `settle_velocity`); "
                                     "see below"),
                          [](Settings& x) -> Settings::SettleRule& { return x.settle_rule; },
                          std::vector<Settings::SettleRule>{Settings::SettleRule::penetration, Settings::SettleRule::velocity});
    bind_member(s.add_key(number_key("settle_velocity", Dimension::velocity)).require().in(positive())
                    .only(when<Settings>([](const Settings& x) { return x.settle_rule == Settings::SettleRule::velocity; },
                                         {"settle_rule"}, "only with $.settle_rule = \"velocity\""))
                    .means("impacts approaching slower than this no longer count"),
                &Settings::settle_velocity);
}

}  // namespace

SectionSpec air_section() {
    SectionSpec s = table_section<Air>("air", false);
    s.count = [](const Case& c) { return c.air ? std::size_t{1} : std::size_t{0}; };
    s.add = [](Case& c) { c.air.emplace(); };
    s.absent_text = "only with an [air] table";
    bind_member(s.add_key(number_key("pressure", Dimension::pressure)).otherwise(kAirPressure0, "101325 Pa (1 atm)")
                    .in(positive()).means("ambient pressure p"),
                &Air::pressure);
    bind_member(s.add_key(number_key("temperature", Dimension::temperature)).otherwise(kAirTemperature0, "300 K")
                    .in(positive()).means("T; enters only the default mean free path"),
                &Air::temperature);
    bind_member(s.add_key(number_key("viscosity", Dimension::viscosity)).otherwise(1.85e-5, "1.85e-5 Pa s")
                    .in(positive()).means("dynamic viscosity mu (air at 300 K)"),
                &Air::viscosity);
    KeySpec& mfp = s.add_key(number_key("mean_free_path", Dimension::length)).in(positive()).means("lambda");
    mfp.default_text = "lambda0 (p0 / p) (T / T0), lambda0 = 68 nm, p0 = 101325 Pa, T0 = 300 K";
    bind_optional<Air>(mfp, [](Air& a) -> std::optional<double>& { return a.mean_free_path; });
    // A path reads the mean free path in effect, given or not.
    mfp.get_number = [](const Case& c, std::size_t, std::size_t) { return c.air->lambda(); };
    bind_member(s.add_key(flag_key("film")).otherwise(std::string("true"))
                    .means("whether the film acts (`false`: the gas is described, no film)"),
                &Air::film);
    return s;
}

SectionSpec films_section() {
    SectionSpec s = array_section<Film>("films", "film", &Case::films, kMaxElectrodes);
    s.params = [](Case& c, std::size_t i) { return i < c.films.size() ? &c.films[i].params : nullptr; };
    bind_member(s.add_key(number_key("from", Dimension::dimensionless, "x/l")).require()
                    .in(interval(0, false, 1, true, " (x/l)")).means("where the film's span starts"),
                &Film::from);
    bind_member(s.add_key(number_key("to", Dimension::dimensionless, "x/l")).require()
                    .in(interval(0, true, 1, false, " (x/l)")).means("where it ends, above `from`"),
                &Film::to);
    bind_choice<Film>(s.add_key(choice_key("side", {"below", "above"})).otherwise(std::string("below"))
                          .means("the side of the beam the surface faces"),
                      [](Film& f) -> Side& { return f.side; }, std::vector<Side>{Side::below, Side::above});
    bind_member(s.add_key(number_key("gap", Dimension::length)).require().in(positive()).means("beam to surface at rest"),
                &Film::gap);
    return s;
}

SectionSpec solver_section() {
    SectionSpec s = table_section<Settings>("solver", false);
    using Method = Settings::Method;
    KeySpec& method = s.add_key(choice_key("method", {"auto", "exact", "cvode"})).otherwise(std::string("auto"));
    method.means("`\"auto\"`: the exact solver when every force is piecewise linear, CVODE otherwise; `\"exact\"`: "
                 "event-driven piecewise-linear solution (an input error naming the force when one is not piecewise "
                 "linear); `\"cvode\"`: SUNDIALS CVODE in modal coordinates (a full model with an electrode or a "
                 "film: in the FE DOFs) with root finding (docs/model.md §13)");
    bind_choice<Settings>(method, [](Settings& x) -> Method& { return x.method; },
                          std::vector<Method>{Method::automatic, Method::exact, Method::cvode});
    // In the Case 0 stands for "not given"; written in a file, these two must be positive.
    KeySpec& horizon = s.add_key(number_key("horizon", Dimension::time)).in(positive());
    horizon.means("simulated time, at most 1e9 of the shortest time scale ([Limits](#limits))");
    horizon.default_text = "not given (the `simulate` command then needs it)";
    bind_member(horizon, &Settings::horizon);
    horizon.is_set = [](const Case& c, std::size_t) { return c.solver.horizon != 0.0; };
    KeySpec& step = s.add_key(number_key("output_step", Dimension::time)).in(positive());
    step.means("sampling step of the time history, not above `horizon`; the history must fit in memory "
               "([Limits](#limits))");
    step.default_text = "`horizon` / 2000";
    bind_member(step, &Settings::output_step);
    step.is_set = [](const Case& c, std::size_t) { return c.solver.output_step != 0.0; };
    KeySpec& field = s.add_key(number_key("field_step", Dimension::time)).in(positive());
    field.means("sampling step of the field output (the whole deflected beam, `simulate --out`: field.pvd and "
                "field/*.vtu for ParaView, field.csv), rounded to a whole number of `output_step`s; at most 5000 "
                "frames and 4e6 values ([Limits](#limits))");
    field.default_text = "no field (`simulate --field`: `horizon` / 200)";
    bind_member(field, &Settings::field_step);
    field.is_set = [](const Case& c, std::size_t) { return c.solver.field_step != 0.0; };
    add_impact_rules(s);
    // The floor: below 1e-12 CVODE's error test is asked to resolve the roundoff of the right-hand
    // side (sums over a hundred modal terms, about 1e-14), while the answers no longer move: the switch
    // examples' closing times agree to 1e-10 between 1e-12 and 1e-15, and the steps grow 1.4-2 times
    // per decade (capacitive_stiction.toml: 0.79 M steps at 1e-12, 1.7 M at 1e-13, no end within 60 s
    // at 1e-14).
    KeyRange rtol_range = interval(1e-12, false, 1e-3, false);
    rtol_range.too_low = "must be at least 1e-12: below, CVODE's error test resolves the roundoff of the "
                         "right-hand side and the steps grow without changing the answer (docs/case-files.md, Limits)";
    bind_member(s.add_key(number_key("rtol", Dimension::dimensionless)).otherwise(1e-10).in(rtol_range)
                    .means("CVODE relative tolerance, at least 1e-12 ([Limits](#limits)); the absolute tolerances "
                           "follow it (1e-4 rtol times each component's scale): on the paper's transient 1e-8 is "
                           "within 2e-9 of the exact solver (0.4 s), 1e-10 within 1e-9 (1 s)"),
                &Settings::rtol);
    bind_member(s.add_key(number_key("min_search_step", Dimension::dimensionless, "periods")).otherwise(1e-9)
                    .in(interval(1e-15, false, 1e-3, false, " (periods of the first mode)"))
                    .means("exact solver: the smallest step of its event search, in periods of the first mode of the "
                           "beam without supports; only a contact that opens and closes within such a step can go "
                           "unseen, and the summary says how deep it could have gone (`solver.unproven_excess`)"),
                &Settings::min_search_step);
    bounded_count(s, "max_events", 1000000, 1, 1e9, &Settings::max_events)
        .means("bound on the work of one transient: contact switches and load breakpoints over the horizon; "
               "reaching it stops the run with an error that names this key (exit 1)");
    bounded_count(s, "max_steps", static_cast<double>(kDefaultMaxSteps), 1000, 1e11, &Settings::max_steps)
        .means("bound on the work of one transient: the exact solver's event- and extremum-search evaluations, or "
               "CVODE's internal steps (10 to 100 us each at 50 elements, [Limits](#limits)); reaching it stops the "
               "run with an error that names this key (exit 1), and so does a pace of CVODE's steps that would "
               "reach it before the horizon; a periodic drive whose periods over the horizon "
               "need more (at least 10 steps each) is refused before the run");
    bounded_count(s, "max_static_iterations", 200, 1, 1e6, &Settings::max_static_iterations)
        .means("bound on the Newton iterations of a static solution (each contact set tried counts); reaching it "
               "stops the run with an error that names this key (exit 1)");
    KeySpec& reduced = bounded_count(s, "reduced_modes", 0, 0, 1e5, &Settings::reduced_modes);
    reduced.range.note = " (0: the full model)";
    reduced.means("CVODE only: 0 integrates every bending mode (the full FE model); N > 0 a reduced-order model on the "
                  "N lowest modes plus static corrections at the contacts and the initial state (docs/model.md §13)");
    using Fallback = Settings::Fallback;
    bind_choice<Settings>(s.add_key(choice_key("fallback", {"cvode", "none"})).otherwise(std::string("cvode"))
                              .means("when the exact solver meets a contact state it cannot decompose: `\"cvode\"` "
                                     "computes the whole transient again with CVODE and says so; `\"none\"` makes it "
                                     "an error (exit 1)"),
                          [](Settings& x) -> Fallback& { return x.fallback; },
                          std::vector<Fallback>{Fallback::cvode, Fallback::none});
    return s;
}

}  // namespace vi::schema
