#include "estimates/companions.hpp"

#include "cases/loader/limits.hpp"

namespace rotbeam::estimate {

namespace {

CompanionPlan p_plan(const Model& model) {
    CompanionPlan plan;
    plan.method = "p+1";
    const int p = model.discretization.order;
    // h-rates at order p: nodal values superconverge at 2p (measured 2.00 and 4.00 for p = 1, 2,
    // docs/studies.md), frequencies at 2p (Rayleigh quotient: twice the energy-norm rate p).
    plan.theoretical_order = {{"displacement", 2 * p},
                              {"rotation", 2 * p},
                              {"frequency", 2 * p},
                              {"in_p", "exponential"}};
    if (p + 1 > cases::kMaxOrder) {
        plan.refusal =
            "the p+1 companion would exceed the largest order, " + std::to_string(cases::kMaxOrder);
        return plan;
    }
    Model companion = model;
    companion.discretization.order = p + 1;
    std::string name = "order " + std::to_string(p + 1);
    // The trapezoidal rule's error does not fall with p (its points stay at the stations) but
    // as refine⁻²: the companion also doubles refine, so that the difference holds 3/4 of the
    // run's quadrature error besides its p-error (docs/error-estimates.md).
    if (model.discretization.quadrature == Quadrature::trapezoidal) {
        const int refine = model.discretization.refine;
        if (2 * refine > cases::kMaxRefine) {
            plan.refusal = "the p+1 companion's refine " + std::to_string(2 * refine) +
                           " would exceed the largest, " + std::to_string(cases::kMaxRefine);
            return plan;
        }
        companion.discretization.refine = 2 * refine;
        name += ", refine " + std::to_string(2 * refine);
    }
    plan.companions.push_back({name, std::move(companion)});
    return plan;
}

// The order p + 2 companion that checks the p-sequence's decay, below kSpectralOrder: one step
// beyond the p+1 companion as that one is beyond the run (with the trapezoidal rule, refine
// doubled again), so that both differences fall at the same rates.
void add_decay_companion(const Model& model, CompanionPlan& plan) {
    const int p = model.discretization.order;
    if (p >= kSpectralOrder || p + 2 > cases::kMaxOrder) return;
    Model companion = plan.companions.front().model;
    companion.discretization.order = p + 2;
    std::string name = "order " + std::to_string(p + 2);
    if (model.discretization.quadrature == Quadrature::trapezoidal) {
        const int refine = 2 * companion.discretization.refine;
        if (refine > cases::kMaxRefine) {
            plan.refusal = "the p+2 companion's refine " + std::to_string(refine) +
                           " would exceed the largest, " + std::to_string(cases::kMaxRefine);
            plan.companions.clear();
            return;
        }
        companion.discretization.refine = refine;
        name += ", refine " + std::to_string(refine);
    }
    plan.companions.push_back({name, std::move(companion)});
}

// The h/2 and h/4 companions: every member's elements doubled and quadrupled.
std::string add_finer_meshes(const Model& model, CompanionPlan& plan) {
    for (const int factor : {2, 4}) {
        Model companion = model;
        for (Member& m : companion.members) {
            if (m.elements > cases::kMaxElementsPerMember / factor) {
                return "the h/" + std::to_string(factor) + " companion would exceed " +
                       std::to_string(cases::kMaxElementsPerMember) + " elements on member '" +
                       m.name + "'";
            }
            m.elements *= factor;
        }
        plan.companions.push_back({std::to_string(factor) + "x elements", std::move(companion)});
    }
    return "";
}

// The 2h and 4h companions: every member's elements halved and quartered, so both meshes nest in
// the run's with the same member ends as nodes.
std::string add_coarser_meshes(const Model& model, CompanionPlan& plan) {
    const int multiple = element_count_multiple(model);
    for (const Member& m : model.members) {
        if (m.elements % multiple != 0) {
            return "the coarser companions need every member's elements divisible by " +
                   std::to_string(multiple) + "; member '" + m.name + "' has " +
                   std::to_string(m.elements);
        }
    }
    for (const int divisor : {2, 4}) {
        Model companion = model;
        for (Member& m : companion.members) m.elements /= divisor;
        plan.companions.push_back(
            {"1/" + std::to_string(divisor) + " elements", std::move(companion)});
    }
    return "";
}

CompanionPlan h_plan(const Model& model) {
    CompanionPlan plan;
    const bool finer = model.analysis.estimate_companions == CompanionSide::finer;
    plan.method = finer ? "h/2,h/4" : "2h,4h";
    plan.h_sequence = finer ? HSequence::finer : HSequence::coarser;
    // Second order for nodal values and frequencies (docs/mixed-formulation.md; measured 2.00
    // for every parameterization, docs/studies.md).
    plan.theoretical_order = {{"displacement", 2}, {"rotation", 2}, {"frequency", 2}};
    plan.refusal = finer ? add_finer_meshes(model, plan) : add_coarser_meshes(model, plan);
    if (!plan.refusal.empty()) plan.companions.clear();
    return plan;
}

}  // namespace

int element_count_multiple(const Model& model) {
    return model.discretization.formulation == Formulation::mixed &&
                   model.analysis.estimate_companions == CompanionSide::coarser
               ? 4
               : 1;
}

CompanionPlan plan_space_companions(const Model& model) {
    return model.discretization.formulation == Formulation::mixed ? h_plan(model) : p_plan(model);
}

CompanionPlan plan_companions(const Model& model) {
    CompanionPlan plan = plan_space_companions(model);
    if (model.analysis.kind == AnalysisKind::dynamic) {
        plan.companions.clear();
        plan.refusal =
            "a dynamic analysis is estimated by add_dynamic_estimate (history_estimate.hpp)";
        return plan;
    }
    if (plan.method == "p+1" && plan.refusal.empty()) add_decay_companion(model, plan);
    return plan;
}

}  // namespace rotbeam::estimate
