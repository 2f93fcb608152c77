// The node frames and section resultants of the mixed formulation's state, for the ParaView output
// (runs/vtk_output.hpp), in one place for the statics and the dynamics: both read their nodes'
// motion and their elements' unknowns through a callable, so the order of the nodes and the
// arc lengths are the same in every analysis.
#pragma once

#include <vector>

#include "core/static_state.hpp"
#include "formulations/mixed/mixed_layout.hpp"

namespace rotbeam::form {

// One node in the order of the node frames: the member, its arc length and the layout's node.
struct MixedFrameNode {
    int member = -1;
    double s = 0.0;
    int node = -1;
};

// Start node, then per element its end node; the elements of a member are of equal arc length,
// so an end node's arc length is twice the mid-point's minus the start node's.
inline std::vector<MixedFrameNode> mixed_frame_nodes(const MixedLayout& layout, int element_count) {
    std::vector<MixedFrameNode> out;
    for (int e = 0; e < element_count; ++e) {
        const MixedElement& el = layout.elements[static_cast<std::size_t>(e)];
        if (out.empty() || out.back().member != el.member)
            out.push_back({el.member, 0.0, el.start_node});
        out.push_back({el.member, 2.0 * el.s_mid - out.back().s, el.end_node});
    }
    return out;
}

// The node frames; motion(node, u_hat, R) gives a node's displacement and relative rotation.
template <class NodeMotion>
std::vector<StaticState::NodeFrame> mixed_node_frames(const MixedLayout& layout, int element_count,
                                                      NodeMotion motion) {
    std::vector<StaticState::NodeFrame> out;
    for (const MixedFrameNode& n : mixed_frame_nodes(layout, element_count)) {
        StaticState::NodeFrame f{n.member, n.s,
                                 layout.nodes[static_cast<std::size_t>(n.node)].reference};
        motion(n.node, f.displacement, f.rotation);
        out.push_back(f);
    }
    return out;
}

// The section resultants at the element mid-points; unknowns(e, R, F, M) gives element e's
// relative rotation and its F, M (deformed material frame, seed 002 Eq. 45's b axes).
template <class ElementUnknowns>
std::vector<SectionResultants> mixed_section_resultants(const MixedLayout& layout,
                                                        int element_count,
                                                        ElementUnknowns unknowns) {
    std::vector<SectionResultants> out;
    for (int e = 0; e < element_count; ++e) {
        const MixedElement& el = layout.elements[static_cast<std::size_t>(e)];
        Mat3 R;
        Vec3 F, M;
        unknowns(e, R, F, M);
        const Mat3 A = R * el.Cab;
        out.push_back({el.member, el.s_mid, A * F, A * M, F, M});
    }
    return out;
}

}  // namespace rotbeam::form
