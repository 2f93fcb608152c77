// The memory a run needs, estimated from the model's sizes (limits.hpp; docs/case-format.md,
// "Limits", states the same formulas). An estimate, meant to be within a small factor: it
// separates a run that fits from one that needs a thousand times the machine, which is what the
// check is for.
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>
#include <vector>

#include "cases/loader/limits.hpp"

namespace rotbeam::cases {

namespace {

// Per stored nonzero of the Jacobian: the triplet list it is assembled from (16 B), the
// compressed matrix (12 B), the sparse LU's factors with their fill-in and the solver's copies.
// Measured: peak resident memory over the element nonzeros of a one-step static run of the
// roll-up is 92 B at order 12 (2000 elements) and 95 B at order 2 (20 000 elements).
constexpr double kBytesPerNonzero = 96.0;
// Per quadrature point of the displacement mesh: four 6×6 matrices (stiffness, mass, damping,
// frame) and the shape-function columns.
constexpr double kBytesPerQuadraturePoint = 1600.0;
// Per mixed element: its frames, compliance and loads.
constexpr double kBytesPerMixedElement = 1000.0;
// Per point and output record of a dynamic run's history, as JSON (a few dozen numbers of
// ~64 B each as nlohmann::json values).
constexpr double kBytesPerPointRecord = 2048.0;

}  // namespace

MemoryEstimate estimate_memory(const Model& model) {
    const Discretization& d = model.discretization;
    const Analysis& a = model.analysis;
    double elements = 0.0;
    for (const Member& m : model.members) elements += m.elements;
    const double points = static_cast<double>(model.points.size());
    const double members = static_cast<double>(model.members.size());
    const bool mixed = d.formulation == Formulation::mixed;
    const double p = std::max(1, d.order);
    double n = 0.0, nonzeros = 0.0, mesh = 0.0;
    if (mixed) {
        // 6 per node, 12 per element (and 6 momenta per element in dynamics); an element's
        // equations couple its own unknowns and its two nodes' (mixed_layout.hpp).
        const double per_element = a.kind == AnalysisKind::dynamic ? 18.0 : 12.0;
        n = 6.0 * (elements - members + points) + per_element * elements;
        nonzeros = elements * std::pow(per_element + 12.0, 2);
        mesh = elements * kBytesPerMixedElement;
    } else {
        // 6 per node, p nodes per element plus the points; an element couples its p+1 nodes.
        n = 6.0 * (elements * p + points);
        nonzeros = elements * std::pow(6.0 * (p + 1.0), 2);
        // Trapezoidal: each member's station intervals and element ends, divided by refine.
        double points = 0.0;
        for (const Member& m : model.members) {
            points += d.quadrature == Quadrature::trapezoidal
                          ? (static_cast<double>(m.sections.size()) + m.elements) * d.refine
                          : m.elements * (d.quadrature_points > 0 ? d.quadrature_points : p + 1.0);
        }
        mesh = points * (kBytesPerQuadraturePoint + 16.0 * (p + 1.0));
    }
    std::vector<std::pair<double, std::string>> parts = {
        {nonzeros * kBytesPerNonzero, "the sparse Jacobian and its LU factors"},
        {mesh, "the mesh"}};
    if (model.solver.linear_solver == LinearSolver::dense) {
        parts.push_back(
            {2.0 * 8.0 * n * n, "the dense Jacobian and its LU (solver.linear_solver)"});
    }
    if (a.kind == AnalysisKind::modal) {
        if (mixed) {
            // Arnoldi: ncv basis vectors (mixed_modal.cpp), three copies.
            const double ncv = std::max(2.0 * (2.0 * a.modal.modes + 4.0) + 1.0, 40.0);
            parts.push_back({3.0 * 8.0 * n * std::min(n, ncv), "the Arnoldi vectors"});
        } else {
            // The generalized eigenproblem is solved dense: K, M, symmetrized K, the eigenvectors
            // and the solver's workspace (displacement_modal.cpp).
            parts.push_back({6.0 * 8.0 * n * n, "the dense modal eigenproblem (6 n×n matrices)"});
        }
    }
    if (a.kind == AnalysisKind::dynamic && a.dynamics.time_step > 0.0) {
        const double steps = a.dynamics.end_time / a.dynamics.time_step;
        const double records =
            a.dynamics.output_interval > 0.0
                ? std::min(steps, a.dynamics.end_time / a.dynamics.output_interval)
                : steps;
        parts.push_back({(records + 1.0) * (points + 1.0) * kBytesPerPointRecord,
                         "the output history (analysis.output_interval)"});
    }
    MemoryEstimate e;
    e.unknowns = static_cast<long>(std::min(n, 1e18));
    double largest = -1.0;
    for (const auto& [bytes, what] : parts) {
        e.bytes += bytes;
        if (bytes > largest) {
            largest = bytes;
            e.dominant = what;
        }
    }
    return e;
}

double physical_memory_bytes() {
    const long pages = sysconf(_SC_PHYS_PAGES);
    const long page = sysconf(_SC_PAGESIZE);
    return pages > 0 && page > 0 ? static_cast<double>(pages) * static_cast<double>(page) : 0.0;
}

std::string memory_text(double bytes) {
    const char* units[] = {"B", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
    int u = 0;
    while (bytes >= 1024.0 && u < 6) {
        bytes /= 1024.0;
        ++u;
    }
    std::ostringstream s;
    s.precision(bytes < 10.0 ? 2 : 3);
    s << bytes << " " << units[u];
    return s.str();
}

}  // namespace rotbeam::cases
