#include "estimates/accuracy_scale.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace rotbeam::estimate {

namespace {

using json = nlohmann::json;

// One estimate `q` ({error, reliable, ...}) of a quantity of scale `scale`.
void add(AccuracyMeasure& m, const json& q, double scale, double target, const std::string& what) {
    const double relative = q["error"].get<double>() / scale;
    const bool reliable = q["reliable"].get<bool>();
    ++m.quantities;
    if (relative >= m.worst) {
        m.worst = relative;
        m.worst_what = what;
        m.worst_order = q.value("observed_order", 0.0);
    }
    if (!reliable) ++m.unreliable;
    if (m.first_problem.empty() && (relative > target || !reliable)) {
        std::ostringstream s;
        s.precision(3);
        s << what << ": estimate " << relative << " of its scale";
        if (!reliable) s << ", not reliable (" << q.value("reason", std::string()) << ")";
        m.first_problem = s.str();
    }
}

void missing(AccuracyMeasure& m, const json& entry, const std::string& what) {
    ++m.missing;
    if (m.first_problem.empty()) {
        m.first_problem = what + ": no estimate (" + entry.value("reason", std::string()) + ")";
    }
}

std::string step_name(const json& step) {
    std::ostringstream s;
    s.precision(10);
    if (step.contains("load_factor")) s << "load factor " << step["load_factor"].get<double>();
    if (step.contains("time")) s << "t = " << step["time"].get<double>();
    return s.str();
}

}  // namespace

double reference_length(const Model& model) {
    double l = 0.0;
    for (const Point& a : model.points) {
        for (const Point& b : model.points) l = std::max(l, (a.position - b.position).norm());
    }
    return l > 0.0 ? l : 1.0;
}

namespace {

// A dynamic run (its estimate has `history`): each responding history's largest estimated error
// (space + time) over its amplitude, reliable when its estimate is reliable at every output time;
// a history at the round-off floor (a clamped point) has no relative error and is not counted; an
// output time without an estimate counts as missing.
AccuracyMeasure measure_histories(const json& result, double target) {
    AccuracyMeasure m;
    const json& steps = result.value("steps", json::array());
    for (const json& step : steps) {
        if (step.contains("estimate") && step["estimate"].contains("status")) {
            missing(m, step["estimate"], step_name(step));
        }
    }
    for (const auto& [point, quantities] : result["estimate"]["history"].items()) {
        for (const auto& [quantity, h] : quantities.items()) {
            if (!h.contains("relative")) continue;
            bool reliable = true, space_reliable = true, time_reliable = true;
            std::string reason;
            for (const json& step : steps) {
                if (!step.contains("estimate") || !step["estimate"].contains(point)) continue;
                const json& q = step["estimate"][point][quantity];
                if (!q.value("reliable", false)) {
                    if (reliable) reason = q.value("reason", std::string());
                    reliable = false;
                    // A part the entry does not state counts as not reliable.
                    const json none = json::object();
                    space_reliable =
                        space_reliable && q.value("space", none).value("reliable", false);
                    time_reliable = time_reliable && q.value("time", none).value("reliable", false);
                }
            }
            m.worst_space = std::max(m.worst_space, h.value("relative_space", 0.0));
            m.worst_time = std::max(m.worst_time, h.value("relative_time", 0.0));
            if (!space_reliable) ++m.space_unreliable;
            if (!time_reliable) ++m.time_unreliable;
            json entry = {{"error", h["relative"]}, {"reliable", reliable}};
            if (!reliable) entry["reason"] = reason;
            add(m, entry, 1.0, target, point + " " + quantity + " history (of its amplitude)");
        }
    }
    return m;
}

}  // namespace

AccuracyMeasure measure_accuracy(const Model& model, const nlohmann::json& result, double target) {
    if (result.contains("estimate") && result["estimate"].contains("history")) {
        return measure_histories(result, target);
    }
    AccuracyMeasure m;
    const double length = reference_length(model);
    for (const json& step : result.value("steps", json::array())) {
        if (!step.contains("estimate")) continue;
        const json& e = step["estimate"];
        if (e.contains("status")) {
            missing(m, e, step_name(step));
            continue;
        }
        for (const auto& [point, q] : e.items()) {
            const std::string at = point + " at " + step_name(step);
            add(m, q["displacement"], length, target, at + " (displacement)");
            add(m, q["rotation"], 1.0, target, at + " (rotation)");
        }
    }
    const json modes = result.value("modes", json::array());
    for (std::size_t k = 0; k < modes.size(); ++k) {
        const json& mode = modes[k];
        if (!mode.contains("estimate")) continue;
        const std::string what = "mode " + std::to_string(k + 1) + " (frequency)";
        if (!mode["estimate"].contains("frequency")) {
            missing(m, mode["estimate"], what);
            continue;
        }
        const double f = std::abs(mode["frequency_hz"].get<double>());
        add(m, mode["estimate"]["frequency"], f > 0.0 ? f : 1.0, target, what);
    }
    return m;
}

bool meets(const AccuracyMeasure& m, double target) {
    return m.missing == 0 && m.unreliable == 0 && m.quantities > 0 && m.worst <= target;
}

}  // namespace rotbeam::estimate
