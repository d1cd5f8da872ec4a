#include "io/output_files.hpp"

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <vector>

namespace vi {

void write_output_files(const std::string& dir, const OutputFiles& files) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const bool existed = fs::exists(dir, ec);
    fs::create_directories(dir, ec);
    if (ec) throw std::runtime_error(dir + ": cannot create folder: " + ec.message());

    std::vector<fs::path> temps;
    auto cleanup = [&]() {
        std::error_code ignore;
        for (const auto& t : temps) fs::remove(t, ignore);
        if (!existed) fs::remove(dir, ignore);
    };
    for (const auto& [name, text] : files) {
        const fs::path tmp = fs::path(dir) / ("." + name + ".partial");
        temps.push_back(tmp);
        std::ofstream out(tmp, std::ios::binary);
        out << text;
        out.close();
        if (!out) {
            cleanup();
            throw std::runtime_error((fs::path(dir) / name).string() + ": cannot write file");
        }
    }
    for (const auto& [name, text] : files) {
        fs::rename(fs::path(dir) / ("." + name + ".partial"), fs::path(dir) / name, ec);
        if (ec) {
            cleanup();
            throw std::runtime_error((fs::path(dir) / name).string() + ": cannot write file: " + ec.message());
        }
    }
}

}  // namespace vi
