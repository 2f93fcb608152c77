// Supports, joints, follower loads, assembly counters and input errors of the displacement
// statics.
#include <boost/test/unit_test.hpp>

#include "core/errors.hpp"
#include "core/so3.hpp"
#include "core/static_driver.hpp"
#include "deformed.hpp"
#include "formulations/displacement/displacement_statics.hpp"

using namespace rotbeam;
using Statics = form::DisplacementStatics<param::Quaternion>;

namespace {

// See test_rollup.cpp: the residual-norm line search stalls on stiff beams.
NewtonSettings plain_newton() {
    NewtonSettings s;
    s.line_search = false;
    s.substeps = 2;
    return s;
}

Vec3 solve_tip(Statics& problem, const std::vector<double>& lambdas, int tip) {
    const StaticOutcome out = run_static(problem, lambdas, plain_newton(), nullptr);
    BOOST_TEST_INFO(out.message);
    BOOST_TEST_REQUIRE(has_solution(out.status));
    return problem.point_state(tip).displacement;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(displacement_structures)

// "Model only what the scene requires": a static dead-load case builds no inertia, no damping
// and no load stiffness; the same case with a follower moment builds the load stiffness.
BOOST_AUTO_TEST_CASE(static_dead_load_assembles_no_inertia_damping_or_load_stiffness) {
    Statics problem(test::rollup(4, 6));
    solve_tip(problem, {1.0}, 1);
    const AssemblyCounters c = problem.counters();
    BOOST_TEST(c.jacobian_evaluations > 0);
    BOOST_TEST(c.elastic_terms > 0);
    BOOST_TEST(c.inertial_terms == 0);
    BOOST_TEST(c.damping_terms == 0);
    BOOST_TEST(c.follower_stiffness == 0);
    BOOST_TEST(c.gravity_terms == 0);
    BOOST_TEST(c.distributed_load_terms == 0);
}

// A follower tip moment about e_y turns about e_y with the tip: the roll-up answer is unchanged
// (exact circle), and the follower load stiffness is assembled.
BOOST_AUTO_TEST_CASE(follower_tip_moment_rollup_matches_exact_and_counts_load_stiffness) {
    Model m = test::rollup(4, 10);
    m.point_loads[0].frame = LoadFrame::follower;
    Statics problem(m);
    const Vec3 u = solve_tip(problem, {0.5, 1.0, 1.5}, 1);
    BOOST_TEST((u - test::rollup_exact_tip(1.5)).norm() / test::kRollupL < 1e-9);
    BOOST_TEST(problem.counters().follower_stiffness > 0);
    BOOST_TEST(problem.counters().inertial_terms == 0);
}

// Two members rigidly joined at a shared point behave exactly as one member with the same
// elements: the roll-up split at mid-span gives the single-member tip to round-off.
BOOST_AUTO_TEST_CASE(members_joined_at_a_shared_point_act_as_one_member) {
    Model one = test::rollup(4, 8);
    Model two = one;
    two.points = {{"root", Vec3::Zero()}, {"tip", Vec3(12, 0, 0)}, {"mid", Vec3(6, 0, 0)}};
    two.members[0].end_point = 2;
    two.members[0].elements = 2;
    Member second = two.members[0];
    second.name = "outer";
    second.start_point = 2;
    second.end_point = 1;
    two.members.push_back(second);
    Statics a(one), b(two);
    const Vec3 ua = solve_tip(a, {0.7, 1.4}, 1);
    const Vec3 ub = solve_tip(b, {0.7, 1.4}, 1);
    BOOST_TEST((ua - ub).norm() < 1e-12 * test::kRollupL);
    BOOST_TEST(b.mesh().nodes.size() == a.mesh().nodes.size());
}

// Prescribing the same rigid motion (large rotation about a skew axis) at both ends of a
// curved, twisted member with a coupled section: the solution is that rigid motion at every
// node (strain-free), to round-off.
BOOST_AUTO_TEST_CASE(prescribed_rigid_motion_at_both_ends_moves_every_node_rigidly) {
    Model m = test::curved_twisted(3, 4, false, false);
    m.point_loads.clear();
    m.distributed_loads.clear();
    const Vec3 theta(0.3, -1.9, 0.8);
    const Mat3 R = so3::exp_map(theta);
    const Vec3 origin = m.points[0].position;
    for (int k = 0; k < 2; ++k) {
        Constraint c;
        c.point = k;
        c.kind = Constraint::Kind::prescribed;
        c.rotation = theta;
        c.displacement = (R - Mat3::Identity()) * (m.points[k].position - origin);
        if (k == 0)
            m.constraints[0] = c;
        else
            m.constraints.push_back(c);
    }
    // The prescribed ends at λ = 1 plus the rigid motion at the free nodes is an equilibrium:
    // the residual vanishes and Newton accepts the state without moving it. (A load path λ d,
    // exp(λ θ) would shorten the chord on the way and buckle the member.)
    Statics problem(m);
    problem.set_load_factor(1.0);
    VecX dx = VecX::Zero(problem.size());
    for (const form::MeshNode& node : problem.mesh().nodes) {
        if (node.dof < 0) continue;
        dx.segment<3>(node.dof) = (R - Mat3::Identity()) * (node.x0 - origin);
        dx.segment<3>(node.dof + 3) = theta;
    }
    problem.retract(dx);
    VecX r;
    problem.evaluate(r, nullptr);
    // Round-off floor: each force term carries EA ε_mach |x′| ≈ 1e4 · 2.2e-16, summed with
    // weights |N′| ~ p²/h ≈ 6 over 5 points, against a force scale of ≈ 4.8 (prescribed-motion
    // scale, compute_scales): ≈ 1e-11. 1e-10 stays far below the 1e-2 of a non-rigid residual.
    BOOST_TEST((r.array() / problem.residual_scale().array()).abs().maxCoeff() < 1e-10);
    // That floor is above the 1e-12 tolerance: Newton moves the state by round-off only, sees
    // the residual not halve and accepts it as stalled at round-off — two corrections (the one
    // that shows the stall and the final one), each below 1e-14 of the scales.
    const NewtonOutcome out = solve_newton(problem, plain_newton());
    BOOST_TEST(out.accepted());
    BOOST_TEST(out.iterations <= 2);
    BOOST_TEST(out.error_bound <= 1e-14);
    for (size_t i = 0; i < problem.mesh().nodes.size(); ++i) {
        const Vec3 x0 = problem.mesh().nodes[i].x0 - origin;
        const Vec3 expected = (R - Mat3::Identity()) * x0;
        BOOST_TEST((problem.node_displacement(static_cast<int>(i)) - expected).norm() < 1e-10);
        const Mat3 Ri = param::Quaternion::matrix(problem.node_rotation(static_cast<int>(i)));
        BOOST_TEST((Ri - R).norm() < 1e-10);
    }
}

BOOST_AUTO_TEST_CASE(invalid_models_are_refused_with_input_errors) {
    Model no_mass = test::rollup(2, 2);
    no_mass.gravity = Vec3(0, 0, -9.81);
    BOOST_CHECK_THROW(Statics{no_mass}, InputError);
    Model no_stiffness = test::rollup(2, 2);
    no_stiffness.members[0].sections[0].section.stiffness.reset();
    BOOST_CHECK_THROW(Statics{no_stiffness}, InputError);
    Model bad_order = test::rollup(2, 2);
    bad_order.discretization.order = 0;  // past the loader, which refuses it too
    BOOST_CHECK_THROW(Statics{bad_order}, InputError);
}

BOOST_AUTO_TEST_SUITE_END()
