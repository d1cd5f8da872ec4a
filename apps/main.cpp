// vibroimpact: finite-element simulation of vibro-impact dynamics in contact-type MEMS devices.

#include <csignal>
#include <cstdio>
#include <exception>
#include <map>
#include <string>

#include "commands.hpp"
#include "model/input_error.hpp"
#include "model/run_control.hpp"
#include "spelling_hints.hpp"
#include "stop_signals.hpp"

namespace {

// What a stopped command prints and returns: 128 + the signal (130 SIGINT, 143 SIGTERM).
int stopped(int signal) {
    std::fprintf(stderr, "vibroimpact: stopped by %s; nothing written\n",
                 signal == SIGTERM ? "SIGTERM" : signal == SIGINT ? "SIGINT" : "a stop request");
    return vi::cli::kExitStoppedBase + (signal > 0 ? signal : SIGINT);
}

}  // namespace

int main(int argc, char** argv) {
    using namespace vi::cli;
    CLI::App app{"vibroimpact: vibro-impact dynamics of MEMS beams on viscoelastic supports", "vibroimpact"};
    app.require_subcommand(1);
    app.set_version_flag("--version", kVersionText);

    std::map<CLI::App*, CommandBody> bodies;
    auto add = [&](CommandBody (*adder)(CLI::App&)) {
        const std::size_t before = app.get_subcommands({}).size();
        CommandBody body = adder(app);
        bodies[app.get_subcommands({}).at(before)] = std::move(body);
    };
    add(add_modes_command);
    add(add_support_scan_command);
    add(add_simulate_command);
    add(add_cycles_command);
    add(add_validate_command);
    add(add_sweep_command);
    add(add_paper_command);
    add(add_pullin_command);
    add(add_switch_report_command);
    add(add_optimize_command);
    add(add_fit_command);
    add(add_new_command);
    add(add_stiction_command);
    add(add_air_q_command);
    add(add_uq_command);
    add(add_plot_command);
    add(add_man_command);
    add(add_completion_command);

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::fprintf(stderr, "vibroimpact: error: %s%s (see --help)\n", e.what(), spelling_hint(app, argc, argv).c_str());
        return kExitBadInput;
    }

    install_stop_handlers();
    for (CLI::App* sub : app.get_subcommands()) {
        // A failure while a stop was requested is the stop's doing (a system call the signal
        // interrupted, work abandoned half-way): the command was stopped, not given bad input.
        try {
            return bodies.at(sub)();
        } catch (const vi::StopRequested& s) {
            return stopped(s.signal());
        } catch (const vi::InputError& e) {
            if (vi::stop_flag().load()) return stopped(vi::stop_signal());
            std::fprintf(stderr, "vibroimpact: error: %s\n", e.what());
            return kExitBadInput;
        } catch (const std::exception& e) {
            if (vi::stop_flag().load()) return stopped(vi::stop_signal());
            std::fprintf(stderr, "vibroimpact: failure: %s\n", e.what());
            return kExitFailure;
        }
    }
    return kExitBadInput;
}
