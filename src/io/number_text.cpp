#include "io/number_text.hpp"

#include <charconv>

namespace vi {

std::string round_trip_text(double v) {
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, r.ptr);
}

}  // namespace vi
