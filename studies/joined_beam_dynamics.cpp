#include "joined_beam_dynamics.hpp"

#include <time.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/results.hpp"
#include "core/static_driver.hpp"
#include "core/version.hpp"

namespace rotbeam::cli {

namespace {

std::string number(double x) {
    std::ostringstream s;
    s.precision(17);
    s << x;
    return s.str();
}

}  // namespace

std::string TimeSetting::label() const {
    std::ostringstream s;
    s.precision(3);
    if (integrator == Integrator::ida) {
        s << "ida-tol=" << tolerance;
    } else {
        s << "dt=" << time_step;
    }
    return s.str();
}

ResponseWindow full_window() { return ResponseWindow{}; }

ResponseWindow quick_window() {
    ResponseWindow w;
    w.end_time = 0.2;
    return w;
}

Integrator fixed_step_integrator(Formulation formulation) {
    return comb::traits(formulation).integrators.front();
}

std::vector<std::string> response_overrides(const Combination& c, const TimeSetting& s,
                                            const ResponseWindow& w) {
    std::vector<std::string> o = {"analysis.time_step=" + number(s.time_step),
                                  "analysis.end_time=" + number(w.end_time),
                                  "analysis.output_interval=" + number(w.output_interval)};
    if (c.formulation == Formulation::displacement) {
        // ρ∞ = 1: the undamped trapezoidal limit, the same time discretization as the mixed
        // formulation's fixed step (docs/displacement-dynamics.md).
        o.push_back("analysis.rho_infinity=1");
        o.push_back("discretization.order=" + std::to_string(w.order));
        if (!w.mass_rule.empty()) o.push_back("discretization.mass_rule=" + w.mass_rule);
    } else {
        o.push_back("analysis.integrator=" + std::string(choice_name(s.integrator)));
        if (s.integrator == Integrator::ida) {
            o.push_back("analysis.relative_tolerance=" + number(s.tolerance));
            o.push_back("analysis.absolute_tolerance=" + number(s.tolerance));
        }
    }
    return o;
}

RunSpec response_spec(const Combination& c, const TimeSetting& s, const ResponseWindow& w) {
    return RunSpec{w.case_name, c, response_overrides(c, s, w), w.elements};
}

History joint_history(const nlohmann::json& result) {
    History h;
    if (!has_solution(result.value("status", "")) || !converged_steps_exist(result)) return h;
    for (const auto& step : result["steps"]) {
        const Vec3 u = point_displacement(step, "joint");
        h.time.push_back(step["time"].get<double>());
        h.x.push_back(u[0]);
        h.y.push_back(u[1]);
        h.z.push_back(u[2]);
    }
    return h;
}

std::vector<TimeSetting> time_settings(Formulation formulation, bool quick) {
    std::vector<TimeSetting> s;
    // Down to twice the reference's coarser step (reference_coarse_step): no swept run is one of
    // the runs its reference is extrapolated from.
    std::vector<double> steps = {2e-3, 1e-3, 5e-4};
    if (!quick) {
        steps.push_back(2.5e-4);
        if (formulation == Formulation::displacement) {
            steps.push_back(1.25e-4);
            steps.push_back(6.25e-5);
        }
    }
    for (double dt : steps) s.push_back({fixed_step_integrator(formulation), dt, 0.0});
    if (comb::takes_integrator(formulation, Integrator::ida)) {
        const std::vector<double> tolerances =
            quick ? std::vector<double>{1e-3, 1e-4, 1e-5}
                  : std::vector<double>{1e-3, 1e-4, 1e-5, 1e-6, 1e-7};
        // IDA's Δt is only the initial step hint; the case's 1 ms.
        for (double tol : tolerances) s.push_back({Integrator::ida, 1e-3, tol});
    }
    return s;
}

double reference_coarse_step(Formulation formulation, bool quick) {
    // The mixed fixed step costs ~12× the displacement one per step on this mesh (486 against 114
    // unknowns, ≈ 3 Newton iterations per step), hence its coarser reference.
    const double full = formulation == Formulation::mixed ? 1.25e-4 : 3.125e-5;
    return quick ? 4.0 * full : full;
}

bool is_unavailable(const nlohmann::json& result) {
    return result.value("status", "") == "unavailable" || !result.value("available", true);
}

int dynamic_newton_iterations(const nlohmann::json& result) {
    for (const char* block : {"integrator", "dynamics"}) {
        if (result.contains(block) && result[block].is_object())
            return result[block].value("newton_iterations", 0);
    }
    return 0;
}

long dynamic_steps(const nlohmann::json& result) {
    for (const char* block : {"integrator", "dynamics"}) {
        if (result.contains(block) && result[block].is_object())
            return result[block].value("steps", 0L);
    }
    return 0;
}

double thread_cpu_seconds() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

}  // namespace rotbeam::cli

namespace rotbeam::cli {

namespace {

nlohmann::json history_json(const History& h) {
    return {{"time", h.time}, {"x", h.x}, {"y", h.y}, {"z", h.z}};
}

History history_from_json(const nlohmann::json& j) {
    History h;
    h.time = j["time"].get<std::vector<double>>();
    h.x = j["x"].get<std::vector<double>>();
    h.y = j["y"].get<std::vector<double>>();
    h.z = j["z"].get<std::vector<double>>();
    return h;
}

// What a cached reference must match to be used.
nlohmann::json reference_key(const Combination& c, const ResponseWindow& w, double coarse_step) {
    return {{"case", w.case_name},
            {"formulation", c.formulation_name()},
            {"rotation", c.rotation_name()},
            {"elements", w.elements},
            {"order", w.order},
            {"end_time", w.end_time},
            {"output_interval", w.output_interval},
            {"coarse_step", coarse_step},
            {"mass_rule", w.mass_rule},
            {"integrator", choice_name(fixed_step_integrator(c.formulation))}};
}

// The case is part of the name: the dead and the follower load's references share one folder.
std::string cache_file(const std::string& dir, const Combination& c, const ResponseWindow& w,
                       double coarse_step) {
    std::ostringstream s;
    // The case is in the name: the dead and follower references of one setting must not
    // overwrite each other (the key inside would refuse the other's, but it would be recomputed).
    s << dir << "/reference_" << w.case_name << "_" << c.formulation_name() << "_"
      << c.rotation_name() << "_n" << w.elements << "_p" << w.order
      << (w.mass_rule.empty() ? "" : "_" + w.mass_rule) << "_T" << w.end_time << "_dt"
      << coarse_step << ".json";
    return s.str();
}

}  // namespace

ReferenceResponse same_mesh_reference(const Combination& c, const ResponseWindow& w,
                                      double coarse_step, const std::string& cache_dir) {
    const nlohmann::json key = reference_key(c, w, coarse_step);
    const std::string file = cache_dir.empty() ? "" : cache_file(cache_dir, c, w, coarse_step);
    ReferenceResponse ref;
    if (!file.empty() && std::filesystem::exists(file)) {
        std::ifstream in(file);
        nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
        if (!j.is_discarded() && j.value("key", nlohmann::json()) == key) {
            ref.history = history_from_json(j["history"]);
            ref.how = j.value("how", "");
            ref.step_difference = j.value("step_difference", kNoValue);
            ref.extrapolation_change = j.value("extrapolation_change", kNoValue);
            ref.cpu_seconds = j.value("cpu_seconds", 0.0);
            ref.version = j.value("version", "");
            ref.status = j.value("status", "");
            ref.from_cache = true;
            return ref;
        }
    }
    const TimeSetting coarse{fixed_step_integrator(c.formulation), coarse_step, 0.0};
    const TimeSetting fine{fixed_step_integrator(c.formulation), coarse_step / 2.0, 0.0};
    const double start = thread_cpu_seconds();
    const nlohmann::json rc = run_spec(response_spec(c, coarse, w));
    if (is_unavailable(rc)) {
        ref.status = "unavailable: " + rc.value("message", "");
        return ref;
    }
    const nlohmann::json rf = run_spec(response_spec(c, fine, w));
    ref.cpu_seconds = thread_cpu_seconds() - start;
    ref.version = kGitDescribe;
    const History hc = joint_history(rc), hf = joint_history(rf);
    if (hc.size() == 0 || hf.size() == 0 || hc.size() != hf.size()) {
        ref.status = "reference runs failed: " + rc.value("status", "") + " / " +
                     rf.value("status", "") + " " + rf.value("message", "").substr(0, 120);
        return ref;
    }
    ref.history = extrapolate_history(hc, hf, 2.0, 2.0);
    ref.step_difference = history_error(hf, hc);
    ref.extrapolation_change = history_error(hf, ref.history);
    ref.status = "converged";
    std::ostringstream how;
    how << c.label() << ", " << w.elements << " elements per member"
        << (c.formulation == Formulation::displacement ? " of order " + std::to_string(w.order)
                                                       : "")
        << (w.mass_rule.empty() ? "" : ", " + w.mass_rule + " mass") << ", "
        << choice_name(fixed_step_integrator(c.formulation)) << " at Δt = " << coarse_step * 1e6
        << " and " << coarse_step * 5e5 << " µs, Richardson-extrapolated at order 2";
    ref.how = how.str();
    if (!file.empty()) {
        std::filesystem::create_directories(cache_dir);
        const nlohmann::json j = {{"key", key},
                                  {"how", ref.how},
                                  {"step_difference", ref.step_difference},
                                  {"extrapolation_change", ref.extrapolation_change},
                                  {"cpu_seconds", ref.cpu_seconds},
                                  {"version", ref.version},
                                  {"schema_version", kSchemaVersion},
                                  {"status", ref.status},
                                  {"history", history_json(ref.history)}};
        write_file_atomically(file, j.dump() + "\n");
    }
    return ref;
}

}  // namespace rotbeam::cli
