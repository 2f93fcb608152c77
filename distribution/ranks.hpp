// A job run by the ranks of `mpirun -np N rotbeam-mpi suite|study|sweep ...`
// (docs/distributed-runs.md, "MPI"). Two implementations, one per program, chosen at link time
// (cases/runner/CMakeLists.txt): ranks_mpi.cpp in rotbeam-mpi; ranks_single.cpp in rotbeam, which
// refuses to run under mpirun with more than one rank, because N copies of the whole job writing
// into one folder would be N times the work for one output.
#pragma once

#include <string>

#include "distribution/distributed.hpp"

namespace rotbeam::cli {

// The number of ranks mpirun started this process among, from the launcher's environment
// (OMPI_COMM_WORLD_SIZE, PMI_SIZE); 1 when not started by mpirun. A build without MPI throws
// InputError ("COMMAND: ...") when that number is above 1.
int launched_ranks(const std::string& command);

// Every unit of the job made by the ranks together, longest expected first, handed out one at a
// time on request (dynamic load balancing): rank 0 serves the requests from a thread of its own
// while its `settings.jobs` worker threads take units too, so no rank only hands out work. The
// units are made into DIR/.rotbeam-ranks (a shard folder 1/1; DIR = settings.dir, a folder every
// rank sees), the timed ones (speed-accuracy) by rank 0 after all others have finished, while the
// other ranks wait without spinning; then rank 0 merges it into DIR (the output of one process)
// and removes it. Started again after a crash, the ranks keep the units already made. Returns the
// exit code of this rank (rank 0: the merge's). A rank that fails aborts every rank (MPI_Abort)
// with the exit code main would give (2 input, 4 output, 3 other), after one line naming it.
int run_over_ranks(const Job& job, const ShardSettings& settings);

// "MPI: <library version>" or "MPI: none" (for `rotbeam --version`).
std::string mpi_description();

}  // namespace rotbeam::cli
