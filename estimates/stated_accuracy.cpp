#include "estimates/stated_accuracy.hpp"

#include <sstream>

#include "estimates/accuracy_scale.hpp"

namespace rotbeam::estimate {

std::string stated_accuracy_line(const Model& model, const nlohmann::json& result) {
    if (result.contains("accuracy") || !result.contains("estimate")) return "";
    const std::string estimated = result["estimate"].value("status", "");
    if (estimated != "estimated" && estimated != "partial") return "";
    const auto stated = model.discretization.stated_accuracy.find(model.discretization.formulation);
    const bool has_target = stated != model.discretization.stated_accuracy.end();
    const double target = has_target ? stated->second / 2.0 : 1.0;
    const AccuracyMeasure m = measure_accuracy(model, result, target);
    if (m.quantities == 0) return "";
    std::ostringstream s;
    s.precision(2);
    s << "accuracy: ";
    if (!has_target) {
        s << "none stated (discretization.accuracy); worst estimate " << m.worst
          << " of its scale (" << m.worst_what
          << "): the status is the solver's, not the answer's accuracy";
        if (m.unreliable + m.missing > 0) {
            s << "; " << m.unreliable << " estimate(s) not reliable, " << m.missing << " missing";
        }
        return s.str();
    }
    s << "stated " << stated->second << " (estimates <= " << target << " of their scale): ";
    if (meets(m, target)) {
        s << "met, worst estimate " << m.worst << " (" << m.worst_what << ")";
    } else {
        s << "NOT met — " << m.first_problem;
    }
    return s.str();
}

}  // namespace rotbeam::estimate
