#include "joined_beam_dynamics.hpp"

#include <time.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/results.hpp"
#include "core/static_driver.hpp"
#include "core/version.hpp"
#include "runs/parallel.hpp"

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
    if (tolerance > 0.0) {
        s << "tol=" << tolerance;
    } else {
        s << "dt=" << time_step;
    }
    if (newton_tolerance > 0.0) s << ", newton=" << newton_tolerance;
    return s.str();
}

std::string TimeSetting::scheme() const {
    const std::string name(choice_name(integrator));
    return tolerance > 0.0 && integrator != Integrator::ida ? name + " adaptive" : name;
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

Integrator reference_integrator(Formulation formulation) {
    return formulation == Formulation::displacement ? Integrator::gauss_legendre_3
                                                    : Integrator::radau_iia_3;
}

std::vector<std::string> response_overrides(const Combination& c, const TimeSetting& s,
                                            const ResponseWindow& w) {
    std::vector<std::string> o = {"analysis.integrator=" + std::string(choice_name(s.integrator)),
                                  "analysis.time_step=" + number(s.time_step),
                                  "analysis.end_time=" + number(w.end_time),
                                  "analysis.output_interval=" + number(w.output_interval)};
    if (s.integrator == Integrator::generalized_alpha) {
        // ρ∞ = 1: the undamped trapezoidal limit, the same time discretization as the mixed
        // formulation's fixed step (docs/displacement-dynamics.md).
        o.push_back("analysis.rho_infinity=1");
    }
    if (s.integrator == Integrator::ida) {
        o.push_back("analysis.relative_tolerance=" + number(s.tolerance));
        o.push_back("analysis.absolute_tolerance=" + number(s.tolerance));
    } else if (s.tolerance > 0.0) {
        o.push_back("analysis.time_tolerance=" + number(s.tolerance));
    }
    if (s.newton_tolerance > 0.0) {
        o.push_back("solver.residual_tolerance=" + number(s.newton_tolerance));
        o.push_back("solver.increment_tolerance=" + number(s.newton_tolerance));
    }
    if (c.formulation == Formulation::displacement) {
        o.push_back("discretization.order=" + std::to_string(w.order));
        if (!w.mass_rule.empty()) o.push_back("discretization.mass_rule=" + w.mass_rule);
    }
    return o;
}

RunSpec response_spec(const Combination& c, const TimeSetting& s, const ResponseWindow& w) {
    return RunSpec{w.case_name, c, response_overrides(c, s, w), w.elements};
}

JointResponse joint_response(const nlohmann::json& result, const std::string& point) {
    JointResponse r;
    if (!has_solution(result.value("status", "")) || !converged_steps_exist(result)) return r;
    const auto add = [](History& h, double t, const nlohmann::json& v) {
        h.time.push_back(t);
        h.x.push_back(v[0].get<double>());
        h.y.push_back(v[1].get<double>());
        h.z.push_back(v[2].get<double>());
    };
    for (const auto& step : result["steps"]) {
        const double t = step["time"].get<double>();
        const nlohmann::json& joint = step["points"][point];
        add(r.displacement, t, joint["displacement"]);
        add(r.rotation, t, joint["rotation_vector"]);
    }
    return r;
}

History joint_history(const nlohmann::json& result) { return joint_response(result).displacement; }

double response_error(const JointResponse& u, const JointResponse& reference) {
    const double d = history_error(u.displacement, reference.displacement);
    const double r = history_error(u.rotation, reference.rotation);
    return std::isfinite(d) && std::isfinite(r) ? std::max(d, r) : kNoValue;
}

std::vector<TimeSetting> time_settings(Formulation formulation, bool quick) {
    std::vector<TimeSetting> s;
    // Fixed steps divide the 2 ms output interval (the outputs fall on step times; others would
    // put the histories on another grid, which history_error refuses).
    const auto fixed = [&](Integrator i, const std::vector<double>& steps) {
        for (double dt : steps) s.push_back({i, dt, 0.0});
    };
    // The second-order schemes from the step where their time error nears 1e-2 down to the one
    // a 1e-3 error needs (docs/performance.md, "joined-beam-dynamic"); the --quick window is 10×
    // shorter, its phase errors 10× smaller.
    if (formulation == Formulation::displacement) {
        fixed(Integrator::generalized_alpha,
              quick ? std::vector<double>{1e-3, 5e-4, 2.5e-4}
                    : std::vector<double>{2.5e-4, 1.25e-4, 6.25e-5, 3.125e-5});
        fixed(Integrator::gauss_legendre_2, quick ? std::vector<double>{2e-3, 1e-3}
                                                  : std::vector<double>{1e-3, 5e-4, 4e-4, 2.5e-4});
        fixed(Integrator::gauss_legendre_3,
              quick ? std::vector<double>{4e-3, 2e-3} : std::vector<double>{2e-3, 1e-3, 5e-4});
    } else {
        fixed(Integrator::trapezoidal,
              quick ? std::vector<double>{1e-3, 5e-4} : std::vector<double>{5e-4, 2.5e-4});
        // 2/3 ms: three steps per output, between 1 ms (1.09e-3, just above the 1e-3 of the
        // target) and 0.5 ms (1.6e-4).
        fixed(Integrator::radau_iia_3,
              quick ? std::vector<double>{2e-3, 1e-3}
                    : std::vector<double>{1e-3, 2e-3 / 3.0, 5e-4, 4e-4, 2.5e-4});
        // IDA's Δt is only the initial step hint; the case's 1 ms.
        for (double tol :
             quick ? std::vector<double>{1e-4, 1e-5} : std::vector<double>{1e-5, 1e-6, 1e-7})
            s.push_back({Integrator::ida, 1e-3, tol});
    }
    if (!quick) {
        // Adaptive steps of the high-order schemes (the global tolerance on the configuration,
        // translations over the reference length: the joint's amplitude is ~0.25 of it). At 1e-4
        // Gauss–Legendre 3 already resolves the ~1 kHz modes (11 798 steps, error 2.7e-5).
        const Integrator high = reference_integrator(formulation);
        for (double tol : {1e-3, 1e-4}) s.push_back({high, 1e-3, tol});
    }
    return s;
}

double reference_coarse_step(Formulation formulation, bool /*quick*/) {
    // Measured on 0–2 s (dead load, docs/performance.md "joined-beam-dynamic"): Gauss–Legendre 3
    // at 125 / 62.5 µs agree to 7.8e-7 (displacement) and 9.3e-6 (rotation); Radau IIA at 250 /
    // 125 µs only to 5.8e-5 (it damps the ~1 kHz modes whose rotation content is ~1e-5 and
    // converges at order ~2 there), hence its 4× finer pair. The --quick window (0–0.2 s) needs
    // the same steps: Gauss–Legendre 3 at 250 / 125 µs differ there by 1.7e-5 (the high modes
    // are excited at the start, not over the window).
    return formulation == Formulation::mixed ? 6.25e-5 : 1.25e-4;
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
// `richardson`: the second-order pair's key (unchanged since its first cache files).
nlohmann::json reference_key(const Combination& c, const ResponseWindow& w, double coarse_step,
                             bool richardson) {
    nlohmann::json key = {
        {"case", w.case_name},
        {"formulation", c.formulation_name()},
        {"rotation", c.rotation_name()},
        {"elements", w.elements},
        {"order", w.order},
        {"end_time", w.end_time},
        {"output_interval", w.output_interval},
        {"coarse_step", coarse_step},
        {"mass_rule", w.mass_rule},
        {"integrator", choice_name(richardson ? fixed_step_integrator(c.formulation)
                                              : reference_integrator(c.formulation))}};
    if (!richardson) key["method"] = "finer of two fixed steps";
    if (w.point != "joint") key["point"] = w.point;  // the joined beam's keys are unchanged
    return key;
}

std::string cache_file(const std::string& dir, const Combination& c, const ResponseWindow& w,
                       double coarse_step, bool richardson) {
    std::ostringstream s;
    // The case is in the name: the dead and follower references of one setting must not
    // overwrite each other (the key inside would refuse the other's, but it would be recomputed).
    s << dir << "/reference_" << w.case_name << "_" << c.formulation_name() << "_"
      << c.rotation_name() << "_n" << w.elements << "_p" << w.order
      << (w.mass_rule.empty() ? "" : "_" + w.mass_rule) << "_T" << w.end_time
      << (richardson ? "" : "_" + std::string(choice_name(reference_integrator(c.formulation))))
      << "_dt" << coarse_step << ".json";
    return s.str();
}

// "converged", or why the two runs do not make a reference.
std::string agreement_status(double step_difference, double agreement) {
    if (step_difference <= agreement) return "converged";
    std::ostringstream s;
    s << "not converged: the two reference steps differ by " << sci(step_difference)
      << " of the amplitude, above " << sci(agreement, 0);
    return s.str();
}

// The reference in words: what ran, `scheme` at the two steps, and `method` (how they combine).
std::string reference_how(const Combination& c, const ResponseWindow& w, double coarse_step,
                          Integrator scheme, const std::string& method) {
    std::ostringstream how;
    how << c.label() << ", " << w.elements << " elements per member"
        << (c.formulation == Formulation::displacement ? " of order " + std::to_string(w.order)
                                                       : "")
        << (w.mass_rule.empty() ? "" : ", " + w.mass_rule + " mass") << ", " << choice_name(scheme)
        << " at Δt = " << coarse_step * 1e6 << " and " << coarse_step * 5e5 << " µs, " << method;
    return how.str();
}

// The cached reference in `file` when its key is `key` (null otherwise), its common fields read
// into `ref`.
nlohmann::json read_cached_reference(const std::string& file, const nlohmann::json& key,
                                     ReferenceResponse& ref) {
    if (file.empty() || !std::filesystem::exists(file)) return nullptr;
    std::ifstream in(file);
    nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
    if (j.is_discarded() || j.value("key", nlohmann::json()) != key) return nullptr;
    ref.how = j.value("how", "");
    ref.step_difference = j.value("step_difference", kNoValue);
    ref.extrapolation_change = j.value("extrapolation_change", kNoValue);
    ref.cpu_seconds = j.value("cpu_seconds", 0.0);
    ref.version = j.value("version", "");
    ref.from_cache = true;
    return j;
}

// Writes `ref` with its `key` and `extra` fields (the histories) to `file` under `dir`.
void write_cached_reference(const std::string& file, const std::string& dir,
                            const nlohmann::json& key, const ReferenceResponse& ref,
                            nlohmann::json extra) {
    if (file.empty()) return;
    std::filesystem::create_directories(dir);
    extra["key"] = key;
    extra["how"] = ref.how;
    extra["step_difference"] = ref.step_difference;
    extra["cpu_seconds"] = ref.cpu_seconds;
    extra["version"] = ref.version;
    extra["schema_version"] = kSchemaVersion;
    write_file_atomically(file, extra.dump() + "\n");
}

}  // namespace

ReferenceResponse same_mesh_reference(const Combination& c, const ResponseWindow& w,
                                      double coarse_step, const std::string& cache_dir,
                                      double agreement) {
    const nlohmann::json key = reference_key(c, w, coarse_step, false);
    const std::string file =
        cache_dir.empty() ? "" : cache_file(cache_dir, c, w, coarse_step, false);
    ReferenceResponse ref;
    if (const nlohmann::json j = read_cached_reference(file, key, ref); !j.is_null()) {
        ref.status = agreement_status(ref.step_difference, agreement);
        if (ref.status == "converged") {
            ref.history = history_from_json(j["displacement"]);
            ref.rotation = history_from_json(j["rotation"]);
        }
        return ref;
    }
    const Integrator scheme = reference_integrator(c.formulation);
    const double start = thread_cpu_seconds();
    const nlohmann::json rc = run_spec(response_spec(c, {scheme, coarse_step, 0.0}, w));
    if (is_unavailable(rc)) {
        ref.status = "unavailable: " + rc.value("message", "");
        return ref;
    }
    const nlohmann::json rf = run_spec(response_spec(c, {scheme, coarse_step / 2.0, 0.0}, w));
    ref.cpu_seconds = thread_cpu_seconds() - start;
    ref.version = kGitDescribe;
    ref.how = reference_how(c, w, coarse_step, scheme, "the finer run");
    const JointResponse hc = joint_response(rc, w.point), hf = joint_response(rf, w.point);
    if (hc.size() == 0 || hf.size() == 0 || hc.size() != hf.size()) {
        ref.status = "reference runs failed: " + rc.value("status", "") + " / " +
                     rf.value("status", "") + " " + rf.value("message", "").substr(0, 120);
        return ref;
    }
    ref.history = hf.displacement;
    ref.rotation = hf.rotation;
    ref.step_difference = response_error(hc, hf);
    ref.status = agreement_status(ref.step_difference, agreement);
    write_cached_reference(
        file, cache_dir, key, ref,
        {{"displacement", history_json(hf.displacement)}, {"rotation", history_json(hf.rotation)}});
    if (ref.status != "converged") ref.history = ref.rotation = History{};
    return ref;
}

void compute_references(std::vector<ReferenceJob>& jobs, const std::string& cache_dir,
                        int threads) {
    std::vector<size_t> order(jobs.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = i;
    const auto steps = [&](size_t i) { return jobs[i].window.end_time / jobs[i].coarse_step; };
    std::stable_sort(order.begin(), order.end(),
                     [&](size_t a, size_t b) { return steps(a) > steps(b); });
    for_each_parallel(order.size(), threads, [&](size_t k) {
        ReferenceJob& j = jobs[order[k]];
        j.result =
            same_mesh_reference(j.combination, j.window, j.coarse_step, cache_dir, j.agreement);
    });
}

ReferenceResponse richardson_reference(const Combination& c, const ResponseWindow& w,
                                       double coarse_step, const std::string& cache_dir) {
    const nlohmann::json key = reference_key(c, w, coarse_step, true);
    const std::string file =
        cache_dir.empty() ? "" : cache_file(cache_dir, c, w, coarse_step, true);
    ReferenceResponse ref;
    if (const nlohmann::json j = read_cached_reference(file, key, ref); !j.is_null()) {
        ref.history = history_from_json(j["history"]);
        ref.status = j.value("status", "");
        return ref;
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
    ref.how = reference_how(c, w, coarse_step, fixed_step_integrator(c.formulation),
                            "Richardson-extrapolated at order 2");
    write_cached_reference(file, cache_dir, key, ref,
                           {{"extrapolation_change", ref.extrapolation_change},
                            {"status", ref.status},
                            {"history", history_json(ref.history)}});
    return ref;
}

}  // namespace rotbeam::cli
