// Fuzz target: the shard manifest reader (cases/runner/shard_manifest.hpp) on a text in memory, as
// `rotbeam merge` reads each folder's shard.json before anything else. docs/fuzzing.md.
//
// A finding is anything but a clean refusal or a manifest that keeps its promises: a crash or
// sanitizer report, any exception other than InputError, an InputError that is not ONE line
// starting with the file's name, or an accepted manifest with a shard outside 1 ≤ I ≤ N ≤
// kMaxShards or a command other than suite and study.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <typeinfo>

#include "cases/runner/shard_manifest.hpp"
#include "core/errors.hpp"

namespace {

constexpr const char* kFile = "fuzz/shard.json";

[[noreturn]] void finding(const std::string& what) {
    std::fprintf(stderr, "fuzz_shard_manifest: %s\n", what.c_str());
    std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        const rotbeam::cli::ShardManifest m = rotbeam::cli::parse_shard_manifest(text, kFile);
        if (m.shard.count < 1 || m.shard.count > rotbeam::cli::kMaxShards || m.shard.index < 1 ||
            m.shard.index > m.shard.count) {
            finding("accepted shard " + std::to_string(m.shard.index) + "/" +
                    std::to_string(m.shard.count));
        }
        if (m.job.command != "suite" && m.job.command != "study" && m.job.command != "sweep")
            finding("accepted command " + m.job.command);
        (void)m.job.to_json().dump();  // merge prints it in its messages
    } catch (const rotbeam::InputError& e) {
        const std::string message = e.what();
        if (message.rfind(kFile, 0) != 0) finding("refusal not naming the file: " + message);
        if (message.find('\n') != std::string::npos)
            finding("refusal on several lines: " + message);
    } catch (const std::exception& e) {
        finding(std::string("escaped exception ") + typeid(e).name() + ": " + e.what());
    }
    return 0;
}
