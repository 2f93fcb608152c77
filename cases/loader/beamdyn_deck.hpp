// A BeamDyn input deck as BeamDyn reads it (docs/beamdyn-import.md): the driver file, the primary
// file it names and the blade-properties file that one names.
//
// BeamDyn reads its files by position: line N holds one value (the first token) or a row of
// numbers, whatever its label says. read_beamdyn_deck reads them in the same order and also
// checks each label against the key BeamDyn expects there, so that a shifted line is refused
// naming the key instead of being read as another one. Every problem, and every option rotbeam
// does not model, throws InputError with one line `FILE:LINE: KEY: problem`.
//
// Sizes (key points, members, stations) are checked against the lines left in the file before
// anything is allocated; each file obeys the case files' limit (cases/loader/limits.hpp).
#pragma once

#include <array>
#include <string>
#include <vector>

namespace rotbeam::cases {

// The text of one file and the name used in messages.
struct DeckText {
    std::string name;
    std::string text;
};

struct BeamDynStation {
    double eta = 0.0;                                  // fraction of the blade length
    std::array<std::array<double, 6>, 6> stiffness{};  // BeamDyn axes: z is the beam axis
    std::array<std::array<double, 6>, 6> mass{};
};

struct BeamDynKeyPoint {
    double x = 0.0, y = 0.0, z = 0.0;  // blade-root frame, m
    double twist_deg = 0.0;            // initial_twist as written (BeamDyn uses its negative)
};

struct BeamDynDeck {
    // driver
    std::array<double, 3> gravity{};
    std::array<double, 3> root_position{};
    std::array<std::array<double, 3>, 3> root_dcm{};  // rows as written (global → root frame)
    std::array<double, 6> distributed_load{};         // N/m, N·m/m, global axes
    std::array<double, 6> tip_load{};                 // N, N·m, global axes
    // A dynamic solve (DynamicSolve): the time span, the driver's step, the root's angular
    // velocity about the global origin (RootVel(4..6)); from the primary file rhoinf, DTBeam (0:
    // DEFAULT, the driver's dt) and QuasiStaticInit.
    bool dynamic = false;
    double t_initial = 0.0, t_final = 0.0, dt = 0.0, rho_infinity = 0.0, beam_dt = 0.0;
    bool quasi_static_init = false;
    std::array<double, 3> root_velocity{};
    // primary
    std::vector<int> member_key_points;  // key points of each member (neighbours share one)
    std::vector<BeamDynKeyPoint> key_points;
    int order = 0;  // order_elem
    // quadrature: 1 Gauss (order_elem + 1 points), 2 trapezoidal (at the blade stations, each
    // interval divided into `refine` parts; one member only, as in BeamDyn).
    int quadrature = 1;
    int refine = 1;
    // blade
    int damping_type = 0;
    std::array<double, 6> damping{};  // mu1..mu6
    std::vector<BeamDynStation> stations;
    // The files and lines where the values came from, for messages about them.
    std::string driver_name, primary_name, blade_name;
    int dcm_line = 0, stations_line = 0, key_points_line = 0, order_line = 0, quadrature_line = 0,
        refine_line = 0;
};

// Reads the driver file at `driver_path` and the files it names (relative to the file naming
// them), checking sizes before reading each file.
BeamDynDeck read_beamdyn_deck(const std::string& driver_path);

// The same from texts already in memory (tests, the fuzz target): `primary` and `blade` are the
// files the driver and the primary name, whatever names they give.
BeamDynDeck parse_beamdyn_deck(const DeckText& driver, const DeckText& primary,
                               const DeckText& blade);

// True for a path that names a BeamDyn driver file (extension `.inp`, any case).
bool is_beamdyn_driver_path(const std::string& path);

}  // namespace rotbeam::cases
