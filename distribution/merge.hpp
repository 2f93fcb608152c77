// The shard folders of one job (`suite`, `study` or `sweep` with --shard I/N) merged into the
// output of one uninterrupted run (docs/distributed-runs.md, "Merge"); `rotbeam merge` and rank 0
// of an MPI run use it.
#pragma once

#include <string>
#include <vector>

namespace rotbeam::cli {

// Exit code of `rotbeam merge` when runs are missing from the shard folders (nothing is written).
constexpr int kExitIncomplete = 5;

// Merges shard folders of one job into `out`: 0, kExitIncomplete (missing units listed on
// stderr, nothing written), InputError naming a damaged file.
int merge_shard_folders(const std::vector<std::string>& dirs, const std::string& out);

}  // namespace rotbeam::cli
