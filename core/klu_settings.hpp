// The one place where KLU's options are chosen, for the real (core/sparse_lu.cpp) and the complex
// (core/complex_klu.cpp) factorizations alike: SuiteSparse's defaults but the fill-reducing
// ordering, COLAMD on the columns instead of AMD on the pattern of A + Aᵀ. SUNDIALS makes the same
// choice for its own KLU solver (SUNKLU_ORDERING_DEFAULT, which KINSOL and IDA use here).
// Measured (callgrind, whole `rotbeam run` of the joined beam 0–2 s, dead and follower load,
// Newton tolerance 1e-7; docs/performance.md, "KLU's ordering"): the mixed formulation's Radau IIA
// stage matrices (mixed stress–displacement unknowns, far from symmetric in pattern) need 20 %
// fewer instructions per run; the displacement formulation's stage and mass matrices (narrow
// bands: both orderings find the same fill) are unchanged to 0.01 %; the results agree to
// round-off (≤ 2e-14 of the histories' amplitudes, the same stage iteration counts).
#pragma once

#include <klu.h>

namespace rotbeam {

inline void set_klu_settings(klu_common& common) {
    klu_defaults(&common);
    common.ordering = 1;  // COLAMD
}

}  // namespace rotbeam
