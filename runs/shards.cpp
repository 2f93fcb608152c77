#include "shards.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <numeric>

#include "core/errors.hpp"

namespace rotbeam::cli {

Shard parse_shard(const std::string& command, const std::string& text) {
    const auto bad = [&](const std::string& why) {
        return InputError("rotbeam " + command + ": --shard: '" + text + "': " + why);
    };
    const size_t slash = text.find('/');
    if (slash == std::string::npos) throw bad("expected I/N, e.g. 2/3 (the second of three)");
    const auto number = [&](const std::string& part) {
        if (part.empty() || part.size() > 6 ||
            !std::all_of(part.begin(), part.end(), [](char c) { return c >= '0' && c <= '9'; })) {
            throw bad("expected I/N with whole numbers, e.g. 2/3");
        }
        return std::stoi(part);
    };
    const int index = number(text.substr(0, slash));
    const int count = number(text.substr(slash + 1));
    if (count < 1 || count > kMaxShards) throw bad("N must be 1 to " + std::to_string(kMaxShards));
    if (index < 1 || index > count) throw bad("I must be 1 to N");
    return {index, count};
}

std::vector<int> assign_longest_first(const std::vector<double>& seconds, int count) {
    ROTBEAM_VERIFY(count >= 1, "assign_longest_first: at least one shard");
    std::vector<size_t> order(seconds.size());
    std::iota(order.begin(), order.end(), size_t{0});
    std::stable_sort(order.begin(), order.end(),
                     [&](size_t a, size_t b) { return seconds[a] > seconds[b]; });
    std::vector<double> load(static_cast<size_t>(count), 0.0);
    std::vector<int> shard(seconds.size(), 0);
    for (const size_t i : order) {
        // min_element returns the first of equal loads: the lower shard.
        const auto least = std::min_element(load.begin(), load.end());
        shard[i] = static_cast<int>(least - load.begin());
        *least += seconds[i];
    }
    return shard;
}

std::vector<double> expected_seconds(const std::vector<double>& modelled,
                                     const std::vector<std::optional<double>>& measured) {
    ROTBEAM_VERIFY(modelled.size() == measured.size(), "expected_seconds: one entry per item");
    double sum_measured = 0.0, sum_modelled = 0.0;
    for (size_t i = 0; i < modelled.size(); ++i) {
        if (measured[i]) {
            sum_measured += *measured[i];
            sum_modelled += modelled[i];
        }
    }
    const double scale =
        sum_modelled > 0.0 && sum_measured > 0.0 ? sum_measured / sum_modelled : 1.0;
    std::vector<double> expected(modelled.size());
    for (size_t i = 0; i < modelled.size(); ++i)
        expected[i] = measured[i] ? *measured[i] : modelled[i] * scale;
    return expected;
}

std::string stable_hash(const std::string& text) {
    std::uint64_t h = 14695981039346656037ull;  // FNV-1a 64-bit offset basis
    for (const unsigned char c : text) {
        h ^= c;
        h *= 1099511628211ull;  // FNV prime
    }
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
    return hex;
}

}  // namespace rotbeam::cli
