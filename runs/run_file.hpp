// The result files a job reads back, checked before anything reads a field of them: a suite that
// resumes (OUT/runs/*.json), `rotbeam merge` (a shard folder's runs/*.json, study-runs/STUDY/*.json
// and studies/STUDY.done.json), the report and the sweep table. The one place where a result file
// is parsed back (docs/durability.md, "Resume").
//
// A file is refused with ONE line, InputError "FILE: KEY: problem", KEY the JSON path of the
// value (`steps[3].points.tip.displacement[1]`): not complete JSON, not an object, a key that a
// reader of the file uses missing, a value of the wrong type, a number that is not finite (a JSON
// number beyond the double range reads as infinity), a `schema_version` other than this
// program's, nesting deeper than any result file has. Keys no reader uses are not checked, but
// every number anywhere must be finite.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

namespace rotbeam {

enum class RunFileKind {
    case_run,     // a run's result: `rotbeam run --out`, the suite's runs/*.json
    study_run,    // one run of a split study: {study, key, input_key, seconds, result}
    whole_study,  // a study made whole in a shard folder: {study, input_key, seconds, files}
};

// Nesting deeper than this is refused (a result file has at most 8 levels).
inline constexpr int kMaxRunFileDepth = 32;

// `text`, the content of `file`, checked as a result file of `kind`; InputError otherwise.
// `input_key`: when given, a file that carries another (well-formed) input_key is not checked
// further and gives nullopt: it was made from other inputs or by another rotbeam version, whose
// files may follow another schema.
std::optional<nlohmann::json> parse_run_file(const std::string& text, const std::string& file,
                                             RunFileKind kind,
                                             const std::optional<std::string>& input_key);

// The same on the file's content read from the disk (InputError when it cannot be read).
std::optional<nlohmann::json> read_run_file(const std::string& file, RunFileKind kind,
                                            const std::optional<std::string>& input_key);

}  // namespace rotbeam
