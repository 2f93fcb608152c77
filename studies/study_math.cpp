#include "study_math.hpp"

#include <cmath>
#include <limits>

#include "core/static_driver.hpp"

namespace rotbeam::cli {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

bool usable(double n, double e, double floor) {
    return std::isfinite(n) && n > 0.0 && std::isfinite(e) && e > floor;
}

// −slope of the least-squares line through (log n, log e).
double negative_log_slope(const std::vector<double>& x, const std::vector<double>& y) {
    const double m = static_cast<double>(x.size());
    double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
    for (size_t i = 0; i < x.size(); ++i) {
        sx += x[i];
        sy += y[i];
        sxx += x[i] * x[i];
        sxy += x[i] * y[i];
    }
    const double denominator = m * sxx - sx * sx;
    if (!(std::abs(denominator) > 0.0)) return kNaN;  // all n equal
    return -(m * sxy - sx * sy) / denominator;
}

}  // namespace

double fit_order(const std::vector<double>& n, const std::vector<double>& error, double floor) {
    return tail_order(n, error, static_cast<int>(n.size()), floor);
}

double tail_order(const std::vector<double>& n, const std::vector<double>& error, int points,
                  double floor) {
    std::vector<double> x, y;
    for (size_t i = 0; i < n.size() && i < error.size(); ++i) {
        if (!usable(n[i], error[i], floor)) continue;
        x.push_back(std::log(n[i]));
        y.push_back(std::log(error[i]));
    }
    if (static_cast<int>(x.size()) > points) {
        x.erase(x.begin(), x.end() - points);
        y.erase(y.begin(), y.end() - points);
    }
    if (x.size() < 2) return kNaN;
    return negative_log_slope(x, y);
}

std::vector<bool> pareto_front(const std::vector<double>& cost, const std::vector<double>& error) {
    const size_t m = std::min(cost.size(), error.size());
    std::vector<bool> front(m, false);
    for (size_t i = 0; i < m; ++i) {
        if (!std::isfinite(cost[i]) || !std::isfinite(error[i])) continue;
        bool dominated = false;
        for (size_t j = 0; j < m && !dominated; ++j) {
            if (j == i || !std::isfinite(cost[j]) || !std::isfinite(error[j])) continue;
            dominated = cost[j] <= cost[i] && error[j] <= error[i] &&
                        (cost[j] < cost[i] || error[j] < error[i]);
        }
        front[i] = !dominated;
    }
    return front;
}

Reach classify_reach(const std::vector<ConvergedStep>& steps, const std::string& status,
                     int target_steps, double tolerance, double jump_factor) {
    Reach reach;
    double previous = kNaN;
    for (const ConvergedStep& s : steps) {
        if (!std::isfinite(s.error) || s.error > tolerance) {
            const bool jumped = !std::isfinite(s.error) || !std::isfinite(previous) ||
                                s.error > jump_factor * previous;
            reach.stopped = jumped ? "wrong branch" : "lost accuracy";
            return reach;
        }
        previous = s.error;
        reach.load_factor = s.load_factor;
        ++reach.steps_reached;
    }
    if (has_solution(status)) {
        reach.stopped = reach.steps_reached >= target_steps ? "completed" : "error";
    } else {
        reach.stopped = status;
    }
    return reach;
}

int floor_index(const std::vector<double>& error) {
    int best = -1;
    for (size_t i = 0; i < error.size(); ++i) {
        if (!std::isfinite(error[i])) continue;
        if (best < 0 || error[i] < error[static_cast<size_t>(best)]) best = static_cast<int>(i);
    }
    return best;
}

}  // namespace rotbeam::cli
