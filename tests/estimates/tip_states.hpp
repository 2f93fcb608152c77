// The tip states the estimate tests compare with: a named point's state at one reported step of a
// result (docs/architecture.md, the result contract: steps[k].points[NAME] with `displacement` and
// `rotation_matrix`), and the continuum reference of the catalog's 45° bend at its load factors.
#pragma once

#include <boost/test/unit_test.hpp>
#include <cstddef>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cases/loader/case_loader.hpp"
#include "core/continuum/continuum.hpp"
#include "core/static_state.hpp"

namespace rotbeam::test {

inline PointState point_state_of(const nlohmann::json& step, const std::string& point = "tip") {
    const nlohmann::json& p = step["points"][point];
    PointState s;
    for (int i = 0; i < 3; ++i) {
        s.displacement[i] = p["displacement"][i].get<double>();
        for (int j = 0; j < 3; ++j) s.rotation(i, j) = p["rotation_matrix"][i][j].get<double>();
    }
    return s;
}

// The reference tip state of reported step k at load factor λ.
using TipStates = std::function<PointState(std::size_t, double)>;

// The continuum reference of cases/bend-45.yaml's tip at its load factors, solved once.
inline TipStates bend_tip_reference() {
    const Model model = load_case(std::string(ROTBEAM_SOURCE_DIR) + "/cases/bend-45.yaml", {},
                                  CaseParts::case_file);
    const ContinuumOutcome out = solve_continuum(model);
    BOOST_TEST_REQUIRE(out.status == "converged", out.message);
    const std::size_t tip = static_cast<std::size_t>(model.point_index("tip"));
    std::vector<PointState> tips;
    for (const ContinuumStep& s : out.steps) tips.push_back(s.points.at(tip));
    return [tips](std::size_t k, double) { return tips.at(k); };
}

}  // namespace rotbeam::test
