// Lagrange interpolation on arbitrary distinct nodes (GLL nodes for the spectral elements), in the
// barycentric form (Berrut & Trefethen 2004), which is stable for high orders.
#pragma once

#include <vector>

#include "core/types.hpp"

namespace rotbeam {

class LagrangeBasis {
public:
    explicit LagrangeBasis(std::vector<double> nodes);

    int size() const { return static_cast<int>(nodes_.size()); }
    const std::vector<double>& nodes() const { return nodes_; }

    // N_i(x) for all i.
    void values(double x, Eigen::Ref<VecX> out) const;
    // dN_i/dx for all i.
    void derivatives(double x, Eigen::Ref<VecX> out) const;

private:
    std::vector<double> nodes_;
    std::vector<double> bary_;  // barycentric weights
};

}  // namespace rotbeam
