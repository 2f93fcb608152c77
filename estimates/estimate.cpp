#include "estimates/estimate.hpp"

#include <algorithm>
#include <chrono>

#include "core/errors.hpp"
#include "core/so3.hpp"
#include "core/static_driver.hpp"
#include "estimates/companions.hpp"
#include "estimates/quantity_estimate.hpp"

namespace rotbeam::estimate {

namespace {

using json = nlohmann::json;
using Clock = std::chrono::steady_clock;

struct CompanionResult {
    std::string label;
    json result;
};

// What the comparisons need of the plan and the model.
struct Comparison {
    std::string method;
    double order_displacement = 2.0;  // theoretical h-orders (h/2,h/4 only)
    double order_rotation = 2.0;
    double order_frequency = 2.0;
    HSequence h_sequence = HSequence::finer;
    double floor_displacement = kRoundOffFloor;
    std::vector<CompanionResult> companions;
};

struct Tally {
    int estimated = 0;
    int unreliable = 0;
    int missing = 0;
    json add(const QuantityEstimate& e) {
        ++estimated;
        if (!e.reliable) ++unreliable;
        return to_json(e);
    }
    json missing_entry(const std::string& reason) {
        ++missing;
        return {{"status", "not-estimated"}, {"reason", reason}};
    }
};

Vec3 vec3(const json& j) { return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()}; }

Mat3 mat3(const json& j) {
    Mat3 R;
    for (int r = 0; r < 3; ++r) R.row(r) = vec3(j[static_cast<std::size_t>(r)]).transpose();
    return R;
}

// The largest distance between two named points (1 when they coincide): the displacement floor's
// scale.
double length_scale(const Model& model) {
    double l = 0.0;
    for (const Point& a : model.points) {
        for (const Point& b : model.points) l = std::max(l, (a.position - b.position).norm());
    }
    return l > 0.0 ? l : 1.0;
}

struct PointDifference {
    double displacement = 0.0;  // ‖u_a − u_b‖
    double rotation = 0.0;      // angle of R_aᵀ R_b
};

PointDifference difference(const json& a, const json& b) {
    return {
        (vec3(a["displacement"]) - vec3(b["displacement"])).norm(),
        so3::rotation_angle(mat3(a["rotation_matrix"]).transpose() * mat3(b["rotation_matrix"]))};
}

std::string missing_reason(const CompanionResult& c, const std::string& what) {
    return "the " + c.label + " companion has no " + what + " (" +
           c.result.value("status", std::string("error")) + ": " +
           c.result.value("message", std::string()) + ")";
}

// The companion's entry of the run's step i: the same load factor (or time) at the same index.
const json* matching_step(const json& companion, std::size_t i, const json& step) {
    if (!companion.contains("steps") || i >= companion["steps"].size()) return nullptr;
    const json& c = companion["steps"][i];
    for (const char* key : {"load_factor", "time"}) {
        if (step.contains(key) != c.contains(key)) return nullptr;
        if (step.contains(key) && step[key].get<double>() != c[key].get<double>()) return nullptr;
    }
    return &c;
}

json step_estimate(const Comparison& cmp, std::size_t i, const json& step, Tally& tally) {
    std::vector<const json*> at;
    for (const CompanionResult& c : cmp.companions) {
        const json* s = matching_step(c.result, i, step);
        if (!s) return tally.missing_entry(missing_reason(c, "state at this step"));
        at.push_back(s);
    }
    json out = json::object();
    for (const auto& [name, point] : step["points"].items()) {
        if (cmp.method == "p+1" && at.size() == 1) {
            const PointDifference d = difference(point, (*at[0])["points"][name]);
            out[name] = {{"displacement", tally.add(p_refinement(d.displacement))},
                         {"rotation", tally.add(p_refinement(d.rotation))}};
            continue;
        }
        if (cmp.method == "p+1") {
            // With the p+2 companion: d₁ = |q_p − q_{p+1}|, d₂ = |q_{p+1} − q_{p+2}|, d₀₂.
            const json& next = (*at[0])["points"][name];
            const json& after = (*at[1])["points"][name];
            const PointDifference d1 = difference(point, next);
            const PointDifference d2 = difference(next, after);
            const PointDifference d02 = difference(point, after);
            out[name] = {
                {"displacement", tally.add(p_refinement(d1.displacement, d2.displacement,
                                                        d02.displacement, cmp.floor_displacement))},
                {"rotation",
                 tally.add(p_refinement(d1.rotation, d2.rotation, d02.rotation, kRoundOffFloor))}};
            continue;
        }
        const json& half = (*at[0])["points"][name];
        const PointDifference d1 = difference(point, half);
        const PointDifference d2 = difference(half, (*at[1])["points"][name]);
        out[name] = {
            {"displacement",
             tally.add(h_refinement(d1.displacement, d2.displacement, cmp.order_displacement,
                                    cmp.floor_displacement, cmp.h_sequence))},
            {"rotation", tally.add(h_refinement(d1.rotation, d2.rotation, cmp.order_rotation,
                                                kRoundOffFloor, cmp.h_sequence))}};
    }
    return out;
}

// Each mode with a frequency gets `estimate`; companions' modes are paired by shape.
void mode_estimates(const Comparison& cmp, const ModePairing& pair_modes, json& result,
                    Tally& tally) {
    json& modes = result["modes"];
    std::vector<std::vector<int>> pairs;
    for (const CompanionResult& c : cmp.companions) {
        pairs.push_back(c.result.contains("modes") ? pair_modes(modes, c.result["modes"])
                                                   : std::vector<int>());
    }
    for (std::size_t i = 0; i < modes.size(); ++i) {
        json& mode = modes[i];
        if (!mode.contains("frequency_hz")) continue;
        std::vector<double> f;
        std::string missing;
        for (std::size_t k = 0; k < cmp.companions.size() && missing.empty(); ++k) {
            const CompanionResult& c = cmp.companions[k];
            const int j = i < pairs[k].size() ? pairs[k][i] : -1;
            if (j < 0) {
                missing = missing_reason(c, "mode of this shape");
            } else if (!c.result["modes"][static_cast<std::size_t>(j)].contains("frequency_hz")) {
                missing = missing_reason(c, "accepted frequency for this mode");
            } else {
                f.push_back(
                    c.result["modes"][static_cast<std::size_t>(j)]["frequency_hz"].get<double>());
            }
        }
        if (!missing.empty()) {
            mode["estimate"] = tally.missing_entry(missing);
            continue;
        }
        const double f0 = mode["frequency_hz"].get<double>();
        const double floor = kRoundOffFloor * std::abs(f0);
        const double d1 = std::abs(f0 - f[0]);
        const QuantityEstimate e =
            cmp.method != "p+1" ? h_refinement(d1, std::abs(f[0] - f[1]), cmp.order_frequency,
                                               floor, cmp.h_sequence)
            : f.size() == 1     ? p_refinement(d1)
                            : p_refinement(d1, std::abs(f[0] - f[1]), std::abs(f0 - f[1]), floor);
        mode["estimate"] = {{"frequency", tally.add(e)}};
    }
}

// The Newton iterations of a run's load steps, summed (its cost; 0 for a run without steps).
int newton_iterations(const json& result) {
    int n = 0;
    for (const json& step : result.value("steps", json::array())) {
        n += step.value("newton_iterations", 0);
    }
    return n;
}

}  // namespace

int total_elements(const Model& model) {
    int n = 0;
    for (const Member& m : model.members) n += m.elements;
    return n;
}

TimedRun run_companion_timed(const CompanionRun& run, const Model& model) {
    const Clock::time_point start = Clock::now();
    TimedRun t;
    try {
        t.result = run(model);
    } catch (const InputError& error) {
        t.result = {{"status", "error"}, {"message", error.what()}, {"steps", json::array()}};
    }
    t.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    return t;
}

bool refuse_estimate(nlohmann::json& result, nlohmann::json header, std::string refusal) {
    const std::string status = result.value("status", std::string("error"));
    if (!has_solution(status)) {
        refusal = "the run's status is " + status + ": an untrustworthy solve gets no estimate";
    }
    if (refusal.empty()) return false;
    header["status"] = "not-estimated";
    header["reason"] = refusal;
    result["estimate"] = std::move(header);
    return true;
}

nlohmann::json estimate_off() { return {{"status", "off"}}; }

void add_estimate(const Model& model, nlohmann::json& result, const CompanionRun& run,
                  const ModePairing& pair_modes) {
    const CompanionPlan plan = plan_companions(model);
    json e = {{"method", plan.method},
              {"theoretical_order", plan.theoretical_order},
              {"companions", json::array()},
              {"wall_seconds", 0.0}};
    if (refuse_estimate(result, e, plan.refusal)) return;
    Comparison cmp;
    cmp.method = plan.method;
    if (plan.method != "p+1") {
        cmp.h_sequence = plan.h_sequence;
        cmp.order_displacement = plan.theoretical_order["displacement"].get<double>();
        cmp.order_rotation = plan.theoretical_order["rotation"].get<double>();
        cmp.order_frequency = plan.theoretical_order["frequency"].get<double>();
    }
    cmp.floor_displacement = kRoundOffFloor * length_scale(model);
    double seconds = 0.0;
    for (const Companion& c : plan.companions) {
        auto [r, dt] = run_companion_timed(run, c.model);
        seconds += dt;
        e["companions"].push_back({{"label", c.label},
                                   {"elements", total_elements(c.model)},
                                   {"order", c.model.discretization.order},
                                   {"status", r.value("status", std::string("error"))},
                                   {"message", r.value("message", std::string())},
                                   {"newton_iterations", newton_iterations(r)},
                                   {"wall_seconds", dt}});
        cmp.companions.push_back({c.label, std::move(r)});
    }
    e["wall_seconds"] = seconds;
    Tally tally;
    for (std::size_t i = 0; i < result["steps"].size(); ++i) {
        json& step = result["steps"][i];
        step["estimate"] = step_estimate(cmp, i, step, tally);
    }
    if (result.contains("modes")) mode_estimates(cmp, pair_modes, result, tally);
    e["estimated"] = tally.estimated;
    e["unreliable"] = tally.unreliable;
    e["missing"] = tally.missing;
    e["status"] = tally.missing == 0    ? "estimated"
                  : tally.estimated > 0 ? "partial"
                                        : "not-estimated";
    if (tally.missing > 0) e["reason"] = "some quantities have no estimate (see each)";
    result["estimate"] = e;
}

}  // namespace rotbeam::estimate
