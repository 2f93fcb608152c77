// The report's 3D picture of a deformed beam: the roll-up (catalog case cantilever-moment,
// displacement formulation, quaternion, its own mesh) rerun with the ParaView output's node
// frames recorded (runs/frame_recorder.hpp), drawn by reports/rollup_ribbon.gp as the ribbon
// x ± h d2 of runs/vtk_output.hpp at several load factors.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace rotbeam {

struct RibbonFigure {
    std::string file;  // relative to the report folder
    std::string caption;
};

// Writes DIR/data/rollup_ribbon.dat and DIR/rollup-ribbon.png/.svg when the suite ran the roll-up
// (a cantilever-moment result among `runs`); nothing otherwise.
std::optional<RibbonFigure> rollup_ribbon_figure(const std::string& out_dir,
                                                 const std::vector<nlohmann::json>& runs);

}  // namespace rotbeam
