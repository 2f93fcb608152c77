#include "continuum_json.hpp"

#include <chrono>

#include "core/beam_rotation.hpp"
#include "core/continuum/continuum.hpp"
#include "core/results.hpp"
#include "core/version.hpp"

namespace rotbeam {

nlohmann::json continuum_result_json(const Model& model, const std::string& case_path) {
    const auto start = std::chrono::steady_clock::now();
    const ContinuumOutcome outcome = solve_continuum(model);
    nlohmann::json result = {{"case", model.name},
                             {"case_file", case_path},
                             {"rotation", "none"},
                             {"formulation", "continuum"},
                             {"elements", 0},
                             {"order", 0},
                             {"dofs", 6},
                             {"status", outcome.status},
                             {"message", outcome.message},
                             {"version", kGitDescribe},
                             {"schema_version", kSchemaVersion},
                             {"steps", nlohmann::json::array()}};
    for (const ContinuumStep& step : outcome.steps) {
        const std::vector<Vec3> continued =
            rotation_vectors_along_beam(model, step.rotations, step.points);
        nlohmann::json s = step_json(model, step.load_factor, std::nullopt, step.iterations,
                                     step.points, continued);
        s["shooting_residual"] = step.residual;
        s["root_force"] = {step.root_force.x(), step.root_force.y(), step.root_force.z()};
        s["root_moment"] = {step.root_moment.x(), step.root_moment.y(), step.root_moment.z()};
        nlohmann::json centreline = nlohmann::json::array();
        for (size_t i = 0; i < step.centreline.size(); ++i) {
            const Vec3& x = step.centreline[i];
            centreline.push_back({step.centreline_s[i], x.x(), x.y(), x.z()});
        }
        s["centreline"] = centreline;  // [s, x, y, z] of the deformed centreline
        result["steps"].push_back(s);
    }
    result["wall_seconds"] =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!all_finite(result)) {
        result["status"] = "error";
        result["message"] = "non-finite values in the continuum solution";
        result["steps"] = nlohmann::json::array();
    }
    return result;
}

}  // namespace rotbeam
