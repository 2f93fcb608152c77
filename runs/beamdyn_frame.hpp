// Results in BeamDyn's frame (docs/beamdyn-import.md, "Results in BeamDyn's frame"): a run of an
// imported deck reports, on request (`run --frame beamdyn`), each step's named points and support
// reactions as BeamDyn's driver writes them: in the blade-root frame, whose axes are the rows of
// the driver's GlbDCM (global → root), the displacement TD = GlbDCM u, the rotation RD as
// Wiener–Milenković parameters 4 tan(φ/4) n of the rotation vector GlbDCM ψ (the rotation from
// the reference state, BeamDyn's TipRD), and the reaction F = GlbDCM f, M = GlbDCM m. With turning
// supports the relative motion (`rotating_frame.points`, `rotating_frame.reactions`, in the
// turning frame's axes) is what BeamDyn's root-frame outputs hold.
//
// Global vectors are not permuted by the import (BeamDyn's global axes are rotbeam's; only the
// section matrices are, e1 = BeamDyn z), so this is a rotation of components, no permutation.
#pragma once

#include <nlohmann/json.hpp>
#include <ostream>

#include "core/types.hpp"

namespace rotbeam {

// Wiener–Milenković parameters c = 4 tan(φ/4) n of the rotation vector ψ = φ n.
Vec3 wiener_milenkovic_of(const Vec3& psi);

// Adds `beamdyn_frame` = {dcm} to the result and per step `beamdyn` = {points: {name: {TD, RD}},
// reactions: {name: {F, M}}} (reactions where the step has them).
void add_beamdyn_frame(const Mat3& root_dcm, nlohmann::json& result);

// The CSV columns of the `beamdyn` block (steps_csv.hpp, history_csv.hpp), named like BeamDyn's
// channels: per named point <point>_TDxr, _TDyr, _TDzr, _RDxr, _RDyr, _RDzr, then per support
// <support>_Fxr … _Mzr where the steps have reactions. None when the result has no
// `beamdyn_frame`.
bool has_beamdyn_columns(const nlohmann::json& result);
// ",<column>…" for the `beamdyn` block of steps[0].
void write_beamdyn_header(const nlohmann::json& result, std::ostream& os);
// ",<value>…" for one step, in the header's order.
void write_beamdyn_row(const nlohmann::json& step, std::ostream& os);

}  // namespace rotbeam
