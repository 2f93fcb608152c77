// The combination registry (combinations/registry.hpp, dispatch.hpp): what it lists, how the gate
// and the studies spread it, the names it prints and parses, and that every combination it lists
// builds its static problem (which links every formulation × parameterization piece) with the
// unloaded reference configuration as an equilibrium.
#include <boost/test/unit_test.hpp>
#include <set>

#include "cases/loader/case_loader.hpp"
#include "combinations/dispatch.hpp"
#include "combinations/registry.hpp"

namespace rotbeam::test {

namespace {

const std::size_t kParameterizations = param::parameterization_ids().size();

}  // namespace

BOOST_AUTO_TEST_SUITE(combination_registry)

BOOST_AUTO_TEST_CASE(every_formulation_meets_every_parameterization_once) {
    const std::vector<comb::Combination> all = comb::all_combinations(false);
    BOOST_TEST(all.size() == comb::kFormulations.size() * kParameterizations);
    std::set<std::string> labels;
    for (const comb::Combination& c : all) {
        BOOST_TEST(!c.interpolation.has_value());
        BOOST_TEST(!c.wm_map.has_value());
        labels.insert(c.label());
    }
    BOOST_TEST(labels.size() == all.size());
    // Formulation-major, in enum and registry order (the suite's and the studies' order).
    BOOST_TEST(all.front().label() == "displacement/quaternion");
    BOOST_TEST(all.back().label() == "mixed/euler-angles");
}

// The gate's spread: one run per interpolation strategy of the displacement formulation, one
// per map of the mixed Wiener–Milenković; counted from the traits, not from a copy of them.
BOOST_AUTO_TEST_CASE(strategies_spread_the_combinations_that_have_them) {
    std::size_t expected = 0;
    for (const comb::FormulationTraits& f : comb::kFormulations) {
        for (const ParameterizationId r : param::parameterization_ids()) {
            if (!f.interpolations.empty()) {
                expected += f.interpolations.size();
            } else {
                expected += comb::has_wm_map(f.id, r) ? 2 : 1;
            }
        }
    }
    const std::vector<comb::Combination> gate = comb::all_combinations(true, true);
    BOOST_TEST(gate.size() == expected);
    BOOST_TEST(gate.size() == 2 * kParameterizations + kParameterizations + 1);
    int continuous = 0;
    for (const comb::Combination& c : gate) {
        if (c.wm_map == WmMap::continuous) {
            ++continuous;
            BOOST_TEST(c.label() == "mixed/wiener-milenkovic/continuous");
        }
        BOOST_TEST(c.interpolation.has_value() ==
                   !comb::traits(c.formulation).interpolations.empty());
    }
    BOOST_TEST(continuous == 1);
}

BOOST_AUTO_TEST_CASE(names_parse_back_to_their_ids) {
    for (const ParameterizationId id : param::parameterization_ids()) {
        BOOST_TEST((param::parse_parameterization(param::name_of(id)) == id));
    }
    for (const Formulation f : comb::formulations()) {
        BOOST_TEST((parse_choice<Formulation>(choice_name(f)) == f));
    }
    for (const Integrator i :
         {Integrator::generalized_alpha, Integrator::trapezoidal, Integrator::ida,
          Integrator::gauss_legendre_2, Integrator::gauss_legendre_3, Integrator::radau_iia_3}) {
        BOOST_TEST((parse_choice<Integrator>(choice_name(i)) == i));
    }
    BOOST_TEST(!parse_choice<Integrator>("").has_value());  // `automatic` has no name
    BOOST_TEST(!parse_choice<Formulation>("Mixed").has_value());
    BOOST_TEST(!param::parse_parameterization("euler").has_value());
}

BOOST_AUTO_TEST_CASE(integrators_default_to_the_first_listed_and_refuse_the_others) {
    BOOST_TEST((comb::integrator_for(Formulation::displacement, Integrator::automatic) ==
                Integrator::generalized_alpha));
    BOOST_TEST((comb::integrator_for(Formulation::mixed, Integrator::automatic) ==
                Integrator::trapezoidal));
    BOOST_TEST(comb::takes_integrator(Formulation::mixed, Integrator::ida));
    BOOST_TEST(!comb::takes_integrator(Formulation::mixed, Integrator::generalized_alpha));
    BOOST_TEST(!comb::takes_integrator(Formulation::displacement, Integrator::trapezoidal));
    BOOST_TEST(comb::takes_integrator(Formulation::displacement, Integrator::gauss_legendre_3));
    BOOST_TEST(!comb::takes_integrator(Formulation::mixed, Integrator::gauss_legendre_2));
    BOOST_TEST(comb::takes_integrator(Formulation::mixed, Integrator::radau_iia_3));
    BOOST_TEST(!comb::takes_integrator(Formulation::displacement, Integrator::radau_iia_3));
}

// Every listed combination (and the mixed WM's continuous map) builds its static problem from the
// roll-up case, and at load factor 0 the reference configuration is its equilibrium: the scaled
// residual is round-off (bound 1e-12: the unloaded residual is the elastic force of a zero
// strain, exactly zero in the displacement formulation; in the mixed one the element equations
// at F = M = 0 and u = 0 cancel to round-off of terms of size 1).
BOOST_AUTO_TEST_CASE(every_combination_builds_and_the_unloaded_reference_is_an_equilibrium) {
    const std::string path = std::string(ROTBEAM_SOURCE_DIR) + "/cases/cantilever-moment.yaml";
    int built = 0;
    for (const comb::Combination& c : comb::all_combinations(true, true)) {
        std::vector<std::string> overrides = {"discretization.formulation=" + c.formulation_name(),
                                              "discretization.rotation=" + c.rotation_name()};
        if (c.interpolation) {
            overrides.push_back("discretization.interpolation=" +
                                std::string(choice_name(*c.interpolation)));
        }
        if (c.wm_map) {
            overrides.push_back("discretization.wm_map=" + std::string(choice_name(*c.wm_map)));
        }
        const Model model = load_case(path, overrides);
        comb::dispatch_formulation(c.formulation, [&]<Formulation F>() {
            comb::dispatch_parameterization_of<F>(model.discretization, [&]<class P>() {
                typename comb::StaticsOf<F, P>::type problem(model);
                problem.set_load_factor(0.0);
                VecX r;
                problem.evaluate(r, nullptr);
                BOOST_TEST_REQUIRE(r.size() == problem.size(), c.label());
                const double scaled =
                    r.cwiseQuotient(problem.residual_scale()).template lpNorm<Eigen::Infinity>();
                BOOST_TEST(scaled <= 1e-12, c.label() << ": scaled residual " << scaled);
                ++built;
            });
        });
    }
    BOOST_TEST(built == static_cast<int>(comb::all_combinations(true, true).size()));
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace rotbeam::test
