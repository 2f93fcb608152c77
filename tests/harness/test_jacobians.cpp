// The analytic Jacobians of every registered combination against central differences
// (jacobian_check.hpp), statics and dynamics, each at its list of strongly deformed states.
//
// Displacement formulation: the residual through the retraction x ⊕ δ at the curved, twisted
// member of tests/displacement/deformed.hpp (tip rotation 2.6 rad) — three meshes and load sets,
// and the additive update of the three-parameter types — and the generalized-α iteration matrix
// at its moving state (tests/displacement/dynamic_state.hpp), undamped and damped. Mixed
// formulation: the residual and, in dynamics, ∂F/∂X and ∂F/∂Ẋ at the two-member structure of
// tests/mixed/deformed_model.hpp with the states of tests/mixed/deformed_state.hpp, one and two
// supports (ρ), and for GXBeam's continuous WM map past π and past 2π.
#include <boost/test/unit_test.hpp>
#include <string>
#include <vector>

#include "formulations/displacement/displacement_dynamics.hpp"
#include "formulations/displacement/displacement_statics.hpp"
#include "formulations/mixed/mixed_dynamics.hpp"
#include "formulations/mixed/mixed_statics.hpp"
#include "parameterizations/wiener_milenkovic_continuous.hpp"
#include "tests/displacement/deformed.hpp"
#include "tests/displacement/dynamic_state.hpp"
#include "tests/harness/coverage.hpp"
#include "tests/harness/harness.hpp"
#include "tests/harness/jacobian_check.hpp"
#include "tests/mixed/deformed_model.hpp"
#include "tests/mixed/deformed_state.hpp"
#include "tests/mixed/dynamic_models.hpp"

namespace rotbeam::test {
namespace {

// A displacement-formulation state: its model, and the smallest tip rotation it must reach.
struct DisplacementState {
    std::string label;
    Model model;
    double min_angle;
};

template <class P>
std::vector<DisplacementState> displacement_states(const comb::Combination& c) {
    std::vector<DisplacementState> states = {
        {"p=4, 2 elements, follower+gravity", curved_twisted(2, 4, true, true), 2.0},
        {"p=2 reduced, 3 elements, follower", curved_twisted(3, 2, true, false), 2.0},
        {"p=6 GLL, 1 element, dead+gravity", curved_twisted(1, 6, false, true), 2.0}};
    states[2].model.discretization.quadrature = Quadrature::gll;
    // The additive update (Newton unknowns δp, p ← p + δp) of the three-parameter types: the
    // differences now go through the additive retraction and check J_ψ · H_s(p). The deforming
    // increment then sets the parameters themselves, so the rotations are smaller for Rodrigues
    // (1.8 rad) and WM (2.3 rad) than for the rotation vector (2.6 rad).
    if constexpr (P::kSize == 3) {
        states.push_back({"additive update, p=4, 2 elements, follower+gravity",
                          curved_twisted(2, 4, true, true), 1.5});
        states.back().model.discretization.displacement.update = Update::additive;
    }
    for (DisplacementState& s : states) apply(c, s.model);
    return states;
}

template <class S>
JacobianError displacement_jacobian_error(S& s, int slot) {
    VecX r;
    SparseMatrix J;
    s.evaluate(r, &J);
    return compare_with_central_differences(
        MatX(J), [&](const VecX& d) { return residual_after_retraction(s, slot, d); },
        s.increment_scale());
}

// Unknowns scaled by increment_scale (displacements by L, rotations by 1), so one step
// h = ∛ε ≈ 6e-6 suits every column. Central differences then err by ~h²|r‴| (truncation,
// ≈ 4e-11 relative for an O(1)-scaled smooth residual) plus ε|r|/h (round-off, ≈ 4e-11 × the
// largest cancelling term: the axial stiffness EA = 1e4 against bending terms ~1e2 gives a
// factor ~1e2). 1e-7 of each column leaves a margin of ~20 over that estimate; a wrong Jacobian
// term (missing curvature map, a sign in a follower term) shows up at 1e-3 or larger.
template <class P>
void check_displacement_statics(const comb::Combination& c) {
    for (const DisplacementState& state : displacement_states<P>(c)) {
        constexpr int kBase = 0;
        form::DisplacementStatics<P> s(state.model);
        s.set_load_factor(1.0);
        s.retract(deforming_increment(s.mesh()));
        s.save_state(kBase);
        BOOST_TEST_CONTEXT(c.label() << ", " << state.label) {
            BOOST_TEST_REQUIRE(s.max_rotation_angle() > state.min_angle);
            const JacobianError e = displacement_jacobian_error(s, kBase);
            BOOST_TEST_MESSAGE(c.label() << ", " << state.label << ": tip rotation "
                                         << s.max_rotation_angle() << " rad, worst column error "
                                         << e.column_relative << " (relative to the column)");
            BOOST_TEST(e.column_relative < 1e-7);
        }
        checked("jacobian", c.label() + " statics", state.label);
    }
}

// The iteration matrix (static part, inertia, damping, the exp tangent T and the generalized-α
// slopes) through the step's retraction Δ ⊕ δ. The statics' estimate applies: truncation
// ~h² ≈ 4e-11, round-off ~ε/h × (largest cancelling term / column size) ≲ 1e-8 here, where the
// inertia slope c_a = (1 − α_m)/((1 − α_f) β h²) ~ 1e4 mixes with stiffness ~1e4. 1e-7 keeps a
// margin of 10; a wrong block (a sign in G^I, a missing T or A_b map) errs by 1e-3 or more.
// The third state turns the supports (rotating_frame, docs/rotating-frame.md): Coriolis and
// centrifugal columns of the inertia, gravity in the frame's axes, the damping on relative rates;
// its dead distributed moment (refused with a rotating frame) is dropped.
template <class P>
void check_displacement_dynamics(const comb::Combination& c) {
    for (const int variant : {0, 1, 2}) {
        const bool damping = variant > 0;
        Model m = moving_model(2, 3, damping);
        if (variant == 2) {
            std::erase_if(m.distributed_loads,
                          [](const DistributedLoad& l) { return l.frame != LoadFrame::follower; });
            m.rotating_frame.angular_velocity = Vec3(0.7, -1.1, 2.3);
            m.rotating_frame.center = Vec3(0.3, -0.2, 0.1);
        }
        apply(c, m);
        form::DisplacementDynamics<P> d(m);
        set_moving_state(d);
        d.save_state(NonlinearSystem::kStepSlot);
        const std::string label = variant == 2 ? "moving, damped, rotating frame"
                                  : damping    ? "moving, damped"
                                               : "moving, undamped";
        BOOST_TEST_CONTEXT(c.label() << ", " << label) {
            const JacobianError e = displacement_jacobian_error(d, NonlinearSystem::kStepSlot);
            const AssemblyCounters n = d.counters();
            BOOST_TEST_MESSAGE(c.label() << ", " << label << ": tip rotation "
                                         << d.statics().max_rotation_angle()
                                         << " rad, worst column error " << e.column_relative);
            BOOST_TEST(e.column_relative < 1e-7);
            BOOST_TEST(n.inertial_terms > 0);
            // Damping is assembled only when a section has damping.
            BOOST_TEST((n.damping_terms > 0) == damping);
        }
        checked("jacobian", c.label() + " dynamics", label);
    }
}

// A mixed-formulation state: its model and the base rotation angle of deformed_mixed_state.
struct MixedState {
    std::string label;
    Model model;
    double base;
};

// GXBeam's continuous WM map is checked past π, where the chain rule through c = (1 − 8m/|θ|)θ
// is active (4.0–5.0 rad), and past 2π (6.5–7.5 rad); the closure ρ of a second support exists
// for the quaternion (mixed_layout.hpp).
template <class P>
std::vector<MixedState> mixed_states(const comb::Combination& c, bool dynamic) {
    const Model one = dynamic ? dynamic_test_model() : deformed_test_model();
    std::vector<MixedState> states;
    if constexpr (std::is_same_v<P, param::WienerMilenkovicContinuous>) {
        states = {{"one support, rotations 4.0-5.0 rad", one, 4.5}};
        if (!dynamic) states.push_back({"one support, rotations 6.5-7.5 rad", one, 7.0});
    } else {
        states = {{"one support", one, 2.1}};
        if constexpr (P::kSize == 4) {
            states.push_back({"two supports (rho)",
                              dynamic ? two_support_dynamic_model() : two_support_model(), 2.1});
        }
    }
    if (dynamic) {
        // The supports turn (rotating_frame, docs/rotating-frame.md): the ω_a and v_i terms of
        // Eqs. 45, 46, 49, 50 at the same deformed, moving state; the dead loads (refused with a
        // rotating frame) are dropped.
        Model spinning = one;
        std::erase_if(spinning.point_loads,
                      [](const PointLoad& l) { return l.frame != LoadFrame::follower; });
        std::erase_if(spinning.distributed_loads,
                      [](const DistributedLoad& l) { return l.frame != LoadFrame::follower; });
        spinning.rotating_frame.angular_velocity = Vec3(0.7, -1.1, 2.3);
        spinning.rotating_frame.center = Vec3(0.3, -0.2, 0.1);
        states.push_back({"one support, rotating frame", spinning, states.front().base});
        // Stiffness-proportional damping (mixed_damping.hpp) with a different μ per component:
        // the rate columns of F, M, the spin term through P, H and, with a turning frame, through
        // c (Ω − Aᵀω_a).
        for (const auto& [label, base] :
             {std::pair{"one support, damped", one},
              std::pair{"one support, damped, rotating frame", spinning}}) {
            Model damped = base;
            for (Member& member : damped.members) {
                for (SectionStation& station : member.sections) {
                    station.section.damping << 0.3, 0.5, 0.2, 0.4, 0.6, 0.25;
                }
            }
            states.push_back({label, damped, states.front().base});
        }
    }
    for (MixedState& s : states) apply(c, s.model);
    return states;
}

// Everything is of unit order (|q| ∈ [0.8, 1.2]); the central-difference step h ≈ ∛ε·max(1, |x|)
// ≲ 7e-5 (the largest parameter, Rodrigues at 2.6 rad, is ≈ 7; the continuous map's |θ| ≤ 11)
// leaves a truncation error h²|f'''|/6 ≲ 1e-8 for third derivatives ≲ 30 (R = C(q)/|q|² adds
// factors 1/|q|ᵏ ≤ 1.25ᵏ, the continuous map factors 1/|θ| ≤ 0.25) and a round-off ε|f|/h ≲ 1e-10.
// 1e-6 keeps a margin of 100 while any wrong term (a sign, a missing S block, a missing 1/|q|²
// derivative, a misplaced ρ column) is O(0.1–1).
template <class P>
void check_mixed_statics(const comb::Combination& c) {
    for (const MixedState& state : mixed_states<P>(c, false)) {
        form::MixedStatics<P> problem(state.model);
        problem.set_load_factor(1.3);
        const VecX x0 = deformed_mixed_state<P>(problem.numbering(), state.base);
        problem.set_state_vector(x0);
        BOOST_TEST_CONTEXT(c.label() << ", " << state.label) {
            BOOST_TEST(problem.max_rotation_angle() > state.base - 0.1);
            VecX r;
            SparseMatrix J;
            problem.evaluate(r, &J);
            const JacobianError e = compare_with_central_differences(
                MatX(J),
                [&](const VecX& d) {
                    problem.set_state_vector(x0 + d);
                    VecX rx;
                    problem.evaluate(rx, nullptr);
                    return rx;
                },
                additive_scale(x0));
            BOOST_TEST_MESSAGE(c.label() << ", " << state.label << ", " << problem.size()
                                         << " unknowns: max |J − J_fd| = " << e.absolute);
            BOOST_TEST(e.absolute < 1e-6);
            BOOST_TEST(e.largest_entry > 1.0);  // the comparison is not vacuous
        }
        checked("jacobian", c.label() + " statics", state.label);
    }
}

// ∂F/∂X and ∂F/∂Ẋ of the mixed dynamic residual F(t, X, Ẋ) (seed 002 Eqs. 45–50, 56) at a
// deformed, moving state; the statics' estimate and tolerance apply (a wrong term — a transpose
// of C^ab, I⁻¹'s off-diagonal block, a missing 1/|q|² — is O(0.1–1)).
template <class P>
void check_mixed_dynamics(const comb::Combination& c) {
    for (const MixedState& state : mixed_states<P>(c, true)) {
        form::MixedDynamics<P> dyn(state.model, 1.0);
        const VecX x0 = deformed_mixed_state<P>(dyn.numbering(), state.base);
        const VecX xd0 = mixed_rates(dyn.size());
        const double t = 0.37;
        BOOST_TEST_CONTEXT(c.label() << ", " << state.label) {
            VecX r;
            SparseMatrix Jx, Jxd;
            dyn.evaluate(t, x0, xd0, r, &Jx, &Jxd);
            const JacobianError ex = compare_with_central_differences(
                MatX(Jx),
                [&](const VecX& d) {
                    VecX rx;
                    dyn.evaluate(t, x0 + d, xd0, rx, nullptr, nullptr);
                    return rx;
                },
                additive_scale(x0));
            const JacobianError exd = compare_with_central_differences(
                MatX(Jxd),
                [&](const VecX& d) {
                    VecX rx;
                    dyn.evaluate(t, x0, xd0 + d, rx, nullptr, nullptr);
                    return rx;
                },
                additive_scale(xd0));
            BOOST_TEST_MESSAGE(c.label() << ", " << state.label << ", " << dyn.size()
                                         << " unknowns: max |∂F/∂X − FD| = " << ex.absolute
                                         << ", max |∂F/∂Ẋ − FD| = " << exd.absolute
                                         << ", largest rotation " << dyn.max_rotation_angle(x0));
            BOOST_TEST(ex.absolute < 1e-6);
            BOOST_TEST(exd.absolute < 1e-6);
            // Not vacuous: both Jacobians are of unit order, and F depends on the rates.
            BOOST_TEST(ex.largest_entry > 1.0);
            BOOST_TEST(exd.largest_entry > 0.5);
            BOOST_TEST(dyn.max_rotation_angle(x0) > 2.0);
            // Algebraic unknowns (F, M, node unknowns) have no rate in F, and neither has the
            // radial direction of an element's quaternion: ∂F/∂Ẋ q = 0 (H_m q = 0).
            const MatX Jd = MatX(Jxd);
            for (int j = 0; j < dyn.size(); ++j) {
                if (dyn.differential()[j] == 0.0)
                    BOOST_TEST(Jd.col(j).cwiseAbs().maxCoeff() == 0.0);
            }
            if constexpr (P::kSize == 4) {
                const form::MixedNumbering& nb = dyn.numbering();
                for (int e = 0; e < nb.element_count; ++e) {
                    const int col = nb.element_column(e) + nb.c();
                    const VecX radial = Jd.middleCols<4>(col) * x0.segment<4>(col);
                    BOOST_TEST(radial.cwiseAbs().maxCoeff() < 1e-14 * Jd.middleCols<4>(col).norm());
                }
            }
        }
        checked("jacobian", c.label() + " dynamics", state.label);
    }
}

}  // namespace

BOOST_AUTO_TEST_SUITE(harness_jacobians)

BOOST_AUTO_TEST_CASE(static_jacobians_match_central_differences_for_every_combination) {
    for_each_combination([]<Formulation F, class P>(const comb::Combination& c) {
        if constexpr (F == Formulation::displacement) {
            check_displacement_statics<P>(c);
        } else {
            check_mixed_statics<P>(c);
        }
    });
}

BOOST_AUTO_TEST_CASE(dynamic_jacobians_match_central_differences_for_every_combination) {
    for_each_combination([]<Formulation F, class P>(const comb::Combination& c) {
        static_assert(comb::traits(F).dynamics, "every formulation has a dynamic analysis");
        if constexpr (F == Formulation::displacement) {
            check_displacement_dynamics<P>(c);
        } else {
            check_mixed_dynamics<P>(c);
        }
    });
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace rotbeam::test
