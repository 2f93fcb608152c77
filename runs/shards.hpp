// Splitting a list of independent runs into N shards for N processes or machines (`--shard I/N`,
// docs/distributed-runs.md): which shard runs which item, from each item's expected run time.
//
// The split is deterministic (a function of the expected times and N only), so N processes started
// with the same arguments and the same timings agree on it without talking to each other: every
// item is in exactly one shard.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace rotbeam::cli {

struct Shard {
    int index = 1;  // 1-based, as written: --shard 2/3 is index 2 of count 3
    int count = 1;
};

// "I/N" with 1 ≤ I ≤ N ≤ kMaxShards; InputError "rotbeam COMMAND: --shard: ..." otherwise.
constexpr int kMaxShards = 100000;
Shard parse_shard(const std::string& command, const std::string& text);

// Longest processing time first (LPT, Graham 1969): the items in decreasing expected time (ties:
// the earlier item first), each given to the shard with the least expected time so far (ties: the
// lower shard). Returns the 0-based shard of every item. Its make-span is at most 4/3 − 1/(3N) of
// the best possible one.
std::vector<int> assign_longest_first(const std::vector<double>& seconds, int count);

// The expected seconds of every item: the measured time where there is one, else the modelled
// cost scaled to seconds by the items that have both (Σ measured / Σ modelled over them), or taken
// as seconds when none has both. `modelled` values are > 0.
std::vector<double> expected_seconds(const std::vector<double>& modelled,
                                     const std::vector<std::optional<double>>& measured);

// FNV-1a (64 bit) in hexadecimal: a file name for a key that is the same on every machine and
// build (std::hash is not).
std::string stable_hash(const std::string& text);

}  // namespace rotbeam::cli
