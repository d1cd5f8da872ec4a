#include "support/run_command.hpp"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace vi::test {
namespace {

std::string slurp(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

}  // namespace

CommandResult run_vibroimpact(const std::vector<std::string>& args) {
    const std::filesystem::path dir = make_temp_dir();
    const std::string out_path = (dir / "stdout").string();
    const std::string err_path = (dir / "stderr").string();

    std::vector<std::string> argv_store{VI_EXE};
    argv_store.insert(argv_store.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (auto& a : argv_store) argv.push_back(a.data());
    argv.push_back(nullptr);

    const pid_t pid = fork();
    if (pid < 0) throw std::runtime_error("fork failed");
    if (pid == 0) {
        const int fo = open(out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const int fe = open(err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const int fi = open("/dev/null", O_RDONLY);
        if (fo < 0 || fe < 0 || fi < 0) _exit(127);
        dup2(fi, 0);
        dup2(fo, 1);
        dup2(fe, 2);
        execv(argv[0], argv.data());
        _exit(127);
    }
    int status = 0;
    waitpid(pid, &status, 0);
    CommandResult r;
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    r.out = slurp(out_path);
    r.err = slurp(err_path);
    std::filesystem::remove_all(dir);
    return r;
}

std::string source_path(const std::string& relative) {
    return (std::filesystem::path(VI_SOURCE_DIR) / relative).string();
}

std::string make_temp_dir() {
    std::string templ = (std::filesystem::temp_directory_path() / "vi_test_XXXXXX").string();
    if (mkdtemp(templ.data()) == nullptr) throw std::runtime_error("mkdtemp failed");
    return templ;
}

}  // namespace vi::test
