// The mechanical energy balance of a time integration, checked after every accepted step so that a
// run whose energy grows without a cause stops and says so, at the step where the growth starts,
// instead of running on until Newton fails at a state that has no physical meaning.
//
// For the exact motion of a beam, E(t) − E(t₀) = W(t) − D(t): E the kinetic plus strain energy, W
// the work of the external loads, D the energy the damping law dissipated (≥ 0). The discrete work
// of a step is W_{n+1} − W_n = ½ (f_n + f_{n+1}) · Δx with Δx = ½ h (v_n + v_{n+1}): for the
// trapezoidal rule (generalized-α at ρ∞ = 1) on a linear system this is exactly the energy change
// of the step (Newmark β = ¼, γ = ½: u_{n+1} − u_n = ½ h (v_n + v_{n+1}) and E is a quadratic
// form), so the defect
//     δ_n = E_n − E_0 − W_n + D_n
// is zero there up to the Newton tolerance at any step size. A geometrically non-linear motion
// leaves δ = O(h²) of the energy moved; numerical dissipation (ρ∞ < 1) makes δ negative. D is
// integrated by the trapezoidal rule of the dissipated power (≥ the discrete dissipation of a
// linear damper, so δ is, if anything, overstated by O(h²)).
//
// The run stops when δ exceeds kGrowth of the energy the loads and the damping moved,
//     S_n = E_0 + Σ |ΔW| + D_n,
// i.e. when the scheme has created more energy than the loads ever put in: not a discretization
// error of a stable run (measured: docs/displacement-dynamics.md, "Energy balance"). The message
// names that step and the first step from which δ stayed above kOnset S, where the growth starts.
#pragma once

#include <cmath>
#include <sstream>
#include <string>

#include "core/types.hpp"

namespace rotbeam {

// What a problem reports for the balance at its current (accepted) state: the energy, the external
// load vector and the velocity in the unknowns' numbering (force and moment rows against the
// translation and spatial angular velocity rows), and the power the damping dissipates.
struct EnergyTerms {
    double energy = 0.0;
    VecX load, velocity;
    double dissipation = 0.0;
    // A potential energy counted in `energy` with a minus sign whose changes are energy moved, like
    // the loads' work (the centrifugal potential of a rotating frame, whose energy is the Jacobi
    // integral; 0 otherwise): energy + potential at the start and Σ |Δ potential| join the scale.
    double potential = 0.0;
};

class EnergyBalance {
  public:
    static constexpr double kGrowth = 1.0;
    static constexpr double kOnset = 0.01;

    void start(const EnergyTerms& e) {
        e0_ = e.energy;
        scale_ = e.energy + e.potential;
        last_potential_ = e.potential;
        last_load_ = e.load;
        last_velocity_ = e.velocity;
        last_dissipation_ = e.dissipation;
    }
    // After the accepted step `step` of size h to time t; true when the energy grows (δ > kGrowth
    // S).
    bool add(const EnergyTerms& e, long step, double t, double h) {
        double dw = 0.0;
        for (Eigen::Index i = 0; i < e.load.size(); ++i) {
            dw += 0.25 * h * (last_load_[i] + e.load[i]) * (last_velocity_[i] + e.velocity[i]);
        }
        work_ += dw;
        const double dd = 0.5 * h * (last_dissipation_ + e.dissipation);
        dissipated_ += dd;
        scale_ += std::abs(dw) + std::abs(dd) + std::abs(e.potential - last_potential_);
        last_potential_ = e.potential;
        last_load_ = e.load;  // same size every step: no allocation
        last_velocity_ = e.velocity;
        last_dissipation_ = e.dissipation;
        energy_ = e.energy;
        defect_ = e.energy - e0_ - work_ + dissipated_;
        if (defect_ <= kOnset * scale_) {
            onset_step_ = -1;
        } else if (onset_step_ < 0) {
            onset_step_ = step;
            onset_time_ = t;
        }
        return std::isfinite(defect_) && defect_ > kGrowth * scale_;
    }
    std::string describe(long step, double t) const {
        std::ostringstream s;
        s.precision(4);
        s << "energy growth at time step " << step << " (t = " << t
          << "): E − E0 − W + D = " << defect_
          << " J exceeds the energy the loads and damping moved (E0 + Σ|ΔW| + D = " << scale_
          << " J; E = " << energy_ << " J, E0 = " << e0_ << " J, W = " << work_
          << " J, D = " << dissipated_ << " J); the growth starts at time step " << onset_step_
          << " (t = " << onset_time_ << ", the imbalance above " << kOnset
          << " of that energy from there on)";
        return s.str();
    }

  private:
    double e0_ = 0.0, work_ = 0.0, dissipated_ = 0.0, scale_ = 0.0, energy_ = 0.0, defect_ = 0.0;
    double last_dissipation_ = 0.0, last_potential_ = 0.0, onset_time_ = 0.0;
    long onset_step_ = -1;
    VecX last_load_, last_velocity_;
};

}  // namespace rotbeam
