// A sweep file (docs/sweeps.md): a user's own study as YAML — cases × combinations × ranges of
// case keys — expanded into a fixed list of independent runs. Every value is validated by the
// case loader, as `rotbeam run --set KEY=VALUE` would validate it, before any run is made; a
// problem is ONE InputError line `FILE:LINE: KEY: problem`.
#pragma once

#include <string>
#include <vector>

namespace rotbeam::cli {

// The most runs a sweep file may expand to (docs/sweeps.md): every run's case is loaded at
// planning (1 000 roll-up runs: 3.2 s of CPU), in every shard and in merge; the suite has ~130.
inline constexpr long kMaxSweepRuns = 10000;

// One run of a sweep: a case, a combination, and one value of every swept key.
struct SweepRun {
    std::string case_name, case_path;
    std::string formulation, rotation;
    std::string interpolation, wm_map;  // empty: the case's own
    std::vector<std::string> values;    // one per Sweep::keys, as `--set KEY=VALUE` text
    double modelled_seconds = 0.0;      // the cost model's expected time (runs/run_cost.hpp)
    // The case-file overrides after the formulation and rotation: interpolation, wm_map, keys.
    std::vector<std::string> overrides(const std::vector<std::string>& keys) const;
};

struct Sweep {
    std::string file;               // the sweep file, as given
    std::string name;               // names the run files and the table
    std::string folder;             // output.folder (default: sweep-NAME)
    bool zip = false;               // combine: zip (default: product)
    bool all_steps = false;         // output.steps: all (default: last) in index.md
    std::vector<std::string> keys;  // the swept case keys, in file order
    std::vector<SweepRun> runs;     // in expansion order
};

// Reads and expands the sweep file at `path`. Relative case paths are read from its folder.
Sweep read_sweep(const std::string& path);

// The same from text in memory; `file` names it in messages, `base_dir` resolves case paths.
Sweep read_sweep_text(const std::string& text, const std::string& file,
                      const std::string& base_dir);

}  // namespace rotbeam::cli
