// SUNDIALS IDA for DaeSystem (core/dae_driver.hpp): analytic iteration matrix into KLU, IDASetId,
// IDASVtolerances, IDASetMaxOrd, started from the shared consistent initial conditions; callbacks
// are trampolines that never let a C++ exception into SUNDIALS.
#include <ida/ida.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_klu.h>
#include <sunmatrix/sunmatrix_sparse.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <memory>
#include <sstream>
#include <utility>

#include "core/dae_driver.hpp"
#include "core/dae_fixed_steps.hpp"
#include "core/errors.hpp"
#include "core/step_observer.hpp"
#include "core/sundials_callbacks.hpp"
#include "core/time_limit.hpp"

namespace rotbeam {

namespace {

struct IdaUser {
    DaeSystem* dae = nullptr;
    VecX x, xdot, residual;
    SparseMatrix Jx, Jxd, J;
    bool singular = false;
    std::string message;
    void load(N_Vector yy, N_Vector yp) {
        const Eigen::Index n = x.size();
        x = Eigen::Map<const VecX>(N_VGetArrayPointer(yy), n);  // no allocation: sizes match
        xdot = Eigen::Map<const VecX>(N_VGetArrayPointer(yp), n);
    }
};

extern "C" int ida_residual(double t, N_Vector yy, N_Vector yp, N_Vector rr, void* data) {
    IdaUser& user = *static_cast<IdaUser*>(data);
    return sundials_guard(user, "residual", [&] {
        user.load(yy, yp);
        user.dae->evaluate(t, user.x, user.xdot, user.residual, nullptr, nullptr);
        if (!user.residual.allFinite()) return 1;  // recoverable: IDA cuts the step
        std::copy(user.residual.data(), user.residual.data() + user.residual.size(),
                  N_VGetArrayPointer(rr));
        return 0;
    });
}

// J = ∂F/∂X + c_j ∂F/∂Ẋ in the fixed pattern, copied into IDA's CSC matrix.
extern "C" int ida_jacobian(double t, double cj, N_Vector yy, N_Vector yp, N_Vector /*rr*/,
                            SUNMatrix J, void* data, N_Vector /*t1*/, N_Vector /*t2*/,
                            N_Vector /*t3*/) {
    IdaUser& user = *static_cast<IdaUser*>(data);
    return sundials_guard(user, "Jacobian", [&] {
        user.load(yy, yp);
        user.dae->evaluate(t, user.x, user.xdot, user.residual, &user.Jx, &user.Jxd);
        combine_same_pattern(user.Jx, cj, user.Jxd, user.J);
        return copy_to_sunmatrix(user.J, J);  // −1: the pattern must not grow
    });
}

// IDA's own error messages go to the outcome, not to stderr.
extern "C" void ida_error(int /*code*/, const char* /*module*/, const char* /*function*/, char* msg,
                          void* data) {
    IdaUser& user = *static_cast<IdaUser*>(data);
    if (user.message.empty()) user.message = msg;
}

void check(int flag, const char* what) {
    if (flag < 0)
        throw SolverError(std::string("IDA setup: ") + what + " returned " + std::to_string(flag));
}

struct Resources {
    SUNContext ctx = nullptr;
    void* ida = nullptr;
    N_Vector yy = nullptr, yp = nullptr, id = nullptr, atol = nullptr;
    SUNMatrix A = nullptr;
    SUNLinearSolver LS = nullptr;
    ~Resources() {
        if (ida != nullptr) IDAFree(&ida);
        if (LS != nullptr) SUNLinSolFree(LS);
        if (A != nullptr) SUNMatDestroy(A);
        for (N_Vector v : {yy, yp, id, atol}) {
            if (v != nullptr) N_VDestroy(v);
        }
        if (ctx != nullptr) SUNContext_Free(&ctx);
    }
};

void fill(N_Vector v, const VecX& values) {
    std::copy(values.data(), values.data() + values.size(), N_VGetArrayPointer(v));
}

void configure(Resources& r, IdaUser& user, const DaeSettings& s, const VecX& x, const VecX& xdot) {
    DaeSystem& dae = *user.dae;
    const long n = dae.size();
    check(SUNContext_Create(nullptr, &r.ctx), "SUNContext_Create");
    r.yy = N_VNew_Serial(n, r.ctx);
    r.yp = N_VNew_Serial(n, r.ctx);
    r.id = N_VNew_Serial(n, r.ctx);
    r.atol = N_VNew_Serial(n, r.ctx);
    r.ida = IDACreate(r.ctx);
    if (r.yy == nullptr || r.yp == nullptr || r.id == nullptr || r.atol == nullptr ||
        r.ida == nullptr) {
        throw SolverError("IDA: allocation failed");
    }
    fill(r.yy, x);
    fill(r.yp, xdot);
    fill(r.id, dae.differential());
    fill(r.atol, s.absolute_tolerance * dae.state_scale());
    check(IDAInit(r.ida, ida_residual, s.start_time, r.yy, r.yp), "IDAInit");
    check(IDASetUserData(r.ida, &user), "IDASetUserData");
    check(IDASetErrHandlerFn(r.ida, ida_error, &user), "IDASetErrHandlerFn");
    check(IDASVtolerances(r.ida, s.relative_tolerance, r.atol), "IDASVtolerances");
    check(IDASetId(r.ida, r.id), "IDASetId");
    check(IDASetSuppressAlg(r.ida, SUNTRUE), "IDASetSuppressAlg");
    check(IDASetMaxOrd(r.ida, s.max_order), "IDASetMaxOrd");
    check(IDASetMaxNumSteps(r.ida, s.max_steps), "IDASetMaxNumSteps");
    check(IDASetStopTime(r.ida, s.end_time), "IDASetStopTime");
    user.dae->evaluate(s.start_time, x, xdot, user.residual, &user.Jx, &user.Jxd);
    combine_same_pattern(user.Jx, 1.0, user.Jxd, user.J);
    r.A = SUNSparseMatrix(n, n, user.J.nonZeros(), CSC_MAT, r.ctx);
    if (r.A == nullptr) throw SolverError("SUNSparseMatrix failed");
    r.LS = SUNLinSol_KLU(r.yy, r.A, r.ctx);
    if (r.LS == nullptr) throw SolverError("SUNLinSol_KLU failed");
    check(IDASetLinearSolver(r.ida, r.LS, r.A), "IDASetLinearSolver");
    check(IDASetJacFn(r.ida, ida_jacobian), "IDASetJacFn");
}

void statistics(void* ida, DaeOutcome& out) {
    using Counter = int (*)(void*, long*);
    const std::pair<Counter, long DaeOutcome::*> counters[] = {
        {IDAGetNumSteps, &DaeOutcome::steps},
        {IDAGetNumNonlinSolvIters, &DaeOutcome::newton_iterations},
        {IDAGetNumResEvals, &DaeOutcome::residual_evaluations},
        {IDAGetNumJacEvals, &DaeOutcome::jacobian_evaluations},
        {IDAGetNumErrTestFails, &DaeOutcome::error_test_failures},
        {IDAGetNumNonlinSolvConvFails, &DaeOutcome::nonlinear_failures}};
    for (const auto& [get, field] : counters) {
        long v = 0;
        get(ida, &v);
        out.*field = v;
    }
    int order = 0;
    IDAGetLastOrder(ida, &order);
    out.last_order = order;
}

std::string failure(const char* where, double t, int flag, const IdaUser& user) {
    std::ostringstream m;
    // SUNDIALS 6 returns the flag's name in a malloc'ed string that the caller frees.
    const std::unique_ptr<char, decltype(&std::free)> name(IDAGetReturnFlagName(flag), &std::free);
    m << where << " failed at t = " << t << ": " << (name ? name.get() : "unknown IDA flag");
    if (!user.message.empty()) m << " (" << user.message << ")";
    return m.str();
}

}  // namespace

DaeOutcome integrate_ida(DaeSystem& dae, VecX& x, VecX& xdot, const DaeSettings& s,
                         const DaeOutput& output) {
    ROTBEAM_VERIFY(s.max_order >= 1 && s.max_order <= 5, "IDA orders are 1 to 5");
    // Consistent initial conditions by the shared scaled Newton of the other schemes
    // (core/dae_driver.hpp), not IDACalcIC: on a very stiff beam started at rest (EA = 1e9)
    // IDACalcIC's line search fails (IDA_LINESEARCH_FAIL) where this Newton converges, its
    // stopping test asking each unknown only for the resolution the residual allows
    // (raise_to_resolution); docs/mixed-dynamics.md, "IDA from rest on a very stiff beam".
    DaeOutcome outcome;
    NewtonOutcome ic;
    if (!start_dae_run(dae, x, xdot, s, output, outcome, ic)) return outcome;
    const long ic_iterations = outcome.newton_iterations;
    // A start accepted at the Newton's round-off floor is reported as the other schemes report it.
    StallSummary stalls;
    stalls.add(ic);
    IdaUser user;
    user.dae = &dae;
    user.x = x;
    user.xdot = xdot;
    Resources r;
    configure(r, user, s, x, xdot);
    const double interval = s.output_interval > 0.0 ? s.output_interval : s.time_step;
    const long outputs = std::lround((s.end_time - s.start_time) / interval);
    long iterations_before = ic_iterations;
    for (long k = 1; k <= outputs; ++k) {
        const double tout =
            k == outputs ? s.end_time : s.start_time + static_cast<double>(k) * interval;
        double tret = outcome.last_time;
        check_time_limit("at time", tret);
        const int flag = IDASolve(r.ida, tout, &tret, r.yy, r.yp, IDA_NORMAL);
        statistics(r.ida, outcome);
        outcome.newton_iterations += ic_iterations;
        if (flag < 0) {
            outcome.status = user.singular ? SolveStatus::singular : SolveStatus::diverged;
            std::ostringstream m;
            m << failure("IDASolve", tret, flag, user) << ", step " << outcome.steps;
            outcome.message = m.str();
            outcome.last_time = tret;
            return outcome;
        }
        // A refusal IDA recovered from is not a failure; one in the interval that failed (even as
        // IDA_TOO_MUCH_WORK: the step cut again and again at the singular set) is the cause.
        user.singular = false;
        user.message.clear();
        x = Eigen::Map<const VecX>(N_VGetArrayPointer(r.yy), x.size());
        xdot = Eigen::Map<const VecX>(N_VGetArrayPointer(r.yp), x.size());
        outcome.last_time = tret;
        if (output) {
            output(tret, x, xdot, static_cast<int>(outcome.newton_iterations - iterations_before));
        }
        iterations_before = outcome.newton_iterations;
        notify_step({tret, outcome.steps, outcome.newton_iterations, outcome.jacobian_evaluations});
    }
    std::ostringstream m;
    m << "IDA (BDF, max order " << s.max_order << "), " << outcome.steps << " steps, last order "
      << outcome.last_order;
    if (stalls.count > 0) {
        outcome.status = SolveStatus::stalled_at_round_off;
        m << "; " << stalls.describe("initial-condition solve", s.newton.residual_tolerance);
    }
    outcome.message = m.str();
    return outcome;
}

}  // namespace rotbeam
