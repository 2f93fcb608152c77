// A sweep file's runs as the suite's list of independent runs (docs/sweeps.md, "Runs and
// distribution").
#include "distribution/sweep_runs.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "runs/shards.hpp"

namespace rotbeam::cli {

namespace fs = std::filesystem;

std::string sweep_file_key(const std::string& path) { return stable_hash(read_text_file(path)); }

std::vector<PlannedRun> plan_sweep_runs(const Sweep& sweep, const std::string& out_dir) {
    std::vector<PlannedRun> runs;
    std::vector<std::pair<std::string, std::string>> texts;  // case path → text
    for (size_t i = 0; i < sweep.runs.size(); ++i) {
        const SweepRun& s = sweep.runs[i];
        PlannedRun run{s.case_name, s.case_path, s.rotation, s.formulation};
        run.overrides = s.overrides(sweep.keys);
        run.as_run = true;
        char number[24];
        std::snprintf(number, sizeof number, "%04zu", i + 1);
        run.output = (fs::path(out_dir) / "runs" /
                      (sweep.name + "-" + number + "_" + s.case_name + "_" + s.rotation + "_" +
                       s.formulation + ".json"))
                         .string();
        auto text = std::find_if(texts.begin(), texts.end(),
                                 [&](const auto& t) { return t.first == s.case_path; });
        if (text == texts.end()) {
            texts.emplace_back(s.case_path, read_text_file(s.case_path));
            text = texts.end() - 1;
        }
        run.key = planned_run_key(text->second, run);
        run.modelled_seconds = s.modelled_seconds;
        runs.push_back(std::move(run));
    }
    return runs;
}

}  // namespace rotbeam::cli
