#include "core/oracles/manufactured.hpp"

#include <cmath>

#include "core/oracles/manufactured_rod.hpp"
#include "core/so3.hpp"

namespace rotbeam::oracle {

namespace {

const Vec3 kE1 = Vec3::UnitX();
const Vec3 kE3 = Vec3::UnitZ();

// α(s), β(s) and their first two derivatives in s.
struct Angles {
    double alpha, alpha1, alpha2, beta, beta1, beta2;
};

Angles angles(const ManufacturedRod& rod, double s, double lambda) {
    const double L = rod.length, k = kPi / L;
    const double sn = std::sin(k * s), cs = std::cos(k * s);
    Angles g;
    g.alpha = lambda * rod.a * (s / L + 0.1 * sn);
    g.alpha1 = lambda * rod.a * (1.0 / L + 0.1 * k * cs);
    g.alpha2 = -lambda * rod.a * 0.1 * k * k * sn;
    g.beta = lambda * rod.b * sn;
    g.beta1 = lambda * rod.b * k * cs;
    g.beta2 = -lambda * rod.b * k * k * sn;
    return g;
}

// w(s) and its derivatives: u = λ w.
void shape(double L, double s, Vec3& w, Vec3& w1, Vec3& w2) {
    const double x = s / L, k = 0.5 * kPi / L;
    w = L * Vec3(-0.2 * x * x, 0.3 * std::sin(k * s), 0.25 * x * x * x);
    w1 = Vec3(-0.4 * x, 0.3 * L * k * std::cos(k * s), 0.75 * x * x);
    w2 = Vec3(-0.4 / L, -0.3 * L * k * k * std::sin(k * s), 1.5 * x / L);
}

}  // namespace

ManufacturedRod::State ManufacturedRod::state(double s, double lambda) const {
    const Angles g = angles(*this, s, lambda);
    Vec3 w, w1, w2;
    shape(length, s, w, w1, w2);
    State out;
    out.displacement = lambda * w;
    out.rotation = so3::exp_map(g.alpha * kE1) * so3::exp_map(g.beta * kE3);
    return out;
}

void ManufacturedRod::loads(double s, double lambda, Vec3& force, Vec3& moment) const {
    const Angles g = angles(*this, s, lambda);
    Vec3 w, w1, w2;
    shape(length, s, w, w1, w2);
    const Mat3 A = so3::exp_map(g.alpha * kE1);
    const Mat3 R = A * so3::exp_map(g.beta * kE3);
    const Vec3 Ae3 = A * kE3;
    // Spatial curvature k = axial(R′Rᵀ) = α′e₁ + β′ A e₃ and its derivative (A′ = α′ ẽ₁ A).
    const Vec3 k = g.alpha1 * kE1 + g.beta1 * Ae3;
    const Vec3 k1 = g.alpha2 * kE1 + g.beta2 * Ae3 + g.beta1 * g.alpha1 * kE1.cross(Ae3);
    const Vec3 x1 = kE1 + lambda * w1;  // x′
    const Vec3 x2 = lambda * w2;        // x″
    const SpatialResultants r = spatial_resultants(R, k, k1, x1, x2, stiffness);
    force = -r.n1;
    moment = -r.m1 - x1.cross(r.n);
}

Mat6 manufactured_section() {
    // Diagonal [EA, GA₂, GA₃, GJ, EI₂, EI₃] = [10, 8, 6, 2, 3, 4] with couplings of a tenth of
    // the geometric mean of the two diagonal entries (extension–twist, shear–bending, bending–
    // bending): strictly diagonally dominant, hence SPD.
    Vec6 d;
    d << 10.0, 8.0, 6.0, 2.0, 3.0, 4.0;
    Mat6 C = Mat6(d.asDiagonal());
    const int pairs[4][2] = {{0, 3}, {1, 5}, {2, 4}, {4, 5}};
    for (const auto& p : pairs) {
        const double c = 0.1 * std::sqrt(d[p[0]] * d[p[1]]);
        C(p[0], p[1]) = C(p[1], p[0]) = c;
    }
    return C;
}

Model manufactured_model(const ManufacturedRod& rod, int elements_per_member, int steps) {
    Model model;
    model.name = "manufactured";
    model.description = "Manufactured static solution: rotation past 2π about a varying axis";
    const double L = rod.length;
    Section section;
    section.name = "manufactured";
    section.stiffness = rod.stiffness;
    section.compliance = rod.stiffness.inverse();
    add_four_member_rod(model, rod.length, section, elements_per_member, [rod](double s0) {
        LoadField field;
        field.density = [rod, s0](double s, double lambda, Vec3& f, Vec3& m) {
            rod.loads(s0 + s, lambda, f, m);
        };
        return field;
    });
    Constraint root;
    root.point = 0;
    Constraint tip;
    tip.point = 4;
    tip.kind = Constraint::Kind::prescribed;
    tip.displacement = rod.state(L, 1.0).displacement;  // u(L, λ) = λ w(L)
    tip.rotation = rod.a * kE1;                         // R(L, λ) = exp(λ a ẽ₁)
    model.constraints = {root, tip};
    model.analysis.kind = AnalysisKind::static_;
    for (int k = 1; k <= steps; ++k) {
        model.analysis.statics.load_factors.push_back(static_cast<double>(k) / steps);
    }
    return model;
}

}  // namespace rotbeam::oracle
