#include "report_estimator_failures.hpp"

#include <iomanip>
#include <optional>
#include <sstream>

#include "core/so3.hpp"
#include "core/static_driver.hpp"
#include "estimates/accuracy_scale.hpp"
#include "report_summary.hpp"
#include "studies/study_common.hpp"

namespace rotbeam::cli {

namespace {

using json = nlohmann::json;

Vec3 vec3(const json& j) { return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()}; }

Mat3 mat3(const json& j) {
    Mat3 R;
    for (int r = 0; r < 3; ++r) R.row(r) = vec3(j[static_cast<size_t>(r)]).transpose();
    return R;
}

bool estimated(const json& run) {
    const std::string status = run.value("estimate", json::object()).value("status", "");
    return has_solution(run.value("status", "")) && (status == "estimated" || status == "partial");
}

// One quantity: a line when its true error is above `floor` and above 3 × its estimate `q`
// (estimates/estimator_failure.hpp).
void check(const std::string& what, double true_error, double floor, const json& q,
           std::vector<std::string>& out) {
    if (const std::optional<std::string> f = estimate::estimator_failure(true_error, floor, q))
        out.push_back(what + ": " + *f);
}

}  // namespace

std::vector<std::string> estimator_failures(const nlohmann::json& run) {
    std::vector<std::string> out;
    if (!estimated(run)) return out;
    const std::optional<PointReference> ref = point_reference(run.value("case", ""));
    if (!ref) return out;
    const Model& model = *ref->model;
    const double length = estimate::reference_length(model);
    for (const json& step : run.value("steps", json::array())) {
        if (!step.contains("load_factor") || !step.contains("points") || !step.contains("estimate"))
            continue;
        const double lambda = step["load_factor"].get<double>();
        for (size_t i = 0; i < model.points.size(); ++i) {
            const std::string& name = model.points[i].name;
            if (!step["points"].contains(name) || !step["estimate"].contains(name)) continue;
            const std::optional<PointState> exact = ref->state(i, lambda);
            if (!exact) continue;
            const json& point = step["points"][name];
            const json& e = step["estimate"][name];
            std::ostringstream lf;
            lf << lambda;
            const std::string at = " at load factor " + lf.str();
            if (e.contains("displacement")) {
                check(name + " displacement" + at,
                      (vec3(point["displacement"]) - exact->displacement).norm(),
                      estimate::kFailureFloor * length, e["displacement"], out);
            }
            if (e.contains("rotation") && point.contains("rotation_matrix")) {
                const Mat3 R = mat3(point["rotation_matrix"]);
                check(name + " rotation" + at, so3::rotation_angle(R.transpose() * exact->rotation),
                      estimate::kFailureFloor, e["rotation"], out);
            }
        }
    }
    return out;
}

std::string estimator_failures_section(const std::vector<nlohmann::json>& runs) {
    std::ostringstream md;
    int checked = 0;
    std::ostringstream list;
    for (const json& run : runs) {
        if (!estimated(run) || !point_reference(run.value("case", ""))) continue;
        ++checked;
        for (const std::string& f : estimator_failures(run)) {
            list << "- " << run.value("case", "") << " " << run.value("formulation", "") << "/"
                 << run.value("rotation", "") << ", " << markdown_cell(f) << "\n";
        }
    }
    md << "## Estimator failures\n\nEvery solved run with an error estimate and an independent "
          "reference (the exact roll-up, the continuum reference), at every load step and named "
          "point: a true error above 3 × its estimate is an estimator failure, listed with the "
          "estimate's own verdict (docs/error-estimates.md). True errors at or below "
       << estimate::kFailureFloor
       << " (of the reference length, or rad) are not counted. Runs checked: " << checked
       << ".\n\n";
    const std::string failures = list.str();
    md << (failures.empty() ? std::string("None.\n") : failures) << "\n";
    return md.str();
}

}  // namespace rotbeam::cli
