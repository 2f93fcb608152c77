// A study as independent runs plus a combine step (studies/study_runs.hpp): every run of a plan
// has its own key, a plan is the same each time it is made, and the results do not depend on how
// many threads made the runs (what lets the runs be distributed).
#include <boost/test/unit_test.hpp>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "parameterizations/registry.hpp"
#include "studies/studies.hpp"
#include "studies/study_runs.hpp"

using namespace rotbeam::cli;

namespace {

std::vector<std::string> keys_of(const std::vector<StudyRun>& plan) {
    std::vector<std::string> keys;
    for (const StudyRun& r : plan) keys.push_back(r.key);
    return keys;
}

// The result without its measured time (the one field that differs between two runs).
nlohmann::json without_time(nlohmann::json result) {
    result.erase("wall_seconds");
    return result;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(study_runs)

BOOST_AUTO_TEST_CASE(every_planned_run_has_its_own_key_and_a_plan_is_reproducible) {
    for (const SplitStudy& study : {convergence_study(), singularity_study(), extremes_study()}) {
        for (const bool quick : {true, false}) {
            const StudyOptions o{"unused", quick, false};
            const std::vector<StudyRun> plan = study.plan(o);
            BOOST_TEST(!plan.empty());
            const std::vector<std::string> keys = keys_of(plan);
            BOOST_TEST(std::set<std::string>(keys.begin(), keys.end()).size() == keys.size());
            BOOST_TEST(keys_of(study.plan(o)) == keys, boost::test_tools::per_element());
            for (const StudyRun& r : plan) BOOST_TEST(!r.spec.case_name.empty());
        }
    }
}

BOOST_AUTO_TEST_CASE(results_do_not_depend_on_the_number_of_threads) {
    // Two small roll-ups and one continuum reference: cheap, and of both kinds.
    const std::vector<StudyRun> plan = {
        {"q", StudyRun::Kind::case_run,
         RunSpec{"cantilever-moment",
                 {rotbeam::Formulation::displacement,
                  rotbeam::param::id_of<rotbeam::param::Quaternion>()},
                 {},
                 2}},
        {"r", StudyRun::Kind::case_run,
         RunSpec{"cantilever-moment",
                 {rotbeam::Formulation::mixed, rotbeam::param::id_of<rotbeam::param::Rodrigues>()},
                 {},
                 4}},
        {"ref", StudyRun::Kind::continuum_reference,
         RunSpec{"cantilever-moment", {}, {"analysis.load_factors=[0.5]"}, 0}},
    };
    const StudyResults one = execute_runs(plan, 1);
    const StudyResults three = execute_runs(plan, 3);
    BOOST_TEST(one.size() == plan.size());
    for (const StudyRun& r : plan) {
        BOOST_TEST(result_of(one, r.key).contains("status"));
        BOOST_TEST(without_time(result_of(one, r.key)) == without_time(result_of(three, r.key)));
    }
}

BOOST_AUTO_TEST_CASE(a_repeated_or_missing_key_is_api_misuse) {
    const RunSpec spec{
        "cantilever-moment",
        {rotbeam::Formulation::displacement, rotbeam::param::id_of<rotbeam::param::Quaternion>()},
        {},
        2};
    const std::vector<StudyRun> twice = {{"a", StudyRun::Kind::case_run, spec},
                                         {"a", StudyRun::Kind::case_run, spec}};
    BOOST_CHECK_THROW(results_by_key(twice, {nlohmann::json(), nlohmann::json()}),
                      std::logic_error);
    BOOST_CHECK_THROW(results_by_key(twice, {nlohmann::json()}), std::logic_error);
    BOOST_CHECK_THROW(result_of(StudyResults{}, "a"), std::logic_error);
}

BOOST_AUTO_TEST_SUITE_END()
