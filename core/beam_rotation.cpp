#include "core/beam_rotation.hpp"

#include <algorithm>
#include <deque>
#include <optional>

#include "core/errors.hpp"
#include "core/so3.hpp"

namespace rotbeam {

namespace {

using Stations = std::vector<StaticProblem::RotationStation>;

// The stations of each member, in arc-length order.
std::vector<std::vector<Mat3>> stations_by_member(const Model& model, const Stations& stations) {
    std::vector<std::vector<Mat3>> by_member(model.members.size());
    for (const StaticProblem::RotationStation& s : stations) {
        if (s.member < 0 || s.member >= static_cast<int>(model.members.size())) {
            throw SolverError("rotation stations name member " + std::to_string(s.member) +
                              ", which the model does not have");
        }
        by_member[static_cast<std::size_t>(s.member)].push_back(s.rotation);
    }
    for (std::size_t m = 0; m < by_member.size(); ++m) {
        if (by_member[m].size() < 2) {
            throw SolverError("member '" + model.members[m].name +
                              "' has fewer than two rotation stations");
        }
    }
    return by_member;
}

}  // namespace

namespace {

struct Continuation {
    std::vector<std::optional<Vec3>> points;  // indexed like model.points
    double largest_angle = 0.0;               // over every station reached
};

Continuation continue_along_beam(const Model& model, const Stations& stations) {
    const std::vector<std::vector<Mat3>> by_member = stations_by_member(model, stations);
    Continuation c;
    c.points.resize(model.points.size());
    std::deque<int> reached;
    auto seed = [&](int point, const Mat3& R) {
        if (point < 0 || c.points[static_cast<std::size_t>(point)]) return;
        c.points[static_cast<std::size_t>(point)] = so3::log_map(R);
        c.largest_angle = std::max(c.largest_angle, so3::log_map(R).norm());
        reached.push_back(point);
    };
    // A supported point's rotation is its member's station there (given, principal value).
    for (const Constraint& con : model.constraints) {
        for (std::size_t m = 0; m < model.members.size(); ++m) {
            if (model.members[m].start_point == con.point) seed(con.point, by_member[m].front());
            if (model.members[m].end_point == con.point) seed(con.point, by_member[m].back());
        }
    }
    if (reached.empty() && !model.members.empty()) {
        seed(model.members.front().start_point, by_member.front().front());
    }
    while (!reached.empty()) {
        const int from = reached.front();
        reached.pop_front();
        for (std::size_t m = 0; m < model.members.size(); ++m) {
            const Member& member = model.members[m];
            const bool forward = member.start_point == from;
            if (!forward && member.end_point != from) continue;
            const int to = forward ? member.end_point : member.start_point;
            if (c.points[static_cast<std::size_t>(to)]) continue;
            Vec3 v = *c.points[static_cast<std::size_t>(from)];
            const std::vector<Mat3>& line = by_member[m];
            for (std::size_t k = 1; k < line.size(); ++k) {
                const Mat3& R = forward ? line[k] : line[line.size() - 1 - k];
                v = so3::unwrap_rotation_vector(so3::log_map(R), v);
                c.largest_angle = std::max(c.largest_angle, v.norm());
            }
            c.points[static_cast<std::size_t>(to)] = v;
            reached.push_back(to);
        }
    }
    return c;
}

}  // namespace

std::vector<Vec3> rotation_vectors_along_beam(const Model& model, const Stations& stations,
                                              const std::vector<PointState>& states) {
    const Continuation c = continue_along_beam(model, stations);
    std::vector<Vec3> out(model.points.size(), Vec3::Zero());
    for (std::size_t i = 0; i < c.points.size(); ++i) {
        if (c.points[i]) {
            out[i] = *c.points[i];
        } else if (i < states.size()) {
            out[i] = so3::log_map(states[i].rotation);
        }
    }
    return out;
}

double largest_continued_angle(const Model& model, const Stations& stations) {
    if (stations.empty()) return 0.0;
    return continue_along_beam(model, stations).largest_angle;
}

}  // namespace rotbeam
