// `rotbeam study manufactured-time` (the manufactured solutions
// in time): observed orders in time of every integrator and in space at a small step, against the
// manufactured motion (core/oracles/manufactured_motion.hpp; runs in manufactured_motion_runs.hpp).
//  - Time, fixed steps: for each combination a sequence of steps Δt; the time error of a run is its
//    difference to the run at Δt/2 on the same mesh (the space error cancels), the error against
//    the exact motion is listed too (it reaches the space error at small Δt). Observed order: the
//    least-squares slope and the last pair.
//  - IDA: the difference to IDA at a tight tolerance, against the tolerance.
//  - Space: h-refinement at a small step (time error below the space error), error against the
//    exact motion.
// Writes study-manufactured-time.{md,json}, data/manufactured_*.dat and the figures.
#include <cmath>
#include <sstream>

#include "core/results.hpp"
#include "manufactured_motion_runs.hpp"
#include "manufactured_semi_discrete.hpp"
#include "studies.hpp"
#include "study_common.hpp"
#include "study_math.hpp"

namespace rotbeam::cli {

namespace {

constexpr double kStudyNewtonTolerance = 1e-12;

struct TimeSeries {
    MotionRunSpec spec;
    std::vector<double> steps;  // Δt
};

// --quick (the suite's form): the quaternion for the displacement formulation and plain
// Wiener–Milenković for the mixed one, as the free-vibration study's quick form; the full study
// lists every combination. Every combination's temporal order is asserted by the tests
// (test_manufactured_motion, test_free_vibration_orders); the quick form checks the study's path.
bool in_quick_form(Formulation formulation, ParameterizationId rotation, WmMap map) {
    return formulation == Formulation::displacement
               ? rotation == param::id_of<param::Quaternion>()
               : rotation == param::id_of<param::WienerMilenkovic>() && map == WmMap::plain;
}

std::vector<TimeSeries> time_series(bool quick) {
    const std::vector<double> dd =
        quick ? std::vector<double>{0.025, 0.0125, 0.00625}
              : std::vector<double>{0.05, 0.025, 0.0125, 0.00625, 0.003125};
    // Mixed: down to the floor the start leaves in the non-dissipative scheme (the study's
    // description below); at Δt = 0.00625 the rotation differences reach it (order 1.2).
    const std::vector<double> dm =
        quick ? std::vector<double>{0.05, 0.025} : std::vector<double>{0.1, 0.05, 0.025, 0.0125};
    std::vector<TimeSeries> out;
    for (const ParameterizationId r : param::parameterization_ids()) {
        if (quick && !in_quick_form(Formulation::displacement, r, WmMap::plain)) continue;
        for (double rho : {0.5, 1.0}) {
            MotionRunSpec s;
            s.rotation = r;
            s.order = 3;
            s.elements = 2;
            s.rho_infinity = rho;
            s.motion = motion_within_reach(Formulation::displacement, r);
            out.push_back({s, dd});
        }
    }
    // Gauss–Legendre collocation (orders 4 and 6): larger steps. Below Δt ≈ 0.025 the differences
    // reach a floor of ~1.5e-6 (the exact start excites the mesh's high modes at the space-error
    // level and Gauss damps none of them; docs/displacement-dynamics.md), which the 3-stage
    // scheme's differences reach from Δt = 0.1 on.
    const std::vector<double> dg =
        quick ? std::vector<double>{0.1, 0.05} : std::vector<double>{0.2, 0.1, 0.05, 0.025};
    for (const ParameterizationId r : param::parameterization_ids()) {
        if (quick && !in_quick_form(Formulation::displacement, r, WmMap::plain)) continue;
        for (Integrator g : {Integrator::gauss_legendre_2, Integrator::gauss_legendre_3}) {
            MotionRunSpec s;
            s.rotation = r;
            s.integrator = g;
            s.order = 3;
            s.elements = 2;
            s.motion = motion_within_reach(Formulation::displacement, r);
            out.push_back({s, dg});
        }
    }
    // Radau IIA (order 5): L-stable, it damps the modes the exact start excites, so no floor of
    // the trapezoidal kind; steps as Gauss's.
    const std::vector<double> dr =
        quick ? std::vector<double>{0.1, 0.05} : std::vector<double>{0.1, 0.05, 0.025, 0.0125};
    for (Integrator scheme : {Integrator::trapezoidal, Integrator::radau_iia_3}) {
        for (const comb::Combination& c : comb::all_combinations(false, true)) {
            if (c.formulation != Formulation::mixed) continue;
            if (quick && !in_quick_form(c.formulation, c.rotation, c.wm_map.value_or(WmMap::plain)))
                continue;
            MotionRunSpec s;
            s.formulation = c.formulation;
            s.rotation = c.rotation;
            s.wm_map = c.wm_map.value_or(WmMap::plain);
            s.integrator = scheme;
            s.elements = 8;
            s.motion = motion_within_reach(c.formulation, c.rotation);
            out.push_back({s, scheme == Integrator::trapezoidal ? dm : dr});
        }
    }
    // Newton (stage iteration) tolerance 1e-12 of every unknown's scale: a 6th-order difference
    // of 1e-10 stays 100× above it.
    for (TimeSeries& t : out) t.spec.newton_tolerance = kStudyNewtonTolerance;
    return out;
}

std::string file_label(std::string s) {
    for (char& c : s) {
        if (c == '/' || c == '.') c = '_';
    }
    return s;
}

// The components of the study's tables: the first four of ComponentDifferences' table order (u,
// R, v, F; the velocity's halves are the test's, tests/agreement/test_semi_discrete_motion.cpp).
constexpr int kTimeComponents = 4;

// "q₁ / q₂ / …" over the components a formulation has (the displacement one has no forces).
std::string order_cell(const std::vector<double>& q, int count) {
    std::string cell;
    for (int k = 0; k < count; ++k) cell += (k > 0 ? " / " : "") + fixed(q[static_cast<size_t>(k)]);
    return cell;
}

// One combination: runs at Δt_i and Δt_i/2, rows "Δt steps wall e_u e_R d_u d_R d_v d_F", the
// table row.
nlohmann::json time_case(const StudyOptions& o, const TimeSeries& t, std::ostringstream& md,
                         std::vector<std::string>& files, std::vector<std::string>& titles) {
    const std::string label = t.spec.label();
    const int components = t.spec.formulation == Formulation::mixed ? 4 : 3;
    std::vector<double> dts;
    std::vector<std::vector<double>> diff(kTimeComponents);
    std::ostringstream data;
    data << "# dt steps wall_s error_u error_R difference_u difference_R difference_velocity "
            "difference_forces ("
         << label << ")\n";
    MotionRunSpec spec = t.spec;
    std::string note;
    double eu_last = kNoValue, eR_last = kNoValue;
    for (double dt : t.steps) {
        spec.dt = dt;
        const MotionRunResult a = run_manufactured_motion(spec);
        spec.dt = dt / 2;
        const MotionRunResult b = a.ok() ? run_manufactured_motion(spec) : a;
        if (a.status == "unavailable") {
            note = a.message;
            break;
        }
        if (!a.ok() || !b.ok()) {  // noted; the smaller steps may still run
            const MotionRunResult& f = a.ok() ? b : a;
            note += "Δt " + sci(f.ok() ? dt / 2 : dt, 2) + " " + f.status + ": " +
                    f.message.substr(0, 60) + "; ";
            continue;
        }
        const ComponentDifferences d = component_differences(a, b, spec.motion.length);
        dts.push_back(dt);
        for (int k = 0; k < kTimeComponents; ++k) {
            diff[static_cast<size_t>(k)].push_back(component(d, k));
        }
        eu_last = b.error_u;
        eR_last = b.error_R;
        // "?" (gnuplot's missing value) for the forces the displacement formulation has not.
        data << dt << " " << a.steps << " " << a.wall_seconds << " " << a.error_u << " "
             << a.error_R << " " << d.u << " " << d.R << " " << d.velocity << " "
             << (components == 4 ? sci(d.forces, 6) : std::string("?")) << "\n";
    }
    // fit_order takes mesh sizes n (error ∝ n^−q); a step size is 1/n.
    std::vector<double> inv;
    for (double dt : dts) inv.push_back(1.0 / dt);
    std::vector<double> q, tail;
    for (const std::vector<double>& e : diff) {
        q.push_back(fit_order(inv, e));
        tail.push_back(tail_order(inv, e, 2));
    }
    md << "| " << label << " | "
       << (dts.empty() ? "—" : sci(dts.front(), 3) + " … " + sci(dts.back(), 3)) << " | ";
    for (int k = 0; k < 4; ++k) {
        const std::vector<double>& e = diff[static_cast<size_t>(k)];
        md << (e.empty() || k >= components ? "—" : sci(e.front()) + " → " + sci(e.back()))
           << " | ";
    }
    md << order_cell(q, components) << " | " << order_cell(tail, components) << " | "
       << sci(eu_last) << " / " << sci(eR_last) << " | " << markdown_cell(note) << " |\n";
    if (!dts.empty()) {
        const std::string f = "data/manufactured_time_" + file_label(label) + ".dat";
        write_text(o, f, data.str());
        files.push_back(out_path(o, f));
        titles.push_back(label);
    }
    nlohmann::json j = {
        {"label", label}, {"dt", dts}, {"newton_tolerance", spec.newton_tolerance}, {"note", note}};
    const char* const keys[kTimeComponents] = {"u", "R", "velocity", "forces"};
    for (int k = 0; k < components; ++k) {
        const size_t i = static_cast<size_t>(k);
        j[std::string("difference_") + keys[k]] = diff[i];
        j[std::string("order_") + keys[k]] = q[i];
        j[std::string("order_") + keys[k] + "_last"] = tail[i];
    }
    return j;
}

nlohmann::json ida_case(const StudyOptions& o, ParameterizationId rotation,
                        std::ostringstream& md) {
    MotionRunSpec spec;
    spec.formulation = Formulation::mixed;
    spec.rotation = rotation;
    spec.integrator = Integrator::ida;
    spec.elements = 8;
    spec.dt = 0.05;
    spec.motion = motion_within_reach(Formulation::mixed, spec.rotation);
    spec.tolerance = o.quick ? 1e-6 : 1e-7;
    const MotionRunResult ref = run_manufactured_motion(spec);
    nlohmann::json out = {{"reference_tolerance", spec.tolerance},
                          {"rows", nlohmann::json::array()}};
    md << "\n**IDA** (BDF, order ≤ 2, mixed " << param::name_of(rotation)
       << ", 8 elements per member): difference to IDA at "
          "rtol = atol = "
       << sci(spec.tolerance, 0) << " against the tolerance.\n\n"
       << "| rtol = atol | steps | wall [s] | ‖Δu‖/L | rotation [rad] | vs exact ‖Δu‖/L |\n"
          "|---|---|---|---|---|---|\n";
    for (double tol : {1e-2, 1e-3, 1e-4, 1e-5}) {
        spec.tolerance = tol;
        const MotionRunResult r = run_manufactured_motion(spec);
        double du = kNoValue, dR = kNoValue;
        if (r.ok() && ref.ok()) run_difference(r, ref, spec.motion.length, du, dR);
        md << "| " << sci(tol, 0) << " | " << r.steps << " | " << fixed(r.wall_seconds, 3) << " | "
           << sci(du) << " | " << sci(dR) << " | " << sci(r.error_u) << " |\n";
        out["rows"].push_back({{"tolerance", tol},
                               {"steps", r.steps},
                               {"difference_u", du},
                               {"difference_R", dR},
                               {"status", r.status}});
    }
    return out;
}

nlohmann::json space_case(const StudyOptions& o, std::ostringstream& md,
                          std::vector<std::string>& files, std::vector<std::string>& titles) {
    nlohmann::json out = nlohmann::json::array();
    struct Refinement {
        Formulation formulation;
        ParameterizationId rotation;
        int order;
        std::vector<int> elements;
        double dt;
    };
    // Steps whose time error (the time table: ≈ 4 (Δt/0.00625)² × its last entry) stays ≤ 1/10
    // of the finest space error: the p = 2 nodal errors fall like h⁴ and need the smallest.
    const std::vector<Refinement> list = {
        {Formulation::displacement, param::id_of<param::Quaternion>(), 1,
         o.quick ? std::vector<int>{2, 4, 8} : std::vector<int>{2, 4, 8, 16}, 0.0025},
        {Formulation::displacement, param::id_of<param::Quaternion>(), 2,
         o.quick ? std::vector<int>{1, 2, 4} : std::vector<int>{1, 2, 4, 8}, 0.0005},
        {Formulation::mixed, param::id_of<param::WienerMilenkovic>(), 1,
         o.quick ? std::vector<int>{2, 4, 8} : std::vector<int>{2, 4, 8, 16}, 0.00125},
        {Formulation::mixed, param::id_of<param::Quaternion>(), 1,
         o.quick ? std::vector<int>{2, 4, 8} : std::vector<int>{2, 4, 8, 16}, 0.00125}};
    md << "\n**Space** (quaternion / WM and quaternion trapezoidal, Δt fixed; error against the "
          "exact motion):\n\n"
          "| combination | Δt | elements per member | ‖Δu‖/L | rotation [rad] | order (last "
          "pair) u / R |\n|---|---|---|---|---|---|\n";
    for (const Refinement& r : list) {
        MotionRunSpec spec;
        spec.formulation = r.formulation;
        spec.rotation = r.rotation;
        spec.integrator = Integrator::trapezoidal;
        spec.order = r.order;
        spec.dt = r.dt;
        spec.motion = motion_within_reach(spec.formulation, spec.rotation);
        std::vector<double> n, eu, eR;
        std::ostringstream data;
        data << "# elements_per_member dofs error_u error_R\n";
        for (int e : r.elements) {
            spec.elements = e;
            const MotionRunResult res = run_manufactured_motion(spec);
            if (!res.ok()) break;
            n.push_back(e);
            eu.push_back(res.error_u);
            eR.push_back(res.error_R);
            data << e << " " << res.dofs << " " << res.error_u << " " << res.error_R << "\n";
        }
        const std::string label = spec.label();
        const double qu = tail_order(n, eu, 2), qR = tail_order(n, eR, 2);
        md << "| " << label << " | " << r.dt << " | "
           << (n.empty() ? "—"
                         : std::to_string(static_cast<int>(n.front())) + " … " +
                               std::to_string(static_cast<int>(n.back())))
           << " | " << (eu.empty() ? "—" : sci(eu.front()) + " → " + sci(eu.back())) << " | "
           << (eR.empty() ? "—" : sci(eR.front()) + " → " + sci(eR.back())) << " | " << fixed(qu)
           << " / " << fixed(qR) << " |\n";
        const std::string f = "data/manufactured_space_" + file_label(label) + ".dat";
        write_text(o, f, data.str());
        files.push_back(out_path(o, f));
        titles.push_back(label);
        out.push_back({{"label", label}, {"elements", n}, {"error_u", eu}, {"error_R", eR}});
    }
    return out;
}

// The combinations of the semi-discrete rows: every scheme × combination of the time table (the
// --quick form: the quaternion, and plain WM for the mixed formulation, as there).
std::vector<MotionRunSpec> semi_discrete_specs(bool quick) {
    std::vector<MotionRunSpec> out;
    for (const TimeSeries& t : time_series(quick)) out.push_back(t.spec);
    return out;
}

// One combination's semi-discrete row: errors against y_h at each Δt, least-squares and per-pair
// orders, the scheme's order; data/manufactured_semi_discrete_*.dat (Δt and the four errors).
nlohmann::json semi_discrete_case(const StudyOptions& o, const MotionRunSpec& spec,
                                  std::ostringstream& md, std::vector<std::string>& files,
                                  std::vector<std::string>& titles) {
    const std::string label = spec.label();
    const int components = spec.formulation == Formulation::mixed ? 4 : 3;
    const SemiDiscreteSeries series = semi_discrete_series(spec);
    const SemiDiscreteResult r = run_semi_discrete_series(spec);
    std::ostringstream data;
    data << "# dt error_u error_R error_velocity error_forces (" << label
         << ", against the semi-discrete trajectory y_h)\n";
    md << "| " << label << " | " << series.order << " | "
       << (r.dt.empty() ? "—" : sci(r.dt.front(), 3) + " … " + sci(r.dt.back(), 3)) << " | "
       << sci(series.newton_tolerance, 0) << " | ";
    for (int k = 0; k < 4; ++k) {
        if (k >= components || r.error.empty()) {
            md << "— | ";
            continue;
        }
        const double first = component(r.error.front(), k), last = component(r.error.back(), k);
        std::string pairs;
        for (const ComponentDifferences& p : r.pair)
            pairs += (pairs.empty() ? "" : ", ") + fixed(component(p, k));
        md << sci(first) << " → " << sci(last) << " (" << pairs << ") | ";
    }
    std::vector<double> q;
    for (int k = 0; k < kTimeComponents; ++k) q.push_back(component(r.order, k));
    md << order_cell(q, components) << " | " << markdown_cell(r.note) << " |\n";
    for (size_t i = 0; i < r.dt.size(); ++i) {
        const ComponentDifferences& e = r.error[i];
        // "?" (gnuplot's missing value) for the forces the displacement formulation has not.
        data << r.dt[i] << " " << e.u << " " << e.R << " " << e.velocity << " "
             << (components == 4 ? sci(e.forces, 6) : std::string("?")) << "\n";
    }
    if (!r.dt.empty()) {
        const std::string f = "data/manufactured_semi_discrete_" + file_label(label) + ".dat";
        write_text(o, f, data.str());
        files.push_back(out_path(o, f));
        titles.push_back(label);
    }
    nlohmann::json j = {
        {"label", label},         {"dt", r.dt},       {"newton_tolerance", series.newton_tolerance},
        {"theory", series.order}, {"steps", r.steps}, {"note", r.note}};
    const char* const keys[kTimeComponents] = {"u", "R", "velocity", "forces"};
    for (int k = 0; k < components; ++k) {
        std::vector<double> e, p;
        for (const ComponentDifferences& d : r.error) e.push_back(component(d, k));
        for (const ComponentDifferences& d : r.pair) p.push_back(component(d, k));
        j[std::string("error_") + keys[k]] = e;
        j[std::string("order_") + keys[k]] = q[static_cast<size_t>(k)];
        j[std::string("pair_orders_") + keys[k]] = p;
    }
    return j;
}

}  // namespace

nlohmann::json study_manufactured_time(const StudyOptions& o) {
    std::ostringstream md;
    md << "## Study: manufactured motion (orders in time and space)\n\n"
          "The manufactured motion of docs/reference-solutions.md §7: a free rod spun past 2π "
          "(displacement formulation and mixed quaternion; mixed three-parameter types to 1.45π, "
          "Rodrigues to 2.7 "
          "rad), twisted and bent about an axis that varies along it and in time, 0 ≤ t ≤ 1, "
          "fully populated stiffness and mass. Time error of a run: max over ten output times "
          "of its difference to the run at Δt/2 on the same mesh "
          "(displacement p = 3, 2 elements per member; mixed 8 per member), per component: "
          "u = positions at five points (‖Δu‖/L), R = their rotations [rad], v = the "
          "velocity-level unknowns (displacement: every node's [u̇; ω]; mixed: every element's "
          "momenta [P; H]) and F = the mixed elements' internal forces [F; M], the last two as "
          "max-norm differences over the component's largest magnitude. Newton (stage "
          "iteration) tolerance 1e-12 in every run. Orders: least squares / last pair, in the "
          "order u / R / v (/ F). The mixed runs start from the exact state, which is not on the "
          "discrete slow manifold (O(h²) off): the start excites the high modes at that level "
          "and the non-dissipative trapezoidal rule keeps them, a floor of ~3e-4 (u) and ~4e-3 "
          "(rotation) in the differences at 8 elements per member, reached near Δt = 0.006; "
          "the steps stop above it. The L-stable Radau IIA damps those modes. The displacement "
          "runs (p = 3) start at their space error, ~1e-5; the undamped Gauss–Legendre schemes "
          "keep the modes it excites (docs/displacement-dynamics.md).\n\n"
       << "| combination | Δt | time error ‖Δu‖/L | rotation [rad] | v | F | order (LS) | "
          "order (last pair) | vs exact at the finest Δt/2 u / R | note |\n"
          "|---|---|---|---|---|---|---|---|---|---|\n";
    nlohmann::json out = {{"study", "manufactured-time"}, {"quick", o.quick}};
    std::vector<std::string> files, titles;
    out["time"] = nlohmann::json::array();
    for (const TimeSeries& t : time_series(o.quick)) {
        out["time"].push_back(time_case(o, t, md, files, titles));
    }
    md << "\n**Semi-discrete manufactured solution** (docs/studies.md): the same combinations "
          "forced "
          "by −R_h(t, y_h, ẏ_h, ÿ_h), y_h the mesh's exact trajectory (displacement: the nodal "
          "interpolant of the motion; mixed: every unknown at its exact value), started at y_h(0): "
          "the error against y_h(t_n) (max over ten output times; u over L and rotation angle at "
          "every node — mixed: and element —, v and F relative to their largest magnitude) is "
          "the scheme's alone. Orders per pair in parentheses, least squares in the order "
          "column.\n\n"
          "| combination | theory | Δt | Newton tol. | u | R | v | F | order (LS) | note |\n"
          "|---|---|---|---|---|---|---|---|---|---|\n";
    std::vector<std::string> sd_files, sd_titles;
    out["semi_discrete"] = nlohmann::json::array();
    for (const MotionRunSpec& spec : semi_discrete_specs(o.quick)) {
        out["semi_discrete"].push_back(semi_discrete_case(o, spec, md, sd_files, sd_titles));
    }
    out["ida"] = ida_case(o, param::id_of<param::WienerMilenkovic>(), md);
    if (!o.quick) out["ida_quaternion"] = ida_case(o, param::id_of<param::Quaternion>(), md);
    std::vector<std::string> sfiles, stitles;
    out["space"] = space_case(o, md, sfiles, stitles);
    // The forces' figure: the mixed runs only (the displacement formulation has none).
    std::vector<std::string> mfiles, mtitles;
    for (size_t i = 0; i < files.size(); ++i) {
        if (titles[i].rfind("mixed", 0) != 0) continue;
        mfiles.push_back(files[i]);
        mtitles.push_back(titles[i]);
    }
    struct Figure {
        const char* base;
        const std::vector<std::string>& files;
        const std::vector<std::string>& titles;
        const char *x, *y, *xlabel, *ylabel, *title, *refx, *slope;
        double refy;
    };
    const Figure figures[] = {
        {"manufactured-time-u", files, titles, "1", "6", "time step Δt [s]",
         "time error ‖Δu‖/L [-]", "Manufactured motion: time error vs Δt", "0.025", "2", 2e-3},
        {"manufactured-time-rotation", files, titles, "1", "7", "time step Δt [s]",
         "time error, rotation [rad]", "Manufactured motion: rotation error vs Δt", "0.025", "2",
         2e-3},
        {"manufactured-time-velocity", files, titles, "1", "8", "time step Δt [s]",
         "time error, velocities / momenta (relative) [-]",
         "Manufactured motion: velocity-level error vs Δt", "0.025", "2", 2e-3},
        {"manufactured-time-forces", mfiles, mtitles, "1", "9", "time step Δt [s]",
         "time error, internal forces (relative) [-]",
         "Manufactured motion (mixed): internal-force error vs Δt", "0.025", "2", 2e-3},
        {"manufactured-space-u", sfiles, stitles, "1", "3", "elements per member [-]",
         "error ‖Δu‖/L [-]", "Manufactured motion: space error at small Δt", "2", "-2", 0.2},
        {"manufactured-semi-discrete-u", sd_files, sd_titles, "1", "2", "time step Δt [s]",
         "error against y_h, ‖u − u_h‖/L [-]",
         "Semi-discrete manufactured solution: time error vs Δt", "0.05", "4", 1e-5},
        {"manufactured-semi-discrete-velocity", sd_files, sd_titles, "1", "4", "time step Δt [s]",
         "error against y_h, velocities / momenta (relative) [-]",
         "Semi-discrete manufactured solution: velocity-level error vs Δt", "0.05", "4", 1e-4}};
    for (const Figure& g : figures) {
        if (g.files.empty()) continue;
        plot("study_manufactured_time.gp", {{"files", join_words(g.files)},
                                            {"titles", join_words(g.titles)},
                                            {"xcol", g.x},
                                            {"ycol", g.y},
                                            {"xlabel", g.xlabel},
                                            {"ylabel", g.ylabel},
                                            {"plottitle", g.title},
                                            {"outbase", out_path(o, g.base)},
                                            {"refx", g.refx},
                                            {"refy", sci(g.refy, 3)},
                                            {"slope", g.slope}});
        out["figures"].push_back(std::string(g.base) + ".png");
        md << "\n![" << g.base << "](" << g.base << ".png)\n";
    }
    write_text(o, "study-manufactured-time.md", md.str());
    out["schema_version"] = kSchemaVersion;
    write_text(o, "study-manufactured-time.json", out.dump(1) + "\n");
    return out;
}

}  // namespace rotbeam::cli
