#include "core/kinematic_check.hpp"

#include <sstream>

#include "core/so3.hpp"

namespace rotbeam {

namespace {
double bound(double turn) { return kMaxRelativeDefect * turn + kDefectRoundOff; }
}  // namespace

std::optional<KinematicDefect> worst_kinematic_defect(
    const std::vector<StaticProblem::RotationStation>& stations) {
    std::optional<KinematicDefect> worst;
    int element = 0;
    for (std::size_t k = 1; k + 1 < stations.size(); ++k) {
        const StaticProblem::RotationStation& s = stations[k];
        if (s.member != stations[k - 1].member) element = 0;
        if (s.node) continue;
        ++element;
        const Mat3 relative = stations[k - 1].rotation.transpose() * stations[k + 1].rotation;
        KinematicDefect d;
        d.member = s.member;
        d.element = element;
        d.turn = s.turn.norm();
        d.defect = so3::rotation_angle(so3::exp_map(s.turn).transpose() * relative);
        if (!worst || d.defect / bound(d.turn) > worst->defect / bound(worst->turn)) worst = d;
    }
    return worst;
}

bool within_kinematic_bound(const KinematicDefect& d) { return d.defect <= bound(d.turn); }

std::string describe_kinematic_defect(const Model& model, const KinematicDefect& d) {
    std::ostringstream s;
    s.precision(4);
    s << "element " << d.element << " of member '"
      << model.members.at(static_cast<std::size_t>(d.member)).name << "' turns by " << d.turn
      << " rad with its curvature, its nodes by a rotation " << d.defect << " rad away from that ("
      << 100.0 * d.defect / (d.turn > 0.0 ? d.turn : 1.0) << " % of the turn; bound "
      << 100.0 * kMaxRelativeDefect << " %, a quaternion element's at a turn of pi/2)";
    return s.str();
}

}  // namespace rotbeam
