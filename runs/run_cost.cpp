#include "run_cost.hpp"

#include <algorithm>
#include <cmath>

namespace rotbeam::cli {

double modelled_seconds(const Model& model) {
    double elements = 0.0;
    for (const Member& m : model.members) elements += std::max(1, m.elements);
    const bool mixed = model.discretization.formulation == Formulation::mixed;
    const double order = mixed ? 1.0 : std::max(1, model.discretization.order);
    double steps = 1.0;
    switch (model.analysis.kind) {
        case AnalysisKind::static_:
            steps = static_cast<double>(
                        std::max<size_t>(1, model.analysis.statics.load_factors.size())) *
                    std::max(1, model.analysis.statics.substeps);
            break;
        case AnalysisKind::dynamic: {
            const DynamicSettings& d = model.analysis.dynamics;
            steps = d.time_step > 0.0 ? std::ceil(d.end_time / d.time_step) : 1.0;
            break;
        }
        case AnalysisKind::modal:
            steps = std::max(1, model.analysis.modal.modes);
            break;
    }
    return kFixedSeconds +
           kSecondsPerElementStep * elements * order * steps * (mixed ? kMixedFactor : 1.0);
}

}  // namespace rotbeam::cli
