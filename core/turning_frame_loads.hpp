// What a dynamic analysis with a turning root can load: follower loads and gravity. Dead loads are
// fixed in inertial axes, so in the turning frame's axes they would turn with −Ω; the motion is
// solved relative to that frame (docs/rotating-frame.md), so they are refused, not silently turned.
#pragma once

#include "core/errors.hpp"
#include "core/model.hpp"

namespace rotbeam {

inline void refuse_dead_loads_with_turning_root(const Model& model) {
    bool has_dead = !model.load_fields.empty();
    for (const PointLoad& l : model.point_loads)
        has_dead = has_dead || l.frame != LoadFrame::follower;
    for (const DistributedLoad& l : model.distributed_loads) {
        has_dead = has_dead || l.frame != LoadFrame::follower;
    }
    if (has_dead) {
        throw InputError(
            "rotating_frame: the dynamics with a rotating frame take follower loads and gravity "
            "only (dead loads and load fields are not turned with the frame)");
    }
}

}  // namespace rotbeam
