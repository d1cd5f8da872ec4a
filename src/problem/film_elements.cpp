#include "problem/film_elements.hpp"

#include <algorithm>

#include "problem/electrode_elements.hpp"

namespace vi {
namespace {

// A film as the builder sees it before the mesh: its name, span (x/l), side and air gap.
struct FilmSpan {
    CaseEntry entry;
    std::string name;
    double from = 0.0, to = 0.0;
    Side side = Side::below;
    double gap = 0.0;
    bool on_layer = false;  // over an electrode's dielectric layer, which stops the beam
};

std::vector<FilmSpan> film_spans(const Case& c) {
    std::vector<FilmSpan> out;
    if (!c.air || !c.air->film) return out;
    for (std::size_t k = 0; k < c.electrodes.size(); ++k) {
        const Electrode& e = c.electrodes[k];
        std::string name = "electrodes[" + std::to_string(k) + "]";
        name += ".film";
        // The gas fills the air gap only: a dielectric layer on the electrode is solid.
        out.push_back({{"electrodes", k}, std::move(name), e.from, e.to, e.side, e.gap - e.dielectric_thickness,
                       e.dielectric_thickness > 0.0});
    }
    for (std::size_t k = 0; k < c.films.size(); ++k) {
        const Film& m = c.films[k];
        out.push_back({{"films", k}, "films[" + std::to_string(k) + "]", m.from, m.to, m.side, m.gap});
    }
    return out;
}

FilmGas gas_of(const Air& a) { return {a.viscosity, a.lambda()}; }

// The widest part of the beam over [from, to] (x/l): where the film is most a spring.
double widest_under(const Case& c, double from, double to) {
    if (c.beam.sections.empty()) return c.beam.width;
    double w = 0.0;
    for (const BeamSection& s : c.beam.sections) {
        if (s.from < to && s.to > from) w = std::max(w, s.width.value_or(c.beam.width));
    }
    return w;
}

// One film per span of the case, all as wide as the beam, skipping a span that faces no part of the
// beam that moves. The gas films damp only: they leave the static state alone (no force at v = 0).
class SqueezeFilms final : public ElementFamily {
public:
    [[nodiscard]] std::string_view name() const override { return "squeeze films"; }
    [[nodiscard]] std::vector<FamilyElement> elements(const ElementSource& src) const override {
        const Case& c = src.c;
        const System& s = src.system;
        std::vector<FamilyElement> out;
        for (const FilmSpan& f : film_spans(c)) {
            FilmGeometry g;
            g.sign = f.side == Side::above ? 1.0 : -1.0;
            g.gap = f.gap;
            g.from = f.from * s.length;
            g.to = f.to * s.length;
            g.width = section_at(s, 0.5 * (g.from + g.to)).width;
            g.ends_on_contact = f.on_layer;
            SpanQuadrature q = span_quadrature(s, src.bending_position, g.from, g.to, kFilmGaussPoints);
            if (q.dofs.empty()) continue;
            // The narrow-beam film damps each length by mu_eff w^3 / g^3: over another width, the
            // point's weight takes (w / w_film)^3.
            // Under release holes the gas also leaves through them: each point takes its section's.
            std::vector<FilmPerforation> holes;
            for (PadPoint& p : q.points) {
                const SectionResultants& here = section_at(s, p.x);
                const double ratio = here.width / g.width;
                if (ratio != 1.0) p.weight *= ratio * ratio * ratio;
                if (!here.holes) continue;
                if (holes.empty()) holes.resize(q.points.size());
                holes[static_cast<std::size_t>(&p - q.points.data())] = {
                    here.holes->size, here.holes->pitch, here.holes->shape == HoleShape::circle, here.thickness,
                    here.width};
            }
            out.push_back({std::make_shared<const SqueezeFilm>(f.name, std::move(q.dofs), std::move(q.points), g,
                                                               gas_of(*c.air), std::move(holes)),
                           f.entry});
        }
        return out;
    }
};

}  // namespace

const ElementFamily& squeeze_films() {
    static const SqueezeFilms family;
    return family;
}

std::vector<FilmRegime> film_regimes(const Case& c, double omega) {
    std::vector<FilmRegime> out;
    for (const FilmSpan& f : film_spans(c)) {
        const FilmGas gas = gas_of(*c.air);
        FilmRegime r;
        r.name = f.name;
        r.gap = f.gap;
        r.knudsen = gas.mean_free_path / f.gap;
        r.viscosity_ratio = 1.0 / veijola_factor(r.knudsen);
        // The widest section the film faces; under release holes (the section at the span's middle) the
        // film's spring-to-damping ratio falls with its damping, so the squeeze number takes their factor.
        double width = widest_under(c, f.from, f.to);
        double factor = 1.0;
        if (!c.beam.sections.empty()) {
            const SectionResultants sec = section_resultants(c, section_index_at(c.beam, 0.5 * (f.from + f.to)));
            if (sec.holes) {
                const FilmCoefficient solid = film_coefficient(gas, width, f.gap);
                factor = perforation_factor({sec.holes->size, sec.holes->pitch, sec.holes->shape == HoleShape::circle,
                                             sec.thickness, width},
                                            gas, f.gap, solid.dc / solid.c)
                             .value;
            }
        }
        r.squeeze_number = squeeze_number(gas, width, f.gap, omega, c.air->pressure) * factor;
        out.push_back(std::move(r));
    }
    return out;
}

}  // namespace vi
