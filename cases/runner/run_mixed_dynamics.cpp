// Dynamic and modal analyses of the mixed formulation (issue 9; analyses.hpp).
#include "analyses.hpp"

namespace rotbeam {

void run_mixed_dynamic(const Model& model, bool /*trace*/, nlohmann::json& result) {
    report_unavailable(model, result);
}

void run_mixed_modal(const Model& model, bool /*trace*/, nlohmann::json& result) {
    report_unavailable(model, result);
}

}  // namespace rotbeam
