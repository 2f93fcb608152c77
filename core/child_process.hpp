// Other programs that rotbeam runs (gnuplot for the figures, rotbeam itself for the whole-process
// timings of `rotbeam bench`), stopped with it (docs/durability.md). Every child rotbeam starts
// goes through run_child_process: there is no other fork, exec, system() or popen.
//
// A child started by run_child_process is registered until it has ended, and the files it writes
// for its caller (its standard error, a report) until the caller has read them. A program stopped
// by a signal calls stop_child_processes() before removing its temporaries: every child still
// running is killed and waited for, so none writes a file after rotbeam has cleaned up and exited,
// and the registered files are removed. A child does not leave with its parent otherwise: it
// inherits the signals rotbeam blocks, and SIGTERM or SIGHUP sent to rotbeam alone never reaches
// it.
#pragma once

#include <sys/resource.h>

#include <functional>
#include <string>
#include <vector>

namespace rotbeam {

// How a child ends: its wait status (as waitpid gives it; -1 if it could not be started or
// waited for) and the resources it used (wait4's rusage).
struct ChildExit {
    int status = -1;
    rusage usage{};
};

struct ChildSpec {
    // The program and its arguments: the first looked up in PATH unless it names a path, as a
    // shell would (no shell runs).
    std::vector<std::string> arguments;
    // Files its standard output and standard error are written to (created, truncated); "" keeps
    // rotbeam's own.
    std::string output_path, error_path;
    // NAME=VALUE, each replacing the variable NAME of rotbeam's environment in the child's.
    std::vector<std::string> environment;
    // Files the child writes for its caller (error_path among them when the caller reads it):
    // removed once `read` has returned, or by stop_child_processes().
    std::vector<std::string> side_files;
    // Called when the child has ended, with its side files still in place (may be empty).
    std::function<void(const ChildExit&)> read;
};

// Runs the child described by `spec`, waits for it, calls spec.read, removes its side files and
// returns how it ended. Blocks forever once stop_child_processes() has run.
ChildExit run_child_process(const ChildSpec& spec);

// Kills (SIGKILL) every child of run_child_process still running, waits until each has ended,
// removes every side file still registered and blocks every later start. Only for a program
// about to exit.
void stop_child_processes();

}  // namespace rotbeam
