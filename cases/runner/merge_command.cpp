// `rotbeam merge DIR... --out DIR`: the command line of the merge (distribution/merge.hpp).
#include <iostream>

#include "arguments.hpp"
#include "commands.hpp"
#include "core/errors.hpp"
#include "distribution/merge.hpp"

namespace rotbeam::cli {

int command_merge(const std::vector<std::string>& args) {
    const CommandSpec spec{
        "merge",
        "SHARD_DIR...",
        1,
        -1,
        "Combine the shard folders of one `rotbeam suite|study|sweep ... --shard I/N` job into the "
        "output of one run (results, studies, report; docs/distributed-runs.md). A damaged "
        "shard file is refused by name (exit 2); missing runs are listed with the commands that "
        "make them (exit 5); in both cases nothing is written.",
        {{"out", "DIR", "output folder (required)"}}};
    const ParsedArguments a = parse_arguments(spec, args);
    if (a.help) {
        std::cout << help_text(spec);
        return 0;
    }
    const auto out = a.value("out");
    if (!out) throw InputError("rotbeam merge: --out DIR: required (where the merged output goes)");
    return merge_shard_folders(a.positional, *out);
}

}  // namespace rotbeam::cli
