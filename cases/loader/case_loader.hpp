// The YAML case loader: reads a case file (docs/case-format.md) into a validated Model.
//
// `load_case(path, overrides)` parses the file, applies the `--set key.path=value` overrides to
// the YAML tree (a value is parsed as YAML, so `analysis.load_factors=[0.4,2]` sets a list), then
// validates everything in one pass. Any problem throws InputError with ONE line
// `FILE:LINE: KEY: problem` (`FILE:--set: KEY: problem` for an override), never a partial model.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/model.hpp"

namespace rotbeam {

// What to read. A catalog case keeps its published references beside it, in
// `references/NAME.yaml` (published_references_path): they are most of its text and of its parse
// (docs/performance.md, start-up), and only check, verify, the suite and the report use them.
// `all`: the case file and that file when it exists (`--set references...` overrides apply to it);
// `case_file`: the case file alone — what `rotbeam run` reads. Either way a `references` block in
// the case file itself (a user's case) is read and validated.
enum class CaseParts { all, case_file };

Model load_case(const std::string& path, const std::vector<std::string>& overrides = {},
                CaseParts parts = CaseParts::all);

// Where the published references of the case at `case_path` are kept (which may not exist).
std::filesystem::path published_references_path(const std::string& case_path);

// The case file alone from text already in memory; `file_name` is used in messages (tests, stdin).
Model load_case_text(const std::string& text, const std::string& file_name,
                     const std::vector<std::string>& overrides = {});

// A human-readable summary for `rotbeam check`: points, members (line, length, twist, elements,
// sections), constraints, loads, analysis, discretization, solver and references.
std::string describe_model(const Model& model);

}  // namespace rotbeam
