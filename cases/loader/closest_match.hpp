// The "did you mean" of every refusal of a name (a case key or choice, a point or member, a
// command, an option, a catalog case, a bench target): the closest candidate by edit distance.
#pragma once

#include <string>
#include <vector>

namespace rotbeam::cases {

// Levenshtein distance, letters compared without regard to case.
int edit_distance(const std::string& a, const std::string& b);

// The candidate closest to `word` within a distance that still reads as a typo, at most
// max(1, |word|/3) edits (one in a short word, a third of a long one: "ordr" → "order",
// "joined-beam-modl" → "joined-beam-modal", but nothing for "frobnicate"); the first of equally
// close ones; empty when none is that close.
std::string closest_match(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace rotbeam::cases
