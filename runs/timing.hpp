// The one timing harness: medians of repeated runs, in-process
// time, whole-process time (the rotbeam executable itself run as a child through /proc/self/exe)
// and peak memory (getrusage / wait4 of the child). Used by the studies and by `rotbeam bench`.
//
// Why medians: the machine is shared (2 cores, other builds running); the median of repeats is
// robust against the occasional descheduled run, where the mean is not.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace rotbeam::cli {

// Median of the samples (mean of the two middle ones for an even count). API misuse
// (ROTBEAM_VERIFY) when empty.
double median(std::vector<double> samples);

struct Timing {
    double median_seconds = 0.0;
    double min_seconds = 0.0;
    int repeats = 0;
    long peak_rss_kb = 0;  // whole-process: largest child max RSS; in-process: this process's
    int exit_code = 0;     // whole-process: the child's exit code of the last repeat
    // Whole-process: median of the child's user + system CPU time (wait4's rusage), which a
    // shared machine inflates far less than the wall time. 0 in process.
    double median_cpu_seconds = 0.0;
};

// How many timed repeats a measurement that wants `wanted` makes: `wanted`, or fewer when
// ROTBEAM_TIMING_REPEATS caps them (a positive integer; at least one repeat either way). The cap
// is for the tests that run a timed study only for what it computes (the quick suite's
// `speed-accuracy`: tests/runner/quick_suite.sh and the tests that run the suite again), whose
// timings scripts/compare-results.py never compares: its repeats are most of the suite's time and
// check nothing there. Unset, nothing changes. A value that is not a positive integer is an
// InputError naming the variable. Every loop of timed repeats goes through here.
int timing_repeats(int wanted);

// Wall time (steady clock) of `work`, repeated `repeats` times (at least once), median.
// `budget_seconds` > 0 stops repeating once that much time has been spent (after one run); the
// repeats are capped by timing_repeats.
Timing time_in_process(const std::function<void()>& work, int repeats, double budget_seconds = 0.0);

// Whole-process wall time: this executable run with `arguments` as a registered child
// (core/child_process.hpp, stopped with rotbeam; stdout/stderr to /dev/null), waited for; the
// median over `repeats` (timing_repeats), and the child's peak RSS.
Timing time_whole_process(const std::vector<std::string>& arguments, int repeats,
                          double budget_seconds = 0.0);

// This process's peak resident set [kB] so far (getrusage RUSAGE_SELF).
long peak_rss_self_kb();

// Why the child reports its own peak: the kernel's ru_maxrss of a child (wait4) includes the
// RSS the child inherited from this process at fork (Linux keeps the high-water mark across
// exec), so a benchmark with a large parent would report the parent's size. The rotbeam program
// calls this first thing in main: when ROTBEAM_PEAK_RSS_FILE is set it writes its own VmHWM [kB]
// (/proc/self/status, a fresh mm after exec) to that file at exit.
void report_peak_rss_at_exit();

}  // namespace rotbeam::cli
