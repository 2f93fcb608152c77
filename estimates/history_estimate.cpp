#include "estimates/history_estimate.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <map>
#include <optional>
#include <sstream>

#include "core/errors.hpp"
#include "core/static_driver.hpp"
#include "estimates/dynamic_companions.hpp"
#include "estimates/point_difference.hpp"
#include "estimates/quantity_estimate.hpp"

namespace rotbeam::estimate {

namespace {

using json = nlohmann::json;
using Clock = std::chrono::steady_clock;

constexpr const char* kQuantities[] = {"displacement", "rotation"};

// A companion's result and, per output time of the run, the index of its step at the same time
// (−1: none).
struct Ran {
    std::string label;
    json result;
    std::vector<long> index;
};

// The companion's steps at the run's output times: equal within 1e-9 Δt (the schemes place their
// outputs at start + n Δt, which halving Δt reproduces to the last bit or nearly).
std::vector<long> match_times(const json& steps, const json& companion, double tolerance) {
    std::vector<long> index(steps.size(), -1);
    if (!companion.contains("steps")) return index;
    const json& c = companion["steps"];
    std::size_t j = 0;
    for (std::size_t i = 0; i < steps.size(); ++i) {
        const double t = steps[i]["time"].get<double>();
        while (j < c.size() && c[j]["time"].get<double>() < t - tolerance) ++j;
        if (j < c.size() && std::abs(c[j]["time"].get<double>() - t) <= tolerance) {
            index[i] = static_cast<long>(j);
        }
    }
    return index;
}

double component(const PointDifference& d, int q) { return q == 0 ? d.displacement : d.rotation; }

// The named points whose motion the estimate measures: with turning supports, the motion relative
// to the turning frame, in its axes (`rotating_frame.points`: displacement and rotation relative
// to the rigidly turning undeformed beam), so that the amplitude is the elastic motion's and not
// the rigid turn's; otherwise the inertial `points`. A difference of two states at the same time is
// the same in both (Q(t) is one rigid rotation: ‖Q a − Q b‖ = ‖a − b‖, (Q R_a)ᵀ Q R_b = R_aᵀ R_b),
// so only the amplitudes, the relative errors and the phase criterion see the choice.
const json& measured_points(const json& step) {
    if (step.contains("rotating_frame")) return step["rotating_frame"]["points"];
    return step["points"];
}

struct Context {
    const DynamicPlan& plan;
    std::vector<Ran> space;  // p+1: one; h/2, h/4 (or 2h, 4h): two
    std::vector<Ran> time;   // one
    double floor_displacement = kRoundOffFloor;
    double time_factor = 4.0 / 3.0;  // Richardson: 1 / |1 − k⁻ᵠ|
    // The coarser history's phase over the run's: 1, or k⁻ᵠ for a 2dt companion (k = 1/2).
    double coarser_phase = 1.0;
};

const json* at(const Ran& c, std::size_t i, const std::string& name) {
    const long j = c.index[i];
    if (j < 0) return nullptr;
    const json& s = measured_points(c.result["steps"][static_cast<std::size_t>(j)]);
    return s.contains(name) ? &s[name] : nullptr;
}

std::optional<QuantityEstimate> space_estimate(const Context& cx, std::size_t i,
                                               const std::string& name, const json& point, int q) {
    std::vector<const json*> c;
    for (const Ran& r : cx.space) {
        const json* p = at(r, i, name);
        if (!p) return std::nullopt;
        c.push_back(p);
    }
    const double d1 = component(point_difference(point, *c[0]), q);
    if (cx.plan.space.method == "p+1") return p_refinement(d1);
    const double d2 = component(point_difference(*c[0], *c[1]), q);
    const double order = cx.plan.space.theoretical_order[kQuantities[q]].get<double>();
    return h_refinement(d1, d2, order, q == 0 ? cx.floor_displacement : kRoundOffFloor,
                        cx.plan.space.h_sequence);
}

std::optional<double> time_difference(const Context& cx, std::size_t i, const std::string& name,
                                      const json& point, int q) {
    const json* p = at(cx.time[0], i, name);
    if (!p) return std::nullopt;
    return component(point_difference(point, *p), q);
}

// One point's displacement or rotation over the whole history.
struct History {
    double amplitude = 0.0;  // max ‖u‖, or max |rotation_angle|
    double max_space = 0.0;
    double max_time = 0.0;
    double max_error = 0.0;
    double max_time_difference = 0.0;
    double phase = 0.0;  // accumulated phase error (rad), when the amplitude is above the floor
    bool responds = false;
};

using Histories = std::map<std::string, History>;  // "<point> <quantity>"

std::string key(const std::string& name, int q) { return name + " " + kQuantities[q]; }

// The amplitudes, the largest time differences and the phase errors (before any estimate is
// written: the time estimate's reliability depends on the phase).
Histories survey(const Context& cx, const json& steps) {
    Histories h;
    for (std::size_t i = 0; i < steps.size(); ++i) {
        for (const auto& [name, point] : measured_points(steps[i]).items()) {
            for (int q = 0; q < 2; ++q) {
                History& x = h[key(name, q)];
                double size = 0.0;
                if (q == 0) {
                    for (int k = 0; k < 3; ++k) {
                        size += std::pow(point["displacement"][k].get<double>(), 2);
                    }
                    size = std::sqrt(size);
                } else {
                    size = std::abs(point["rotation_angle"].get<double>());
                }
                x.amplitude = std::max(x.amplitude, size);
                if (const auto d = time_difference(cx, i, name, point, q)) {
                    x.max_time_difference = std::max(x.max_time_difference, *d);
                }
            }
        }
    }
    for (auto& [k, x] : h) {
        const bool rotation = k.ends_with(kQuantities[1]);
        x.responds = x.amplitude > (rotation ? kRoundOffFloor : cx.floor_displacement);
        if (x.responds) {
            x.phase = accumulated_phase(x.max_time_difference, x.amplitude, cx.plan.time_order,
                                        cx.plan.time_ratio);
        }
    }
    return h;
}

struct Tally {
    int estimated = 0;
    int unreliable = 0;
    int missing = 0;
};

// The estimate of one quantity at one output time (nullopt: a companion has no state there).
std::optional<json> quantity_entry(const Context& cx, std::size_t i, const std::string& name,
                                   const json& point, int q, const QuantityEstimate& time_verdict,
                                   History& h) {
    const std::optional<QuantityEstimate> s = space_estimate(cx, i, name, point, q);
    const std::optional<double> dt = time_difference(cx, i, name, point, q);
    if (!s || !dt) return std::nullopt;
    QuantityEstimate t;
    t.reliable = time_verdict.reliable;
    if (!t.reliable) t.reason = "the phase criterion fails (estimate.time_reason)";
    t.error = cx.time_factor * *dt;
    const double error = s->error + t.error;
    h.max_space = std::max(h.max_space, s->error);
    h.max_time = std::max(h.max_time, t.error);
    h.max_error = std::max(h.max_error, error);
    json e = {{"error", error},
              {"reliable", s->reliable && t.reliable},
              {"space", to_json(*s)},
              {"time", to_json(t)}};
    if (h.responds) e["relative"] = error / h.amplitude;
    if (!s->reliable || !t.reliable) {
        e["reason"] = (s->reliable ? "" : "space: " + s->reason + "; ") +
                      (t.reliable ? "" : "time: " + t.reason);
    }
    return e;
}

json step_entry(const Context& cx, std::size_t i, const json& step,
                const QuantityEstimate& time_verdict, Histories& h, Tally& tally) {
    json out = json::object();
    int unreliable = 0;
    for (const auto& [name, point] : measured_points(step).items()) {
        for (int q = 0; q < 2; ++q) {
            std::optional<json> e =
                quantity_entry(cx, i, name, point, q, time_verdict, h[key(name, q)]);
            if (!e) {
                ++tally.missing;
                return {{"status", "not-estimated"},
                        {"reason", "a companion has no state at t = " +
                                       std::to_string(step["time"].get<double>())}};
            }
            if (!(*e)["reliable"].get<bool>()) ++unreliable;
            out[name][kQuantities[q]] = std::move(*e);
        }
    }
    tally.estimated += 2 * static_cast<int>(out.size());
    tally.unreliable += unreliable;
    return out;
}

json history_json(const Histories& h) {
    json out = json::object();
    for (const auto& [k, x] : h) {
        const std::size_t space = k.rfind(' ');
        json e = {{"amplitude", x.amplitude},
                  {"max_space", x.max_space},
                  {"max_time", x.max_time},
                  {"max_error", x.max_error}};
        if (x.responds) {
            e["relative_space"] = x.max_space / x.amplitude;
            e["relative_time"] = x.max_time / x.amplitude;
            e["relative"] = x.max_error / x.amplitude;
            e["phase_error_rad"] = x.phase;
        }
        out[k.substr(0, space)][k.substr(space + 1)] = e;
    }
    return out;
}

// Newton iterations × unknowns of a dynamic result: the work of its time steps.
double work(const json& r) {
    for (const char* block : {"integrator", "dynamics"}) {
        if (r.contains(block) && r[block].contains("newton_iterations")) {
            return r[block]["newton_iterations"].get<double>() * r.value("dofs", 0.0);
        }
    }
    return 0.0;
}

Ran run_companion(const Companion& c, const CompanionRun& run, const json& steps, double dt,
                  json& estimate, double& companion_work) {
    auto [r, seconds] = run_companion_timed(run, c.model);
    estimate["companions"].push_back({{"label", c.label},
                                      {"elements", total_elements(c.model)},
                                      {"order", c.model.discretization.order},
                                      {"time_step", c.model.analysis.dynamics.time_step},
                                      {"status", r.value("status", std::string("error"))},
                                      {"message", r.value("message", std::string())},
                                      {"wall_seconds", seconds}});
    estimate["wall_seconds"] = estimate["wall_seconds"].get<double>() + seconds;
    companion_work += work(r);
    std::vector<long> index = match_times(steps, r, 1e-9 * dt);
    return {c.label, std::move(r), std::move(index)};
}

// The companions' wall time, CPU time and work against the run's.
json cost_json(const json& result, double wall_seconds, double cpu_seconds, double companion_work) {
    const double run_seconds = result.value("wall_seconds", 0.0);
    const double run_work = work(result);
    return {{"run_wall_seconds", run_seconds},
            {"wall_ratio", run_seconds > 0.0 ? wall_seconds / run_seconds : 0.0},
            {"cpu_seconds", cpu_seconds},
            {"work_ratio", run_work > 0.0 ? companion_work / run_work : 0.0},
            {"work", "Newton iterations x unknowns of the companions over the run's"}};
}

json header(const DynamicPlan& plan) {
    json order = plan.space.theoretical_order;
    order["time"] = plan.time_order;
    return {{"method", plan.space.method + " & " + plan.time_method},
            {"space_method", plan.space.method},
            {"time_method", plan.time_method},
            {"theoretical_order", order},
            {"companions", json::array()},
            {"wall_seconds", 0.0}};
}

// The largest distance between two named points (1 when they coincide): the displacement floor's
// scale, as for the statics.
double length_scale(const Model& model) {
    double l = 0.0;
    for (const Point& a : model.points) {
        for (const Point& b : model.points) l = std::max(l, (a.position - b.position).norm());
    }
    return l > 0.0 ? l : 1.0;
}

// The largest accumulated phase error among the responding histories, and whose.
struct WorstPhase {
    double run = 0.0;      // the run's φ
    double coarser = 0.0;  // the coarser history's (the run's, or a 2dt companion's 2^q φ)
    std::string of;
};

WorstPhase worst_phase(const Histories& h, double coarser_phase) {
    WorstPhase worst;
    for (const auto& [k, x] : h) {
        if (x.responds && x.phase >= worst.run) worst = {x.phase, x.phase * coarser_phase, k};
    }
    return worst;
}

// The criteria hold for the coarser of the two histories: the Richardson estimate is linear in
// the phase of both, and a 2dt companion carries 2^q times the run's.
QuantityEstimate time_verdict(const WorstPhase& phase) {
    QuantityEstimate t;
    if (phase.coarser <= kPhaseReliable) return t;
    std::ostringstream why;
    why.precision(3);
    why << "accumulated phase error of the " << phase.of << " history " << phase.run << " rad";
    if (phase.coarser > phase.run) why << " (its 2dt companion's " << phase.coarser << " rad)";
    why << ", not << 1 rad (criterion <= " << kPhaseReliable << " rad)";
    t.reliable = false;
    t.reason = why.str();
    return t;
}

// `inaccurate` when the phase criterion fails far (φ > 1 rad) or a history's estimated error
// reaches half its amplitude; the message names the quantity, the estimate and the criterion.
void judge(const Histories& h, const WorstPhase& phase, const std::string& time_method,
           json& result) {
    const std::string status = result["status"].get<std::string>();
    std::ostringstream why;
    why.precision(3);
    if (phase.coarser > kPhaseInaccurate) {
        why << "the time step is beyond what the estimate can vouch for: the " << phase.of
            << " history's accumulated phase error is " << phase.run << " rad by the "
            << time_method << " companion";
        if (phase.coarser > phase.run) why << " (the companion's own " << phase.coarser << " rad)";
        why << ", criterion <= " << kPhaseInaccurate << " rad";
    } else {
        for (const auto& [k, x] : h) {
            if (!x.responds || x.max_error < kRelativeInaccurate * x.amplitude) continue;
            why << "the " << k << " history's estimated error " << x.max_error << " is "
                << x.max_error / x.amplitude << " of its amplitude " << x.amplitude
                << ", criterion < " << kRelativeInaccurate;
            break;
        }
    }
    if (why.str().empty()) return;
    result["message"] =
        why.str() + "; the solve: " + status + " — " + result["message"].get<std::string>();
    result["status"] = kInaccurate;
}

}  // namespace

double accumulated_phase(double difference, double amplitude, double order, double ratio) {
    const double s = std::min(1.0, difference / (2.0 * amplitude));
    return 2.0 * std::asin(s) / std::abs(1.0 - std::pow(ratio, -order));
}

void add_dynamic_estimate(const Model& model, nlohmann::json& result, const CompanionRun& run) {
    const DynamicPlan plan = plan_dynamic_companions(model);
    json e = header(plan);
    if (refuse_estimate(result, e,
                        plan.space.refusal.empty() ? plan.time_refusal : plan.space.refusal)) {
        return;
    }
    const std::clock_t cpu = std::clock();
    Context cx{plan, {}, {}};
    cx.floor_displacement = kRoundOffFloor * length_scale(model);
    cx.time_factor = 1.0 / std::abs(1.0 - std::pow(plan.time_ratio, -plan.time_order));
    cx.coarser_phase = std::max(1.0, std::pow(plan.time_ratio, -plan.time_order));
    const json& steps = result["steps"];
    const double dt = model.analysis.dynamics.time_step;
    double companion_work = 0.0;
    for (const Companion& c : plan.space.companions) {
        cx.space.push_back(run_companion(c, run, steps, dt, e, companion_work));
    }
    cx.time.push_back(run_companion(plan.time[0], run, steps, dt, e, companion_work));
    Histories h = survey(cx, steps);
    const WorstPhase phase = worst_phase(h, cx.coarser_phase);
    const QuantityEstimate verdict = time_verdict(phase);
    Tally tally;
    for (std::size_t i = 0; i < steps.size(); ++i) {
        result["steps"][i]["estimate"] = step_entry(cx, i, steps[i], verdict, h, tally);
    }
    e["cost"] = cost_json(result, e["wall_seconds"].get<double>(),
                          static_cast<double>(std::clock() - cpu) / CLOCKS_PER_SEC, companion_work);
    e["history"] = history_json(h);
    e["phase_error_rad"] = phase.run;
    e["phase_of"] = phase.of;
    e["time_reliable"] = verdict.reliable;
    e["estimated"] = tally.estimated;
    e["unreliable"] = tally.unreliable;
    e["missing"] = tally.missing;
    e["status"] = tally.missing == 0    ? "estimated"
                  : tally.estimated > 0 ? "partial"
                                        : "not-estimated";
    if (tally.missing > 0) e["reason"] = "some output times have no estimate (see each)";
    if (!verdict.reliable) e["time_reason"] = verdict.reason;
    if (!steps.empty() && steps[0].contains("rotating_frame")) {
        e["motion"] = "relative to the turning frame";
    }
    result["estimate"] = e;
    judge(h, phase, plan.time_method, result);
}

}  // namespace rotbeam::estimate
