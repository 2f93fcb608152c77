// When the stage iterations keep their factored matrices (core/stage_iteration.hpp,
// KeptMatrices): the two rules decide on the sequences of iteration counts and contraction
// factors they are given, the step-size test refuses another step, and fresh_cost ≤ 0 never keeps.
// The expected decisions are worked out by hand from each rule's definition in the comments.
#include <boost/test/unit_test.hpp>

#include "core/stage_iteration.hpp"

using rotbeam::KeptMatrices;
using rotbeam::KeptMatrixRule;

BOOST_AUTO_TEST_SUITE(kept_matrices)

// Renewal with fresh matrices costing 8 iterations. A fresh step of 3 iterations: the cycle has
// cost 11 over 1 step, and 3 < 11 keeps. Kept steps of 3, 4, 4: averages 14/2, 18/3, 22/4 = 5.5,
// each step below its average keeps. A kept step of 6: the cycle's 28 over 5 steps is 5.6, and
// 6 ≥ 5.6 renews. Fresh matrices again start a new cycle (3 < 11 keeps).
BOOST_AUTO_TEST_CASE(renewal_keeps_while_the_last_step_costs_less_than_the_cycles_average) {
    KeptMatrices kept(8.0, KeptMatrixRule::renewal);
    const double h = 1e-3;
    BOOST_TEST(!kept.usable(h));  // nothing factored yet
    kept.made(h);
    kept.converged(3, 0.5, true);
    BOOST_TEST(kept.usable(h));
    for (const int iterations : {3, 4, 4}) {
        kept.converged(iterations, 0.5, false);
        BOOST_TEST(kept.usable(h), "after a kept step of " << iterations);
    }
    kept.converged(6, 0.5, false);
    BOOST_TEST(!kept.usable(h));
    kept.made(h);
    kept.converged(3, 0.5, true);
    BOOST_TEST(kept.usable(h));
}

// A step exactly at the average renews (the next step is expected to cost at least as much, so
// keeping no longer lowers the average): fresh 2 + 2 iterations, then a kept step of 2 makes the
// cycle 6 over 2 steps, average 3; a kept step of 3 makes it 9 over 3, average 3, and 3 ≥ 3.
BOOST_AUTO_TEST_CASE(renewal_renews_at_the_average) {
    KeptMatrices kept(2.0, KeptMatrixRule::renewal);
    const double h = 1e-3;
    kept.made(h);
    kept.converged(2, 0.0, true);
    kept.converged(2, 0.0, false);
    BOOST_TEST(kept.usable(h));
    kept.converged(3, 0.0, false);
    BOOST_TEST(!kept.usable(h));
}

// The contraction rule looks at the worst ratio alone: 0.05 keeps, 0.051 does not, whatever the
// iteration counts.
BOOST_AUTO_TEST_CASE(contraction_keeps_while_the_worst_ratio_is_small) {
    KeptMatrices kept(3.0, KeptMatrixRule::contraction);
    const double h = 1e-3;
    kept.made(h);
    kept.converged(3, 0.05, true);
    BOOST_TEST(kept.usable(h));
    kept.converged(20, 0.05, false);
    BOOST_TEST(kept.usable(h));
    kept.converged(3, 0.051, false);
    BOOST_TEST(!kept.usable(h));
}

// Both rules refuse a step size more than 1e-6 (relative) from the factored one, and never keep
// with fresh_cost ≤ 0 (fresh matrices at every step).
BOOST_AUTO_TEST_CASE(another_step_size_or_no_fresh_cost_refuses) {
    for (const KeptMatrixRule rule : {KeptMatrixRule::contraction, KeptMatrixRule::renewal}) {
        KeptMatrices kept(8.0, rule);
        kept.made(1e-3);
        kept.converged(3, 0.0, true);
        BOOST_TEST(kept.usable(1e-3 * (1.0 + 0.9e-6)));
        BOOST_TEST(!kept.usable(1e-3 * (1.0 + 1.1e-6)));
        kept.made(0.0);
        BOOST_TEST(!kept.usable(1e-3));
        KeptMatrices never(0.0, rule);
        never.made(1e-3);
        never.converged(3, 0.0, true);
        BOOST_TEST(!never.usable(1e-3));
    }
}

BOOST_AUTO_TEST_SUITE_END()
