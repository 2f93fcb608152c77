// Progress of long work (`rotbeam suite`, `study`, `bench`): how many items of how many are
// done, which is running, the time spent and an estimate of the time left.
//
// On a terminal it is one line that is redrawn in place (carriage return, clear to the end of the
// line) at every event and every second; elsewhere (a CI log, a file) it is a plain line, at most
// one per interval (10 s by default), so that a log shows that work goes on without filling up.
// The lines go to stderr: stdout keeps the commands' own output (tables, file names).
//
// The estimate of the time left weighs the items by their expected run times when the caller knows
// them (set_total_cost, started), else counts them as equal (runs/time_left.hpp); it is an
// estimate and printed as "about", and "(expected)" while it rests on the cost model alone.
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
    int workers = 0;     // threads running the items at once; 0: unknown (estimated as they run)
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

    // An item starts, finishes, or is found done already (skipped: a result of an earlier
    // run; its cost leaves the total and it tells nothing of the speed). Thread-safe. `cost`: its
    // expected run time in seconds (with set_total_cost; else every item weighs the same).
    // `alone`: it runs after the pool's items, one at a time (a timed study, a combine step).
    void started(const std::string& item, double cost = 0.0, bool alone = false);
    void finished(const std::string& item);
    void skipped(const std::string& item);
    // The expected run time of all items in seconds, those of the pool and those run alone, when
    // the caller knows it: the time left then follows the cost left (runs/time_left.hpp).
    void set_total_cost(double pooled_seconds, double alone_seconds = 0.0);
    // Prints if a line is due (what the ticker calls every second).
    void poll();
    // The line as it would be printed now (the facts: done/total, current item, elapsed, left).
    std::string line() const;

  private:
    struct Running {
        std::string item;
        double start = 0.0, cost = 0.0;
        bool alone = false;
    };

    void print_locked(bool force);
    std::string line_locked() const;
    double now() const;
    // finished (worked) or skipped.
    void end(const std::string& item, bool worked);

    std::string what_;
    size_t total_;
    std::ostream& out_;
    ProgressOptions options_;
    double start_ = 0.0;
    double last_print_ = -1.0;  // < 0: nothing printed yet
    size_t done_ = 0;
    bool costs_known_ = false;
    // Expected cost of the items not finished (running or not started), of the pool and alone;
    // of the finished ones and the wall time they ran.
    double pooled_left_ = 0.0, alone_left_ = 0.0, finished_cost_ = 0.0, finished_seconds_ = 0.0;
    std::vector<Running> running_;
    mutable std::mutex mutex_;
    std::condition_variable stop_signal_;
    bool stopping_ = false;
    std::thread ticker_;
};

// Seconds as people read them: "42 s", "3 min 05 s", "1 h 02 min".
std::string human_seconds(double seconds);

}  // namespace rotbeam::cli
