// The YAML case loader: reads a case file (docs/case-format.md) into a validated Model.
//
// `load_case(path, overrides)` parses the file, applies the `--set key.path=value` overrides to
// the YAML tree (a value is parsed as YAML, so `analysis.load_factors=[0.4,2]` sets a list), then
// validates everything in one pass. Any problem throws InputError with ONE line
// `FILE:LINE: KEY: problem` (`FILE:--set: KEY: problem` for an override), never a partial model.
#pragma once

#include <string>
#include <vector>

#include "core/model.hpp"

namespace rotbeam {

// What to read. `without_references`: everything but the top-level `references` block, which is
// neither parsed nor validated and leaves Model::references empty. On a catalog case that block is
// 80 % of the parse (docs/performance.md, start-up); `rotbeam run` still reads everything, since
// the program contract has it refuse a bad reference (exit 2).
enum class CaseParts { all, without_references };

Model load_case(const std::string& path, const std::vector<std::string>& overrides = {},
                CaseParts parts = CaseParts::all);

// The same from text already in memory; `file_name` is used in messages (tests, stdin).
Model load_case_text(const std::string& text, const std::string& file_name,
                     const std::vector<std::string>& overrides = {},
                     CaseParts parts = CaseParts::all);

// A human-readable summary for `rotbeam check`: points, members (line, length, twist, elements,
// sections), constraints, loads, analysis, discretization, solver and references.
std::string describe_model(const Model& model);

}  // namespace rotbeam
