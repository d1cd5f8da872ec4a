// vibroimpact: finite-element simulation of vibro-impact dynamics in contact-type MEMS devices.

#include <cstdio>
#include <exception>
#include <map>
#include <string>

#include "commands.hpp"
#include "io/input_error.hpp"

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

    for (CLI::App* sub : app.get_subcommands()) {
        try {
            return bodies.at(sub)();
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
