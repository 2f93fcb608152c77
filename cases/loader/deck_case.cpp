#include "cases/loader/deck_case.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "cases/loader/beamdyn_deck.hpp"
#include "cases/loader/beamdyn_import.hpp"
#include "cases/loader/model_builder.hpp"
#include "cases/loader/yaml_file.hpp"
#include "core/errors.hpp"

namespace rotbeam::cases {

std::optional<DeckCase> read_deck_case(const std::string& text, const std::string& file) {
    // Only a text that holds the key can be a deck entry: an ordinary case is not parsed twice.
    if (text.find("beamdyn:") == std::string::npos) return std::nullopt;
    const YAML::Node root = parse_yaml_file(text, file, kCaseFile);
    if (!root["beamdyn"]) return std::nullopt;
    YamlReader r(file, {});
    r.index_lines(root);
    try {
        // The deck is the whole case: nothing beside it would be read.
        r.expect_map(root, "", {"beamdyn"});
        const YAML::Node n = root["beamdyn"];
        r.expect_map(n, "beamdyn", {"driver", "set", "refused"});
        DeckCase deck;
        const std::string driver = r.string(r.required(n, "beamdyn", "driver"), "beamdyn.driver");
        if (!is_beamdyn_driver_path(driver))
            r.fail(n["driver"], "beamdyn.driver", "expected a BeamDyn driver file (*.inp)");
        deck.driver = (std::filesystem::path(file).parent_path() / driver).lexically_normal();
        if (const YAML::Node set = n["set"]) {
            if (!set.IsSequence())
                r.fail(set, "beamdyn.set", "expected a list of key.path=value overrides");
            for (size_t i = 0; i < set.size(); ++i) {
                deck.overrides.push_back(
                    r.string(set[i], child_key("beamdyn.set", std::to_string(i))));
            }
        }
        if (const YAML::Node refused = n["refused"]) {
            r.expect_map(refused, "beamdyn.refused", {"displacement", "mixed"});
            for (const auto& item : refused) {
                const std::string key = "beamdyn.refused." + item.first.Scalar();
                const std::string words = r.string(item.second, key);
                if (words.empty()) r.fail(item.second, key, "name the words of the refusal");
                deck.refused[*parse_choice<Formulation>(item.first.Scalar())] = words;
            }
        }
        return deck;
    } catch (const YAML::Exception& e) {
        throw InputError(file + ":" + std::to_string(e.mark.line + 1) +
                         ": (yaml): " + one_line(e.msg));
    }
}

namespace {

// The file's text; `ok` false when it cannot be opened.
std::string deck_case_file_text(const std::string& path, bool& ok) {
    std::ifstream in(path, std::ios::binary);
    ok = in.good();
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

}  // namespace

std::string case_input_text(const std::string& path) {
    bool ok = false;
    std::string text = deck_case_file_text(path, ok);
    if (!ok) throw InputError(path + ": (file): cannot open the case file");
    if (const std::optional<DeckCase> deck = read_deck_case(text, path))
        text.append(1, '\n').append(import_beamdyn(deck->driver));
    return text;
}

std::map<Formulation, std::string> stated_refusals(const std::string& path) {
    bool ok = false;
    const std::string text = deck_case_file_text(path, ok);
    if (!ok) return {};
    try {
        if (const std::optional<DeckCase> deck = read_deck_case(text, path)) return deck->refused;
    } catch (const InputError&) {
        // A malformed entry states nothing; loading the case reports it.
    }
    return {};
}

}  // namespace rotbeam::cases
