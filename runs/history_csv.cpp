#include "history_csv.hpp"

#include <iomanip>
#include <sstream>

#include "beamdyn_frame.hpp"
#include "estimate_columns.hpp"

namespace rotbeam {

namespace {

// Per named point: the displacement, the rotation vector and the rotation angle.
void write_points(const nlohmann::json& points, std::ostream& os) {
    for (const auto& [name, point] : points.items()) {
        for (int i = 0; i < 3; ++i) os << "," << point["displacement"][i].get<double>();
        for (int i = 0; i < 3; ++i) os << "," << point["rotation_vector"][i].get<double>();
        os << "," << point["rotation_angle"].get<double>();
    }
}

}  // namespace

bool has_time_history(const nlohmann::json& result) {
    const nlohmann::json& steps = result["steps"];
    return !steps.empty() && steps[0].contains("time");
}

std::string history_csv(const nlohmann::json& result) {
    std::ostringstream os;
    os << std::setprecision(17);
    const nlohmann::json& steps = result["steps"];
    const bool estimate = has_estimate_columns(result);
    os << "time";
    if (!steps.empty()) {
        for (const auto& [name, point] : steps[0]["points"].items()) {
            for (const char* c : {"ux", "uy", "uz", "rx", "ry", "rz", "angle"}) {
                os << "," << name << "_" << c;
            }
        }
        // With turning supports, the motion relative to the turning frame, in its axes: what the
        // estimate columns measure.
        if (steps[0].contains("rotating_frame")) {
            for (const auto& [name, point] : steps[0]["rotating_frame"]["points"].items()) {
                for (const char* c : {"ux", "uy", "uz", "rx", "ry", "rz", "angle"}) {
                    os << "," << name << "_rel_" << c;
                }
            }
        }
        // Support reactions (force and moment on the beam) where the formulation provides them.
        if (steps[0].contains("reactions")) {
            for (const auto& [name, r] : steps[0]["reactions"].items()) {
                for (const char* c : {"Fx", "Fy", "Fz", "Mx", "My", "Mz"}) {
                    os << "," << name << "_" << c;
                }
            }
        }
        if (steps[0].contains("energy")) os << ",kinetic_energy,strain_energy";
        // The points and reactions in BeamDyn's frame (`run --frame beamdyn`, beamdyn_frame.hpp).
        if (has_beamdyn_columns(result)) write_beamdyn_header(result, os);
        if (estimate) write_estimate_header(result, os);
    }
    os << "\n";
    for (const nlohmann::json& step : steps) {
        os << step["time"].get<double>();
        write_points(step["points"], os);
        if (step.contains("rotating_frame")) write_points(step["rotating_frame"]["points"], os);
        if (step.contains("reactions")) {
            for (const auto& [name, r] : step["reactions"].items()) {
                for (int i = 0; i < 3; ++i) os << "," << r["force"][i].get<double>();
                for (int i = 0; i < 3; ++i) os << "," << r["moment"][i].get<double>();
            }
        }
        if (step.contains("energy")) {
            os << "," << step["energy"]["kinetic"].get<double>() << ","
               << step["energy"]["strain"].get<double>();
        }
        if (has_beamdyn_columns(result)) write_beamdyn_row(step, os);
        if (estimate) write_estimate_row(result, step, os);
        os << "\n";
    }
    return os.str();
}

}  // namespace rotbeam
