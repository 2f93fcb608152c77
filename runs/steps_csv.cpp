#include "steps_csv.hpp"

#include <iomanip>
#include <sstream>

#include "beamdyn_frame.hpp"
#include "estimate_columns.hpp"

namespace rotbeam {

bool has_load_steps(const nlohmann::json& result) {
    const nlohmann::json& steps = result["steps"];
    return !result.contains("modes") && !steps.empty() && steps[0].contains("load_factor");
}

std::string steps_csv(const nlohmann::json& result) {
    std::ostringstream os;
    os << std::setprecision(17);
    const nlohmann::json& steps = result["steps"];
    const bool estimate = has_estimate_columns(result);
    // After the points: the step's stability assessment (core/static_stability.hpp); the estimate's
    // columns, when estimated, come last (as in every CSV of a result: docs/error-estimates.md).
    const bool stability = steps[0].contains("stability");
    // Then the step's points in BeamDyn's frame (`run --frame beamdyn`, beamdyn_frame.hpp).
    const bool beamdyn = has_beamdyn_columns(result);
    os << "load_factor";
    for (const auto& [name, point] : steps[0]["points"].items()) {
        for (const char* c : {"ux", "uy", "uz", "rx", "ry", "rz", "angle"}) {
            os << "," << name << "_" << c;
        }
    }
    if (stability) os << ",stability";
    if (beamdyn) write_beamdyn_header(result, os);
    if (estimate) write_estimate_header(result, os);
    os << "\n";
    for (const nlohmann::json& step : steps) {
        os << step["load_factor"].get<double>();
        for (const auto& [name, point] : step["points"].items()) {
            for (int i = 0; i < 3; ++i) os << "," << point["displacement"][i].get<double>();
            for (int i = 0; i < 3; ++i) os << "," << point["rotation_vector"][i].get<double>();
            os << "," << point["rotation_angle"].get<double>();
        }
        if (stability) os << "," << step["stability"]["assessment"].get<std::string>();
        if (beamdyn) write_beamdyn_row(step, os);
        if (estimate) write_estimate_row(result, step, os);
        os << "\n";
    }
    return os.str();
}

}  // namespace rotbeam
