// The parts of the mixed dynamics (mixed_dynamics.hpp) that do not depend on the parameterization,
// beyond the element (mixed_dynamic_element.hpp): loads in time, the section masses and their
// inverses (seed 002 Eq. 18) and the scales of the momentum unknowns and rows. Also used by the
// statics' solver.assemble_all_terms (mixed_statics_rest_terms.hpp).
#pragma once

#include <vector>

#include "core/model.hpp"
#include "formulations/mixed/mixed_damping.hpp"
#include "formulations/mixed/mixed_layout.hpp"

namespace rotbeam::form {

// The model without its distributed loads: build_mixed_layout then folds only gravity into the
// elements, and the dynamics add the distributed loads with their time functions.
Model without_distributed_loads(Model m);

// Energies and angular momentum of a mixed dynamic state (MixedDynamics<P>::energy).
struct MixedEnergy {
    double kinetic = 0.0;
    double strain = 0.0;
    Vec3 angular_momentum = Vec3::Zero();
    double total() const { return kinetic + strain; }
};

// Every element's stiffness-proportional damping (mixed_damping.hpp): μ at mid-length, linear
// between stations, and C* = S⁻¹ (the stiffness linear between stations, mixed_layout.cpp). Throws
// InputError when a damped element's compliance is singular (a rigid component has no strain rate
// to damp).
std::vector<MixedDampingSection> mixed_damping_sections(const Model& model,
                                                        const MixedLayout& layout);

// Throws InputError when a section carries damping: the mixed modal analysis is undamped, and
// refusing beats ignoring the input.
void refuse_mixed_modal_damping(const Model& model);

// A time function at t. Tables and ramps may jump at the start (a release: 1 → 0 within 1e-12 s);
// they are evaluated at their right limit there, max(t, floor). Sines and constants are continuous
// and evaluated at t.
double mixed_time_value(const TimeFunction& f, double t, double floor);

// The element with its distributed loads at time t (Eqs. 51–54, constant per length); gravity is
// already in the layout's f_dead.
MixedElement mixed_loaded_element(const Model& model, const MixedElement& element, double t,
                                  double floor);

// The inverse of every element's section mass I (Eq. 18 is inverted: [V; Ω] = I⁻¹ [P; H]) and the
// largest mass per length and rotary inertia (the momentum scales). Throws InputError when a
// section has no mass or a singular one.
struct MixedMassInverses {
    std::vector<Mat6> inverse;
    double mass_scale = 0.0;
    double inertia_scale = 0.0;
};
MixedMassInverses mixed_mass_inverses(const Model& model, const MixedLayout& layout);

// The section mass I (material axes) of an element, by discretization.mass_rule: `midpoint` the
// mid-length value (seed 002's GEBT), `consistent` the average over the element (the consistent
// mass of the element's constant momenta; equal to midpoint for a section constant along the
// element, every shipped case), `lumped` refused (no nodal masses). Linear between stations.
// Throws InputError when the member's sections carry no mass.
Mat6 mixed_element_mass(const Model& model, const MixedElement& element);

}  // namespace rotbeam::form
