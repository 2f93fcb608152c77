// The manufactured solution of the semi-discrete equations: given a trajectory y_h(t) of a mesh's
// unknowns (any smooth motion, with its exact rates), the forcing −R_h(t, y_h(t), ẏ_h(t), ÿ_h(t))
// added to the discrete residual makes y_h(t) an exact solution of the discrete system. Started at
// y_h(0), a time integrator's error against y_h(t_n) is then purely temporal, and the start is
// consistent (for a DAE: with its algebraic unknowns, at its index) — unlike the exact continuum
// motion, whose start carries the space error and excites the mesh's stiff modes (docs/studies.md
// "Manufactured motion").
//
// Two decorators on the time integrators' problem interfaces, so every integrator runs unchanged:
//  - ForcedDae (core/dae_system.hpp): F(t, X, Ẋ) − F(t, y_h(t), ẏ_h(t)); its Jacobians are F's;
//  - ForcedCollocation<D> (core/gauss_collocation.hpp, hence generalized-α too): r(q, v, v˙, t) −
//    r_h(t), r_h(t) the residual of the same mesh at (q_h(t), v_h(t), v˙_h(t)), given by the caller
//    (a second problem set to that state). The consistent start acceleration, M v˙ = −r(q, v, 0, t)
//    + r_h(t), is the inner problem's plus the correction M⁻¹ (r_h − r(q, v, v˙_inner, t)) (one
//    linear solve: r is linear in v˙ with matrix M). D provides set_node_acceleration (v˙ and the
//    generalized-α pseudo-acceleration a of a node) and mesh(), as DisplacementDynamics does. The
//    forcing does work that the energy balance does not see, so it has none (energy_terms false).
// The forcing is computed once per distinct time (stages repeat their times over the stage
// iterations): ForcingCache keeps the last few.
#pragma once

#include <array>
#include <functional>
#include <utility>

#include "core/dae_system.hpp"
#include "core/errors.hpp"
#include "core/gauss_collocation.hpp"
#include "core/sparse_lu.hpp"

namespace rotbeam::cli {

// r_h(t) by `compute`, kept for the last kSlots distinct times.
class ForcingCache {
  public:
    explicit ForcingCache(std::function<void(double t, VecX& r)> compute)
        : compute_(std::move(compute)) {}
    const VecX& at(double t) {
        for (size_t i = 0; i < kSlots; ++i) {
            if (filled_[i] && times_[i] == t) return values_[i];
        }
        next_ = (next_ + 1) % kSlots;
        compute_(t, values_[next_]);
        times_[next_] = t;
        filled_[next_] = true;
        return values_[next_];
    }

  private:
    static constexpr size_t kSlots = 8;  // ≥ the stages of a step and its neighbours
    std::function<void(double, VecX&)> compute_;
    std::array<double, kSlots> times_{};
    std::array<VecX, kSlots> values_;
    std::array<bool, kSlots> filled_{};
    size_t next_ = 0;
};

class ForcedDae : public DaeSystem {
  public:
    ForcedDae(DaeSystem& inner, ForcingCache& forcing) : inner_(inner), forcing_(forcing) {}
    int size() const override { return inner_.size(); }
    void evaluate(double t, const VecX& x, const VecX& xdot, VecX& residual, SparseMatrix* J_x,
                  SparseMatrix* J_xdot) override {
        const VecX& f = forcing_.at(t);  // before: it evaluates the inner system itself
        inner_.evaluate(t, x, xdot, residual, J_x, J_xdot);
        residual -= f;
    }
    const SparseMatrix& pattern() const override { return inner_.pattern(); }
    const VecX& differential() const override { return inner_.differential(); }
    VecX initial_condition_differential(const VecX& x) const override {
        return inner_.initial_condition_differential(x);
    }
    void complete_initial_rates(const VecX& x, VecX& xdot) const override {
        inner_.complete_initial_rates(x, xdot);
    }
    const VecX& configuration() const override { return inner_.configuration(); }
    const VecX& residual_scale() const override { return inner_.residual_scale(); }
    const VecX& state_scale() const override { return inner_.state_scale(); }
    const VecX& increment_scale() const override { return inner_.increment_scale(); }
    AssemblyCounters counters() const override { return inner_.counters(); }
    std::string describe_state(const VecX& x) const override { return inner_.describe_state(x); }

  private:
    DaeSystem& inner_;
    ForcingCache& forcing_;
};

template <class D>
class ForcedCollocation : public CollocationProblem {
  public:
    ForcedCollocation(D& inner, ForcingCache& forcing) : inner_(inner), forcing_(forcing) {}

    int size() const override { return inner_.size(); }
    void evaluate(VecX& residual, SparseMatrix* jacobian) override {
        const VecX& f = forcing_.at(time_);
        inner_.evaluate(residual, jacobian);
        residual -= f;
    }
    void retract(const Eigen::Ref<const VecX>& dx) override { inner_.retract(dx); }
    void save_state(int slot) override { inner_.save_state(slot); }
    void restore_state(int slot) override { inner_.restore_state(slot); }
    const VecX& residual_scale() const override { return inner_.residual_scale(); }
    const VecX& increment_scale() const override { return inner_.increment_scale(); }
    std::string describe_state() const override { return inner_.describe_state(); }

    void initialize_acceleration(double t) override {
        inner_.initialize_acceleration(t);
        VecX v, v_dot, r;
        inner_.start_rates(v, v_dot);
        const VecX zero = VecX::Zero(size());
        inner_.stage_matrices(zero, v, v_dot, t, r, K_, C_, M_);
        r -= forcing_.at(t);
        if (!mass_lu_.factorize(M_)) {
            throw SolverError("forced initial acceleration: the mass matrix is singular");
        }
        VecX correction;
        mass_lu_.solve(r, correction);
        v_dot -= correction;
        for (size_t i = 0; i < inner_.mesh().nodes.size(); ++i) {
            const int d = inner_.mesh().nodes[i].dof;
            if (d >= 0)
                inner_.set_node_acceleration(static_cast<int>(i), v_dot.template segment<6>(d));
        }
        time_ = t;
    }
    void begin_step(double t_next, double h, const GeneralizedAlpha& scheme) override {
        inner_.begin_step(t_next, h, scheme);
        time_ = t_next;
    }
    void end_step() override { inner_.end_step(); }
    double acceleration_change(double length) const override {
        return inner_.acceleration_change(length);
    }
    bool energy_terms(EnergyTerms& /*terms*/) override { return false; }

    void start_rates(VecX& v, VecX& v_dot) const override { inner_.start_rates(v, v_dot); }
    void set_start_acceleration(const Eigen::Ref<const VecX>& v_dot) override {
        inner_.set_start_acceleration(v_dot);
    }
    void set_stage(const Eigen::Ref<const VecX>& delta, const Eigen::Ref<const VecX>& v,
                   const Eigen::Ref<const VecX>& v_dot, double t, double c_v, double c_a) override {
        inner_.set_stage(delta, v, v_dot, t, c_v, c_a);
        time_ = t;
    }
    void stage_matrices(const Eigen::Ref<const VecX>& delta, const Eigen::Ref<const VecX>& v,
                        const Eigen::Ref<const VecX>& v_dot, double t, VecX& r, SparseMatrix& K,
                        SparseMatrix& C, SparseMatrix& M) override {
        const VecX& f = forcing_.at(t);
        inner_.stage_matrices(delta, v, v_dot, t, r, K, C, M);
        r -= f;
        time_ = t;
    }
    void velocity_of_rate(const Eigen::Ref<const VecX>& delta, const Eigen::Ref<const VecX>& w,
                          Eigen::Ref<VecX> v) const override {
        inner_.velocity_of_rate(delta, w, v);
    }
    void keep_start(int slot) override { inner_.keep_start(slot); }
    void restore_start(int slot) override { inner_.restore_start(slot); }
    double distance_from_kept(int slot, double length) const override {
        return inner_.distance_from_kept(slot, length);
    }

  private:
    D& inner_;
    ForcingCache& forcing_;
    double time_ = 0.0;  // the load time of the inner problem's iterate
    SparseMatrix K_, C_, M_;
    SparseLUSolver mass_lu_{SparseLUSolver::Kind::klu_refactor};
};

}  // namespace rotbeam::cli
