#pragma once
// vibroimpact's public C++ API in one include, <vibroimpact/vibroimpact.hpp> once installed: the
// headers of what a program does with a case, lowest layer first (docs/install.md, examples/cpp/).
//
//   vi::Case c = vi::read_case_file("switch.toml");          // InputError "FILE:LINE: KEY: reason"
//   vi::set_case_text(c, "electrodes[0].voltage", "75 V");   // the paths of `sweep --set`, with units
//   if (!vi::check_case(c).empty()) ...                      // each problem with its key
//   vi::BeamModel model = vi::build_beam_model(c);           // matrices, force elements, omega1
//   vi::SimulationRun run = vi::run_simulation(c);           // transient, impacts, switching ledger
//   vi::PullinResult p = vi::trace_pullin(c);                // static pull-in, touch-down, release
//   vi::ModalStudy m = vi::modal_study(c, 3, vi::SupportModel::pin);
//   vi::SweepGrid g = vi::parse_sweep_grid({"supports[0].stiffness=log:100:1e5:7"}, c);
//   vi::run_sweep_points(c, g, indices, {}, 0, on_point);    // one SweepPointResult per point
//
// Errors: InputError (input to fix), WorkLimitReached and TimeLimitReached (a bound on a run's
// work or time, naming its setting), std::runtime_error (numerical trouble); a stop requested
// through stop_flag() abandons a run with StopRequested.

#include "model/case.hpp"          // Case: a device and its run, SI units
#include "model/input_error.hpp"   // InputError
#include "model/case_checks.hpp"   // check_case
#include "model/run_control.hpp"   // stop_flag, WorkLimitReached, TimeLimitReached, StopRequested
#include "io/case_reader.hpp"      // read_case_file, read_case_text, locate_in_case
#include "io/case_writer.hpp"      // case_to_toml, case_to_json
#include "modal/modal_analysis.hpp"  // modal_study
#include "problem/beam_model.hpp"  // build_beam_model
#include "statics/pullin.hpp"      // trace_pullin
#include "impacts/simulation.hpp"  // run_simulation, SimulationOptions
#include "sweep/case_paths.hpp"    // resolve_case_path, get_case_value, set_case_value, set_case_text
#include "sweep/columns.hpp"       // sweep_result_columns, numeric_cell
#include "sweep/grid.hpp"          // parse_sweep_grid, SweepGrid
#include "sweep/runner.hpp"        // run_sweep_points, SweepSettings, SweepPointResult
