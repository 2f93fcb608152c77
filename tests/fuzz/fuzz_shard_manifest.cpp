// Fuzz target: the shard manifest reader (distribution/shard_manifest.hpp) on a text in memory, as
// `rotbeam merge` reads each folder's shard.json before anything else. docs/fuzzing.md.
//
// A finding is anything but a clean refusal or a manifest that keeps its promises: a crash or
// sanitizer report, any exception other than InputError, an InputError that is not ONE line
// starting with the file's name, or an accepted manifest with a shard outside 1 ≤ I ≤ N ≤
// kMaxShards or a command other than suite, study and sweep.
#include <cstdint>
#include <string>

#include "distribution/shard_manifest.hpp"
#include "tests/fuzz/fuzz_finding.hpp"

namespace {

constexpr const char* kTarget = "fuzz_shard_manifest";
constexpr const char* kFile = "fuzz/shard.json";

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using rotbeam::fuzz::finding;
    const std::string text(reinterpret_cast<const char*>(data), size);
    rotbeam::fuzz::expect_clean_refusal(kTarget, kFile, [&] {
        const rotbeam::cli::ShardManifest m = rotbeam::cli::parse_shard_manifest(text, kFile);
        if (m.shard.count < 1 || m.shard.count > rotbeam::cli::kMaxShards || m.shard.index < 1 ||
            m.shard.index > m.shard.count) {
            finding(kTarget, "accepted shard " + std::to_string(m.shard.index) + "/" +
                                 std::to_string(m.shard.count));
        }
        if (m.job.command != "suite" && m.job.command != "study" && m.job.command != "sweep")
            finding(kTarget, "accepted command " + m.job.command);
        (void)m.job.to_json().dump();  // merge prints it in its messages
    });
    return 0;
}
