// A catalog entry that is a BeamDyn deck (docs/beamdyn-import.md, "Catalog entries"): a case file
// whose only top-level key is `beamdyn`, naming a driver file (relative to the case file) and the
// catalog's choices for it:
//
//   beamdyn:
//     driver: ../tests/data/beamdyn/bd_5MW_dynamic_gravity_Az00/bd_driver.inp
//     set: ["name=nrel5mw-gravity", "analysis.end_time=1"]   # --set overrides, before the user's
//     refused: {mixed: "words of its refusal"}
//
// The deck is imported as `rotbeam run DRIVER.inp` imports it, then `set` applies as `--set`
// overrides (the user's come after and win). `refused` states, per formulation, that the deck does
// not run in it and the words its refusal must contain: the suite's report shows such a run as
// refused as stated, and the catalog tests check the refusal.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/choices.hpp"

namespace rotbeam::cases {

struct DeckCase {
    std::string driver;                  // the driver file, relative to the working directory
    std::vector<std::string> overrides;  // `set`, in order
    std::map<Formulation, std::string> refused;
};

// The text a case's results depend on: the case file's, and for a deck entry also the imported
// deck's (what the suite's run keys hash). InputError when the file cannot be read.
std::string case_input_text(const std::string& path);

// The refusals the case file at `path` states per formulation (empty for an ordinary case, or a
// file that cannot be read).
std::map<Formulation, std::string> stated_refusals(const std::string& path);

// The deck entry of the case file `file` with text `text`, or nullopt when the text is an ordinary
// case (no top-level `beamdyn` key). InputError (one line FILE:LINE: KEY: problem) for a malformed
// entry.
std::optional<DeckCase> read_deck_case(const std::string& text, const std::string& file);

}  // namespace rotbeam::cases
