#include "mode_matching.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>
#include <utility>

namespace rotbeam {

namespace {

// Nodes on the straight segment a–b (within 1e-9 of its length), ordered along it: (t, u).
std::vector<std::pair<double, Vec3>> nodes_on_chord(const Vec3& a, const Vec3& b,
                                                    const std::vector<NodeDisplacement>& nodes) {
    const Vec3 d = b - a;
    const double length2 = d.squaredNorm();
    std::vector<std::pair<double, Vec3>> on;
    for (const NodeDisplacement& n : nodes) {
        const double t = (n.x0 - a).dot(d) / length2;
        if (t < -1e-9 || t > 1.0 + 1e-9) continue;
        if ((n.x0 - (a + t * d)).squaredNorm() > 1e-18 * length2) continue;
        on.emplace_back(t, n.u);
    }
    std::sort(on.begin(), on.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    return on;
}

Vec3 nearest(const Vec3& x, const std::vector<NodeDisplacement>& nodes) {
    double best = std::numeric_limits<double>::infinity();
    Vec3 u = Vec3::Zero();
    for (const NodeDisplacement& n : nodes) {
        const double d = (n.x0 - x).squaredNorm();
        if (d < best) {
            best = d;
            u = n.u;
        }
    }
    return u;
}

}  // namespace

std::vector<double> station_displacements(const Model& model,
                                          const std::vector<NodeDisplacement>& nodes) {
    std::vector<double> out;
    for (const Member& m : model.members) {
        const Vec3 a = model.points[static_cast<size_t>(m.start_point)].position;
        const Vec3 b = model.points[static_cast<size_t>(m.end_point)].position;
        const std::vector<std::pair<double, Vec3>> on = nodes_on_chord(a, b, nodes);
        const bool straight =
            on.size() >= 2 && on.front().first < 1e-9 && on.back().first > 1.0 - 1e-9;
        for (int k = 0; k < kModeStationsPerMember; ++k) {
            const double t = static_cast<double>(k) / (kModeStationsPerMember - 1);
            Vec3 u = Vec3::Zero();
            if (straight) {
                size_t j = 1;
                while (j + 1 < on.size() && on[j].first < t) ++j;
                const double w = (t - on[j - 1].first) / (on[j].first - on[j - 1].first);
                u = (1.0 - w) * on[j - 1].second + w * on[j].second;
            } else {
                u = nearest(a + (b - a) * t, nodes);
            }
            out.insert(out.end(), {u[0], u[1], u[2]});
        }
    }
    return out;
}

double modal_assurance(const std::vector<double>& a, const std::vector<double>& b) {
    if (a.size() != b.size() || a.empty()) return 0.0;
    double ab = 0.0, aa = 0.0, bb = 0.0;
    for (size_t i = 0; i < a.size(); ++i) {
        ab += a[i] * b[i];
        aa += a[i] * a[i];
        bb += b[i] * b[i];
    }
    return aa > 0.0 && bb > 0.0 ? ab * ab / (aa * bb) : 0.0;
}

std::vector<int> match_modes(const std::vector<std::vector<double>>& reference,
                             const std::vector<std::vector<double>>& candidates, double min_mac) {
    std::vector<std::tuple<double, int, int>> pairs;  // (MAC, reference, candidate)
    for (size_t r = 0; r < reference.size(); ++r) {
        for (size_t c = 0; c < candidates.size(); ++c) {
            pairs.emplace_back(modal_assurance(reference[r], candidates[c]), static_cast<int>(r),
                               static_cast<int>(c));
        }
    }
    std::sort(pairs.begin(), pairs.end(),
              [](const auto& x, const auto& y) { return std::get<0>(x) > std::get<0>(y); });
    std::vector<int> match(reference.size(), -1);
    std::vector<bool> used(candidates.size(), false);
    for (const auto& [mac, r, c] : pairs) {
        if (mac < min_mac) break;
        if (match[static_cast<size_t>(r)] >= 0 || used[static_cast<size_t>(c)]) continue;
        match[static_cast<size_t>(r)] = c;
        used[static_cast<size_t>(c)] = true;
    }
    return match;
}

}  // namespace rotbeam
