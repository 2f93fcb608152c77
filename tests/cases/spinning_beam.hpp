// What the spinning-beam tests (test_rotating_frame, test_rotating_dynamics) share: the YAML of a
// section `s` with diagonal 6×6 stiffness and mass matrices, a run of a case written in code
// (without the error estimate: the tests compare with closed forms), and what counts as solved.
#pragma once

#include <array>
#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <vector>

#include "cases/loader/case_loader.hpp"
#include "runs/run_case.hpp"

namespace rotbeam::test {

inline void write_diagonal_section(std::ostream& c, const std::array<double, 6>& stiffness,
                                   const std::array<double, 6>& mass) {
    const auto matrix = [&c](const std::array<double, 6>& d) {
        for (int i = 0; i < 6; ++i) {
            c << "      - [";
            for (int j = 0; j < 6; ++j) c << (j ? ", " : "") << (i == j ? d[i] : 0.0);
            c << "]\n";
        }
    };
    c << "sections:\n  s:\n    stiffness:\n";
    matrix(stiffness);
    c << "    mass:\n";
    matrix(mass);
}

inline nlohmann::json run_spinning_case(const std::string& text,
                                        const std::vector<std::string>& overrides = {}) {
    RunRequest request;
    request.model = load_case_text(text, "spinning-beam.yaml", overrides);
    request.model.analysis.estimate = false;
    return run_case(request);
}

inline bool solved(const nlohmann::json& r) {
    const std::string s = r["status"].get<std::string>();
    return s == "converged" || s == "stalled-at-round-off";
}

}  // namespace rotbeam::test
