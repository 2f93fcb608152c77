#include "distribution/study_cost.hpp"

#include "core/errors.hpp"
#include "runs/estimate_cost.hpp"

namespace rotbeam::cli {

namespace {

// The expected time of a study made whole, before it has ever run (quick, full), in seconds of
// one core: measured on the 2-core machine (docs/distributed-runs.md, "Cost model"). The full
// speed-accuracy study: 3 007 s of CPU (2026-11-28, every combination on the joined beam's 0–2 s
// and the free vibration's 0–0.5 s, the free vibration's adaptive rows at 1e-4 and 1e-5; its
// references ~1 680 s of that, which it makes on every thread it is given: docs/studies.md,
// "Threads"; 3 949 s while those rows went to 1e-6).
struct StudyCost {
    const char* name;
    double quick, full;
};
constexpr StudyCost kStudyCosts[] = {
    {"manufactured-time", 21.0, 400.0},
    {"joined-beam-modal", 2.2, 30.0},
    {"speed-accuracy", 120.0, 3000.0},
    {"joined-beam-dynamics", 60.0, 1200.0},
    {"joined-beam-agreement", 30.0, 1200.0},
    {"free-vibration-time", 20.0, 300.0},
    // 4.3 s and 372 s of CPU measured 2026-11-28 and 2026-11-29 (--jobs 1, the full form with its
    // dynamic rows: space sequences for every combination, the adaptive steps' sequences).
    {"effectivity", 5.0, 375.0},
};
// A study without an entry above, and a continuum reference run of a split study.
constexpr double kUnknownStudySeconds = 60.0;
constexpr double kContinuumReferenceSeconds = 0.5;
// The quick suite's four combine steps took 2.5 to 22 s of wall time at a load average of 16
// (2026-11-27), where the whole studies ran 14.4 times their CPU time (joined-beam-modal 1.9 s
// of CPU, free-vibration-time 9.2 s, manufactured-time 23.8 s): 0.2 to 1.5 s of one core. One
// figure for all of them: next to the timed study run alone after them (120 s), the difference
// is lost in the noise. Not measured in the full suite.
constexpr double kCombineStepSeconds = 1.0;

}  // namespace

double whole_study_seconds(const std::string& name, bool quick) {
    for (const StudyCost& c : kStudyCosts) {
        if (name == c.name) return quick ? c.quick : c.full;
    }
    return kUnknownStudySeconds;
}

double combine_step_seconds() { return kCombineStepSeconds; }

double study_run_seconds(const StudyRun& run) {
    if (run.kind == StudyRun::Kind::continuum_reference) return kContinuumReferenceSeconds;
    try {
        return modelled_seconds(build_model(run.spec),
                                run.kind == StudyRun::Kind::estimated_case_run);
    } catch (const InputError&) {
        return kFixedSeconds;  // a combination that does not exist: refused at once
    }
}

}  // namespace rotbeam::cli
