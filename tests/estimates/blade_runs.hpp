// The MH-104 blade's runs of the verification tests (test_blade_agreement.cpp,
// test_blade_accuracy.cpp): the catalog case with Wiener–Milenković and the given overrides, run
// and estimated through the program's own code path (run_case, add_run_estimate), and what the
// tests read of the tip.
#pragma once

#include <boost/test/unit_test.hpp>
#include <string>
#include <vector>

#include "cases/loader/case_loader.hpp"
#include "core/static_driver.hpp"
#include "estimates/point_difference.hpp"
#include "runs/run_case.hpp"

namespace rotbeam::blade {

using json = nlohmann::json;

inline json estimated_blade(const std::vector<std::string>& overrides) {
    const std::string path = std::string(ROTBEAM_SOURCE_DIR) + "/cases/blade-mh104.yaml";
    std::vector<std::string> all = {"discretization.rotation=wiener-milenkovic"};
    all.insert(all.end(), overrides.begin(), overrides.end());
    const RunRequest request{path, load_case(path, all, CaseParts::case_file)};
    json result = run_case(request);
    BOOST_TEST_REQUIRE(has_solution(result["status"].get<std::string>()),
                       result["message"].get<std::string>());
    add_run_estimate(request, result);
    return result;
}

// The estimate of the tip's `what` at output time i (space + time), or −1 when none.
inline double tip_estimate(const json& result, std::size_t i, const std::string& what) {
    const json& e = result["steps"][i]["estimate"];
    if (!e.contains("tip") || !e["tip"][what].contains("error")) return -1.0;
    return e["tip"][what]["error"].get<double>();
}

// The tip's displacement (q = 0) or rotation (q = 1) difference of two runs at one output time.
inline double tip_difference(const json& a, const json& b, int q) {
    const estimate::PointDifference d =
        estimate::point_difference(a["points"]["tip"], b["points"]["tip"]);
    return q == 0 ? d.displacement : d.rotation;
}

inline const char* const kQuantities[] = {"displacement", "rotation"};

}  // namespace rotbeam::blade
