#include "model/number_format.hpp"

#include <cstdio>

namespace vi {

std::string significant(double v, int digits) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*g", digits, v);
    return buf;
}

std::string decimals(double v, int places) {
    char buf[400];  // "%.*f" of 1e308 has 309 digits before the point
    std::snprintf(buf, sizeof buf, "%.*f", places, v);
    return buf;
}

std::string formatted(const char* format, double v) {
    char buf[128];
    std::snprintf(buf, sizeof buf, format, v);
    return buf;
}

}  // namespace vi
