#include "effectivity_sequences.hpp"

#include <cmath>
#include <sstream>

#include "core/errors.hpp"
#include "core/oracles/manufactured.hpp"
#include "core/oracles/rollup.hpp"
#include "estimates/accuracy_scale.hpp"
#include "estimates/estimator_failure.hpp"
#include "estimates/point_difference.hpp"
#include "manufactured_rod_case.hpp"
#include "runs/mode_matching.hpp"

namespace rotbeam::cli {

namespace {

using json = nlohmann::json;

// The levels of each sequence. p: orders on two elements per member (the p-sequence of
// docs/studies.md: the roll-up and the bend reach the round-off floor near order 8); h: the mixed
// meshes, each with its companions at 2N and 4N. The quick form keeps the three or four levels that
// classify at least one level as asymptotic (it needs the true errors of the next two).
struct Levels {
    std::vector<int> p, h;
    int p_elements = 2;
};

Levels static_levels(const std::string& case_name, bool quick) {
    if (quick) return {{3, 4, 5, 6}, {4, 8, 16}, 2};
    // The helices and the roll-up to λ = 4 turn twice (4π): two elements per turn, and the mixed
    // meshes from the catalog's 16 (companions to 256).
    if (case_name == "helix-precessing" || case_name == "helix" ||
        case_name == "cantilever-moment-4")
        return {{4, 5, 6, 7, 8}, {16, 32, 64}, 4};
    return {{2, 3, 4, 5, 6, 7, 8}, {4, 8, 16, 32, 64}, 2};
}

// The joined beam's modes: the mixed meshes of test_effectivity_modal.cpp; the displacement
// formulation with consistent mass (the catalog's midpoint rule needs order ≥ 3 and lumps the
// inertia at a rate of its own) on two elements per member.
Levels modal_levels() { return {{2, 3, 4, 5, 6}, {5, 10, 20, 40}, 2}; }

// The coarser companions need every member's elements divisible by 4 and a row needs the true
// errors of the two levels below it: the joined beam's coarser sequence doubles from 8.
const std::vector<int> kModalCoarserLevels = {8, 16, 32, 64};

// The catalog's joined beam at convergence: the reference modes (the first spec) and the order
// below, whose distance to it bounds the reference's own error.
constexpr int kModalReferenceOrder = 8;
constexpr int kModalReferenceElements = 10;

// True errors of a frequency below this multiple of the reference's own error (its distance to
// the order below) are the reference's, not the run's.
constexpr double kModalFloorFactor = 100.0;

// The reference modes' combination: about the undeformed state the parameterization does not
// enter (docs/error-estimates.md), so every sequence shares one reference.
Combination modal_reference_combination() {
    for (const Combination& c : all_combinations(false)) {
        if (c.formulation == Formulation::displacement && c.rotation_name() == "quaternion")
            return c;
    }
    ROTBEAM_VERIFY(false, "the registry has no displacement/quaternion combination");
    return {};
}

ReferenceKind reference_of(const std::string& case_name) {
    if (case_name == "cantilever-moment" || case_name == "cantilever-moment-4")
        return ReferenceKind::rollup_exact;
    if (case_name == kManufacturedRodCase) return ReferenceKind::manufactured_exact;
    if (case_name == "joined-beam") return ReferenceKind::converged_modes;
    return ReferenceKind::continuum;
}

json reference_point_json(const Vec3& u, const Mat3& R) {
    json rows = json::array();
    for (int r = 0; r < 3; ++r) rows.push_back({R(r, 0), R(r, 1), R(r, 2)});
    return {{"displacement", {u.x(), u.y(), u.z()}}, {"rotation_matrix", rows}};
}

// The reference state of `point` at load factor `lambda`, null where there is none.
json reference_point(const EffectivitySequence& s, const std::vector<json>& references,
                     const Model& model, const std::string& point, double lambda) {
    if (s.reference == ReferenceKind::rollup_exact) {
        if (point != "tip") return nullptr;
        const oracle::RollupState exact = oracle::rollup_tip(member_length(model), lambda);
        return reference_point_json(exact.displacement, exact.rotation);
    }
    if (s.reference == ReferenceKind::manufactured_exact) {
        // The rod lies along +x from the origin: a point's arc length is its x.
        const int p = model.point_index(point);
        if (p < 0) return nullptr;
        const oracle::ManufacturedRod::State exact =
            manufactured_rod().state(model.points[static_cast<size_t>(p)].position.x(), lambda);
        return reference_point_json(exact.displacement, exact.rotation);
    }
    for (const json& step : references.at(0).value("steps", json::array())) {
        if (std::abs(step["load_factor"].get<double>() - lambda) <= 1e-12 * std::abs(lambda)) {
            return step["points"].value(point, json());
        }
    }
    return nullptr;
}

std::string load_factor_text(double lambda) {
    std::ostringstream s;
    s << lambda;
    return s.str();
}

LevelQuantities static_quantities(const EffectivitySequence& s, const json& result,
                                  const std::vector<json>& references) {
    LevelQuantities out;
    const Model model = build_model(s.spec(0));
    const double floor = estimate::kFailureFloor * estimate::reference_length(model);
    // Every point with a reference, estimated or not: the rows of the other levels classify their
    // regime by this level's true errors whether or not its own companions reached the step (the
    // coarser companions of a coarse mesh stop earlier than the run).
    for (const json& step : result.value("steps", json::array())) {
        if (!step.contains("points")) continue;
        const double lambda = step["load_factor"].get<double>();
        const json no_estimate = json::object();
        for (const auto& [point, state] : step["points"].items()) {
            const json ref = reference_point(s, references, model, point, lambda);
            if (ref.is_null()) continue;
            const json* e = &no_estimate;
            if (step.contains("estimate") && step["estimate"].contains(point) &&
                step["estimate"][point].contains("displacement")) {
                e = &step["estimate"][point];
            }
            const estimate::PointDifference d = estimate::point_difference(state, ref);
            const std::string at = " at load factor " + load_factor_text(lambda);
            out.push_back({point + " displacement" + at, e->value("displacement", json::object()),
                           d.displacement, floor});
            out.push_back({point + " rotation" + at, e->value("rotation", json::object()),
                           d.rotation, estimate::kFailureFloor});
        }
    }
    return out;
}

std::vector<std::vector<double>> stations_of(const json& result) {
    std::vector<std::vector<double>> stations;
    for (const json& mode : result.value("modes", json::array())) {
        stations.push_back(mode.value("stations", std::vector<double>()));
    }
    return stations;
}

LevelQuantities modal_quantities(const json& result, const std::vector<json>& references) {
    LevelQuantities out;
    const json& reference = references.at(0);
    const json& below = references.at(1);
    const std::vector<std::vector<double>> ref_stations = stations_of(reference);
    // The reference's own error per mode: its distance to the order below, paired by shape.
    const std::vector<int> below_pair = match_modes(ref_stations, stations_of(below), kMatchMac);
    const std::vector<int> pair = match_modes(stations_of(result), ref_stations, kMatchMac);
    for (size_t i = 0; i < pair.size(); ++i) {
        const json& mode = result["modes"][i];
        const int j = pair[i];
        if (j < 0 || !mode.contains("estimate") || !mode["estimate"].contains("frequency"))
            continue;
        const auto ju = static_cast<size_t>(j);
        const double f_ref = reference["modes"][ju]["frequency_hz"].get<double>();
        const int k = below_pair[ju];
        const double own =
            k < 0 ? std::abs(f_ref)  // unpaired: nothing is known below it
                  : std::abs(f_ref -
                             below["modes"][static_cast<size_t>(k)]["frequency_hz"].get<double>());
        out.push_back({"frequency of mode " + std::to_string(j + 1), mode["estimate"]["frequency"],
                       std::abs(mode["frequency_hz"].get<double>() - f_ref),
                       std::max(kModalFloorFactor * own, estimate::kFailureFloor * f_ref)});
    }
    return out;
}

}  // namespace

RunSpec EffectivitySequence::spec(size_t level) const {
    RunSpec r{case_name, combination, overrides, 0};
    if (kind == RefinementKind::p) {
        r.overrides.push_back("discretization.order=" + std::to_string(levels.at(level)));
        r.elements = p_elements;
    } else {
        r.elements = levels.at(level);
    }
    return r;
}

std::vector<EffectivitySequence> effectivity_sequences(bool quick) {
    std::vector<std::string> cases = {"cantilever-moment", "bend-45", kManufacturedRodCase};
    // The full form adds the other cases with an independent reference: the precessing helix,
    // the joined beam's frequencies, the roll-up on to λ = 4 (exact), the helix to κL = 4π and the
    // slender tip-loaded cantilever (both within the continuum solver's scope).
    if (!quick) {
        cases.insert(cases.end(), {"helix-precessing", "joined-beam", "cantilever-moment-4",
                                   "helix", "tip-load-cantilever"});
    }
    std::vector<EffectivitySequence> out;
    for (const std::string& c : cases) {
        const bool modal = c == "joined-beam";
        const Levels levels = modal ? modal_levels() : static_levels(c, quick);
        for (const Combination& comb : all_combinations(false)) {
            if (quick && comb.rotation_name() != "quaternion") continue;
            EffectivitySequence s{c, comb, RefinementKind::h, reference_of(c), levels.h, 0, {}};
            if (comb.formulation == Formulation::displacement) {
                s.kind = RefinementKind::p;
                s.levels = levels.p;
                s.p_elements = levels.p_elements;
            }
            if (modal) s.overrides = {"discretization.mass_rule=consistent"};
            if (modal && s.kind == RefinementKind::h) s.overrides.clear();
            out.push_back(s);
            // The mixed formulation's coarser companions on the same meshes: a level is
            // estimated from the two before it (levels not divisible by 4 have no estimate).
            if (s.kind == RefinementKind::h) {
                s.kind = RefinementKind::h_coarser;
                if (modal) s.levels = kModalCoarserLevels;
                s.overrides.push_back("analysis.estimate_companions=coarser");
                out.push_back(s);
            }
        }
    }
    return out;
}

std::vector<RunSpec> reference_specs(const EffectivitySequence& s) {
    switch (s.reference) {
        case ReferenceKind::rollup_exact:
        case ReferenceKind::manufactured_exact:
            return {};
        case ReferenceKind::continuum:
            return {RunSpec{s.case_name, {}, {}, 0}};
        case ReferenceKind::converged_modes: {
            std::vector<RunSpec> specs;
            for (const int order : {kModalReferenceOrder, kModalReferenceOrder - 1}) {
                specs.push_back({s.case_name,
                                 modal_reference_combination(),
                                 {"discretization.order=" + std::to_string(order),
                                  "discretization.mass_rule=consistent", "analysis.modes=8"},
                                 kModalReferenceElements});
            }
            return specs;
        }
    }
    ROTBEAM_VERIFY(false, "reference_specs: unknown reference kind");
    return {};
}

LevelQuantities level_quantities(const EffectivitySequence& s, const json& result,
                                 const std::vector<json>& references) {
    if (s.reference == ReferenceKind::converged_modes) return modal_quantities(result, references);
    return static_quantities(s, result, references);
}

}  // namespace rotbeam::cli
