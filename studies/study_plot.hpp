// Multi-panel figures of the studies (reports/study_panels.gp): curves grouped into panels, e.g.
// one per discretization with the parameterizations inside, so that curves which coincide are not
// hidden behind each other (nested markers inside a panel), shared padded axis ranges so that no
// point sits on the frame, keys below the panels, and runs without a result drawn as a distinct
// marker instead of being joined to the curves.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "study_common.hpp"

namespace rotbeam::cli {

struct PanelFigure {
    std::vector<std::string> panel_titles;
    std::vector<std::string> files, titles;      // titles free of spaces
    std::vector<int> groups;                     // panel (1-based) of each file
    std::vector<std::pair<double, int>> failed;  // (x, panel) of runs without a result

    int panel(const std::string& title);  // its 1-based index, added when new
    void add(const std::string& panel_title, const std::string& file, const std::string& title);
    void add_failure(const std::string& panel_title, double x);
};

// Writes the failures' data file (when any) under DIR/data and runs study_panels.gp with `vars`
// (xcol, ycol, xlabel, ylabel, plottitle, outbase, logx, logy and the optional ones the script
// lists) plus the figure's files, titles, panels and layout.
bool plot_panels(const StudyOptions& o, const PanelFigure& figure,
                 std::vector<std::pair<std::string, std::string>> vars);

}  // namespace rotbeam::cli
