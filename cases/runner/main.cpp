// The rotbeam program. Bad input → one line on stderr naming the file/option and the problem, exit
// code 2, no partial output; anything unexpected → exit 3 with the message (a bug); an output file
// that cannot be written (full disk, file size limit) → exit 4 with its name, nothing partial left;
// stopped by SIGINT/SIGTERM/SIGHUP → exit 128 + signal (interrupt.hpp); `merge` with runs missing
// from its shard folders → exit 5 (distributed.hpp).
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "arguments.hpp"
#include "cases/loader/yaml_reader.hpp"
#include "commands.hpp"
#include "core/errors.hpp"
#include "core/results.hpp"
#include "core/version.hpp"
#include "dependency_versions.hpp"
#include "distribution/distributed.hpp"
#include "distribution/ranks.hpp"
#include "distribution/study_registry.hpp"
#include "interrupt.hpp"
#include "runs/timing.hpp"

namespace {

using rotbeam::cases::one_line;  // a message quoting what the user wrote stays one line
using rotbeam::cli::Command;

int command_completion(const rotbeam::cli::Args& args);

const std::map<std::string, std::pair<Command, std::string>>& commands() {
    using namespace rotbeam::cli;
    static const std::map<std::string, std::pair<Command, std::string>> table = {
        {"list", {command_list, "list cases, parameterizations and formulations"}},
        {"check", {command_check, "validate a case file and describe the model"}},
        {"import", {command_import, "translate a BeamDyn input deck into a case file"}},
        {"run", {command_run, "run a case with one parameterization and formulation"}},
        {"suite", {command_suite, "run the benchmark suite and write the report"}},
        {"merge",
         {command_merge, "combine the shard folders of a suite, study or sweep into one output"}},
        {"sweep", {command_sweep, "run a sweep file: cases × combinations × ranges of case keys"}},
        {"verify", {command_verify, "compare against published numbers (exit 1 on a miss)"}},
        {"reference", {command_reference, "continuum reference solution of a static case"}},
        {"study", {command_study, "run a study (" + study_name_list() + ")"}},
        {"bench", {command_bench, "time-to-solution benchmark (static and joined-beam targets)"}},
        {"completion", {command_completion, "print the bash completion script"}},
    };
    return table;
}

int command_completion(const rotbeam::cli::Args& args) {
    std::map<std::string, Command> table;
    for (const auto& [name, entry] : commands()) table[name] = entry.first;
    return rotbeam::cli::command_completion_with(args, table);
}

void print_usage(std::ostream& os) {
    os << "rotbeam " << rotbeam::kGitDescribe
       << " — verification testbed for geometrically exact beams\n\nusage: rotbeam COMMAND "
          "[options]   (rotbeam COMMAND --help for details)\n\ncommands:\n";
    for (const auto& [name, entry] : commands()) {
        std::string left = "  " + name;
        left.resize(14, ' ');
        os << left << entry.second << "\n";
    }
}

}  // namespace

int main(int argc, char** argv) {
    rotbeam::cli::install_interrupt_handling();  // before any thread starts
    rotbeam::cli::report_peak_rss_at_exit();     // only under `rotbeam bench` (timing.hpp)
    const std::vector<std::string> all(argv + 1, argv + argc);
    if (all.empty()) {
        std::cerr << "rotbeam: missing command; see 'rotbeam --help'\n";
        return 2;
    }
    if (all[0] == "--help" || all[0] == "-h" || all[0] == "help") {
        print_usage(std::cout);
        return 0;
    }
    if (all[0] == "--version") {
        std::cout << "rotbeam " << rotbeam::kGitDescribe << " (JSON schema_version "
                  << rotbeam::kSchemaVersion << ")\nbuilt with:\n"
                  << rotbeam::cli::dependency_versions() << "  " << rotbeam::cli::mpi_description()
                  << "\n";
        return 0;
    }
    const auto it = commands().find(all[0]);
    try {
        if (it == commands().end()) {
            std::vector<std::string> names;
            for (const auto& [name, entry] : commands()) names.push_back(name);
            const std::string guess = rotbeam::cli::closest_match(all[0], names);
            throw rotbeam::InputError("rotbeam: unknown command '" + all[0] + "'" +
                                      (guess.empty() ? "" : " (did you mean '" + guess + "'?)"));
        }
        return it->second.first(std::vector<std::string>(all.begin() + 1, all.end()));
    } catch (const rotbeam::InputError& e) {
        std::cerr << one_line(e.what()) << "\n";
        return 2;
    } catch (const rotbeam::OutputError& e) {
        std::cerr << "rotbeam: " << one_line(e.what()) << "\n";
        return 4;
    } catch (const std::exception& e) {
        std::cerr << "rotbeam: internal error: " << one_line(e.what()) << "\n";
        return 3;
    }
}
