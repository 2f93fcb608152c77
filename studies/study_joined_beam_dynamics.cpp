// `rotbeam study joined-beam-dynamics`: speed versus accuracy of
// the joined beam's 0–2 s response under the joint force 1e5 sin(20t) N, dead and follower
// (joined_beam_dynamics.hpp; each load measured on its own, with its own references). Per
// combination on the paper's mesh, every integrator setting (Δt of the fixed-step schemes,
// tolerances of the adaptive ones and of IDA) is run; its time error is the joint histories'
// distance to the combination's own same-mesh time-converged reference, its cost the median
// thread CPU time (and wall time) of the run. The Pareto front across all of them, which
// combination wins at which accuracy in words, and the checks that make the references
// trustworthy: the two formulations' references on the same discrete model, the mixed reference
// against IDA at a tight tolerance, and the space error of the paper mesh against a refined one.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <map>
#include <numeric>
#include <sstream>
#include <thread>

#include "core/results.hpp"
#include "core/static_driver.hpp"
#include "dynamic_speed.hpp"
#include "joined_beam_dynamics.hpp"
#include "runs/parallel.hpp"
#include "runs/timing.hpp"
#include "studies.hpp"
#include "study_math.hpp"
#include "study_plot.hpp"

namespace rotbeam::cli {

namespace {

nlohmann::json reference_json(const ReferenceResponse& r) {
    return {{"how", r.how},
            {"status", r.status},
            {"step_difference", r.step_difference},
            {"cpu_seconds", r.cpu_seconds},
            {"version", r.version},
            {"from_cache", r.from_cache}};
}

}  // namespace

namespace {

void sweep_table(const std::vector<DynamicPoint>& points, std::ostringstream& md) {
    md << "Every run (time error against the combination's own same-mesh reference):\n\n"
          "| combination | integrator | Δt / tolerance | status | unknowns | steps | Newton | CPU "
          "(median) | wall (median) | repeats | time error |\n"
          "|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const DynamicPoint& p : points) {
        md << "| " << p.combination << " | " << p.scheme << " | " << p.setting.label() << " | "
           << markdown_cell(p.status) << " | " << p.dofs << " | " << p.steps << " | " << p.newton
           << " | " << cpu_seconds_text(p.cpu) << " | " << cpu_seconds_text(p.wall) << " | "
           << p.repeats << " | " << sci(p.error) << " |\n";
    }
    md << "\n";
}

}  // namespace

namespace {

// The checks of the references: same discrete model across formulations, the mixed reference
// against IDA, and the paper mesh's space error. Appends to md, returns the JSON.
nlohmann::json reference_checks(const StudyOptions& o, bool quick, const ResponseWindow& w,
                                const std::map<std::string, ReferenceResponse>& same_mesh,
                                std::ostringstream& md) {
    nlohmann::json out;
    const std::string cache = out_path(o, "joined-beam-references");
    const Combination disp{Formulation::displacement, param::id_of<param::Quaternion>()};
    const Combination mixed{Formulation::mixed, param::id_of<param::WienerMilenkovic>()};
    ResponseWindow midpoint = w, p2 = w, p3 = w;
    midpoint.mass_rule = "midpoint";
    p2.order = 2;
    p3.order = 3;
    // These compare discretizations whose differences (≥ 1e-3) dwarf a time error of 1e-4, so
    // their two reference steps need only agree to that: 1e-2 of what they measure.
    const double step = reference_coarse_step(Formulation::displacement, o.quick);
    constexpr double kCheckAgreement = 1e-4;
    std::vector<ReferenceJob> jobs = {{disp, midpoint, step, {}, kCheckAgreement},
                                      {disp, p2, step, {}, kCheckAgreement}};
    if (!quick) jobs.push_back({disp, p3, step, {}, kCheckAgreement});
    // IDA at a tight tolerance on the mixed paper mesh, on its own thread beside the references.
    const TimeSetting tight{Integrator::ida, 1e-3, quick ? 1e-7 : 1e-8};
    nlohmann::json ida;
    double ida_cpu = 0.0;
    std::thread ida_thread([&] {
        const double c0 = thread_cpu_seconds();
        ida = run_spec(response_spec(mixed, tight, w));
        ida_cpu = thread_cpu_seconds() - c0;
    });
    try {
        compute_references(jobs, cache, o.jobs);
    } catch (...) {
        ida_thread.join();  // a joinable thread's destructor would end the program
        throw;
    }
    ida_thread.join();
    const ReferenceResponse& fine_space = jobs.back().result;
    const JointResponse ida_response = joint_response(ida);

    auto error_or_nan = [](const ReferenceResponse& a, const ReferenceResponse& b) {
        return has_solution(a.status) && has_solution(b.status)
                   ? response_error(a.response(), b.response())
                   : kNoValue;
    };
    md << "### The references\n\nEach combination's same-mesh reference is the formulation's "
          "high-order scheme (Gauss–Legendre 3, order 6, for the displacement formulation; Radau "
          "IIA 3, order 5, for the mixed) at two fixed steps; the finer run is the reference, "
          "accepted when the two agree to "
       << sci(kReferenceAgreement, 0)
       << " (the finer run's own error is then ≲ 1/30 of that). The error measure is the larger "
          "of the joint displacement's and the joint rotation vector's max over the output times "
          "(every "
       << w.output_interval * 1e3
       << " ms) of ‖Δ‖ / max ‖reference‖.\n\n| reference | coarser vs finer step | status | CPU "
          "|\n|---|---|---|---|\n";
    nlohmann::json refs = nlohmann::json::object();
    const auto reference_row = [&](const ReferenceResponse& r) {
        md << "| " << r.how << " | " << sci(r.step_difference) << " | " << markdown_cell(r.status)
           << " | "
           << (r.from_cache ? "cached (" + r.version + ")" : cpu_seconds_text(r.cpu_seconds))
           << " |\n";
    };
    for (const auto& [label, r] : same_mesh) {
        reference_row(r);
        refs[label] = reference_json(r);
    }
    for (const ReferenceJob& j : jobs) reference_row(j.result);
    out["same_mesh"] = refs;
    const auto find = [&](const std::string& label) {
        const auto it = same_mesh.find(label);
        return it == same_mesh.end() ? ReferenceResponse{} : it->second;
    };
    const ReferenceResponse mixed_ref = find(mixed.label());
    const ReferenceResponse disp_ref = find(disp.label());
    const double cross = error_or_nan(jobs[0].result, mixed_ref);
    const double ida_vs_reference = has_solution(mixed_ref.status) && ida_response.size() > 0
                                        ? response_error(ida_response, mixed_ref.response())
                                        : kNoValue;
    const double space_p1 = error_or_nan(disp_ref, fine_space);
    const double space_mixed = error_or_nan(mixed_ref, fine_space);
    const double space_p2 = quick ? kNoValue : error_or_nan(jobs[1].result, fine_space);
    md << "\nChecks (same error measure):\n\n"
       << "- Two formulations, one discrete model: the displacement formulation with linear "
          "elements, one-point stiffness and midpoint mass has the mixed element's frequencies "
          "(docs/displacement-modal.md); its reference against the mixed (WM) reference: "
       << sci(cross) << ".\n"
       << "- Two integrators: mixed (WM) IDA at rtol = atol = " << sci(tight.tolerance, 0) << " ("
       << ida.value("status", "") << ", " << dynamic_steps(ida) << " steps, "
       << cpu_seconds_text(ida_cpu)
       << " CPU) against the mixed Radau reference: " << sci(ida_vs_reference) << ".\n"
       << "- Space error of the paper mesh (" << w.elements
       << " elements per member) against the displacement formulation with order-"
       << (quick ? 2 : 3) << " elements on the same mesh (" << fine_space.how
       << "): displacement order 1 " << sci(space_p1) << ", mixed " << sci(space_mixed);
    if (!quick) md << ", displacement order 2 " << sci(space_p2);
    md << ". No Δt or tolerance removes this part; it adds to the time errors below.\n\n";
    out["checks"] = {{"cross_formulation", cross},
                     {"ida_tight_vs_reference", ida_vs_reference},
                     {"ida_tight_tolerance", tight.tolerance},
                     {"ida_tight_cpu_seconds", ida_cpu},
                     {"space_error_displacement_p1", space_p1},
                     {"space_error_mixed", space_mixed},
                     {"space_error_displacement_p2", space_p2}};
    out["extra_references"] = nlohmann::json::array();
    for (const ReferenceJob& j : jobs) out["extra_references"].push_back(reference_json(j.result));
    return out;
}

}  // namespace

namespace {

// Threads measuring one load's sweep (two loads at once: 6 runs in parallel on a shared machine,
// where each thread gets a share of the cores; the costs are per-thread CPU times).
constexpr int kSweepThreads = 3;

// One load's measurement: its references, sweep, checks, front and words (`md`, the JSON), and
// what its figure needs.
struct LoadStudy {
    std::string load;  // "dead" | "follower"
    ResponseWindow window;
    bool quick_sweep = false;  // the --quick sweep (and checks) on this window
    std::ostringstream md;
    nlohmann::json json;
    PanelFigure figure;  // one panel per formulation and integrator, parameterizations inside
    std::string front_file;
    std::map<std::string, ReferenceResponse> same_mesh;
};

const char* load_words(const std::string& load) {
    return load == "follower" ? "follower joint force 1e5 sin(20t) N (turns with the joint)"
                              : "dead joint force 1e5 sin(20t) N (fixed vertical direction)";
}

void measure_load(const StudyOptions& o, LoadStudy& l) {
    const ResponseWindow& w = l.window;
    const bool sweep_quick = o.quick || l.quick_sweep;
    const std::string cache = out_path(o, "joined-beam-references");
    std::vector<ReferenceJob> jobs;
    for (const Combination& c : all_combinations(false)) {
        jobs.push_back({c, w, reference_coarse_step(c.formulation, o.quick), {}});
    }
    compute_references(jobs, cache, o.jobs);
    std::vector<DynamicPoint> points;
    std::vector<std::string> notes;
    // Panels in the order of the table: per formulation, its schemes in the sweep's order.
    for (const Formulation f : comb::formulations()) {
        for (const TimeSetting& s : time_settings(f, sweep_quick))
            l.figure.panel(dynamic_panel_title(s, f));
    }
    // Every (combination, setting) run, measured by a pool of threads (each run single-threaded,
    // its cost its own thread's CPU time), kept in the order of the list.
    struct Task {
        const ReferenceJob* job;
        TimeSetting setting;
    };
    std::vector<Task> tasks;
    for (const ReferenceJob& j : jobs) {
        if (!has_solution(j.result.status)) continue;
        for (const TimeSetting& s : time_settings(j.combination.formulation, sweep_quick))
            tasks.push_back({&j, s});
    }
    std::vector<DynamicPoint> measured(tasks.size());
    std::atomic<size_t> next{0};
    auto worker = [&] {
        for (size_t i = next++; i < tasks.size(); i = next++) {
            measured[i] = dynamic_point(tasks[i].job->combination, tasks[i].setting, w,
                                        tasks[i].job->result.response());
        }
    };
    std::vector<std::thread> pool;
    for (int t = 0; t < kSweepThreads; ++t) pool.emplace_back(worker);
    for (std::thread& t : pool) t.join();
    size_t task = 0;
    for (const ReferenceJob& j : jobs) {
        if (!has_solution(j.result.status)) {
            notes.push_back(j.combination.label() + ": " + j.result.status.substr(0, 160));
            continue;
        }
        l.same_mesh[j.combination.label()] = j.result;
        const Formulation f = j.combination.formulation;
        std::map<std::string, std::pair<TimeSetting, Series>> by_scheme;
        for (const TimeSetting& s : time_settings(f, sweep_quick)) {
            points.push_back(measured[task++]);
            const DynamicPoint& p = points.back();
            auto& [setting, series] = by_scheme.try_emplace(s.scheme(), s, Series{}).first->second;
            series.label = p.series;
            series.add(s.tolerance > 0.0 ? s.tolerance : s.time_step, p.dofs, p.cpu, p.error);
            if (!std::isfinite(p.error)) l.figure.add_failure(dynamic_panel_title(s, f), p.spent);
        }
        for (const auto& [scheme, entry] : by_scheme) {
            const auto& [s, series] = entry;
            l.figure.add(dynamic_panel_title(s, f),
                         write_series(o,
                                      "data/joined_beam_dynamic_" + l.load + "_" +
                                          std::to_string(l.figure.files.size()) + ".dat",
                                      series),
                         std::string(param::name_of(j.combination.rotation)));
        }
    }
    std::ostringstream& md = l.md;
    md << "## " << (l.load == "follower" ? "Follower" : "Dead") << " load (" << w.case_name
       << ")\n\nThe joined beam under the " << load_words(l.load) << ", cases/" << w.case_name
       << ".yaml, 0–" << w.end_time << " s.\n\n";
    for (const std::string& n : notes) md << "- not run: " << n << "\n";
    if (!notes.empty()) md << "\n";
    l.json = {{"case", w.case_name}, {"not_run", notes}};
    if (l.quick_sweep && !o.quick) {
        md << "**Reduced sweep** (`--reduced-follower`): the --quick settings (fewer steps per "
              "scheme, no adaptive runs) on the full window, order-2 elements as the space "
              "reference and IDA at 1e-7 as the integrators' check.\n\n";
    }
    l.json["reduced_sweep"] = l.quick_sweep && !o.quick;
    l.json["references"] = reference_checks(o, sweep_quick, w, l.same_mesh, md);
    l.front_file = "data/joined_beam_dynamic_front_" + l.load + ".dat";
    l.json["front"] = dynamic_front(o, points, l.front_file, md);
    l.json["winners"] = winners_in_words(points, md);
    if (l.json["front"].empty()) {
        md << "No figure: no run gave a time error (the references and runs are listed).\n\n";
    } else {
        md << "![joined-beam-dynamics-" << l.load << ".png](joined-beam-dynamics-" << l.load
           << ".png)\n\n";
    }
    sweep_table(points, md);
    l.json["points"] = nlohmann::json::array();
    for (const DynamicPoint& p : points) l.json["points"].push_back(dynamic_point_json(p));
}

}  // namespace

nlohmann::json study_joined_beam_dynamics(const StudyOptions& o) {
    const ResponseWindow base = o.quick ? quick_window() : full_window();
    std::vector<LoadStudy> loads(2);
    loads[0].load = "dead";
    loads[1].load = "follower";
    for (LoadStudy& l : loads) {
        l.window = base;
        l.window.case_name = "joined-beam-" + l.load;
        l.quick_sweep = l.load == "follower" && o.reduced_follower;
    }
    // The two loads on two threads (each run is single-threaded and its cost is its thread's CPU
    // time, which the other thread does not change); figures after both, from this thread.
    std::vector<std::exception_ptr> failed(loads.size());
    std::vector<std::thread> threads;
    for (size_t i = 0; i < loads.size(); ++i) {
        threads.emplace_back([&, i] {
            try {
                measure_load(o, loads[i]);
            } catch (...) {
                failed[i] = std::current_exception();
            }
        });
    }
    for (std::thread& t : threads) t.join();
    for (const std::exception_ptr& e : failed)
        if (e) std::rethrow_exception(e);

    std::ostringstream md;
    md << "## Study: joined beam, dynamic speed versus accuracy\n\nThe joined beam under the joint "
          "force 1e5 sin(20t) N, dead (cases/joined-beam-dead.yaml) and follower "
          "(cases/joined-beam-follower.yaml), each measured on its own, 0–"
       << base.end_time << " s, on the paper's mesh (" << base.elements
       << " elements per member; displacement: linear elements, consistent mass). For every "
          "combination, every scheme it takes at several Δt (fixed steps) or tolerances (adaptive "
          "steps, IDA); "
          "cost = thread CPU time of the whole run_case (median of up to 3 repeats for runs under "
          "1 s; the machine was shared, so CPU rather than wall time decides), time error = the "
          "joint histories' distance to the combination's own same-mesh reference for that load. "
          "The space error of the mesh is measured separately per load and is the same for every "
          "integrator setting.\n\n";
    // How much the load's direction matters: the two loads' references, same combination.
    const std::string probe =
        Combination{Formulation::displacement, param::id_of<param::Quaternion>()}.label();
    const auto dead_ref = loads[0].same_mesh.find(probe);
    const auto follower_ref = loads[1].same_mesh.find(probe);
    double load_difference = kNoValue;
    if (dead_ref != loads[0].same_mesh.end() && follower_ref != loads[1].same_mesh.end()) {
        load_difference =
            response_error(follower_ref->second.response(), dead_ref->second.response());
        md << "The follower response against the dead one (" << probe
           << " references, same measure, relative to the dead response): " << sci(load_difference)
           << ".\n\n";
    }
    nlohmann::json out = {{"study", "joined-beam-dynamics"},
                          {"quick", o.quick},
                          {"end_time", base.end_time},
                          {"output_interval", base.output_interval},
                          {"elements_per_member", base.elements},
                          {"follower_vs_dead", load_difference},
                          {"loads", nlohmann::json::object()}};
    for (LoadStudy& l : loads) {
        if (!l.json["front"].empty())
            plot_panels(
                o, l.figure,
                {{"xcol", "3"},
                 {"ycol", "4"},
                 {"xlabel", "thread CPU time of the run, median of repeats [s]"},
                 {"ylabel", "max_t ‖Δu_{joint}‖ / max_t ‖u_{joint}‖ (same-mesh reference) [-]"},
                 {"plottitle", "Joined beam, " + l.load + " load, 0–" +
                                   cpu_seconds_text(base.end_time) +
                                   ": time error vs CPU time, one panel per formulation and "
                                   "integrator, the Pareto front of all runs in every panel"},
                 {"outbase", out_path(o, "joined-beam-dynamics-" + l.load)},
                 {"logx", "1"},
                 {"logy", "1"},
                 {"extra", out_path(o, l.front_file)},
                 {"extratitle", "Pareto front (all runs)"}});
        md << l.md.str();
        out["loads"][l.load] = l.json;
    }
    write_text(o, "study-joined-beam-dynamics.md", md.str());
    out["schema_version"] = kSchemaVersion;
    write_text(o, "study-joined-beam-dynamics.json", out.dump(1) + "\n");
    return out;
}

}  // namespace rotbeam::cli
