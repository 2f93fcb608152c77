// Quadrature rules on [−1, 1].
//
// Gauss–Legendre nodes and weights come from GSL's fixed tables, polished by Newton on P_n (exact
// for polynomials of degree 2n − 1). Gauss–Lobatto–Legendre (GLL) nodes are ±1 and the roots of
// P′_{n−1}, found by Newton on GSL's Legendre polynomials; weights 2 / (n(n−1) P_{n−1}(x)²); exact
// for degree 2n − 3.
#pragma once

#include <vector>

namespace rotbeam {

struct QuadratureRule {
    std::vector<double> points;   // ascending, in [−1, 1]
    std::vector<double> weights;  // sum to 2
};

QuadratureRule gauss_legendre(int n);          // n ≥ 1
QuadratureRule gauss_lobatto_legendre(int n);  // n ≥ 2
// `breaks` ascending from −1 to 1 (at least two); refine ≥ 1.
QuadratureRule trapezoidal(const std::vector<double>& breaks, int refine);

}  // namespace rotbeam
