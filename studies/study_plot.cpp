#include "study_plot.hpp"

#include <algorithm>
#include <filesystem>
#include <sstream>

namespace rotbeam::cli {

int PanelFigure::panel(const std::string& title) {
    const auto it = std::find(panel_titles.begin(), panel_titles.end(), title);
    if (it != panel_titles.end()) return static_cast<int>(it - panel_titles.begin()) + 1;
    panel_titles.push_back(title);
    return static_cast<int>(panel_titles.size());
}

void PanelFigure::add(const std::string& panel_title, const std::string& file,
                      const std::string& title) {
    groups.push_back(panel(panel_title));
    files.push_back(file);
    titles.push_back(title);
}

void PanelFigure::add_failure(const std::string& panel_title, double x) {
    failed.emplace_back(x, panel(panel_title));
}

namespace {

// gnuplot word lists split at spaces: the script turns '_' back into spaces.
std::string underscored(std::string s) {
    std::replace(s.begin(), s.end(), ' ', '_');
    return s;
}

std::string layout_of(size_t panels) {
    if (panels <= 3) return "1," + std::to_string(std::max<size_t>(panels, 1));
    if (panels == 4) return "2,2";
    return std::to_string((panels + 2) / 3) + ",3";
}

}  // namespace

bool plot_panels(const StudyOptions& o, const PanelFigure& figure,
                 std::vector<std::pair<std::string, std::string>> vars) {
    if (figure.files.empty()) return false;
    std::string outbase;
    for (const auto& [k, v] : vars)
        if (k == "outbase") outbase = v;
    std::vector<std::string> groups, panels;
    for (int g : figure.groups) groups.push_back(std::to_string(g));
    for (const std::string& t : figure.panel_titles) panels.push_back(underscored(t));
    vars.push_back({"files", join_words(figure.files)});
    vars.push_back({"titles", join_words(figure.titles)});
    vars.push_back({"groups", join_words(groups)});
    vars.push_back({"panels", join_words(panels)});
    vars.push_back({"layout", layout_of(figure.panel_titles.size())});
    if (!figure.failed.empty()) {
        std::ostringstream s;
        s.precision(12);
        s << "# x panel (runs without a result)\n";
        for (const auto& [x, p] : figure.failed) s << x << " " << p << "\n";
        const std::string rel =
            "data/" + std::filesystem::path(outbase).filename().string() + "_failed.dat";
        write_text(o, rel, s.str());
        vars.push_back({"failed", out_path(o, rel)});
    }
    plot("study_panels.gp", vars);
    return true;
}

}  // namespace rotbeam::cli
