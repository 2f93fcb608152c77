#include "benches/bench_accuracy.hpp"

#include <algorithm>
#include <functional>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

#include "cases/loader/case_loader.hpp"
#include "core/continuum/continuum.hpp"
#include "core/oracles/rollup.hpp"
#include "core/so3.hpp"
#include "core/static_driver.hpp"
#include "estimates/accuracy_scale.hpp"
#include "runs/accuracy_run.hpp"
#include "runs/catalog.hpp"
#include "runs/timing.hpp"

namespace rotbeam::cli {

namespace {

using json = nlohmann::json;

constexpr double kTolerance = 1e-6;

struct Target {
    std::string name;
    std::string case_name;
    std::vector<std::string> overrides;  // the load steps of the target
    std::vector<PointState> reference;   // the tip per reported step
};

Model load(const Target& t, std::vector<std::string> extra) {
    std::vector<std::string> o = t.overrides;
    o.insert(o.end(), extra.begin(), extra.end());
    return load_case(resolve_case_path(t.case_name), o, CaseParts::case_file);
}

// The largest true error of the tip over the steps, relative to the accuracy control's scales
// (estimates/accuracy_scale.hpp); infinite when the run has no solution for every step.
double true_error(const Target& t, const Model& model, const json& r) {
    if (!has_solution(r["status"].get<std::string>()) && r["status"] != "accuracy-not-reached") {
        return 1e300;
    }
    if (r["steps"].size() != t.reference.size()) return 1e300;
    const double length = estimate::reference_length(model);
    double worst = 0.0;
    for (std::size_t k = 0; k < t.reference.size(); ++k) {
        const json& tip = r["steps"][k]["points"]["tip"];
        Vec3 u;
        Mat3 R;
        for (int i = 0; i < 3; ++i) {
            u[i] = tip["displacement"][i].get<double>();
            for (int j = 0; j < 3; ++j) R(i, j) = tip["rotation_matrix"][i][j].get<double>();
        }
        worst = std::max({worst, (u - t.reference[k].displacement).norm() / length,
                          so3::rotation_angle(R.transpose() * t.reference[k].rotation)});
    }
    return worst;
}

std::vector<Target> targets() {
    Target rollup{"rollup-2.0", "cantilever-moment", {"analysis.load_factors=[2.0]"}, {}};
    const oracle::RollupState s = oracle::rollup_tip(12.0, 2.0);
    rollup.reference.push_back({s.displacement, s.rotation});
    Target bend{"bend-45", "bend-45", {}, {}};
    const Model model = load(bend, {});
    const ContinuumOutcome out = solve_continuum(model);
    const std::size_t tip = static_cast<std::size_t>(model.point_index("tip"));
    for (const ContinuumStep& step : out.steps) bend.reference.push_back(step.points.at(tip));
    return {rollup, bend};
}

std::vector<std::string> discretization(int elements, int order) {
    return {"discretization.formulation=displacement", "discretization.rotation=quaternion",
            "members.*.elements=" + std::to_string(elements),
            "discretization.order=" + std::to_string(order)};
}

// The fastest grid point reaching the tolerance: per element count, the lowest order that
// reaches it (higher orders only cost more), timed once; the three fastest re-timed.
json hand_picked(const Target& t, bool quick, int repeats) {
    struct Found {
        int elements, order;
        double seconds;
    };
    std::vector<Found> found;
    for (const int n : quick ? std::vector<int>{1, 2, 4} : std::vector<int>{1, 2, 4, 8, 16}) {
        for (int p = 2; p <= 14; ++p) {
            const Model m = load(t, discretization(n, p));
            json r;
            const Timing once = time_in_process([&] { r = run_case(RunRequest{"", m}); }, 1);
            if (true_error(t, m, r) <= kTolerance) {
                found.push_back({n, p, once.median_seconds});
                break;
            }
        }
    }
    std::sort(found.begin(), found.end(),
              [](const Found& a, const Found& b) { return a.seconds < b.seconds; });
    json best;
    for (std::size_t i = 0; i < std::min<std::size_t>(3, found.size()); ++i) {
        const Model m = load(t, discretization(found[i].elements, found[i].order));
        const Timing ti = time_in_process([&] { run_case(RunRequest{"", m}); }, repeats);
        if (best.is_null() || ti.median_seconds < best["seconds"].get<double>()) {
            best = {{"elements", found[i].elements},
                    {"order", found[i].order},
                    {"seconds", ti.median_seconds}};
        }
    }
    return best;
}

json controlled(const Target& t, const std::vector<std::string>& start, int repeats) {
    std::vector<std::string> o = {"analysis.accuracy=1e-6"};
    o.insert(o.end(), start.begin(), start.end());
    const Model m = load(t, o);
    json r;
    const Timing ti = time_in_process([&] { r = run_to_accuracy(RunRequest{"", m}); }, repeats);
    return {{"start", start},
            {"seconds", ti.median_seconds},
            {"status", r["accuracy"]["status"]},
            {"chosen", r["accuracy"]["chosen"]},
            {"attempts", r["accuracy"]["attempts"].size()},
            {"true_error", true_error(t, m, r)}};
}

}  // namespace

json bench_accuracy_control(bool quick, int repeats) {
    json out = {{"name", "accuracy-control"}, {"accuracy", kTolerance}, {"results", json::array()}};
    std::cout << "accuracy control, displacement quaternion, TOL = 1e-6 (in-process medians)\n";
    for (const Target& t : targets()) {
        const json best = hand_picked(t, quick, repeats);
        json row = {{"target", t.name}, {"hand_picked", best}};
        std::cout << std::setprecision(3) << "  " << t.name << ": hand-picked " << best["elements"]
                  << " x order " << best["order"] << " " << 1e3 * best["seconds"].get<double>()
                  << " ms\n";
        // The control starts coarse whatever the case's mesh (estimate::coarse_start).
        json c = controlled(t, {}, repeats);
        c["ratio"] = c["seconds"].get<double>() / best["seconds"].get<double>();
        std::cout << "    --accuracy: " << c["status"].get<std::string>() << ", "
                  << c["chosen"]["elements"] << " x order " << c["chosen"]["order"] << ", "
                  << c["attempts"] << " attempts, " << 1e3 * c["seconds"].get<double>()
                  << " ms, ratio " << c["ratio"].get<double>() << ", true error "
                  << c["true_error"].get<double>() << "\n";
        row["controlled"] = c;
        out["results"].push_back(row);
    }
    return out;
}

}  // namespace rotbeam::cli
