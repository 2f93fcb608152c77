// The continuum reference solution of a case in the result contract of `run` (formulation
// "continuum", rotation "—").
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "core/model.hpp"

namespace rotbeam {

nlohmann::json continuum_result_json(const Model& model, const std::string& case_path);

}  // namespace rotbeam
