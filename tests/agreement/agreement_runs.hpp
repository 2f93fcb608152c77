// Shared helpers of test_agreement: load a catalog case with `--set` overrides and solve it with
// the continuum reference (core/continuum) or with one finite-element formulation driven by the
// shared static driver, returning the tip displacement at every reported load factor together
// with what it took (steps, Newton/multiroot iterations, wall time).
#pragma once

#include <string>
#include <vector>

#include "core/model.hpp"
#include "core/types.hpp"

namespace rotbeam::test {

struct TipRun {
    std::vector<Vec3> tips;  // tip displacement per reported load factor
    int steps = 0;           // load increments (sub-steps) taken
    int iterations = 0;      // Newton (FE) or multiroot (continuum) iterations, summed
    double seconds = 0.0;    // wall time of the solve
};

// cases/<name>.yaml from the source tree, with `--set` overrides.
Model catalog_case(const std::string& name, const std::vector<std::string>& overrides = {});

TipRun run_continuum(const Model& model);
// form::DisplacementStatics<param::Quaternion>, order p, N elements (case overrides).
TipRun run_displacement(const Model& model);
// form::MixedStatics<param::WienerMilenkovic>.
TipRun run_mixed(const Model& model);

// ‖a − b‖ / ‖b‖.
double relative_difference(const Vec3& a, const Vec3& b);

}  // namespace rotbeam::test
