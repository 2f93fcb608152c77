#include "report_ribbon.hpp"

#include <filesystem>
#include <sstream>

#include "cases/loader/case_loader.hpp"
#include "core/atomic_file.hpp"
#include "core/geometry.hpp"
#include "runs/catalog.hpp"
#include "runs/frame_recorder.hpp"
#include "runs/run_case.hpp"
#include "studies/gnuplot.hpp"

namespace rotbeam {

namespace fs = std::filesystem;

std::optional<RibbonFigure> rollup_ribbon_figure(const std::string& out_dir,
                                                 const std::vector<nlohmann::json>& runs) {
    bool ran = false;
    for (const nlohmann::json& r : runs) ran = ran || r.value("case", "") == "cantilever-moment";
    if (!ran) return std::nullopt;
    const std::string path = cli::resolve_case_path("cantilever-moment");
    const Model model = load_case(
        path, {"discretization.formulation=displacement", "discretization.rotation=quaternion"},
        CaseParts::case_file);
    FrameRecorder frames;
    nlohmann::json result;
    {
        const ScopedFrameRecorder recording(frames);
        result = run_case(RunRequest{path, model});
    }
    // The ribbon of runs/vtk_output.hpp: half-width 1/40 of the member's length, along d2.
    const double h = ReferenceGeometry(model, 0).length() / 40.0;
    std::ostringstream data, lambdas;
    data.precision(10);
    for (size_t i = 0; i < frames.snapshots.size() && i < result["steps"].size(); ++i) {
        const double lambda = result["steps"][i]["load_factor"].get<double>();
        // Four of the seven load factors keep the picture readable.
        if (lambda != 0.4 && lambda != 1.0 && lambda != 1.6 && lambda != 2.0) continue;
        lambdas << lambda << " ";
        data << "# lambda " << lambda << "\n";
        for (const double side : {-1.0, 1.0}) {
            for (const StaticState::NodeFrame& n : frames.snapshots[i].nodes) {
                const Vec3 x = n.reference + n.displacement;
                const Vec3 d2 = n.rotation * ReferenceGeometry(model, n.member).frame(n.s).col(1);
                const Vec3 edge = x + side * h * d2;
                data << edge[0] << " " << edge[1] << " " << edge[2] << "\n";
            }
            data << "\n";
        }
        data << "\n";
    }
    const fs::path file = fs::path(out_dir) / "data" / "rollup_ribbon.dat";
    write_file_atomically(file.string(), data.str());
    cli::run_gnuplot_script("rollup_ribbon.gp",
                            {{"datafile", file.string()},
                             {"lambdas", lambdas.str()},
                             {"outbase", (fs::path(out_dir) / "rollup-ribbon").string()}});
    return RibbonFigure{
        "rollup-ribbon.png",
        "The roll-up in 3D: the ribbon x ± h d2 of the section frames (the ParaView "
        "output's, `rotbeam run --vtk`) at λ = 0.4, 1, 1.6 and 2 (displacement "
        "formulation, quaternion, the case's 16 elements of order 4); at λ = 2 "
        "the beam closes into a full circle."};
}

}  // namespace rotbeam
