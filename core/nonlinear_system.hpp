// What a formulation exposes to the solver drivers: a residual, its consistent Jacobian and a
// retraction. The drivers (core/static_driver, KINSOL) know nothing else — not the
// parameterization, not the formulation (MFEM's "residual + Jacobian" habit).
//
// The state lives inside the system. `retract(dx)` moves it to x ⊕ dx: for rotations this composes
// the increment (multiplicative update), for additive systems it is x + dx. The Jacobian is the
// derivative of the residual with respect to dx at dx = 0, through the retraction.
#pragma once

#include <Eigen/SparseCore>
#include <string>
#include <vector>

#include "core/types.hpp"

namespace rotbeam {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

// Counts of what an assembly built: the "model only what the scene requires" evidence.
struct AssemblyCounters {
    long residual_evaluations = 0;
    long jacobian_evaluations = 0;
    long elastic_terms = 0;       // quadrature-point evaluations of elastic forces
    long inertial_terms = 0;      // ... of inertial forces (zero in statics)
    long damping_terms = 0;       // ... of damping forces (zero without damping)
    long follower_stiffness = 0;  // follower-load stiffness contributions (zero for dead loads)
    long distributed_load_terms = 0;
    long gravity_terms = 0;
};

class NonlinearSystem {
public:
    virtual ~NonlinearSystem() = default;

    // Number of unknowns (the dimension of dx and of the residual).
    virtual int size() const = 0;
    // Residual at the current state; the Jacobian too when `jacobian` is non-null. The sparsity
    // pattern of the Jacobian must not change between calls (drivers reuse the symbolic
    // factorization). May throw SingularityError.
    virtual void evaluate(VecX& residual, SparseMatrix* jacobian) = 0;
    // state ← state ⊕ dx. May throw SingularityError (the state is then unchanged).
    virtual void retract(const Eigen::Ref<const VecX>& dx) = 0;
    // Checkpoints: slot kLineSearchSlot is used by the Newton line search, kStepSlot by the
    // load-step cutting (the last converged state). A system keeps kCheckpointSlots copies.
    static constexpr int kLineSearchSlot = 0;
    static constexpr int kStepSlot = 1;
    static constexpr int kCheckpointSlots = 2;
    virtual void save_state(int slot) = 0;
    virtual void restore_state(int slot) = 0;
    // Characteristic scales: r_i / residual_scale_i and dx_i / increment_scale_i are O(1)
    // (forces by a force scale, moments by force × length, displacements by a length, rotations
    // and dimensionless parameters by 1).
    virtual const VecX& residual_scale() const = 0;
    virtual const VecX& increment_scale() const = 0;

    // Additive systems (retract(dx) is x + dx) can also be driven by KINSOL through these.
    virtual bool additive() const { return false; }
    virtual VecX state_vector() const { return VecX(); }
    virtual void set_state_vector(const Eigen::Ref<const VecX>& /*x*/) {}

    // A short description of the current state for messages (e.g. the largest rotation angle).
    virtual std::string describe_state() const { return {}; }
};

// Named-point results every formulation provides: displacement and rotation relative to the
// reference configuration, R = R^c R^rᵀ (material → inertial).
struct PointState {
    Vec3 displacement = Vec3::Zero();
    Mat3 rotation = Mat3::Identity();
};

// Section resultants at one station of a member: the internal force and moment the part beyond
// the station (larger arc length) exerts on the part before it, in inertial and in material
// (deformed section) components.
struct SectionResultants {
    int member = -1;   // index into Model::members
    double s = 0.0;    // arc length along the member's reference line
    Vec3 force = Vec3::Zero();
    Vec3 moment = Vec3::Zero();
    Vec3 force_material = Vec3::Zero();
    Vec3 moment_material = Vec3::Zero();
};

// A formulation set up for a static analysis of a model.
class StaticProblem : public NonlinearSystem {
public:
    virtual void set_load_factor(double lambda) = 0;
    virtual PointState point_state(int point_index) const = 0;
    virtual AssemblyCounters counters() const = 0;
    // Largest rotation angle [rad] held in the state's parameters (for messages and tests; the
    // messages also give the largest angle continued along the beam, core/beam_rotation.hpp).
    virtual double max_rotation_angle() const { return 0.0; }
    // Section resultants along the members at the formulation's natural stations (mixed: element
    // mid-points, where F and M are unknowns); empty when the formulation does not provide them.
    virtual std::vector<SectionResultants> section_resultants() const { return {}; }
    // Deformed positions x^r + u of the formulation's nodes along each member, in arc-length
    // order (for shape plots); empty when the formulation does not provide them.
    struct CenterlinePoint {
        int member = -1;
        Vec3 position = Vec3::Zero();
    };
    virtual std::vector<CenterlinePoint> centerline() const { return {}; }
    // Rotations relative to the reference, R^c R^rᵀ, along each member from its start point to
    // its end point in arc-length order: every node, and in the mixed formulation each element's
    // rotation between its two nodes (`node` false). The reported rotation angle is continued
    // along them from the root (core/beam_rotation.hpp), and the kinematic check
    // (core/kinematic_check.hpp) compares neighbours; empty when the formulation does not provide them.
    struct RotationStation {
        int member = -1;
        bool node = true;
        Mat3 rotation = Mat3::Identity();
        // Element stations: the rotation vector of the turn from the element's start node to its
        // end node that the element's own curvature makes, ΔL C^ab κ (R_b = R_a exp of it, to the
        // element's discretization error); zero where the formulation has no element curvature.
        Vec3 turn = Vec3::Zero();
    };
    virtual std::vector<RotationStation> rotation_stations() const { return {}; }
};

}  // namespace rotbeam
