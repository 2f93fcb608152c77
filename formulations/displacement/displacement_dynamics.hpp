// Dynamics of the displacement-based formulation (seed 000 Eq. 9 with the inertial and damping
// forces) as a SecondOrderProblem for the Lie-group generalized-α integrator
// (core/generalized_alpha.hpp; Brüls, Cardona & Arnold 2012) and a CollocationProblem for the
// Gauss–Legendre collocation (core/gauss_collocation.hpp), which sets stage states directly.
//
// State per free node: displacement u and rotation R (stored as parameters p of P), spatial
// velocity v = [u˙; ω] (Ṙ = ω̃ R), true acceleration v˙ and the pseudo-acceleration a. The Newton
// unknowns of a step are the increment Δ = [Δu; ψ] per node:
//   u_{n+1} = u_n + Δu,   R_{n+1} = exp(ψ̃) R_n   (p_{n+1} = compose(p(ψ), p_n): the spatial
//   increment is composed on the left, as the static retraction does),
// and v_{n+1}, v˙_{n+1} follow from Δ by the generalized-α relations. Velocities and
// accelerations are spatial vectors, so a chart rescale of p changes none of them and needs no
// restart of the integrator's history.
//
// Residual rows per free node a (weak form of seed 000 Eq. 9):
//   r_a = [static part: Σ w (N_a′ F^E1 + N_a F^E2 − N_a f_ext) − point loads]
//       + Σ_mass points w N_a F^I + Σ_stiffness points w (N_a′ F^D1 + N_a F^D2),
// with v, v˙ interpolated from the nodes by N_j (and v′ by N_j′), F^I and its blocks from
// calculate_inertial_forces.hpp on the mass rule's quadrature (consistent by default, the same M
// as the modal analysis), F^D from calculate_damping_forces.hpp on the stiffness quadrature, built
// only when a section has damping (AssemblyCounters::damping_terms stays 0 otherwise).
// Jacobian with respect to Δ: ∂r/∂q · diag(I, T(ψ_i)) + c_v ∂r/∂v + c_a ∂r/∂v˙ (T = dexp, the
// rotation vector's spatial tangent; c_v, c_a the generalized-α slopes). Loads carry their own
// time functions (DisplacementStatics::set_time).
//
// Rotating root (case key `rotating_frame`, docs/rotating-frame.md): the supports turn at constant
// angular velocity Ω about the axis through c. The unknowns are then the motion relative to the
// frame Q(t) = exp(t Ω̃) that turns with them (supports at rest in it), in that frame's axes: u, R
// and v = [u˙; ω] relative. The inertial force is F^I of the absolute motion, whose kinematics in
// the frame's axes are (r = x − c, v_u the relative translation rate)
//   u¨_abs = v˙_u + 2 Ω × v_u + Ω × (Ω × r),  ω_abs = ω + Ω,  ω˙_abs = ω˙ + Ω × ω,
// so its tangent gains ∂/∂v_u = M_u 2Ω̃, ∂/∂ω = M_ω Ω̃ (Coriolis) and ∂/∂x = M_u Ω̃Ω̃
// (centrifugal), M_u, M_ω the mass's translation and rotation columns. The damping law acts on
// the relative rates (a rigid rotation dissipates nothing), gravity turns in the frame's axes
// (Q(t)ᵀ g); dead loads, which would turn too, are refused with a rotating frame.
//
// Nothing allocates after the first evaluation (buffers sized in the constructor).
#pragma once

#include <array>
#include <vector>

#include "core/gauss_collocation.hpp"
#include "core/generalized_alpha.hpp"
#include "core/model.hpp"
#include "core/sparse_lu.hpp"
#include "formulations/displacement/displacement_statics.hpp"
#include "formulations/displacement/interpolate_rotation.hpp"
#include "formulations/displacement/mesh.hpp"
#include "parameterizations/registry.hpp"

namespace rotbeam::form {

struct BeamEnergy {
    double kinetic = 0.0;  // ½ vᵀ M v with the mass rule's quadrature (absolute velocity)
    double strain = 0.0;   // ½ ∫ [ε; κ]ᵀ C [ε; κ] (= the material-axis form with C*)
    // ∫ (r × p + h) about the rotating frame's centre (the origin without one), [p; h] = M v the
    // section's momentum and angular momentum about its centre; in the unknowns' axes.
    Vec3 angular_momentum = Vec3::Zero();
    // ½ ∫ v_fᵀ M v_f of the frame's rigid velocity v_f = [Ω × r; Ω] at the current configuration
    // (0 without a rotating frame): the Jacobi integral is kinetic + strain − Ω · L
    //   = ½ ∫ v_relᵀ M v_rel + strain − frame_kinetic.
    double frame_kinetic = 0.0;
    double total() const { return kinetic + strain; }
};

template <param::RotationParameterization P>
class DisplacementDynamics : public CollocationProblem {
  public:
    using Params = param::Params<P::kSize>;

    explicit DisplacementDynamics(const Model& model);

    // NonlinearSystem (unknowns: the step increment Δ)
    int size() const override { return statics_.size(); }
    void evaluate(VecX& residual, SparseMatrix* jacobian) override;
    void retract(const Eigen::Ref<const VecX>& dx) override;
    void save_state(int slot) override;
    void restore_state(int slot) override;
    const VecX& residual_scale() const override { return statics_.residual_scale(); }
    const VecX& increment_scale() const override { return statics_.increment_scale(); }
    std::string describe_state() const override { return statics_.describe_state(); }

    // SecondOrderProblem
    void initialize_acceleration(double t) override;
    void begin_step(double t_next, double h, const GeneralizedAlpha& scheme) override;
    void end_step() override;
    double acceleration_change(double length) const override;
    bool energy_terms(EnergyTerms& terms) override;

    // CollocationProblem (vectors in the unknowns' numbering, 6 per free node: [u; rotation])
    void start_rates(VecX& v, VecX& v_dot) const override;
    void set_start_acceleration(const Eigen::Ref<const VecX>& v_dot) override;
    void set_stage(const Eigen::Ref<const VecX>& delta, const Eigen::Ref<const VecX>& v,
                   const Eigen::Ref<const VecX>& v_dot, double t, double c_v, double c_a) override;
    void velocity_of_rate(const Eigen::Ref<const VecX>& delta, const Eigen::Ref<const VecX>& w,
                          Eigen::Ref<VecX> v) const override;
    // K from one evaluation at (c_v, c_a) = (0, 0); C and M from the terms that depend on the
    // rates alone (inertial and damping), which are all of ∂r/∂v and ∂r/∂v˙: the elastic terms and
    // the loads depend on q and t only. Saves two static assemblies per iteration matrix.
    void stage_matrices(const Eigen::Ref<const VecX>& delta, const Eigen::Ref<const VecX>& v,
                        const Eigen::Ref<const VecX>& v_dot, double t, VecX& r, SparseMatrix& K,
                        SparseMatrix& C, SparseMatrix& M) override;
    void keep_start(int slot) override;
    void restore_start(int slot) override;
    double distance_from_kept(int slot, double length) const override;

    // The static problem on the same mesh (its state is this problem's configuration): used for
    // `initial_state: static` (run_static on it at the loads of t = 0, then adopt_static_state()).
    DisplacementStatics<P>& statics() { return statics_; }
    // The same static problem with the steady rotating frame's inertial force switched on, for
    // that solve (adopt_static_state() switches it off again: the dynamics assemble their own).
    DisplacementStatics<P>& static_problem();
    void adopt_static_state();
    // The rotating frame of the supports (docs/rotating-frame.md): its rotation Q(t) = exp(t Ω̃)
    // from the unknowns' axes to inertial axes (the identity without one), Ω and the centre c.
    bool rotating() const { return spinning_; }
    Mat3 frame_rotation(double t) const;
    const Vec3& frame_angular_velocity() const { return omega_frame_; }
    const Vec3& frame_center() const { return center_; }
    // The Jacobi integral of the motion relative to the frame, E − Ω · L (kinetic + strain
    // energy minus Ω times the angular momentum about c): constant for a free undamped beam whose
    // supports turn at constant Ω (the supports' work Ω · M equals Ω · dL/dt); E without a frame.
    double frame_energy();
    // Sets every free node's velocity: translation u˙ and spatial angular velocity ω (relative to
    // the rotating frame when there is one: zero is the rigid rotation).
    void set_velocity(const Vec3& u_dot, const Vec3& omega);
    void set_node_velocity(int node, const Vec6& v) { v_n_[node] = v_[node] = v; }
    // Sets a node's acceleration v˙ (and a = v˙) at the step start, e.g. for tests of a moving
    // state that is not consistent; initialize_acceleration sets the consistent one.
    void set_node_acceleration(int node, const Vec6& a) {
        vd_n_[node] = a_n_[node] = vd_[node] = a_[node] = a;
    }

    PointState point_state(int point) const { return statics_.point_state(point); }
    AssemblyCounters counters() const;
    BeamEnergy energy();
    // Reaction at a constrained node: the residual rows it would have (elastic, damping, inertial
    // and distributed-load terms of its elements). The support load R is an external load on the
    // node, r_a − R = 0, so this is the force and moment the support exerts on the beam (inertial
    // axes; a +z tip force on a cantilever gives a −z root force).
    Vec6 reaction(int node);

    const Mesh& mesh() const { return statics_.mesh(); }
    const Vec6& node_velocity(int node) const { return v_[node]; }
    const Vec6& node_acceleration(int node) const { return vd_[node]; }
    const Vec3& node_displacement(int node) const { return statics_.node_displacement(node); }
    const Params& node_rotation(int node) const { return statics_.node_rotation(node); }
    bool damped() const { return damped_; }
    // ∫ [ε˙; κ˙]ᵀ D [ε˙; κ˙] ds with seed 000 Eq. 10's spatial rates: the power the damping law
    // dissipates at the current state (its lack of objectivity: docs/benchmarks.md, Errata).
    double damping_dissipation();
    // The external loads at the current state and load time, in the unknowns' numbering: point
    // loads (follower ones turned by the node's rotation), distributed loads, load fields and
    // gravity on the stiffness points — the load terms of the residual with the opposite sign.
    void external_load(VecX& f);

  private:
    void update_iterate();
    // The loads' time t: the statics' time functions, and gravity turned into the frame's axes.
    void set_load_time(double t);
    // The absolute kinematics of a point in the rotating frame (header comment), in place: s holds
    // the relative u¨, ω, ω˙ on entry; v_u is the relative translation rate, x the position.
    void add_frame_motion(InertialState& s, const Vec3& v_u, const Vec3& x) const;
    // Absolute 6-velocity of a point from its relative one: [v_u + Ω × (x − c); ω + Ω].
    Vec6 absolute_velocity(const Vec6& v, const Vec3& x) const;
    void set_configuration();
    // What a point's kernel reads of the interpolation: all of it (R, κ, H_s, and the nodes'
    // H_s⁺ for the tangent maps A_j), or R alone (the inertial terms without ∂/∂q); `rotation`
    // leaves the rest of InterpolatedRotation as it was.
    enum class PointNeeds { everything, rotation };
    void gather(const MeshElement& e, PointNeeds needs = PointNeeds::everything);
    void interpolate(const MeshElement& e, int q, InterpolatedRotation<P>& rot,
                     PointNeeds needs = PointNeeds::everything) const;
    // point(k, e, q, rot) at every quadrature point q of every element k of `elements`, with the
    // element's nodal parameters gathered and the rotation interpolated at the point (`needs`).
    template <class Point>
    void for_each_point(const std::vector<MeshElement>& elements, Point&& point,
                        PointNeeds needs = PointNeeds::everything);
    // Inertial forces on the mass mesh: r += F^I terms; J += kq ∂/∂q T + cv ∂/∂v + ca ∂/∂v˙.
    void assemble_inertia(VecX& r, SparseMatrix* J, double kq, double cv, double ca);
    // Damping forces: r += F^D terms; J += kq ∂/∂q T + cv ∂/∂v.
    void assemble_damping(VecX& r, SparseMatrix* J, double kq, double cv);
    void apply_exp_tangent(SparseMatrix& J) const;

    Model model_;
    DisplacementStatics<P> statics_;
    Mesh mass_mesh_;
    bool damped_ = false;
    bool spinning_ = false;
    Vec3 omega_frame_ = Vec3::Zero(), center_ = Vec3::Zero(), gravity_ = Vec3::Zero();
    Mat3 W_ = Mat3::Zero();  // Ω̃
    GeneralizedAlpha scheme_;
    double h_ = 0.0;
    double time_ = 0.0;  // time of the loads (t_{n+1} in a step)
    double cv_ = 0.0, ca_ = 0.0;

    // Step state (n) and the current iterate (n+1), per node (constrained nodes stay at rest).
    std::vector<Vec3> u_n_;
    std::vector<Params> p_n_;
    std::vector<Vec6> v_n_, vd_n_, a_n_;
    std::vector<Vec6> v_, vd_, a_;
    std::vector<Mat3> T_;  // dexp(ψ_i)
    std::vector<Params> p_trial_;
    VecX delta_;
    VecX stage_backup_;  // set_stage: delta_ before the stage, restored if it is refused
    std::array<VecX, kCheckpointSlots> saved_delta_;
    // keep_start: the accepted state (u, p, v, v˙, a) per node, two slots.
    struct KeptStart {
        std::vector<Vec3> u;
        std::vector<Params> p;
        std::vector<Vec6> v, vd, a;
    };
    std::array<KeptStart, 2> kept_;

    // Per-element workspace (p+1 nodes).
    std::vector<Params> pe_;
    std::vector<param::TangentInverse<P::kSize>> Me_;
    std::vector<Mat3> A_, K_;
    std::vector<Mat6> X1_, X2_;  // damping: per-node column maps of F^D1, F^D2
    Mat3 R0_ = Mat3::Identity();
    // initialize_acceleration: the mass matrix on the statics' pattern, its KLU kept and
    // refactored in place for every output (the pattern is fixed), the residual and v˙.
    SparseMatrix mass_;
    SparseLUSolver mass_lu_{SparseLUSolver::Kind::klu_refactor};
    VecX r0_, a0_;
    VecX rate_residual_;  // stage_matrices: the rate terms' residual, not used
    long inertial_terms_ = 0;
    long damping_terms_ = 0;
};

#define ROTBEAM_DISPLACEMENT_DYNAMICS_EXTERN(P) \
    extern template class DisplacementDynamics<param::P>;
ROTBEAM_FOR_EACH_PARAMETERIZATION(ROTBEAM_DISPLACEMENT_DYNAMICS_EXTERN)
#undef ROTBEAM_DISPLACEMENT_DYNAMICS_EXTERN

}  // namespace rotbeam::form
