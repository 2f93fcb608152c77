// The linearization order check of the displacement statics' exact consistent Jacobian at the
// strongly deformed state of deformed.hpp (the column-by-column check against central differences,
// for every combination, is the generic harness's: tests/harness/test_jacobians.cpp).
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <iostream>

#include "deformed.hpp"
#include "formulations/displacement/displacement_statics.hpp"
#include "tests/harness/jacobian_check.hpp"

using namespace rotbeam;
using Statics = form::DisplacementStatics<param::Quaternion>;

namespace {

constexpr int kBase = 0;  // checkpoint slot holding the deformed state

// Deformed problem at load factor 1 with its state saved in kBase.
template <class S>
void deform(S& s) {
    s.set_load_factor(1.0);
    s.retract(test::deforming_increment(s.mesh()));
    s.save_state(kBase);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(displacement_jacobian)

// ‖r(x ⊕ h d) − r(x) − h J d‖ falls 4× when h halves (second-order remainder): the Jacobian is
// the derivative through the retraction, not an approximation of it.
BOOST_AUTO_TEST_CASE(linearization_remainder_is_second_order) {
    Statics s(test::curved_twisted(2, 4, true, true));
    deform(s);
    VecX r0;
    SparseMatrix J;
    s.evaluate(r0, &J);
    VecX d(s.size());
    for (int i = 0; i < s.size(); ++i) d[i] = std::sin(1.0 + 2.3 * i) * s.increment_scale()[i];
    const VecX Jd = J * d;
    double previous = 0.0;
    for (int k = 0; k < 5; ++k) {
        const double h = 1e-2 / std::pow(2.0, k);
        const double e = (test::residual_after_retraction(s, kBase, h * d) - r0 - h * Jd).norm();
        if (k > 0) {
            const double ratio = previous / e;
            std::cout << "h = " << h << ": remainder " << e << ", ratio " << ratio << '\n';
            BOOST_TEST(ratio > 3.6);
            BOOST_TEST(ratio < 4.4);
        }
        previous = e;
    }
}

BOOST_AUTO_TEST_SUITE_END()
