// The YAML of a section `s` with diagonal 6×6 stiffness and mass matrices, for test cases written
// in code (the spinning beams of test_rotating_frame and test_rotating_dynamics).
#pragma once

#include <array>
#include <ostream>

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

}  // namespace rotbeam::test
