// Case loader: points, sections, members, constraints, loads (docs/case-format.md).
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "cases/loader/limits.hpp"
#include "cases/loader/model_builder.hpp"
#include "core/errors.hpp"
#include "core/geometry.hpp"

namespace rotbeam::cases {

std::vector<std::string> point_names(const Model& model) {
    std::vector<std::string> names;
    for (const Point& p : model.points) names.push_back(p.name);
    return names;
}

namespace {

// Symmetry to round-off of printed data: 1e-9 of the largest entry.
bool symmetric(const Mat6& M) {
    return (M - M.transpose()).cwiseAbs().maxCoeff() <= 1e-9 * M.cwiseAbs().maxCoeff();
}

// The range of a section matrix's diagonal: the assembly and the factorizations form products
// of two numbers of a stiffness's (or a mass's) size (element Schur complements, the round-off
// floor's |J| row sums times the scales), and such a product is a normal, finite double only
// when both lie within [√DBL_MIN, √DBL_MAX] ≈ [1.5e-154, 1.3e154]. Outside it the solve fails or
// answers wrongly (measured on the tip-load cantilever with E and the load scaled together: the
// displacement formulation is exact to 1e-15 for EA from 2e-173 to 2e157, reports `converged`
// with a zero displacement at EA = 2e167, and E = 1e-300 with a 1 N load ends `diverged`
// (singular tangent) and, in the mixed formulation, `singular` with a NaN rotation angle). No
// unit system puts a beam's stiffness or mass there.
const double kSmallestEntry = std::sqrt(std::numeric_limits<double>::min());
const double kLargestEntry = std::sqrt(std::numeric_limits<double>::max());

std::string entry_range() {
    std::ostringstream s;
    s.precision(2);
    s << "[" << kSmallestEntry << ", " << kLargestEntry << "]";
    return s.str();
}

// Positive definite and not numerically singular, judged on the Jacobi-scaled matrix
// D^-1/2 M D^-1/2 (unit diagonal, D = diag M): its eigenvalue ratio is that of the section's
// couplings, independent of the units (within a factor 6 of the best diagonal scaling's, van der
// Sluis), where the unscaled ratio of EI to EA would refuse a slender section for its units.
// Bound: the smallest scaled eigenvalue at least kDefiniteness of the largest, i.e. a scaled
// condition number at most 1e12 ≈ 1/(4500 ε). Its eigenvalues are computed to ~6 ε ‖·‖ ≈ 1e-15,
// so at the bound the smallest is known to 0.1 % (positive definite, not a round-off artefact);
// and the compliance K⁻¹ the loader forms for the mixed formulation keeps at least
// 1 − cond·ε ≈ 4 of its 16 digits in the softest direction. Below, the matrix is singular to
// the precision its data and a 6×6 inverse can carry. Empty when it holds, else the problem.
constexpr double kDefiniteness = 1e-12;

std::string definiteness_problem(const Eigen::MatrixXd& M, const std::string& what) {
    const Eigen::VectorXd d = M.diagonal();
    for (Eigen::Index i = 0; i < d.size(); ++i) {
        if (!(d(i) > 0.0)) return what + " is not positive definite";
    }
    const Eigen::VectorXd inv_sqrt = d.cwiseSqrt().cwiseInverse();
    const Eigen::MatrixXd scaled = inv_sqrt.asDiagonal() * M * inv_sqrt.asDiagonal();
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(scaled, Eigen::EigenvaluesOnly);
    const double smallest = eig.eigenvalues().minCoeff();
    const double largest = eig.eigenvalues().maxCoeff();
    if (!(smallest > 0.0)) return what + " is not positive definite";
    if (smallest <= kDefiniteness * largest) {
        std::ostringstream s;
        s.precision(3);
        s << what << " is numerically singular: condition number " << largest / smallest
          << " of the matrix scaled to a unit diagonal, above 1e12";
        return s.str();
    }
    return {};
}

// Every diagonal entry of `M` within [kSmallestEntry, kLargestEntry]; `names` name them.
std::string range_problem(const Eigen::VectorXd& diagonal, const std::vector<std::string>& names,
                          const std::string& what) {
    for (Eigen::Index i = 0; i < diagonal.size(); ++i) {
        const double v = std::abs(diagonal(i));
        if (v != 0.0 && (v < kSmallestEntry || v > kLargestEntry)) {
            std::ostringstream s;
            s.precision(3);
            s << what << " entry " << names[static_cast<std::size_t>(i)] << " = " << diagonal(i)
              << " is outside " << entry_range()
              << ": products of two such numbers, which the solve forms, underflow or overflow";
            return s.str();
        }
    }
    return {};
}

std::vector<std::string> diagonal_names(const std::vector<int>& rows) {
    std::vector<std::string> names;
    for (int i : rows) {
        std::ostringstream s;
        s << "(" << i + 1 << "," << i + 1 << ")";
        names.push_back(s.str());
    }
    return names;
}

std::vector<int> all_rows() { return {0, 1, 2, 3, 4, 5}; }

// A 6×6 (or its flexible rows) in range, positive definite and not numerically singular.
void check_section_matrix(const YamlReader& r, const YAML::Node& n, const std::string& k,
                          const Eigen::MatrixXd& M, const std::vector<int>& rows,
                          const std::string& what) {
    std::string problem = range_problem(M.diagonal(), diagonal_names(rows), what);
    if (problem.empty()) problem = definiteness_problem(M, what);
    if (!problem.empty()) r.fail(n, k, problem);
}

Mat6 isotropic_stiffness(const YamlReader& r, const YAML::Node& n, const std::string& key,
                         double* density_area, Vec3* density_inertia) {
    r.expect_map(n, key, {"E", "G", "nu", "A", "I2", "I3", "J", "k2", "k3"});
    const double E = r.positive(r.required(n, key, "E"), key + ".E");
    if (n["G"] && n["nu"]) r.fail(n["nu"], key + ".nu", "give G or nu, not both");
    if (!n["G"] && !n["nu"]) r.fail(n, key + ".G", "missing required key (or give nu)");
    double G = 0.0;
    if (n["G"]) {
        G = r.positive(n["G"], key + ".G");
    } else {
        const double nu = r.number(n["nu"], key + ".nu");
        if (!(nu > -1.0 && nu < 0.5)) r.fail(n["nu"], key + ".nu", "must lie in (-1, 0.5)");
        G = E / (2.0 * (1.0 + nu));
    }
    const double A = r.positive(r.required(n, key, "A"), key + ".A");
    const double I2 = r.positive(r.required(n, key, "I2"), key + ".I2");
    const double I3 = r.positive(r.required(n, key, "I3"), key + ".I3");
    const double J = r.positive(r.required(n, key, "J"), key + ".J");
    // Shear factor 5/6 (rectangle, Timoshenko) unless given.
    const double k2 = n["k2"] ? r.positive(n["k2"], key + ".k2") : 5.0 / 6.0;
    const double k3 = n["k3"] ? r.positive(n["k3"], key + ".k3") : 5.0 / 6.0;
    Vec6 d;
    d << E * A, k2 * G * A, k3 * G * A, G * J, E * I2, E * I3;
    const std::string problem =
        range_problem(d, {"EA", "k2 GA", "k3 GA", "GJ", "EI2", "EI3"}, "stiffness");
    if (!problem.empty()) r.fail(n, key, problem);
    *density_area = A;
    *density_inertia = Vec3(I2 + I3, I2, I3);
    return d.asDiagonal();
}

Mat6 read_stiffness(const YamlReader& r, const YAML::Node& n, const std::string& k) {
    const Mat6 K = r.mat6(n, k);
    if (!symmetric(K)) r.fail(n, k, "stiffness matrix is not symmetric");
    check_section_matrix(r, n, k, K, all_rows(), "stiffness matrix");
    return 0.5 * (K + K.transpose());
}

// A compliance may have zero rows (rigid modes); the rest must be positive definite. Sets the
// stiffness when no row is zero.
void read_compliance(const YamlReader& r, const YAML::Node& n, const std::string& k, Section& s) {
    const Mat6 C = r.mat6(n, k);
    if (!symmetric(C)) r.fail(n, k, "compliance matrix is not symmetric");
    std::vector<int> flexible;
    for (int i = 0; i < 6; ++i) {
        if (C.row(i).cwiseAbs().maxCoeff() > 0.0) flexible.push_back(i);
    }
    if (flexible.empty()) r.fail(n, k, "compliance is zero: the section is rigid");
    const auto m = static_cast<Eigen::Index>(flexible.size());
    Eigen::MatrixXd sub(m, m);
    for (Eigen::Index i = 0; i < m; ++i) {
        for (Eigen::Index j = 0; j < m; ++j) {
            sub(i, j) = C(flexible[static_cast<size_t>(i)], flexible[static_cast<size_t>(j)]);
        }
    }
    check_section_matrix(r, n, k, sub, flexible, "compliance matrix (without its zero rows)");
    s.compliance = 0.5 * (C + C.transpose());
    if (flexible.size() == 6) s.stiffness = s.compliance.inverse();
}

// `mass` (6×6) or `density` (isotropic sections: ρA and the rotary inertias), and `damping`.
void read_inertia_and_damping(const YamlReader& r, const YAML::Node& n, const std::string& key,
                              double area, const Vec3& inertia, Section& s) {
    if (n["mass"] && n["density"])
        r.fail(n["density"], key + ".density", "give mass or density, not both");
    if (n["density"]) {
        if (!n["isotropic"]) {
            r.fail(n["density"], key + ".density", "density needs an isotropic section; give mass");
        }
        const double rho = r.positive(n["density"], key + ".density");
        Mat6 M = Mat6::Zero();
        M.diagonal() << rho * area, rho * area, rho * area, rho * inertia[0], rho * inertia[1],
            rho * inertia[2];
        const std::string problem =
            range_problem(M.diagonal(), {"ρA", "ρA", "ρA", "ρ(I2 + I3)", "ρI2", "ρI3"}, "mass");
        if (!problem.empty()) r.fail(n["density"], key + ".density", problem);
        s.mass = M;
    } else if (n["mass"]) {
        const Mat6 M = r.mat6(n["mass"], key + ".mass");
        if (!symmetric(M)) r.fail(n["mass"], key + ".mass", "mass matrix is not symmetric");
        check_section_matrix(r, n["mass"], key + ".mass", M, all_rows(), "mass matrix");
        s.mass = 0.5 * (M + M.transpose());
    }
    if (n["damping"]) {
        s.damping = r.vec6(n["damping"], key + ".damping");
        if (s.damping.minCoeff() < 0.0)
            r.fail(n["damping"], key + ".damping", "must not be negative");
    }
}

Section read_section(const YamlReader& r, const YAML::Node& n, const std::string& key) {
    r.expect_map(n, key, {"isotropic", "stiffness", "compliance", "mass", "density", "damping"});
    const int given =
        (n["isotropic"] ? 1 : 0) + (n["stiffness"] ? 1 : 0) + (n["compliance"] ? 1 : 0);
    if (given != 1) {
        r.fail(n, key,
               given == 0 ? "missing required key: one of isotropic, stiffness, compliance"
                          : "give exactly one of isotropic, stiffness, compliance");
    }
    Section s;
    double area = 0.0;
    Vec3 inertia = Vec3::Zero();
    if (n["isotropic"]) {
        const Mat6 K = isotropic_stiffness(r, n["isotropic"], key + ".isotropic", &area, &inertia);
        s.stiffness = K;
        s.compliance = K.inverse();
    } else if (n["stiffness"]) {
        s.stiffness = read_stiffness(r, n["stiffness"], key + ".stiffness");
        s.compliance = s.stiffness->inverse();
    } else {
        read_compliance(r, n["compliance"], key + ".compliance", s);
    }
    read_inertia_and_damping(r, n, key, area, inertia, s);
    return s;
}

ReferenceLine read_line(const YamlReader& r, const YAML::Node& n, const std::string& key) {
    ReferenceLine line;
    if (n.IsScalar()) {
        r.choice(n, key, {"straight"});  // arcs and key-point curves need more data
        return line;
    }
    r.expect_map(n, key, {"type", "center", "normal", "points"});
    const std::string type =
        r.choice(r.required(n, key, "type"), key + ".type", {"straight", "arc", "keypoints"});
    const auto only_for = [&](const char* k, const std::string& kind) {
        if (n[k] && type != kind) r.fail(n[k], child_key(key, k), "only for type " + kind);
    };
    only_for("center", "arc");
    only_for("normal", "arc");
    only_for("points", "keypoints");
    if (type == "arc") {
        line.kind = LineKind::arc;
        line.center = r.vec3(r.required(n, key, "center"), key + ".center");
        if (n["normal"]) line.normal = r.vec3(n["normal"], key + ".normal");
    } else if (type == "keypoints") {
        line.kind = LineKind::keypoints;
        const YAML::Node pts = r.required(n, key, "points");
        if (!pts.IsSequence() || pts.size() == 0) {
            r.fail(pts, key + ".points", "expected a non-empty list of [x, y, z] interior points");
        }
        for (size_t i = 0; i < pts.size(); ++i) {
            line.keypoints.push_back(r.vec3(pts[i], key + ".points[" + std::to_string(i) + "]"));
        }
    }
    return line;
}

void read_member_sections(const YamlReader& r, const YAML::Node& n, const std::string& key,
                          const SectionTable& sections, Member& m) {
    std::vector<std::string> names;
    for (const auto& [name, s] : sections) names.push_back(name);
    if (n["section"] && n["sections"])
        r.fail(n["sections"], key + ".sections", "give section or sections, not both");
    if (n["section"]) {
        const std::string name = r.name_in(n["section"], key + ".section", names, "section");
        m.sections.push_back({0.0, sections.at(name)});
        return;
    }
    const YAML::Node list = n["sections"];
    if (!list) r.fail(n, key + ".section", "missing required key (or give sections)");
    const std::string lk = key + ".sections";
    if (!list.IsSequence() || list.size() < 2) {
        r.fail(list, lk, "expected a list of at least 2 stations {at: s/L, section: name}");
    }
    for (size_t i = 0; i < list.size(); ++i) {
        const std::string ik = lk + "[" + std::to_string(i) + "]";
        r.expect_map(list[i], ik, {"at", "section"});
        const double at = r.number(r.required(list[i], ik, "at"), ik + ".at");
        const bool first = i == 0, last = i + 1 == list.size();
        if ((first && at != 0.0) || (last && at != 1.0) || at < 0.0 || at > 1.0 ||
            (!first && at <= m.sections.back().s_fraction)) {
            r.fail(list[i]["at"], ik + ".at", "stations must increase from 0 to 1 (s/L)");
        }
        const std::string name =
            r.name_in(r.required(list[i], ik, "section"), ik + ".section", names, "section");
        m.sections.push_back({at, sections.at(name)});
    }
}

Member read_member(const YamlReader& r, const YAML::Node& n, const std::string& key,
                   const std::string& name, const SectionTable& sections, const Model& model) {
    r.expect_map(n, key, {"from", "to", "line", "e2", "twist", "section", "sections", "elements"});
    Member m;
    m.name = name;
    const std::vector<std::string> points = point_names(model);
    m.start_point =
        model.point_index(r.name_in(r.required(n, key, "from"), key + ".from", points, "point"));
    m.end_point =
        model.point_index(r.name_in(r.required(n, key, "to"), key + ".to", points, "point"));
    if (m.start_point == m.end_point)
        r.fail(n["to"], key + ".to", "a member must join two different points");
    if (n["line"]) m.line = read_line(r, n["line"], key + ".line");
    if (n["e2"]) m.line.e2_hint = r.vec3(n["e2"], key + ".e2");
    if (const YAML::Node t = n["twist"]) {
        const std::vector<double> tw = r.numbers(t, key + ".twist");
        if (tw.size() > kMaxTwistValues)
            r.fail(t, key + ".twist",
                   "expected one angle, [start, end] or at most " +
                       std::to_string(kMaxTwistValues) + " angles at equally spaced s/L (radians)");
        m.twist_start = tw.front();
        m.twist_end = tw.back();
        if (tw.size() > 2) m.twist_values = tw;
    }
    read_member_sections(r, n, key, sections, m);
    m.elements = r.positive_integer(r.required(n, key, "elements"), key + ".elements",
                                    kMaxElementsPerMember);
    return m;
}

}  // namespace

void read_points(const YamlReader& r, const YAML::Node& root, Model& model) {
    const YAML::Node pts = r.required(root, "", "points");
    r.expect_named_map(pts, "points");
    for (const auto& item : pts) {
        const std::string name = item.first.Scalar();
        model.points.push_back({name, r.vec3(item.second, "points." + name)});
    }
}

SectionTable read_sections(const YamlReader& r, const YAML::Node& root) {
    const YAML::Node secs = r.required(root, "", "sections");
    r.expect_named_map(secs, "sections");
    SectionTable table;
    for (const auto& item : secs) {
        const std::string name = item.first.Scalar();
        table[name] = read_section(r, item.second, "sections." + name);
        table[name].name = name;
    }
    return table;
}

void read_members(const YamlReader& r, const YAML::Node& root, const SectionTable& sections,
                  Model& model) {
    const YAML::Node members = r.required(root, "", "members");
    r.expect_named_map(members, "members");
    for (const auto& item : members) {
        const std::string name = item.first.Scalar();
        const std::string key = "members." + name;
        model.members.push_back(read_member(r, item.second, key, name, sections, model));
        // The geometry refuses coincident ends, inconsistent arcs, coincident key points;
        // elements too short for double arithmetic are refused with their length (a straight
        // member's before the geometry divides by it).
        try {
            const Member& member = model.members.back();
            if (member.line.kind == LineKind::straight ||
                (member.line.kind == LineKind::keypoints && member.line.keypoints.empty())) {
                const double chord = chord_length(model, member);
                const std::string problem = element_length_problem(model, member, chord);
                if (chord > 0.0 && !problem.empty()) throw InputError(problem);
            }
            const ReferenceGeometry g(model, static_cast<int>(model.members.size()) - 1);
            // Coordinates so large (or a member so long) that the length, the frame or the
            // curvature overflow would reach the solver as NaN: refused here, with the length.
            bool finite = std::isfinite(g.length());
            for (double f : {0.0, 0.5, 1.0}) {
                if (!finite) break;
                finite = g.frame(f * g.length()).allFinite() &&
                         g.curvature(f * g.length()).allFinite() &&
                         g.position(f * g.length()).allFinite();
            }
            if (!finite) {
                std::ostringstream m;
                m << "its geometry overflows double precision (length " << g.length()
                  << "): use units that keep coordinates well below 1e150";
                throw InputError(m.str());
            }
            const std::string problem = element_length_problem(model, member, g.length());
            if (!problem.empty()) throw InputError(problem);
        } catch (const InputError& e) {
            const YAML::Node line = item.second["line"];
            r.fail(line ? line : item.second, line ? key + ".line" : key, e.what());
        }
    }
}

}  // namespace rotbeam::cases
