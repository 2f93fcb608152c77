// The test models of the catalog's benchmarks, read from the catalog's YAML (cases/NAME.yaml)
// through the case loader with `--set` overrides, so that a test solves the model the program
// runs, not a copy rebuilt by hand. Needs rotbeam_cases and ROTBEAM_SOURCE_DIR (rotbeam_add_test
// defines it).
#pragma once

#include <string>
#include <vector>

#include "cases/loader/case_loader.hpp"
#include "core/model.hpp"

namespace rotbeam::test {

inline Model catalog_model(const std::string& name, const std::vector<std::string>& overrides) {
    return load_case(std::string(ROTBEAM_SOURCE_DIR) + "/cases/" + name + ".yaml", overrides);
}

}  // namespace rotbeam::test
