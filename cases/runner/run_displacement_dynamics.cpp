// Dynamic and modal analyses of the displacement formulation (issue 6; analyses.hpp).
#include "analyses.hpp"

namespace rotbeam {

void run_displacement_dynamic(const Model& model, bool /*trace*/, nlohmann::json& result) {
    report_unavailable(model, result);
}

void run_displacement_modal(const Model& model, bool /*trace*/, nlohmann::json& result) {
    report_unavailable(model, result);
}

}  // namespace rotbeam
