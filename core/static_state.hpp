// What a run reads of a solved static state: the observation side of a formulation set up for a
// static analysis. The driver solves through StaticSystem (core/nonlinear_system.hpp) and never
// sees these functions; the run's observers (runs/static_observers.hpp) build what a result
// reports from them, after each reported step.
#pragma once

#include <optional>
#include <vector>

#include "core/nodal_field.hpp"
#include "core/nonlinear_system.hpp"
#include "core/types.hpp"

namespace rotbeam {

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
    int member = -1;  // index into Model::members
    double s = 0.0;   // arc length along the member's reference line
    Vec3 force = Vec3::Zero();
    Vec3 moment = Vec3::Zero();
    Vec3 force_material = Vec3::Zero();
    Vec3 moment_material = Vec3::Zero();
};

// The current state of a static problem, read-only.
class StaticState {
  public:
    virtual ~StaticState() = default;
    virtual PointState point_state(int point_index) const = 0;
    virtual AssemblyCounters counters() const = 0;
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
    // (core/kinematic_check.hpp) compares neighbours; empty when the formulation does not provide
    // them.
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
    // The state at every node of every member in arc-length order (the shared end node once):
    // arc length, reference position, displacement and rotation R^c R^rᵀ, for the ParaView
    // output (runs/vtk_output.hpp), which adds the reference frame R^r(s). Empty when the
    // formulation does not provide them.
    struct NodeFrame {
        int member = -1;
        double s = 0.0;
        Vec3 reference = Vec3::Zero();
        Vec3 displacement = Vec3::Zero();
        Mat3 rotation = Mat3::Identity();
    };
    virtual std::vector<NodeFrame> node_frames() const { return {}; }
};

// A formulation set up for a static analysis of a model: solved as a StaticSystem, observed as a
// StaticState.
// The warm start (core/nodal_field.hpp) is optional: a formulation without it returns nullopt and
// false, and its runs start every load step from the last converged state.
class StaticProblem : public StaticSystem, public StaticState {
  public:
    // The current state as a field along the members.
    virtual std::optional<NodalField> nodal_field() const { return std::nullopt; }
    // Sets the free nodes' state to `field` (another discretization's solution of the same model)
    // evaluated at this discretization's nodes; false, the state unchanged, when the field does
    // not fit (another parameterization or interpolation, a member it does not cover). The
    // constrained nodes keep their state (set_load_factor sets them).
    virtual bool start_from(const NodalField& /*field*/) { return false; }
};

}  // namespace rotbeam
