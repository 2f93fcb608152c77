// The BeamDyn decks shipped in tests/data/beamdyn, and reading BeamDyn's driver output
// (bd_driver.out, shipped with some of them): the tests compare rotbeam with the last row BeamDyn
// printed.
#pragma once

#include <unistd.h>

#include <boost/test/unit_test.hpp>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace rotbeam::test {

// The folder of the shipped decks (one folder per deck, its driver file bd_driver.inp).
inline const std::string kBeamDynDecks = std::string(ROTBEAM_SOURCE_DIR) + "/tests/data/beamdyn/";

// The last row of a BeamDyn output file, by channel name (the header row starts with "Time", the
// units row with "(s)").
inline std::map<std::string, double> last_output_row(const std::string& file) {
    std::ifstream in(file);
    BOOST_REQUIRE_MESSAGE(in.good(), "cannot read " << file);
    std::vector<std::string> names;
    std::vector<double> values;
    for (std::string line; std::getline(in, line);) {
        std::istringstream s(line);
        std::vector<std::string> tokens;
        for (std::string t; s >> t;) tokens.push_back(t);
        if (tokens.empty()) continue;
        if (tokens[0] == "Time") {
            names = tokens;
        } else if (!names.empty() && tokens.size() == names.size() && tokens[0] != "(s)") {
            values.clear();
            for (const std::string& t : tokens) values.push_back(std::stod(t));
        }
    }
    BOOST_REQUIRE(!values.empty());
    std::map<std::string, double> row;
    for (std::size_t i = 0; i < names.size(); ++i) row[names[i]] = values[i];
    return row;
}

// A temporary copy of the driver file `driver` with each `from` text replaced by its `to` (each
// must occur), named `name` plus the process id in the system's temporary folder; the files the
// driver names must then be given by absolute paths. The caller removes it.
inline std::filesystem::path changed_driver(
    const std::string& driver, const std::string& name,
    const std::vector<std::pair<std::string, std::string>>& changes) {
    std::ifstream in(driver);
    std::stringstream text;
    text << in.rdbuf();
    std::string deck = text.str();
    for (const auto& [from, to] : changes) {
        const std::size_t at = deck.find(from);
        BOOST_TEST_REQUIRE(at != std::string::npos, driver << " has no '" << from << "'");
        deck.replace(at, from.size(), to);
    }
    const std::filesystem::path file =
        std::filesystem::temp_directory_path() / (name + "-" + std::to_string(::getpid()) + ".inp");
    std::ofstream(file) << deck;
    return file;
}

}  // namespace rotbeam::test
