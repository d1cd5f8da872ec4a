#include "io/vtk_series.hpp"

#include <cstdio>
#include <stdexcept>


namespace vi {
namespace {

// Round-trip text of a double (17 significant digits), as the CSV files write them.
std::string num(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

std::string frame_name(const std::string& stem, std::size_t k) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "_%05zu.vtu", k);
    return stem + "/" + stem + buf;
}

// A DataArray of `components` Float64 values per tuple, given in order.
void data_array(std::string& out, const std::string& name, int components, const std::vector<double>& values) {
    out += "        <DataArray type=\"Float64\" Name=\"" + name + "\" NumberOfComponents=\"" + std::to_string(components) +
           "\" format=\"ascii\">\n          ";
    for (std::size_t i = 0; i < values.size(); ++i) out += num(values[i]) + (i + 1 < values.size() ? " " : "\n");
    out += "        </DataArray>\n";
}

std::string vtu(const std::vector<double>& x, const BeamFrame& f) {
    const std::size_t n = x.size();
    std::vector<double> points, displacement;
    for (std::size_t i = 0; i < n; ++i) {
        points.insert(points.end(), {x[i], 0.0, 0.0});
        displacement.insert(displacement.end(), {0.0, f.v[i], 0.0});
    }
    std::string out = "<?xml version=\"1.0\"?>\n"
                      "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
                      "  <UnstructuredGrid>\n    <FieldData>\n"
                      "      <DataArray type=\"Float64\" Name=\"TimeValue\" NumberOfTuples=\"1\" format=\"ascii\">" +
                      num(f.t) + "</DataArray>\n    </FieldData>\n";
    out += "    <Piece NumberOfPoints=\"" + std::to_string(n) + "\" NumberOfCells=\"" + std::to_string(n - 1) + "\">\n";
    out += "      <PointData Vectors=\"displacement\" Scalars=\"deflection_m\">\n";
    data_array(out, "displacement", 3, displacement);
    data_array(out, "deflection_m", 1, f.v);
    data_array(out, "rotation_rad", 1, f.theta);
    out += "      </PointData>\n      <Points>\n";
    data_array(out, "coordinates_m", 3, points);
    out += "      </Points>\n      <Cells>\n";
    std::string conn, offsets, types;
    for (std::size_t e = 0; e + 1 < n; ++e) {
        conn += std::to_string(e) + " " + std::to_string(e + 1) + (e + 2 < n ? " " : "");
        offsets += std::to_string(2 * (e + 1)) + (e + 2 < n ? " " : "");
        types += std::string("3") + (e + 2 < n ? " " : "");  // VTK_LINE
    }
    out += "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n          " + conn + "\n        </DataArray>\n";
    out += "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n          " + offsets + "\n        </DataArray>\n";
    out += "        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n          " + types + "\n        </DataArray>\n";
    out += "      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
    return out;
}

}  // namespace

OutputFiles vtk_beam_series(const std::string& stem, const std::vector<double>& x, const std::vector<BeamFrame>& frames) {
    if (x.size() < 2) throw std::invalid_argument("vtk_beam_series: a beam needs at least two nodes");
    OutputFiles files;
    std::string pvd = "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
                      "  <Collection>\n";
    for (std::size_t k = 0; k < frames.size(); ++k) {
        const BeamFrame& f = frames[k];
        if (f.v.size() != x.size() || f.theta.size() != x.size()) {
            throw std::invalid_argument("vtk_beam_series: frame " + std::to_string(k) + " does not have one value per node");
        }
        const std::string name = frame_name(stem, k);
        files[name] = vtu(x, f);
        pvd += "    <DataSet timestep=\"" + num(f.t) + "\" part=\"0\" file=\"" + name + "\"/>\n";
    }
    pvd += "  </Collection>\n</VTKFile>\n";
    files[stem + ".pvd"] = pvd;
    return files;
}

}  // namespace vi
