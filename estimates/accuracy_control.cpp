#include "estimates/accuracy_control.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "core/static_driver.hpp"
#include "estimates/accuracy_scale.hpp"
#include "estimates/companions.hpp"

namespace rotbeam::estimate {

namespace {

using json = nlohmann::json;
using Clock = std::chrono::steady_clock;

// The p-sequence decays spectrally when each order divides the worst estimate by at least 2
// (the successive-difference ratio below 0.5 of docs/error-estimates.md); then raising p is
// the cheaper refinement (docs/accuracy-control.md, "Strategy", measured).
constexpr double kSpectralRatio = 0.5;
// Below kSpectralOrder (companions.hpp) the p-sequence on a coarse mesh is not yet spectral even
// for a smooth solution (the locking bump of orders 2–3 on two elements, docs/studies.md; one
// element turning 2π decays by only 0.65–0.73 per order up to order 4, then spectrally): p is
// raised regardless, and the coarse start begins at that order.
// At most this many orders are added at once: the prediction from ρ extrapolates a decay seen
// over one or two orders.
constexpr int kMaxOrderJump = 4;
// Element counts predicted from an h-rate get this margin (the rate is asymptotic) and lie
// between 2× and 16× the current count per refinement.
constexpr double kCountMargin = 1.2;
constexpr double kMinSplit = 2.0;
constexpr double kMaxSplit = 16.0;
// Two refinements in a row that each leave more than half the worst estimate: stagnation.
constexpr double kStagnation = 0.5;
// Trapezoidal quadrature: refine ≥ this × the order (refine_quadrature).
constexpr int kTrapezoidalPointsPerOrder = 2;

struct Attempt {
    int order = 1;
    std::vector<int> elements;  // per member
    int substeps = 1;
    int refine = 1;  // trapezoidal quadrature
    std::string status;
    bool measured = false;  // estimated: `worst` is defined
    double worst = 0.0;
    bool refined = false;   // the discretization was refined for it (not only the load steps)
    std::size_t steps = 0;  // reported (converged) load steps
};

bool dynamic(const Model& model) { return model.analysis.kind == AnalysisKind::dynamic; }

int total(const std::vector<int>& elements) {
    int n = 0;
    for (const int e : elements) n += e;
    return n;
}

std::vector<int> elements_of(const Model& model) {
    std::vector<int> e;
    for (const Member& m : model.members) e.push_back(m.elements);
    return e;
}

std::string number(double x) {
    std::ostringstream s;
    s.precision(3);
    s << x;
    return s.str();
}

// The next discretization, or nullopt with `stop` set (the budget).
struct Step {
    std::optional<Model> model;
    std::string decision;  // what changes and why
    std::string stop;      // why not
};

bool uses_trapezoidal_rule(const Model& model) {
    return model.discretization.formulation == Formulation::displacement &&
           model.discretization.quadrature == Quadrature::trapezoidal;
}

// The trapezoidal rule's error does not fall with the order or the elements but as refine⁻², and
// it has a point at each station and element end and refine − 1 between. Each refinement step of
// the control doubles refine per order it adds (`doublings`), as the estimate's p+1 companion
// (order p + 1, refine 2r) does: the quadrature part of the error then falls at least fourfold
// per step and the companion is the next step's run. Refine stays ≥ twice the order, so every
// element has at least 2p + 1 points: with p + 1 (the fewest the mesh accepts) one element of
// order 15 on the roll-up diverged, and near that the rule's error is far above its r⁻²
// asymptote (docs/accuracy-control.md, "Trapezoidal quadrature"). False: past the budget.
bool refine_quadrature(Model& next, int doublings, const AccuracyBudget& budget) {
    if (!uses_trapezoidal_rule(next)) return true;
    int& r = next.discretization.refine;
    for (int i = 0; i < doublings; ++i) r *= 2;
    r = std::max(r, kTrapezoidalPointsPerOrder * next.discretization.order);
    return r <= budget.refine;
}

std::string refine_note(const Model& model, const Model& next) {
    if (!uses_trapezoidal_rule(model)) return "";
    return ", refine " + std::to_string(model.discretization.refine) + " -> " +
           std::to_string(next.discretization.refine);
}

Step refine_budget_stop(const AccuracyBudget& budget, const Model& next) {
    Step s;
    s.stop = "budget: refine " + std::to_string(next.discretization.refine) +
             " would pass the largest, " + std::to_string(budget.refine) +
             " (its p+1 companion doubles it)";
    return s;
}

// `n` rounded up to the multiple the model's companions need (element_count_multiple).
int round_up_elements(const Model& model, double n) {
    const double k = element_count_multiple(model);
    return static_cast<int>(std::ceil(n / k) * k);
}

// Every member's elements times `factor` (at least one more, and a multiple of
// element_count_multiple), within the budget.
Step split(const Model& model, double factor, const AccuracyBudget& budget,
           const std::string& why) {
    Step s;
    Model next = model;
    bool at_budget = true;
    const int k = element_count_multiple(model);
    const int largest = budget.elements_per_member / k * k;
    for (Member& m : next.members) {
        const int want = round_up_elements(model, std::ceil(m.elements * factor));
        const int n = std::min(want, largest);
        if (m.elements < largest) at_budget = false;
        m.elements = std::max(n, m.elements);
    }
    if (at_budget) {
        s.stop = "budget: " + std::to_string(budget.elements_per_member) +
                 " elements per member reached (" + why + ")";
        return s;
    }
    if (!refine_quadrature(next, 1, budget)) return refine_budget_stop(budget, next);
    s.decision = "elements " + std::to_string(total(elements_of(model))) + " -> " +
                 std::to_string(total(elements_of(next))) + refine_note(model, next) + " (" + why +
                 ")";
    s.model = std::move(next);
    return s;
}

// The split factor that brings `worst` to `target` at h-rate `order`, with the margin.
double predicted_split(double worst, double target, double order) {
    const double f = kCountMargin * std::pow(worst / target, 1.0 / order);
    return std::clamp(f, kMinSplit, kMaxSplit);
}

// Displacement formulation: p while the estimates decay spectrally, else h.
Step refine_displacement(const Model& model, const std::vector<Attempt>& history, double target,
                         const AccuracyBudget& budget) {
    const Attempt& now = history.back();
    const int p = model.discretization.order;
    // The previous measured attempt on this mesh at a lower order: the decay per order.
    std::optional<double> rho;
    for (auto it = history.rbegin() + 1; it != history.rend(); ++it) {
        if (it->measured && it->elements == now.elements && it->order < p && it->worst > 0.0) {
            rho = std::pow(now.worst / it->worst, 1.0 / (p - it->order));
            break;
        }
    }
    const bool first_on_mesh = !rho.has_value();
    if (p < budget.order && (first_on_mesh || p < kSpectralOrder || *rho < kSpectralRatio)) {
        int jump = 1;
        std::string why = "first order step on this mesh";
        if (rho && p < kSpectralOrder && *rho >= kSpectralRatio) {
            why = "order below " + std::to_string(kSpectralOrder) + ", ratio " + number(*rho);
        } else if (rho) {
            jump = static_cast<int>(std::ceil(std::log(target / now.worst) / std::log(*rho)));
            jump = std::clamp(jump, 1, kMaxOrderJump);
            why = "spectral decay, ratio " + number(*rho) + " per order";
        }
        Model next = model;
        next.discretization.order = std::min(p + jump, budget.order);
        if (!refine_quadrature(next, next.discretization.order - p, budget)) {
            return refine_budget_stop(budget, next);
        }
        Step s;
        s.decision = "order " + std::to_string(p) + " -> " +
                     std::to_string(next.discretization.order) + refine_note(model, next) + " (" +
                     why + ")";
        s.model = std::move(next);
        return s;
    }
    // Nodal values converge at h^(2p) (docs/error-estimates.md).
    const std::string why = rho ? "no spectral decay, ratio " + number(*rho) + " per order"
                                : "order budget " + std::to_string(budget.order) + " reached";
    return split(model, predicted_split(now.worst, target, 2.0 * p), budget,
                 why + "; h-rate " + std::to_string(2 * p));
}

// Mixed formulation: h, the count predicted from the observed order (the theory's 2 when the
// observed one is undefined or outside its window).
Step refine_mixed(const Model& model, const Attempt& now, double observed, double target,
                  const AccuracyBudget& budget) {
    const bool use_observed = std::abs(observed - 2.0) <= 0.5;
    const double r = use_observed ? observed : 2.0;
    double f = predicted_split(now.worst, target, r);
    // The h/2 and h/4 companions already solved 2× and 4× the elements: a prediction up to 4×
    // takes the next of those meshes, whose run is at hand (runs/accuracy_run.cpp reuses it).
    // Coarser companions leave no finer run at hand.
    if (model.analysis.estimate_companions == CompanionSide::finer && f <= 4.0) {
        f = f <= 2.0 ? 2.0 : 4.0;
    }
    return split(model, f, budget,
                 std::string(use_observed ? "observed" : "theoretical") + " order " + number(r));
}

// What keeps an estimate from being complete: its first missing or failing quantity, or, when it
// has none, the estimate's own reason (a refused estimate has no quantities).
std::string estimate_problem(const AccuracyMeasure& m, const json& result) {
    if (!m.first_problem.empty()) return m.first_problem;
    return result.contains("estimate") ? result["estimate"].value("reason", std::string())
                                       : std::string();
}

// Stagnation: the last two refinements of the discretization each left more than half the worst
// estimate.
bool stagnated(const std::vector<Attempt>& history) {
    std::vector<double> w;
    for (const Attempt& a : history) {
        if (a.measured && a.refined) w.push_back(a.worst);
    }
    const std::size_t n = w.size();
    return n >= 3 && w[n - 1] > kStagnation * w[n - 2] && w[n - 2] > kStagnation * w[n - 3];
}

json attempt_json(const Model& model, const Attempt& a, const json& result, double seconds,
                  const AccuracyMeasure* m) {
    json per_member = json::object();
    for (std::size_t i = 0; i < model.members.size(); ++i) {
        per_member[model.members[i].name] = a.elements[i];
    }
    json j = {{"elements", total(a.elements)},
              {"elements_per_member", per_member},
              {"order", a.order},
              {"substeps", a.substeps},
              {"status", a.status},
              {"wall_seconds", seconds},
              {"run_seconds", result.value("wall_seconds", 0.0)}};
    if (uses_trapezoidal_rule(model)) j["refine"] = a.refine;
    if (dynamic(model)) j["time_tolerance"] = model.analysis.dynamics.time_tolerance;
    if (result.contains("estimate")) {
        j["estimate_status"] = result["estimate"].value("status", std::string());
        j["estimate_seconds"] = result["estimate"].value("wall_seconds", 0.0);
    }
    if (m) {
        j["worst_relative"] = m->worst;
        j["worst_quantity"] = m->worst_what;
        if (dynamic(model)) {
            j["worst_space"] = m->worst_space;
            j["worst_time"] = m->worst_time;
        }
        j["unreliable"] = m->unreliable;
        j["missing"] = m->missing;
    }
    return j;
}

// Dynamics: each half of the target goes to one of the two errors, the mesh's and the time
// step's (their estimates add up to the history's, docs/error-estimates.md, Dynamics).
constexpr double kDynamicShare = 0.5;

// The adaptive steps' global error is proportional to their tolerance (order 1 in it,
// estimates/dynamic_companions.cpp): the tolerance that brings the time part to its share, with
// the margin of the element counts, divided by at least 4 and at most 16. At least 4: a smaller
// step would hardly move the error and still cost a whole attempt, while the steps grow only as
// τ^(−1/q) (4^(1/6) = 1.26 times as many for Gauss–Legendre 3). A time part that is not reliable
// (the phase criterion) has no usable size: 4.
Step tighten_time(const Model& model, const AccuracyMeasure& m, double share,
                  const AccuracyBudget& budget, double case_tolerance) {
    Step s;
    double f = m.time_unreliable > 0 ? 4.0 : kCountMargin * m.worst_time / share;
    f = std::clamp(f, 4.0, kMaxSplit);
    const double now = model.analysis.dynamics.time_tolerance;
    const double next = now / f;
    if (next < case_tolerance / budget.time_tolerance_factor || next < kMinAccuracy) {
        s.stop = "budget: the time tolerance " + number(next) + " would pass the smallest, " +
                 number(std::max(case_tolerance / budget.time_tolerance_factor, kMinAccuracy));
        return s;
    }
    s.model = model;
    s.model->analysis.dynamics.time_tolerance = next;
    s.decision = "time tolerance " + number(now) + " -> " + number(next) + " (time part " +
                 number(m.worst_time) + (m.time_unreliable > 0 ? ", not reliable" : "") +
                 " of its history, share " + number(share) + ")";
    return s;
}

// One attempt: runs `model` with its estimate, measures the estimates against `target` (when the
// run has a solution) and records the attempt in `history` and `attempts`. The attempt's `worst`
// is the measure's worst, or in dynamics its worst space part, which the mesh refinement follows.
std::optional<AccuracyMeasure> run_attempt(const EstimatedRun& run, const Model& model,
                                           double target, bool refined, json& result,
                                           std::vector<Attempt>& history, json& attempts) {
    const Clock::time_point t0 = Clock::now();
    result = run(model);
    const bool reused = result.value("reused", false);
    result.erase("reused");
    const double seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    Attempt a{model.discretization.order, elements_of(model), model.analysis.statics.substeps,
              model.discretization.refine, result.value("status", std::string("error"))};
    a.refined = refined;
    a.steps = result.value("steps", json::array()).size();
    std::optional<AccuracyMeasure> m;
    if (has_solution(a.status)) {
        m = measure_accuracy(model, result, target);
        a.measured = m->quantities > 0 && m->missing == 0;
        a.worst = dynamic(model) ? m->worst_space : m->worst;
    }
    history.push_back(a);
    attempts.push_back(attempt_json(model, a, result, seconds, m ? &*m : nullptr));
    attempts.back()["reused"] = reused;
    return m;
}

// Whether the budget's time stopped the attempt: its run, or a companion of its estimate, ran out
// of the wall time the budget had left, which the caller gives every run as its limit
// (runs/accuracy_run.cpp); such a run keeps no numbers (status `time-limit`).
bool stopped_by_time(const json& result) {
    if (result.value("status", std::string()) == "time-limit") return true;
    const json none = json::array();
    const json& estimate = result.contains("estimate") ? result["estimate"] : json::object();
    for (const json& c : estimate.contains("companions") ? estimate["companions"] : none) {
        if (c.value("status", std::string()) == "time-limit") return true;
    }
    return false;
}

// Why the control stops when the budget's time stopped an attempt; `previous`: an earlier attempt
// with a solution is returned in its place (its estimates did not meet the target either).
std::string time_budget_stop(Clock::time_point start, const AccuracyBudget& budget, bool previous) {
    const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
    return "budget: " + number(elapsed) + " s spent of " + number(budget.seconds) +
           " s; the last attempt's runs stopped at the budget's time" +
           (previous ? ", the result is the attempt before it" : "");
}

// The budget's attempts or time spent after `attempts` attempts since `start`: why to stop, or "".
std::string budget_spent(std::size_t attempts, Clock::time_point start,
                         const AccuracyBudget& budget, const std::string& problem) {
    const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
    if (static_cast<int>(attempts) >= budget.attempts) {
        return "budget: " + std::to_string(budget.attempts) + " attempts; " + problem;
    }
    if (elapsed >= budget.seconds) {
        return "budget: " + number(elapsed) + " s spent of " + number(budget.seconds) + " s; " +
               problem;
    }
    return "";
}

std::string strategy(const Model& model) {
    if (model.discretization.formulation == Formulation::mixed) {
        return "h (element count from the observed order)";
    }
    return uses_trapezoidal_rule(model) ? "p while spectral, else h; refine doubled per step"
                                        : "p while spectral, else h";
}

}  // namespace

Model coarse_start(const Model& model) {
    Model start = model;
    if (model.discretization.formulation != Formulation::displacement) return start;
    for (Member& m : start.members) m.elements = 1;
    start.discretization.order = std::max(model.discretization.order, kSpectralOrder);
    if (uses_trapezoidal_rule(start)) {
        start.discretization.refine = std::max(
            start.discretization.refine, kTrapezoidalPointsPerOrder * start.discretization.order);
    }
    return start;
}

nlohmann::json control_accuracy(const Model& model, double tolerance, const AccuracyBudget& budget,
                                const EstimatedRun& run, const std::optional<Model>& start_from) {
    const double target = tolerance / 2.0;
    const Clock::time_point start = Clock::now();
    const bool mixed = model.discretization.formulation == Formulation::mixed;
    Model current = start_from.value_or(model);
    // Coarser companions need element counts that divide by 4: the first attempt rounds the
    // case's up (the attempts list its elements).
    for (Member& m : current.members) m.elements = round_up_elements(current, m.elements);
    // From a coarse start, a run that does not solve or cannot be estimated moves to the case's
    // own discretization (once) instead of stopping: one element may not resolve the solution
    // or may put a node at a chart's singular angle where the case's mesh does not.
    bool on_coarse_path = elements_of(current) != elements_of(model) ||
                          current.discretization.order != model.discretization.order ||
                          current.discretization.refine != model.discretization.refine;
    std::vector<Attempt> history;
    json attempts = json::array();
    json result;
    std::string stop;  // non-empty: not reached, why
    bool reached = false;
    bool refined = false;  // the current model refines the discretization of the previous one
    json solved;           // the last attempt's result with a solution (for a budget stop)
    while (true) {
        const std::optional<AccuracyMeasure> m =
            run_attempt(run, current, target, refined, result, history, attempts);
        const Attempt& a = history.back();
        Step next;
        if (m && meets(*m, target)) {
            reached = true;
            break;
        }
        if (stopped_by_time(result)) {
            // Its attempt stays in `attempts` (the record); the answer is the one before it.
            stop = time_budget_stop(start, budget, !solved.is_null());
            if (!solved.is_null()) {
                result = std::move(solved);
                history.pop_back();
            }
            break;
        }
        if (has_solution(a.status)) solved = result;
        if (a.status == "diverged") {
            // A Newton failure at a load step: more, smaller load steps (the discretization error
            // of a static state does not depend on the path, only Newton's convergence does).
            const int s = current.analysis.statics.substeps;
            const std::size_t reached_steps = result.value("steps", json::array()).size();
            if (history.size() >= 2 && history[history.size() - 2].status == "diverged" &&
                history[history.size() - 2].steps >= reached_steps) {
                // Twice the sub-steps did not pass the step that failed: what stops Newton is
                // not the load increment (a chart near its singular angle, a limit point).
                stop = "the solve fails at the same load step with twice the sub-steps (" +
                       std::to_string(s) + "): not a load-stepping problem (" +
                       result.value("message", std::string()) + ")";
            } else if (s * 2 > model.analysis.statics.substeps * budget.substeps_factor) {
                stop = "the solve diverges with " + std::to_string(s) +
                       " sub-steps per load step, the budget's largest (" +
                       result.value("message", std::string()) + ")";
            } else {
                next.model = current;
                next.model->analysis.statics.substeps = 2 * s;
                next.decision = "sub-steps " + std::to_string(s) + " -> " + std::to_string(2 * s) +
                                " (Newton failed: " + result.value("message", std::string()) + ")";
                refined = false;
            }
        } else if (a.status == "kinematics-unresolved") {
            next = split(current, 2.0, budget, "the elements do not resolve the rotation");
            refined = true;
        } else if (!m) {
            stop = (a.status == "singular" ? "singular chart: "
                                           : "the run's status is " + a.status + ": ") +
                   result.value("message", std::string());
        } else if (m->missing > 0 || m->quantities == 0) {
            stop = "no complete estimate: " + estimate_problem(*m, result);
        } else if (stagnated(history)) {
            stop = "round-off floor: the estimates stagnate near " + number(m->worst) +
                   " of their scale over the last refinements, above TOL/10 = " +
                   number(tolerance / 10.0);
        } else {
            next = mixed ? refine_mixed(current, a, m->worst_order, target, budget)
                         : refine_displacement(current, history, target, budget);
            refined = true;
        }
        if (on_coarse_path && (!stop.empty() || a.status == "diverged")) {
            const std::string why =
                stop.empty() ? "Newton failed: " + result.value("message", std::string()) : stop;
            stop.clear();
            on_coarse_path = false;
            next.model = model;
            next.decision = "the case's discretization (the coarse start failed: " + why + ")";
            refined = false;
        }
        if (!stop.empty()) break;
        if (!next.model) {
            stop = next.stop + "; " + (m ? m->first_problem : std::string());
            break;
        }
        attempts.back()["next"] = next.decision;
        stop = budget_spent(history.size(), start, budget, m ? m->first_problem : std::string());
        if (!stop.empty()) break;
        current = std::move(*next.model);
    }
    const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
    const Attempt& last = history.back();
    json acc = {
        {"tolerance", tolerance},
        {"target", target},
        {"status", reached ? "reached" : "not-reached"},
        {"strategy", strategy(model)},
        {"scales",
         {{"displacement", reference_length(model)},
          {"rotation", 1.0},
          {"frequency", "the frequency"}}},
        {"chosen",
         {{"elements", total(last.elements)}, {"order", last.order}, {"substeps", last.substeps}}},
        {"attempts", attempts},
        {"wall_seconds", elapsed},
        {"solver_status", last.status}};
    if (uses_trapezoidal_rule(model)) acc["chosen"]["refine"] = last.refine;
    if (last.measured) acc["worst_relative"] = last.worst;
    if (!reached) {
        acc["reason"] = stop;
        result["status"] = "accuracy-not-reached";
        result["message"] = "accuracy " + number(tolerance) + " not reached: " + stop;
    }
    result["accuracy"] = acc;
    return result;
}

nlohmann::json control_dynamic_accuracy(const Model& model, double tolerance,
                                        const AccuracyBudget& budget, const EstimatedRun& run) {
    const double target = tolerance / 2.0;
    const double share = kDynamicShare * target;
    const Clock::time_point start = Clock::now();
    const bool mixed = model.discretization.formulation == Formulation::mixed;
    const double case_tolerance = model.analysis.dynamics.time_tolerance;
    Model current = model;
    std::vector<Attempt> history;  // `worst`: the space part, which the mesh refinement follows
    json attempts = json::array();
    json result;
    std::optional<AccuracyMeasure> m;
    std::string stop;
    bool reached = false;
    bool refined = false;
    // The last attempt with a solution: its result, measure and model (for a budget stop).
    struct Solved {
        json result;
        std::optional<AccuracyMeasure> m;
        Model model;
    };
    std::optional<Solved> solved;
    while (true) {
        m = run_attempt(run, current, target, refined, result, history, attempts);
        const Attempt& a = history.back();
        if (m && meets(*m, target)) {
            reached = true;
            break;
        }
        if (stopped_by_time(result)) {
            // Its attempt stays in `attempts` (the record); the answer is the one before it.
            stop = time_budget_stop(start, budget, solved.has_value());
            if (solved) {
                result = std::move(solved->result);
                m = solved->m;
                current = std::move(solved->model);
                history.pop_back();
            }
            break;
        }
        if (has_solution(a.status)) solved = Solved{result, m, current};
        if (!m) {
            stop =
                "the run's status is " + a.status + ": " + result.value("message", std::string());
            break;
        }
        if (m->missing > 0 || m->quantities == 0) {
            stop = "no complete estimate: " + estimate_problem(*m, result);
            break;
        }
        const bool space = m->worst_space > share || m->space_unreliable > 0;
        // The combined estimate is at most the sum of its parts: with both parts within their
        // shares only reliability can fail it, and an unreliable space part refines the mesh.
        const bool time = m->worst_time > share || m->time_unreliable > 0 || !space;
        Model next = current;
        std::vector<std::string> decisions;
        refined = false;
        if (space) {
            if (stagnated(history)) {
                stop = "round-off floor: the space estimates stagnate near " +
                       number(m->worst_space) + " of their amplitude over the last refinements";
                break;
            }
            Step s = mixed ? refine_mixed(current, a, m->worst_order, share, budget)
                           : refine_displacement(current, history, share, budget);
            if (!s.model) {
                stop = s.stop + "; " + m->first_problem;
                break;
            }
            next = std::move(*s.model);
            decisions.push_back(s.decision);
            refined = true;
        }
        if (time) {
            Step s = tighten_time(next, *m, share, budget, case_tolerance);
            if (!s.model) {
                stop = s.stop + "; " + m->first_problem;
                break;
            }
            next = std::move(*s.model);
            decisions.push_back(s.decision);
        }
        std::string decision;
        for (const std::string& d : decisions) decision += (decision.empty() ? "" : "; ") + d;
        attempts.back()["next"] = decision;
        stop = budget_spent(history.size(), start, budget, m->first_problem);
        if (!stop.empty()) break;
        current = std::move(next);
    }
    const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
    const Attempt& last = history.back();
    json acc = {{"tolerance", tolerance},
                {"target", target},
                {"share", share},
                {"status", reached ? "reached" : "not-reached"},
                {"strategy", "the mesh (" + strategy(model) +
                                 ") and the adaptive steps' time tolerance, each to half the "
                                 "target"},
                {"scales", {{"history", "its amplitude (largest |u(t)| or |angle(t)|)"}}},
                {"chosen",
                 {{"elements", total(last.elements)},
                  {"order", last.order},
                  {"time_tolerance", current.analysis.dynamics.time_tolerance}}},
                {"attempts", attempts},
                {"wall_seconds", elapsed},
                {"solver_status", last.status}};
    if (uses_trapezoidal_rule(model)) acc["chosen"]["refine"] = last.refine;
    if (m) {
        acc["worst_relative"] = m->worst;
        acc["worst_quantity"] = m->worst_what;
        acc["space_estimate"] = m->worst_space;
        acc["time_estimate"] = m->worst_time;
    }
    if (!reached) {
        acc["reason"] = stop;
        if (has_solution(last.status)) {
            result["status"] = "accuracy-not-reached";
            result["message"] = "accuracy " + number(tolerance) + " not reached: " + stop;
        }
    }
    result["accuracy"] = acc;
    return result;
}

}  // namespace rotbeam::estimate
