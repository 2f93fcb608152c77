// The non-template parts of the mixed dynamics (section mass, loads in time) and the explicit
// instantiations for every parameterization.
#include "core/errors.hpp"
#include "core/geometry.hpp"
#include "formulations/mixed/mixed_dynamic_common.hpp"
#include "formulations/mixed/mixed_dynamics_impl.hpp"
#include "parameterizations/registry.hpp"
#include "parameterizations/wiener_milenkovic_continuous.hpp"

namespace rotbeam::form {

namespace {

// The section mass at arc-length fraction f of a member, linear between stations.
Mat6 section_mass_at(const Member& member, double f) {
    auto mass_of = [&](const SectionStation& s) -> Mat6 {
        if (!s.section.mass) {
            throw InputError("member '" + member.name + "', section '" + s.section.name +
                             "': the dynamic and modal analyses need a mass matrix (density or "
                             "mass)");
        }
        return *s.section.mass;
    };
    const std::vector<SectionStation>& st = member.sections;
    if (st.size() == 1 || f <= st.front().s_fraction) return mass_of(st.front());
    for (std::size_t k = 1; k < st.size(); ++k) {
        if (f <= st[k].s_fraction) {
            const double w = (f - st[k - 1].s_fraction) / (st[k].s_fraction - st[k - 1].s_fraction);
            return (1.0 - w) * mass_of(st[k - 1]) + w * mass_of(st[k]);
        }
    }
    return mass_of(st.back());
}

}  // namespace

Mat6 mixed_element_mass(const Model& model, const MixedElement& element) {
    const MassRule rule = model.discretization.mixed.mass_rule;
    if (rule == MassRule::lumped) {
        throw InputError(
            "discretization.mass_rule: 'lumped' is not available in the mixed formulation (its "
            "momenta P, H are element unknowns: there are no nodal masses to lump; consistent | "
            "midpoint)");
    }
    const Member& member = model.members[static_cast<std::size_t>(element.member)];
    const double L = ReferenceGeometry(model, element.member).length();
    if (rule == MassRule::midpoint) return section_mass_at(member, element.s_mid / L);
    // Consistent: ∫ Nᵀ I N ds / ΔL with the element's constant momentum shape N = 1, i.e. the
    // average of I over the element's arc-length span s_mid ∓ L/2n (build_mixed_layout's uniform
    // division), exact for the piecewise-linear station interpolation: trapezoids between the
    // span's ends and the stations inside it.
    const double half = 0.5 / member.elements;
    const double a = element.s_mid / L - half, b = element.s_mid / L + half;
    std::vector<double> breaks = {a};
    for (const SectionStation& st : member.sections) {
        if (st.s_fraction > a && st.s_fraction < b) breaks.push_back(st.s_fraction);
    }
    breaks.push_back(b);
    Mat6 sum = Mat6::Zero();
    for (std::size_t k = 1; k < breaks.size(); ++k) {
        sum += 0.5 * (breaks[k] - breaks[k - 1]) *
               (section_mass_at(member, breaks[k - 1]) + section_mass_at(member, breaks[k]));
    }
    return sum / (b - a);
}

Model without_distributed_loads(Model m) {
    m.distributed_loads.clear();
    return m;
}

std::vector<MixedDampingSection> mixed_damping_sections(const Model& model,
                                                        const MixedLayout& layout) {
    std::vector<MixedDampingSection> out(layout.elements.size());
    if (!model.has_damping()) return out;
    for (std::size_t e = 0; e < layout.elements.size(); ++e) {
        const MixedElement& el = layout.elements[e];
        const Member& member = model.members[static_cast<std::size_t>(el.member)];
        // μ linear between stations, as the stiffness (mixed_layout.cpp).
        out[e].mu =
            section_property_at(member, el.s_mid / ReferenceGeometry(model, el.member).length(),
                                [](const Section& s) { return s.damping; });
        if (!out[e].active()) continue;
        const Eigen::FullPivLU<Mat6> lu(el.S);
        if (!lu.isInvertible()) {
            throw InputError("member '" + member.name +
                             "': damping needs an invertible compliance in the mixed dynamics "
                             "(a rigid component has no strain rate to damp)");
        }
        out[e].stiffness = lu.inverse();
    }
    return out;
}

void refuse_mixed_modal_damping(const Model& model) {
    if (model.has_damping()) {
        throw InputError(
            "sections: damping is not available in the mixed modal analysis (its modes are "
            "undamped)");
    }
}

double mixed_time_value(const TimeFunction& f, double t, double floor) {
    const bool may_jump = f.kind == TimeFunction::Kind::table || f.kind == TimeFunction::Kind::ramp;
    return f(may_jump ? std::max(t, floor) : t);
}

MixedElement mixed_loaded_element(const Model& model, const MixedElement& element, double t,
                                  double floor) {
    MixedElement el = element;
    for (const DistributedLoad& load : model.distributed_loads) {
        if (load.member != el.member) continue;
        el.add_load(load, mixed_time_value(load.time, t, floor));
    }
    return el;
}

MixedMassInverses mixed_mass_inverses(const Model& model, const MixedLayout& layout) {
    MixedMassInverses out;
    for (const MixedElement& el : layout.elements) {
        const Mat6 I = mixed_element_mass(model, el);
        const Eigen::FullPivLU<Mat6> lu(I);
        if (!lu.isInvertible() || lu.rcond() < 1e-14) {
            throw InputError("member '" + model.members[static_cast<std::size_t>(el.member)].name +
                             "': the mixed dynamics invert the section mass (seed 002 Eq. 18); "
                             "it is singular");
        }
        out.inverse.push_back(lu.inverse());
        out.mass_scale = std::max(out.mass_scale, I(0, 0));
        out.inertia_scale = std::max(out.inertia_scale, I.diagonal().tail<3>().maxCoeff());
    }
    return out;
}

#define ROTBEAM_MIXED_DYNAMICS_INSTANTIATE(P) template class MixedDynamics<param::P>;
ROTBEAM_FOR_EACH_PARAMETERIZATION(ROTBEAM_MIXED_DYNAMICS_INSTANTIATE)
#undef ROTBEAM_MIXED_DYNAMICS_INSTANTIATE
template class MixedDynamics<param::WienerMilenkovicContinuous>;

}  // namespace rotbeam::form
