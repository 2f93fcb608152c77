#include "run_cost.hpp"

#include <algorithm>
#include <cmath>

#include "estimate_cost.hpp"
#include "estimates/companions.hpp"
#include "estimates/dynamic_companions.hpp"

namespace rotbeam::cli {

double mixed_cost_factor(AnalysisKind kind) {
    switch (kind) {
        case AnalysisKind::static_:
            return kMixedStaticFactor;
        case AnalysisKind::dynamic:
            return kMixedDynamicFactor;
        case AnalysisKind::modal:
            return kMixedModalFactor;
    }
    return kMixedStaticFactor;
}

double modelled_seconds(const Model& model) {
    double elements = 0.0;
    for (const Member& m : model.members) elements += std::max(1, m.elements);
    const bool mixed = model.discretization.formulation == Formulation::mixed;
    const double order = mixed ? 1.0 : std::max(1, model.discretization.order);
    double steps = 1.0;
    switch (model.analysis.kind) {
        case AnalysisKind::static_:
            steps = static_cast<double>(
                        std::max<size_t>(1, model.analysis.statics.load_factors.size())) *
                    std::max(1, model.analysis.statics.substeps);
            break;
        case AnalysisKind::dynamic: {
            const DynamicSettings& d = model.analysis.dynamics;
            steps = d.time_step > 0.0 ? std::ceil(d.end_time / d.time_step) : 1.0;
            break;
        }
        case AnalysisKind::modal:
            steps = std::max(1, model.analysis.modal.modes);
            break;
    }
    return kFixedSeconds + kSecondsPerElementStep * elements * order * steps *
                               (mixed ? mixed_cost_factor(model.analysis.kind) : 1.0);
}

namespace {

// A static displacement run's estimate over the run, callgrind instructions of `rotbeam run …
// --quiet` with and without it (2026-11-27; the runs: docs/distributed-runs.md, "Cost model"),
// the geometric mean of the smallest and largest ratio measured (each within 1.5× of it). Its
// companions start from the run's solved path, so they cost far less than their unknowns, and
// the less, the more Newton iterations the run itself took: not a cost the model can derive.
constexpr double kWarmStartedDecayCheckFactor = 1.93;  // p+1 and p+2: 1.29 … 2.89
constexpr double kWarmStartedFactor = 1.15;            // p+1 alone: 1.08 … 1.22
// The mixed formulation's modes: the companions' eigenproblems (2N, 4N elements) grow faster than
// their unknowns (as N^2.3 here), which the model, linear in the elements, cannot say. One
// measurement: joined-beam, 5 elements per member. Coarser companions (N/2, N/4) cost what the
// model says of them: less than the run, where the superlinear growth only makes the model safe.
constexpr double kMixedModesFactor = 29.4;

// The part of the modelled time that grows with the discretization (the companions run in the
// run's process: no start-up of their own).
double discretization_seconds(const Model& model) {
    return modelled_seconds(model) - kFixedSeconds;
}

double companions_seconds(const std::vector<estimate::Companion>& companions) {
    double seconds = 0.0;
    for (const estimate::Companion& c : companions) seconds += discretization_seconds(c.model);
    return seconds;
}

}  // namespace

double estimate_cost_factor(const Model& model) {
    if (model.analysis.kind == AnalysisKind::static_ &&
        model.discretization.formulation == Formulation::displacement) {
        if (!estimate::plan_companions(model).refusal.empty()) return 1.0;  // refused at once
        return model.discretization.order < estimate::kSpectralOrder ? kWarmStartedDecayCheckFactor
                                                                     : kWarmStartedFactor;
    }
    if (model.analysis.kind == AnalysisKind::modal &&
        model.discretization.formulation == Formulation::mixed &&
        model.analysis.estimate_companions == CompanionSide::finer) {
        return kMixedModesFactor;
    }
    // Companions that start cold (mixed statics, displacement modes, dynamics) cost what the
    // model says of their discretizations.
    double companions = 0.0;
    if (model.analysis.kind == AnalysisKind::dynamic) {
        const estimate::DynamicPlan plan = estimate::plan_dynamic_companions(model);
        companions = companions_seconds(plan.space.companions) + companions_seconds(plan.time);
    } else {
        companions = companions_seconds(estimate::plan_companions(model).companions);
    }
    return 1.0 + companions / discretization_seconds(model);
}

}  // namespace rotbeam::cli
