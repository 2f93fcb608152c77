// `rotbeam import beamdyn DRIVER.inp [--out CASE.yaml]`: a BeamDyn deck as a rotbeam case file
// (docs/beamdyn-import.md). The text is validated by the case loader before it is written, so a
// deck that imports is a case that loads; nothing is written for a deck that does not.
#include <iostream>

#include "arguments.hpp"
#include "cases/loader/beamdyn_deck.hpp"
#include "cases/loader/beamdyn_import.hpp"
#include "cases/loader/case_loader.hpp"
#include "commands.hpp"
#include "core/atomic_file.hpp"
#include "core/errors.hpp"

namespace rotbeam::cli {

int command_import(const Args& args) {
    const CommandSpec spec{
        "import",
        "beamdyn DRIVER.inp",
        2,
        2,
        "Translate an input deck of another program into a rotbeam case. `beamdyn`: a BeamDyn "
        "driver file, the primary file it names and the blade file that one names (static and "
        "dynamic decks, a turning root included; the supported keys and the refused ones: "
        "docs/beamdyn-import.md). `rotbeam run "
        "DRIVER.inp` runs the same case directly.",
        {{"out", "CASE.yaml", "write the case to this file (default: standard output)"}}};
    const ParsedArguments a = parse_arguments(spec, args);
    if (a.help) {
        std::cout << help_text(spec);
        return 0;
    }
    if (a.positional[0] != "beamdyn") {
        throw InputError("rotbeam import: unknown format '" + a.positional[0] +
                         "' (the one format is 'beamdyn')");
    }
    const std::string& driver = a.positional[1];
    const std::string text = cases::import_beamdyn(driver);
    load_case_text(text, driver + " (imported)");
    if (const auto out = a.value("out")) {
        write_file_atomically(*out, text);
    } else {
        std::cout << text;
    }
    return 0;
}

}  // namespace rotbeam::cli
