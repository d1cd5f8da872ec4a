// Section 10 of docs/validation.md: electrostatic pull-in against the parallel-plate closed form and
// the cantilever's shooting solution.

#include <cmath>
#include <sstream>
#include <string>

#include "statics/pullin.hpp"
#include "io/case_reader.hpp"
#include "validation/electrostatic_references.hpp"
#include "validation/report.hpp"

namespace vi::validation_detail {

std::string section_electrostatics(const ValidationOptions& o) {
    std::ostringstream s;
    s << "## 10. Electrostatic pull-in\n\n"
      << "A rigid plate of area A = 100 um x 100 um on a spring k = 2 N/m across a gap g = 2 um "
         "(`ElectrostaticPullin.OneDegreeOfFreedomPlateMatchesTheClosedForm`): the parallel-plate closed form "
         "V_PI = sqrt(8 k g^3 / (27 eps0 A)) at a travel of g/3 (S. D. Senturia, *Microsystem Design*, Kluwer "
         "2001, section 6.4.2). Then the paper's cantilever under a full-length electrode, gap 2 um, no "
         "fringing, against the shooting solution of u'''' = lambda/(1 - u)^2 (`validation/"
         "electrostatic_references.hpp`; no code shared with the FE model): lambda = eps0 w V^2 l^4 / (2 EI g^3). "
         "Details and the model in docs/electrostatics.md.\n\n";
    Table t;
    t.header = {"case", "computed", "reference", "rel. error", "test asserts"};
    {
        const double k = 2.0, g = 2e-6, w = 100e-6, L = 100e-6;
        const PullinModel m = parallel_plate_model(k, 1e-10, g, w, L);
        const PullinResult r = trace_pullin(m);
        const double v = std::sqrt(8.0 * k * g * g * g / (27.0 * kEpsilon0 * w * L));
        if (r.pullin) {
            t.add({"1 DOF: V_PI [V]", num(r.pullin->voltage, 10), num(v, 10), err(r.pullin->voltage / v - 1.0), "< 1e-6"});
            t.add({"1 DOF: travel at pull-in / g", num(r.pullin->travel / g, 10), num(1.0 / 3.0, 10),
                   err(3.0 * r.pullin->travel / g - 1.0), "< 1e-6"});
        }
    }
    report_progress(o, "electrostatic pull-in: shooting reference");
    const double lambda = cantilever_pullin_lambda_shooting();
    for (int elements : {5, 10, 20, 40}) {
        const Case c = read_case_text("[beam]\nlength = \"117 um\"\nwidth = \"30 um\"\nthickness = \"2 um\"\nelements = " +
                                          std::to_string(elements) +
                                          "\n[material]\nyoungs_modulus = \"207 GPa\"\ndensity = \"8902 kg/m^3\"\n"
                                          "poisson_ratio = 0.31\n[[electrodes]]\nfrom = 0.0\nto = 1.0\ngap = \"2 um\"\n"
                                          "voltage = \"1 V\"\n",
                                          "cantilever.toml");
        const PullinResult r = trace_pullin(c);
        if (!r.pullin) continue;
        const double EI = c.material.effective_modulus() * c.beam.second_moment(), g = 2e-6, l = c.beam.length;
        const double fe = kEpsilon0 * c.beam.width * r.pullin->voltage * r.pullin->voltage * l * l * l * l / (2 * EI * g * g * g);
        t.add({"cantilever, m = " + std::to_string(elements) + ": lambda_PI (tip travel " +
                   fixed(r.pullin->watched_travel / g, 4) + " g)",
               num(fe, 10), num(lambda, 10), err(fe / lambda - 1.0), elements == 40 ? "< 1e-6, falling with m" : "falling with m"});
    }
    s << t.str()
      << "\nThe cantilever's error falls as h^4 (16 times per halving of the element length), as the cubic "
         "Hermite element's static error should; the tip moves 0.4465 g before it pulls in.\n\n";
    return s.str();
}

}  // namespace vi::validation_detail
