// Hand-made runs written as the suite writes its result files, for tests of write_report: the
// report reads them back through runs/run_file.hpp, which requires what every result file carries,
// the schema version and the program's version (runs/run_case.cpp), and the input key the suite
// stamps on each run (distribution/suite_plan.cpp, execute_planned_run).
#pragma once

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/results.hpp"
#include "core/version.hpp"

namespace rotbeam::test {

// Writes runs[i] to DIR/run<i>.json with those three keys; returns the file names in order.
inline std::vector<std::string> write_suite_run_files(const std::filesystem::path& dir,
                                                      const std::vector<nlohmann::json>& runs) {
    std::vector<std::string> files;
    for (size_t i = 0; i < runs.size(); ++i) {
        nlohmann::json run = runs[i];
        run["input_key"] = "hand-made-" + std::to_string(i);
        if (!run.contains("schema_version")) run["schema_version"] = kSchemaVersion;
        if (!run.contains("version")) run["version"] = kGitDescribe;
        files.push_back((dir / ("run" + std::to_string(i) + ".json")).string());
        std::ofstream(files.back()) << run.dump();
    }
    return files;
}

}  // namespace rotbeam::test
