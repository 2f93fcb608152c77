#include "core/static_driver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <ostream>
#include <sstream>

#include "core/errors.hpp"
#include "core/potential_hessian.hpp"
#include "core/sparse_lu.hpp"
#include "core/static_stability_kinetic.hpp"
#include "core/time_limit.hpp"

namespace rotbeam {

const char* to_string(SolveStatus s) {
    switch (s) {
        case SolveStatus::converged:
            return "converged";
        case SolveStatus::stalled_at_round_off:
            return "stalled-at-round-off";
        case SolveStatus::diverged:
            return "diverged";
        case SolveStatus::singular:
            return "singular";
        case SolveStatus::error:
            return "error";
    }
    return "error";
}

std::ostream& operator<<(std::ostream& os, SolveStatus s) { return os << to_string(s); }

bool has_solution(SolveStatus s) {
    return s == SolveStatus::converged || s == SolveStatus::stalled_at_round_off;
}

bool has_solution(const std::string& status) {
    return status == to_string(SolveStatus::converged) ||
           status == to_string(SolveStatus::stalled_at_round_off);
}

NewtonSettings newton_settings_from(const SolverSettings& solver, const StaticSettings& statics) {
    NewtonSettings s;
    s.residual_tolerance = solver.residual_tolerance.value_or(s.residual_tolerance);
    s.increment_tolerance = solver.increment_tolerance.value_or(s.increment_tolerance);
    s.max_iterations = solver.max_iterations;
    s.line_search = solver.line_search;
    s.max_step_cuts = statics.max_step_cuts;
    s.substeps = std::max(1, statics.substeps);
    s.dense_linear_solver = solver.linear_solver == LinearSolver::dense;
    return s;
}

namespace {

// Root-mean-square of v_i / scale_i (the increment norm of the monotonicity test).
double scaled_rms(const VecX& v, const VecX& scale) {
    return std::sqrt((v.array() / scale.array()).square().mean());
}

// Damping along the retraction by Deuflhard's natural monotonicity test (NLEQ-ERR): a trial
// x ⊕ α δ is accepted when the simplified Newton correction there, δ̄ = −J(x)⁻¹ r(x ⊕ α δ)
// (the factorization is reused), is smaller than the Newton correction: ‖δ̄‖ ≤ (1 − α/4)‖δ‖.
// Unlike a residual-norm (Armijo) test this is affine invariant: it does not depend on how force
// and moment rows are scaled, which is what made a residual test stall on the roll-up (moment
// rows dominate after a large rotation). α starts from min(1, 4 α_previous) and is halved; a
// parameterization refusing x ⊕ α δ counts as a failed trial. Returns the accepted α or 0.
//
// The simplified correction misjudges a good full step when J changes fast along it: with a
// stiff axial row (EA/EI ~ 1e4, the precessing helix) a rotation increment makes an axial residual
// of order EA·θ² that the old J answers with a large δ̄ although the true Newton correction
// −J(x ⊕ δ)⁻¹ r is tiny. So when the first trial (α = α_start) fails the simplified test, the same
// test is made with the true correction (one more Jacobian, kept for the next iteration). On the
// precessing helix this takes the iterations per load step from 20–170 to 4–10.
struct DampingWork {
    explicit DampingWork(SparseLUSolver::Kind kind) : lu_trial(kind) {}
    VecX r_trial, dx_bar;
    VecX step;  // α δ: a named vector, since Ref<const VecX> of an expression is a heap temporary
    SparseMatrix J_trial;
    SparseLUSolver lu_trial;
    bool trial_jacobian_ready = false;  // J_trial, r_trial belong to the accepted state
};

bool exact_correction_accepts(NonlinearSystem& system, DampingWork& w, const VecX& xscale,
                              double limit) {
    system.evaluate(w.r_trial, &w.J_trial);
    if (!w.r_trial.allFinite()) return false;
    if (!w.lu_trial.factorize(w.J_trial)) return false;
    w.lu_trial.solve(w.r_trial, w.dx_bar);
    w.dx_bar *= -1.0;
    const double norm = scaled_rms(w.dx_bar, xscale);
    w.trial_jacobian_ready = std::isfinite(norm) && norm <= limit;
    return w.trial_jacobian_ready;
}

double damped_step(NonlinearSystem& system, SparseLUSolver& lu, const VecX& dx, const VecX& xscale,
                   double alpha_start, DampingWork& w, bool& saw_singular) {
    constexpr double kMinAlpha = 1.0 / 8192.0;
    const double norm_dx = scaled_rms(dx, xscale);
    w.trial_jacobian_ready = false;
    system.save_state(NonlinearSystem::kLineSearchSlot);
    for (double alpha = alpha_start; alpha >= kMinAlpha; alpha *= 0.5) {
        try {
            w.step = alpha * dx;
            system.retract(w.step);
            system.evaluate(w.r_trial, nullptr);
            if (w.r_trial.allFinite()) {
                const double limit = (1.0 - 0.25 * alpha) * norm_dx;
                lu.solve(w.r_trial, w.dx_bar);
                w.dx_bar *= -1.0;
                const double norm_bar = scaled_rms(w.dx_bar, xscale);
                if (std::isfinite(norm_bar) && norm_bar <= limit) return alpha;
                if (alpha == alpha_start && exact_correction_accepts(system, w, xscale, limit)) {
                    return alpha;
                }
            }
        } catch (const SingularityError&) {
            saw_singular = true;
        }
        system.restore_state(NonlinearSystem::kLineSearchSlot);
    }
    return 0.0;
}

}  // namespace

struct NewtonWorkspace::Impl {
    explicit Impl(SparseLUSolver::Kind kind) : damping(kind), lu(kind) {}
    VecX r, dx;
    VecX floor_work;  // round_off_floor's row sums
    SparseMatrix J;
    DampingWork damping;
    SparseLUSolver lu;
    int size = -1;
};

NewtonWorkspace::NewtonWorkspace(bool refactor_in_place)
    : impl(std::make_unique<Impl>(refactor_in_place ? SparseLUSolver::Kind::klu_refactor
                                                    : SparseLUSolver::Kind::sparse_lu)) {}
NewtonWorkspace::NewtonWorkspace(SparseLUSolver::Kind kind) : impl(std::make_unique<Impl>(kind)) {}
NewtonWorkspace::~NewtonWorkspace() = default;
int NewtonWorkspace::symbolic_analyses() const {
    return impl->lu.symbolic_analyses() + impl->damping.lu_trial.symbolic_analyses();
}

NewtonOutcome solve_newton(NonlinearSystem& system, const NewtonSettings& settings) {
    NewtonWorkspace workspace(settings.dense_linear_solver ? SparseLUSolver::Kind::dense
                                                           : SparseLUSolver::Kind::sparse_lu);
    return solve_newton(system, settings, workspace);
}

NewtonOutcome solve_newton(NonlinearSystem& system, const NewtonSettings& settings,
                           NewtonWorkspace& workspace) {
    const int n = system.size();
    NewtonOutcome out;
    NewtonWorkspace::Impl& w = *workspace.impl;
    if (w.size != n) {
        w.r.resize(n);
        w.dx.resize(n);
        w.floor_work.resize(n);
        w.damping.r_trial.resize(n);
        w.damping.dx_bar.resize(n);
        w.damping.step.resize(n);
        w.size = n;
    }
    w.damping.trial_jacobian_ready = false;
    VecX& r = w.r;
    VecX& dx = w.dx;
    SparseMatrix& J = w.J;
    DampingWork& damping = w.damping;
    SparseLUSolver& lu = w.lu;
    double previous_alpha = 1.0;
    const VecX& rscale = system.residual_scale();
    const VecX& xscale = system.increment_scale();
    const ConvergenceTolerances tolerances{settings.residual_tolerance,
                                           settings.increment_tolerance};
    IterateMeasures m;

    // The iteration limit counts the corrections taken; a final one that is accepted is not
    // refused by it.
    auto no_convergence = [&]() {
        std::ostringstream s;
        s << "no convergence in " << settings.max_iterations
          << " Newton iterations (scaled residual " << m.residual << ", expected round-off floor "
          << m.round_off_floor << ")";
        out.failure = s.str();
        return out;
    };
    auto refused = [&](const SingularityError& e) {
        out.failure = e.what();
        out.singular = true;
        return out;
    };

    for (int it = 0;; ++it) {
        check_time_limit("in Newton iteration", it);
        try {
            if (damping.trial_jacobian_ready) {
                // The damping test already evaluated r and J at this state.
                std::swap(r, damping.r_trial);
                std::swap(J, damping.J_trial);
                damping.trial_jacobian_ready = false;
            } else {
                system.evaluate(r, &J);
            }
        } catch (const SingularityError& e) {
            return refused(e);
        }
        m.residual = scaled_max_norm(r, rscale);
        out.scaled_residual = m.residual;
        out.iterations = it;
        if (settings.trace) {
            *settings.trace << "  newton " << it << ": scaled residual " << m.residual << "\n";
        }
        if (!std::isfinite(m.residual)) {
            out.failure = "non-finite residual";
            return out;
        }
        if (m.residual == 0.0) {
            out.criterion = Convergence::exact;
            out.converged = true;
            out.error_bound = 0.0;
            return out;
        }
        if (!lu.factorize(J)) {
            out.failure = "singular tangent matrix";
            return out;
        }
        lu.solve(r, dx);
        dx *= -1.0;
        if (!dx.allFinite()) {
            out.failure = "non-finite Newton increment";
            return out;
        }
        m.correction = scaled_max_norm(dx, xscale);
        m.round_off_floor = round_off_floor(J, rscale, xscale, w.floor_work);
        out.round_off_floor = m.round_off_floor;
        if (settings.trace) {
            *settings.trace << "    scaled correction " << m.correction
                            << ", expected round-off floor " << m.round_off_floor << "\n";
        }
        const Convergence criterion = accepted(m, tolerances);
        if (criterion != Convergence::none) {
            try {
                system.retract(dx);  // the final correction (docs/solver-convergence.md)
            } catch (const SingularityError& e) {
                return refused(e);
            }
            out.criterion = criterion;
            out.converged = criterion != Convergence::stalled_at_round_off;
            out.error_bound = m.correction;
            out.iterations = it + 1;
            if (settings.trace) *settings.trace << "  accepted: " << to_string(criterion) << "\n";
            return out;
        }
        if (it >= settings.max_iterations) return no_convergence();
        double alpha = 1.0;
        if (settings.line_search && m.correction > settings.increment_tolerance &&
            !at_round_off(m)) {
            bool saw_singular = false;
            alpha = damped_step(system, lu, dx, xscale, std::min(1.0, 4.0 * previous_alpha),
                                damping, saw_singular);
            if (settings.trace) *settings.trace << "    damping " << alpha << "\n";
            if (alpha == 0.0) {
                out.failure = saw_singular ? "every line-search trial was refused by the "
                                             "parameterization (singular)"
                                           : "damping found no monotone step";
                out.singular = saw_singular;
                out.iterations = it + 1;
                return out;
            }
        } else {
            // A correction below the tolerance, or one taken at the residual's round-off floor
            // (where no monotonicity test can be passed), is taken in full.
            try {
                system.retract(dx);
            } catch (const SingularityError& e) {
                return refused(e);
            }
        }
        previous_alpha = alpha;
        m.previous_residual = m.residual;
        m.last_step_full = alpha == 1.0;
    }
}

void StallSummary::add(const NewtonOutcome& o) {
    if (o.criterion != Convergence::stalled_at_round_off) return;
    ++count;
    if (o.scaled_residual >= worst_residual) {
        worst_residual = o.scaled_residual;
        floor = o.round_off_floor;
    }
    worst_error_bound = std::max(worst_error_bound, o.error_bound);
}

std::string StallSummary::describe(const char* what, double tolerance) const {
    std::ostringstream s;
    s.precision(3);
    s << count << " " << what << " stalled at round-off: scaled residual up to " << worst_residual
      << " (tolerance " << tolerance << "), expected floor " << floor
      << " (eps × scaled Jacobian row sum); algebraic error <= " << worst_error_bound
      << " (scaled)";
    return s.str();
}

namespace {

std::string failure_message(const char* what, size_t step, double target, double lambda,
                            double converged, int cuts, const NewtonOutcome& last,
                            const StaticSystem& problem) {
    std::ostringstream s;
    s.precision(6);
    s << what << " at load step " << step + 1 << " (target load factor " << target
      << "): Newton failed at load factor " << lambda << " after " << cuts << " step cuts ("
      << last.failure << "); last converged load factor " << converged;
    const std::string state = problem.describe_state();
    if (!state.empty()) s << "; " << state;
    return s.str();
}

// A reported step's one Newton solve at its load factor `target` from the guess the problem holds.
NewtonOutcome solve_from_guess(StaticSystem& problem, const NewtonSettings& settings,
                               const StepSolver& solver, NewtonWorkspace& workspace,
                               double target) {
    check_time_limit("before the load step from its initial guess to load factor", target);
    problem.set_load_factor(target);
    if (settings.trace) *settings.trace << "load factor " << target << " from its initial guess\n";
    NewtonOutcome out;
    try {
        out = solver ? solver(problem, settings) : solve_newton(problem, settings, workspace);
    } catch (const TimeLimitReached& e) {
        rethrow_with_context(e, "in the load step from its initial guess to load factor", target);
    }
    if (settings.trace && !out.accepted()) {
        *settings.trace << "  initial guess refused: " << out.failure << "\n";
    }
    return out;
}

// The stability of a reported step's state: the inertia of the Hessian of the potential energy
// at the energy's stationary point next to the state when the system forms one (conservative
// loads; core/potential_hessian.hpp); otherwise that of the last
// Jacobian of its Newton solve — the one at the iterate before the final correction, a scaled
// distance below increment_tolerance from the reported state — which is the Hessian only where it
// is symmetric (the straight states; docs/solver-convergence.md, Stability of the equilibrium). A
// substituted solver (KINSOL) leaves no Jacobian here. Loads without a potential are assessed by
// the kinetic criterion where the system forms its linearized motion and has a mass
// (core/static_stability_kinetic.hpp); otherwise the tangent's inertia as above, in a system that
// forms an energy only (not the mixed formulation, whose tangent is a saddle point).
StaticStability stability_of_step(StaticSystem& problem, const NewtonWorkspace& workspace,
                                  const StepSolver& solver) {
    auto* potential = dynamic_cast<PotentialSystem*>(&problem);
    std::string unavailable = "no potential energy formed";
    if (potential) {
        unavailable.clear();
        // The Newton solve's tangent and its factorization, of the iterate before the last
        // correction (absent with a substituted solver; in another chart when additive).
        TangentSolve tangent;
        if (!solver && !problem.additive() && workspace.impl->J.rows() == problem.size()) {
            tangent = [&workspace](const VecX& b, VecX& x) { workspace.impl->lu.solve(b, x); };
        }
        const StaticStability assessed =
            assess_stability_at_stationary_point(problem, *potential, tangent, unavailable);
        if (unavailable.empty()) return assessed;
    }
    // No energy: the kinetic criterion where the system forms its linearized motion.
    StaticStability s;
    if (auto* kinetic = dynamic_cast<KineticSystem*>(&problem)) {
        StaticStability k = assess_kinetic_stability(kinetic->kinetic_spectrum(kKineticModes));
        if (k.criterion == StaticStability::Criterion::kinetic) return k;
        unavailable += "; " + k.reason;
    }
    // A system that forms no energy at all gives no reason to read its tangent as an energy's
    // Hessian: the mixed formulation's is a saddle point (its stress unknowns make it indefinite
    // at every stable state, so its pivots count no unstable direction).
    if (!potential) {
        s.reason = unavailable;
        return s;
    }
    if (solver) {
        s.reason = "the step solver keeps no tangent to assess; " + unavailable;
        return s;
    }
    const SparseMatrix& J = workspace.impl->J;
    if (J.rows() != problem.size()) {
        s.reason = "no Newton solve was made at this step";
        return s;
    }
    s = assess_stability(J, problem.increment_scale());
    if (s.assessment == StaticStability::Assessment::not_assessed) s.reason += "; " + unavailable;
    return s;
}

}  // namespace

StaticOutcome run_static(StaticSystem& problem, const std::vector<double>& load_factors,
                         const NewtonSettings& settings,
                         const std::function<void(const StepRecord&)>& on_step,
                         const StepSolver& solver, const StepGuess& guess) {
    StaticOutcome outcome;
    // One workspace for every load step: the sparse LU's symbolic analysis (and the vectors) are
    // made once per pattern, not once per sub-step.
    NewtonWorkspace workspace(settings.dense_linear_solver ? SparseLUSolver::Kind::dense
                                                           : SparseLUSolver::Kind::sparse_lu);
    double lambda = 0.0;
    StallSummary stalls;
    problem.set_load_factor(lambda);
    for (size_t step = 0; step < load_factors.size(); ++step) {
        const double target = load_factors[step];
        const double span = target - lambda;
        const double h_max = span / settings.substeps;
        double h = h_max;
        StepRecord record;
        record.load_factor = target;
        int cuts = 0;   // all halvings in this reported step (reported in messages)
        int depth = 0;  // current halvings below h_max: the sub-step is h_max / 2^depth
        int successes_since_cut = 0;
        NewtonOutcome last;
        problem.save_state(NonlinearSystem::kStepSlot);
        if (guess && guess(step)) {
            last = solve_from_guess(problem, settings, solver, workspace, target);
            if (last.accepted()) {
                lambda = target;
                record.newton_iterations = last.iterations;
                record.substeps = 1;
                record.criterion = last.criterion;
                record.scaled_residual = last.scaled_residual;
                record.error_bound = last.error_bound;
                record.round_off_floor = last.round_off_floor;
            } else {
                problem.restore_state(NonlinearSystem::kStepSlot);
                problem.set_load_factor(lambda);
            }
        }
        // Relative to the load factors themselves: a tiny load (1e-14 of the case's) is a load.
        while (std::abs(target - lambda) > 1e-14 * std::max(std::abs(target), std::abs(lambda))) {
            const double trial =
                (std::abs(target - lambda) <= std::abs(h) * (1.0 + 1e-12)) ? target : lambda + h;
            check_time_limit("before the sub-step to load factor", trial);
            problem.set_load_factor(trial);
            if (settings.trace) *settings.trace << "load factor " << trial << "\n";
            try {
                last =
                    solver ? solver(problem, settings) : solve_newton(problem, settings, workspace);
            } catch (const TimeLimitReached& e) {
                rethrow_with_context(e, "in the sub-step to load factor", trial);
            }
            if (last.accepted()) {
                lambda = trial;
                record.newton_iterations += last.iterations;
                ++record.substeps;
                record.criterion = last.criterion;
                record.scaled_residual = last.scaled_residual;
                record.error_bound = last.error_bound;
                record.round_off_floor = last.round_off_floor;
                problem.save_state(NonlinearSystem::kStepSlot);
                // After two clean sub-steps, try a longer one again (never beyond the
                // initial sub-step).
                if (++successes_since_cut >= 2 && depth > 0) {
                    h *= 2.0;
                    --depth;
                    successes_since_cut = 0;
                }
                continue;
            }
            problem.restore_state(NonlinearSystem::kStepSlot);
            problem.set_load_factor(lambda);
            if (settings.trace) *settings.trace << "  step cut: " << last.failure << "\n";
            // The budget bounds the depth of consecutive halvings (a smallest sub-step of
            // h_max / 2^max_step_cuts), as the continuum solver's does, not the halvings summed
            // over the reported step: a long step that crosses several hard stretches, each
            // passable with one or two halvings, must not fail for their sum (the precessing
            // helix between κL = 6.3 and 7, docs/displacement-formulation.md §Reach).
            ++cuts;
            if (++depth > settings.max_step_cuts) {
                const bool singular = last.singular;
                outcome.status = singular ? SolveStatus::singular : SolveStatus::diverged;
                outcome.last_converged_load_factor = lambda;
                outcome.message = failure_message(singular ? "singular" : "diverged", step, target,
                                                  trial, lambda, cuts - 1, last, problem);
                return outcome;
            }
            h *= 0.5;
            successes_since_cut = 0;
        }
        if (settings.assess_stability)
            record.stability = stability_of_step(problem, workspace, solver);
        outcome.steps.push_back(record);
        stalls.add(last);  // the reported state is the last sub-step's
        if (on_step) on_step(record);
    }
    outcome.last_converged_load_factor = lambda;
    if (stalls.count > 0) {
        outcome.status = SolveStatus::stalled_at_round_off;
        outcome.message = stalls.describe("load steps", settings.residual_tolerance);
    } else {
        outcome.message = "all load steps converged";
    }
    // The final state's description (e.g. the quaternion's norm drift), as a failure reports it.
    const std::string state = problem.describe_state();
    if (!state.empty()) outcome.message += "; " + state;
    return outcome;
}

}  // namespace rotbeam
