// `rotbeam study joined-beam-dynamics` (issue 12 item 4, issue 9 item 7): speed versus accuracy of
// the joined beam's 0–2 s response under the dead joint force (joined_beam_dynamics.hpp). Per
// combination on the paper's mesh, every integrator setting (Δt of the fixed-step schemes, IDA
// tolerances) is run; its time error is the joint history's distance to the combination's own
// same-mesh self-converged reference, its cost the median thread CPU time (and wall time) of the
// run. The Pareto front across all of them, which combination wins at which accuracy in words,
// and the checks that make the references trustworthy: the two formulations' references on the
// same discrete model, the mixed fixed step against IDA at a tight tolerance, and the space error
// of the paper mesh against a refined one.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <map>
#include <numeric>
#include <sstream>
#include <thread>

#include "joined_beam_dynamics.hpp"
#include "studies.hpp"
#include "study_math.hpp"
#include "timing.hpp"

namespace rotbeam::cli {

namespace {

struct DynamicPoint {
    std::string combination, series;
    TimeSetting setting;
    std::string status;
    double cpu = kNoValue, wall = kNoValue, error = kNoValue;
    int dofs = 0, newton = 0, repeats = 0;
    long steps = 0;
};

// One setting: the first run gives the history (and its error); runs cheaper than 1 s CPU are
// repeated up to 3 times (2 s budget) for the median.
DynamicPoint dynamic_point(const Combination& c, const TimeSetting& s, const ResponseWindow& w,
                           const History& reference) {
    DynamicPoint p;
    p.combination = c.label();
    p.series = c.label() + "/" + s.integrator;
    p.setting = s;
    const RunSpec spec = response_spec(c, s, w);
    std::vector<double> cpu, wall;
    nlohmann::json first;
    for (int i = 0; i < 3; ++i) {
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
        if (first.value("status", "") != "converged" || cpu.back() > 1.0 || spent > 2.0) break;
    }
    p.status = first.value("status", "error");
    p.dofs = first.value("dofs", 0);
    p.newton = dynamic_newton_iterations(first);
    p.steps = dynamic_steps(first);
    p.repeats = static_cast<int>(cpu.size());
    if (p.status == "converged") {
        p.cpu = median(cpu);
        p.wall = median(wall);
        p.error = history_error(joint_history(first), reference);
    } else {
        p.status += ": " + first.value("message", "").substr(0, 100);
    }
    return p;
}

nlohmann::json point_json(const DynamicPoint& p) {
    auto num = [](double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(); };
    return {{"combination", p.combination},
            {"integrator", p.setting.integrator},
            {"time_step", p.setting.time_step},
            {"tolerance", p.setting.tolerance},
            {"status", p.status},
            {"cpu_seconds", num(p.cpu)},
            {"wall_seconds", num(p.wall)},
            {"repeats", p.repeats},
            {"time_error", num(p.error)},
            {"dofs", p.dofs},
            {"newton_iterations", p.newton},
            {"steps", p.steps}};
}

nlohmann::json reference_json(const ReferenceResponse& r) {
    return {{"how", r.how},
            {"status", r.status},
            {"step_difference", r.step_difference},
            {"extrapolation_change", r.extrapolation_change},
            {"cpu_seconds", r.cpu_seconds},
            {"version", r.version},
            {"from_cache", r.from_cache}};
}

// Computes the references of `jobs` on two threads (they are not timed; each run is
// single-threaded), in order of the list.
struct ReferenceJob {
    Combination combination;
    ResponseWindow window;
    double coarse_step;
    ReferenceResponse result;
};

void compute_references(std::vector<ReferenceJob>& jobs, const std::string& cache_dir) {
    std::atomic<size_t> next{0};
    auto worker = [&] {
        for (size_t i = next++; i < jobs.size(); i = next++) {
            jobs[i].result = same_mesh_reference(jobs[i].combination, jobs[i].window,
                                                 jobs[i].coarse_step, cache_dir);
        }
    };
    std::thread a(worker), b(worker);
    a.join();
    b.join();
}

std::string seconds_text(double s) {
    if (!std::isfinite(s)) return "—";
    std::ostringstream t;
    t.precision(3);
    t << s << " s";
    return t.str();
}

}  // namespace

namespace {

// The Pareto front of (CPU time, time error) across every run, its table and data file.
nlohmann::json dynamic_front(const StudyOptions& o, const std::vector<DynamicPoint>& points,
                             std::ostringstream& md) {
    std::vector<double> cost, error;
    for (const DynamicPoint& p : points) {
        cost.push_back(p.cpu);
        error.push_back(p.error);
    }
    const std::vector<bool> front = pareto_front(cost, error);
    std::vector<const DynamicPoint*> on;
    for (size_t i = 0; i < points.size(); ++i)
        if (front[i]) on.push_back(&points[i]);
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
        md << "| " << p->combination << " | " << p->setting.integrator << " | "
           << p->setting.label() << " | " << p->steps << " | " << p->newton << " | "
           << seconds_text(p->cpu) << " | " << seconds_text(p->wall) << " | " << sci(p->error)
           << " |\n";
        out.push_back(point_json(*p));
    }
    md << "\n";
    write_text(o, "data/joined_beam_dynamic_front.dat", data.str());
    return out;
}

void winners_in_words(const std::vector<DynamicPoint>& points, std::ostringstream& md) {
    md << "Cheapest run reaching each time-error level (CPU time):\n\n";
    for (double level : {1e-1, 1e-2, 1e-3, 1e-4}) {
        const DynamicPoint* best = nullptr;
        for (const DynamicPoint& p : points) {
            if (std::isfinite(p.error) && p.error <= level && (!best || p.cpu < best->cpu))
                best = &p;
        }
        md << "- ≤ " << sci(level, 0) << ": ";
        if (best) {
            md << best->combination << " with " << best->setting.integrator << " "
               << best->setting.label() << ", " << seconds_text(best->cpu) << " CPU (error "
               << sci(best->error) << ")\n";
        } else {
            md << "no run reached it\n";
        }
    }
    md << "\n";
}

void sweep_table(const std::vector<DynamicPoint>& points, std::ostringstream& md) {
    md << "Every run (time error against the combination's own same-mesh reference):\n\n"
          "| combination | integrator | Δt / tolerance | status | unknowns | steps | Newton | CPU "
          "(median) | wall (median) | repeats | time error |\n"
          "|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const DynamicPoint& p : points) {
        md << "| " << p.combination << " | " << p.setting.integrator << " | " << p.setting.label()
           << " | " << p.status << " | " << p.dofs << " | " << p.steps << " | " << p.newton << " | "
           << seconds_text(p.cpu) << " | " << seconds_text(p.wall) << " | " << p.repeats << " | "
           << sci(p.error) << " |\n";
    }
    md << "\n";
}

}  // namespace

namespace {

// The checks of the references: same discrete model across formulations, fixed step against IDA,
// and the paper mesh's space error. Appends to md, returns the JSON.
nlohmann::json reference_checks(const StudyOptions& o, const ResponseWindow& w,
                                const std::map<std::string, ReferenceResponse>& same_mesh,
                                std::ostringstream& md) {
    nlohmann::json out;
    const std::string cache = out_path(o, "joined-beam-references");
    const Combination disp{"displacement", "quaternion", ""};
    const Combination mixed{"mixed", "wiener-milenkovic", ""};
    ResponseWindow midpoint = w, p2 = w, p3 = w;
    midpoint.mass_rule = "midpoint";
    p2.order = 2;
    p3.order = 3;
    // These compare discretizations whose differences (≥ 1e-3) dwarf the time errors of a 2×
    // coarser reference step, which halves their cost (order 3: ~10 CPU-minutes otherwise).
    const double step = 2.0 * reference_coarse_step("displacement", o.quick);
    std::vector<ReferenceJob> jobs = {{disp, midpoint, step, {}}, {disp, p2, step, {}}};
    if (!o.quick) jobs.push_back({disp, p3, step, {}});
    compute_references(jobs, cache);
    const ReferenceResponse& fine_space = jobs.back().result;
    // IDA at a tight tolerance on the mixed paper mesh.
    const TimeSetting tight{"ida", 1e-3, o.quick ? 1e-7 : 1e-8};
    const double c0 = thread_cpu_seconds();
    const nlohmann::json ida = run_spec(response_spec(mixed, tight, w));
    const double ida_cpu = thread_cpu_seconds() - c0;
    const History ida_history = joint_history(ida);

    auto error_or_nan = [](const ReferenceResponse& a, const ReferenceResponse& b) {
        return a.status == "converged" && b.status == "converged"
                   ? history_error(a.history, b.history)
                   : kNoValue;
    };
    md << "### The references\n\nEach combination's same-mesh reference is its own fixed-step "
          "scheme (generalized-α with ρ∞ = 1, or GEBT's trapezoidal step — the same trapezoidal "
          "rule "
          "for this undamped case) at the two finest steps, extrapolated pointwise at order 2. The "
          "error measure is max over the output times (every "
       << w.output_interval * 1e3
       << " ms) of ‖Δu_joint‖ / max ‖u_joint‖ of the reference.\n\n| reference | finer vs coarser "
          "step | finer step vs extrapolation | CPU |\n|---|---|---|---|\n";
    nlohmann::json refs = nlohmann::json::object();
    for (const auto& [label, r] : same_mesh) {
        md << "| " << r.how << " | " << sci(r.step_difference) << " | "
           << sci(r.extrapolation_change) << " | "
           << (r.from_cache ? "cached (" + r.version + ")" : seconds_text(r.cpu_seconds)) << " |\n";
        refs[label] = reference_json(r);
    }
    for (const ReferenceJob& j : jobs) {
        md << "| " << j.result.how << " | " << sci(j.result.step_difference) << " | "
           << sci(j.result.extrapolation_change) << " | "
           << (j.result.from_cache ? "cached (" + j.result.version + ")"
                                   : seconds_text(j.result.cpu_seconds))
           << " |\n";
    }
    out["same_mesh"] = refs;
    const auto find = [&](const std::string& label) {
        const auto it = same_mesh.find(label);
        return it == same_mesh.end() ? ReferenceResponse{} : it->second;
    };
    const ReferenceResponse mixed_ref = find(mixed.label());
    const ReferenceResponse disp_ref = find(disp.label());
    const double cross = error_or_nan(jobs[0].result, mixed_ref);
    const double ida_vs_trap = mixed_ref.status == "converged" && ida_history.size() > 0
                                   ? history_error(ida_history, mixed_ref.history)
                                   : kNoValue;
    const double space_p1 = error_or_nan(disp_ref, fine_space);
    const double space_mixed = error_or_nan(mixed_ref, fine_space);
    const double space_p2 = o.quick ? kNoValue : error_or_nan(jobs[1].result, fine_space);
    md << "\nChecks (same error measure):\n\n"
       << "- Two formulations, one discrete model: the displacement formulation with linear "
          "elements, one-point stiffness and midpoint mass has the mixed element's frequencies "
          "(docs/displacement-modal.md); its reference against the mixed (WM) reference: "
       << sci(cross) << ".\n"
       << "- Two integrators: mixed (WM) IDA at rtol = atol = " << sci(tight.tolerance, 0) << " ("
       << ida.value("status", "") << ", " << dynamic_steps(ida) << " steps, "
       << seconds_text(ida_cpu)
       << " CPU) against the mixed trapezoidal reference: " << sci(ida_vs_trap) << ".\n"
       << "- Space error of the paper mesh (" << w.elements
       << " elements per member) against the displacement formulation with order-"
       << (o.quick ? 2 : 3) << " elements on the same mesh (" << fine_space.how
       << "): displacement order 1 " << sci(space_p1) << ", mixed " << sci(space_mixed);
    if (!o.quick) md << ", displacement order 2 " << sci(space_p2);
    md << ". No Δt or tolerance removes this part; it adds to the time errors below.\n\n";
    out["checks"] = {{"cross_formulation", cross},
                     {"ida_tight_vs_trapezoidal", ida_vs_trap},
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

nlohmann::json study_joined_beam_dynamics(const StudyOptions& o) {
    const ResponseWindow w = o.quick ? quick_window() : full_window();
    const std::string cache = out_path(o, "joined-beam-references");
    std::vector<ReferenceJob> jobs;
    for (const Combination& c : all_combinations(false)) {
        jobs.push_back({c, w, reference_coarse_step(c.formulation, o.quick), {}});
    }
    compute_references(jobs, cache);
    std::map<std::string, ReferenceResponse> same_mesh;
    std::vector<DynamicPoint> points;
    std::vector<std::string> files, titles, notes;
    for (const ReferenceJob& j : jobs) {
        if (j.result.status != "converged") {
            notes.push_back(j.combination.label() + ": " + j.result.status.substr(0, 160));
            continue;
        }
        same_mesh[j.combination.label()] = j.result;
        std::map<std::string, Series> by_integrator;
        for (const TimeSetting& s : time_settings(j.combination.formulation, o.quick)) {
            points.push_back(dynamic_point(j.combination, s, w, j.result.history));
            const DynamicPoint& p = points.back();
            Series& series = by_integrator[p.series];
            series.label = p.series;
            series.add(s.integrator == "ida" ? s.tolerance : s.time_step, p.dofs, p.cpu, p.error);
        }
        for (const auto& [label, series] : by_integrator) {
            files.push_back(write_series(
                o, "data/joined_beam_dynamic_" + std::to_string(files.size()) + ".dat", series));
            titles.push_back(label);
        }
    }
    std::ostringstream md;
    md << "## Study: joined beam, dynamic speed versus accuracy\n\nThe joined beam under the dead "
          "joint force 1e5 sin(20t) N (cases/joined-beam-dead.yaml), 0–"
       << w.end_time << " s, on the paper's mesh (" << w.elements
       << " elements per member; displacement: linear elements, consistent mass). For every "
          "combination, the fixed-step scheme at several Δt and (mixed) IDA at several tolerances; "
          "cost = thread CPU time of the whole run_case (median of up to 3 repeats for runs under "
          "1 s; the machine was shared, so CPU rather than wall time decides), time error = the "
          "joint history's distance to the combination's own same-mesh reference. The space error "
          "of the mesh is measured separately (below) and is the same for every integrator "
          "setting.\n\n";
    for (const std::string& n : notes) md << "- not run: " << n << "\n";
    if (!notes.empty()) md << "\n";
    nlohmann::json out = {{"study", "joined-beam-dynamics"},
                          {"quick", o.quick},
                          {"end_time", w.end_time},
                          {"output_interval", w.output_interval},
                          {"elements_per_member", w.elements},
                          {"not_run", notes}};
    out["references"] = reference_checks(o, w, same_mesh, md);
    out["front"] = dynamic_front(o, points, md);
    winners_in_words(points, md);
    plot("study_joined_beam_pareto.gp",
         {{"files", join_words(files)},
          {"titles", join_words(titles)},
          {"front", out_path(o, "data/joined_beam_dynamic_front.dat")},
          {"plottitle", "Joined beam 0–" + seconds_text(w.end_time) +
                            ": time error vs CPU time (every combination, Δt and IDA tolerance)"},
          {"outbase", out_path(o, "joined-beam-dynamics")}});
    md << "![joined-beam-dynamics.png](joined-beam-dynamics.png)\n\n";
    sweep_table(points, md);
    out["points"] = nlohmann::json::array();
    for (const DynamicPoint& p : points) out["points"].push_back(point_json(p));
    write_text(o, "study-joined-beam-dynamics.md", md.str());
    write_text(o, "study-joined-beam-dynamics.json", out.dump(1) + "\n");
    return out;
}

}  // namespace rotbeam::cli
