#include "parameterizations/registry.hpp"

#include "core/errors.hpp"

namespace rotbeam::param {

std::vector<std::string> parameterization_names() {
    std::vector<std::string> names;
    for_each_parameterization([&]<class P>() { names.emplace_back(P::kName); });
    return names;
}

namespace detail {
void throw_unknown_parameterization(std::string_view name) {
    std::string valid;
    for (const std::string& n : parameterization_names()) {
        valid += valid.empty() ? n : ", " + n;
    }
    throw InputError("unknown rotation parameterization '" + std::string(name) +
                     "' (valid: " + valid + ")");
}
}  // namespace detail

}  // namespace rotbeam::param
