// `rotbeam verify`: the published-tolerance gate (distribution/gate.hpp) over the given cases,
// printed as a table; exit 1 on any gated miss (an unavailable result is one) or changed stop.
#include <iostream>

#include "arguments.hpp"
#include "commands.hpp"
#include "core/atomic_file.hpp"
#include "core/results.hpp"
#include "core/version.hpp"
#include "distribution/gate.hpp"

namespace rotbeam::cli {

int command_verify(const Args& args) {
    const CommandSpec spec{
        "verify",
        "[CASE ...]",
        0,
        -1,
        "Run every published reference of the given cases (default: the whole catalog) with every "
        "combination its applies_to selects and compare with its tolerance; check every expected "
        "stop. Prints a table; exit 1 on any gated miss (an unavailable result is one) or a "
        "changed stop.",
        {{"json", "FILE", "also write the table as JSON (default: not written)"}}};
    const ParsedArguments a = parse_arguments(spec, args);
    if (a.help) {
        std::cout << help_text(spec);
        return 0;
    }
    std::vector<std::string> cases = a.positional;
    if (cases.empty()) cases = catalog_cases();
    const std::vector<Row> rows = verify_rows(cases);
    nlohmann::json table_rows = nlohmann::json::array();
    print_table(rows, std::cout);
    int pairs = 0, pair_misses = 0, stops = 0, stop_misses = 0, recorded = 0, not_reached = 0;
    for (const Row& r : rows) {
        const bool gated = r.verdict == "pass" || r.verdict == "FAIL";
        const bool miss = r.verdict == "FAIL";
        if (r.quantity == "stop") {
            ++stops;
            stop_misses += miss ? 1 : 0;
        } else if (gated) {
            ++pairs;
            pair_misses += miss ? 1 : 0;
        } else if (r.verdict == "not reached") {
            ++not_reached;
        } else {
            ++recorded;
        }
        table_rows.push_back(row_json(r));
    }
    std::cout << "\nverify: " << pairs - pair_misses << " of " << pairs
              << " gated (reference × combination) pairs passed, " << pair_misses << " missed; "
              << stops - stop_misses << " of " << stops << " expected stops held, " << stop_misses
              << " changed; " << not_reached << " pairs end at an expected stop first; " << recorded
              << " recorded only\n";
    if (const auto file = a.value("json")) {
        const nlohmann::json table = {{"schema_version", kSchemaVersion},
                                      {"version", kGitDescribe},
                                      {"rows", table_rows},
                                      {"summary",
                                       {{"gated_pairs", pairs},
                                        {"gated_misses", pair_misses},
                                        {"expected_stops", stops},
                                        {"changed_stops", stop_misses},
                                        {"not_reached", not_reached},
                                        {"recorded_only", recorded}}}};
        write_file_atomically(*file, table.dump(2) + "\n");
    }
    return pair_misses + stop_misses > 0 ? 1 : 0;
}

}  // namespace rotbeam::cli
