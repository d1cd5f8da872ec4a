#pragma once
// The case's squeeze films as force elements on the bending DOFs (docs/squeeze-film.md §2).

#include <memory>
#include <string>
#include <vector>

#include "fem/system.hpp"
#include "forces/element_family.hpp"
#include "forces/squeeze_film.hpp"
#include "model/case.hpp"

namespace vi {

// The squeeze films as an element family of the model: one per electrode (its span, its air gap
// gap - t_d) named "electrodes[i].film", and one per [[films]] entry named "films[k]", all as wide as
// the beam; none without [air] or with film = false.
const ElementFamily& squeeze_films();

// A film's regime at rest: Knudsen number lambda / g [-], mu_eff / mu [-], squeeze number at omega
// (of the widest part of the beam the film faces, where it is most a spring).
struct FilmRegime {
    std::string name;
    double gap = 0.0;             // [m]
    double knudsen = 0.0;
    double viscosity_ratio = 0.0;
    double squeeze_number = 0.0;
};
// Every film of c at rest, at circular frequency omega [rad/s] (the first natural one).
std::vector<FilmRegime> film_regimes(const Case& c, double omega);

}  // namespace vi
