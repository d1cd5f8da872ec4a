#pragma once
// Measured features of a device (its first natural frequency, quality factor, period of free
// impact vibrations, pull-in voltage, ...), each with its uncertainty: CSV with a header row naming
// the columns name, value and sigma (any order), one feature a row (docs/calibration.md).

#include <cstddef>
#include <string>
#include <vector>

namespace vi {

struct MeasuredFeature {
    std::string name;    // one of feature_names()
    double value = 0.0;  // [SI, the unit in the name]
    double sigma = 0.0;  // its standard uncertainty (> 0), same unit
    std::size_t line = 0;
};

struct MeasuredFeatures {
    std::string file;
    std::vector<MeasuredFeature> features;
};

// The names a features file may use, in the order they are documented.
const std::vector<std::string>& feature_names();

// Reads `path`. Throws InputError("FILE:LINE: reason") for an unreadable or empty file, a missing or
// repeated column, a name not among feature_names() or given twice, a value that is not a finite
// number, a sigma not positive.
MeasuredFeatures read_measured_features(const std::string& path);

}  // namespace vi
