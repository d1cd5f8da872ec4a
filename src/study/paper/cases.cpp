#include "study/paper/cases.hpp"

#include <filesystem>

#include "study/paper/examples.hpp"
#include "io/case_reader.hpp"
#include "model/input_error.hpp"

namespace vi {
namespace {

Case read_builtin(const char* name) {
    for (const EmbeddedFile& f : paper_example_files()) {
        if (f.name == name) return read_case_text(std::string(f.text), std::string("examples/paper/") + name);
    }
    throw InputError(std::string("examples/paper/") + name + ": not built into this program (rebuild it)");
}

// "KEY: reason" placed at the key's line; a key the file lacks gets the file name alone.
void require(bool ok, const Case& c, const std::string& what) {
    if (ok) return;
    const InputError placed = locate_in_case(c, InputError(what));
    if (std::string(placed.what()).rfind(c.origin.file, 0) == 0) throw placed;
    throw InputError(c.origin.file + ": " + what);
}

}  // namespace

PaperCases load_paper_cases(const std::string& folder) {
    PaperCases p;
    auto read = [&](const char* name) {
        return folder.empty() ? read_builtin(name) : read_case_file((std::filesystem::path(folder) / name).string());
    };
    p.cantilever = read(kCantileverFile);
    p.free_impact = read(kFreeImpactFile);
    p.prestress = read(kPrestressFile);
    p.source = folder.empty() ? "built-in examples/paper/" : folder;
    require(!p.cantilever.supports.empty(), p.cantilever, "supports: the modal study moves supports[0]; give one");
    for (const Case* c : {&p.free_impact, &p.prestress}) {
        require(!c->supports.empty(), *c, "supports: the study moves or prestresses supports[0]; give one");
        require(c->solver.horizon > 0.0, *c, "solver.horizon: required for the transients of the study");
        require(c->supports.front().side == Side::below, *c, "supports[0].side: the study expects a support below");
    }
    return p;
}

}  // namespace vi
