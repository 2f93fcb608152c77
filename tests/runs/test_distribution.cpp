// Splitting runs into shards (runs/shards.hpp) and the progress lines of long work
// (runs/progress.hpp).
#define BOOST_TEST_MODULE rotbeam distribution
#include <boost/test/unit_test.hpp>
#include <regex>
#include <sstream>

#include "core/errors.hpp"
#include "runs/estimate_cost.hpp"
#include "runs/progress.hpp"
#include "runs/shards.hpp"

using namespace rotbeam;
using namespace rotbeam::cli;

BOOST_AUTO_TEST_SUITE(shards)

BOOST_AUTO_TEST_CASE(parse_shard_accepts_i_of_n_and_refuses_the_rest) {
    const Shard s = parse_shard("suite", "2/3");
    BOOST_TEST(s.index == 2);
    BOOST_TEST(s.count == 3);
    for (const char* bad : {"", "3", "0/3", "4/3", "1/0", "a/3", "1/3x", "-1/3", "1.5/3", "/3"})
        BOOST_CHECK_THROW(parse_shard("suite", bad), InputError);
}

// LPT on a case whose optimum is known by hand: {7, 5, 4, 3, 3, 2} on two machines. LPT gives
// 7+3+2 = 12 and 5+4+3 = 12 — the optimum (24 / 2), every item once.
BOOST_AUTO_TEST_CASE(longest_first_balances_a_hand_checked_case) {
    const std::vector<double> seconds = {3, 7, 2, 5, 3, 4};
    const std::vector<int> shard = assign_longest_first(seconds, 2);
    double load[2] = {0, 0};
    for (size_t i = 0; i < seconds.size(); ++i) load[shard[i]] += seconds[i];
    BOOST_TEST(load[0] == 12.0);
    BOOST_TEST(load[1] == 12.0);
    BOOST_TEST(shard[1] == 0);  // the longest item goes to the first shard
}

// Graham's bound: LPT's make-span ≤ (4/3 − 1/(3N)) × optimum ≤ (4/3) × max(mean load, longest
// item); checked on a deterministic pseudo-random set, with every item in exactly one shard, and
// the split the same when computed again (no state between calls).
BOOST_AUTO_TEST_CASE(longest_first_is_deterministic_and_within_grahams_bound) {
    std::vector<double> seconds;
    unsigned x = 12345;
    for (int i = 0; i < 113; ++i) {
        x = x * 1103515245u + 12345u;
        seconds.push_back(0.01 + (x >> 16) % 1000 / 100.0);
    }
    for (int n : {1, 2, 3, 7, 200}) {
        const std::vector<int> a = assign_longest_first(seconds, n);
        BOOST_TEST(a == assign_longest_first(seconds, n));
        std::vector<double> load(n, 0.0);
        double total = 0.0, longest = 0.0;
        for (size_t i = 0; i < seconds.size(); ++i) {
            BOOST_TEST((a[i] >= 0 && a[i] < n));
            load[a[i]] += seconds[i];
            total += seconds[i];
            longest = std::max(longest, seconds[i]);
        }
        const double lower_bound = std::max(total / n, longest);  // no split does better
        const double makespan = *std::max_element(load.begin(), load.end());
        BOOST_TEST(makespan <= (4.0 / 3.0 - 1.0 / (3.0 * n)) * lower_bound + 1e-9);
    }
}

BOOST_AUTO_TEST_CASE(expected_seconds_prefers_measurements_and_scales_the_model) {
    // Items 0 and 1 measured at twice their modelled cost: the model is scaled by 2 for item 2.
    const std::vector<double> e = expected_seconds({1.0, 3.0, 5.0}, {2.0, 6.0, std::nullopt});
    BOOST_TEST(e[0] == 2.0);
    BOOST_TEST(e[1] == 6.0);
    BOOST_TEST(e[2] == 10.0);
    const std::vector<double> none = expected_seconds({1.0, 3.0}, {std::nullopt, std::nullopt});
    BOOST_TEST(none[1] == 3.0);
}

// A run with its error estimate is priced with it (runs/estimate_cost.hpp): the cost model's ratio
// with/without the estimate against the ratio measured on `rotbeam run … --quiet` (baseline binary
// bdc24a0, 2026-11-27; docs/distributed-runs.md, "Cost model"), callgrind instructions for the
// static and modal runs, CPU seconds (/usr/bin/time, user + sys) for the dynamic ones. The warm-
// started static displacement companions (and the mixed modal ones) are one measured factor per
// strategy, within 1.5× of each ratio measured; the others are priced from their plan, within
// 1.2× of the measured ratio. 1.6×
// either way bounds both; the plain pricing (ratio 1) misses every strategy but the high-order p+1.
BOOST_AUTO_TEST_CASE(an_estimated_run_is_priced_with_its_estimate) {
    struct Measured {
        const char* run;
        Formulation formulation;
        AnalysisKind kind;
        int order;
        double without, with;
    };
    const Measured measured[] = {
        {"bend-45, 2 x order 2", Formulation::displacement, AnalysisKind::static_, 2, 48464041,
         139925270},
        {"bend-45, 2 x order 4", Formulation::displacement, AnalysisKind::static_, 4, 131241746,
         169133779},
        {"cantilever-moment, 2 x order 3", Formulation::displacement, AnalysisKind::static_, 3,
         63802086, 135209467},
        {"bend-45, 2 x order 6", Formulation::displacement, AnalysisKind::static_, 6, 269658517,
         295499595},
        {"bend-45, 2 x order 8", Formulation::displacement, AnalysisKind::static_, 8, 443557679,
         478328677},
        {"cantilever-moment, 2 x order 6", Formulation::displacement, AnalysisKind::static_, 6,
         223426074, 272228608},
        {"bend-45, mixed 4", Formulation::mixed, AnalysisKind::static_, 1, 115890707, 785109996},
        {"joined-beam modes, 2 x order 2", Formulation::displacement, AnalysisKind::modal, 2,
         6980388, 32687009},
        {"joined-beam modes, 2 x order 6", Formulation::displacement, AnalysisKind::modal, 6,
         54694284, 131493292},
        {"joined-beam modes, mixed 5", Formulation::mixed, AnalysisKind::modal, 1, 37415076,
         1101593552},
        {"bend-45, mixed 16", Formulation::mixed, AnalysisKind::static_, 1, 455117521, 3124700133},
        {"free-vibration, displacement", Formulation::displacement, AnalysisKind::dynamic, 2, 0.31,
         1.66},
        {"joined-beam-dead, displacement", Formulation::displacement, AnalysisKind::dynamic, 1,
         1.38, 6.47},
        {"free-vibration, mixed", Formulation::mixed, AnalysisKind::dynamic, 1, 0.56, 5.01},
    };
    for (const Measured& m : measured) {
        Model model;
        model.members.resize(1);
        model.members[0].elements = 2;
        model.discretization.formulation = m.formulation;
        model.discretization.order = m.order;
        model.analysis.kind = m.kind;
        model.analysis.statics.load_factors = {1.0, 2.0};
        model.analysis.modal.modes = 5;
        model.analysis.dynamics.time_step = 0.01;
        model.analysis.dynamics.end_time = 1.0;
        const double priced = modelled_seconds(model, true) / modelled_seconds(model, false);
        const double ratio = m.with / m.without;
        BOOST_TEST(priced <= 1.6 * ratio, m.run << ": priced " << priced << ", measured " << ratio);
        BOOST_TEST(priced >= ratio / 1.6, m.run << ": priced " << priced << ", measured " << ratio);
    }
}

// The mixed formulation's price against the displacement formulation's on the catalog's cases at
// their own discretizations: the cost model's ratio mixed / displacement against the ratio
// measured on `rotbeam run CASE --formulation F --estimate off --quiet` (baseline binary
// 63e469b, quaternion, 2026-11-27, under `nice -n 19` at load 10–18; docs/distributed-runs.md,
// "Cost model"): callgrind instructions of the whole process for statics and modes, CPU seconds
// (/usr/bin/time, user + sys) for dynamics. One factor per analysis (run_cost.hpp) is the
// geometric mean of the smallest and largest fitted, so each case lies within √(largest /
// smallest) of it: 1.4× for statics and dynamics; 1.6× bounds them with the spread of a
// repeated timing (the dynamic ratios of one case vary by up to 1.3× between timings). The single
// factor 5 of before priced the static runs 2.7–4.0× and the modes 27× off (it passed only the
// linear dynamics).
BOOST_AUTO_TEST_CASE(a_mixed_run_is_priced_as_measured_against_a_displacement_one) {
    struct Measured {
        const char* run;
        AnalysisKind kind;
        std::vector<int> elements;  // per member
        int order;                  // of the displacement run
        int steps;                  // reported load factors × sub-steps, time steps, modes
        double displacement, mixed;
    };
    const Measured measured[] = {
        {"bend-45", AnalysisKind::static_, {16}, 3, 30, 868863487, 454992214},
        {"cantilever-moment", AnalysisKind::static_, {16}, 4, 28, 970219859, 350298824},
        {"cantilever-moment-4", AnalysisKind::static_, {16}, 4, 32, 1354565664, 400261065},
        {"helix", AnalysisKind::static_, {16}, 4, 32, 906173619, 402084537},
        {"joined-beam (midpoint mass)", AnalysisKind::modal, {10, 10}, 1, 5, 32248658, 1305742807},
        // Dynamics: the sums of three timings (one of the follower).
        {"free-vibration", AnalysisKind::dynamic, {8}, 2, 500, 1.11, 1.78},
        {"joined-beam-dead", AnalysisKind::dynamic, {10, 10}, 1, 2000, 4.09, 22.58},
        {"joined-beam-follower", AnalysisKind::dynamic, {10, 10}, 1, 2000, 1.55, 8.03},
        {"blade-mh104", AnalysisKind::dynamic, {10}, 1, 2000, 2.11, 12.11},
    };
    for (const Measured& m : measured) {
        Model model;
        for (const int e : m.elements) {
            model.members.emplace_back();
            model.members.back().elements = e;
        }
        model.analysis.kind = m.kind;
        model.analysis.statics.load_factors = std::vector<double>(static_cast<size_t>(m.steps));
        model.analysis.modal.modes = m.steps;
        model.analysis.dynamics.time_step = 1.0;
        model.analysis.dynamics.end_time = m.steps;
        model.discretization.formulation = Formulation::displacement;
        model.discretization.order = m.order;
        const double displacement = modelled_seconds(model);
        model.discretization.formulation = Formulation::mixed;
        const double priced = modelled_seconds(model) / displacement;
        const double ratio = m.mixed / m.displacement;
        BOOST_TEST(priced <= 1.6 * ratio, m.run << ": priced " << priced << ", measured " << ratio);
        BOOST_TEST(priced >= ratio / 1.6, m.run << ": priced " << priced << ", measured " << ratio);
    }
}

// FNV-1a 64 of "a" is af63dc4c8601ec8c (the published test vector of the FNV reference code).
BOOST_AUTO_TEST_CASE(stable_hash_is_fnv1a) {
    BOOST_TEST(stable_hash("") == "cbf29ce484222325");
    BOOST_TEST(stable_hash("a") == "af63dc4c8601ec8c");
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(progress)

namespace {

ProgressOptions log_options(double& now, double interval) {
    ProgressOptions o;
    o.terminal = false;
    o.interval_seconds = interval;
    o.clock = [&now] { return now; };
    o.ticker = false;
    return o;
}

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

}  // namespace

// Not a terminal: one plain line at the first event, then at most one per interval however many
// items start and finish, each with done/total, the current item, the time spent and left.
BOOST_AUTO_TEST_CASE(log_lines_come_at_most_once_per_interval_with_every_fact) {
    double now = 0.0;
    std::ostringstream out;
    {
        Progress p("rotbeam suite", 40, out, log_options(now, 10.0));
        for (int i = 0; i < 40; ++i) {
            const std::string item = "run-" + std::to_string(i);
            p.started(item);
            now += 0.75;  // 30 s in all: lines at 0, 10.5 (the first event ≥ 10 s later), 21
            p.finished(item);
            p.poll();
        }
    }
    const std::vector<std::string> lines = lines_of(out.str());
    BOOST_TEST(lines.size() == 3u);
    const std::regex format(
        "rotbeam suite: [0-9]+/40 done(, running [a-z0-9-]+( \\(\\+[0-9]+ more\\))?)?, "
        "[0-9]+ s elapsed, (about [0-9]+ s left( \\(expected\\))?|time left not yet known|"
        "nothing left)");
    for (const std::string& line : lines) BOOST_TEST(std::regex_match(line, format), line);
    BOOST_TEST(lines[0] ==
               "rotbeam suite: 0/40 done, running run-0, 0 s elapsed, time left not "
               "yet known");
    // At 10.5 s the 14th item ends: 0.75 s each, 26 left: about 19.5 s, printed rounded.
    BOOST_TEST(lines[1] == "rotbeam suite: 14/40 done, 11 s elapsed, about 20 s left");
}

// A long item with nothing starting or ending: the ticker's polls still print, once per interval.
BOOST_AUTO_TEST_CASE(polls_print_during_a_long_item) {
    double now = 0.0;
    std::ostringstream out;
    Progress p("rotbeam study", 2, out, log_options(now, 10.0));
    p.started("convergence");
    for (int second = 1; second <= 35; ++second) {
        now = second;
        p.poll();
    }
    const std::vector<std::string> lines = lines_of(out.str());
    BOOST_TEST(lines.size() == 4u);  // at 0, 10, 20, 30 s
    BOOST_TEST(lines[3] ==
               "rotbeam study: 0/2 done, running convergence, 30 s elapsed, time "
               "left not yet known");
}

// With the items' expected costs, the time left follows the cost left, not the item count.
BOOST_AUTO_TEST_CASE(time_left_follows_the_cost_when_known) {
    double now = 0.0;
    std::ostringstream out;
    Progress p("rotbeam suite", 3, out, log_options(now, 10.0));
    p.set_total_cost(10.0);
    p.started("long", 8.0);
    now = 8.0;
    p.finished("long");  // 8 of 10 cost units in 8 s: about 2 s left
    BOOST_TEST(p.line() == "rotbeam suite: 1/3 done, 8 s elapsed, about 2 s left");
}

// Before any item has finished, the expected cost (in seconds) gives the estimate.
BOOST_AUTO_TEST_CASE(time_left_before_the_first_item_is_the_expected_cost) {
    double now = 0.0;
    std::ostringstream out;
    Progress p("rotbeam suite", 1, out, log_options(now, 10.0));
    p.set_total_cost(120.0);
    p.started("study speed-accuracy", 120.0);
    now = 30.0;
    BOOST_TEST(p.line() ==
               "rotbeam suite: 0/1 done, running study speed-accuracy, 30 s elapsed, "
               "about 1 min 30 s left (expected)");
}

// On a terminal the line is redrawn in place: carriage return, the line, clear to its end.
BOOST_AUTO_TEST_CASE(terminal_redraws_one_line) {
    double now = 0.0;
    std::ostringstream out;
    {
        ProgressOptions o = log_options(now, 10.0);
        o.terminal = true;
        Progress p("rotbeam bench", 1, out, o);
        p.started("roll-up");
        p.finished("roll-up");
    }
    const std::string text = out.str();
    BOOST_TEST(std::count(text.begin(), text.end(), '\n') == 1);  // only the final newline
    BOOST_TEST(text.find("\r") == 0u);
    BOOST_TEST(text.find("rotbeam bench: 1/1 done, 0 s elapsed, nothing left\033[K\r\n") !=
               std::string::npos);
}

BOOST_AUTO_TEST_CASE(human_seconds_reads_like_a_clock) {
    BOOST_TEST(human_seconds(42.4) == "42 s");
    BOOST_TEST(human_seconds(185) == "3 min 05 s");
    BOOST_TEST(human_seconds(3720) == "1 h 02 min");
}

BOOST_AUTO_TEST_SUITE_END()
