#include "parameterizations/registry.hpp"

#include <stdexcept>

namespace rotbeam::param {

std::vector<ParameterizationId> parameterization_ids() {
    std::vector<ParameterizationId> ids;
    for_each_parameterization([&]<class P>() { ids.push_back(id_of<P>()); });
    return ids;
}

std::vector<std::string> parameterization_names() {
    std::vector<std::string> names;
    for_each_parameterization([&]<class P>() { names.emplace_back(P::kName); });
    return names;
}

std::string_view name_of(ParameterizationId id) {
    return dispatch_parameterization(id, []<class P>() { return P::kName; });
}

std::optional<ParameterizationId> parse_parameterization(std::string_view name) {
    std::optional<ParameterizationId> found;
    for_each_parameterization([&]<class P>() {
        if (name == P::kName) found = id_of<P>();
    });
    return found;
}

namespace detail {
void throw_invalid_id(ParameterizationId id) {
    throw std::logic_error("parameterization id " + std::to_string(static_cast<int>(id)) +
                           " is not in the registry");
}
}  // namespace detail

}  // namespace rotbeam::param
