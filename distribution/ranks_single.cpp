// rotbeam built without MPI (ranks.hpp): one rank, and a clear refusal when mpirun starts several.
#include <cstdlib>

#include "core/errors.hpp"
#include "distribution/ranks.hpp"

namespace rotbeam::cli {

int launched_ranks(const std::string& command) {
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"}) {
        const char* value = std::getenv(name);
        if (value && std::atoi(value) > 1) {
            throw InputError(
                command + ": started by mpirun with " + value +
                " ranks, but this rotbeam was built without MPI: every rank would "
                "run the whole job; use rotbeam-mpi (built beside rotbeam when MPI is found), "
                "or --shard I/N "
                "(docs/distributed-runs.md)");
        }
    }
    return 1;
}

int run_over_ranks(const Job&, const ShardSettings&) {
    throw InputError("rotbeam: built without MPI: no ranks to run on");
}

std::string mpi_description() { return "MPI: none (rotbeam-mpi has it)"; }

}  // namespace rotbeam::cli
