#include "cases/loader/beamdyn_import.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <sstream>

#include "cases/loader/beamdyn_geometry.hpp"
#include "core/errors.hpp"

namespace rotbeam::cases {

namespace {

using Matrix6 = std::array<std::array<double, 6>, 6>;

// Samples of a curved member's fitted line handed to the key-point curve (a natural cubic spline
// through them), at the Chebyshev–Lobatto points of ξ: the spline's end condition (zero
// curvature) differs from the fit's, an error of the order of the end interval squared, which
// the clustering makes small (the spline's distance from the fit is measured in
// tests/cases/test_beamdyn_import.cpp).
constexpr int kCurveSamples = 512;
// A fitted line is straight when no sample is farther than this from the chord (relative to the
// chord length): the fit of collinear key points is exact to round-off.
constexpr double kStraightTolerance = 1e-12;

std::string num(double v) {
    char buffer[40];
    std::snprintf(buffer, sizeof buffer, "%.17g", v);
    return buffer;
}

std::string vec(const Vec3& v) {
    std::ostringstream os;
    os << "[" << num(v(0)) << ", " << num(v(1)) << ", " << num(v(2)) << "]";
    return os.str();
}

struct RootFrame {
    Vec3 position = Vec3::Zero();
    Mat3 to_global = Mat3::Identity();  // GlbDCMᵀ: root frame → global
};

RootFrame root_frame(const BeamDynDeck& deck) {
    RootFrame f;
    Mat3 dcm;
    for (int i = 0; i < 3; ++i) {
        f.position(i) = deck.root_position[static_cast<size_t>(i)];
        for (int j = 0; j < 3; ++j) {
            dcm(i, j) = deck.root_dcm[static_cast<size_t>(i)][static_cast<size_t>(j)];
        }
    }
    // The deck prints 8 significant digits: orthonormal to 1e-6.
    if (!((dcm * dcm.transpose() - Mat3::Identity()).cwiseAbs().maxCoeff() <= 1e-6) ||
        !(dcm.determinant() > 0.0)) {
        throw InputError(deck.driver_name + ":" + std::to_string(deck.dcm_line) +
                         ": GlbDCM: not a rotation (orthonormal to 1e-6 with determinant +1)");
    }
    f.to_global = dcm.transpose();
    return f;
}

Matrix6 permuted(const Matrix6& m) {
    Matrix6 out{};
    for (int i = 0; i < 6; ++i) {
        for (int j = 0; j < 6; ++j) {
            out[static_cast<size_t>(i)][static_cast<size_t>(j)] =
                m[static_cast<size_t>(kBeamDynRow[i])][static_cast<size_t>(kBeamDynRow[j])];
        }
    }
    return out;
}

bool is_zero(const Matrix6& m) {
    for (const auto& row : m) {
        for (double v : row) {
            if (v != 0.0) return false;
        }
    }
    return true;
}

// The properties at blade fraction eta, linear between stations (BeamDyn.f90,
// InitializeMassStiffnessMatrices).
BeamDynStation at_eta(const std::vector<BeamDynStation>& stations, double eta) {
    size_t k = 1;
    while (k + 1 < stations.size() && stations[k].eta < eta) ++k;
    const BeamDynStation& a = stations[k - 1];
    const BeamDynStation& b = stations[k];
    const double t = std::clamp((eta - a.eta) / (b.eta - a.eta), 0.0, 1.0);
    BeamDynStation s;
    s.eta = eta;
    for (size_t i = 0; i < 6; ++i) {
        for (size_t j = 0; j < 6; ++j) {
            s.stiffness[i][j] = (1.0 - t) * a.stiffness[i][j] + t * b.stiffness[i][j];
            s.mass[i][j] = (1.0 - t) * a.mass[i][j] + t * b.mass[i][j];
        }
    }
    return s;
}

bool same_properties(const BeamDynStation& a, const BeamDynStation& b) {
    return a.stiffness == b.stiffness && a.mass == b.mass;
}

void write_matrix(std::ostringstream& os, const char* key, const Matrix6& m) {
    os << "    " << key << ":\n";
    for (const auto& row : m) {
        os << "      - [";
        for (size_t j = 0; j < 6; ++j) os << (j ? ", " : "") << num(row[j]);
        os << "]\n";
    }
}

// One rotbeam member: its line, frame rule, twist and sections.
struct MemberText {
    std::string yaml;
    std::vector<std::pair<std::string, BeamDynStation>> sections;
};

class Importer {
  public:
    Importer(const BeamDynDeck& deck) : deck_(deck), frame_(root_frame(deck)) {}

    std::string text(const std::string& name);

  private:
    std::string point_name(size_t member_end) const {
        if (member_end == 0) return "root";
        if (member_end == deck_.member_key_points.size()) return "tip";
        return "joint-" + std::to_string(member_end);
    }
    [[noreturn]] void fail_member(size_t m, const std::string& key,
                                  const std::string& problem) const {
        throw InputError(deck_.primary_name + ":" + std::to_string(deck_.key_points_line) + ": " +
                         key + ": member " + std::to_string(m + 1) + ": " + problem);
    }
    MemberText member(size_t m, int first, const BeamDynMemberLine& line, double eta0,
                      double eta1) const;

    const BeamDynDeck& deck_;
    RootFrame frame_;
};

MemberText Importer::member(size_t m, int first, const BeamDynMemberLine& line, double eta0,
                            double eta1) const {
    const int count = deck_.member_key_points[m];
    const BeamDynKeyPoint& a = deck_.key_points[static_cast<size_t>(first)];
    const BeamDynKeyPoint& b =
        deck_.key_points[static_cast<size_t>(first) + static_cast<size_t>(count) - 1];
    const Vec3 x0(a.x, a.y, a.z);
    const Vec3 x1(b.x, b.y, b.z);
    const double chord = (x1 - x0).norm();
    bool straight = true;
    bool planar_xz = true;  // the line keeps y constant: BeamDyn's x axis is the projected x̂
    for (int i = 0; i <= 64; ++i) {
        const double xi = -1.0 + i / 32.0;
        const Vec3 x = line.position(xi);
        const Vec3 t = line.derivative(xi);
        if (!(t(2) > 0.0)) {
            fail_member(m, "kp_zr",
                        "the fitted line must advance along z everywhere (BeamDyn's "
                        "section frame is undefined where its tangent has z ≤ 0)");
        }
        const Vec3 d = (x1 - x0) / chord;
        if (((x - x0) - d * d.dot(x - x0)).norm() > kStraightTolerance * chord) straight = false;
        if (std::abs(x(1) - x0(1)) > kStraightTolerance * chord) planar_xz = false;
    }
    std::ostringstream os;
    os << "  member-" << m + 1 << ":\n    from: " << point_name(m)
       << "\n    to: " << point_name(m + 1) << "\n";
    // BeamDyn's section x axis: normalize(ŷ × t) (BD_ComputeIniNodalCrv) = rotbeam's e2.
    const Vec3 t0 = line.derivative(-1.0).normalized();
    if (straight) {
        os << "    line: straight\n";
        os << "    e2: " << vec(frame_.to_global * Vec3::UnitY().cross(t0).normalized()) << "\n";
    } else {
        if (deck_.quadrature == 2) {
            throw InputError(deck_.primary_name + ":" + std::to_string(deck_.quadrature_line) +
                             ": quadrature: trapezoidal quadrature on a curved member is not "
                             "imported: BeamDyn places its points at the stations' fractions of "
                             "the key points' z-parameter, rotbeam at fractions of arc length");
        }
        if (!planar_xz) {
            fail_member(m, "kp_yr",
                        "a curved line that leaves the x-z plane is not imported: BeamDyn's "
                        "section axis normalize(y × tangent) is not rotbeam's e2 rule there");
        }
        os << "    line:\n      type: keypoints\n      points:\n";
        for (int i = 1; i < kCurveSamples; ++i) {
            const double xi = -std::cos(std::numbers::pi * i / kCurveSamples);
            os << "        - " << vec(frame_.position + frame_.to_global * line.position(xi))
               << "\n";
        }
        // The projection of x̂ onto the normal plane is normalize(ŷ × t) when t_y = 0, t_z > 0.
        os << "    e2: " << vec(frame_.to_global * Vec3::UnitX()) << "\n";
    }
    // Twist: BeamDyn's fitted polynomial of degree q − 1 in ξ. A straight member's ξ is
    // proportional to arc length, so the polynomial through its values at q equally spaced
    // s/L is the same polynomial (rotbeam's member twist list); a linear one is written as
    // [start, end]. A curved member's ξ is not proportional to arc length, so there the twist
    // must be constant.
    const double tw0 = line.twist_rad(-1.0);
    const double tw1 = line.twist_rad(1.0);
    bool linear_twist = true;
    for (int i = 0; i <= 64; ++i) {
        const double xi = -1.0 + i / 32.0;
        const double linear = tw0 + (tw1 - tw0) * (xi + 1.0) / 2.0;
        const double expected = straight ? linear : tw0;
        if (std::abs(line.twist_rad(xi) - expected) >
            1e-10 * (1.0 + std::abs(tw0) + std::abs(tw1))) {
            if (!straight) {
                fail_member(m, "initial_twist",
                            "a twist that varies along a curved member is not modelled");
            }
            linear_twist = false;
        }
    }
    if (!linear_twist) {
        const int q = line.fit_points();
        os << "    twist: [";
        for (int i = 0; i < q; ++i) {
            os << (i > 0 ? ", " : "") << num(line.twist_rad(-1.0 + 2.0 * i / (q - 1)));
        }
        os << "]\n";
    } else if (tw0 != 0.0 || tw1 != 0.0) {
        os << "    twist: [" << num(tw0) << ", " << num(tw1) << "]\n";
    }
    // Sections: the blade stations inside [eta0, eta1] and the properties at its ends.
    MemberText out;
    std::vector<std::pair<double, std::string>> at;
    auto add = [&](double position, const std::string& section, const BeamDynStation& s) {
        out.sections.emplace_back(section, s);
        at.emplace_back(position, section);
    };
    size_t k = 0;
    while (k < deck_.stations.size() && deck_.stations[k].eta <= eta0) ++k;
    const BeamDynStation start = at_eta(deck_.stations, eta0);
    add(0.0, "member-" + std::to_string(m + 1) + "-start", start);
    for (; k < deck_.stations.size() && deck_.stations[k].eta < eta1; ++k) {
        add((deck_.stations[k].eta - eta0) / (eta1 - eta0), "station-" + std::to_string(k + 1),
            deck_.stations[k]);
    }
    add(1.0, "member-" + std::to_string(m + 1) + "-end", at_eta(deck_.stations, eta1));
    // Trapezoidal quadrature places its points at the stations: keep them all.
    bool constant = deck_.quadrature != 2;
    for (const auto& [section_name, s] : out.sections)
        constant = constant && same_properties(s, start);
    if (constant) {
        out.sections.resize(1);
        os << "    section: " << out.sections[0].first << "\n";
    } else {
        if (!straight) {
            throw InputError(deck_.blade_name + ":" + std::to_string(deck_.stations_line) +
                             ": station_eta: properties that vary along a curved member (" +
                             std::to_string(m + 1) +
                             ") are not imported: BeamDyn interpolates them in the key points' "
                             "z-parameter, rotbeam in arc length");
        }
        os << "    sections:\n";
        for (const auto& [position, section] : at) {
            os << "      - {at: " << num(position) << ", section: " << section << "}\n";
        }
    }
    os << "    elements: 1\n";
    out.yaml = os.str();
    return out;
}

std::string Importer::text(const std::string& name) {
    // BeamDyn's trapezoidal rule has (stations − 1) refine + 1 points on its one element; fewer
    // than its order + 1 nodes leave the element's matrices singular (mesh.hpp refuses them).
    const size_t trapezoid_points = (deck_.stations.size() - 1) * deck_.refine + 1;
    if (deck_.quadrature == 2 && trapezoid_points < static_cast<size_t>(deck_.order) + 1) {
        throw InputError(deck_.primary_name + ":" + std::to_string(deck_.refine_line) +
                         ": refine: trapezoidal quadrature with " +
                         std::to_string(trapezoid_points) + " points on an element of order " +
                         std::to_string(deck_.order) +
                         " (fewer points than nodes: its matrices would be singular)");
    }
    // Members, their lines and their share of the blade length (BeamDyn.f90, BD_MemberEta).
    std::vector<BeamDynMemberLine> lines;
    std::vector<int> firsts;
    double total = 0.0;
    int first = 0;
    for (size_t m = 0; m < deck_.member_key_points.size(); ++m) {
        const int count = deck_.member_key_points[m];
        const BeamDynKeyPoint& a = deck_.key_points[static_cast<size_t>(first)];
        const BeamDynKeyPoint& b =
            deck_.key_points[static_cast<size_t>(first) + static_cast<size_t>(count) - 1];
        if (!(b.z > a.z))
            fail_member(m, "kp_zr", "the last key point must lie above the first in z");
        try {
            lines.emplace_back(deck_.key_points, first, count, deck_.order);
        } catch (const InputError& e) {
            fail_member(m, "kp_zr", e.what());
        }
        firsts.push_back(first);
        total += lines.back().length();
        first += count - 1;
    }
    std::ostringstream os;
    os << "# Imported from the BeamDyn deck "
       << std::filesystem::path(deck_.driver_name).filename().string()
       << " by `rotbeam import beamdyn` (docs/beamdyn-import.md).\n";
    os << "name: " << name << "\n";
    os << "description: \"BeamDyn deck " << name << ", imported";
    if (deck_.quadrature == 2) {
        // The deck's quadrature is a choice of the displacement formulation's element; the mixed
        // element has none (its equations are taken at the element mid-point), so a trapezoidal
        // deck run there is the same beam with the mixed formulation's own discretization.
        os << "; trapezoidal quadrature at its " << deck_.stations.size() << " stations, refine "
           << deck_.refine
           << ", in the displacement formulation; the mixed formulation ignores it (element "
              "mid-points)";
    }
    os << "\"\n";
    os << "units: \"m, N, kg, s\"\n";
    os << "points:\n";
    first = 0;
    for (size_t m = 0; m <= deck_.member_key_points.size(); ++m) {
        const BeamDynKeyPoint& p = deck_.key_points[static_cast<size_t>(first)];
        os << "  " << point_name(m) << ": "
           << vec(frame_.position + frame_.to_global * Vec3(p.x, p.y, p.z)) << "\n";
        if (m < deck_.member_key_points.size()) first += deck_.member_key_points[m] - 1;
    }
    std::ostringstream members;
    std::vector<std::pair<std::string, BeamDynStation>> sections;
    double eta = 0.0;
    for (size_t m = 0; m < lines.size(); ++m) {
        const double eta1 = m + 1 == lines.size() ? 1.0 : eta + lines[m].length() / total;
        MemberText t = member(m, firsts[m], lines[m], eta, eta1);
        members << t.yaml;
        for (auto& s : t.sections) sections.push_back(std::move(s));
        eta = eta1;
    }
    os << "sections:\n";
    for (const auto& [section_name, s] : sections) {
        os << "  " << section_name << ":\n";
        write_matrix(os, "stiffness", permuted(s.stiffness));
        if (!is_zero(s.mass)) write_matrix(os, "mass", permuted(s.mass));
        if (deck_.damping_type == 1) {
            os << "    damping: [";
            for (int i = 0; i < 6; ++i) {
                os << (i ? ", " : "") << num(deck_.damping[static_cast<size_t>(kBeamDynRow[i])]);
            }
            os << "]\n";
        }
    }
    os << "members:\n" << members.str();
    os << "constraints:\n  root: clamped\n";
    const auto& tl = deck_.tip_load;
    const auto& dl = deck_.distributed_load;
    const bool tip = std::any_of(tl.begin(), tl.end(), [](double v) { return v != 0.0; });
    const bool distributed = std::any_of(dl.begin(), dl.end(), [](double v) { return v != 0.0; });
    if (tip || distributed) os << "loads:\n";
    if (tip) {
        os << "  tip-load:\n    point: tip\n    force: " << vec(Vec3(tl[0], tl[1], tl[2]))
           << "\n    moment: " << vec(Vec3(tl[3], tl[4], tl[5])) << "\n";
    }
    for (size_t m = 0; distributed && m < lines.size(); ++m) {
        os << "  distributed-load-" << m + 1 << ":\n    member: member-" << m + 1
           << "\n    force: " << vec(Vec3(dl[0], dl[1], dl[2]))
           << "\n    moment: " << vec(Vec3(dl[3], dl[4], dl[5])) << "\n";
    }
    const auto& g = deck_.gravity;
    if (g[0] != 0.0 || g[1] != 0.0 || g[2] != 0.0)
        os << "gravity: " << vec(Vec3(g[0], g[1], g[2])) << "\n";
    const auto& w = deck_.root_velocity;
    if (w[0] != 0.0 || w[1] != 0.0 || w[2] != 0.0) {
        // BeamDyn's driver turns the root about the global origin at RootVel from t_initial.
        os << "rotating_frame:\n  angular_velocity: " << vec(Vec3(w[0], w[1], w[2]))
           << "\n  center: [0, 0, 0]\n";
    }
    if (deck_.dynamic) {
        // BeamDyn steps with DTBeam (DEFAULT: the driver's dt); its generalized-α is
        // Chung–Hulbert's with rhoinf. Time starts at 0 here (t_initial is BeamDyn's clock only).
        // The integrator is left to the formulation: the displacement formulation's default is
        // that generalized-α, and the mixed one then takes its own (its trapezoidal rule) and
        // meets the deck itself (its damping) instead of refusing a scheme it does not have.
        const double step = deck_.beam_dt > 0.0 ? deck_.beam_dt : deck_.dt;
        os << "analysis:\n  type: dynamic\n  # integrator: the formulation's default; the "
              "displacement formulation's is BeamDyn's generalized-alpha\n  rho_infinity: "
           << num(deck_.rho_infinity) << "\n  time_step: " << num(step)
           << "\n  end_time: " << num(deck_.t_final - deck_.t_initial)
           << "\n  output_interval: " << num(deck_.dt)
           << "\n  initial_state: " << (deck_.quasi_static_init ? "static" : "rest") << "\n";
    } else {
        os << "analysis:\n  type: static\n  load_factors: [1]\n";
    }
    os << "discretization:\n  formulation: displacement\n  order: " << deck_.order;
    if (deck_.quadrature == 2) {
        os << "\n  quadrature: trapezoidal\n  refine: " << deck_.refine << "\n";
    } else {
        os << "\n  quadrature: full\n";
    }
    return os.str();
}

// A case name from a folder or file name: letters, digits, '_' and '-' only.
std::string case_name(const std::string& driver_path) {
    const std::filesystem::path p = std::filesystem::absolute(driver_path);
    std::string raw = p.parent_path().filename().string();
    if (raw.empty()) raw = p.stem().string();
    std::string name;
    for (char c : raw) {
        const bool ok = std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
        name += ok ? c : '_';
    }
    return name.empty() ? "beamdyn" : name.substr(0, 64);
}

}  // namespace

std::string beamdyn_case_text(const BeamDynDeck& deck, const std::string& name) {
    return Importer(deck).text(name);
}

std::string import_beamdyn(const std::string& driver_path) {
    return beamdyn_case_text(read_beamdyn_deck(driver_path), case_name(driver_path));
}

}  // namespace rotbeam::cases
