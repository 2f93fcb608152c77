// How far a run's estimated errors are from an accuracy target (docs/accuracy-control.md): every
// estimated quantity divided by its scale, the worst of them, and whether each meets the target.
//
// Scales (one place, argued in docs/accuracy-control.md, "Scales"):
//   displacement: the model's reference length, the largest distance between two named points
//                 (the scale of the estimate's round-off floor, estimates/estimate.hpp);
//   rotation:     1 rad (an angle is already relative: TOL rad);
//   frequency:    the frequency itself;
//   a history:    (dynamics) its amplitude, the largest |u(t)| or |angle(t)| over the run
//                 (estimates/history_estimate.hpp): the largest estimated error over the run
//                 relative to it.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "core/model.hpp"

namespace rotbeam::estimate {

// The largest distance between two named points of the model (1 when they all coincide).
double reference_length(const Model& model);

struct AccuracyMeasure {
    double worst = 0.0;      // the largest estimate / scale over every estimated quantity
    std::string worst_what;  // which quantity: "tip displacement at load factor 2", "mode 3"
    // The observed h-order of the worst quantity's estimate (h/2, h/4), 0 when it has none.
    double worst_order = 0.0;
    // A dynamic run's histories: the largest space and time parts of the estimate (each over its
    // history's amplitude) and how many histories have a space or a time part that is not
    // reliable at some output time; the accuracy control refines the mesh or the time step by
    // them (estimates/accuracy_control.hpp).
    double worst_space = 0.0, worst_time = 0.0;
    int space_unreliable = 0, time_unreliable = 0;
    int quantities = 0;  // estimated quantities
    int unreliable = 0;  // estimates not reliable: they never meet a target
    int missing = 0;     // quantities without an estimate
    // The first quantity above the target or not reliable, for the message.
    std::string first_problem;
};

// Measures the estimates of `result` (a run with its `estimate`, docs/error-estimates.md)
// against `target` (relative): a quantity meets it when its reliable estimate / scale ≤ target.
AccuracyMeasure measure_accuracy(const Model& model, const nlohmann::json& result, double target);

// True when every quantity of `m` meets the target it was measured against.
bool meets(const AccuracyMeasure& m, double target);

}  // namespace rotbeam::estimate
