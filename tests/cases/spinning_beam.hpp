// What the spinning-beam tests (test_rotating_frame, test_rotating_dynamics) share: the case file
// of a uniform spinning beam, a run of a case written in code
// (without the error estimate: the tests compare with closed forms), and what counts as solved.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cases/loader/case_loader.hpp"
#include "combinations/registry.hpp"
#include "core/so3.hpp"
#include "core/types.hpp"
#include "runs/run_case.hpp"

namespace rotbeam::test {

// A uniform beam of length 1 along x from the origin, clamped at the root, with diagonal 6×6
// stiffness and mass matrices (m = 1, rotary inertias 1e-6 by default), the same damping factor μ
// on every component (none when 0), turning at Ω about the axis through `center`.
struct SpinningBeam {
    std::array<double, 6> stiffness{};
    std::array<double, 6> mass{1.0, 1.0, 1.0, 2e-6, 1e-6, 1e-6};
    double damping = 0.0;
    Vec3 angular_velocity = Vec3::Zero();
    Vec3 center = Vec3::Zero();
    int elements = 1;
    int order = 1;
    bool mixed = false;  // the mixed formulation (no element order) instead of the displacement one
    std::string loads;   // the YAML lines under `loads:` (none when empty)
};

// The case file of `beam` with `analysis` (the YAML lines under `analysis:`).
inline std::string spinning_beam_case(const std::string& analysis, const SpinningBeam& beam) {
    std::ostringstream c;
    c << std::setprecision(17);
    const auto matrix = [&c](const std::array<double, 6>& d) {
        for (int i = 0; i < 6; ++i) {
            c << "      - [";
            for (int j = 0; j < 6; ++j) c << (j ? ", " : "") << (i == j ? d[i] : 0.0);
            c << "]\n";
        }
    };
    const auto vec = [&c](const Vec3& v) {
        c << "[" << v.x() << ", " << v.y() << ", " << v.z() << "]";
    };
    c << "name: spinning-beam\n"
      << "points: {root: [0, 0, 0], tip: [1, 0, 0]}\n"
      << "sections:\n  s:\n    stiffness:\n";
    matrix(beam.stiffness);
    c << "    mass:\n";
    matrix(beam.mass);
    if (beam.damping > 0.0) {
        c << "    damping: [" << beam.damping;
        for (int i = 1; i < 6; ++i) c << ", " << beam.damping;
        c << "]\n";
    }
    c << "members:\n  beam: {from: root, to: tip, section: s, elements: " << beam.elements << "}\n"
      << "constraints: {root: clamped}\n"
      << "rotating_frame: {angular_velocity: ";
    vec(beam.angular_velocity);
    c << ", center: ";
    vec(beam.center);
    c << "}\n";
    if (!beam.loads.empty()) c << "loads:\n" << beam.loads;
    c << "analysis:\n" << analysis;
    if (beam.mixed) {
        c << "discretization: {formulation: mixed}\n";
    } else {
        c << "discretization: {formulation: displacement, order: " << beam.order << "}\n";
    }
    return c.str();
}

inline nlohmann::json run_spinning_case(const std::string& text,
                                        const std::vector<std::string>& overrides = {}) {
    RunRequest request;
    request.model = load_case_text(text, "spinning-beam.yaml", overrides);
    request.model.analysis.estimate = false;
    return run_case(request);
}

inline bool solved(const nlohmann::json& r) {
    const std::string s = r["status"].get<std::string>();
    return s == "converged" || s == "stalled-at-round-off";
}

inline Vec3 json_vec3(const nlohmann::json& j) {
    return Vec3(j[0].get<double>(), j[1].get<double>(), j[2].get<double>());
}

// How far a run of the beam turning at Ω about z through (−R0, 0, 0) departs from a steady
// spinning state whose tip displacement relative to the frame is `steady`: the largest distance
// of the relative tip displacement from it, and of the inertial tip displacement from that state
// turned by exp(t Ω ẑ) about the centre (the tip of the unit beam is at X = (1, 0, 0)).
struct SpinningDeparture {
    double relative = 0.0;
    double inertial = 0.0;
};
inline SpinningDeparture departure_from_steady_spin(const nlohmann::json& r, const Vec3& steady,
                                                    double Omega, double R0) {
    SpinningDeparture d;
    const Vec3 X(1, 0, 0), c(-R0, 0, 0);
    for (const nlohmann::json& step : r["steps"]) {
        const double t = step["time"].get<double>();
        const Vec3 u = json_vec3(step["rotating_frame"]["points"]["tip"]["displacement"]);
        d.relative = std::max(d.relative, (u - steady).norm());
        const Vec3 expected = c + so3::exp_map(Vec3(0, 0, Omega * t)) * (X + steady - c) - X;
        const Vec3 ui = json_vec3(step["points"]["tip"]["displacement"]);
        d.inertial = std::max(d.inertial, (ui - expected).norm());
    }
    return d;
}

// How far a run departs from the rigid rotation about the axis Ω through `center` (the tip of the
// unit beam, X = (1, 0, 0), at center + exp(t Ω̃)(X − center), its section turned by exp(t Ω̃)):
// the largest tip position error and the largest |R − exp(t Ω̃)| (Frobenius) over the outputs.
struct RigidRotationDeparture {
    double position = 0.0;
    double rotation = 0.0;
};
inline RigidRotationDeparture departure_from_rigid_rotation(const nlohmann::json& r,
                                                            const Vec3& Omega, const Vec3& center) {
    RigidRotationDeparture d;
    const Vec3 X(1, 0, 0);
    for (const nlohmann::json& step : r["steps"]) {
        const Mat3 Q = so3::exp_map(step["time"].get<double>() * Omega);
        const Vec3 u = json_vec3(step["points"]["tip"]["displacement"]);
        d.position = std::max(d.position, (u - (center + Q * (X - center) - X)).norm());
        Mat3 R;
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) {
                R(i, j) = step["points"]["tip"]["rotation_matrix"][i][j].get<double>();
            }
        }
        d.rotation = std::max(d.rotation, (R - Q).norm());
    }
    return d;
}

// The `analysis:` lines of a dynamic run over one turn of the frame turning at Ω, in `steps` time
// steps with `outputs` output times.
inline std::string one_turn_analysis(const Vec3& Omega, int steps = 100, int outputs = 10) {
    const double turn = 2.0 * std::acos(-1.0) / Omega.norm();
    std::ostringstream a;
    a << std::setprecision(17) << "  type: dynamic\n  time_step: " << turn / steps
      << "\n  end_time: " << turn << "\n  output_interval: " << turn / outputs << "\n";
    return a.str();
}

// The tip of the spinning beam stretched by its centrifugal load, in closed form:
// EA u″ + m Ω² (R0 + x + u) = 0, u(0) = 0, N(1) = 0 (m = 1, length 1, hub radius R0):
// u(1) = −(R0 + 1) + C sin k + R0 cos k, k = Ω/√EA.
inline double stretch_tip(double Omega, double R0, double EA) {
    const double k = Omega / std::sqrt(EA);
    const double C = (1.0 + R0 * k * std::sin(k)) / (k * std::cos(k));
    return -(R0 + 1.0) + C * std::sin(k) + R0 * std::cos(k);
}

// Every parameterization of `formulation` with each of `integrators`, as --set overrides
// {discretization.rotation=…, analysis.integrator=…}; `override_label` names one.
inline std::vector<std::vector<std::string>> dynamic_overrides(
    Formulation formulation, const std::vector<std::string>& integrators) {
    std::vector<std::vector<std::string>> out;
    for (const comb::Combination& c : comb::all_combinations(false)) {
        if (c.formulation != formulation) continue;
        for (const std::string& integrator : integrators) {
            out.push_back({"discretization.rotation=" + c.rotation_name(),
                           "analysis.integrator=" + integrator});
        }
    }
    return out;
}
inline std::string override_label(const std::vector<std::string>& o) { return o[0] + " " + o[1]; }

// The largest departure of a run's Jacobi integral (the energy in the turning frame, conserved
// without damping) from its first value, relative to the largest strain energy the run reaches.
inline double jacobi_integral_drift(const nlohmann::json& r) {
    const double J0 = r["steps"][0]["energy"]["jacobi_integral"].get<double>();
    double moved = 0.0, drift = 0.0;
    for (const nlohmann::json& step : r["steps"]) {
        moved = std::max(moved, step["energy"]["strain"].get<double>());
        drift = std::max(drift, std::abs(step["energy"]["jacobi_integral"].get<double>() - J0));
    }
    return drift / moved;
}

// The `analysis:` lines of a dynamic run with fixed time step h from 0 to `end_time`.
inline std::string fixed_step_analysis(double h, double end_time) {
    std::ostringstream a;
    a << std::setprecision(17) << "  type: dynamic\n  time_step: " << h
      << "\n  end_time: " << end_time << "\n";
    return a.str();
}

}  // namespace rotbeam::test
