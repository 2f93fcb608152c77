// `rotbeam study free-vibration-time`: the time integrators on the undamped free vibration
// (cases/free-vibration.yaml; runs in free_vibration_runs.hpp), 2 elements (displacement p = 1):
//  - Orders: every scheme × parameterization, errors per component (tip u_z, tip rotation, the
//    velocity-level unknowns, the root reaction) at ten output times over 0–0.5 s against the
//    same combination's highest-order scheme at a small step (Gauss–Legendre 3 or Radau IIA at
//    Δt = 156.25 µs); observed orders per pair and by least squares.
//  - Energy: (E − E0)/E0 over 1000 periods of the first mode (50 with --quick) at Δt = 1 ms for
//    generalized-α ρ∞ = 1 and 0.9, Gauss–Legendre 2 and 3, the mixed trapezoidal rule and Radau
//    IIA: means over windows of ten periods, their least-squares drift, the largest deviation.
// Writes study-free-vibration-time.{md,json}, data/free_vibration_*.dat and the figures.
#include <cmath>
#include <sstream>

#include "core/results.hpp"
#include "free_vibration_runs.hpp"
#include "parameterizations/registry.hpp"
#include "studies.hpp"
#include "study_common.hpp"
#include "study_math.hpp"

namespace rotbeam::cli {

namespace {

constexpr FreeVibrationGroup kFreeVibrationGroupList[kFreeVibrationGroups] = {
    FreeVibrationGroup::position, FreeVibrationGroup::rotation, FreeVibrationGroup::velocity,
    FreeVibrationGroup::force};

// Newton tolerances: the displacement formulation's residual scale is the EA floor (1e-4 EA =
// 2100 N), so 1e-12 would stop at 2e-9 N, 2e-9 of the 1 N release (a floor of ~4e-12 m under the
// tip errors, tests/displacement/test_gauss_collocation.cpp); 1e-14 resolves to round-off. The
// mixed unknowns' own scales (1 m, the load scale): 1e-12.
double free_vibration_newton_tolerance(Formulation f) {
    return f == Formulation::displacement ? 1e-14 : 1e-12;
}

// The second-order schemes: over 0–0.5 s (≈ 80 periods of the second bending mode, ω₂ ≈ 330
// rad/s) their phase error (ω₂h)²ω₂t/12 is O(1) at Δt = 2 ms (measured orders 1.1 and 0.3: that
// mode is dephased, not converged); from 0.2 ms on it is ≤ 0.06 rad.
const std::vector<double> kSecondOrderSteps = {2e-4, 1e-4, 5e-5};

struct OrderSeries {
    FreeVibrationSpec spec;
    double theory;
    std::vector<double> steps;
};

// --quick: the quaternion (displacement) and Wiener–Milenkovic (mixed) only; the parameterizations
// give the same digits at this amplitude (the full study lists them all).
std::vector<OrderSeries> order_series(bool quick) {
    std::vector<OrderSeries> out;
    for (const ParameterizationId r : param::parameterization_ids()) {
        if (quick && r != param::id_of<param::Quaternion>()) continue;
        FreeVibrationSpec s;
        s.rotation = r;
        s.newton_tolerance = free_vibration_newton_tolerance(Formulation::displacement);
        for (double rho : {1.0, 0.9}) {
            s.integrator = Integrator::generalized_alpha;
            s.rho_infinity = rho;
            out.push_back({s, 2.0, kSecondOrderSteps});
        }
        // Gauss 2 from 1.25 ms (at 2.5 ms the second bending mode, ωh ≈ 0.8, is pre-asymptotic);
        // Gauss 3 to 625 µs (below, the axial and shear modes' floor, ~1e-11).
        s.integrator = Integrator::gauss_legendre_2;
        out.push_back({s, 4.0, {1.25e-3, 6.25e-4, 3.125e-4}});
        s.integrator = Integrator::gauss_legendre_3;
        out.push_back({s, 6.0, {2.5e-3, 1.25e-3, 6.25e-4}});
    }
    for (const comb::Combination& c : comb::all_combinations(false, true)) {
        if (c.formulation != Formulation::mixed) continue;
        if (quick && (c.rotation != param::id_of<param::WienerMilenkovic>() ||
                      c.wm_map.value_or(WmMap::plain) != WmMap::plain))
            continue;
        FreeVibrationSpec s;
        s.formulation = Formulation::mixed;
        s.rotation = c.rotation;
        s.wm_map = c.wm_map.value_or(WmMap::plain);
        s.newton_tolerance = free_vibration_newton_tolerance(Formulation::mixed);
        s.integrator = Integrator::trapezoidal;
        out.push_back({s, 2.0, kSecondOrderSteps});
        // Radau IIA from 1.25 ms (at 2.5 ms the damping of the second bending mode is
        // pre-asymptotic: order 2.3 measured).
        s.integrator = Integrator::radau_iia_3;
        out.push_back({s, 5.0, {1.25e-3, 6.25e-4, 3.125e-4}});
    }
    return out;
}

std::string free_vibration_file_label(std::string s) {
    for (char& c : s) {
        if (c == '/' || c == '.') c = '_';
    }
    return s;
}

// The reference of a combination: its formulation's highest-order scheme at a quarter of the
// finest step of that scheme's series (Gauss–Legendre 3 at 156.25 µs; Radau IIA at 78.125 µs:
// 4^-5 of the finest Radau run's error).
FreeVibrationRun reference_run(FreeVibrationSpec spec) {
    const bool displacement = spec.formulation == Formulation::displacement;
    spec.integrator = displacement ? Integrator::gauss_legendre_3 : Integrator::radau_iia_3;
    spec.dt = displacement ? 1.5625e-4 : 7.8125e-5;
    return run_free_vibration(spec);
}

nlohmann::json order_case(const StudyOptions& o, const OrderSeries& t, const FreeVibrationRun& ref,
                          std::ostringstream& md, std::vector<std::string>& files,
                          std::vector<std::string>& titles) {
    const std::string label = t.spec.label();
    std::vector<double> inv;
    std::vector<std::vector<double>> e(kFreeVibrationGroups);
    std::ostringstream data;
    data << "# dt steps wall_s error_u error_rotation error_velocity error_force (" << label
         << ")\n";
    std::string note;
    FreeVibrationSpec spec = t.spec;
    for (double dt : t.steps) {
        spec.dt = dt;
        const FreeVibrationRun r = run_free_vibration(spec);
        if (!r.ok() || !ref.ok()) {
            const FreeVibrationRun& f = r.ok() ? ref : r;
            note += "Δt " + sci(dt, 2) + " " + f.status + ": " + f.message.substr(0, 60) + "; ";
            continue;
        }
        inv.push_back(1.0 / dt);
        data << dt << " " << r.steps << " " << r.wall_seconds;
        for (int g = 0; g < kFreeVibrationGroups; ++g) {
            const double d = group_difference(r, ref, kFreeVibrationGroupList[g]);
            e[static_cast<size_t>(g)].push_back(d);
            data << " " << d;
        }
        data << "\n";
    }
    nlohmann::json j = {{"label", label}, {"theory", t.theory}, {"dt", t.steps}, {"note", note}};
    md << "| " << label << " | " << fixed(t.theory, 0) << " | ";
    std::string pairs, fits;
    bool within = !inv.empty();
    for (int g = 0; g < kFreeVibrationGroups; ++g) {
        const std::vector<double>& eg = e[static_cast<size_t>(g)];
        md << (eg.empty() ? "—" : sci(eg.front()) + " → " + sci(eg.back())) << " | ";
        std::vector<double> q;
        for (size_t k = 1; k < eg.size(); ++k) {
            q.push_back(std::log2(eg[k - 1] / eg[k]));
            within = within && std::abs(q.back() - t.theory) <= 0.2;
        }
        const double fit = fit_order(inv, eg);
        std::string cell;
        for (double v : q) cell += (cell.empty() ? "" : ", ") + fixed(v);
        pairs += (g > 0 ? " / " : "") + cell;
        fits += (g > 0 ? " / " : "") + fixed(fit);
        const std::string name = group_name(kFreeVibrationGroupList[g]);
        j["error_" + name] = eg;
        j["orders_" + name] = q;
        j["order_" + name] = fit;
    }
    j["within_0.2"] = within;
    md << pairs << " | " << fits << " | " << (within ? "yes" : "**no**") << " | "
       << markdown_cell(note) << " |\n";
    if (!inv.empty()) {
        const std::string f =
            "data/free_vibration_order_" + free_vibration_file_label(label) + ".dat";
        write_text(o, f, data.str());
        files.push_back(out_path(o, f));
        titles.push_back(label);
    }
    return j;
}

nlohmann::json energy_case(const StudyOptions& o, const FreeVibrationSpec& spec,
                           std::ostringstream& md, std::vector<std::string>& files,
                           std::vector<std::string>& titles) {
    const FreeVibrationRun r = run_free_vibration(spec);
    const std::string label = spec.label();
    nlohmann::json j = {
        {"label", label}, {"status", r.status}, {"dt", spec.dt}, {"end_time", spec.end_time}};
    if (!r.ok() || r.energy.size() < 2) {
        md << "| " << label << " | " << r.status << ": " << markdown_cell(r.message.substr(0, 80))
           << " | | | | | | |\n";
        return j;
    }
    const EnergyDrift d = energy_drift(r);
    std::ostringstream data;
    data << "# periods mean_relative_energy_deviation_over_ten_periods (" << label << ")\n";
    for (size_t k = 0; k < d.window_means.size(); ++k) {
        data << d.window_periods[k] << " " << d.window_means[k] << "\n";
    }
    const std::vector<double>& mean = d.window_means;
    md << "| " << label << " | " << r.steps << " | " << fixed(d.periods, 1) << " | "
       << fixed(r.wall_seconds, 1) << " | " << sci(d.max_deviation) << " | "
       << (mean.empty() ? "—" : sci(mean.front()) + " → " + sci(mean.back())) << " | "
       << sci(d.drift_per_1000_periods) << " | " << r.status << " |\n";
    const std::string f = "data/free_vibration_energy_" + free_vibration_file_label(label) + ".dat";
    write_text(o, f, data.str());
    files.push_back(out_path(o, f));
    titles.push_back(label);
    j["steps"] = r.steps;
    j["periods"] = d.periods;
    j["energy0"] = r.energy.front();
    j["max_deviation"] = d.max_deviation;
    j["window_means"] = mean;
    j["window_periods"] = d.window_periods;
    j["drift_per_1000_periods"] = d.drift_per_1000_periods;
    j["newton_tolerance"] = spec.newton_tolerance;
    j["contraction_stop"] = spec.contraction_stop;
    return j;
}

std::vector<FreeVibrationSpec> energy_schemes(bool quick) {
    std::vector<FreeVibrationSpec> out;
    FreeVibrationSpec s;
    s.dt = 1e-3;
    s.end_time = quick ? 6.0 : 120.0;  // 50 or 1000 periods of the 2-element mesh's 8.5 Hz
    s.output_interval = 0.01;
    s.rotation = param::id_of<param::Quaternion>();
    s.newton_tolerance = free_vibration_newton_tolerance(Formulation::displacement);
    s.contraction_stop = false;  // the energy measures the scheme, not the stop (NewtonSettings)
    for (Integrator g : {Integrator::gauss_legendre_2, Integrator::gauss_legendre_3}) {
        s.integrator = g;
        out.push_back(s);
    }
    s.integrator = Integrator::generalized_alpha;
    for (double rho : {1.0, 0.9}) {
        s.rho_infinity = rho;
        out.push_back(s);
    }
    s.formulation = Formulation::mixed;
    s.rotation = param::id_of<param::WienerMilenkovic>();
    s.newton_tolerance = free_vibration_newton_tolerance(Formulation::mixed);
    for (Integrator g : {Integrator::trapezoidal, Integrator::radau_iia_3}) {
        s.integrator = g;
        out.push_back(s);
    }
    return out;
}

void plot_free_vibration(const StudyOptions& o, const std::string& base,
                         const std::vector<std::string>& files,
                         const std::vector<std::string>& titles, const std::string& ycol,
                         const std::string& ylabel, const std::string& title, nlohmann::json& out,
                         std::ostringstream& md) {
    if (files.empty()) return;
    plot("study_manufactured_time.gp", {{"files", join_words(files)},
                                        {"titles", join_words(titles)},
                                        {"xcol", "1"},
                                        {"ycol", ycol},
                                        {"xlabel", "time step Δt [s]"},
                                        {"ylabel", ylabel},
                                        {"plottitle", title},
                                        {"outbase", out_path(o, base)},
                                        {"refx", sci(1e-3, 3)},
                                        {"refy", sci(1e-6, 3)},
                                        {"slope", "4"}});
    out["figures"].push_back(base + ".png");
    md << "\n![" << base << "](" << base << ".png)\n";
}

}  // namespace

nlohmann::json study_free_vibration_time(const StudyOptions& o) {
    std::ostringstream md;
    nlohmann::json out = {{"study", "free-vibration-time"}, {"quick", o.quick}};
    md << "## Study: time integrators on the free vibration (orders, energy)\n\n"
          "The undamped free vibration of cases/free-vibration.yaml (docs/benchmarks.md §8: "
          "the cantilever released at rest from its static deflection under 1 N, tip 1.9e-3 L), "
          "2 elements (displacement p = 1; a coarse mesh has few modes, all resolved at the "
          "steps below but the axial and shear ones). Errors per component at ten output times "
          "over 0–0.5 s against the same combination's highest-order scheme at a small step "
          "(Gauss–Legendre 3 at 156.25 µs, Radau IIA at 78.125 µs), max over the times over the "
          "component's largest "
          "magnitude: u = tip u_z, rotation = tip rotation about y, velocity = tip [u̇_z, ω_y] "
          "(displacement) or the last element's momenta [P_z, H_y] (mixed), force = the root "
          "reaction [F_z, M_y]. Newton (stage iteration) tolerances 1e-14 (displacement: its "
          "residual scale is the EA floor) and 1e-12 (mixed). Orders: each pair, and least "
          "squares, in the order u / rotation / velocity / force; 'within 0.2' when every pair "
          "of every component is.\n\n"
       << "| combination | theory | u | rotation | velocity | force | orders per pair | order "
          "(LS) | within 0.2 | note |\n|---|---|---|---|---|---|---|---|---|---|\n";
    std::vector<std::string> files, titles;
    out["orders"] = nlohmann::json::array();
    FreeVibrationRun ref;
    std::string ref_label;
    for (const OrderSeries& t : order_series(o.quick)) {
        FreeVibrationSpec key = t.spec;
        key.integrator = Integrator::automatic;
        const std::string k = std::string(choice_name(key.formulation)) + "/" +
                              std::string(param::name_of(key.rotation)) +
                              (key.wm_map == WmMap::continuous ? "-continuous" : "");
        if (k != ref_label) {
            ref = reference_run(t.spec);
            ref_label = k;
        }
        out["orders"].push_back(order_case(o, t, ref, md, files, titles));
    }
    const char* const ycols[] = {"4", "5", "6", "7"};
    for (int g = 0; g < kFreeVibrationGroups; ++g) {
        const std::string name = group_name(kFreeVibrationGroupList[g]);
        plot_free_vibration(o, "free-vibration-order-" + name, files, titles, ycols[g],
                            "error, " + name + " (relative) [-]",
                            "Free vibration: " + name + " error vs Δt (slope 4 for reference)", out,
                            md);
    }
    md << "\n**Energy** over " << (o.quick ? "50" : "1000")
       << " periods of the first mode, Δt = 1 ms (≈ 120 steps per period), outputs every 10 ms; "
          "quaternion (displacement), Wiener–Milenkovic (mixed); each step's stages solved to the "
          "residual-and-correction criterion, not stopped by their contraction bound (which "
          "lets the energy drift by the tolerance per step). Window means of (E − E0)/E0 "
          "over ten periods; drift = their least-squares slope per 1000 periods.\n\n"
       << "| scheme | steps | periods | wall [s] | max \\|E − E0\\|/E0 | window mean first → last "
          "| drift per 1000 periods | status |\n|---|---|---|---|---|---|---|---|\n";
    std::vector<std::string> efiles, etitles;
    out["energy"] = nlohmann::json::array();
    for (const FreeVibrationSpec& s : energy_schemes(o.quick)) {
        out["energy"].push_back(energy_case(o, s, md, efiles, etitles));
    }
    if (!efiles.empty()) {
        plot("study_free_vibration_energy.gp", {{"files", join_words(efiles)},
                                                {"titles", join_words(etitles)},
                                                {"outbase", out_path(o, "free-vibration-energy")}});
        out["figures"].push_back("free-vibration-energy.png");
        md << "\n![free-vibration-energy](free-vibration-energy.png)\n";
    }
    write_text(o, "study-free-vibration-time.md", md.str());
    out["schema_version"] = kSchemaVersion;
    write_text(o, "study-free-vibration-time.json", out.dump(1) + "\n");
    return out;
}

}  // namespace rotbeam::cli
