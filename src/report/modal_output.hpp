#pragma once
// Modal results as JSON (stable field names), a readable text table and CSV files.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "modal/support_scan.hpp"
#include "io/csv_writer.hpp"
#include "io/output_files.hpp"
#include "modal/modal_analysis.hpp"

namespace vi {

// {"case_name", "dofs", "unsupported": {"bending", "axial"}, "supported": {"bending", "axial", "ratios"}, ...}
nlohmann::json modal_study_json(const ModalStudy& study);

// Plain-text tables of frequencies, ratios, nodal points and peaks for a terminal.
std::string modal_study_text(const ModalStudy& study);

// Sampled bending shapes: x_over_l, x_m, then per mode v_<i>_per_sqrt_kg and theta_<i>_per_m_sqrt_kg
// (mass normalised, SI).
CsvTable mode_shapes_csv(const ModalResult& result, int per_element);

// Every file `modes --out` writes: modes.json, frequencies.csv, shapes_*.csv.
OutputFiles modal_study_files(const ModalStudy& study);

// One row per support position: x0_over_l, ratio_<i> = omega_i/omega_in, f_supported_<i>_hz.
CsvTable support_scan_csv(const std::vector<SupportScanPoint>& points, int count);

}  // namespace vi
