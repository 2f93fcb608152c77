#include "core/kinsol_driver.hpp"

#include <kinsol/kinsol.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_klu.h>
#include <sunmatrix/sunmatrix_sparse.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <memory>
#include <sstream>

#include "core/convergence.hpp"
#include "core/errors.hpp"
#include "core/sparse_lu.hpp"
#include "core/sundials_callbacks.hpp"

namespace rotbeam {

namespace {

struct KinsolUser {
    NonlinearSystem* system = nullptr;
    VecX residual;
    SparseMatrix jacobian;
    bool singular = false;
    std::string message;
};

// Copies the C vector into the system's state; the system evaluates there.
void set_state(KinsolUser& user, N_Vector x) {
    const Eigen::Map<const VecX> xv(N_VGetArrayPointer(x), user.system->size());
    user.system->set_state_vector(xv);
}

extern "C" int kinsol_residual(N_Vector x, N_Vector f, void* data) {
    KinsolUser& user = *static_cast<KinsolUser*>(data);
    return sundials_guard(user, "residual", [&] {
        set_state(user, x);
        user.system->evaluate(user.residual, nullptr);
        if (!user.residual.allFinite()) return 1;  // recoverable: the line search backs off
        std::copy(user.residual.data(), user.residual.data() + user.residual.size(),
                  N_VGetArrayPointer(f));
        return 0;
    });
}

extern "C" int kinsol_jacobian(N_Vector x, N_Vector /*f*/, SUNMatrix J, void* data,
                               N_Vector /*tmp1*/, N_Vector /*tmp2*/) {
    KinsolUser& user = *static_cast<KinsolUser*>(data);
    return sundials_guard(user, "Jacobian", [&] {
        set_state(user, x);
        user.system->evaluate(user.residual, &user.jacobian);
        user.jacobian.makeCompressed();
        return copy_to_sunmatrix(user.jacobian, J);  // −1: the pattern must not grow
    });
}

extern "C" void kinsol_error(int /*code*/, const char* /*module*/, const char* /*function*/,
                             char* message, void* data) {
    static_cast<KinsolUser*>(data)->message = message;  // reported in KinsolOutcome::failure
}

void check(int flag, const char* call) {
    if (flag < 0) throw SolverError(std::string("KINSOL setup failed in ") + call);
}

// RAII owners of the SUNDIALS objects.
struct Resources {
    SUNContext ctx = nullptr;
    void* kin = nullptr;
    N_Vector x = nullptr, uscale = nullptr, fscale = nullptr;
    SUNMatrix A = nullptr;
    SUNLinearSolver LS = nullptr;
    ~Resources() {
        if (kin != nullptr) KINFree(&kin);
        if (LS != nullptr) SUNLinSolFree(LS);
        if (A != nullptr) SUNMatDestroy(A);
        for (N_Vector v : {x, uscale, fscale}) {
            if (v != nullptr) N_VDestroy(v);
        }
        if (ctx != nullptr) SUNContext_Free(&ctx);
    }
};

void fill(N_Vector v, const VecX& values, bool invert) {
    double* p = N_VGetArrayPointer(v);
    for (Eigen::Index i = 0; i < values.size(); ++i) p[i] = invert ? 1.0 / values[i] : values[i];
}

void configure(Resources& r, KinsolUser& user, const KinsolSettings& settings, long nnz) {
    const long n = user.system->size();
    check(KINInit(r.kin, kinsol_residual, r.x), "KINInit");
    check(KINSetUserData(r.kin, &user), "KINSetUserData");
    check(KINSetErrHandlerFn(r.kin, kinsol_error, &user), "KINSetErrHandlerFn");
    check(KINSetFuncNormTol(r.kin, settings.residual_tolerance), "KINSetFuncNormTol");
    check(KINSetScaledStepTol(r.kin, settings.step_tolerance), "KINSetScaledStepTol");
    check(KINSetNumMaxIters(r.kin, settings.max_iterations), "KINSetNumMaxIters");
    check(KINSetMaxSetupCalls(r.kin, 1), "KINSetMaxSetupCalls");  // exact Newton
    // The default bound (1000 × scaled initial guess) is meaningless from x = 0: allow any step,
    // the line search does the damping.
    check(KINSetMaxNewtonStep(r.kin, 1e12 * std::sqrt(static_cast<double>(n))),
          "KINSetMaxNewtonStep");
    r.A = SUNSparseMatrix(n, n, nnz, CSC_MAT, r.ctx);
    if (r.A == nullptr) throw SolverError("SUNSparseMatrix failed");
    r.LS = SUNLinSol_KLU(r.x, r.A, r.ctx);
    if (r.LS == nullptr) throw SolverError("SUNLinSol_KLU failed");
    check(KINSetLinearSolver(r.kin, r.LS, r.A), "KINSetLinearSolver");
    check(KINSetJacFn(r.kin, kinsol_jacobian), "KINSetJacFn");
}

// The shared criteria (core/convergence.hpp) at KINSOL's iterate. KINSOL stops on its residual
// test alone, so the Newton correction there is computed from one more factorization; when it is
// not accepted yet but the residual is within its tolerance or at its round-off floor, up to
// kFinishingCorrections plain Newton corrections finish the solve. KINSOL reports a stall itself
// (its last step fell below its step tolerance, or the line search found no decrease): that
// stands for "the last step did not halve the residual". An accepted state gets its correction.
void accept_or_refuse(NonlinearSystem& system, KinsolUser& user, const KinsolSettings& settings,
                      KinsolOutcome& out) {
    constexpr int kFinishingCorrections = 3;
    const VecX& rscale = system.residual_scale();
    const VecX& xscale = system.increment_scale();
    const ConvergenceTolerances t{settings.residual_tolerance, settings.increment_tolerance};
    IterateMeasures m;
    if (out.flag == KIN_STEP_LT_STPTOL || out.flag == KIN_LINESEARCH_NONCONV) {
        m.previous_residual = 0.0;
        m.last_step_full = true;
    }
    SparseLUSolver lu(SparseLUSolver::Kind::sparse_lu);
    VecX dx, work;
    for (int k = 0; k <= kFinishingCorrections; ++k) {
        system.evaluate(user.residual, &user.jacobian);
        m.residual = scaled_max_norm(user.residual, rscale);
        out.scaled_residual = m.residual;
        if (!std::isfinite(m.residual) || !lu.factorize(user.jacobian)) return;
        lu.solve(user.residual, dx);
        dx *= -1.0;
        m.correction = scaled_max_norm(dx, xscale);
        m.round_off_floor = round_off_floor(user.jacobian, rscale, xscale, work);
        out.round_off_floor = m.round_off_floor;
        out.criterion = accepted(m, t);
        out.converged = out.criterion != Convergence::none &&
                        out.criterion != Convergence::stalled_at_round_off;
        if (out.criterion == Convergence::exact) {
            out.error_bound = 0.0;
            return;
        }
        if (!out.accepted() && m.residual > t.residual && !at_round_off(m)) return;
        system.set_state_vector(system.state_vector() + dx);
        if (out.accepted()) {
            out.error_bound = m.correction;
            return;
        }
        out.iterations += 1;
        m.previous_residual = m.residual;
        m.last_step_full = true;
    }
}

}  // namespace

KinsolOutcome solve_kinsol(NonlinearSystem& system, const KinsolSettings& settings) {
    if (!system.additive()) {
        throw InputError("KINSOL drives additive systems only (retract(dx) = x + dx)");
    }
    const long n = system.size();
    KinsolUser user;
    user.system = &system;
    system.evaluate(user.residual, &user.jacobian);  // fixes the pattern and its size
    user.jacobian.makeCompressed();

    Resources r;
    check(SUNContext_Create(nullptr, &r.ctx), "SUNContext_Create");
    r.x = N_VNew_Serial(n, r.ctx);
    r.uscale = N_VNew_Serial(n, r.ctx);
    r.fscale = N_VNew_Serial(n, r.ctx);
    r.kin = KINCreate(r.ctx);
    if (r.x == nullptr || r.uscale == nullptr || r.fscale == nullptr || r.kin == nullptr) {
        throw SolverError("KINSOL: allocation failed");
    }
    fill(r.x, system.state_vector(), false);
    fill(r.uscale, system.increment_scale(), true);
    fill(r.fscale, system.residual_scale(), true);
    configure(r, user, settings, user.jacobian.nonZeros());

    KinsolOutcome out;
    out.flag =
        KINSol(r.kin, r.x, settings.line_search ? KIN_LINESEARCH : KIN_NONE, r.uscale, r.fscale);
    long value = 0;
    KINGetNumNonlinSolvIters(r.kin, &value);
    out.iterations = value;
    KINGetNumFuncEvals(r.kin, &value);
    out.residual_evaluations = value;
    KINGetNumJacEvals(r.kin, &value);
    out.jacobian_evaluations = value;
    set_state(user, r.x);  // leave the system at KINSOL's iterate
    accept_or_refuse(system, user, settings, out);
    out.singular = user.singular;
    if (!out.accepted()) {
        std::ostringstream m;
        m << "KINSol flag " << out.flag << (user.message.empty() ? "" : ": " + user.message)
          << " (scaled residual " << out.scaled_residual << ")";
        out.failure = m.str();
    }
    return out;
}

}  // namespace rotbeam
