// The estimate of the time left of long work made of items (runs/progress.hpp): a suite's runs, a
// study's runs and whole studies, the units of a shard.
//
// Each item has an expected cost: seconds of one core from the cost model (runs/estimate_cost.hpp,
// the studies' table in distribution/study_cost.hpp), or 1 when the caller knows no costs (then an
// item is like any other). The items done so far give the speed v = their expected cost over the
// wall time they ran, item by item: how much faster or slower than the model one worker goes on
// this machine now. The time left is then the cost left over v, divided among the workers:
//
//   left = max( pooled cost left / (v k), largest cost left of one running item / v )
//          + cost left of the items run alone / v
//
// with k the worker threads (or, unknown, the mean number of items running so far), and the items
// run alone (a timed study, a combine step: after the pool, one at a time) added in sequence. A
// running item's cost left is its cost less v times the time t it has run; once that is spent
// (the item is overdue: the model was wrong about it, by an unknown factor) it is expected to run
// as long again, v t: all that is known of it is t, and "as long again" is the median rest of a
// duration observed at a random moment of its course, whatever its scale (J. R. Gott, Nature 363,
// 315, 1993: with probability 1/2 the rest lies between t/3 and 3 t). Before any item has ended,
// v is 1 (the model is right), or less when the running items have already run longer than their
// cost: then their cost over the time they ran (the fastest the machine can be); an item is then
// overdue when it has run longer than its cost.
//
// Why not the time spent times the share left: the items are far from equal (a whole study is
// hours of one core, a study run milliseconds), and the first to end is often the longest, run
// in parallel with others that are half done; "elapsed × items left / items done" then printed
// 138 h for a suite that had less than an hour left.
#pragma once

#include <optional>
#include <vector>

namespace rotbeam::cli {

struct RunningItem {
    double cost = 0.0;     // expected cost
    double seconds = 0.0;  // wall time it has run so far
    bool alone = false;    // run after the pool, one at a time
};

struct WorkSoFar {
    double elapsed = 0.0;                                  // wall seconds since the work began
    double pooled_cost_left = 0.0, alone_cost_left = 0.0;  // of the unfinished items (running too)
    double finished_cost = 0.0;     // expected cost of the items finished (skipped ones left out)
    double finished_seconds = 0.0;  // the wall time those items ran, summed item by item
    std::vector<RunningItem> running;
    double workers = 0.0;          // threads of the pool; 0: the mean number of items running
    bool cost_in_seconds = false;  // costs are expected seconds (else each item costs 1)
};

struct TimeLeft {
    double seconds = 0.0;
    bool expected = false;  // no item has finished: the costs are taken as the seconds they say
};

// The time left (above); none while nothing has finished and the costs are not in seconds.
std::optional<TimeLeft> estimate_time_left(const WorkSoFar& w);

}  // namespace rotbeam::cli
