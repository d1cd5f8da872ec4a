#include "support/mpi_launch.hpp"

#include <cstdlib>

namespace vi::test {
namespace {

// "NAME=<the variable's value>:<more>".
std::string extended(const char* name, const std::string& more) {
    const char* now = std::getenv(name);
    return std::string(name) + "=" + (now && *now ? std::string(now) + ":" : std::string()) + more;
}

}  // namespace

std::string find_mpirun() { return find_on_path("mpirun"); }

std::string mpi_unavailable() {
    if (!VI_EXE_HAS_MPI) return "vibroimpact was built without MPI (libopenmpi-dev missing)";
    if (find_mpirun().empty()) return "mpirun is not on PATH (scripts/install-deps installs openmpi-bin)";
    return "";
}

std::vector<std::string> mpi_argv(const std::vector<std::string>& args, int ranks) {
    std::vector<std::string> argv{find_mpirun(), "--allow-run-as-root", "--oversubscribe", "-n", std::to_string(ranks),
                                  vibroimpact_path()};
    argv.insert(argv.end(), args.begin(), args.end());
    return argv;
}

std::vector<std::string> mpi_env() {
    return {extended("LSAN_OPTIONS", "suppressions=" + source_path("tests/lsan-openmpi.supp")),
            extended("ASAN_OPTIONS", "fast_unwind_on_malloc=0")};
}

CommandResult run_mpi(const std::vector<std::string>& args, double limit_s) {
    return run_program(mpi_argv(args), mpi_env(), limit_s);
}

}  // namespace vi::test
