#pragma once
// Case: the validated, unit-free (SI) description of one beam with its supports, damping and loads.

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "model/parameter_set.hpp"
#include "model/time_function.hpp"
#include "model/waveform.hpp"

namespace vi {

// Boundary condition of one beam end.
enum class EndCondition { clamped, pinned, free };

// Which side of the beam a support's surface faces: below pushes up (+v), above pushes down.
enum class Side { below, above };

// Isotropic material; SI units (Pa, kg/m^3, dimensionless).
struct Material {
    double youngs_modulus = 0.0;   // E [Pa]
    double density = 0.0;          // rho [kg/m^3]
    double poisson_ratio = 0.0;    // nu [-]
    bool plate_modulus = false;    // use E/(1-nu^2) for wide beams
    // Modulus that enters the bending and axial stiffness [Pa].
    [[nodiscard]] double effective_modulus() const;
};

// A material a layer names ([[materials]]); SI units. Its residual stress is the in-plane stress the
// layer carries while the beam is held straight and at length (as deposited); its stress gradient
// grows that stress linearly toward the layer's top.
struct LayerMaterial {
    std::string name;                  // how layers refer to it
    double youngs_modulus = 0.0;       // E [Pa]
    double density = 0.0;              // rho [kg/m^3]
    double poisson_ratio = 0.0;        // nu [-]
    double residual_stress = 0.0;      // sigma_r, tension positive [Pa]
    double stress_gradient = 0.0;      // Gamma, d sigma / dz through the layer [Pa/m]
};

// One layer of a section's stack, listed bottom to top.
struct Layer {
    std::string material;              // a LayerMaterial's name
    double thickness = 0.0;            // [m]
};

// The shape of a section's release holes.
enum class HoleShape { square, circle };

// Release holes through a section in a square array: each a square of side `size` or a circle of
// diameter `size`, at `pitch` along and across the beam [m].
struct Holes {
    double size = 0.0;
    double pitch = 0.0;
    HoleShape shape = HoleShape::square;
};

// A part [from, to] (x/l) of the beam with its own width, thickness or layer stack; what it leaves
// out is the plain beam's (its width, its thickness, the [material]).
struct BeamSection {
    double from = 0.0;                 // x/l where it starts
    double to = 1.0;                   // x/l where it ends
    std::optional<double> width;       // [m]; unset: the beam's
    std::optional<double> thickness;   // [m]; unset: the beam's (or the layers' sum)
    std::vector<Layer> layers;         // bottom to top; empty: one layer of [material]
    std::optional<Holes> holes;        // unset: a solid section
};

// Straight beam along x from 0 to length, rectangular section width x thickness [m], optionally
// made of sections that change the width, the thickness or the layer stack along it.
struct Beam {
    double length = 0.0;     // l [m]
    double width = 0.0;      // w [m]
    double thickness = 0.0;  // t [m]
    int elements = 50;       // m, elements of the uniform mesh before support nodes are added
    EndCondition left = EndCondition::clamped;   // end at x = 0
    EndCondition right = EndCondition::free;     // end at x = l
    // Residual axial stress sigma0 [Pa], positive = tension; the axial force N0 = sigma0 A stiffens
    // (or, compressive, softens) bending. Only with both ends clamped or pinned (docs/electrostatics.md §8).
    double residual_stress = 0.0;
    // Mid-plane stretching: the axial force (E A / (2 l)) int v'^2 dx of a beam whose ends hold the axis.
    bool stretching = false;
    // The parts of the beam, ascending, covering [0, 1] (x/l) without gaps or overlaps; empty: one
    // prismatic beam of [material] with width and thickness.
    std::vector<BeamSection> sections{};
    [[nodiscard]] double area() const { return width * thickness; }                          // A [m^2]
    [[nodiscard]] double second_moment() const { return width * thickness * thickness * thickness / 12.0; }  // I [m^4]
    // Whether both ends hold the axis (clamped or pinned), so that an axial force can act.
    [[nodiscard]] bool axis_held() const { return left != EndCondition::free && right != EndCondition::free; }
};

// Adhesion law of a support's contact (docs/adhesion.md): none, or the pull-off force of a sphere of
// radius R on a flat with work of adhesion w: DMT 2 pi R w, JKR 1.5 pi R w.
enum class Adhesion { none, dmt, jkr };

// Default separation over which the pull-off force falls to zero once the surfaces part [m]: a few
// atomic spacings of surface-force range plus nm-scale roughness (docs/adhesion.md §2).
inline constexpr double kDefaultAdhesionRange = 2e-9;

// Kelvin-Voigt motion limiter acting on v(x0).
struct Support {
    double position = 1.0;  // x0 / l in (0, 1]
    Side side = Side::below;
    // Height of the support surface above the beam's unloaded axis, on the support's own side
    // convention: s = -gap; s > 0 is a prestress [m].
    double surface = 0.0;
    // Which key set the surface in the case file ("gap", "prestress", or "" when neither), so that
    // problems with it name the key the user wrote.
    std::string surface_key;
    double stiffness = 0.0;                  // Kc [N/m]
    double damping = 0.0;                    // Cc [N s/m]
    std::optional<double> damping_ratio;     // if set, Cc is derived from it (see docs/model.md)
    Adhesion adhesion = Adhesion::none;
    double work_of_adhesion = 0.0;           // w [J/m^2]
    double contact_radius = 0.0;             // R of the contacting asperity or sphere [m]
    double adhesion_range = kDefaultAdhesionRange;  // delta [m]
    ParameterSet params;                     // values of keys registered for supports (a law's own)
    // Whether its contact is the built-in linear (Kelvin-Voigt) law, plain or adhesive: true unless a
    // law registered by a force family is chosen (params' `law`).
    [[nodiscard]] bool linear_law() const { return params.text("law", "kelvin-voigt") == "kelvin-voigt"; }
    // The pull-off force F_po [N]: 2 pi R w (DMT), 1.5 pi R w (JKR), 0 without adhesion.
    [[nodiscard]] double pull_off_force() const;
};

// Rayleigh damping C = alpha M + beta K: either alpha/beta directly or two ratios at two bending modes.
struct RayleighDamping {
    bool from_ratios = false;
    double alpha = 0.0;        // [1/s]
    double beta = 0.0;         // [s]
    double ratio1 = 0.0;       // xi1 [-]
    double ratio2 = 0.0;       // xi2 [-]
    int mode1 = 1;             // bending mode numbers (1-based, unsupported beam) the ratios refer to
    int mode2 = 2;
};

// How the transient starts (paper section 3): a static step, then release at t = 0.
struct InitialState {
    // rest: the static equilibrium with the supports (prestressed ones push), no step.
    // displacement: the point at `position` is lifted by `displacement` above that equilibrium by a
    // static point force there. force: a static point force `force` at `position`.
    enum class Kind { rest, displacement, force };
    Kind kind = Kind::displacement;
    double position = 1.0;       // x/l of the displaced or loaded point
    double displacement = 0.0;   // y0 [m], positive up
    double force = 0.0;          // [N], positive up
    // Initial velocity: none (release from rest), uniform v for every transverse DOF, or along a
    // bending mode of the unsupported beam scaled so that the free end (or x = position) moves at
    // `velocity`.
    enum class Velocity { none, uniform, mode };
    Velocity velocity_kind = Velocity::none;
    double velocity = 0.0;       // [m/s]
    int velocity_mode = 1;       // 1-based bending mode for Velocity::mode
};

// A time-dependent transverse point load Q(t) = amplitude * g(t) at x/l = position.
struct PointLoad {
    double position = 1.0;       // x/l
    double amplitude = 0.0;      // [N]
    TimeFunction time;
    std::string table_file;      // kind table: the CSV file as the case file names it
    ParameterSet params;         // values of keys registered for loads
};

// Fringing-field correction of an electrode's force (docs/electrostatics.md §2): none (the
// parallel-plate force of the overlap alone) or the Meijs-Fokkema capacitance of a line over a
// ground plane (stated for 0.3 <= w/g <= 30 and 0.3 <= t/g <= 30).
enum class Fringing { none, meijs_fokkema };

// A fixed electrode facing the span [from, to] (x/l) of the beam across an air gap, on one side,
// with an optional dielectric layer on it; voltage V(t) = voltage g(t) between it and the beam.
struct Electrode {
    double from = 0.0;                     // x/l where the electrode starts
    double to = 1.0;                       // x/l where it ends
    Side side = Side::below;               // below pulls the beam down (-v), above pulls it up
    double gap = 0.0;                      // beam to electrode at rest, dielectric included [m]
    double dielectric_thickness = 0.0;     // t_d of the layer on the electrode, < gap [m]
    double dielectric_permittivity = 1.0;  // eps_r of that layer [-]
    // Young's modulus E_d of that layer [Pa]: where the beam lands on it, the layer is an elastic
    // foundation of line stiffness E_d w_e / t_d (the default: silicon nitride, 250 GPa).
    double dielectric_modulus = 250e9;
    // Adhesion of the beam to that layer: the work of adhesion w [J/m^2] (none when empty) and the
    // range over which the attraction falls to 0 above the face [m] (docs/adhesion.md §9).
    std::optional<double> work_of_adhesion;
    double adhesion_range = kDefaultAdhesionRange;
    double width = 0.0;                    // effective electrode width w_e [m]; 0 = the beam's width
    Fringing fringing = Fringing::none;
    double voltage = 0.0;                  // amplitude [V]
    // The waveform as the case file gives it; `time` is built from it (waveform_function) unless
    // it is a table or given: set a shape key or the voltage through set_case_value, which builds
    // `time` again.
    Waveform waveform;
    TimeFunction time;                     // g(t) (ramps, pulses and two-step drives are tables)
    std::string table_file;                // waveform table: the CSV file as the case file names it
    ParameterSet params;                   // values of keys registered for electrodes
};

// The gas around the beam (docs/squeeze-film.md). Its presence in a case ([air]) turns on the
// squeeze film under every electrode and every [[films]] span; without it the beam is in vacuum.
struct Air {
    double pressure = 101325.0;   // p [Pa]
    double temperature = 300.0;   // T [K]; enters the default mean free path only
    double viscosity = 1.85e-5;   // mu [Pa s], air at 300 K
    // lambda [m]; unset: kMeanFreePath0 (p0 / p) (T / T0) (kinetic theory's lambda ~ T / p).
    std::optional<double> mean_free_path;
    bool film = true;             // false: the gas is described but no film acts
    // The mean free path in effect [m].
    [[nodiscard]] double lambda() const;
};

// Mean free path of air at p0 = 101325 Pa, T0 = 300 K [m] (docs/squeeze-film.md §1).
inline constexpr double kMeanFreePath0 = 68e-9;
inline constexpr double kAirPressure0 = 101325.0;
inline constexpr double kAirTemperature0 = 300.0;

// A squeeze film where no electrode is: the span [from, to] (x/l) over a surface at `gap` [m].
struct Film {
    double from = 0.0;
    double to = 1.0;
    Side side = Side::below;
    double gap = 0.0;  // beam to surface at rest [m]
    ParameterSet params;  // values of keys registered for films
};

// Default bound on the work of one transient (solver.max_steps): CVODE steps cost 10 to 100 us at
// 50 elements (the switch examples take 6 000 to 164 000 of them at their rtol,
// capacitive_stiction.toml the most; a grazing contact or a contact damper far above critical
// 400 000 to 500 000), the exact solver's search evaluations about 1 us (the paper's example over
// 10 ms takes 63 000), so a run that would go on for hours ends within about 10 s at 50 elements
// (an impact sensor rattling between its stops for 300 drive periods in air: 2 000 000 steps in
// 21 s), naming the key.
inline constexpr long kDefaultMaxSteps = 1000000;

// Transient solver settings.
struct SolverSettings {
    // automatic: the exact solver when every force element is piecewise linear, else CVODE.
    enum class Method { automatic, exact, cvode };
    Method method = Method::automatic;
    double horizon = 0.0;            // t_end [s]; 0 = not given (required by `simulate`)
    double output_step = 0.0;        // time-history sampling [s]; 0 = horizon / 2000
    double field_step = 0.0;         // sampling of the whole beam's deflection [s]; 0 = none
    double group_gap = 0.0;          // flights shorter than this join episodes into one impact [s];
                                     // 0 = a quarter of the first unsupported period
    double settle_tolerance = 0.01;  // impacts below this fraction of the first peak penetration end T_p
    // How contact episodes form impacts: flights shorter than group_gap join them (the paper's
    // impacts I, II, III), or none: every episode is an impact of its own.
    enum class Grouping { flights, none };
    Grouping grouping = Grouping::flights;
    // What ends T_p: the last impact whose peak penetration exceeds settle_tolerance times the
    // first's (penetration), or whose approach speed |v_in| reaches settle_velocity (velocity).
    enum class SettleRule { penetration, velocity };
    SettleRule settle_rule = SettleRule::penetration;
    double settle_velocity = 0.0;    // [m/s], > 0 with settle_rule = velocity
    double rtol = 1e-10;             // CVODE relative tolerance
    // CVODE's basis: 0 = every bending mode (the full FE model); N > 0 = a reduced-order model on the
    // first N unsupported modes plus static corrections at the force elements (docs/model.md §13).
    int reduced_modes = 0;
    double min_search_step = 1e-9;   // exact solver's smallest event-search step [periods of mode 1]
    // Bounds on the work of one transient (docs/case-files.md): reaching one is an error naming it.
    long max_events = 1000000;       // contact switches and load breakpoints over the horizon
    long max_steps = kDefaultMaxSteps;  // exact: event and extremum search evaluations; cvode: internal steps
    int max_static_iterations = 200; // Newton iterations of a static solution (each contact set counts)
    // What happens when the exact solver meets a contact state it cannot decompose (defective
    // eigenvalues): the whole transient is computed again by CVODE (reported), or the run fails.
    enum class Fallback { cvode, none };
    Fallback fallback = Fallback::cvode;
};

// Where a case came from: the file and the line of every key read, for messages about problems
// found after reading (e.g. while building the transient problem).
struct CaseOrigin {
    std::string file;                        // as given; empty for cases built in code
    std::map<std::string, int> key_lines;    // dotted key -> 1-based line
};

// Everything read from one case file, in SI units.
struct Case {
    CaseOrigin origin;
    std::string name;             // for output files and reports
    Beam beam;
    Material material;
    std::vector<LayerMaterial> materials;  // the materials layers name ([[materials]])
    std::vector<Support> supports;
    RayleighDamping damping;
    InitialState initial;
    std::vector<PointLoad> loads;
    std::vector<Electrode> electrodes;
    std::optional<Air> air;       // none: vacuum (no squeeze film)
    std::vector<Film> films;      // explicit film spans (only with air)
    SolverSettings solver;
    // Entries of sections registered by higher layers (model/case_schema.hpp), by section name.
    std::map<std::string, std::vector<ParameterSet>, std::less<>> sections;
};

}  // namespace vi
