// Mixed-integration-point (MIP) Newton for the displacement statics (solver.mip; Magisano,
// Leonetti & Garcea, "How to improve efficiency and robustness of the Newton method in
// geometrically nonlinear structural problems discretized via displacement-based finite
// elements", CMAME 313, 2017). The discrete equations and their solution are the displacement
// formulation's; only the Newton iteration changes.
//
// Why: from a straight beam, the first Newton step of a large load rotates the sections by the
// linearized rotation but moves the nodes along the linearized displacement, so the next state
// carries an axial strain of order θ²/2 and a spurious axial force EA θ²/2 (EA/EI ~ 1e3 … 1e6).
// Standard Newton then builds its geometric stiffness from that force and wanders: ~40 iterations
// for the roll-up to λ = 2 or the 45° bend, against 4 for the mixed formulation, whose resultants
// are unknowns of their own.
//
// The MIP iteration treats the section resultants σ* at every quadrature point (material axes) as
// independent variables of the Hellinger–Reissner pair  ∫ Bᵀ(d) σ = f,  C*⁻¹σ* = ε*(d)  and
// condenses them out point by point. Newton on the pair gives
//   (K_G(σ̂) + Bᵀ C B) Δd = −r(d)         (the standard residual, the standard material part)
//   σ̂*⁺ = σ*(d) + C* δε*(Δd)              (the stresses the linearization predicts)
// i.e. the standard Jacobian with its stress-linear (geometric) part evaluated with σ̂ = Q σ̂*
// instead of σ(d) = C e(d). Both blocks of calculate_stiffness_blocks are linear in the force,
// so passing σ̂ there is the whole change of the Jacobian. In inertial components the predicted
// increment is δF = C [δu′ + x̃p δψ; δκ + κ̃ δψ] (the material part of δF^E1,
// calculate_stiffness_blocks.hpp), stored per quadrature point and node as S_b with
// δF = Σ_b S_b [Δu_b; Δψ_b].
//
// At a solution σ̂ = σ(d) to second order in the last increment, so convergence stays quadratic.
// σ̂ is known only right after a Newton update from a state whose Jacobian (and the maps S) was
// assembled; after a load change, a restore to another state or a retraction from a state the
// maps do not belong to, σ̂ is dropped and the next Jacobian is the standard one.
#pragma once

#include <array>
#include <vector>

#include "core/nonlinear_system.hpp"
#include "core/types.hpp"
#include "formulations/displacement/mesh.hpp"

namespace rotbeam::form {

class MipStresses {
  public:
    // Sizes the store for the mesh (enabled = solver.mip).
    void setup(const Mesh& mesh, bool enabled);
    bool enabled() const { return enabled_; }
    int first_point(int element) const { return first_point_[static_cast<size_t>(element)]; }

    // The resultants the geometric stiffness is built from at point g: Q σ̂* when σ̂ is known,
    // else the true F^E1 of the state.
    Vec6 geometric_force(int g, const Mat3& Q, const Vec6& FE1) const;
    // Records what the update needs at point g while the Jacobian is assembled: Q = R R^r, the
    // true F^E1, and δF^E1 maps S_b = [C_:,0:3 N_b′, C_:,3:6 K_b + Cx A_b] of its nn nodes
    // (Cx = C_:,0:3 x̃p + C_:,3:6 κ̃).
    void record(int g, const Mat3& Q, const Vec6& FE1, int b, const Mat6& S_b) {
        Q_[static_cast<size_t>(g)] = Q;
        F_[static_cast<size_t>(g)] = FE1;
        S_[static_cast<size_t>(g) * nn_ + static_cast<size_t>(b)] = S_b;
    }
    // The Jacobian assembly recorded the maps of the current state.
    void maps_recorded() { maps_id_ = state_id_; }

    // The state moves by dx (node layout of the mesh): σ̂* is predicted when the maps belong to
    // the state being left, dropped otherwise.
    void retract(const Mesh& mesh, const Eigen::Ref<const VecX>& dx);
    // The state changed in a way the maps do not follow (load factor, prescribed motion).
    void drop();
    void save(int slot);
    void restore(int slot);

  private:
    bool enabled_ = false;
    bool known_ = false;  // σ̂ holds a prediction for the current state
    size_t nn_ = 0;       // nodes per element
    std::vector<int> first_point_;
    std::vector<Vec6> sigma_;  // σ̂*, material axes
    std::vector<Mat3> Q_;
    std::vector<Vec6> F_;
    std::vector<Mat6> S_;
    long state_id_ = 0, maps_id_ = -1, next_id_ = 1;
    std::array<std::vector<Vec6>, NonlinearSystem::kCheckpointSlots> saved_sigma_;
    std::array<bool, NonlinearSystem::kCheckpointSlots> saved_known_{};
    std::array<long, NonlinearSystem::kCheckpointSlots> saved_id_{};
};

}  // namespace rotbeam::form
