// The estimate of the time left (runs/time_left.hpp) against the true time left of a simulated
// pool: items of known cost run by k workers, each taking the next item when it is free (as
// for_each_parallel does), at a speed the estimate does not know, then the items run alone.
#include <algorithm>
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "runs/progress.hpp"
#include "runs/time_left.hpp"

using namespace rotbeam::cli;

namespace {

struct SimulatedEvent {
    double time;
    bool start;
    size_t item;
};

// The starts and ends of items that take `pooled` seconds (wall time) on `workers` workers, each
// taking the next item when it is free, in order, then of `alone` one after the other; the items
// are numbered pooled first.
std::vector<SimulatedEvent> simulate_durations(const std::vector<double>& pooled,
                                               const std::vector<double>& alone, int workers) {
    std::vector<SimulatedEvent> events;
    std::vector<double> free_at(static_cast<size_t>(workers), 0.0);
    for (size_t i = 0; i < pooled.size(); ++i) {
        const auto w = std::min_element(free_at.begin(), free_at.end());
        events.push_back({*w, true, i});
        *w += pooled[i];
        events.push_back({*w, false, i});
    }
    double t = *std::max_element(free_at.begin(), free_at.end());
    for (size_t i = 0; i < alone.size(); ++i) {
        events.push_back({t, true, pooled.size() + i});
        t += alone[i];
        events.push_back({t, false, pooled.size() + i});
    }
    // Ends before starts at the same time: a worker frees itself, then takes the next item.
    std::stable_sort(events.begin(), events.end(), [](const auto& a, const auto& b) {
        return a.time < b.time || (a.time == b.time && !a.start && b.start);
    });
    return events;
}

// The same for items of known cost (`pooled`, `alone`) that all run at `speed` (cost per second).
std::vector<SimulatedEvent> simulate_pool(const std::vector<double>& pooled,
                                          const std::vector<double>& alone, int workers,
                                          double speed) {
    const auto seconds = [speed](std::vector<double> costs) {
        for (double& c : costs) c /= speed;
        return costs;
    };
    return simulate_durations(seconds(pooled), seconds(alone), workers);
}

// The seconds of "about … left" in a progress line ("1 h 02 min", "3 min 05 s", "42 s").
double seconds_in(const std::string& line) {
    const size_t about = line.find("about ");
    BOOST_REQUIRE_MESSAGE(about != std::string::npos, line);
    std::istringstream in(line.substr(about + 6));
    double seconds = 0.0, value = 0.0;
    std::string unit;
    while (in >> value >> unit && unit != "left") {
        seconds += value * (unit == "h" ? 3600.0 : unit == "min" ? 60.0 : 1.0);
    }
    return seconds;
}

ProgressOptions simulated_options(const double& now, int workers) {
    ProgressOptions o;
    o.clock = [&now] { return now; };
    o.ticker = false;
    o.interval_seconds = 1e9;  // nothing printed: the test reads line()
    o.workers = workers;
    return o;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(time_left)

// The suite's studies: two whole studies (hours of one core in the full suite, first in the
// pool), a thousand short runs, then a combine step and the timed study alone; two workers, the
// machine twice as slow as the cost model. The first item to end is a whole study, while the
// other is two thirds done. At every end from then on the speed is measured exactly (all items
// run at the same speed), so the estimate can only miss the pool's shape: it takes the pool as
// busy to the end, so it is a lower bound of the list schedule's time, and by Graham's bound of
// list scheduling (R. L. Graham, SIAM J. Appl. Math. 17, 1969) the schedule ends at most one
// item's time after that bound. The progress line rounds to the second (or the minute past an
// hour): 60 s of slack. At the first end (600 s, 1 350 s left) "time spent × items left / items
// done" gave 167 h, and "time spent × cost left / cost done" 51 min: both more than twice off.
BOOST_AUTO_TEST_CASE(the_time_left_follows_the_costs_from_the_first_item_to_end) {
    std::vector<double> pooled = {400.0, 300.0};
    pooled.insert(pooled.end(), 1000, 1.0);
    const std::vector<double> alone = {5.0, 120.0};
    const double speed = 0.5;
    const std::vector<SimulatedEvent> events = simulate_pool(pooled, alone, 2, speed);
    const double end = events.back().time;
    double now = 0.0;
    std::ostringstream out;
    Progress p("rotbeam suite: studies", pooled.size() + alone.size(), out,
               simulated_options(now, 2));
    p.set_total_cost(1700.0, 125.0);
    bool first = true;
    for (const SimulatedEvent& e : events) {
        now = e.time;
        const std::string item = "item " + std::to_string(e.item);
        if (e.start) {
            const bool is_alone = e.item >= pooled.size();
            p.started(item, is_alone ? alone[e.item - pooled.size()] : pooled[e.item], is_alone);
            continue;
        }
        p.finished(item);
        if (e.time == end) break;
        const double estimate = seconds_in(p.line());
        const double actual = end - now;
        if (first) {
            BOOST_TEST_MESSAGE("first end at " << now << " s: " << p.line() << "; actual " << actual
                                               << " s");
            BOOST_TEST(estimate > actual / 2);
            BOOST_TEST(estimate < actual * 2);
            first = false;
        }
        // The largest item not yet ended, at this speed: the most the schedule's end can lie
        // past its lower bound.
        double longest = 0.0;
        for (const SimulatedEvent& later : events) {
            if (later.time > now && !later.start && later.item < pooled.size())
                longest = std::max(longest, pooled[later.item] / speed);
        }
        BOOST_TEST(estimate <= actual + 60.0, p.line() << " (actual " << actual << " s)");
        BOOST_TEST(actual <= estimate + longest + 60.0, p.line() << " (actual " << actual << " s)");
    }
}

// A result of an earlier run, found done at once, is no sign of speed: its cost leaves the
// total. Three items of 10 s, the first skipped, the second run in 20 s (half the model's
// speed): the third takes 20 s more. Counted as done work, it made the speed twice the true one
// and the estimate 10 s.
BOOST_AUTO_TEST_CASE(a_skipped_item_leaves_the_total_but_tells_nothing_of_the_speed) {
    double now = 0.0;
    std::ostringstream out;
    Progress p("rotbeam suite", 3, out, simulated_options(now, 1));
    p.set_total_cost(30.0);
    for (const char* item : {"a", "b"}) p.started(item, 10.0);
    p.skipped("a");
    now = 20.0;
    p.finished("b");
    BOOST_TEST(p.line() == "rotbeam suite: 2/3 done, 20 s elapsed, about 20 s left");
}

// Before any item has ended the estimate is the model's, marked "(expected)"; items that have run
// longer than their cost slow it down: two items of 0.2 s running for 10 s each make the speed at
// most 0.02, and being overdue they are expected to run as long again (10 s each, 0.2 of cost at
// that speed), so the 4 s of cost left on two workers take 100 s. (Before overdue items ran as
// long again, they were taken as about to end: 90 s.)
BOOST_AUTO_TEST_CASE(items_running_past_their_cost_slow_the_expected_speed) {
    WorkSoFar w;
    w.elapsed = 10.0;
    w.pooled_cost_left = 4.0;
    w.running = {{0.2, 10.0, false}, {0.2, 10.0, false}};
    w.workers = 2;
    w.cost_in_seconds = true;
    const auto left = estimate_time_left(w);
    BOOST_REQUIRE(left.has_value());
    BOOST_TEST(left->expected);
    BOOST_TEST(left->seconds == 100.0, boost::test_tools::tolerance(1e-12));
    // On time (each at 0.1 s of its 0.2 s): the model's speed, 3.8 s of cost on two workers.
    w.running = {{0.2, 0.1, false}, {0.2, 0.1, false}};
    BOOST_TEST(estimate_time_left(w)->seconds == 1.9, boost::test_tools::tolerance(1e-12));
}

// An item that runs four times its expected cost, alone at the end of the pool: the other 50
// items (4 s each, the model right: speed 1) end at 200 s on the second worker, the long one
// (expected 100 s) at 400 s. From 100 s on it is overdue and expected to run as long again as it
// has run, so at time t the estimate is t (at least) where the truth is 400 − t: never below a
// third of it (t / (400 − t) ≥ 100 / 300 from 100 s on, the bound 1/(k − 1) of an item that runs
// k times its cost), with a second of the line's rounding. Counted as done once its cost was
// spent, it made the line say "about 0 s left" from 200 s to 400 s.
BOOST_AUTO_TEST_CASE(an_overdue_item_is_expected_to_run_as_long_again) {
    std::vector<double> costs = {100.0}, seconds = {400.0};
    costs.insert(costs.end(), 50, 4.0);
    seconds.insert(seconds.end(), 50, 4.0);
    const std::vector<SimulatedEvent> events = simulate_durations(seconds, {}, 2);
    const double end = events.back().time;
    BOOST_TEST_REQUIRE(end == 400.0);
    double now = 0.0;
    std::ostringstream out;
    Progress p("rotbeam suite", costs.size(), out, simulated_options(now, 2));
    p.set_total_cost(300.0);
    size_t next = 0;
    for (double t = 1.0; t < end; t += 1.0) {
        for (; next < events.size() && events[next].time <= t; ++next) {
            now = events[next].time;
            const SimulatedEvent& e = events[next];
            const std::string item = "item " + std::to_string(e.item);
            if (e.start) {
                p.started(item, costs[e.item]);
            } else {
                p.finished(item);
            }
        }
        now = t;
        if (t <= 100.0) continue;  // the long item is not overdue yet
        const double estimate = seconds_in(p.line());
        const double actual = end - t;
        BOOST_TEST(estimate >= actual / 3.0 - 1.0, p.line() << " (actual " << actual << " s)");
        BOOST_TEST(estimate >= 1.0, p.line());
    }
}

// Without costs in seconds nothing is known before the first item ends.
BOOST_AUTO_TEST_CASE(without_costs_the_time_left_waits_for_the_first_item) {
    WorkSoFar w;
    w.elapsed = 5.0;
    w.pooled_cost_left = 3.0;
    w.running = {{1.0, 5.0, false}};
    BOOST_TEST(!estimate_time_left(w).has_value());
}

BOOST_AUTO_TEST_SUITE_END()
