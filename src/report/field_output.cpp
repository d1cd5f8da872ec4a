#include "report/field_output.hpp"

#include <stdexcept>

namespace vi {

BeamField beam_field(const System& s, const TimeHistory& h) {
    BeamField f;
    f.x = s.mesh.x;
    const std::size_t nodes = f.x.size();
    for (std::size_t k = 0; k < h.field_q.size(); ++k) {
        const std::vector<double>& q = h.field_q[k];
        if (q.size() != s.bending.size()) throw std::invalid_argument("beam_field: a frame is not over the bending DOFs");
        BeamFrame frame;
        frame.t = h.t.at(h.field_sample.at(k));
        frame.v.assign(nodes, 0.0);
        frame.theta.assign(nodes, 0.0);
        for (std::size_t i = 0; i < q.size(); ++i) {
            const int global = s.free_dofs[static_cast<std::size_t>(s.bending[i])];
            const auto node = static_cast<std::size_t>(global / 3);
            (global % 3 == 1 ? frame.v : frame.theta)[node] = q[i];
        }
        f.frames.push_back(std::move(frame));
    }
    return f;
}

CsvTable field_csv(const BeamField& f) {
    CsvTable t;
    t.header = {"frame", "t_s", "x_m", "v_m", "theta_rad"};
    for (std::size_t k = 0; k < f.frames.size(); ++k) {
        const BeamFrame& fr = f.frames[k];
        for (std::size_t i = 0; i < f.x.size(); ++i) t.add_row({static_cast<double>(k), fr.t, f.x[i], fr.v[i], fr.theta[i]});
    }
    return t;
}

OutputFiles field_files(const BeamField& f) {
    if (f.frames.empty()) return {};
    OutputFiles files = vtk_beam_series("field", f.x, f.frames);
    files["field.csv"] = field_csv(f).str();
    return files;
}

}  // namespace vi
