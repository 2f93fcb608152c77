// SIGINT, SIGTERM and SIGHUP stop rotbeam cleanly (docs/durability.md): the files already written
// stay (each was written atomically), the temporaries of writes in flight are removed, one line
// on stderr names the signal, and the exit code is 128 + the signal's number (130 for SIGINT,
// 143 for SIGTERM). SIGXFSZ is ignored, so a file size limit (ulimit -f) makes the write fail
// with EFBIG, which is reported, instead of killing the program in the middle of a file.
#pragma once

namespace rotbeam::cli {

// Call first in main, before any thread starts: the signals are blocked in every thread and
// taken by one watcher thread. A signal the parent set to be ignored (a background job of a
// non-interactive shell) stays ignored.
void install_interrupt_handling();

}  // namespace rotbeam::cli
