// Case loader: lengths and places that double arithmetic cannot resolve (docs/case-format.md,
// "Geometry that double precision resolves").
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

#include "cases/loader/model_builder.hpp"
#include "core/geometry.hpp"

namespace rotbeam::cases {

namespace {

// √ε: a length at least this fraction of the coordinates it is computed from keeps at least half
// of a double's 16 digits (each coordinate is rounded to ε/2 of its magnitude; a node's reference
// position x₀ + s·d too), so a strain formed from node positions is not round-off of them.
const double kRelativeLength = std::sqrt(std::numeric_limits<double>::epsilon());
// √DBL_MIN ≈ 1.5e-154: the element kernels form squared lengths (norms of chords and tangents)
// and divide section entries by the element length; below it the square leaves the normal double
// range, and a section entry of at most √DBL_MAX (the section check) divided by it stays finite.
// Measured (tip-load cantilever, 8 elements, displacement formulation): exact to round-off for
// elements down to 1.25e-154, `error` (non-finite values) at 1.25e-155.
const double kSmallestLength = std::sqrt(std::numeric_limits<double>::min());

double largest_coordinate(const Vec3& a, const Vec3& b) {
    return std::max(a.cwiseAbs().maxCoeff(), b.cwiseAbs().maxCoeff());
}

// The shortest length a member's element or the distance between two points may have, next to
// points whose largest coordinate magnitude is `coordinate`.
double shortest_length(double coordinate) {
    return std::max(kSmallestLength, kRelativeLength * coordinate);
}

// Why a length below shortest_length(coordinate) is refused, with what to do.
std::string why_unresolved(double coordinate) {
    std::ostringstream s;
    s.precision(3);
    if (kRelativeLength * coordinate <= kSmallestLength) {
        s << "sqrt of the smallest normal double, where the squared lengths the element kernels "
             "form underflow: use units in which the beam is larger";
    } else {
        s << "sqrt(eps) = " << kRelativeLength << " of the largest coordinate " << coordinate
          << ", where rounding the coordinates leaves it less than half of its digits: move the "
             "origin nearer the beam";
    }
    return s.str();
}

// Eigen's norm squares the components first: two points 1e-160 apart would be 0 apart.
double distance(const Vec3& a, const Vec3& b) { return (a - b).stableNorm(); }

}  // namespace

std::string element_length_problem(const Model& model, const Member& member, double length) {
    const double element = length / member.elements;
    const double coordinate =
        largest_coordinate(model.points[static_cast<size_t>(member.start_point)].position,
                           model.points[static_cast<size_t>(member.end_point)].position);
    const double shortest = shortest_length(coordinate);
    if (element >= shortest) return "";
    std::ostringstream s;
    s.precision(3);
    s << "length " << length << " in " << member.elements << " element(s) of " << element
      << ", below " << shortest << " (" << why_unresolved(coordinate) << ", or use fewer elements)";
    return s.str();
}

double chord_length(const Model& model, const Member& member) {
    return distance(model.points[static_cast<size_t>(member.start_point)].position,
                    model.points[static_cast<size_t>(member.end_point)].position);
}

void check_distinct_points(const YamlReader& r, const YAML::Node& root, const Model& model) {
    // Candidates by their x coordinate (no pair farther apart in x than the largest length the
    // test can refuse), so that a file of many points is not checked pair by pair.
    double widest = kSmallestLength;
    for (const Point& p : model.points)
        widest = std::max(widest, kRelativeLength * p.position.cwiseAbs().maxCoeff());
    std::vector<size_t> order(model.points.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = i;
    const auto x = [&](size_t i) { return model.points[i].position.x(); };
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return x(a) < x(b); });
    for (size_t k = 0; k < order.size(); ++k) {
        for (size_t l = k + 1; l < order.size() && x(order[l]) - x(order[k]) <= widest; ++l) {
            const size_t i = std::min(order[k], order[l]), j = std::max(order[k], order[l]);
            const Vec3& a = model.points[i].position;
            const Vec3& b = model.points[j].position;
            const double coordinate = largest_coordinate(a, b);
            const double apart = distance(a, b);
            if (apart >= shortest_length(coordinate)) continue;
            std::ostringstream s;
            s.precision(3);
            s << "at the place of points." << model.points[i].name << " (";
            if (apart == 0.0) {
                s << "the same coordinates";
            } else {
                s << apart << " apart, below " << shortest_length(coordinate) << ": "
                  << why_unresolved(coordinate);
            }
            s << "); distinct points are never joined: members meet at a point they share, so "
                 "name it once";
            r.fail(root["points"][model.points[j].name], "points." + model.points[j].name, s.str());
        }
    }
}

}  // namespace rotbeam::cases
