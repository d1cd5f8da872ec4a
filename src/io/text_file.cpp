#include "io/text_file.hpp"

#include <cerrno>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <system_error>

namespace vi {

std::string one_line(std::string s) {
    std::string out;
    for (const char ch : s) {
        if (ch == '\n') {
            out += "\\n";
        } else if (ch == '\r') {
            out += "\\r";
        } else {
            out += ch;
        }
    }
    return out;
}

// The whole file as text; nullopt with the reason ("No such file or directory") when unreadable.
// Only regular files and pipes (a case from `<(...)`), and at most kMaxTextBytes of them: a device
// (/dev/zero) or a huge file named as a case or load table would otherwise be read without end.
std::optional<std::string> file_text(const std::string& path, std::string& reason) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) {
        reason = "it is a directory";
        return std::nullopt;
    }
    const auto status = std::filesystem::status(path, ec);
    if (!ec && std::filesystem::exists(status) && !std::filesystem::is_regular_file(status) &&
        !std::filesystem::is_fifo(status)) {
        reason = "not a regular file or a pipe";
        return std::nullopt;
    }
    errno = 0;
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        const int err = errno;
        reason = err != 0 ? std::generic_category().message(err) : "cannot open";
        return std::nullopt;
    }
    std::string text;
    char buf[1 << 16];
    while (in.read(buf, sizeof buf) || in.gcount() > 0) {
        text.append(buf, static_cast<std::size_t>(in.gcount()));
        if (text.size() > kMaxTextBytes) {
            reason = "larger than " + std::to_string(kMaxTextBytes >> 20) + " MiB";
            return std::nullopt;
        }
    }
    if (in.bad()) {
        reason = "read error";
        return std::nullopt;
    }
    return text;
}

std::string trimmed(std::string_view s) {
    const auto b = s.find_first_not_of(" \t\r");
    if (b == std::string_view::npos) return {};
    return std::string(s.substr(b, s.find_last_not_of(" \t\r") - b + 1));
}

}  // namespace vi
