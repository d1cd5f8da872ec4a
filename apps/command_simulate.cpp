// `vibroimpact simulate CASE`: the free impact transient: time history, contact events, summary.

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "impacts/electrical_ledger.hpp"
#include "impacts/simulation.hpp"
#include "commands.hpp"
#include "io/case_reader.hpp"
#include "model/input_error.hpp"
#include "io/output_files.hpp"
#include "io/units.hpp"
#include "model/run_control.hpp"
#include "report/field_output.hpp"
#include "report/transient_output.hpp"
#include "stop_signals.hpp"
#include "sweep/case_paths.hpp"
#include "model/number_format.hpp"

namespace vi::cli {
namespace {

std::string us(const std::optional<double>& v) {
    if (!v) return "n/a";
    return decimals(*v * 1e6, 4) + " us";
}

void print_switching(const SwitchingLedger& l) {
    std::printf("Switching [%s]: %s\n", l.state.c_str(), l.reason.c_str());
    std::printf("  closing time (first contact)     %s\n", us(l.closing_time).c_str());
    std::printf("  bounces before stable contact    %s\n", bounce_text(l).c_str());
    std::printf("  stable contact from              %s\n", us(l.stable_contact).c_str());
    if (!l.contacts.empty()) std::printf("  peak contact force               %.4g N\n", l.peak_force);
    std::printf("  release                          %s\n", us(l.release_time).c_str());
    if (l.stuck && l.stuck->layer) {
        const LayerHold& h = *l.stuck->layer;
        std::printf("  stuck on %s: restoring force %.4g N (the layer pulls %.4g N); peel balance: released %.4g J/m vs "
                    "w w_e %.4g J/m\n",
                    l.stuck->contact.c_str(), l.stuck->restoring_force, -l.stuck->contact_force,
                    std::max(h.release_from, h.release_to), h.adhesion_energy);
    } else if (l.stuck) {
        std::printf("  stuck on supports[%d]: restoring force %.4g N vs pull-off force %.4g N (the contact pulls %.4g N)\n",
                    l.stuck->support, l.stuck->restoring_force, l.stuck->pull_off_force, -l.stuck->contact_force);
    }
}

// --r-on TEXT: the on threshold of every support with a resistivity, as its key r_on [ohm]. One line
// naming the option when the value is not a positive finite number or no support has a resistance.
void apply_r_on(Case& c, const std::string& text) {
    double v = 0.0;
    try {
        v = parse_quantity(text, Dimension::dimensionless);
    } catch (const std::invalid_argument& e) {
        throw InputError("--r-on " + in_quotes(text) + ": " + e.what());
    }
    if (!(v > 0.0)) throw InputError("--r-on " + in_quotes(text) + ": the threshold must be above 0 ohm");
    bool any = false;
    for (Support& s : c.supports) {
        if (s.params.numbers.count("resistivity") == 0) continue;
        s.params.numbers["r_on"] = v;
        any = true;
    }
    if (!any) throw InputError("--r-on: no support of " + c.name + " has a resistivity (a contact resistance to threshold)");
}

std::string ohm_text(double r) { return significant(r, 4) + " ohm"; }

// The electrical bounce ledger of each contact with a threshold: one line each.
void print_electrical(const SimulationRun& run) {
    for (const ContactConduction& c : run.result.conduction) {
        const std::string& name = run.built.model.contacts[static_cast<std::size_t>(c.contact)].name;
        const std::optional<ElectricalLedger> l = electrical_ledger(c);
        const std::string end = std::isfinite(c.end_resistance) ? ohm_text(c.end_resistance) : "open";
        if (!l) {
            std::printf("Contact resistance %s: %s at the end; no r_on, no electrical bounce ledger\n", name.c_str(), end.c_str());
            continue;
        }
        const std::string settled = l->settle_time ? "settled from " + us(l->settle_time) : "never settled below r_on";
        std::printf("Contact resistance %s: %s at the end; below r_on = %s first at %s, %d electrical bounce(s), %s\n",
                    name.c_str(), end.c_str(), ohm_text(l->r_on).c_str(), us(l->first_closure).c_str(), l->bounces,
                    settled.c_str());
    }
}

// The impacts' damage indicators summed over the run (one actuation cycle), where the solver recorded
// the contact energy.
void print_damage(const ImpactSummary& s) {
    const ContactDamage d = contact_damage(s.impacts);
    if (s.impacts.empty() || std::isnan(d.contact_energy)) return;
    std::printf("  contact energy %.4g J over %zu impacts, peak force %.4g N", d.contact_energy, s.impacts.size(),
                d.peak_force);
    if (!std::isnan(d.peak_pressure)) std::printf(", peak Hertz pressure %.4g Pa", d.peak_pressure);
    if (d.yield_known) std::printf(", %d impact(s) past yield onset 1.6 Y", d.yield_impacts);
    std::printf("\n");
}

// The film model's range (docs/squeeze-film.md §3): one line, once, naming the worst film.
void warn_film_range(const std::string& path, const std::vector<FilmRegime>& films) {
    const FilmRegime* sigma = nullptr;
    const FilmRegime* kn = nullptr;
    for (const FilmRegime& f : films) {
        if (f.squeeze_number > kSqueezeNumberLimit && (!sigma || f.squeeze_number > sigma->squeeze_number)) sigma = &f;
        if (f.knudsen > kVeijolaKnudsenMax && (!kn || f.knudsen > kn->knudsen)) kn = &f;
    }
    if (!sigma && !kn) return;
    std::string line = "vibroimpact: warning: ";
    line.append(path).append(":");
    char buf[320];
    if (sigma) {
        std::snprintf(buf, sizeof buf,
                      " %s: squeeze number %.3g at the first natural frequency is above %.1f, where the gas film "
                      "also acts as a spring and the incompressible model overstates its damping;",
                      sigma->name.c_str(), sigma->squeeze_number, kSqueezeNumberLimit);
        line += buf;
    }
    if (kn) {
        std::snprintf(buf, sizeof buf, " %s: Knudsen number %.3g is beyond Veijola's fitted range (<= %.0f);",
                      kn->name.c_str(), kn->knudsen, kVeijolaKnudsenMax);
        line += buf;
    }
    line += " see docs/squeeze-film.md\n";
    std::fputs(line.c_str(), stderr);
}

}  // namespace

CommandBody add_simulate_command(CLI::App& app) {
    struct SimulateCommandOptions {
        std::string case_path;
        bool json = false;
        std::string out_dir;
        std::string r_on;
        CLI::Option* r_on_option = nullptr;
        bool field = false;
        std::vector<std::string> sets;
    };
    auto opt = std::make_shared<SimulateCommandOptions>();
    CLI::App* sub = app.add_subcommand("simulate", "Free impact transient: release, bouncing, settling");
    sub->add_option("case", opt->case_path, "Case file (TOML) with [initial] and [solver] horizon")->required();
    sub->add_flag("--json", opt->json, "Print the summary JSON on stdout instead of a table");
    sub->add_option("--out,-o", opt->out_dir, "Folder for history.csv, events.csv and summary.json");
    opt->r_on_option = sub->add_option("--r-on", opt->r_on,
                    "On threshold of the contact resistance [ohm] for every support with a resistivity (sets their "
                    "r_on): the electrical bounce ledger");

    sub->add_option("--set", opt->sets,
                    "PATH=VALUE: a value of the case for this run, as --set of sweep takes one (SI, or a unit of the "
                    "key's dimension: supports[0].gap=0.5um, electrodes[0].voltage=70V); repeat for more")
        ->allow_extra_args(false)
        ->type_name("PATH=VALUE");
    sub->add_flag("--field", opt->field,
                  "Also record the whole deflected beam (solver.field_step, else horizon / 200) into --out: "
                  "field.pvd with field/*.vtu (ParaView) and field.csv");

    return [opt]() {
        if (opt->field && opt->out_dir.empty()) throw InputError("--field: the field is written as files; give --out DIR");
        Case c = read_case_file(opt->case_path);
        apply_case_settings(c, "--set", opt->sets);
        if (opt->r_on_option->count() > 0) apply_r_on(c, opt->r_on);
        SimulationRun run;
        try {
            SimulationOptions so;
            so.field = opt->field || c.solver.field_step > 0.0;
            run = run_simulation(c, so);
        } catch (const InputError& e) {
            throw locate_in_case(c, e);
        }
        warn_film_range(opt->case_path, run.built.model.films);
        // A contact narrower than the smallest search step could have gone unseen this deep (a
        // fraction of the watched signal's size); at roundoff level (1e-14 typically) it is noise.
        if (run.result.stats.unproven_excess > 1e-9) {
            std::fprintf(stderr,
                         "vibroimpact: warning: %s: a contact narrower than the smallest event-search step may have "
                         "been missed (solver.unproven_excess = %.3g of the signal's size; lower "
                         "solver.min_search_step)\n",
                         opt->case_path.c_str(), run.result.stats.unproven_excess);
        }
        if (!run.result.stats.fallback_reason.empty()) {
            std::fprintf(stderr,
                         "vibroimpact: warning: %s: computed by CVODE, not the exact solver: %s (summary.json: "
                         "solver.fallback_reason; solver.fallback = \"none\" makes this an error)\n",
                         opt->case_path.c_str(), run.result.stats.fallback_reason.c_str());
        }
        OutputFiles files =
            transient_files(c, run.built, run.result, run.summary, run.switching ? &*run.switching : nullptr);
        files.merge(field_files(beam_field(run.built.model.system, run.result.history)));
        // Last chance to stop: from here the results are complete and go out together.
        check_run();
        if (!opt->out_dir.empty()) {
            const CommitSection commit;
            write_output_files(opt->out_dir, files);
        }
        if (opt->json) {
            std::fputs(files.at("summary.json").c_str(), stdout);
            return kExitOk;
        }
        const ImpactSummary& s = run.summary;
        std::printf("Case %s: %s, solver %s, %zu episodes in %zu impacts\n", opt->case_path.c_str(), c.name.c_str(),
                    run.result.stats.method.c_str(), run.result.episodes.size(), s.impacts.size());
        std::printf("  T  (period of impact vibrations) %s\n", us(s.T_first).c_str());
        std::printf("  T1 (flight)                      %s\n", us(s.T1_first).c_str());
        std::printf("  T2 (impact duration)             %s\n", us(s.T2_first).c_str());
        std::printf("  Tp (transient duration)          %s  [%s]\n", us(s.Tp).c_str(), s.Tp_reason.c_str());
        if (s.y_max) std::printf("  y_max %.4g m, z_max %.4g\n", *s.y_max, *s.z_max);
        print_damage(s);
        if (run.switching) print_switching(*run.switching);
        print_electrical(run);
        if (!opt->out_dir.empty()) std::printf("Written to %s/\n", opt->out_dir.c_str());
        return kExitOk;
    };
}

}  // namespace vi::cli
