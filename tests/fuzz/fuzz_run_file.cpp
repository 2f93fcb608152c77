// Fuzz target: the reader of result files read back (runs/run_file.hpp) on a text in memory, as a
// resumed suite, `rotbeam merge`, the report and the sweep table read a run's result, a split
// study's run and a whole study's record. docs/fuzzing.md.
//
// A finding is anything but a clean refusal or a file that keeps the reader's promises: a crash or
// sanitizer report, any exception other than InputError, an InputError that is not ONE line
// starting with the file's name, or an accepted file holding a number that is not finite, or a
// run result without its status, its steps, or a step without its points and its load factor or
// time (the keys the report reads without looking).
#include <cmath>
#include <cstdint>
#include <string>

#include "runs/run_file.hpp"
#include "tests/fuzz/fuzz_finding.hpp"

namespace {

constexpr const char* kTarget = "fuzz_run_file";
constexpr const char* kFile = "fuzz/runs/run.json";

bool finite_everywhere(const nlohmann::json& j) {
    if (j.is_number_float()) return std::isfinite(j.get<double>());
    if (j.is_structured()) {
        for (const auto& child : j) {
            if (!finite_everywhere(child)) return false;
        }
    }
    return true;
}

void check_accepted_run(const nlohmann::json& j) {
    using rotbeam::fuzz::finding;
    if (!j.is_object() || !j["status"].is_string() || !j["steps"].is_array())
        finding(kTarget, "accepted a run without status or steps: " + j.dump().substr(0, 200));
    for (const auto& step : j["steps"]) {
        const bool when = (step.contains("load_factor") && step["load_factor"].is_number()) ||
                          (step.contains("time") && step["time"].is_number());
        if (!when || !step.contains("points") || !step["points"].is_object())
            finding(kTarget, "accepted a step without points or load factor: " + step.dump());
        for (const auto& [name, point] : step["points"].items()) {
            if (!point.contains("displacement") || point["displacement"].size() != 3)
                finding(kTarget, "accepted a point without its displacement: " + name);
        }
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using rotbeam::RunFileKind;
    using rotbeam::fuzz::finding;
    const std::string text(reinterpret_cast<const char*>(data), size);
    for (const RunFileKind kind :
         {RunFileKind::case_run, RunFileKind::study_run, RunFileKind::whole_study}) {
        rotbeam::fuzz::expect_clean_refusal(kTarget, kFile, [&] {
            const auto j = rotbeam::parse_run_file(text, kFile, kind, std::nullopt);
            if (!j) finding(kTarget, "no input key asked for, yet not read");
            if (!finite_everywhere(*j)) finding(kTarget, "accepted a number that is not finite");
            if (kind == RunFileKind::case_run) check_accepted_run(*j);
        });
    }
    // With the plan's input key: a file of another key is left unchecked, never a crash.
    rotbeam::fuzz::expect_clean_refusal(kTarget, kFile, [&] {
        (void)rotbeam::parse_run_file(text, kFile, RunFileKind::case_run, std::string("fuzz-key"));
    });
    return 0;
}
