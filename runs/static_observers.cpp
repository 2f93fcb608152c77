#include "static_observers.hpp"

#include "combinations/registry.hpp"
#include "core/beam_rotation.hpp"
#include "core/results.hpp"

namespace rotbeam {

nlohmann::json observe_points(const Model& model, const StaticState& state,
                              const StepRecord& step) {
    std::vector<PointState> states(model.points.size());
    for (size_t i = 0; i < model.points.size(); ++i) {
        states[i] = state.point_state(static_cast<int>(i));
    }
    const std::vector<Vec3> continued =
        rotation_vectors_along_beam(model, state.rotation_stations(), states);
    return step_json(model, step.load_factor, std::nullopt, step.newton_iterations, states,
                     continued);
}

nlohmann::json observe_convergence(const StepRecord& step) {
    nlohmann::json c = {{"criterion", to_string(step.criterion)},
                        {"scaled_residual", step.scaled_residual},
                        {"error_bound", step.error_bound}};
    if (step.round_off_floor > 0.0) c["round_off_floor"] = step.round_off_floor;
    return c;
}

std::optional<nlohmann::json> observe_centerline(const StaticState& state) {
    constexpr size_t kMaxPoints = 2000;
    const std::vector<StaticState::CenterlinePoint> line = state.centerline();
    if (line.empty() || line.size() > kMaxPoints) return std::nullopt;
    nlohmann::json points = nlohmann::json::array();
    for (const StaticState::CenterlinePoint& p : line) {
        points.push_back({p.member, p.position[0], p.position[1], p.position[2]});
    }
    return points;
}

std::optional<nlohmann::json> observe_sections(const Model& model, const StaticState& state,
                                               double load_factor) {
    const std::vector<SectionResultants> sections = state.section_resultants();
    if (sections.empty()) return std::nullopt;
    auto vec = [](const Vec3& v) { return nlohmann::json::array({v[0], v[1], v[2]}); };
    nlohmann::json stations = nlohmann::json::array();
    for (const SectionResultants& r : sections) {
        stations.push_back({{"member", model.members[static_cast<size_t>(r.member)].name},
                            {"s", r.s},
                            {"force", vec(r.force)},
                            {"moment", vec(r.moment)},
                            {"force_material", vec(r.force_material)},
                            {"moment_material", vec(r.moment_material)}});
    }
    return nlohmann::json{{"load_factor", load_factor}, {"stations", stations}};
}

std::string stability_not_assessed(const Model& model) {
    const std::string_view formulation =
        comb::traits(model.discretization.formulation).no_stability_reason;
    if (!formulation.empty()) return std::string(formulation);
    // Follower loads have no energy: the driver assesses them kinetically (with a mass).
    return {};
}

nlohmann::json observe_stability(const StepRecord& step, const std::string& not_assessed) {
    const StaticStability& s = step.stability;
    nlohmann::json j = {{"assessment", to_string(s.assessment)}};
    if (s.assessment == StaticStability::Assessment::not_assessed) {
        j["reason"] = s.reason.empty() ? not_assessed : s.reason;
        return j;
    }
    j["criterion"] = to_string(s.criterion);
    if (s.kinetic) {
        const KineticSummary& k = *s.kinetic;
        j["growing_modes"] = s.negative;
        j["kinetic"] = {{"modes", k.modes},
                        {"highest_frequency_hz", k.highest_frequency_hz},
                        {"divergent", k.divergent},
                        {"fluttering", k.fluttering},
                        {"growth_rate", k.growth_rate},
                        {"growth_rate_error", k.growth_rate_error},
                        {"largest_error", k.largest_error}};
    } else {
        j["negative_eigenvalues"] = s.negative;
    }
    if (s.stationary_point_distance) j["stationary_point_distance"] = *s.stationary_point_distance;
    if (!s.reason.empty()) j["reason"] = s.reason;
    return j;
}

std::optional<KinematicDefect> observe_unresolved_kinematics(const StaticState& state) {
    const std::optional<KinematicDefect> worst = worst_kinematic_defect(state.rotation_stations());
    if (!worst || within_kinematic_bound(*worst)) return std::nullopt;
    return worst;
}

}  // namespace rotbeam
