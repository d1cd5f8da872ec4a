#pragma once
// Base64 (RFC 4648, with padding), for images embedded in a self-contained HTML report. Written by
// hand: twenty lines, where a library (OpenSSL, for one function) would be a new dependency.

#include <string>
#include <string_view>

namespace vi {

std::string base64_encode(std::string_view bytes);

}  // namespace vi
