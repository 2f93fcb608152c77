// Progress of long work (`rotbeam suite`, `study`, `bench`): how many items of how many are
// done, which is running, the time spent and an estimate of the time left.
//
// On a terminal it is one line that is redrawn in place (carriage return, clear to the end of the
// line) at every event and every second; elsewhere (a CI log, a file) it is a plain line, at most
// one per interval (10 s by default), so that a log shows that work goes on without filling up.
// The lines go to stderr: stdout keeps the commands' own output (tables, file names).
//
// The estimate of the time left is the mean time per finished item times the items left, or from
// the items' expected run times when the caller knows them (set_total_cost): it is an estimate
// and printed as "about".
#pragma once

#include <condition_variable>
#include <functional>
#include <mutex>
#include <ostream>
#include <string>
#include <thread>
#include <vector>

namespace rotbeam::cli {

struct ProgressOptions {
    bool terminal = false;           // redraw one line in place; otherwise a line per interval
    double interval_seconds = 10.0;  // non-terminal: at most one line per this many seconds
    // Monotonic seconds; injectable so that a test can advance time without waiting.
    std::function<double()> clock;
    bool ticker = true;  // a thread that prints while no item starts or ends (long runs)
};

// The options for stderr: terminal when stderr is a terminal, the real steady clock, the ticker.
ProgressOptions progress_options_for_stderr();

class Progress {
  public:
    // `what` opens every line ("rotbeam suite"); `total` items.
    Progress(std::string what, size_t total, std::ostream& out, ProgressOptions options);
    ~Progress();  // stops the ticker, ends the terminal line
    Progress(const Progress&) = delete;
    Progress& operator=(const Progress&) = delete;

    // An item starts or finishes (thread-safe). `cost`: its expected run time in seconds, for
    // the estimate of the time left; 0 for "like the others".
    void started(const std::string& item);
    void finished(const std::string& item, double cost = 0.0);
    // The expected run time of all items in seconds, when the caller knows it: the time left is
    // then the time spent scaled by the cost left over the cost done, and before the first item
    // ends, the expected time minus the time spent.
    void set_total_cost(double seconds);
    // Prints if a line is due (what the ticker calls every second).
    void poll();
    // The line as it would be printed now (the facts: done/total, current item, elapsed, left).
    std::string line() const;

  private:
    void print_locked(bool force);
    std::string line_locked() const;
    double now() const;

    std::string what_;
    size_t total_;
    std::ostream& out_;
    ProgressOptions options_;
    double start_ = 0.0;
    double last_print_ = -1.0;  // < 0: nothing printed yet
    size_t done_ = 0;
    double cost_done_ = 0.0, total_cost_ = 0.0;
    std::vector<std::string> running_;
    mutable std::mutex mutex_;
    std::condition_variable stop_signal_;
    bool stopping_ = false;
    std::thread ticker_;
};

// Seconds as people read them: "42 s", "3 min 05 s", "1 h 02 min".
std::string human_seconds(double seconds);

}  // namespace rotbeam::cli
