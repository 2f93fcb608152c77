// The limits on what a case file (and every command-line value) may ask for, in one place
// (docs/case-format.md, "Limits"). They keep every input either refused with one line or run:
// no value may drive memory or time past what a verification run can use, and no YAML file may
// expand (aliases), nest or weigh more than a case file ever needs.
//
// - The YAML shape is checked on the parser's events before any tree is built
//   (check_yaml_shape): yaml-cpp resolves aliases by sharing nodes, so a file whose anchor
//   contains its own alias is a cycle, and a "billion laughs" file is a few lines that expand to
//   billions of nodes; both only explode when something walks the tree.
// - Each size key has a hard cap, checked where the key is read (settings.cpp, model_parts.cpp).
// - The memory a run would need is estimated from the model before anything is allocated
//   (estimate_memory) and refused above the machine's physical memory.
#pragma once

#include <cstddef>
#include <string>

#include "core/model.hpp"

namespace rotbeam::cases {

// A case or references file: the catalog's largest is 8 KB; a long time table of 10 000 points
// is ~200 KB.
inline constexpr std::size_t kMaxFileBytes = 1u << 20;
// Nesting of mappings and lists: a case file nests 5 deep at most (a section's 6×6 matrix
// under sections.NAME.stiffness).
inline constexpr int kMaxYamlDepth = 32;
// Nodes of the tree with every alias expanded (keys, values, list items).
inline constexpr long kMaxYamlNodes = 200000;

// members.NAME.elements (and `--elements`): the scaling benches run 8192 elements per member.
inline constexpr int kMaxElementsPerMember = 100000;
// discretization.order: the p-refinement study reaches round-off by p = 12 on two elements;
// past twice that the element's dense (6(p+1))² blocks and p+1 quadrature points cost p³ per
// element with nothing left to gain.
inline constexpr int kMaxOrder = 24;
// members.NAME.twist: angles at equally spaced s/L, interpolated by one polynomial. BeamDyn's
// twist is a polynomial of degree ≤ 6 (seven values); a degree much past that through equally
// spaced values oscillates between them (Runge).
inline constexpr std::size_t kMaxTwistValues = 8;
// discretization.quadrature_points: twice the Gauss points the highest order needs (p + 1).
inline constexpr int kMaxQuadraturePoints = 50;
// discretization.refine: the trapezoidal rule's divisions per station interval. Its error falls
// as refine⁻² (docs/displacement-formulation.md), 1e-6 of the unrefined one at 1000.
inline constexpr int kMaxRefine = 1000;
// analysis.load_factors entries, analysis.substeps, and their product (the sub-steps a static
// run starts with).
inline constexpr int kMaxLoadFactors = 10000;
inline constexpr int kMaxSubsteps = 100000;
inline constexpr long kMaxStaticSubsteps = 1000000;
// analysis.max_step_cuts: a sub-step cut 40 times is 1e-12 of itself, a load-factor increment
// at round-off.
inline constexpr int kMaxStepCuts = 40;
// end_time / time_step of a dynamic analysis.
inline constexpr double kMaxTimeSteps = 1e6;
// analysis.modes.
inline constexpr int kMaxModes = 1000;
// analysis.accuracy (and `run --accuracy`): 1e-12 ≤ TOL < 1. Below 1e-12 the target TOL/2 lies
// under the solves' own round-off (the Newton acceptance bounds the scaled algebraic error near
// 1e-12, docs/solver-convergence.md); 1 asks for nothing (docs/accuracy-control.md).
inline constexpr double kMinAccuracy = 1e-12;
inline constexpr double kMaxAccuracy = 1.0;  // exclusive
// solver.max_iterations (Newton iterations per step; the catalog converges in under 50).
inline constexpr int kMaxNewtonIterations = 10000;

// Throws InputError `FILE:LINE: (yaml): problem` for a document with anchors that nests deeper
// than kMaxYamlDepth, expands to more than kMaxYamlNodes, or has an alias inside the node its
// anchor names (a cycle); also for malformed YAML (the parser's own message). A document without
// anchors is left to the parse and to YamlReader::index, which checks its nesting.
void check_yaml_shape(const std::string& text, const std::string& file);

// The memory a run of `model` would need, estimated from its sizes alone (nothing is built).
struct MemoryEstimate {
    double bytes = 0.0;
    long unknowns = 0;
    std::string dominant;  // what most of it is, for the message
};
MemoryEstimate estimate_memory(const Model& model);

// The machine's physical memory in bytes (0 when unknown).
double physical_memory_bytes();

// "1.5 GiB", "2.3 TiB".
std::string memory_text(double bytes);

}  // namespace rotbeam::cases
