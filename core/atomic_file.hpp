// Output files that are never seen half-written (docs/durability.md).
//
// Every result, CSV, data and report file goes through write_file_atomically: the text is written
// to a temporary file in the target's directory, flushed to the disk (fsync), checked for write
// errors (a full disk, ENOSPC; a file size limit, EFBIG), and renamed over the target. A reader
// therefore sees the old file or the complete new one, never a prefix. A failed write throws
// OutputError naming the file and removes the temporary.
//
// A program stopped by a signal calls stop_writes_and_remove_temporaries() first: it removes the
// temporaries of writes in flight in any thread (a figure's too, those its writer has created) and
// makes every later write wait forever, so nothing partial is left behind when the process then
// exits.
#pragma once

#include <functional>
#include <string>

namespace rotbeam {

// Writes `text` to `path` atomically (above). Creates the parent directories. Throws OutputError.
void write_file_atomically(const std::string& path, const std::string& text);

// The same for files written by another program (gnuplot's figures), named by a base path and a
// suffix each (`BASE.png`, `BASE-tip.svg`): `write` is called with a temporary base next to
// `target_base` (".NAME.rotbeam-tmp.PID.N_") and writes its files as that base + suffix. Each file
// it wrote is then flushed to the disk and renamed to `target_base` + suffix. If `write` throws,
// its files are removed and the exception propagates; a failed flush or rename removes the files
// not yet renamed and throws OutputError naming the target. `complete(file)`, when given, says
// whether a file the writer left is whole: a program that does not check its writes (gnuplot, past
// a file size limit or on a full disk, exits 0 with a figure cut short) cannot be trusted to fail.
// Every file is checked before any is renamed; one that is not whole fails the write the same way,
// with the likely reason (the file size limit it reached, a full disk).
void write_files_atomically(const std::string& target_base,
                            const std::function<void(const std::string& temporary_base)>& write,
                            const std::function<bool(const std::string& file)>& complete = {});

// Removes the temporaries of every write in flight and blocks all further writes (never
// returns the lock). Only for a program about to exit.
void stop_writes_and_remove_temporaries();

// Removes temporaries left in `directory` and its subfolders by a rotbeam process that no longer
// runs (one killed with SIGKILL in the middle of a write). Returns how many were removed.
int remove_stale_temporaries(const std::string& directory);

}  // namespace rotbeam
