// vibroimpact: finite-element simulation of vibro-impact dynamics in contact-type MEMS devices.

#include <csignal>
#include <cstdio>
#include <exception>
#include <map>
#include <string>

#include "commands.hpp"
#include "model/input_error.hpp"
#include "model/run_control.hpp"

namespace {

extern "C" void on_stop_signal(int signal) { vi::request_stop(signal); }

// SIGINT and SIGTERM set the stop flag that every solver loop checks (model/run_control.hpp): the
// command abandons its work, writes nothing half-done and exits 128 + the signal. The handler then
// resets itself, so a second signal ends the process at once.
void stop_on_signals() {
    struct sigaction sa {};
    sa.sa_handler = on_stop_signal;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = SA_RESETHAND;
    sigaction(SIGINT, &sa, nullptr);
    sigaction(SIGTERM, &sa, nullptr);
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
    add(add_validate_command);
    add(add_sweep_command);
    add(add_paper_command);

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::fprintf(stderr, "vibroimpact: error: %s (see --help)\n", e.what());
        return kExitBadInput;
    }

    stop_on_signals();
    for (CLI::App* sub : app.get_subcommands()) {
        try {
            return bodies.at(sub)();
        } catch (const vi::StopRequested& s) {
            std::fprintf(stderr, "vibroimpact: stopped by %s; nothing written\n",
                         s.signal() == SIGTERM ? "SIGTERM" : s.signal() == SIGINT ? "SIGINT" : "a stop request");
            return kExitStoppedBase + (s.signal() > 0 ? s.signal() : SIGINT);
        } catch (const vi::InputError& e) {
            std::fprintf(stderr, "vibroimpact: error: %s\n", e.what());
            return kExitBadInput;
        } catch (const std::exception& e) {
            std::fprintf(stderr, "vibroimpact: failure: %s\n", e.what());
            return kExitFailure;
        }
    }
    return kExitBadInput;
}
