// A BeamDyn deck as a rotbeam case (docs/beamdyn-import.md).
//
// The deck (cases/loader/beamdyn_deck.hpp) becomes the text of a case file in the format of
// docs/case-format.md, which the case loader then validates like any other: `rotbeam run
// DRIVER.inp` and `rotbeam import beamdyn DRIVER.inp` read the same case, and everything that
// takes a case (every combination, the estimates, --set, the JSON) takes an imported one.
//
// What the translation does, in BeamDyn's terms:
// - each member becomes one rotbeam member of ONE element of order order_elem with order+1
//   Gauss points (`quadrature: full`): BeamDyn's discretization;
// - its reference line is BeamDyn's least-squares fit of the member's key points
//   (beamdyn_geometry.hpp): straight when the fit is straight, else a key-point curve sampled
//   densely from the fit;
// - BeamDyn's section axes (x, y, z = tangent) become rotbeam's material axes (e2, e3, e1): the
//   6×6 stiffness, mass and damping coefficients are permuted, and the e2 hint is BeamDyn's
//   x axis rule;
// - the root frame: points are GlbPos + GlbDCMᵀ · key point; loads and gravity are global.
#pragma once

#include <string>

#include "cases/loader/beamdyn_deck.hpp"

namespace rotbeam::cases {

// The case text of a deck; `name` is the case name (letters, digits, '_' and '-').
// InputError for what the deck asks and rotbeam does not model (naming the file and key).
std::string beamdyn_case_text(const BeamDynDeck& deck, const std::string& name);

// read_beamdyn_deck + beamdyn_case_text, the case named after the driver's folder.
std::string import_beamdyn(const std::string& driver_path);

// The 6×6 permutation from BeamDyn's section order [x, y, z] (z = beam axis) to rotbeam's
// [axial, e2, e3]: rotbeam row i is BeamDyn row kBeamDynRow[i].
inline constexpr int kBeamDynRow[6] = {2, 0, 1, 5, 3, 4};

}  // namespace rotbeam::cases
