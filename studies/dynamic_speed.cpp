#include "dynamic_speed.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "core/results.hpp"
#include "core/static_driver.hpp"
#include "parameterizations/registry.hpp"
#include "runs/timing.hpp"
#include "study_math.hpp"
#include "study_plot.hpp"

namespace rotbeam::cli {

DynamicPoint dynamic_point(const Combination& c, const TimeSetting& s, const ResponseWindow& w,
                           const JointResponse& reference) {
    DynamicPoint p;
    p.combination = c.label();
    p.formulation = c.formulation;
    p.scheme = s.scheme();
    p.series = c.label() + "/" + p.scheme;
    p.setting = s;
    const RunSpec spec = response_spec(c, s, w);
    std::vector<double> cpu, wall;
    nlohmann::json first;
    const int most = timing_repeats(3);
    for (int i = 0; i < most; ++i) {
        const double c0 = thread_cpu_seconds();
        const Timing t = time_in_process(
            [&] {
                nlohmann::json r = run_spec(spec);
                if (i == 0) first = std::move(r);
            },
            1);
        cpu.push_back(thread_cpu_seconds() - c0);
        wall.push_back(t.median_seconds);
        const double spent = std::accumulate(cpu.begin(), cpu.end(), 0.0);
        if (!has_solution(first.value("status", "")) || cpu.back() > 1.0 || spent > 2.0) break;
    }
    p.status = first.value("status", "error");
    p.dofs = first.value("dofs", 0);
    p.newton = dynamic_newton_iterations(first);
    p.steps = dynamic_steps(first);
    p.repeats = static_cast<int>(cpu.size());
    p.spent = cpu.front();
    if (has_solution(p.status)) {
        p.cpu = median(cpu);
        p.wall = median(wall);
        p.error = response_error(joint_response(first, w.point), reference);
    } else {
        p.status += ": " + first.value("message", "").substr(0, 100);
    }
    return p;
}

namespace {

nlohmann::json finite_or_null(double x) { return std::isfinite(x) ? nlohmann::json(x) : nullptr; }

}  // namespace

nlohmann::json dynamic_point_json(const DynamicPoint& p) {
    return {{"combination", p.combination},
            {"integrator", choice_name(p.setting.integrator)},
            {"scheme", p.scheme},
            {"time_step", p.setting.time_step},
            {"tolerance", p.setting.tolerance},
            {"status", p.status},
            {"cpu_seconds", finite_or_null(p.cpu)},
            {"wall_seconds", finite_or_null(p.wall)},
            {"repeats", p.repeats},
            {"time_error", finite_or_null(p.error)},
            {"dofs", p.dofs},
            {"newton_iterations", p.newton},
            {"steps", p.steps}};
}

std::string cpu_seconds_text(double seconds) {
    if (!std::isfinite(seconds)) return "—";
    std::ostringstream t;
    t.precision(3);
    t << seconds << " s";
    return t.str();
}

nlohmann::json dynamic_front(const StudyOptions& o, const std::vector<DynamicPoint>& points,
                             const std::string& front_file, std::ostringstream& md) {
    std::vector<double> cost, error;
    for (const DynamicPoint& p : points) {
        cost.push_back(p.cpu);
        error.push_back(p.error);
    }
    const std::vector<bool> front = pareto_front(cost, error);
    std::vector<const DynamicPoint*> on;
    for (size_t i = 0; i < points.size(); ++i)
        if (front[i]) on.push_back(&points[i]);
    // No run with a finite time error (every reference failed, or every run stopped): no front,
    // and no data file, which would be empty (an empty file reads as a truncated one).
    if (on.empty()) {
        md << "No Pareto front: no run gave a time error.\n\n";
        return nlohmann::json::array();
    }
    std::sort(on.begin(), on.end(),
              [](const DynamicPoint* a, const DynamicPoint* b) { return a->cpu < b->cpu; });
    std::ostringstream data;
    data.precision(10);
    md << "Pareto front (no other run is both cheaper in CPU time and more accurate):\n\n"
          "| combination | integrator | Δt / tolerance | steps | Newton | CPU | wall | time error "
          "|\n"
          "|---|---|---|---|---|---|---|---|\n";
    nlohmann::json out = nlohmann::json::array();
    for (const DynamicPoint* p : on) {
        data << p->cpu << " " << std::max(p->error, 1e-17) << "\n";
        md << "| " << p->combination << " | " << p->scheme << " | " << p->setting.label() << " | "
           << p->steps << " | " << p->newton << " | " << cpu_seconds_text(p->cpu) << " | "
           << cpu_seconds_text(p->wall) << " | " << sci(p->error) << " |\n";
        out.push_back(dynamic_point_json(*p));
    }
    md << "\n";
    write_text(o, front_file, data.str());
    return out;
}

const std::vector<double>& accuracy_levels() {
    static const std::vector<double> levels = {1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8};
    return levels;
}

std::vector<int> cheapest_per_level(const std::vector<DynamicPoint>& points,
                                    const std::vector<double>& levels) {
    std::vector<int> out;
    for (double level : levels) {
        int best = -1;
        for (size_t i = 0; i < points.size(); ++i) {
            const DynamicPoint& p = points[i];
            if (!std::isfinite(p.error) || !std::isfinite(p.cpu) || p.error > level) continue;
            const DynamicPoint* b = best < 0 ? nullptr : &points[static_cast<size_t>(best)];
            if (!b || p.cpu < b->cpu || (p.cpu == b->cpu && p.error < b->error))
                best = static_cast<int>(i);
        }
        out.push_back(best);
    }
    return out;
}

nlohmann::json winners_in_words(const std::vector<DynamicPoint>& points, std::ostringstream& md) {
    const std::vector<double>& levels = accuracy_levels();
    const std::vector<int> best = cheapest_per_level(points, levels);
    const auto scheme_of = [&](size_t k) {
        return best[k] < 0 ? std::string() : points[static_cast<size_t>(best[k])].scheme;
    };
    md << "**Which scheme wins at which accuracy** (the cheapest run in CPU time whose time error "
          "is at or below the level; generated from the runs above):\n\n";
    nlohmann::json out = nlohmann::json::array();
    // Consecutive levels won by the same scheme make one range.
    for (size_t k = 0; k < levels.size();) {
        size_t end = k;
        while (end + 1 < levels.size() && scheme_of(end + 1) == scheme_of(k)) ++end;
        md << "- error ≤ " << sci(levels[k], 0);
        if (end > k) md << " … " << sci(levels[end], 0);
        if (best[k] < 0) {
            md << ": no run reached " << (end > k ? "them" : "it") << ".\n";
        } else {
            md << ": **" << scheme_of(k) << "** wins (";
            for (size_t i = k; i <= end; ++i) {
                const DynamicPoint& p = points[static_cast<size_t>(best[i])];
                md << (i > k ? "; " : "") << sci(levels[i], 0) << ": " << p.combination << ", "
                   << p.setting.label() << ", " << cpu_seconds_text(p.cpu) << " CPU, error "
                   << sci(p.error);
            }
            md << ").\n";
        }
        k = end + 1;
    }
    md << "\n";
    for (size_t k = 0; k < levels.size(); ++k) {
        nlohmann::json j = {{"level", levels[k]}, {"index", best[k]}};
        if (best[k] >= 0) {
            const DynamicPoint& p = points[static_cast<size_t>(best[k])];
            j["scheme"] = p.scheme;
            j["combination"] = p.combination;
            j["setting"] = p.setting.label();
            j["cpu_seconds"] = p.cpu;
            j["time_error"] = p.error;
        }
        out.push_back(j);
    }
    return out;
}

std::string dynamic_panel_title(const TimeSetting& s, Formulation formulation) {
    const std::string f(choice_name(formulation));
    if (s.integrator == Integrator::ida) return f + ", IDA (BDF ≤ 2), tolerances";
    if (s.integrator == Integrator::generalized_alpha) return f + ", generalized-α ρ∞ = 1, Δt";
    return f + ", " + s.scheme() + (s.tolerance > 0.0 ? ", tolerances" : ", Δt");
}

namespace {

std::vector<TimeSetting> fixed_steps(Integrator i, const std::vector<double>& steps) {
    std::vector<TimeSetting> s;
    for (double dt : steps) s.push_back({i, dt, 0.0});
    return s;
}

std::vector<TimeSetting> concatenated(std::vector<std::vector<TimeSetting>> parts) {
    std::vector<TimeSetting> s;
    for (auto& p : parts) s.insert(s.end(), p.begin(), p.end());
    return s;
}

std::vector<TimeSetting> ida_tolerances(const std::vector<double>& tolerances) {
    std::vector<TimeSetting> s;
    for (double tol : tolerances) s.push_back({Integrator::ida, 1e-3, tol});
    return s;
}

std::vector<TimeSetting> adaptive(Integrator i, const std::vector<double>& tolerances) {
    std::vector<TimeSetting> s;
    for (double tol : tolerances) s.push_back({i, 1e-3, tol});
    return s;
}

// --quick: the quaternion (displacement) and Wiener–Milenkovic (mixed) only; the
// parameterizations of a formulation give the same errors to 2–3 digits on these small
// amplitudes (docs/studies.md), the full form lists them all.
std::vector<Combination> speed_combinations(bool quick) {
    std::vector<Combination> out;
    for (const Combination& c : all_combinations(false)) {
        if (quick && c.rotation != (c.formulation == Formulation::displacement
                                        ? param::id_of<param::Quaternion>()
                                        : param::id_of<param::WienerMilenkovic>()))
            continue;
        out.push_back(c);
    }
    return out;
}

DynamicSpeedProblem joined_beam_problem(bool quick) {
    DynamicSpeedProblem p;
    p.key = "joined_beam";
    p.window = full_window();
    p.combinations = speed_combinations(quick);
    p.error_words = "joint displacement and rotation vector";
    for (Formulation f : {Formulation::displacement, Formulation::mixed})
        p.coarse_step[f] = reference_coarse_step(f, quick);
    if (!quick) {
        // The joined-beam-dynamics study's sweep on its 0–2 s window.
        for (Formulation f : {Formulation::displacement, Formulation::mixed})
            p.settings[f] = time_settings(f, false);
        p.title = "Joined beam, dead load, 0–2 s";
        return p;
    }
    // 0–20 ms (ten outputs): the high modes are excited from the start, so every scheme's error
    // is resolved above the references' 1e-5 agreement at these steps; each run costs ≤ 0.2 s.
    p.window.end_time = 0.02;
    p.title = "Joined beam, dead load, 0–20 ms (quick)";
    p.settings[Formulation::displacement] =
        concatenated({fixed_steps(Integrator::generalized_alpha, {1e-3, 5e-4, 2.5e-4}),
                      fixed_steps(Integrator::gauss_legendre_2, {2e-3, 1e-3, 5e-4}),
                      fixed_steps(Integrator::gauss_legendre_3, {2e-3, 1e-3, 5e-4})});
    p.settings[Formulation::mixed] =
        concatenated({fixed_steps(Integrator::trapezoidal, {1e-3, 5e-4, 2.5e-4}),
                      fixed_steps(Integrator::radau_iia_3, {2e-3, 1e-3, 5e-4}),
                      ida_tolerances({1e-4, 1e-5, 1e-6})});
    return p;
}

DynamicSpeedProblem free_vibration_problem(bool quick) {
    DynamicSpeedProblem p;
    p.key = "free_vibration";
    p.combinations = speed_combinations(quick);
    p.error_words = "tip displacement and rotation vector";
    ResponseWindow& w = p.window;
    w.case_name = "free-vibration";
    w.point = "tip";
    w.order = 2;  // the case's
    w.output_interval = 5e-3;
    // The --quick references: Gauss–Legendre 3 at 125 / 62.5 µs, Radau IIA at 62.5 / 31.25 µs
    // (the joined beam's pairs; Radau damps the unresolved modes and converges more slowly there).
    p.coarse_step[Formulation::displacement] = 1.25e-4;
    p.coarse_step[Formulation::mixed] = 6.25e-5;
    // Every fixed step divides the 5 ms output interval.
    if (quick) {
        // 0–0.1 s (0.84 periods of the first mode), 2 elements.
        w.end_time = 0.1;
        w.elements = 2;
        p.title = "Free vibration, 2 elements, 0–0.1 s (quick)";
        p.settings[Formulation::displacement] =
            concatenated({fixed_steps(Integrator::generalized_alpha, {2.5e-3, 1e-3, 5e-4}),
                          fixed_steps(Integrator::gauss_legendre_2, {5e-3, 2.5e-3, 1e-3}),
                          fixed_steps(Integrator::gauss_legendre_3, {5e-3, 2.5e-3, 1e-3})});
        p.settings[Formulation::mixed] =
            concatenated({fixed_steps(Integrator::trapezoidal, {2.5e-3, 1e-3, 5e-4}),
                          fixed_steps(Integrator::radau_iia_3, {5e-3, 2.5e-3, 1e-3}),
                          ida_tolerances({1e-4, 1e-5, 1e-6})});
        return p;
    }
    // The case: 0–0.5 s (about 4 periods of the first mode), 8 elements.
    w.end_time = 0.5;
    w.elements = 8;
    // The release puts ~1e-3 of the tip rotation's amplitude into the mesh modes at 1–20 kHz
    // (displacement, order 2: 3.8e-4 at 1–5 kHz, 1.7e-4 at 5–10 kHz, 4.8e-5 at 10–20 kHz,
    // 2.5e-6 at 20–40 kHz, < 5e-7 above; measured on a resolved 0–2 ms run, docs/studies.md).
    // A pair agrees to 1e-5 only when its coarser step resolves them: Gauss–Legendre 3 at 125 /
    // 62.5 µs differ by 1.1e-3 (tip rotation), at 10 / 5 µs by 1.04e-5, at 5 / 2.5 µs by 1.9e-6.
    p.coarse_step[Formulation::displacement] = 5e-6;
    // The mixed mesh (8 linear elements) holds more: 1.4e-3 at 1–5 kHz, 6.5e-4 at 5–10 kHz,
    // 1.9e-4 in its 32.6 kHz pair of modes. Radau IIA damps a mode by |R(iωΔt)| per step, so its
    // pair agrees only once neither run damps that pair over 0.5 s (measured: 10 / 5 µs and
    // 5 / 2.5 µs differ by 1.65e-4 and 1.67e-4). By |R|, 2.5 / 1.25 µs keep 0.61 and 0.985 of it
    // (a 7e-5 difference), 1.25 µs / 625 ns 0.985 and 0.9995 (3e-6).
    p.coarse_step[Formulation::mixed] = 1.25e-6;
    p.title = "Free vibration, 8 elements, 0–0.5 s";
    p.settings[Formulation::displacement] =
        concatenated({fixed_steps(Integrator::generalized_alpha, {1e-3, 5e-4, 2.5e-4, 1.25e-4}),
                      fixed_steps(Integrator::gauss_legendre_2, {5e-3, 2.5e-3, 1.25e-3, 6.25e-4}),
                      // Down to the steps that resolve the 1–20 kHz modes (above 125 µs every
                      // setting's tip-rotation error is floored at their ~1e-3); 7.8125 µs
                      // reaches ~1e-5 (10 / 5 µs differ by 1.04e-5).
                      fixed_steps(Integrator::gauss_legendre_3,
                                  {5e-3, 2.5e-3, 1.25e-3, 1.25e-4, 3.125e-5, 1.5625e-5, 7.8125e-6}),
                      // Adaptive to 1e-5, not 1e-6: at 1e-6 the step-doubling pair resolves the
                      // mesh modes with 169 400 steps (57–92 s per combination, 2.3e-6), the fixed
                      // 7.8125 µs above costs a tenth of it for the 1e-5 level.
                      adaptive(Integrator::gauss_legendre_3, {1e-4, 1e-5})});
    p.settings[Formulation::mixed] =
        concatenated({fixed_steps(Integrator::trapezoidal, {1e-3, 5e-4, 2.5e-4, 1.25e-4}),
                      fixed_steps(Integrator::radau_iia_3, {2.5e-3, 1.25e-3, 6.25e-4, 3.125e-4}),
                      // 1e-5, not 1e-6: 1e-6 took 471 600 steps, 141–226 s per combination.
                      adaptive(Integrator::radau_iia_3, {1e-4, 1e-5}),
                      ida_tolerances({1e-4, 1e-5, 1e-6, 1e-7})});
    return p;
}

}  // namespace

std::vector<DynamicSpeedProblem> dynamic_speed_problems(bool quick) {
    return {joined_beam_problem(quick), free_vibration_problem(quick)};
}

DynamicSpeedProblem dynamic_speed_problem(const std::string& key, bool quick) {
    for (DynamicSpeedProblem& p : dynamic_speed_problems(quick))
        if (p.key == key) return p;
    throw std::invalid_argument("no dynamic speed problem " + key);
}

std::vector<std::vector<ReferenceResponse>> speed_references(
    const std::vector<DynamicSpeedProblem>& problems, const std::string& cache_dir, int threads) {
    std::vector<ReferenceJob> jobs;
    for (const DynamicSpeedProblem& p : problems) {
        for (const Combination& c : p.combinations)
            jobs.push_back({c, p.window, p.coarse_step.at(c.formulation), {}});
    }
    compute_references(jobs, cache_dir, threads);
    std::vector<std::vector<ReferenceResponse>> out;
    size_t next = 0;
    for (const DynamicSpeedProblem& p : problems) {
        out.emplace_back();
        for (size_t i = 0; i < p.combinations.size(); ++i)
            out.back().push_back(std::move(jobs[next++].result));
    }
    return out;
}

DynamicSpeedResult measure_dynamic_speed(const DynamicSpeedProblem& p,
                                         std::vector<ReferenceResponse> references) {
    if (references.size() != p.combinations.size())
        throw std::invalid_argument("measure_dynamic_speed: one reference per combination");
    DynamicSpeedResult r;
    r.references = std::move(references);
    const double start = thread_cpu_seconds();
    for (size_t i = 0; i < p.combinations.size(); ++i) {
        const Combination& c = p.combinations[i];
        const ReferenceResponse& ref = r.references[i];
        r.cpu_seconds += ref.cpu_seconds;
        if (!has_solution(ref.status)) {
            r.not_run.push_back(c.label() + ": " + ref.status.substr(0, 160));
            continue;
        }
        for (const TimeSetting& s : p.settings.at(c.formulation))
            r.points.push_back(dynamic_point(c, s, p.window, ref.response()));
    }
    r.cpu_seconds += thread_cpu_seconds() - start;
    return r;
}

namespace {

nlohmann::json problem_section(const StudyOptions& o, const DynamicSpeedProblem& p,
                               std::vector<ReferenceResponse> references, std::ostringstream& md) {
    const DynamicSpeedResult r = measure_dynamic_speed(p, std::move(references));
    md << "### " << p.title << "\n\ncases/" << p.window.case_name << ".yaml, " << p.window.elements
       << " elements per member"
       << " (displacement: order " << p.window.order << "), outputs every "
       << p.window.output_interval * 1e3 << " ms; time error = the larger of the " << p.error_words
       << " histories' max over the outputs of ‖Δ‖ / max ‖reference‖. Measured with references in "
       << cpu_seconds_text(r.cpu_seconds) << " CPU.\n\n";
    for (const std::string& n : r.not_run) md << "- not run: " << n << "\n";
    md << "| reference | coarser vs finer step | status | CPU |\n|---|---|---|---|\n";
    nlohmann::json refs = nlohmann::json::array();
    for (const ReferenceResponse& ref : r.references) {
        md << "| " << ref.how << " | " << sci(ref.step_difference) << " | "
           << markdown_cell(ref.status) << " | "
           << (ref.from_cache ? "cached (" + ref.version + ")" : cpu_seconds_text(ref.cpu_seconds))
           << " |\n";
        refs.push_back({{"how", ref.how},
                        {"status", ref.status},
                        {"step_difference", finite_or_null(ref.step_difference)},
                        {"from_cache", ref.from_cache}});
    }
    md << "\n";
    nlohmann::json out = {{"problem", p.key},
                          {"case", p.window.case_name},
                          {"end_time", p.window.end_time},
                          {"elements", p.window.elements},
                          {"cpu_seconds", r.cpu_seconds},
                          {"references", refs},
                          {"not_run", r.not_run}};
    const std::string front_file = "data/speed_dynamic_" + p.key + "_front.dat";
    out["front"] = dynamic_front(o, r.points, front_file, md);
    out["winners"] = winners_in_words(r.points, md);
    // The figure: a panel per formulation and scheme, the parameterizations inside.
    PanelFigure figure;
    std::map<std::string, Series> series;
    std::map<std::string, std::pair<std::string, std::string>> panel_and_rotation;
    std::vector<std::string> order;
    for (const DynamicPoint& q : r.points) {
        if (!series.count(q.series)) order.push_back(q.series);
        Series& s = series[q.series];
        s.label = q.series;
        s.add(q.setting.tolerance > 0.0 ? q.setting.tolerance : q.setting.time_step, q.dofs, q.cpu,
              q.error);
        const std::string panel = dynamic_panel_title(q.setting, q.formulation);
        panel_and_rotation[q.series] = {panel, q.combination.substr(q.combination.find('/') + 1)};
        if (!std::isfinite(q.error)) figure.add_failure(panel, q.spent);
    }
    for (const std::string& label : order) {
        const auto& [panel, rotation] = panel_and_rotation[label];
        figure.add(panel,
                   write_series(o,
                                "data/speed_dynamic_" + p.key + "_" +
                                    std::to_string(figure.files.size()) + ".dat",
                                series[label]),
                   rotation);
    }
    // No run with a time error, no figure: every reference failed (each listed above with its
    // reason) or every run stopped, and a link to a figure that gnuplot was given nothing to
    // draw would leave a hole in the report.
    if (out["front"].empty()) {
        md << "No figure: no run gave a time error (the references and runs are listed).\n\n";
    } else {
        plot_panels(o, figure,
                    {{"xcol", "3"},
                     {"ycol", "4"},
                     {"xlabel", "thread CPU time of the whole run, median of repeats [s]"},
                     {"ylabel", "time error against the same-mesh high-order reference [-]"},
                     {"plottitle", p.title + ": time error vs CPU, one panel per formulation and "
                                             "scheme, the Pareto front of all runs in every panel"},
                     {"outbase", out_path(o, "speed-dynamic-" + p.key)},
                     {"logx", "1"},
                     {"logy", "1"},
                     {"extra", out_path(o, front_file)},
                     {"extratitle", "Pareto front (all runs)"}});
        md << "![speed-dynamic-" << p.key << ".png](speed-dynamic-" << p.key << ".png)\n\n";
    }
    md << "Every run:\n\n| combination | scheme | Δt / tolerance | status | steps | Newton | CPU "
          "| repeats | time error |\n|---|---|---|---|---|---|---|---|---|\n";
    out["points"] = nlohmann::json::array();
    for (const DynamicPoint& q : r.points) {
        md << "| " << q.combination << " | " << q.scheme << " | " << q.setting.label() << " | "
           << markdown_cell(q.status) << " | " << q.steps << " | " << q.newton << " | "
           << cpu_seconds_text(q.cpu) << " | " << q.repeats << " | " << sci(q.error) << " |\n";
        out["points"].push_back(dynamic_point_json(q));
    }
    md << "\n";
    return out;
}

}  // namespace

nlohmann::json dynamic_speed_section(const StudyOptions& o, std::ostringstream& md) {
    md << "## Dynamics: speed versus accuracy of the time schemes\n\nEvery combination with "
          "every scheme it takes (displacement: generalized-α ρ∞ = 1, Gauss–Legendre 2 and 3; "
          "mixed: the trapezoidal rule, Radau IIA 3, IDA) at several steps or tolerances. Cost: "
          "the thread CPU time of the whole run_case (median of up to 3 repeats for runs under "
          "1 s). Error: against the combination's same-mesh high-order reference "
          "(Gauss–Legendre 3 or Radau IIA at two steps that agree to "
       << sci(kReferenceAgreement, 0)
       << " of the amplitude; the finer is the reference), never against a second-order "
          "scheme.\n\n";
    nlohmann::json out = nlohmann::json::array();
    double cpu = 0.0;
    const std::vector<DynamicSpeedProblem> problems = dynamic_speed_problems(o.quick);
    // The references are not timed: all of them first, on every thread the study has, then the
    // timed points on one.
    std::vector<std::vector<ReferenceResponse>> references =
        speed_references(problems, out_path(o, "joined-beam-references"), o.jobs);
    for (size_t i = 0; i < problems.size(); ++i) {
        out.push_back(problem_section(o, problems[i], std::move(references[i]), md));
        cpu += out.back()["cpu_seconds"].get<double>();
    }
    md << "The dynamic part took " << cpu_seconds_text(cpu) << " CPU in all.\n\n";
    return out;
}

}  // namespace rotbeam::cli
