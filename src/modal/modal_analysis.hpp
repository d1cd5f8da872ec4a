#pragma once
// Modal analysis of a case: bending and axial modes of the unsupported and the supported beam.

#include <Eigen/Dense>
#include <optional>
#include <string>
#include <vector>

#include "fem/system.hpp"
#include "modal/released_curl.hpp"
#include "modal/shape_points.hpp"
#include "model/case.hpp"

namespace vi {

// One natural mode with its shape features (docs/model.md §§8-9).
struct Mode {
    int number = 0;            // 1-based within its family (bending or axial)
    double omega = 0.0;        // circular frequency [rad/s]
    double frequency_hz = 0.0; // [Hz]
    Eigen::VectorXd shape;     // global DOF vector, mass normalised (phi^T M phi = 1) [1/sqrt(kg)]
    ShapeFeatures features;
};

// Modes of one System: bending (v, theta) and axial (u) apart, since they decouple.
struct ModalResult {
    System system;             // the model the modes belong to (mesh and DOF maps for sampling)
    int dofs = 0;              // free DOFs of the system
    std::vector<Mode> bending;
    std::vector<Mode> axial;
};

// Modes of a built system: the lowest `count` of each family.
ModalResult analyse_modes(const System& s, int count);

// The unsupported beam, the supported beam (supports as pins or as springs), and the ratios
// omega_i / omega_in of supported over unsupported bending frequencies.
struct ModalStudy {
    std::string case_name;  // the case's name (its `name` key, else its file's stem)
    SupportModel support_model = SupportModel::pin;
    ModalResult unsupported;
    ModalResult supported;
    std::vector<double> ratios;
    // The beam's released (curled) shape at rest, about which it vibrates; none when nothing curls it.
    std::optional<ReleasedCurl> released;
};

// Runs both analyses; `count` bending (and axial) modes each. support_model is pin or spring.
ModalStudy modal_study(const Case& c, int count, SupportModel support_model);

}  // namespace vi
