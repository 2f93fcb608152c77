// `rotbeam check`: a readable summary of a validated model.
#include <iomanip>
#include <sstream>

#include "cases/loader/case_loader.hpp"
#include "cases/loader/limits.hpp"
#include "core/dae_driver.hpp"
#include "core/geometry.hpp"
#include "parameterizations/registry.hpp"

namespace rotbeam {

namespace {

std::string rounded_vec(const Vec3& v) {
    std::ostringstream s;
    s << std::setprecision(6) << "(" << v.x() << ", " << v.y() << ", " << v.z() << ")";
    return s.str();
}

std::string line_text(const Member& m) {
    switch (m.line.kind) {
        case LineKind::straight:
            return "straight";
        case LineKind::arc:
            return "arc about centre " + rounded_vec(m.line.center) +
                   (m.line.normal ? ", normal " + rounded_vec(*m.line.normal) : "");
        case LineKind::keypoints:
            return "spline through " + std::to_string(m.line.keypoints.size()) + " key point(s)";
    }
    return "";
}

std::string time_text(const TimeFunction& f) {
    std::ostringstream s;
    s << std::setprecision(6);
    switch (f.kind) {
        case TimeFunction::Kind::constant:
            s << "constant " << f.value;
            break;
        case TimeFunction::Kind::ramp:
            s << "ramp to " << f.value << " from t=" << f.start << " over " << f.duration;
            break;
        case TimeFunction::Kind::sine:
            s << f.value << "·sin(" << f.omega << "(t−" << f.start << ")+" << f.phase << ")";
            break;
        case TimeFunction::Kind::table:
            s << "table of " << f.times.size() << " points";
            break;
    }
    return s.str();
}

void describe_members(const Model& model, std::ostream& os) {
    os << "members (" << model.members.size() << "):\n";
    for (size_t i = 0; i < model.members.size(); ++i) {
        const Member& m = model.members[i];
        const ReferenceGeometry g(model, static_cast<int>(i));
        os << "  " << m.name << ": " << model.points[m.start_point].name << " → "
           << model.points[m.end_point].name << ", " << line_text(m) << ", length " << g.length()
           << ", " << m.elements << " element(s)";
        if (m.twist_start != 0.0 || m.twist_end != 0.0) {
            os << ", twist " << m.twist_start << " → " << m.twist_end << " rad";
            if (m.twist_values.size() > 2) {
                os << " (degree-" << m.twist_values.size() - 1 << " polynomial)";
            }
        }
        os << "\n";
        for (const SectionStation& st : m.sections) {
            const Section& s = st.section;
            os << "    section " << s.name << " at s/L = " << st.s_fraction;
            if (s.stiffness) {
                const Vec6 d = s.stiffness->diagonal();
                os << ": EA " << d[0] << ", GA2 " << d[1] << ", GA3 " << d[2] << ", GJ " << d[3]
                   << ", EI2 " << d[4] << ", EI3 " << d[5];
                const Mat6 off = *s.stiffness - Mat6(d.asDiagonal());
                if (off.cwiseAbs().maxCoeff() > 0.0) os << " (coupled)";
            } else {
                os << ": compliance with rigid rows";
            }
            if (s.mass) os << "; mass/length " << (*s.mass)(0, 0);
            if (s.has_damping()) os << "; damped";
            os << "\n";
        }
    }
}

void describe_loads(const Model& model, std::ostream& os) {
    os << "constraints (" << model.constraints.size() << "):\n";
    for (const Constraint& c : model.constraints) {
        os << "  " << model.points[c.point].name << ": "
           << (c.kind == Constraint::Kind::clamped
                   ? std::string("clamped")
                   : "prescribed u " + rounded_vec(c.displacement) + ", rotation " +
                         rounded_vec(c.rotation) + ", " + time_text(c.time))
           << "\n";
    }
    os << "loads (" << model.point_loads.size() + model.distributed_loads.size() << "):\n";
    for (const PointLoad& l : model.point_loads) {
        os << "  point " << model.points[l.point].name << ": force " << rounded_vec(l.force)
           << ", moment " << rounded_vec(l.moment) << ", "
           << (l.frame == LoadFrame::dead ? "dead" : "follower") << ", " << time_text(l.time)
           << "\n";
    }
    for (const DistributedLoad& l : model.distributed_loads) {
        os << "  member " << model.members[l.member].name << ": force/length "
           << rounded_vec(l.force) << ", moment/length " << rounded_vec(l.moment) << ", "
           << (l.frame == LoadFrame::dead ? "dead" : "follower") << ", " << time_text(l.time)
           << "\n";
    }
    if (model.gravity.norm() > 0.0) os << "gravity " << rounded_vec(model.gravity) << "\n";
}

void describe_analysis(const Model& model, std::ostream& os) {
    const Analysis& a = model.analysis;
    os << "analysis: ";
    if (a.kind == AnalysisKind::dynamic) {
        os << "dynamic, Δt " << a.dynamics.time_step << ", end " << a.dynamics.end_time << ", ρ∞ "
           << a.dynamics.rho_infinity << ", initial state " << choice_name(a.dynamics.initial_state)
           << "\n";
    } else if (a.kind == AnalysisKind::modal && a.statics.load_factors.empty()) {
        os << "modal, " << a.modal.modes << " modes about the "
           << (a.modal.about_static_state ? "unloaded static state" : "reference configuration")
           << "\n";
    } else {
        if (a.kind == AnalysisKind::modal) os << "modal, " << a.modal.modes << " modes; ";
        os << "static load factors [";
        for (size_t i = 0; i < a.statics.load_factors.size(); ++i) {
            os << (i ? ", " : "") << a.statics.load_factors[i];
        }
        os << "]\n";
    }
    const Discretization& d = model.discretization;
    os << "discretization: " << choice_name(d.formulation) << ", " << param::name_of(d.rotation)
       << ", order " << d.order << ", interpolation " << choice_name(d.displacement.interpolation)
       << ", update " << choice_name(d.displacement.update) << ", mass rule "
       << choice_name(d.mass_rule()) << (d.displacement.rescale ? ", rescale" : ", no rescale")
       << "\n";
    os << "solver: " << choice_name(model.solver.driver) << ", residual tol "
       << step_newton_settings(model).residual_tolerance << ", max " << model.solver.max_iterations
       << " iterations\n";
    os << "references: " << model.references.size();
    int gated = 0;
    for (const ReferenceValue& r : model.references) gated += r.gated ? 1 : 0;
    os << " (" << gated << " gated)";
    if (!model.expected_stops.empty()) os << ", expected stops: " << model.expected_stops.size();
    os << "\n";
    const cases::MemoryEstimate e = cases::estimate_memory(model);
    os << "memory: estimated " << cases::memory_text(e.bytes) << " (about " << e.unknowns
       << " unknowns; mostly " << e.dominant << "; docs/case-format.md, Limits)\n";
}

}  // namespace

std::string describe_model(const Model& model) {
    std::ostringstream os;
    os << std::setprecision(6);
    os << "case " << model.name;
    if (!model.units.empty()) os << " [" << model.units << "]";
    os << "\n";
    if (!model.description.empty()) os << "  " << model.description << "\n";
    os << "points (" << model.points.size() << "):\n";
    for (const Point& p : model.points)
        os << "  " << p.name << " " << rounded_vec(p.position) << "\n";
    describe_members(model, os);
    describe_loads(model, os);
    describe_analysis(model, os);
    return os.str();
}

}  // namespace rotbeam
