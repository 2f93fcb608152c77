// A shard folder's manifest, shard.json (docs/distributed-runs.md): the job the shard belongs to,
// which shard of how many it is, and the files of the units it was given. `rotbeam suite|study
// --shard I/N` writes it; `rotbeam merge` reads it back through parse_shard_manifest, the one
// reader of the format (fuzzed by tests/fuzz/fuzz_shard_manifest.cpp, docs/fuzzing.md).
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "runs/shards.hpp"

namespace rotbeam::cli {

// What is run: the suite or a study, with the arguments that decide its results.
struct Job {
    std::string command = "suite";  // "suite", "study" or "sweep"
    std::string study;              // study: its name, or "all"
    std::string sweep;              // sweep: the sweep file (absolute path)
    std::string sweep_key;          // sweep: stable_hash of the sweep file's text when planned
    std::string cases = "*";        // suite: --cases
    bool quick = false;
    bool studies = true;  // suite: the static studies are part of the job
    bool reduced_follower = false;
    bool estimate = true;  // suite: the case runs carry their error estimates
    nlohmann::json to_json() const;
    bool operator==(const Job&) const = default;
};
// The job of a shard.json; InputError "FILE: job: ..." when it is not one.
Job job_from_json(const nlohmann::json& j, const std::string& file);

// A shard.json as read back.
struct ShardManifest {
    std::string version;  // the rotbeam that wrote it (merge takes one version only)
    Job job;
    Shard shard;                     // 1 ≤ index ≤ count ≤ kMaxShards
    std::vector<std::string> units;  // the unit files given to the shard
};

// The manifest in `text`, the content of `file`. InputError on one line, starting with `file`
// and naming the key, when the text is not complete JSON or not a rotbeam shard manifest: a key
// missing or of another type, an unknown command, a shard outside 1 ≤ shard ≤ of ≤ kMaxShards.
// Every key is checked before its value is used; no value is trusted for a size.
ShardManifest parse_shard_manifest(const std::string& text, const std::string& file);

}  // namespace rotbeam::cli
