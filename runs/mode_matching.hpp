// Mode shapes on a mesh-independent set of stations, and the matching of modes across meshes by
// the modal assurance criterion (MAC), not by sort order: two meshes (or formulations) may order
// close frequencies differently, and a coarse mesh may miss a mode.
//
// Stations: on every member, 9 points at chord fractions 0, 1/8, …, 1 of its end points. On a
// straight member (its nodes on the chord) each station interpolates the nodal displacement
// amplitudes linearly between the two nodes around it; on a curved member it takes the nearest
// node's. A supported node's amplitude is zero. A mesh too coarse to resolve a mode (one or two
// elements per member) may pair it with a higher mode of similar station pattern or leave it
// unmatched: the pairing is as good as the shapes the mesh can represent.
// Translations only (the rotations have other units). A mode's
// `stations` in the result JSON is that list, 3 numbers per station, members in order.
//
// MAC(a, b) = |aᴴb|² / (aᴴa · bᴴb) ∈ [0, 1]: 1 for proportional shapes, 0 for orthogonal ones.
// Matching: pairs (reference mode, candidate mode) taken greedily in decreasing MAC, each mode
// used once; a reference mode whose best remaining MAC is below `min_mac` stays unmatched (−1).
#pragma once

#include <vector>

#include "core/model.hpp"

namespace rotbeam {

inline constexpr int kModeStationsPerMember = 9;

// A node's reference position and the real displacement amplitude of one mode there.
struct NodeDisplacement {
    Vec3 x0;
    Vec3 u;
};

std::vector<double> station_displacements(const Model& model,
                                          const std::vector<NodeDisplacement>& nodes);

double modal_assurance(const std::vector<double>& a, const std::vector<double>& b);

// For each reference mode the index of its candidate, or −1.
std::vector<int> match_modes(const std::vector<std::vector<double>>& reference,
                             const std::vector<std::vector<double>>& candidates, double min_mac);

// Accepted MAC of a match: the joined beam's five lowest modes of two meshes (1 … 32 elements
// per member, any order, both formulations) match with MAC ≥ 0.9 while distinct modes of one mesh
// stay below 0.5 on the stations (measured in docs/displacement-modal.md).
inline constexpr double kMatchMac = 0.8;

}  // namespace rotbeam
