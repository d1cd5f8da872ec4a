#include "report/modal_output.hpp"

#include "modal/shape_sampling.hpp"
#include "model/number_format.hpp"

#include <cstdio>
#include <limits>
#include <string>

namespace vi {
namespace {

nlohmann::json peaks_json(const std::vector<ShapePeak>& peaks) {
    nlohmann::json a = nlohmann::json::array();
    for (const ShapePeak& p : peaks) a.push_back({{"x", p.x}, {"amplitude", p.amplitude}});
    return a;
}

nlohmann::json modes_json(const std::vector<Mode>& modes, bool with_features) {
    nlohmann::json a = nlohmann::json::array();
    for (const Mode& m : modes) {
        nlohmann::json j{{"mode", m.number}, {"frequency_hz", m.frequency_hz}, {"omega_rad_s", m.omega}};
        if (with_features) {
            j["nodes"] = m.features.nodes;
            j["rotation_nodes"] = m.features.rotation_nodes;
            j["peaks"] = peaks_json(m.features.peaks);
            j["rotation_peaks"] = peaks_json(m.features.rotation_peaks);
        }
        a.push_back(std::move(j));
    }
    return a;
}

const char* model_name(SupportModel m) {
    switch (m) {
        case SupportModel::pin: return "pin";
        case SupportModel::spring: return "spring";
        case SupportModel::none: break;
    }
    return "none";
}

std::string list_text(const std::vector<double>& xs) {
    std::string s;
    for (double x : xs) {
        if (!s.empty()) s += ' ';
        s += formatted("%.4f", x);
    }
    return s.empty() ? "-" : s;
}

std::string peaks_text(const std::vector<ShapePeak>& ps) {
    std::string s;
    for (const ShapePeak& p : ps) {
        if (!s.empty()) s += ' ';
        s += formatted("%.4f", p.x);
        s += formatted("(%.3f)", p.amplitude);
    }
    return s.empty() ? "-" : s;
}

void bending_table(std::string& out, const std::vector<Mode>& modes, const std::vector<double>* ratios) {
    out += "  mode   frequency [Hz]    omega [rad/s]   ratio to 1st";
    out += ratios ? "   w_i/w_in\n" : "\n";
    for (std::size_t i = 0; i < modes.size(); ++i) {
        const Mode& m = modes[i];
        out += formatted("  %4.0f", m.number) + formatted("  %15.6e", m.frequency_hz) + formatted("  %15.6e", m.omega) +
               formatted("  %13.5f", m.omega / modes.front().omega);
        if (ratios && i < ratios->size()) out += formatted("  %9.5f", (*ratios)[i]);
        out += "\n";
    }
    out += "  mode   nodal points of v (x/l) | of theta (x/l)\n";
    for (const Mode& m : modes) {
        out += formatted("  %4.0f   ", m.number) + list_text(m.features.nodes) + " | " +
               list_text(m.features.rotation_nodes) + "\n";
    }
    out += "  mode   peaks of |v|: x/l(amplitude) | peaks of |theta|\n";
    for (const Mode& m : modes) {
        out += formatted("  %4.0f   ", m.number) + peaks_text(m.features.peaks) + " | " +
               peaks_text(m.features.rotation_peaks) + "\n";
    }
}

}  // namespace

nlohmann::json modal_study_json(const ModalStudy& study) {
    nlohmann::json j;
    j["case_name"] = study.case_name;
    j["dofs"] = study.unsupported.dofs;
    j["unsupported"] = {{"dofs", study.unsupported.dofs},
                        {"bending", modes_json(study.unsupported.bending, true)},
                        {"axial", modes_json(study.unsupported.axial, false)}};
    j["supported"] = {{"support_model", model_name(study.support_model)},
                      {"dofs", study.supported.dofs},
                      {"bending", modes_json(study.supported.bending, true)},
                      {"axial", modes_json(study.supported.axial, false)},
                      {"ratios", study.ratios}};
    if (study.released) {
        const ReleasedCurl& r = *study.released;
        const double l = study.unsupported.system.length;
        std::vector<double> at;
        for (double x : r.x) at.push_back(x / l);
        j["released"] = {{"tip_lift_m", r.tip_lift}, {"largest_lift_m", r.largest}, {"largest_at_x_over_l", r.largest_at},
                         {"nodes", {{"x_over_l", at}, {"v_m", r.v}, {"theta_rad", r.theta}}}};
    }
    j["units"] = {{"frequency_hz", "Hz"},
                  {"omega_rad_s", "rad/s"},
                  {"nodes", "x/l"},
                  {"amplitude", "v*sqrt(rho*A*l) or theta*l*sqrt(rho*A*l) of the mass-normalised shape"}};
    return j;
}

std::string modal_study_text(const ModalStudy& study) {
    std::string out;
    out += "Unsupported beam (" + std::to_string(study.unsupported.dofs) + " free DOF): bending modes\n";
    bending_table(out, study.unsupported.bending, nullptr);
    out += "Unsupported beam: axial modes\n  mode   frequency [Hz]    omega [rad/s]\n";
    for (const Mode& m : study.unsupported.axial) {
        out += formatted("  %4.0f", m.number) + formatted("  %15.6e", m.frequency_hz) + formatted("  %15.6e", m.omega) + "\n";
    }
    if (study.released) {
        const ReleasedCurl& r = *study.released;
        out += "Released shape at rest (the curl): tip lift " + significant(r.tip_lift * 1e6, 5) + " um, largest lift " +
               significant(r.largest * 1e6, 5) + " um at x/l = " + significant(r.largest_at, 4) +
               " (modes are about the straight beam; gaps are measured from it)\n";
    }
    if (!study.supported.bending.empty()) {
        out += std::string("Supported beam (supports as ") + model_name(study.support_model) + "): bending modes\n";
        bending_table(out, study.supported.bending, &study.ratios);
    } else {
        out += "Supported beam: the case has no support\n";
    }
    return out;
}

CsvTable mode_shapes_csv(const ModalResult& result, int per_element) {
    CsvTable t;
    t.header = {"x_over_l", "x_m"};
    std::vector<SampledShape> shapes;
    for (const Mode& m : result.bending) {
        // Mass normalised (phi^T M phi = 1 with M in kg and kg m^2): v in 1/sqrt(kg), theta in 1/(m sqrt(kg)).
        t.header.push_back("v_" + std::to_string(m.number) + "_per_sqrt_kg");
        t.header.push_back("theta_" + std::to_string(m.number) + "_per_m_sqrt_kg");
        shapes.push_back(sample_shape(result.system, m.shape, per_element));
    }
    if (shapes.empty()) return t;
    const double l = result.system.length;
    for (std::size_t k = 0; k < shapes.front().x.size(); ++k) {
        std::vector<double> row{shapes.front().x[k] / l, shapes.front().x[k]};
        for (const SampledShape& s : shapes) {
            row.push_back(s.v[k]);
            row.push_back(s.theta[k]);
        }
        t.add_row(std::move(row));
    }
    return t;
}

OutputFiles modal_study_files(const ModalStudy& study) {
    OutputFiles files;
    files["modes.json"] = modal_study_json(study).dump(2) + "\n";
    CsvTable freq;
    freq.header = {"mode", "unsupported_hz", "unsupported_rad_s", "supported_hz", "supported_rad_s", "ratio"};
    for (std::size_t i = 0; i < study.unsupported.bending.size(); ++i) {
        const Mode& u = study.unsupported.bending[i];
        const bool has = i < study.supported.bending.size();
        const double nan = std::numeric_limits<double>::quiet_NaN();
        freq.add_row({static_cast<double>(u.number), u.frequency_hz, u.omega,
                      has ? study.supported.bending[i].frequency_hz : nan,
                      has ? study.supported.bending[i].omega : nan, has ? study.ratios[i] : nan});
    }
    files["frequencies.csv"] = freq.str();
    files["shapes_unsupported.csv"] = mode_shapes_csv(study.unsupported, 8).str();
    if (study.released) {
        CsvTable shape;
        shape.header = {"x_over_l", "x_m", "v_m", "theta_rad"};
        const ReleasedCurl& r = *study.released;
        for (std::size_t k = 0; k < r.x.size(); ++k) {
            shape.add_row({r.x[k] / study.unsupported.system.length, r.x[k], r.v[k], r.theta[k]});
        }
        files["released_shape.csv"] = shape.str();
    }
    if (!study.supported.bending.empty()) files["shapes_supported.csv"] = mode_shapes_csv(study.supported, 8).str();
    return files;
}

CsvTable support_scan_csv(const std::vector<SupportScanPoint>& points, int count) {
    CsvTable t;
    t.header = {"x0_over_l"};
    for (int i = 1; i <= count; ++i) t.header.push_back("ratio_" + std::to_string(i));
    for (int i = 1; i <= count; ++i) t.header.push_back("f_supported_" + std::to_string(i) + "_hz");
    for (const SupportScanPoint& p : points) {
        std::vector<double> row{p.position};
        for (int i = 0; i < count; ++i) row.push_back(p.study.ratios.at(static_cast<std::size_t>(i)));
        for (int i = 0; i < count; ++i) row.push_back(p.study.supported.bending.at(static_cast<std::size_t>(i)).frequency_hz);
        t.add_row(std::move(row));
    }
    return t;
}

}  // namespace vi
