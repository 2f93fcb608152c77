// Other programs that rotbeam runs (gnuplot for the figures), stopped with it (docs/durability.md).
//
// A child started by run_child_process is registered until it has ended. A program stopped by a
// signal calls stop_child_processes() before removing its temporaries: every child still running
// is killed and waited for, so none writes a file after rotbeam has cleaned up and exited. A child
// does not leave with its parent otherwise: it inherits the signals rotbeam blocks, and SIGTERM
// or SIGHUP sent to rotbeam alone never reaches it.
#pragma once

#include <string>
#include <vector>

namespace rotbeam {

// Runs `arguments` (the first looked up in PATH, as a shell would) with its standard error
// written to the file `error_path`, waits for it, and returns its wait status (as waitpid gives
// it); -1 if it could not be started. Blocks forever once stop_child_processes() has run.
int run_child_process(const std::vector<std::string>& arguments, const std::string& error_path);

// Kills (SIGKILL) every child of run_child_process still running, waits until each has ended,
// and blocks every later start. Only for a program about to exit.
void stop_child_processes();

}  // namespace rotbeam
