// Dynamic and modal analyses of the displacement formulation (issue 6; analyses.hpp). This file
// holds the parameterization switch for them, as make_problem.cpp does for statics.
#include <iostream>

#include "analyses.hpp"
#include "core/errors.hpp"
#include "core/results.hpp"
#include "core/static_driver.hpp"
#include "formulations/displacement/displacement_modal.hpp"
#include "formulations/displacement/displacement_statics.hpp"
#include "parameterizations/registry.hpp"

namespace rotbeam {

namespace {

bool has_static_load(const Model& m) {
    return !m.point_loads.empty() || !m.distributed_loads.empty() || m.gravity.squaredNorm() > 0.0;
}

nlohmann::json vec3(const Eigen::Ref<const VecX>& v) {
    return nlohmann::json::array({v[0], v[1], v[2]});
}

// Named points' displacement and rotation amplitudes of one mode, largest component 1.
nlohmann::json mode_json(const Model& model, const form::Mesh& mesh, const VecX& shape,
                         double frequency_hz) {
    const double peak = shape.cwiseAbs().maxCoeff();
    const VecX v = peak > 0.0 ? VecX(shape / peak) : shape;
    nlohmann::json points = nlohmann::json::object();
    for (size_t i = 0; i < model.points.size(); ++i) {
        const int node = mesh.point_node[i];
        const int dof = node < 0 ? -1 : mesh.nodes[static_cast<size_t>(node)].dof;
        const VecX zero = VecX::Zero(6);
        const Eigen::Ref<const VecX> s = dof < 0 ? Eigen::Ref<const VecX>(zero)
                                                 : Eigen::Ref<const VecX>(v.segment(dof, 6));
        points[model.points[i].name] = {{"displacement", vec3(s.head(3))},
                                        {"rotation", vec3(s.tail(3))}};
    }
    return {{"frequency_hz", frequency_hz}, {"growth_rate", 0.0}, {"points", points}};
}

template <class P>
void modal(const Model& model, bool trace, nlohmann::json& result) {
    form::DisplacementStatics<P> problem(model);
    result["dofs"] = problem.size();
    if (model.analysis.modal.about_static_state && has_static_load(model)) {
        NewtonSettings settings = newton_settings_from(model.solver, model.analysis.statics);
        if (trace) settings.trace = &std::cerr;
        std::vector<double> loads = model.analysis.statics.load_factors;
        if (loads.empty()) loads = {1.0};
        RotationUnwrapper unwrapper(model.points.size());
        std::vector<PointState> states(model.points.size());
        const StaticOutcome out = run_static(problem, loads, settings, [&](const StepRecord& s) {
            for (size_t i = 0; i < model.points.size(); ++i) {
                states[i] = problem.point_state(static_cast<int>(i));
            }
            result["steps"].push_back(
                step_json(model, s.load_factor, std::nullopt, s.newton_iterations, states, unwrapper));
        });
        if (out.status != SolveStatus::converged) {
            result["status"] = to_string(out.status);
            result["message"] = "static state for the modal analysis: " + out.message;
            return;
        }
    }
    VecX r;
    SparseMatrix K;
    problem.evaluate(r, &K);
    const form::Mesh mass_mesh = form::build_mass_mesh(model);
    const SparseMatrix M = form::assemble_mass_matrix(
        model, mass_mesh, [&](int node) { return P::matrix(problem.node_rotation(node)); });
    const form::ModalSolution s = form::solve_modal(K, M, model.analysis.modal.modes);
    result["frequencies_hz"] = s.frequencies_hz;
    result["modes"] = nlohmann::json::array();
    for (size_t i = 0; i < s.frequencies_hz.size(); ++i) {
        result["modes"].push_back(mode_json(model, problem.mesh(), s.shapes[i], s.frequencies_hz[i]));
    }
    result["modal"] = {{"solver", s.symmetric ? "symmetric (K symmetric to round-off)" : "QZ"},
                       {"stiffness_asymmetry", s.asymmetry},
                       {"mass_rule", model.discretization.mass_rule}};
    result["counters"] = counters_json(problem.counters());
    result["status"] = "converged";
    result["message"] = "modes of the " +
                        std::string(result["steps"].empty() ? "undeformed" : "static") + " state";
}

}  // namespace

void run_displacement_dynamic(const Model& model, bool /*trace*/, nlohmann::json& result) {
    report_unavailable(model, result);
}

void run_displacement_modal(const Model& model, bool trace, nlohmann::json& result) {
    param::dispatch_parameterization(model.discretization.rotation,
                                     [&]<class P>() { modal<P>(model, trace, result); });
}

}  // namespace rotbeam
