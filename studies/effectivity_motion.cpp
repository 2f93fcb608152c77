#include "effectivity_motion.hpp"

#include <cmath>
#include <cstring>
#include <optional>
#include <sstream>

#include "core/errors.hpp"
#include "core/so3.hpp"
#include "estimates/estimator_failure.hpp"
#include "estimates/history_estimate.hpp"
#include "estimates/point_difference.hpp"
#include "parameterizations/registry.hpp"
#include "study_common.hpp"

namespace rotbeam::cli {

namespace {

using json = nlohmann::json;

const char* const kMotionPoints[] = {"root", "q1", "mid", "q3", "tip"};

bool is_ida(const MotionRunSpec& s) {
    return s.formulation == Formulation::mixed && s.integrator == Integrator::ida;
}

// Whether the time levels are tolerances (IDA's rtol = atol, or the adaptive steps' global
// tolerance), refined by the tolerance/4 companion, rather than fixed steps.
bool tolerance_levels(const MotionRunSpec& s) { return is_ida(s) || s.time_tolerance > 0.0; }

// The level's tolerance of such a sequence.
double& level_tolerance(MotionRunSpec& s) { return is_ida(s) ? s.tolerance : s.time_tolerance; }

// The levels of the sequences (docs/error-estimates.md, "Dynamics in the effectivity study"):
//  - time, on the manufactured-time study's meshes (displacement p = 3 on 2 elements per member,
//    mixed 8 elements per member) and its steps, three or four levels (three are the fewest that
//    classify one level);
//  - space, at Δt = 0.005, where the time error is below a quarter of the finest level's space
//    error (measured: displacement p = 2, 1.3e-4 against 1.9e-3 at Δt = 0.0025; mixed 8 elements,
//    2.1e-5 against 9.4e-3 at Δt = 0.00125, ×4 per doubled step).
struct MotionLevels {
    std::vector<double> time, space;
    double space_dt = 0.005;
};

// Adaptive steps: tolerances a quarter apart (the companion's ratio), from where the steps leave
// the output interval's cap (at the cap the time error does not follow the tolerance:
// Gauss–Legendre 3 at 1e-2 … 1e-5 kept a time error near 2e-6), four levels, the reference at the
// finest over 64 (order 1 in the tolerance).
std::vector<double> adaptive_levels(Integrator integrator) {
    switch (integrator) {
        case Integrator::gauss_legendre_2:
            return {1e-3, 2.5e-4, 6.25e-5, 1.5625e-5};
        case Integrator::gauss_legendre_3:
            return {1e-5, 2.5e-6, 6.25e-7, 1.5625e-7};
        default:  // generalized-α, Radau IIA
            return {1e-2, 2.5e-3, 6.25e-4, 1.5625e-4};
    }
}

MotionLevels motion_levels(const MotionRunSpec& base, bool quick) {
    if (base.time_tolerance > 0.0) return {adaptive_levels(base.integrator), {}};
    switch (base.integrator) {
        case Integrator::gauss_legendre_2:
        case Integrator::gauss_legendre_3:
            return {{0.2, 0.1, 0.05}, {}};
        case Integrator::radau_iia_3:
            return {{0.1, 0.05, 0.025}, {}};
        case Integrator::ida:
            return {{1.6e-3, 4e-4, 1e-4}, {}};
        case Integrator::trapezoidal:
            return {{0.05, 0.025, 0.0125}, {2, 4, 8}};
        default:
            return quick ? MotionLevels{{0.025, 0.0125, 0.00625}, {}}
                         : MotionLevels{{0.05, 0.025, 0.0125, 0.00625}, {1, 2, 3}};
    }
}

MotionRunSpec motion_base(const Combination& c, Integrator integrator) {
    MotionRunSpec s;
    s.formulation = c.formulation;
    s.rotation = c.rotation;
    s.wm_map = c.wm_map.value_or(WmMap::plain);
    s.integrator = integrator;
    s.elements = c.formulation == Formulation::mixed ? 8 : 2;
    s.order = c.formulation == Formulation::mixed ? 1 : 3;
    if (integrator == Integrator::ida) s.dt = 0.05;  // the initial step hint
    s.motion = motion_within_reach(c.formulation, c.rotation);
    return s;
}

void add_motion_sequences(std::vector<MotionSequence>& out, const Combination& c,
                          Integrator integrator, bool with_space, bool quick,
                          bool adaptive = false) {
    MotionRunSpec base = motion_base(c, integrator);
    if (adaptive) {
        base.time_tolerance = adaptive_levels(integrator).front();
        // Mixed: 4 elements per member (h/4 companion 16), not 8 (32), whose adaptive companions
        // cost 4–5× (Radau IIA: the reference 88 s against 17 s, measured 2026-11-29); the time
        // part does not need the finer mesh, it is measured against the same mesh.
        if (base.formulation == Formulation::mixed) base.elements = 4;
    }
    const MotionLevels l = motion_levels(base, quick);
    out.push_back({base, MotionDirection::time, l.time});
    if (!with_space) return;
    MotionSequence space{base, MotionDirection::space, l.space};
    space.base.dt = l.space_dt;
    out.push_back(space);
}

// The largest over the output times of ‖u_h − u‖ (q = 0) or the angle of R_hᵀR (q = 1) at the
// tip, against the exact motion.
double exact_tip_error(const MotionRunSpec& spec, const json& result, int q) {
    const Model model = motion_run_model(spec);
    const double x = model.points.at(static_cast<size_t>(model.point_index("tip"))).position.x();
    double e = 0.0;
    for (const json& step : result["steps"]) {
        const oracle::ManufacturedMotion::State exact =
            spec.motion.state(x, step["time"].get<double>());
        const json& h = step["points"]["tip"];
        if (q == 0) {
            const Vec3 u(h["displacement"][0].get<double>(), h["displacement"][1].get<double>(),
                         h["displacement"][2].get<double>());
            e = std::max(e, (u - exact.u).norm());
        } else {
            Mat3 R;
            for (int i = 0; i < 3; ++i) {
                for (int j = 0; j < 3; ++j) R(i, j) = h["rotation_matrix"][i][j].get<double>();
            }
            e = std::max(e, so3::log_map(R.transpose() * exact.R).norm());
        }
    }
    return e;
}

// The same against another run's tip at the same output times (NaN where it has none).
double tip_difference(const json& a, const json& b, int q) {
    if (!b.contains("steps") || b["steps"].size() != a["steps"].size()) return kNoValue;
    double e = 0.0;
    for (size_t i = 0; i < a["steps"].size(); ++i) {
        const estimate::PointDifference d = estimate::point_difference(
            a["steps"][i]["points"]["tip"], b["steps"][i]["points"]["tip"]);
        e = std::max(e, q == 0 ? d.displacement : d.rotation);
    }
    return e;
}

// Whether every output time's estimate of `point`'s quantity (or of its `part`: "space", "time")
// says reliable, and the first reason otherwise.
json history_verdict(const json& result, const std::string& point, const char* quantity,
                     const char* part) {
    for (const json& step : result["steps"]) {
        if (!step.contains("estimate") || !step["estimate"].contains(point)) continue;
        const json& e =
            part ? step["estimate"][point][quantity][part] : step["estimate"][point][quantity];
        if (!e.value("reliable", false)) {
            return {{"reliable", false},
                    {"reason", e.value("reason", std::string("not reliable")) +
                                   " (at t = " + fixed(step["time"].get<double>(), 3) + ")"}};
        }
    }
    return {{"reliable", true}};
}

}  // namespace

MotionRunSpec MotionSequence::spec(size_t level) const {
    MotionRunSpec s = base;
    const double x = levels.at(level);
    if (direction == MotionDirection::time) {
        (tolerance_levels(s) ? level_tolerance(s) : s.dt) = x;
    } else if (s.formulation == Formulation::displacement) {
        s.order = static_cast<int>(x);
    } else {
        s.elements = static_cast<int>(x);
    }
    return s;
}

MotionRunSpec MotionSequence::reference(size_t level) const {
    if (direction == MotionDirection::space) {
        MotionRunSpec r = spec(level);
        r.dt /= kReferenceStepRatio;
        return r;
    }
    MotionRunSpec r = spec(levels.size() - 1);
    if (tolerance_levels(r)) {
        level_tolerance(r) /= kReferenceStepRatio * kReferenceStepRatio;  // order 1 in it
    } else {
        r.dt /= kReferenceStepRatio;
    }
    return r;
}

RefinementKind MotionSequence::kind() const {
    return direction == MotionDirection::space && base.formulation == Formulation::displacement
               ? RefinementKind::p
               : RefinementKind::h;
}

std::string MotionSequence::strategy() const {
    if (direction == MotionDirection::time) return tolerance_levels(base) ? "tolerance/4" : "dt/2";
    return kind() == RefinementKind::p ? "p+1" : "h/2,h/4";
}

std::string MotionSequence::x_label() const {
    if (direction == MotionDirection::time) {
        if (is_ida(base)) return "IDA tolerance";
        return base.time_tolerance > 0.0 ? "time tolerance" : "Δt";
    }
    return kind() == RefinementKind::p ? "order p" : "elements per member";
}

std::string MotionSequence::label() const {
    std::ostringstream s;
    s << base.label();
    if (direction == MotionDirection::time) {
        s << ", " << base.elements << " elements per member";
    } else {
        s << ", Δt " << base.dt;
    }
    return s.str();
}

std::string MotionSequence::combination_label() const {
    Combination c(base.formulation, base.rotation);
    if (base.wm_map == WmMap::continuous) c.wm_map = base.wm_map;
    return c.label();
}

std::vector<MotionSequence> motion_sequences(bool quick) {
    std::vector<MotionSequence> out;
    for (const Combination& c : all_combinations(false)) {
        const bool quaternion = c.rotation == param::id_of<param::Quaternion>();
        const bool mixed = c.formulation == Formulation::mixed;
        // Quick (the CI suite's): the displacement formulation's generalized-α in time only.
        // Full: every combination's default scheme in time and in space.
        if (quick && (!quaternion || mixed)) continue;
        add_motion_sequences(
            out, c, mixed ? Integrator::trapezoidal : Integrator::generalized_alpha, !quick, quick);
        if (quick || !quaternion) continue;
        const std::vector<Integrator> others =
            mixed ? std::vector<Integrator>{Integrator::radau_iia_3, Integrator::ida}
                  : std::vector<Integrator>{Integrator::gauss_legendre_2,
                                            Integrator::gauss_legendre_3};
        for (const Integrator i : others) add_motion_sequences(out, c, i, false, quick);
        // Adaptive steps (the tolerance/4 companion): every scheme that has them but the mixed
        // trapezoidal rule, whose reference run fails on this motion (docs/error-estimates.md,
        // "Effectivity of adaptive steps").
        const std::vector<Integrator> adaptive =
            mixed ? std::vector<Integrator>{Integrator::radau_iia_3}
                  : std::vector<Integrator>{Integrator::generalized_alpha,
                                            Integrator::gauss_legendre_2,
                                            Integrator::gauss_legendre_3};
        for (const Integrator i : adaptive) add_motion_sequences(out, c, i, false, quick, true);
    }
    return out;
}

json motion_result_json(const MotionRunResult& r) {
    json steps = json::array();
    const std::size_t n = r.u.size() / std::size(kMotionPoints);
    for (std::size_t k = 0; k < n; ++k) {
        json points = json::object();
        for (std::size_t p = 0; p < std::size(kMotionPoints); ++p) {
            const Vec3& u = r.u[k * std::size(kMotionPoints) + p];
            const Mat3& R = r.R[k * std::size(kMotionPoints) + p];
            json rows = json::array();
            for (int i = 0; i < 3; ++i) rows.push_back({R(i, 0), R(i, 1), R(i, 2)});
            points[kMotionPoints[p]] = {{"displacement", {u[0], u[1], u[2]}},
                                        {"rotation_matrix", rows},
                                        {"rotation_angle", so3::rotation_angle(R)}};
        }
        steps.push_back({{"time", r.times.at(k)}, {"points", points}});
    }
    return {{"status", r.status},
            {"message", r.message},
            {"dofs", r.dofs},
            {"wall_seconds", r.wall_seconds},
            {"integrator", {{"newton_iterations", r.newton_iterations}}},
            {"steps", steps}};
}

json estimated_motion_run(const MotionRunSpec& spec) {
    return with_motion_estimate(run_manufactured_motion(spec), spec);
}

json with_motion_estimate(const MotionRunResult& run, const MotionRunSpec& spec) {
    json result = motion_result_json(run);
    estimate::add_dynamic_estimate(motion_run_model(spec), result, [&](const Model& companion) {
        MotionRunSpec c = spec;
        c.order = companion.discretization.order;
        c.elements = companion.members[0].elements;
        c.dt = companion.analysis.dynamics.time_step;
        c.tolerance = companion.analysis.dynamics.relative_tolerance;
        c.time_tolerance = companion.analysis.dynamics.time_tolerance;
        c.output_interval = companion.analysis.dynamics.output_interval;
        return motion_result_json(run_manufactured_motion(c));
    });
    return result;
}

namespace {

constexpr const char* kMotionOrder = "discretization.order=";
constexpr const char* kMotionIntegrator = "analysis.dynamics.integrator=";
constexpr const char* kMotionStep = "analysis.dynamics.time_step=";
constexpr const char* kMotionTolerance = "analysis.dynamics.relative_tolerance=";
constexpr const char* kMotionRho = "analysis.dynamics.rho_infinity=";
constexpr const char* kMotionTimeTolerance = "analysis.dynamics.time_tolerance=";

std::string exact_text(double x) {
    std::ostringstream s;
    s.precision(17);
    s << x;
    return s.str();
}

}  // namespace

RunSpec motion_run_spec(const MotionRunSpec& m) {
    Combination c(m.formulation, m.rotation);
    if (m.wm_map == WmMap::continuous) c.wm_map = m.wm_map;
    RunSpec r{
        kManufacturedMotionCase,
        c,
        {kMotionOrder + std::to_string(m.order),
         kMotionIntegrator + std::string(choice_name(m.integrator)), kMotionStep + exact_text(m.dt),
         kMotionTolerance + exact_text(m.tolerance), kMotionRho + exact_text(m.rho_infinity)},
        m.elements};
    // Only adaptive runs name it, so a fixed-step run keeps the name it always had.
    if (m.time_tolerance > 0.0) {
        r.overrides.push_back(kMotionTimeTolerance + exact_text(m.time_tolerance));
    }
    return r;
}

MotionRunSpec motion_spec_of(const RunSpec& r) {
    MotionRunSpec m;
    m.formulation = r.combination.formulation;
    m.rotation = r.combination.rotation;
    m.wm_map = r.combination.wm_map.value_or(WmMap::plain);
    m.elements = r.elements;
    m.motion = motion_within_reach(m.formulation, m.rotation);
    for (const std::string& o : r.overrides) {
        const auto value = [&](const char* key) {
            return o.rfind(key, 0) == 0 ? std::optional<std::string>(o.substr(std::strlen(key)))
                                        : std::nullopt;
        };
        if (const auto v = value(kMotionOrder)) {
            m.order = std::stoi(*v);
        } else if (const auto i = value(kMotionIntegrator)) {
            const std::optional<Integrator> parsed = parse_choice<Integrator>(*i);
            if (!parsed) throw InputError(std::string(kManufacturedMotionCase) + ": " + o);
            m.integrator = *parsed;
        } else if (const auto d = value(kMotionStep)) {
            m.dt = std::stod(*d);
        } else if (const auto t = value(kMotionTolerance)) {
            m.tolerance = std::stod(*t);
        } else if (const auto rho = value(kMotionRho)) {
            m.rho_infinity = std::stod(*rho);
        } else if (const auto tt = value(kMotionTimeTolerance)) {
            m.time_tolerance = std::stod(*tt);
        } else {
            throw InputError(std::string(kManufacturedMotionCase) + ": " + o +
                             ": not a setting of the built-in motion");
        }
    }
    return m;
}

LevelQuantities motion_quantities(const MotionSequence& s, size_t level, const json& result,
                                  const json& reference) {
    LevelQuantities out;
    if (!result.contains("estimate") || !result["estimate"].contains("history")) return out;
    const MotionRunSpec spec = s.spec(level);
    const json& history = result["estimate"]["history"]["tip"];
    const bool time = s.direction == MotionDirection::time;
    const char* const part = time ? "time" : "space";
    const char* const quantities[] = {"displacement", "rotation"};
    for (int q = 0; q < 2; ++q) {
        const json& h = history[quantities[q]];
        const double true_error = exact_tip_error(spec, result, q);
        // The refined direction's own true error: in time the distance to the fine-step run on
        // the same mesh, in space the exact error of the same mesh at a small enough step.
        const double true_part = time ? tip_difference(result, reference, q)
                                      : exact_tip_error(s.reference(level), reference, q);
        const double floor = estimate::kFailureFloor * (q == 0 ? spec.motion.length : 1.0);
        const std::string name = std::string("tip ") + quantities[q] + " history";
        // The whole estimate, and the part the sequence refines (its size beside the other's).
        json total = history_verdict(result, "tip", quantities[q], nullptr);
        total["error"] = h["max_error"];
        total["space"] = h["max_space"];
        total["time"] = h["max_time"];
        json refined = history_verdict(result, "tip", quantities[q], part);
        if (time && !result["estimate"].value("time_reliable", true)) {
            refined = {{"reliable", false},
                       {"reason", result["estimate"].value("time_reason", std::string())}};
        }
        refined["error"] = h[time ? "max_time" : "max_space"];
        refined["other_part"] = h[time ? "max_space" : "max_time"];
        out.push_back({name + ", space + time", total, true_error, floor});
        if (std::isfinite(true_part)) {
            out.push_back({name + ", " + part + " part", refined, true_part, floor});
        }
    }
    return out;
}

double motion_level_rate(const MotionSequence& s, const json& result) {
    if (!result.contains("estimate") || !result["estimate"].contains("theoretical_order"))
        return kNoValue;
    const json& t = result["estimate"]["theoretical_order"];
    if (s.direction == MotionDirection::space) return t.value("displacement", kNoValue);
    // The levels follow the companion's ratio (motion_levels), which the method names.
    const double ratio = result["estimate"].value("time_method", "") == "tolerance/4" ? 4.0 : 2.0;
    return t.value("time", kNoValue) * std::log2(ratio);
}

}  // namespace rotbeam::cli
