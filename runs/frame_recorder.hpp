// The node frames of every reported step of one run, for the ParaView output (vtk_output.hpp).
// `run --vtk` installs a recorder around the run itself (not around its companion runs, which
// estimate its error); the analyses add a snapshot after each reported step, output time or mode
// when one is installed. Like the step observer (core/step_observer.hpp) a recorder only reads
// the state, so it cannot change a result; a run without one pays one thread-local load per step.
#pragma once

#include <optional>
#include <vector>

#include "core/static_state.hpp"
#include "core/types.hpp"

namespace rotbeam {

// A turning frame's position at a snapshot's time (docs/rotating-frame.md): the rotation Q(t) about
// the axis through `center` that turns the motion relative to the frame into the inertial one.
struct TurningFrame {
    Mat3 rotation = Mat3::Identity();
    Vec3 center = Vec3::Zero();
};

struct FrameSnapshot {
    std::vector<StaticState::NodeFrame> nodes;  // arc-length order per member
    // Section resultants at the formulation's stations (mixed: element mid-points, one per pair
    // of neighbouring nodes); empty where the formulation gives none.
    std::vector<SectionResultants> sections;
    // A mode's amplitude [u; θ] at every node (modal analyses), in the order of `nodes`.
    std::vector<Vec6> mode;
    // With turning supports (dynamics): the frame at the output time; `nodes` and `sections` are
    // then the motion relative to it, in its axes.
    std::optional<TurningFrame> turning;
    // Where the formulation keeps no resultants (displacement): its nodal state, from which the
    // ParaView output evaluates them per cell (formulations/displacement/cell_resultants.hpp).
    std::optional<NodalField> field;
};

struct FrameRecorder {
    std::vector<FrameSnapshot> snapshots;
};

// Per thread: a recorder installed by one thread never sees another thread's runs.
inline thread_local FrameRecorder* current_frame_recorder = nullptr;

inline bool frames_recorded() { return current_frame_recorder != nullptr; }

// Adds a snapshot when a recorder is installed.
inline void record_snapshot(FrameSnapshot snapshot) {
    if (current_frame_recorder != nullptr) {
        current_frame_recorder->snapshots.push_back(std::move(snapshot));
    }
}

// Adds a snapshot of `state` (and a mode's node amplitudes, or the turning frame of a dynamic
// output) when a recorder is installed.
inline void record_frames(const StaticProblem& state, std::vector<Vec6> mode = {},
                          std::optional<TurningFrame> turning = std::nullopt) {
    if (current_frame_recorder == nullptr) return;
    std::vector<SectionResultants> sections = state.section_resultants();
    std::optional<NodalField> field;
    if (sections.empty()) field = state.nodal_field();
    record_snapshot(
        {state.node_frames(), std::move(sections), std::move(mode), turning, std::move(field)});
}

// Installs a recorder for the scope; the previous one is restored on exit.
class ScopedFrameRecorder {
  public:
    explicit ScopedFrameRecorder(FrameRecorder& recorder) : previous_(current_frame_recorder) {
        current_frame_recorder = &recorder;
    }
    ~ScopedFrameRecorder() { current_frame_recorder = previous_; }
    ScopedFrameRecorder(const ScopedFrameRecorder&) = delete;
    ScopedFrameRecorder& operator=(const ScopedFrameRecorder&) = delete;

  private:
    FrameRecorder* previous_;
};

}  // namespace rotbeam
