#include "combinations/registry.hpp"

#include <algorithm>

namespace rotbeam::comb {

bool has_wm_map(Formulation f, ParameterizationId rotation) {
    if (!traits(f).wm_maps) return false;
    return param::dispatch_parameterization(rotation, []<class P>() { return kHasWmMap<P>; });
}

Integrator integrator_for(Formulation f, Integrator asked) {
    return asked == Integrator::automatic ? traits(f).integrators.front() : asked;
}

bool takes_integrator(Formulation f, Integrator asked) {
    const std::span<const Integrator> list = traits(f).integrators;
    return asked == Integrator::automatic ||
           std::find(list.begin(), list.end(), asked) != list.end();
}

std::string integrator_names(Formulation f) {
    std::string names;
    for (const Integrator i : traits(f).integrators) {
        if (!names.empty()) names.append(" | ");
        names.append(choice_name(i));
    }
    return names;
}

std::string Combination::label() const {
    std::string s(choice_name(formulation));
    s.append("/").append(param::name_of(rotation));
    if (interpolation) s.append("/").append(choice_name(*interpolation));
    if (wm_map) s.append("/").append(choice_name(*wm_map));
    return s;
}

std::vector<Combination> all_combinations(bool with_interpolation, bool with_wm_map) {
    std::vector<Combination> list;
    for (const FormulationTraits& f : kFormulations) {
        for (ParameterizationId r : param::parameterization_ids()) {
            if (with_interpolation && !f.interpolations.empty()) {
                for (Interpolation i : f.interpolations) list.push_back({f.id, r, i, {}});
            } else if (with_wm_map && has_wm_map(f.id, r)) {
                for (WmMap m : {WmMap::plain, WmMap::continuous}) list.push_back({f.id, r, {}, m});
            } else {
                list.push_back({f.id, r, {}, {}});
            }
        }
    }
    return list;
}

std::vector<Formulation> formulations() {
    std::vector<Formulation> list;
    for (const FormulationTraits& f : kFormulations) list.push_back(f.id);
    return list;
}

}  // namespace rotbeam::comb
