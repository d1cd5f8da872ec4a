#include "sweep/ranks.hpp"

#include <cstdlib>

namespace vi {

std::vector<std::size_t> share_of_rank(const std::vector<std::size_t>& todo, int rank, int size) {
    std::vector<std::size_t> mine;
    for (std::size_t k = static_cast<std::size_t>(rank); k < todo.size(); k += static_cast<std::size_t>(size)) {
        mine.push_back(todo[k]);
    }
    return mine;
}

bool launched_by_mpi() {
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"}) {
        if (std::getenv(name)) return true;
    }
    return false;
}

int launcher_rank() {
    for (const char* name : {"OMPI_COMM_WORLD_RANK", "PMI_RANK", "PMIX_RANK"}) {
        if (const char* v = std::getenv(name)) return std::atoi(v);
    }
    return 0;
}

}  // namespace vi
