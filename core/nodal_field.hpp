// A solved static state as a field along the members, and a load path of them: what a run of one
// discretization hands to the next run of the same model on another discretization (the accuracy
// control's warm start, docs/accuracy-control.md "Warm start"). The field keeps each element's
// nodes with their arc lengths, displacements and rotation parameters, so that the receiving
// formulation evaluates the old discrete solution at its own nodes through the old element's
// shape functions and its own rotation interpolation (StaticProblem::start_from).
#pragma once

#include <string>
#include <vector>

#include "core/types.hpp"

namespace rotbeam {

struct NodalField {
    struct Element {
        int member = -1;             // index into Model::members
        std::vector<double> node_s;  // arc lengths of its nodes along the member, increasing
        std::vector<Vec3> displacement;
        std::vector<VecX> rotation;  // the nodal parameters of `parameterization`
    };
    std::string parameterization;  // the parameterization's name (the parameters' meaning)
    bool relative = true;          // the rotation interpolation that produced it
    std::vector<Element> elements;
};

// The reported steps of a solved static run: the load factor and the field of each.
struct SolvedPath {
    std::vector<double> load_factors;
    std::vector<NodalField> states;
};

}  // namespace rotbeam
