#include "runs/time_left.hpp"

#include <algorithm>

namespace rotbeam::cli {

std::optional<TimeLeft> estimate_time_left(const WorkSoFar& w) {
    const bool measured = w.finished_cost > 0.0 && w.finished_seconds > 0.0;
    if (!measured && !w.cost_in_seconds) return std::nullopt;
    double busy = w.finished_seconds, running_cost = 0.0, running_seconds = 0.0;
    for (const RunningItem& r : w.running) {
        running_cost += r.cost;
        running_seconds += r.seconds;
    }
    busy += running_seconds;
    // Expected cost per wall second of one worker. Before any item ends, the model's own unit,
    // unless the running items have already run longer than they should: then at most their cost
    // over that time (the fastest the machine can be).
    const double v =
        measured
            ? w.finished_cost / w.finished_seconds
            : std::min(1.0, running_seconds > running_cost ? running_cost / running_seconds : 1.0);
    if (v <= 0.0) return std::nullopt;  // only items without a cost are running, for long
    const double k =
        w.workers > 0.0 ? w.workers : std::max(1.0, w.elapsed > 0.0 ? busy / w.elapsed : 0.0);
    // Whether an item is overdue is judged at the measured speed, or before any item has ended at
    // the model's (v is then derived from these very items).
    const double due_speed = measured ? v : 1.0;
    double pooled = w.pooled_cost_left, alone = w.alone_cost_left, longest = 0.0;
    for (const RunningItem& r : w.running) {
        const bool overdue = due_speed * r.seconds > r.cost;
        const double rest = overdue ? v * r.seconds : r.cost - v * r.seconds;
        (r.alone ? alone : pooled) += rest - r.cost;
        if (!r.alone) longest = std::max(longest, rest);
    }
    const double seconds =
        std::max(std::max(0.0, pooled) / (v * k), longest / v) + std::max(0.0, alone) / v;
    return TimeLeft{seconds, !measured};
}

}  // namespace rotbeam::cli
