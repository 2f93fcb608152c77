#include "distribution/shard_manifest.hpp"

#include <cstdint>

#include "core/errors.hpp"

namespace rotbeam::cli {

namespace {

// The value of `key` in the object `j` when it has `type`; InputError naming the file and key
// otherwise.
const nlohmann::json& member(const nlohmann::json& j, const char* key, nlohmann::json::value_t type,
                             const char* expected, const std::string& file) {
    const auto it = j.find(key);
    if (it == j.end()) throw InputError(file + ": " + key + ": missing");
    if (it->type() != type) {
        throw InputError(file + ": " + key + ": expected " + expected + ", found " +
                         it->type_name());
    }
    return *it;
}

// A whole number in [low, high] (a JSON integer, not a float), low ≥ 0; InputError naming the file
// and key otherwise.
int bounded_int(const nlohmann::json& j, const char* key, int low, int high,
                const std::string& file) {
    const auto it = j.find(key);
    if (it == j.end()) throw InputError(file + ": " + key + ": missing");
    if (!it->is_number_integer()) {
        throw InputError(file + ": " + key + ": expected a whole number, found " +
                         (it->is_number() ? it->dump() : std::string(it->type_name())));
    }
    // Unsigned and signed integers are told apart: no value is converted before it is checked.
    const bool in_range = it->is_number_unsigned()
                              ? it->get<std::uint64_t>() >= static_cast<std::uint64_t>(low) &&
                                    it->get<std::uint64_t>() <= static_cast<std::uint64_t>(high)
                              : it->get<std::int64_t>() >= low && it->get<std::int64_t>() <= high;
    if (!in_range) {
        throw InputError(file + ": " + key + ": " + it->dump() + " is not " + std::to_string(low) +
                         " to " + std::to_string(high));
    }
    return it->get<int>();
}

}  // namespace

nlohmann::json Job::to_json() const {
    return {{"command", command},   {"study", study},     {"cases", cases},
            {"quick", quick},       {"studies", studies}, {"reduced_follower", reduced_follower},
            {"estimate", estimate}, {"sweep", sweep},     {"sweep_key", sweep_key}};
}

Job job_from_json(const nlohmann::json& j, const std::string& file) {
    const std::string where = file + ": job";
    if (!j.is_object()) throw InputError(where + ": expected an object, found " + j.type_name());
    using T = nlohmann::json::value_t;
    Job job;
    job.command = member(j, "command", T::string, "a string", where).get<std::string>();
    job.study = member(j, "study", T::string, "a string", where).get<std::string>();
    job.cases = member(j, "cases", T::string, "a string", where).get<std::string>();
    job.quick = member(j, "quick", T::boolean, "true or false", where).get<bool>();
    job.studies = member(j, "studies", T::boolean, "true or false", where).get<bool>();
    job.reduced_follower =
        member(j, "reduced_follower", T::boolean, "true or false", where).get<bool>();
    job.estimate = member(j, "estimate", T::boolean, "true or false", where).get<bool>();
    job.sweep = member(j, "sweep", T::string, "a string", where).get<std::string>();
    // Written since merge checks the sweep file against it; a manifest without it has "".
    if (j.contains("sweep_key"))
        job.sweep_key = member(j, "sweep_key", T::string, "a string", where).get<std::string>();
    if (job.command != "suite" && job.command != "study" && job.command != "sweep")
        throw InputError(where + ": command: " + nlohmann::json(job.command).dump() +
                         " is not suite, study or sweep");
    return job;
}

ShardManifest parse_shard_manifest(const std::string& text, const std::string& file) {
    nlohmann::json j;
    try {
        j = nlohmann::json::parse(text);
    } catch (const nlohmann::json::exception& e) {
        throw InputError(file + ": not complete JSON (" + e.what() + ")");
    }
    using T = nlohmann::json::value_t;
    if (!j.is_object() || !j.contains("format") || j["format"] != "rotbeam-shard")
        throw InputError(file + ": format: not a rotbeam shard file");
    ShardManifest m;
    m.version = member(j, "version", T::string, "a string", file).get<std::string>();
    m.job = job_from_json(member(j, "job", T::object, "an object", file), file);
    m.shard.count = bounded_int(j, "of", 1, kMaxShards, file);
    m.shard.index = bounded_int(j, "shard", 1, m.shard.count, file);
    for (const auto& u : member(j, "units", T::array, "an array", file)) {
        if (!u.is_string())
            throw InputError(file + ": units: expected file names, found " + u.type_name());
        m.units.push_back(u.get<std::string>());
    }
    return m;
}

}  // namespace rotbeam::cli
