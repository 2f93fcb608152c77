// `rotbeam study joined-beam-agreement`: at converged Δt and mesh, the mixed
// formulation's 0–2 s joined-beam response (dead and follower joint force) agrees with the
// displacement formulation's. The error measure is the shared one: max over the output times of
// ‖u_mixed − u_disp‖ / max ‖u_disp‖ at the joint (history_error).
//
// Each response is time-converged: the displacement formulation's as a same-mesh reference
// (joined_beam_dynamics.hpp: generalized-α with ρ∞ = 1, the trapezoidal rule, at two steps,
// Richardson-extrapolated pointwise at order 2; its residual measured with a pair at half the
// steps), the mixed formulation's by IDA at a tight tolerance (its residual measured against a
// tenth of it, and against the mixed trapezoidal pair). Then:
// - the displacement formulation's converged response: order-4 elements (order 3 beside it: their
//   difference is its space uncertainty) on the paper's 10 elements per member;
// - the mixed formulation (WM) on 10, 20, 40 elements per member, its observed order in space from
//   the three meshes, and a Richardson extrapolation in space (order 2, its element's order: the
//   frequencies converge as h², docs/mixed-dynamics.md) from the two finest;
// - the agreement of each with the displacement response, which must fall at that order towards
//   the references' own uncertainties.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <thread>

#include "core/results.hpp"
#include "core/version.hpp"
#include "joined_beam_dynamics.hpp"
#include "runs/parallel.hpp"
#include "studies.hpp"
#include "study_plot.hpp"

namespace rotbeam::cli {

namespace {

// What the study runs: the window, the mixed meshes, the time integration of each response.
// The mixed responses are IDA at a tight tolerance: the trapezoidal rule does not reach its
// asymptotic order 2 on this response at affordable steps (the higher modes the joint force's
// start excites keep phase errors ω³Δt²t/12 of order one; measured: successive differences fall
// by 2.3–3, not 4, and the Richardson extrapolations of successive pairs differ by more than their
// corrections), while IDA at 1e-7 and 1e-8 agree to ~1e-5 (docs/studies.md).
struct AgreementPlan {
    ResponseWindow window;
    std::vector<std::string> cases;
    std::vector<int> meshes;         // mixed elements per member, coarse → fine (ratio 2)
    int displacement_elements = 10;  // the order-3/4 displacement meshes
    double ida_tolerance = 0.0;      // rtol = atol of the mixed responses
    double mixed_step = 0.0;  // coarser step of the mixed trapezoidal pair (paper mesh check)
    double displacement_step = 0.0;  // coarser step of the displacement pairs
};

AgreementPlan agreement_plan(bool quick) {
    AgreementPlan p;
    p.window = quick ? quick_window() : full_window();
    p.meshes = {10, 20, 40};
    p.ida_tolerance = 1e-7;
    if (quick) {
        // 0–0.2 s, dead and follower load: the orders in about a CPU-minute per load (the
        // study's test), down to 80 elements per member, where the extrapolation in space meets
        // the references' own time errors. The follower case is the one that softens under load
        // (seed 002 Fig. 7): its first excursion, the largest, falls in this window.
        p.cases = {"joined-beam-dead", "joined-beam-follower"};
        p.meshes = {10, 20, 40, 80};
        p.mixed_step = 2.5e-4;
        p.displacement_step = 1.25e-4;
    } else {
        p.cases = {"joined-beam-dead", "joined-beam-follower"};
        p.mixed_step = 1.25e-4;
        p.displacement_step = 6.25e-5;
    }
    return p;
}

const Combination kMixed{Formulation::mixed, param::id_of<param::WienerMilenkovic>()};
const Combination kDisplacement{Formulation::displacement, param::id_of<param::Quaternion>()};

struct Job {
    std::string name;  // key of the result
    Combination combination;
    ResponseWindow window;
    double coarse_step;        // the fixed-step pair's coarser step (when ida_tolerance is 0)
    double ida_tolerance = 0;  // > 0: one IDA run at rtol = atol = this instead of the pair
    ReferenceResponse result = {};
};

std::string number_text(double x) {
    std::ostringstream s;
    s.precision(6);
    s << x;
    return s.str();
}

// One IDA run of the mixed formulation at a tight tolerance as a time-converged response, cached
// under `cache_dir` like richardson_reference's (keyed by every setting that changes it).
ReferenceResponse ida_response(const Combination& c, const ResponseWindow& w, double tolerance,
                               const std::string& cache_dir) {
    const nlohmann::json key = {
        {"case", w.case_name},           {"formulation", c.formulation_name()},
        {"rotation", c.rotation_name()}, {"elements", w.elements},
        {"end_time", w.end_time},        {"output_interval", w.output_interval},
        {"integrator", "ida"},           {"tolerance", tolerance}};
    const std::string file = cache_dir + "/ida_" + c.formulation_name() + "_" + c.rotation_name() +
                             "_" + w.case_name + "_n" + std::to_string(w.elements) + "_T" +
                             number_text(w.end_time) + "_tol" + number_text(tolerance) + ".json";
    ReferenceResponse r;
    if (std::filesystem::exists(file)) {
        std::ifstream in(file);
        const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
        if (!j.is_discarded() && j.value("key", nlohmann::json()) == key) {
            r.history.time = j["time"].get<std::vector<double>>();
            r.history.x = j["x"].get<std::vector<double>>();
            r.history.y = j["y"].get<std::vector<double>>();
            r.history.z = j["z"].get<std::vector<double>>();
            r.how = j.value("how", "");
            r.cpu_seconds = j.value("cpu_seconds", 0.0);
            r.version = j.value("version", "");
            r.status = j.value("status", "");
            r.from_cache = true;
            return r;
        }
    }
    const TimeSetting s{Integrator::ida, 1e-3, tolerance};
    const double c0 = thread_cpu_seconds();
    const nlohmann::json run = run_spec(response_spec(c, s, w));
    r.cpu_seconds = thread_cpu_seconds() - c0;
    r.version = kGitDescribe;
    r.history = joint_history(run);
    r.status = r.history.size() > 0
                   ? "converged"
                   : run.value("status", "error") + ": " + run.value("message", "").substr(0, 120);
    r.step_difference = r.extrapolation_change = kNoValue;
    r.how = c.label() + ", " + std::to_string(w.elements) +
            " elements per member, IDA (BDF ≤ 2) at rtol = atol = " + sci(tolerance, 0) + " (" +
            std::to_string(dynamic_steps(run)) + " steps)";
    if (r.status == "converged") {
        std::filesystem::create_directories(cache_dir);
        const nlohmann::json j = {{"key", key},
                                  {"how", r.how},
                                  {"cpu_seconds", r.cpu_seconds},
                                  {"version", r.version},
                                  {"schema_version", kSchemaVersion},
                                  {"status", r.status},
                                  {"time", r.history.time},
                                  {"x", r.history.x},
                                  {"y", r.history.y},
                                  {"z", r.history.z}};
        write_file_atomically(file, j.dump() + "\n");
    }
    return r;
}

// The references of `jobs` on two threads, in the order of the list (each run is single-threaded).
void compute(std::vector<Job>& jobs, const std::string& cache_dir) {
    for_each_parallel(jobs.size(), 2, [&](size_t i) {
        const Job& j = jobs[i];
        jobs[i].result =
            j.ida_tolerance > 0.0
                ? ida_response(j.combination, j.window, j.ida_tolerance, cache_dir)
                : richardson_reference(j.combination, j.window, j.coarse_step, cache_dir);
    });
}

ResponseWindow window_of(const AgreementPlan& p, const std::string& case_name, int elements,
                         int order) {
    ResponseWindow w = p.window;
    w.case_name = case_name;
    w.elements = elements;
    w.order = order;
    return w;
}

std::string mixed_key(const std::string& case_name, int n) {
    return case_name + "/mixed/" + std::to_string(n);
}
std::string displacement_key(const std::string& case_name, int order) {
    return case_name + "/displacement/p" + std::to_string(order);
}

// The job list, most informative first: the dead load's displacement reference and mixed meshes,
// then the follower's, then the time checks on the paper mesh (IDA at a tenth of the tolerance,
// the mixed trapezoidal pair, the displacement pair at half the steps).
std::vector<Job> plan_jobs(const AgreementPlan& p) {
    std::vector<Job> jobs;
    for (const std::string& c : p.cases) {
        for (int order : {4, 3}) {
            jobs.push_back({displacement_key(c, order), kDisplacement,
                            window_of(p, c, p.displacement_elements, order), p.displacement_step});
        }
        for (int n : p.meshes) {
            jobs.push_back({mixed_key(c, n), kMixed, window_of(p, c, n, 1), 0.0, p.ida_tolerance});
        }
    }
    const std::string& first = p.cases.front();
    const ResponseWindow paper = window_of(p, first, p.meshes.front(), 1);
    jobs.push_back({mixed_key(first, p.meshes.front()) + "/tighter", kMixed, paper, 0.0,
                    p.ida_tolerance / 10.0});
    jobs.push_back(
        {mixed_key(first, p.meshes.front()) + "/trapezoidal", kMixed, paper, p.mixed_step});
    jobs.push_back({displacement_key(first, 3) + "/half-step", kDisplacement,
                    window_of(p, first, p.displacement_elements, 3), p.displacement_step / 2.0});
    return jobs;
}

// ‖u(t) − u_ref(t)‖ / max ‖u_ref‖ at every output time (the integrand of history_error).
std::vector<double> pointwise_error(const History& u, const History& ref) {
    double scale = 0.0;
    for (size_t i = 0; i < ref.size(); ++i)
        scale = std::max(scale, std::hypot(ref.x[i], ref.y[i], ref.z[i]));
    std::vector<double> e;
    for (size_t i = 0; i < u.size() && i < ref.size(); ++i)
        e.push_back(std::hypot(u.x[i] - ref.x[i], u.y[i] - ref.y[i], u.z[i] - ref.z[i]) / scale);
    return e;
}

std::string cpu_text(const ReferenceResponse& r) {
    if (r.from_cache) return "cached (" + sci(r.cpu_seconds, 3) + " s when computed)";
    return sci(r.cpu_seconds, 3) + " s";
}

double error_between(const ReferenceResponse& a, const ReferenceResponse& b) {
    return a.status == "converged" && b.status == "converged" ? history_error(a.history, b.history)
                                                              : kNoValue;
}

nlohmann::json reference_entry(const Job& j) {
    auto num = [](double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(); };
    return {{"how", j.result.how},
            {"status", j.result.status},
            {"step_difference", num(j.result.step_difference)},
            {"extrapolation_change", num(j.result.extrapolation_change)},
            {"cpu_seconds", j.result.cpu_seconds},
            {"from_cache", j.result.from_cache},
            {"version", j.result.version}};
}

}  // namespace

namespace {

struct CaseFigures {
    PanelFigure agreement, pointwise;
};

// One load case: the table, the histories, the figures' data; returns the case's JSON.
nlohmann::json agreement_case(const StudyOptions& o, const AgreementPlan& p,
                              const std::string& case_name,
                              const std::map<std::string, const Job*>& done, CaseFigures& figures,
                              std::ostringstream& md) {
    auto get = [&](const std::string& key) -> const ReferenceResponse& {
        static const ReferenceResponse missing{};
        const auto it = done.find(key);
        return it == done.end() ? missing : it->second->result;
    };
    auto num = [](double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(); };
    const ReferenceResponse& p4 = get(displacement_key(case_name, 4));
    const ReferenceResponse& p3 = get(displacement_key(case_name, 3));
    nlohmann::json out = {{"case", case_name}};
    md << "### " << case_name << "\n\nConverged displacement response: " << p4.how << " ("
       << p4.status << "). Order 3 on the same mesh against it (its space uncertainty): **"
       << sci(error_between(p3, p4)) << "**.\n\n";
    out["displacement_p3_vs_p4"] = num(error_between(p3, p4));
    out["displacement_time_residual_p4"] = num(p4.extrapolation_change);

    std::vector<History> mixed;
    std::vector<double> agreement, elements, self_difference;
    md << "| mixed (WM), elements per member | agreement with displacement p = 4 | order | vs the "
          "next finer mesh | its order | CPU |\n"
          "|---|---|---|---|---|---|\n";
    for (size_t k = 0; k < p.meshes.size(); ++k) {
        const ReferenceResponse& r = get(mixed_key(case_name, p.meshes[k]));
        mixed.push_back(r.status == "converged" ? r.history : History{});
        agreement.push_back(error_between(r, p4));
        elements.push_back(p.meshes[k]);
    }
    for (size_t k = 0; k + 1 < p.meshes.size(); ++k)
        self_difference.push_back(error_between(get(mixed_key(case_name, p.meshes[k])),
                                                get(mixed_key(case_name, p.meshes[k + 1]))));
    std::vector<double> orders(p.meshes.size(), kNoValue), self_orders(p.meshes.size(), kNoValue);
    for (size_t k = 1; k < p.meshes.size(); ++k)
        orders[k] = std::log2(agreement[k - 1] / agreement[k]);
    for (size_t k = 1; k < self_difference.size(); ++k)
        self_orders[k] = std::log2(self_difference[k - 1] / self_difference[k]);
    for (size_t k = 0; k < p.meshes.size(); ++k) {
        const ReferenceResponse& r = get(mixed_key(case_name, p.meshes[k]));
        md << "| " << p.meshes[k]
           << (r.status == "converged" ? "" : " (" + markdown_cell(r.status) + ")") << " | "
           << sci(agreement[k], 3) << " | " << (k > 0 ? sci(orders[k], 3) : "") << " | "
           << (k < self_difference.size() ? sci(self_difference[k], 3) : "") << " | "
           << (k < self_difference.size() && k > 0 ? sci(self_orders[k], 3) : "") << " | "
           << cpu_text(r) << " |\n";
    }
    // Richardson in space from every pair of successive meshes (ratio 2, order 2); the finest
    // pair's is the study's answer.
    const size_t m = p.meshes.size();
    std::vector<double> extrapolated(m, kNoValue);
    History extrapolated_history;
    for (size_t k = 1; k < m; ++k) {
        if (mixed[k - 1].size() == 0 || mixed[k].size() != mixed[k - 1].size()) continue;
        const History e = extrapolate_history(mixed[k - 1], mixed[k], 2.0, 2.0);
        if (p4.status == "converged") extrapolated[k] = history_error(e, p4.history);
        if (k + 1 == m) extrapolated_history = e;
        md << "| Richardson in space (" << p.meshes[k - 1] << ", " << p.meshes[k] << "; order 2) | "
           << (k + 1 == m ? "**" : "") << sci(extrapolated[k], 3) << (k + 1 == m ? "**" : "")
           << " | " << (k > 1 ? sci(std::log2(extrapolated[k - 1] / extrapolated[k]), 3) : "")
           << " | | | |\n";
    }
    md << "\nObserved orders: of the agreement with the displacement response";
    for (size_t k = 1; k < m; ++k) md << (k > 1 ? ", " : " ") << sci(orders[k], 3);
    md << "; of the mixed meshes among themselves (successive differences)";
    for (size_t k = 1; k + 1 < m; ++k) md << (k > 1 ? ", " : " ") << sci(self_orders[k], 3);
    md << ".\n\n";

    out["elements_per_member"] = elements;
    out["agreement"] = nlohmann::json::array();
    for (double a : agreement) out["agreement"].push_back(num(a));
    out["agreement_orders"] = nlohmann::json::array();
    for (double q : orders) out["agreement_orders"].push_back(num(q));
    out["mesh_differences"] = nlohmann::json::array();
    for (double d : self_difference) out["mesh_differences"].push_back(num(d));
    out["mesh_orders"] = nlohmann::json::array();
    for (size_t k = 1; k + 1 < m; ++k) out["mesh_orders"].push_back(num(self_orders[k]));
    // [k]: extrapolated from meshes k−1 and k (null at 0).
    out["extrapolated_agreements"] = nlohmann::json::array();
    for (double e : extrapolated) out["extrapolated_agreements"].push_back(num(e));
    out["extrapolated_agreement"] = num(extrapolated[m - 1]);

    // Data: the joint histories (CSV), |Δu|(t) per mixed mesh, agreement vs elements.
    std::ostringstream csv;
    csv.precision(10);
    std::vector<std::pair<std::string, const History*>> columns = {
        {"displacement_p4", &p4.history}, {"displacement_p3", &p3.history}};
    for (size_t k = 0; k < m; ++k)
        columns.push_back({"mixed_" + std::to_string(p.meshes[k]), &mixed[k]});
    columns.push_back({"mixed_extrapolated", &extrapolated_history});
    csv << "time";
    for (const auto& [label, h] : columns)
        csv << "," << label << "_x," << label << "_y," << label << "_z";
    csv << "\n";
    for (size_t i = 0; i < p4.history.size(); ++i) {
        csv << p4.history.time[i];
        for (const auto& [label, h] : columns) {
            if (i < h->size()) {
                csv << "," << h->x[i] << "," << h->y[i] << "," << h->z[i];
            } else {
                csv << ",,,";
            }
        }
        csv << "\n";
    }
    write_text(o, "data/agreement_" + case_name + "_joint.csv", csv.str());
    const std::string panel = case_name;
    for (size_t k = 0; k < columns.size(); ++k) {
        if (k == 0 || columns[k].second->size() == 0 || p4.history.size() == 0) continue;
        const std::vector<double> e = pointwise_error(*columns[k].second, p4.history);
        // At most ~250 points per curve: the largest value of each block of output times (the
        // envelope the maximum over t is taken from), at the block's last time.
        const size_t block = std::max<size_t>(1, (e.size() + 249) / 250);
        std::ostringstream d;
        d.precision(8);
        d << "# t  |u - u_displacement_p4| / max |u_displacement_p4| (largest of every " << block
          << " output times): " << columns[k].first << "\n";
        for (size_t i = 0; i < e.size(); i += block) {
            const size_t end = std::min(e.size(), i + block);
            const double largest = *std::max_element(e.begin() + static_cast<long>(i),
                                                     e.begin() + static_cast<long>(end));
            if (largest > 0.0) d << p4.history.time[end - 1] << " " << largest << "\n";
        }
        const std::string file = "data/agreement_" + case_name + "_du_" + columns[k].first + ".dat";
        write_text(o, file, d.str());
        figures.pointwise.add(panel, out_path(o, file), columns[k].first);
    }
    Series s;
    s.label = "mixed_vs_displacement_p4";
    for (size_t k = 0; k < m; ++k)
        s.add(p.meshes[k], 0, get(mixed_key(case_name, p.meshes[k])).cpu_seconds, agreement[k]);
    figures.agreement.add(
        panel, write_series(o, "data/agreement_" + case_name + "_vs_elements.dat", s), s.label);
    Series d;
    d.label = "mixed_vs_next_finer_mesh";
    for (size_t k = 0; k + 1 < m; ++k) d.add(p.meshes[k], 0, 0.0, self_difference[k]);
    figures.agreement.add(
        panel, write_series(o, "data/agreement_" + case_name + "_mesh_differences.dat", d),
        d.label);
    return out;
}

}  // namespace

nlohmann::json study_joined_beam_agreement(const StudyOptions& o) {
    const AgreementPlan p = agreement_plan(o.quick);
    const std::string cache = out_path(o, "joined-beam-references");
    std::vector<Job> jobs = plan_jobs(p);
    compute(jobs, cache);
    std::map<std::string, const Job*> done;
    for (const Job& j : jobs) done[j.name] = &j;

    std::ostringstream md;
    md << "## Study: joined beam, agreement of the formulations at converged Δt and mesh\n\n"
          "The joined beam (docs/benchmarks.md §3) under the joint force 1e5 sin(20t) N, 0–"
       << p.window.end_time << " s, outputs every " << p.window.output_interval * 1e3
       << " ms. Every response is Richardson-extrapolated in time (order 2) from its trapezoidal "
          "fixed step (generalized-α with ρ∞ = 1 for the displacement formulation) at Δt = "
       << p.displacement_step * 1e6 << "/" << p.displacement_step * 5e5 << " µs (displacement) and "
       << p.mixed_step * 1e6 << "/" << p.mixed_step * 5e5
       << " µs (mixed). Agreement = max over t of ‖u_mixed − u_disp‖ / max ‖u_disp‖ at the joint, "
          "against the displacement formulation with order-4 elements on "
       << p.displacement_elements << " elements per member.\n\n";
    nlohmann::json out = {
        {"study", "joined-beam-agreement"},        {"quick", o.quick},
        {"end_time", p.window.end_time},           {"output_interval", p.window.output_interval},
        {"mixed_ida_tolerance", p.ida_tolerance},  {"mixed_trapezoidal_step", p.mixed_step},
        {"displacement_step", p.displacement_step}};
    CaseFigures figures;
    out["cases"] = nlohmann::json::array();
    for (const std::string& c : p.cases)
        out["cases"].push_back(agreement_case(o, p, c, done, figures, md));

    // The time checks on the paper mesh (first case).
    const std::string& first = p.cases.front();
    const std::string m10 = mixed_key(first, p.meshes.front());
    const double ida_self = error_between(done[m10]->result, done[m10 + "/tighter"]->result);
    const double ida_vs_trapezoidal =
        error_between(done[m10 + "/tighter"]->result, done[m10 + "/trapezoidal"]->result);
    const ReferenceResponse& d3 = done[displacement_key(first, 3)]->result;
    const ReferenceResponse& d3h = done[displacement_key(first, 3) + "/half-step"]->result;
    const double disp_time = error_between(d3, d3h);
    md << "### Time error of the responses (" << first << ", paper mesh)\n\n"
       << "- mixed, " << p.meshes.front() << " elements per member, IDA at "
       << sci(p.ida_tolerance, 0) << " against " << sci(p.ida_tolerance / 10.0, 0) << ": **"
       << sci(ida_self, 3) << "** (CPU " << cpu_text(done[m10]->result) << " and "
       << cpu_text(done[m10 + "/tighter"]->result) << ").\n"
       << "- the other integrator's limit: IDA at " << sci(p.ida_tolerance / 10.0, 0)
       << " against the mixed trapezoidal rule at " << p.mixed_step * 1e6 << "/"
       << p.mixed_step * 5e5 << " µs, Richardson-extrapolated: **" << sci(ida_vs_trapezoidal, 3)
       << "** (the pair's finer step against its extrapolation: "
       << sci(done[m10 + "/trapezoidal"]->result.extrapolation_change) << ").\n"
       << "- displacement p = 3: extrapolated from " << p.displacement_step * 1e6 << "/"
       << p.displacement_step * 5e5 << " µs against " << p.displacement_step * 5e5 << "/"
       << p.displacement_step * 2.5e5 << " µs: **" << sci(disp_time, 3) << "** (" << cpu_text(d3h)
       << ").\n\n";
    out["time_checks"] = {{"mixed_ida_vs_tighter", ida_self},
                          {"mixed_ida_tighter_vs_trapezoidal", ida_vs_trapezoidal},
                          {"displacement_p3_pair_vs_half_pair", disp_time}};
    for (auto& [k, v] : out["time_checks"].items())
        if (v.is_number() && !std::isfinite(v.get<double>())) v = nullptr;
    out["references"] = nlohmann::json::object();
    md << "### References\n\n| reference | finer vs coarser step | finer step vs extrapolation | "
          "CPU |\n|---|---|---|---|\n";
    for (const Job& j : jobs) {
        out["references"][j.name] = reference_entry(j);
        md << "| "
           << (j.result.how.empty() ? j.name + ": " + markdown_cell(j.result.status) : j.result.how)
           << " | " << sci(j.result.step_difference) << " | " << sci(j.result.extrapolation_change)
           << " | " << cpu_text(j.result) << " |\n";
    }
    md << "\n";

    const std::string window = "0–" + number_text(p.window.end_time) + " s";
    std::vector<std::pair<std::string, std::string>> reference_line;
    if (std::isfinite(disp_time)) {
        reference_line = {{"hline", sci(disp_time, 6)},
                          {"hlabel", "time error of the displacement reference"}};
    }
    std::vector<std::pair<std::string, std::string>> agreement_vars = {
        {"xcol", "1"},
        {"ycol", "4"},
        {"xlabel", "mixed elements per member [-]"},
        {"ylabel", "max_t |Δu| / max |u| [-]"},
        {"plottitle", "Joined beam " + window + ": mixed against displacement p = 4"},
        {"outbase", out_path(o, "joined-beam-agreement")},
        {"logx", "1"},
        {"logy", "1"},
        {"slopes", sci(static_cast<double>(p.meshes.front()), 6) + " " +
                       sci(out["cases"][0]["agreement"][0].is_number()
                               ? out["cases"][0]["agreement"][0].get<double>()
                               : 1.0,
                           6)}};
    agreement_vars.insert(agreement_vars.end(), reference_line.begin(), reference_line.end());
    plot_panels(o, figures.agreement, agreement_vars);
    plot_panels(o, figures.pointwise,
                {{"xcol", "1"},
                 {"ycol", "2"},
                 {"xlabel", "t [s]"},
                 {"ylabel", "|Δu(t)| / max |u| [-]"},
                 {"plottitle", "Joined beam " + window + ": distance to displacement p = 4"},
                 {"outbase", out_path(o, "joined-beam-agreement-history")},
                 {"logx", "0"},
                 {"logy", "1"}});
    md << "![joined-beam-agreement.png](joined-beam-agreement.png)\n\n"
          "![joined-beam-agreement-history.png](joined-beam-agreement-history.png)\n\n";
    write_text(o, "study-joined-beam-agreement.md", md.str());
    out["schema_version"] = kSchemaVersion;
    write_text(o, "study-joined-beam-agreement.json", out.dump(1) + "\n");
    return out;
}

}  // namespace rotbeam::cli
