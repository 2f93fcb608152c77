// DisplacementDynamics<P>: construction, the generalized-α state updates and checkpoints.
// Included only by displacement_dynamics.cpp.
#pragma once

#include <algorithm>

#include "core/errors.hpp"
#include "core/so3.hpp"
#include "core/turning_frame_loads.hpp"
#include "formulations/displacement/displacement_dynamics.hpp"
#include "formulations/displacement/displacement_modal.hpp"
#include "parameterizations/rotation_vector.hpp"

namespace rotbeam::form {

template <param::RotationParameterization P>
DisplacementDynamics<P>::DisplacementDynamics(const Model& model)
    : model_(model), statics_(model), mass_mesh_(build_mass_mesh(model)) {
    if (model.rotating_frame.active()) {
        refuse_dead_loads_with_turning_root(model);
        spinning_ = true;
        omega_frame_ = model.rotating_frame.angular_velocity;
        center_ = model.rotating_frame.center;
        W_ = so3::skew(omega_frame_);
    }
    gravity_ = model.gravity;
    if (model.discretization.displacement.update != Update::multiplicative) {
        throw InputError(
            "discretization.update: dynamics composes rotation increments "
            "(multiplicative); '" +
            std::string(choice_name(model.discretization.displacement.update)) +
            "' is for statics only");
    }
    for (const PrescribedMotion& m : mesh().prescribed) {
        if (m.displacement.norm() > 0.0 || m.rotation.norm() > 0.0) {
            throw InputError(
                "constraints: prescribed (non-zero) motion is not supported by the "
                "displacement dynamics, only clamped supports");
        }
    }
    ROTBEAM_VERIFY(mass_mesh_.elements.size() == mesh().elements.size(),
                   "mass mesh and stiffness mesh differ");
    for (const MeshElement& e : mass_mesh_.elements) {
        for (const QuadraturePoint& q : e.qp) {
            if (!(q.M_star(0, 0) > 0.0)) {
                throw InputError("member '" + model.members[e.member].name +
                                 "': dynamic analyses need a section mass (density or mass)");
            }
        }
    }
    // solver.assemble_all_terms: the damping terms also for undamped sections (D* = 0: exact
    // zeros, at the full cost); the inertia is assembled here, not as the statics' rest terms.
    damped_ = model.has_damping() || model.solver.assemble_all_terms;
    statics_.assemble_absent_terms(false, model.solver.assemble_all_terms);
    const size_t nodes = mesh().nodes.size();
    u_n_.assign(nodes, Vec3::Zero());
    p_n_.assign(nodes, P::identity());
    p_trial_ = p_n_;
    for (auto* v : {&v_n_, &vd_n_, &a_n_, &v_, &vd_, &a_}) v->assign(nodes, Vec6::Zero());
    T_.assign(nodes, Mat3::Identity());
    delta_ = VecX::Zero(size());
    for (VecX& s : saved_delta_) s = delta_;
    r0_ = delta_;
    const size_t nn = static_cast<size_t>(mesh().order) + 1;
    pe_.resize(nn);
    Me_.resize(nn);
    A_.resize(nn);
    K_.resize(nn);
    X1_.resize(nn);
    X2_.resize(nn);
    // The dynamics assemble the frame's inertial force (assemble_inertia); the statics' steady
    // one is switched on only for `initial_state: static` (static_problem()).
    statics_.set_rotating_frame_forces(false);
    set_load_time(0.0);
}

template <param::RotationParameterization P>
Mat3 DisplacementDynamics<P>::frame_rotation(double t) const {
    return spinning_ ? so3::exp_map(t * omega_frame_) : Mat3::Identity();
}

template <param::RotationParameterization P>
void DisplacementDynamics<P>::set_load_time(double t) {
    statics_.set_time(t);
    time_ = t;
    if (spinning_) {
        gravity_ = frame_rotation(t).transpose() * model_.gravity;
        statics_.set_gravity(gravity_);
    }
}

template <param::RotationParameterization P>
void DisplacementDynamics<P>::add_frame_motion(InertialState& s, const Vec3& v_u,
                                               const Vec3& x) const {
    if (!spinning_) return;
    s.u_ddot += 2.0 * W_ * v_u + W_ * (W_ * (x - center_));
    s.omega_dot += W_ * s.omega;
    s.omega += omega_frame_;
}

template <param::RotationParameterization P>
Vec6 DisplacementDynamics<P>::absolute_velocity(const Vec6& v, const Vec3& x) const {
    if (!spinning_) return v;
    Vec6 out = v;
    out.head<3>() += omega_frame_.cross(x - center_);
    out.tail<3>() += omega_frame_;
    return out;
}

template <param::RotationParameterization P>
DisplacementStatics<P>& DisplacementDynamics<P>::static_problem() {
    statics_.set_rotating_frame_forces(true);
    return statics_;
}

template <param::RotationParameterization P>
void DisplacementDynamics<P>::adopt_static_state() {
    for (size_t i = 0; i < mesh().nodes.size(); ++i) {
        u_n_[i] = statics_.node_displacement(static_cast<int>(i));
        p_n_[i] = statics_.node_rotation(static_cast<int>(i));
    }
    delta_.setZero();
    statics_.set_rotating_frame_forces(false);
}

template <param::RotationParameterization P>
void DisplacementDynamics<P>::set_velocity(const Vec3& u_dot, const Vec3& omega) {
    for (size_t i = 0; i < mesh().nodes.size(); ++i) {
        if (mesh().nodes[i].dof < 0) continue;
        v_n_[i] << u_dot, omega;
        v_[i] = v_n_[i];
    }
}

// The iterate of the step from Δ: configuration, then a_{n+1}, v_{n+1}, v˙_{n+1}
// (core/generalized_alpha.hpp). All parameters are computed before any state changes, so a
// parameterization refusing one (SingularityError) leaves the iterate as it was.
template <param::RotationParameterization P>
void DisplacementDynamics<P>::update_iterate() {
    set_configuration();
    const Mesh& m = mesh();
    const GeneralizedAlpha& g = scheme_;
    const double h = h_;
    for (size_t i = 0; i < m.nodes.size(); ++i) {
        const int d = m.nodes[i].dof;
        if (d < 0) continue;
        const Vec6 D = delta_.segment<6>(d);
        a_[i] = (D - h * v_n_[i] - h * h * (0.5 - g.beta) * a_n_[i]) / (g.beta * h * h);
        v_[i] = v_n_[i] + h * (1.0 - g.gamma) * a_n_[i] + h * g.gamma * a_[i];
        vd_[i] = ((1.0 - g.alpha_m) * a_[i] + g.alpha_m * a_n_[i] - g.alpha_f * vd_n_[i]) /
                 (1.0 - g.alpha_f);
    }
}

// The configuration exp(Δ) ∘ q_n of the increment delta_. All parameters are computed before any
// node changes, so a parameterization refusing one (SingularityError) leaves the state as it was.
template <param::RotationParameterization P>
void DisplacementDynamics<P>::set_configuration() {
    const Mesh& m = mesh();
    for (size_t i = 0; i < m.nodes.size(); ++i) {
        const int d = m.nodes[i].dof;
        if (d < 0) continue;
        p_trial_[i] = P::compose(P::from_rotation_vector(delta_.segment<3>(d + 3)), p_n_[i]);
        if constexpr (P::kSize == 4) p_trial_[i].normalize();
        if (statics_.rescales_nodes()) p_trial_[i] = P::rescale(p_trial_[i], P::identity());
    }
    for (size_t i = 0; i < m.nodes.size(); ++i) {
        const int d = m.nodes[i].dof;
        if (d < 0) continue;
        statics_.set_node_state(static_cast<int>(i), u_n_[i] + delta_.segment<3>(d), p_trial_[i]);
    }
}

template <param::RotationParameterization P>
void DisplacementDynamics<P>::retract(const Eigen::Ref<const VecX>& dx) {
    delta_ += dx;
    try {
        update_iterate();
    } catch (...) {
        delta_ -= dx;
        throw;
    }
}

template <param::RotationParameterization P>
void DisplacementDynamics<P>::save_state(int slot) {
    ROTBEAM_VERIFY(slot >= 0 && slot < kCheckpointSlots, "checkpoint slot out of range");
    saved_delta_[slot] = delta_;
}

template <param::RotationParameterization P>
void DisplacementDynamics<P>::restore_state(int slot) {
    ROTBEAM_VERIFY(slot >= 0 && slot < kCheckpointSlots, "checkpoint slot out of range");
    delta_ = saved_delta_[slot];
    update_iterate();
}

// M v˙_0 = −r(q_0, v_0, v˙ = 0, t): M = ∂r/∂v˙ is the inertia assembly with c_a = 1 alone, on
// the statics' pattern (taken from the first call's Jacobian; later calls evaluate the residual
// alone). Its KLU is kept: every later call (the collocation's outputs) refactors it in place
// with the first call's pivot order (core/sparse_lu.hpp), so an output neither analyses the
// pattern again nor allocates.
template <param::RotationParameterization P>
void DisplacementDynamics<P>::initialize_acceleration(double t) {
    set_load_time(t);
    for (size_t i = 0; i < mesh().nodes.size(); ++i) {
        statics_.set_node_state(static_cast<int>(i), u_n_[i], p_n_[i]);
        v_[i] = v_n_[i];
        vd_[i].setZero();
    }
    statics_.evaluate(r0_, mass_.nonZeros() == 0 ? &mass_ : nullptr);
    std::fill(mass_.valuePtr(), mass_.valuePtr() + mass_.nonZeros(), 0.0);
    assemble_inertia(r0_, &mass_, 0.0, 0.0, 1.0);
    if (damped_) assemble_damping(r0_, nullptr, 1.0, 0.0);
    if (!mass_lu_.factorize(mass_)) {
        throw SolverError("initial acceleration: the mass matrix is singular");
    }
    mass_lu_.solve(r0_, a0_);
    for (size_t i = 0; i < mesh().nodes.size(); ++i) {
        const int d = mesh().nodes[i].dof;
        if (d < 0) continue;
        vd_n_[i] = a_n_[i] = vd_[i] = a_[i] = -a0_.segment<6>(d);
    }
}

// Predictor: v˙_{n+1} = 0, hence a_{n+1} = (α_f v˙_n − α_m a_n)/(1 − α_m) and Δ from it (as
// OpenTurbine/Kynema). Predicting v˙_{n+1} = v˙_n instead fails at large amplitude with ρ∞ = 1:
// undamped axial modes (ω h ≫ 1) make v˙ alternate in sign from step to step, and Newton started
// from the doubled acceleration found no monotone step (the 150 N release of
// tests/displacement/test_dynamics.cpp at Δt = 1 ms, step 185).
template <param::RotationParameterization P>
void DisplacementDynamics<P>::begin_step(double t_next, double h, const GeneralizedAlpha& g) {
    scheme_ = g;
    h_ = h;
    cv_ = g.velocity_slope(h);
    ca_ = g.acceleration_slope(h);
    set_load_time(t_next);
    for (size_t i = 0; i < mesh().nodes.size(); ++i) {
        const int d = mesh().nodes[i].dof;
        if (d < 0) continue;
        const Vec6 a1 = (g.alpha_f * vd_n_[i] - g.alpha_m * a_n_[i]) / (1.0 - g.alpha_m);
        delta_.segment<6>(d) = h * v_n_[i] + h * h * ((0.5 - g.beta) * a_n_[i] + g.beta * a1);
    }
    update_iterate();
}

template <param::RotationParameterization P>
void DisplacementDynamics<P>::end_step() {
    for (size_t i = 0; i < mesh().nodes.size(); ++i) {
        if (mesh().nodes[i].dof < 0) continue;
        u_n_[i] = statics_.node_displacement(static_cast<int>(i));
        p_n_[i] = statics_.node_rotation(static_cast<int>(i));
        v_n_[i] = v_[i];
        vd_n_[i] = vd_[i];
        a_n_[i] = a_[i];
    }
    delta_.setZero();
}

// The local error estimate's |a_{n+1} − a_n| (core/generalized_alpha.hpp), every free node.
template <param::RotationParameterization P>
double DisplacementDynamics<P>::acceleration_change(double length) const {
    double worst = 0.0;
    for (size_t i = 0; i < mesh().nodes.size(); ++i) {
        if (mesh().nodes[i].dof < 0) continue;
        const Vec6 d = a_[i] - a_n_[i];
        worst = std::max({worst, d.head<3>().norm() / length, d.tail<3>().norm()});
    }
    return worst;
}

template <param::RotationParameterization P>
void DisplacementDynamics<P>::start_rates(VecX& v, VecX& v_dot) const {
    v.setZero(size());
    v_dot.setZero(size());
    for (size_t i = 0; i < mesh().nodes.size(); ++i) {
        const int d = mesh().nodes[i].dof;
        if (d < 0) continue;
        v.segment<6>(d) = v_n_[i];
        v_dot.segment<6>(d) = vd_n_[i];
    }
}

template <param::RotationParameterization P>
void DisplacementDynamics<P>::set_start_acceleration(const Eigen::Ref<const VecX>& v_dot) {
    for (size_t i = 0; i < mesh().nodes.size(); ++i) {
        const int d = mesh().nodes[i].dof;
        if (d >= 0) vd_n_[i] = v_dot.segment<6>(d);
    }
}

// A stage of the collocation: the configuration, rates and loads are set directly (the
// generalized-α history a_n is not used); evaluate() then uses the slopes c_v, c_a.
template <param::RotationParameterization P>
void DisplacementDynamics<P>::set_stage(const Eigen::Ref<const VecX>& delta,
                                        const Eigen::Ref<const VecX>& v,
                                        const Eigen::Ref<const VecX>& v_dot, double t, double c_v,
                                        double c_a) {
    stage_backup_ = delta_;
    delta_ = delta;
    try {
        set_configuration();
    } catch (...) {
        delta_ = stage_backup_;
        throw;
    }
    for (size_t i = 0; i < mesh().nodes.size(); ++i) {
        const int d = mesh().nodes[i].dof;
        if (d < 0) continue;
        v_[i] = v.segment<6>(d);
        vd_[i] = a_[i] = v_dot.segment<6>(d);
    }
    set_load_time(t);
    cv_ = c_v;
    ca_ = c_a;
}

// ω = dexp(ψ) ψ˙ with the rotation vector's spatial tangent (the map T of the iteration matrix).
template <param::RotationParameterization P>
void DisplacementDynamics<P>::velocity_of_rate(const Eigen::Ref<const VecX>& delta,
                                               const Eigen::Ref<const VecX>& w,
                                               Eigen::Ref<VecX> v) const {
    for (size_t i = 0; i < mesh().nodes.size(); ++i) {
        const int d = mesh().nodes[i].dof;
        if (d < 0) continue;
        v.segment<3>(d) = w.segment<3>(d);
        v.segment<3>(d + 3) =
            param::RotationVector::spatial_tangent(delta.segment<3>(d + 3)) * w.segment<3>(d + 3);
    }
}

template <param::RotationParameterization P>
void DisplacementDynamics<P>::keep_start(int slot) {
    ROTBEAM_VERIFY(slot == 0 || slot == 1, "keep_start: slot out of range");
    KeptStart& k = kept_[static_cast<size_t>(slot)];
    k.u = u_n_;
    k.p = p_n_;
    k.v = v_n_;
    k.vd = vd_n_;
    k.a = a_n_;
}

template <param::RotationParameterization P>
void DisplacementDynamics<P>::restore_start(int slot) {
    ROTBEAM_VERIFY(slot == 0 || slot == 1, "restore_start: slot out of range");
    const KeptStart& k = kept_[static_cast<size_t>(slot)];
    ROTBEAM_VERIFY(k.u.size() == u_n_.size(), "restore_start: nothing kept");
    u_n_ = k.u;
    p_n_ = k.p;
    v_n_ = v_ = k.v;
    vd_n_ = vd_ = k.vd;
    a_n_ = a_ = k.a;
    delta_.setZero();
    set_configuration();
}

// max over the free nodes of |u − u_kept| / length and the angle of R R_keptᵀ.
template <param::RotationParameterization P>
double DisplacementDynamics<P>::distance_from_kept(int slot, double length) const {
    ROTBEAM_VERIFY(slot == 0 || slot == 1, "distance_from_kept: slot out of range");
    const KeptStart& k = kept_[static_cast<size_t>(slot)];
    double worst = 0.0;
    for (size_t i = 0; i < mesh().nodes.size(); ++i) {
        if (mesh().nodes[i].dof < 0) continue;
        const int n = static_cast<int>(i);
        const double du = (statics_.node_displacement(n) - k.u[i]).norm() / length;
        const Mat3 dR = P::matrix(statics_.node_rotation(n)) * P::matrix(k.p[i]).transpose();
        worst = std::max({worst, du, so3::log_map(dR).norm()});
    }
    return worst;
}

template <param::RotationParameterization P>
AssemblyCounters DisplacementDynamics<P>::counters() const {
    AssemblyCounters c = statics_.counters();
    c.inertial_terms = inertial_terms_;
    c.damping_terms = damping_terms_;
    return c;
}

}  // namespace rotbeam::form
