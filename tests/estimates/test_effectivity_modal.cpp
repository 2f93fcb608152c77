// Effectivity of the frequency estimate (docs/error-estimates.md) on the joined beam's modes about
// the undeformed state (cases/joined-beam.yaml, docs/benchmarks.md): the mixed formulation's h/2,
// h/4 estimate over 5 … 40 elements per member against the displacement formulation at
// convergence (order 8, 10 elements per member, consistent mass), an independent discretization
// of the same continuum. Modes are paired with the reference by shape (MAC on the stations of
// runs/mode_matching.hpp), as the estimate pairs them with its companions.
//
// The reference's own error: orders 7 and 8 on that mesh agree to below kReferenceAgreement
// (asserted), so true errors down to 100 × that are the mixed formulation's, not the reference's.
// Asserted as for the statics (test_effectivity.cpp): effectivity in [0.5, 2] and `reliable` where
// the true errors at N, 2N, 4N fall at order 2 ± kOrderWindow; no reliable estimate with a true
// error above 3 × the estimate; a minimum number of asymptotic points.
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "cases/loader/case_loader.hpp"
#include "runs/mode_matching.hpp"
#include "runs/run_case.hpp"
#include "core/static_driver.hpp"
#include "estimates/quantity_estimate.hpp"

namespace rotbeam {

namespace {

using json = nlohmann::json;

// Relative agreement of the reference's orders 7 and 8: far below the mixed formulation's errors
// (0.4–4 % on the catalog mesh, falling as h²: ~2e-5 at 160 elements per member).
constexpr double kReferenceAgreement = 1e-7;

struct Modes {
    json result;
    std::vector<std::vector<double>> stations;
};

Modes joined_beam(const std::vector<std::string>& overrides, bool estimate) {
    const std::string path = std::string(ROTBEAM_SOURCE_DIR) + "/cases/joined-beam.yaml";
    const RunRequest request{path, load_case(path, overrides, CaseParts::case_file)};
    Modes m{run_case(request), {}};
    BOOST_TEST_REQUIRE(m.result["status"] == "converged", m.result["message"]);
    if (estimate) add_run_estimate(request, m.result);
    for (const json& mode : m.result["modes"]) {
        m.stations.push_back(mode["stations"].get<std::vector<double>>());
    }
    return m;
}

Modes reference(int order) {
    return joined_beam(
        {"discretization.formulation=displacement", "discretization.order=" + std::to_string(order),
         "discretization.mass_rule=consistent", "analysis.modes=8"},
        false);
}

// The reference frequency of each of `m`'s modes (paired by shape), or NaN when unpaired.
std::vector<double> reference_frequencies(const Modes& m, const Modes& ref) {
    const std::vector<int> pair = match_modes(m.stations, ref.stations, kMatchMac);
    std::vector<double> f;
    for (const int j : pair) {
        f.push_back(
            j < 0 ? std::nan("")
                  : ref.result["modes"][static_cast<std::size_t>(j)]["frequency_hz"].get<double>());
    }
    return f;
}

}  // namespace

BOOST_AUTO_TEST_CASE(h_refinement_estimate_of_the_joined_beam_frequencies) {
    const Modes ref = reference(8);
    const Modes ref7 = reference(7);
    const std::vector<double> f7 = reference_frequencies(ref7, ref);
    for (std::size_t i = 0; i < 5; ++i) {
        const double f = ref7.result["modes"][i]["frequency_hz"].get<double>();
        BOOST_TEST_REQUIRE(std::abs(f - f7[i]) <= kReferenceAgreement * f);
    }
    for (const char* rotation : {"wiener-milenkovic", "quaternion"}) {
        std::vector<Modes> runs;
        std::vector<std::vector<double>> errors;  // true error per run and mode
        for (int n = 5; n <= 160; n *= 2) {
            runs.push_back(joined_beam({"discretization.formulation=mixed",
                                        std::string("discretization.rotation=") + rotation,
                                        "members.*.elements=" + std::to_string(n)},
                                       n <= 40));
            const std::vector<double> exact = reference_frequencies(runs.back(), ref);
            std::vector<double> e;
            for (std::size_t i = 0; i < exact.size(); ++i) {
                e.push_back(std::abs(runs.back().result["modes"][i]["frequency_hz"].get<double>() -
                                     exact[i]));
            }
            errors.push_back(e);
        }
        int asymptotic = 0;
        double lo = 1e300, hi = 0.0;
        std::ostringstream table;
        for (std::size_t k = 0; k + 2 < runs.size(); ++k) {
            const json& modes = runs[k].result["modes"];
            for (std::size_t i = 0; i < 5 && i < modes.size(); ++i) {
                const double f = modes[i]["frequency_hz"].get<double>();
                const json& est = modes[i]["estimate"];
                BOOST_TEST_REQUIRE(est.contains("frequency"), est.dump());
                const json& q = est["frequency"];
                const double e0 = errors[k][i];
                // The same mode on the finer meshes: paired with the reference by shape too.
                const auto same_mode_error = [&](std::size_t j) {
                    const std::vector<int> pair =
                        match_modes({runs[k].stations[i]}, runs[k + j].stations, kMatchMac);
                    return pair[0] < 0 ? std::nan("")
                                       : errors[k + j][static_cast<std::size_t>(pair[0])];
                };
                const double e1 = same_mode_error(1), e2 = same_mode_error(2);
                const bool monotone = e1 < e0 && e2 < e1 && e2 > 100 * kReferenceAgreement * f;
                const bool is_asymptotic =
                    monotone && std::abs(std::log2(e0 / e1) - 2.0) <= estimate::kOrderWindow &&
                    std::abs(std::log2(e1 / e2) - 2.0) <= estimate::kOrderWindow;
                const double eff = q["error"].get<double>() / e0;
                table << rotation << " N=" << (5 << k) << " mode " << i + 1 << std::setprecision(4)
                      << " f " << f << " true " << e0 << " est " << q["error"].get<double>()
                      << " eff " << eff << (is_asymptotic ? " [asymptotic]" : "")
                      << (q["reliable"].get<bool>() ? "" : " (not reliable)") << "\n";
                if (is_asymptotic) {
                    ++asymptotic;
                    lo = std::min(lo, eff);
                    hi = std::max(hi, eff);
                    BOOST_TEST(eff >= 0.5);
                    BOOST_TEST(eff <= 2.0);
                    BOOST_TEST(q["reliable"].get<bool>());
                }
                if (q["reliable"].get<bool>() && e0 > 100 * kReferenceAgreement * f) {
                    BOOST_TEST(e0 <= 3.0 * q["error"].get<double>(), "estimator failure");
                }
            }
        }
        BOOST_TEST_MESSAGE(table.str());
        BOOST_TEST_MESSAGE("joined-beam mixed " << rotation << ": " << asymptotic
                                                << " asymptotic points, effectivity " << lo << " … "
                                                << hi);
        // 5 modes × 4 meshes.
        BOOST_TEST(asymptotic >= 12, rotation << ": " << asymptotic << " asymptotic points");
    }
}

}  // namespace rotbeam
