#include "core/model.hpp"

#include <algorithm>
#include <cmath>

namespace rotbeam {

double TimeFunction::operator()(double t) const {
    switch (kind) {
        case Kind::constant:
            return value;
        case Kind::ramp:
            if (t <= start) return 0.0;
            if (duration <= 0.0 || t >= start + duration) return value;
            return value * (t - start) / duration;
        case Kind::sine:
            if (t < start) return 0.0;
            return value * std::sin(omega * (t - start) + phase);
        case Kind::table: {
            if (times.empty()) return 0.0;
            if (t <= times.front()) return values.front();
            if (t >= times.back()) return values.back();
            const auto it = std::upper_bound(times.begin(), times.end(), t);
            const size_t i = static_cast<size_t>(it - times.begin());
            const double a = (t - times[i - 1]) / (times[i] - times[i - 1]);
            return (1.0 - a) * values[i - 1] + a * values[i];
        }
    }
    return 0.0;
}

int Model::point_index(const std::string& name) const {
    for (size_t i = 0; i < points.size(); ++i) {
        if (points[i].name == name) return static_cast<int>(i);
    }
    return -1;
}

bool Model::has_follower_loads() const {
    return std::any_of(point_loads.begin(), point_loads.end(),
                       [](const PointLoad& l) { return l.frame == LoadFrame::follower; }) ||
           std::any_of(distributed_loads.begin(), distributed_loads.end(),
                       [](const DistributedLoad& l) { return l.frame == LoadFrame::follower; });
}

bool Model::has_damping() const {
    for (const Member& m : members) {
        for (const SectionStation& st : m.sections) {
            if (st.section.has_damping()) return true;
        }
    }
    return false;
}

}  // namespace rotbeam
