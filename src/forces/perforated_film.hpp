#pragma once
// The squeeze film under a perforated strip: the modified Reynolds equation of Bao et al. (2003),
// the holes a sink spread over the plate, solved across the strip's width (docs/squeeze-film.md §9).

namespace vi {

struct FilmGas;

// Release holes through the plate over a film, in a square array: side (square) or diameter
// (circle) `size` at `pitch` [m], each hole a tube as long as the plate is thick [m], in a strip of
// `width` [m] whose long edges vent to ambient.
struct FilmPerforation {
    double size = 0.0;
    double pitch = 0.0;
    bool circle = false;
    double plate_thickness = 0.0;
    double width = 0.0;
};

// What the holes do to the film's damping per unit length at gap g: c = c_solid(g) factor, with its
// derivative d factor / d g [1/m] given d ln c_solid / d g (the solid strip's slope, Veijola's slip
// included).
struct PerforationFactor {
    double value = 1.0;
    double slope = 0.0;
};
PerforationFactor perforation_factor(const FilmPerforation& p, const FilmGas& gas, double gap, double solid_log_slope);

// The parts of the model, for its tests. The hole's radius and its cell's, as equal-area circles [m].
struct PerforationCell {
    double hole_radius = 0.0;  // r0: d / 2, or s / sqrt(pi) for a square hole
    double cell_radius = 0.0;  // rc = pitch / sqrt(pi)
};
PerforationCell perforation_cell(const FilmPerforation& p);

// Skvor's function of beta = r0 / rc, K = 4 beta^2 - beta^4 - 4 ln beta - 3: a cell's gap flow
// alone damps with 3 pi mu rc^4 K / (2 g^3).
double skvor_function(double beta);

// The flow resistance of one hole [Pa s/m^3] at viscosity mu: Poiseuille through the plate (a round
// tube 8 mu H / (pi r0^4), a square duct 28.45 mu H / s^4) plus Sampson's orifice term 3 mu / r0^3.
double hole_resistance(const FilmPerforation& p, double viscosity);

// The strip's factor F(z) = (12 / z^2) (1 - (2 / z) tanh(z / 2)) and dF / d(z^2): the damping of a
// strip that leaks through its face, against the closed strip's (F(0) = 1).
struct StripFactor {
    double value = 1.0;
    double slope = 0.0;
};
StripFactor strip_factor(double z_squared);

}  // namespace vi
