// The static manufactured rod (core/oracles/manufactured.hpp) as a case of the studies: a model
// built in code (its load is a field no case file can state), named kManufacturedRodCase in a
// RunSpec. build_model (study_common.hpp) builds it with the spec's combination, its `elements` on
// each of the four members (default 2) and, of the overrides, discretization.order=N and
// analysis.estimate_companions=coarser only (any other is an InputError); run_spec and the cost
// model then take it as any case.
#pragma once

#include "core/oracles/manufactured.hpp"

namespace rotbeam::cli {

inline constexpr const char* kManufacturedRodCase = "manufactured-rod";

// Its load factors: λ = 1/20 … 1, the path tests/agreement/test_manufactured.cpp follows on every
// mesh (the mixed quaternion past 2π included).
inline constexpr int kManufacturedRodSteps = 20;

// The rod: ManufacturedRod's defaults with the fully coupled section
// (oracle::manufactured_section()), as tests/agreement/test_manufactured.cpp.
oracle::ManufacturedRod manufactured_rod();

}  // namespace rotbeam::cli
