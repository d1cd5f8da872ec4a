#include "io/output_files.hpp"

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <vector>

namespace vi {
namespace {

// A file's temporary name beside it: a name with folders ("field/beam_00000.vtu") keeps them.
std::filesystem::path partial_path(const std::string& dir, const std::string& name) {
    const std::filesystem::path p = std::filesystem::path(dir) / name;
    std::string temp_name = ".";  // appended, not "." + string: GCC 12's -Wrestrict misfires there
    temp_name += p.filename().string();
    temp_name += ".partial";
    return p.parent_path() / temp_name;
}

}  // namespace

void write_output_files(const std::string& dir, const OutputFiles& files) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const bool existed = fs::exists(dir, ec);
    fs::create_directories(dir, ec);
    if (ec) throw std::runtime_error(dir + ": cannot create folder: " + ec.message());

    std::vector<fs::path> temps;
    std::vector<fs::path> made;  // sub-folders this call created, deepest last
    auto cleanup = [&]() {
        std::error_code ignore;
        for (const auto& t : temps) fs::remove(t, ignore);
        for (auto m = made.rbegin(); m != made.rend(); ++m) fs::remove(*m, ignore);
        if (!existed) fs::remove(dir, ignore);
    };
    for (const auto& [name, text] : files) {
        const fs::path tmp = partial_path(dir, name);
        if (!fs::exists(tmp.parent_path(), ec)) {
            fs::create_directories(tmp.parent_path(), ec);
            if (ec) {
                cleanup();
                throw std::runtime_error(tmp.parent_path().string() + ": cannot create folder: " + ec.message());
            }
            made.push_back(tmp.parent_path());
        }
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
        fs::rename(partial_path(dir, name), fs::path(dir) / name, ec);
        if (ec) {
            cleanup();
            throw std::runtime_error((fs::path(dir) / name).string() + ": cannot write file: " + ec.message());
        }
    }
}

}  // namespace vi
