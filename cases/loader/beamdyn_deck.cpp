// The three files of a BeamDyn deck, read in BeamDyn's order (its Driver_Beam_Subs.f90
// BD_ReadDvrFile, BeamDyn_IO.f90 BD_ReadPrimaryFile and BD_ReadBladeFile), with the options
// rotbeam does not model refused by name. docs/beamdyn-import.md has the table of every key.
#include "cases/loader/beamdyn_deck.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "cases/loader/beamdyn_lines.hpp"
#include "cases/loader/limits.hpp"
#include "core/errors.hpp"

namespace rotbeam::cases {

namespace {

namespace fs = std::filesystem;

// A deck with more than this many members, key points or stations is refused; the limits are
// far above a blade's (the NREL 5-MW blade has 49 stations and one member) and each one is also
// bounded by the lines left in its file, checked before anything is allocated.
constexpr int kMaxMembers = 1000;
constexpr int kMaxKeyPoints = 100000;
constexpr int kMaxStations = 100000;

void refuse_if(bool unsupported, DeckLines& in, std::string_view key, const std::string& why) {
    if (unsupported) in.fail(key, why);
}

// Driver: returns the primary file name as written.
std::string parse_driver(DeckLines& in, BeamDynDeck& deck) {
    in.comment("(header)");
    in.comment("(title)");
    in.comment("SIMULATION CONTROL");
    const bool dynamic = in.flag("DynamicSolve");
    // Used only by a dynamic solve; a static one repeats the same solve at each time.
    deck.dynamic = dynamic;
    deck.t_initial = in.number("t_initial");
    deck.t_final = in.number("t_final");
    const int t_final_line = in.line();
    deck.dt = in.number("dt");
    const int dt_line = in.line();
    in.comment("GRAVITY PARAMETER");
    deck.gravity = {in.number("Gx"), in.number("Gy"), in.number("Gz")};
    in.comment("FRAME PARAMETER");
    deck.root_position = {in.number("GlbPos(1)"), in.number("GlbPos(2)"), in.number("GlbPos(3)")};
    in.comment("(direction cosine matrix)");
    in.comment("(direction cosine matrix)");
    deck.dcm_line = in.line() + 1;
    for (auto& row : deck.root_dcm) {
        const auto r = in.row("GlbDCM", 3);
        row = {r[0], r[1], r[2]};
    }
    const bool root_frame = in.flag("GlbRotBladeT0");
    const int root_frame_line = in.line();
    in.comment("ROOT VELOCITY PARAMETER");
    std::array<double, 3> root_velocity{};
    std::array<int, 3> root_velocity_line{};
    for (size_t i = 0; i < 3; ++i) {
        root_velocity[i] = in.number("RootVel(" + std::to_string(i + 4) + ")");
        root_velocity_line[i] = in.line();
    }
    auto refuse_at = [&](int line, const std::string& key, const std::string& why) {
        throw InputError(in.name() + ":" + std::to_string(line) + ": " + key + ": " + why);
    };
    // A dynamic deck: time span and step checked here; a rotating root is the turning supports of
    // docs/rotating-frame.md (BeamDyn's driver turns the root about the global origin).
    if (dynamic) {
        if (!(deck.t_final > deck.t_initial)) {
            refuse_at(t_final_line, "t_final", "must be greater than t_initial");
        }
        if (!(deck.dt > 0.0) || deck.dt > deck.t_final - deck.t_initial) {
            refuse_at(dt_line, "dt", "must be positive and at most t_final - t_initial");
        }
        deck.root_velocity = root_velocity;
    } else {
        for (size_t i = 0; i < 3; ++i) {
            if (root_velocity[i] != 0.0) {
                refuse_at(root_velocity_line[i], "RootVel(" + std::to_string(i + 4) + ")",
                          "a rotating root in a static solve is not modelled (BeamDyn ignores "
                          "it there; a steady rotation is rotbeam's rotating_frame)");
            }
        }
    }
    // GlbRotBladeT0 = False: BeamDyn computes in the global frame and starts the root at GlbDCM
    // relative to it; with an identity GlbDCM both frames coincide, so only that case is taken.
    if (!root_frame) {
        bool identity = true;
        for (size_t r = 0; r < 3; ++r) {
            for (size_t c = 0; c < 3; ++c) {
                identity = identity && std::abs(deck.root_dcm[r][c] - (r == c ? 1.0 : 0.0)) <= 1e-6;
            }
        }
        if (!identity) {
            refuse_at(root_frame_line, "GlbRotBladeT0",
                      "False (calculations in the global frame, the root turned by GlbDCM in "
                      "it) is modelled only with an identity GlbDCM");
        }
    }
    in.comment("APPLIED FORCE");
    for (int i = 0; i < 6; ++i) {
        deck.distributed_load[static_cast<size_t>(i)] =
            in.number("DistrLoad(" + std::to_string(i + 1) + ")");
    }
    for (int i = 0; i < 6; ++i) {
        deck.tip_load[static_cast<size_t>(i)] = in.number("TipLoad(" + std::to_string(i + 1) + ")");
    }
    const int point_loads = in.integer("NumPointLoads", 0, 1000000);
    refuse_if(point_loads != 0, in, "NumPointLoads",
              "point loads along the span are not imported (only TipLoad and DistrLoad)");
    in.comment("(point load table header)");
    in.comment("(point load table units)");
    in.comment("PRIMARY INPUT FILE");
    const std::string primary = in.text("InputFile");
    // What follows (WrVTK, VTK_fps) is output only.
    return primary;
}

// Primary file: returns the blade file name as written.
std::string parse_primary(DeckLines& in, BeamDynDeck& deck) {
    in.comment("(header)");
    in.comment("(title)");
    in.comment("SIMULATION CONTROL");
    in.flag("Echo");                                      // output only
    deck.quasi_static_init = in.flag("QuasiStaticInit");  // dynamic only
    deck.rho_infinity = in.number("rhoinf");              // dynamic only
    if (deck.dynamic && !(deck.rho_infinity >= 0.0 && deck.rho_infinity <= 1.0)) {
        in.fail("rhoinf", "must lie in [0, 1]");
    }
    deck.quadrature = in.integer("quadrature", 1, 2);
    deck.quadrature_line = in.line();
    double unused = 0.0;
    double refine = 1.0;  // DEFAULT: 1; used only with trapezoidal quadrature
    in.number_or_default("refine", refine);
    deck.refine_line = in.line();
    if (deck.quadrature == 2) {
        if (!(refine >= 1.0 && refine <= kMaxRefine && refine == std::floor(refine))) {
            in.fail("refine", "must be a whole number from 1 to " + std::to_string(kMaxRefine));
        }
        deck.refine = static_cast<int>(refine);
    }
    // Solver controls: rotbeam's own convergence criteria apply (docs/beamdyn-import.md).
    in.number_or_default("n_fact", unused);
    if (in.number_or_default("DTBeam", deck.beam_dt) && deck.dynamic && !(deck.beam_dt > 0.0)) {
        in.fail("DTBeam", "must be positive");
    }
    for (const char* key : {"load_retries", "NRMax", "stop_tol"}) in.number_or_default(key, unused);
    for (const char* key : {"tngt_stf_fd", "tngt_stf_comp"}) {
        if (in.peek_label() == key) {
            std::string value = in.text(key);
            std::transform(value.begin(), value.end(), value.begin(),
                           [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
            if (value != "default" && value != "false" && value != "f" && value != ".false.") {
                in.fail(key, "a finite-difference tangent is not modelled (rotbeam's is analytic)");
            }
        }
    }
    for (const char* key : {"tngt_stf_pert", "tngt_stf_difftol"}) {
        if (in.peek_label() == key) in.number_or_default(key, unused);
    }
    if (in.peek_label() == "RotStates") in.flag("RotStates");  // linearization only
    in.comment("GEOMETRY PARAMETER");
    const int members = in.integer("member_total", 1, kMaxMembers);
    refuse_if(deck.quadrature == 2 && members != 1, in, "member_total",
              "trapezoidal quadrature takes one member only (as in BeamDyn)");
    const int key_points = in.integer("kp_total", 3, kMaxKeyPoints);
    if (members + 2 + key_points > in.lines_left()) {
        in.fail("kp_total", "the file has fewer lines than member_total and kp_total need");
    }
    int sum = 0;
    for (int m = 0; m < members; ++m) {
        const auto r = in.row("member key points", 2);
        if (r[0] != m + 1)
            in.fail("member key points", "members must be numbered 1, 2, ... in order");
        if (r[1] != std::floor(r[1]) || r[1] < 3 || r[1] > kMaxKeyPoints) {
            in.fail("member key points", "a member needs a whole number of at least 3 key points");
        }
        deck.member_key_points.push_back(static_cast<int>(r[1]));
        sum += static_cast<int>(r[1]);
    }
    if (sum != key_points + members - 1) {
        in.fail("kp_total", "the members' key points (" + std::to_string(sum) +
                                ") do not add up to kp_total + member_total - 1 (" +
                                std::to_string(key_points + members - 1) + ")");
    }
    in.comment("(key point header)");
    in.comment("(key point units)");
    deck.key_points_line = in.line() + 1;
    deck.key_points.reserve(static_cast<size_t>(key_points));
    for (int k = 0; k < key_points; ++k) {
        const auto r = in.row("kp_xr kp_yr kp_zr initial_twist", 4);
        deck.key_points.push_back({r[0], r[1], r[2], r[3]});
    }
    const BeamDynKeyPoint& first = deck.key_points.front();
    if (first.x != 0.0 || first.y != 0.0 || first.z != 0.0) {
        throw InputError(in.name() + ":" + std::to_string(deck.key_points_line) +
                         ": kp_xr kp_yr kp_zr: the first key point must be at the root (0, 0, 0)");
    }
    in.comment("MESH PARAMETER");
    // Gauss quadrature needs order ≥ 2 (BeamDyn refuses 1 with it), trapezoidal ≥ 1.
    deck.order = in.integer("order_elem", deck.quadrature == 2 ? 1 : 2, kMaxOrder);
    deck.order_line = in.line();
    in.comment("MATERIAL PARAMETER");
    const std::string blade = in.text("BldFile");
    // The pitch actuator (older decks) must be off; the outputs that follow are not read.
    while (!in.at_end()) {
        if (in.peek_label() == "UsePitchAct") {
            refuse_if(in.flag("UsePitchAct"), in, "UsePitchAct",
                      "a pitch actuator is not modelled");
            break;
        }
        in.comment("(outputs)");
    }
    return blade;
}

void parse_blade(DeckLines& in, BeamDynDeck& deck) {
    in.comment("(header)");
    in.comment("(title)");
    in.comment("Blade Parameters");
    const int stations = in.integer("station_total", 2, kMaxStations);
    deck.stations_line = in.line();
    // Each station takes 14 lines (eta, 6 + 6 rows, two separators); refuse a count the file
    // cannot hold before reserving for it.
    if (stations * 14 > in.lines_left() + 1) {
        in.fail("station_total",
                "the file has fewer lines than " + std::to_string(stations) + " stations need");
    }
    deck.damping_type = in.integer("damp_type", 0, 2);
    refuse_if(deck.damping_type == 2, in, "damp_type", "modal damping (2) is not modelled");
    in.comment("Stiffness-Proportional Damping");
    in.comment("(mu header)");
    in.comment("(mu units)");
    const auto mu = in.row("mu1..mu6", 6);
    std::copy(mu.begin(), mu.end(), deck.damping.begin());
    in.comment("Modal Damping");
    in.integer("n_modes", 0, 1000000);
    in.comment("zeta");  // used only by modal damping, refused above
    in.comment("Distributed Properties");
    deck.stations.reserve(static_cast<size_t>(stations));
    for (int s = 0; s < stations; ++s) {
        if (s > 0) in.comment("(blank line)");
        BeamDynStation st;
        st.eta = in.row("station_eta", 1)[0];
        for (auto& row : st.stiffness) {
            const auto r = in.row("stiffness matrix", 6);
            std::copy(r.begin(), r.end(), row.begin());
        }
        in.comment("(blank line)");
        for (auto& row : st.mass) {
            const auto r = in.row("mass matrix", 6);
            std::copy(r.begin(), r.end(), row.begin());
        }
        deck.stations.push_back(st);
    }
    if (deck.stations.front().eta != 0.0 || deck.stations.back().eta != 1.0) {
        throw InputError(in.name() + ":" + std::to_string(deck.stations_line) +
                         ": station_eta: the first station must be at 0 and the last at 1");
    }
    for (size_t s = 1; s < deck.stations.size(); ++s) {
        if (!(deck.stations[s].eta > deck.stations[s - 1].eta)) {
            throw InputError(in.name() + ":" + std::to_string(deck.stations_line) +
                             ": station_eta: stations must increase strictly (station " +
                             std::to_string(s + 1) + ")");
        }
    }
}

std::string read_deck_file(const std::string& path, const std::string& named_by) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) {
        throw InputError(named_by + ": (file): cannot open '" + path + "'");
    }
    const auto size = fs::file_size(path, ec);
    if (ec || size > kMaxFileBytes) {
        throw InputError(path + ":1: (file): larger than " + std::to_string(kMaxFileBytes) +
                         " bytes (a limit of the case format)");
    }
    std::ifstream in(path, std::ios::binary);
    std::string text(static_cast<size_t>(size), '\0');
    if (!in.read(text.data(), static_cast<std::streamsize>(size))) {
        throw InputError(path + ": (file): cannot read it");
    }
    return text;
}

// A file named inside another one: relative to the naming file's folder.
std::string named_path(const std::string& naming_file, const std::string& name) {
    const fs::path p(name);
    return p.is_absolute() ? name : (fs::path(naming_file).parent_path() / p).string();
}

}  // namespace

bool is_beamdyn_driver_path(const std::string& path) {
    std::string ext = fs::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext == ".inp";
}

BeamDynDeck parse_beamdyn_deck(const DeckText& driver, const DeckText& primary,
                               const DeckText& blade) {
    BeamDynDeck deck;
    DeckLines d(driver.name, driver.text);
    parse_driver(d, deck);
    DeckLines p(primary.name, primary.text);
    parse_primary(p, deck);
    DeckLines b(blade.name, blade.text);
    parse_blade(b, deck);
    deck.driver_name = driver.name;
    deck.primary_name = primary.name;
    deck.blade_name = blade.name;
    return deck;
}

BeamDynDeck read_beamdyn_deck(const std::string& driver_path) {
    BeamDynDeck deck;
    DeckLines d(driver_path, read_deck_file(driver_path, driver_path));
    const std::string primary_name = parse_driver(d, deck);
    const std::string primary_path = named_path(driver_path, primary_name);
    DeckLines p(
        primary_path,
        read_deck_file(primary_path, driver_path + ":" + std::to_string(d.line()) + ": InputFile"));
    const std::string blade_name = parse_primary(p, deck);
    const std::string blade_path = named_path(primary_path, blade_name);
    DeckLines b(blade_path, read_deck_file(blade_path, primary_path + ": BldFile"));
    parse_blade(b, deck);
    deck.driver_name = driver_path;
    deck.primary_name = primary_path;
    deck.blade_name = blade_path;
    return deck;
}

}  // namespace rotbeam::cases
