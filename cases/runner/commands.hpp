// The program's commands (docs/architecture.md, The program and its results). Each returns the exit
// code: 0 ran (whatever the solver status), 1 a verify miss, 2 bad input (InputError, caught in
// main with its one-line message).
#pragma once

#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "runs/catalog.hpp"  // the catalog lookup the commands share

namespace rotbeam::cli {

using Args = std::vector<std::string>;
using Command = int (*)(const Args&);

int command_list(const Args& args);
int command_check(const Args& args);
int command_run(const Args& args);
int command_suite(const Args& args);
int command_verify(const Args& args);
int command_reference(const Args& args);
int command_study(const Args& args);
int command_bench(const Args& args);   // bench_command.cpp
int command_import(const Args& args);  // import_command.cpp
int command_sweep(const Args& args);   // sweep_command.cpp
int command_merge(const Args& args);   // merge_command.cpp
// completion.cpp: `rotbeam completion bash`, from `commands` (name → command) and their options.
int command_completion_with(const Args& args, const std::map<std::string, Command>& commands);

}  // namespace rotbeam::cli
