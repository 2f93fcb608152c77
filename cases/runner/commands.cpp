#include "commands.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>
#include <thread>

#include "arguments.hpp"
#include "cases/loader/beamdyn_deck.hpp"
#include "cases/loader/case_loader.hpp"
#include "cases/loader/yaml_reader.hpp"
#include "core/errors.hpp"
#include "core/results.hpp"
#include "distribution/distributed.hpp"
#include "distribution/study_help.hpp"
#include "distribution/study_registry.hpp"
#include "estimates/stated_accuracy.hpp"
#include "parameterizations/registry.hpp"
#include "parameterizations/rotation_study.hpp"
#include "runs/accuracy_run.hpp"
#include "runs/beamdyn_frame.hpp"
#include "runs/continuum_json.hpp"
#include "runs/frame_recorder.hpp"
#include "runs/history_csv.hpp"
#include "runs/run_case.hpp"
#include "runs/steps_csv.hpp"
#include "runs/vtk_output.hpp"

namespace rotbeam::cli {

namespace fs = std::filesystem;

namespace {

const OptionSpec kSetOption{"set", "KEY.PATH=VALUE",
                            "override any case key, validated like the file (default: none)", true};

// Whether the key path `key` is one `pattern` stands for (a `*` segment matches any one segment).
bool key_matches(const std::string& pattern, const std::string& key) {
    std::stringstream p(pattern), k(key);
    std::string ps, ks;
    while (std::getline(p, ps, '.')) {
        if (!std::getline(k, ks, '.') || (ps != "*" && ps != ks)) return false;
    }
    return !std::getline(k, ks, '.');
}

// The loader names an override's key (`FILE:--set: KEY: problem`); for a value given by a
// shorthand the message names the option the user typed, and the key:
// `FILE:--elements: members.beam.elements: problem`. Left as it is when a --set names the same key
// too (either could be the one refused).
std::string name_the_option(const std::string& message, const ParsedArguments& a) {
    const std::string marker = ":--set: ";
    const size_t at = message.find(marker);
    if (at == std::string::npos) return message;
    const size_t key_end = message.find(": ", at + marker.size());
    if (key_end == std::string::npos) return message;
    const std::string key = message.substr(at + marker.size(), key_end - at - marker.size());
    for (const auto& [option, pattern] : run_shorthands()) {
        if (!a.value(option) || !key_matches(pattern, key)) continue;
        for (const std::string& s : a.values("set")) {
            if (key_matches(pattern, s.substr(0, s.find('=')))) return message;
        }
        return message.substr(0, at) + ":--" + option + ": " + message.substr(at + marker.size());
    }
    return message;
}

Model load_with_options(const std::string& path, const ParsedArguments& a,
                        CaseParts parts = CaseParts::all) {
    try {
        return load_case(path, case_overrides(a), parts);
    } catch (const InputError& e) {
        throw InputError(name_the_option(e.what(), a));
    }
}

// "± 3.1e-09" and, when the estimate is not reliable, why.
std::string plus_minus(const nlohmann::json& q) {
    std::ostringstream s;
    s << std::setprecision(2) << "± " << q["error"].get<double>();
    if (!q["reliable"].get<bool>())
        s << " (not reliable: " << q["reason"].get<std::string>() << ")";
    return s.str();
}

// A modal run's modes: frequency (or why it is not reported), growth rate and the checks.
void print_modes(const nlohmann::json& r, std::ostream& os) {
    if (!r.contains("modes")) return;
    const std::streamsize precision = os.precision();
    int k = 0;
    for (const auto& m : r["modes"]) {
        ++k;
        os << "  mode " << k << ": ";
        if (m.contains("frequency_hz")) {
            os << std::setprecision(10) << m["frequency_hz"].get<double>() << " Hz";
        } else {
            os << "not reported (s = " << m["s"][0].get<double>() << " + "
               << m["s"][1].get<double>() << "i)";
        }
        const auto& c = m["check"];
        os << std::setprecision(2) << std::scientific << "  growth rate "
           << m.value("growth_rate", 0.0) << " 1/s, backward error "
           << c["backward_error"].get<double>();
        if (c.contains("error_bound")) os << ", error bound " << c["error_bound"].get<double>();
        if (c.contains("mass_orthogonality"))
            os << ", mass orthogonality " << c["mass_orthogonality"].get<double>();
        if (c.contains("mass_participation"))
            os << ", mass participation " << c["mass_participation"].get<double>();
        if (c.contains("failed")) os << "  REJECTED (" << c["failed"].get<std::string>() << ")";
        os << std::defaultfloat << "\n";
        if (m.contains("estimate")) {
            const auto& e = m["estimate"];
            os << "          ";
            if (e.contains("frequency")) {
                os << plus_minus(e["frequency"]) << " Hz ("
                   << r["estimate"]["method"].get<std::string>() << " estimate)\n";
            } else {
                os << "no estimate: " << e.value("reason", std::string()) << "\n";
            }
        }
    }
    os.precision(precision);
}

// One line under a point (or a mode) with its estimated discretization error.
void print_point_estimate(const nlohmann::json& e, const std::string& method, std::ostream& os) {
    os << "             ";
    if (!e.contains("displacement")) {
        os << "no estimate: " << e.value("reason", std::string()) << "\n";
        return;
    }
    os << "|u| " << plus_minus(e["displacement"]) << "  angle " << plus_minus(e["rotation"])
       << " rad (" << method << " estimate)\n";
}

// A dynamic estimate's maxima over the history, relative to each history's amplitude, the phase
// criterion and the cost ratios.
void print_history_estimate(const nlohmann::json& e, std::ostream& os) {
    os << std::setprecision(2);
    if (e.contains("motion")) {
        os << "  histories measured " << e["motion"].get<std::string>()
           << " (rotating_frame.points)\n";
    }
    for (const auto& [name, point] : e["history"].items()) {
        for (const auto& [quantity, h] : point.items()) {
            if (!h.contains("relative")) continue;
            os << "  " << name << " " << quantity << " history: max error "
               << h["relative"].get<double>() << " of its amplitude "
               << h["amplitude"].get<double>() << " (space " << h["relative_space"].get<double>()
               << ", time " << h["relative_time"].get<double>() << ")\n";
        }
    }
    os << "  phase error " << e["phase_error_rad"].get<double>() << " rad ("
       << e["phase_of"].get<std::string>() << "): time estimate "
       << (e["time_reliable"].get<bool>() ? "reliable" : "not reliable") << "; companions cost "
       << e["cost"]["wall_ratio"].get<double>() << "x the run's wall time, "
       << e["cost"]["work_ratio"].get<double>() << "x its Newton work\n";
}

// The estimate's method, companions and cost, or why there is none.
void print_estimate_summary(const nlohmann::json& e, std::ostream& os) {
    os << "estimate: " << e["status"].get<std::string>();
    if (e.contains("method") && !e["companions"].empty()) {
        os << " (" << e["method"].get<std::string>() << "; companions";
        for (const auto& c : e["companions"]) {
            os << " " << c["label"].get<std::string>() << ": " << c["status"].get<std::string>();
        }
        os << std::setprecision(3) << "; " << e["wall_seconds"].get<double>() << " s";
        if (e.value("unreliable", 0) > 0) os << "; " << e["unreliable"] << " not reliable";
        os << ")";
    }
    if (e.contains("reason")) os << " — " << e["reason"].get<std::string>();
    os << "\n";
    if (e.contains("history")) print_history_estimate(e, os);
}

// Accuracy control: every attempt with its cost and decision, then the outcome.
void print_accuracy_summary(const nlohmann::json& a, std::ostream& os) {
    os << std::setprecision(3) << "accuracy " << a["tolerance"].get<double>()
       << " (estimates <= " << a["target"].get<double>() << " of their scale; "
       << a["strategy"].get<std::string>() << "):\n";
    for (const auto& t : a["attempts"]) {
        os << "  " << t["elements"] << " elements, order " << t["order"] << ", ";
        if (t.contains("refine")) os << "refine " << t["refine"] << ", ";
        if (t.contains("time_tolerance")) {
            os << "time tolerance " << t["time_tolerance"].get<double>();
        } else {
            os << t["substeps"] << " sub-steps";
        }
        os << ": " << t["status"].get<std::string>();
        // With quantities missing, the worst is over those that have an estimate: not a measure.
        const bool complete = t.value("missing", 0) == 0;
        if (!complete) {
            os << ", estimate incomplete (" << t["missing"].get<int>() << " without, status "
               << t.value("estimate_status", std::string("none")) << ")";
        } else if (t.contains("worst_relative")) {
            os << ", worst estimate " << t["worst_relative"].get<double>() << " ("
               << t["worst_quantity"].get<std::string>() << ")";
        }
        if (complete && t.contains("worst_space")) {
            os << ", space " << t["worst_space"].get<double>() << ", time "
               << t["worst_time"].get<double>();
        }
        os << "; " << t["wall_seconds"].get<double>() << " s";
        if (t.contains("next")) os << " -> " << t["next"].get<std::string>();
        os << "\n";
    }
    os << "accuracy: " << a["status"].get<std::string>() << ", " << a["chosen"]["elements"]
       << " elements, order " << a["chosen"]["order"] << ", ";
    if (a["chosen"].contains("refine")) os << "refine " << a["chosen"]["refine"] << ", ";
    if (a["chosen"].contains("time_tolerance")) {
        os << "time tolerance " << a["chosen"]["time_tolerance"].get<double>() << "; ";
    } else {
        os << a["chosen"]["substeps"] << " sub-steps; ";
    }
    os << a["wall_seconds"].get<double>() << " s in all";
    if (a.contains("reason")) os << " — " << a["reason"].get<std::string>();
    os << std::setprecision(10) << "\n";
}

// A static step's stability (core/static_stability.hpp): "; stable", "; UNSTABLE: N negative
// eigenvalues" (or "(kinetic): N growing modes"), "; stability critical: why" or "; stability not
// assessed: why".
void print_stability(const nlohmann::json& s, std::ostream& os) {
    const std::string a = s["assessment"].get<std::string>();
    if (a == "stable") {
        os << "; stable";
    } else if (a == "unstable" && s.contains("growing_modes")) {
        os << "; UNSTABLE (kinetic): " << s["growing_modes"] << " growing mode(s)";
    } else if (a == "unstable") {
        os << "; UNSTABLE: " << s["negative_eigenvalues"] << " negative eigenvalue(s)";
    } else {
        os << "; stability " << (a == "critical" ? "critical" : "not assessed") << ": "
           << s.value("reason", "");
    }
}

void print_run_summary(const nlohmann::json& r, std::ostream& os) {
    os << cases::one_line(r["case"].get<std::string>()) << " | " << r["rotation"].get<std::string>()
       << " | " << r["formulation"].get<std::string>() << " | " << r["elements"]
       << " elements, order " << r["order"] << ", " << r["dofs"] << " unknowns\n";
    os << "status: " << r["status"].get<std::string>() << " — "
       << cases::one_line(r["message"].get<std::string>()) << "\n";
    os << std::setprecision(10);
    for (const auto& step : r["steps"]) {
        if (step.contains("load_factor"))
            os << "  load factor " << step["load_factor"].get<double>();
        if (step.contains("time")) os << "  t = " << step["time"].get<double>();
        os << "  (" << step["newton_iterations"] << " Newton iterations";
        if (step.contains("convergence")) {
            const auto& c = step["convergence"];
            os << std::setprecision(3) << "; " << c["criterion"].get<std::string>()
               << ", scaled residual " << c["scaled_residual"].get<double>()
               << ", algebraic error <= " << c["error_bound"].get<double>()
               << std::setprecision(10);
        }
        if (step.contains("stability")) print_stability(step["stability"], os);
        os << ")\n";
        for (const auto& [name, p] : step["points"].items()) {
            const auto& u = p["displacement"];
            os << "    " << std::left << std::setw(8) << name << std::right << " u = ["
               << u[0].get<double>() << ", " << u[1].get<double>() << ", " << u[2].get<double>()
               << "]  angle = " << p["rotation_angle"].get<double>() << " rad\n";
            if (step.contains("estimate")) {
                const auto& e = step["estimate"];
                print_point_estimate(e.contains(name) ? e[name] : e,
                                     r["estimate"]["method"].get<std::string>(), os);
            }
        }
    }
    print_modes(r, os);
    if (r.contains("estimate")) print_estimate_summary(r["estimate"], os);
    if (r.contains("accuracy")) print_accuracy_summary(r["accuracy"], os);
    os << "wall time: " << r["wall_seconds"].get<double>() << " s\n";
}

void write_outputs(const ParsedArguments& a, const nlohmann::json& r) {
    // A dynamic run also writes its time history as CSV next to each JSON file, a static run its
    // load steps.
    const bool history = has_time_history(r);
    const bool load_steps = has_load_steps(r);
    auto write = [&](const fs::path& json_path) {
        write_file_atomically(json_path.string(), r.dump(2) + "\n");
        const std::string csv = fs::path(json_path).replace_extension(".csv").string();
        if (history) write_file_atomically(csv, history_csv(r));
        if (load_steps) write_file_atomically(csv, steps_csv(r));
    };
    if (const auto file = a.value("json")) write(*file);
    if (const auto dir = a.value("out")) {
        write(fs::path(*dir) /
              (r["case"].get<std::string>() + "_" + r["rotation"].get<std::string>() + "_" +
               r["formulation"].get<std::string>() + ".json"));
    }
}

// --frame: for `beamdyn`, the driver's GlbDCM (global → root frame), read again from the deck.
std::optional<Mat3> beamdyn_frame_request(const ParsedArguments& a, const std::string& path) {
    const std::string frame = a.value("frame").value_or("rotbeam");
    if (frame == "rotbeam") return std::nullopt;
    if (frame != "beamdyn") {
        throw InputError("run: --frame: expected rotbeam or beamdyn, got '" + frame + "'");
    }
    if (!cases::is_beamdyn_driver_path(path)) {
        throw InputError("run: --frame beamdyn: only for a BeamDyn driver file (.inp), got '" +
                         path + "'");
    }
    const cases::BeamDynDeck deck = cases::read_beamdyn_deck(path);
    Mat3 dcm;
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) {
            dcm(r, c) = deck.root_dcm[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)];
        }
    }
    return dcm;
}

// What --vtk cannot write, refused before the run.
void check_vtk_request(const ParsedArguments& a, const Model& model) {
    if (!a.has("vtk")) return;
    if (model.analysis.accuracy > 0.0) {
        throw InputError(
            "run: --vtk: not with accuracy control (analysis.accuracy or --accuracy), whose "
            "attempts are several runs; run the chosen discretization without it");
    }
}

// The recorded frames of every step (or mode) the result reports: none of a run whose steps were
// dropped (time limit, non-finite values).
void write_vtk_files(const std::string& dir, const Model& model, const nlohmann::json& result,
                     std::vector<FrameSnapshot> frames) {
    const size_t reported =
        result.contains("modes") ? result["modes"].size() : result["steps"].size();
    frames.resize(std::min(frames.size(), reported));
    write_vtk(dir, model, result, frames);
}

}  // namespace

int command_list(const Args& args) {
    const CommandSpec spec{
        "list", "", 0, 0, "List the catalog cases, the parameterizations and the formulations.",
        {}};
    const ParsedArguments a = parse_arguments(spec, args);
    if (a.help) {
        std::cout << help_text(spec);
        return 0;
    }
    std::cout << "cases (" << catalog_directory() << "):\n";
    for (const std::string& c : catalog_cases()) std::cout << "  " << c << "\n";
    std::cout << "parameterizations:\n";
    for (const std::string& p : param::parameterization_names()) std::cout << "  " << p << "\n";
    std::cout << "formulations:\n";
    for (const Formulation f : comb::formulations()) std::cout << "  " << choice_name(f) << "\n";
    return 0;
}

int command_check(const Args& args) {
    const CommandSpec spec{"check",
                           "CASE.yaml",
                           1,
                           1,
                           "Validate a case file (with any --set overrides) and describe the "
                           "model: points, members, elements, sections, loads, analysis.",
                           {kSetOption}};
    const ParsedArguments a = parse_arguments(spec, args);
    if (a.help) {
        std::cout << help_text(spec);
        return 0;
    }
    const std::string path = resolve_case_path(a.positional[0]);
    const Model model = load_case(path, a.values("set"));
    std::cout << describe_model(model);
    return 0;
}

int command_run(const Args& args) {
    const CommandSpec spec{
        "run",
        "CASE.yaml",
        1,
        1,
        "Run a case with one parameterization and formulation. Prints a summary; --json writes the "
        "result (docs/architecture.md). Exit 0 whatever the solver status, 2 on bad input.",
        {{"rotation", "NAME",
          "quaternion | wiener-milenkovic | rodrigues | rotation-vector | euler-angles (default: "
          "the case's discretization.rotation)"},
         {"formulation", "NAME",
          "displacement | mixed (default: the case's discretization.formulation)"},
         {"elements", "N", "elements of every member (default: the case's members.*.elements)"},
         {"order", "P",
          "element order, displacement formulation (default: the case's discretization.order)"},
         {"interpolation", "NAME",
          "relative | direct (default: the case's discretization.interpolation)"},
         kSetOption,
         {"out", "DIR", "write DIR/<case>_<rotation>_<formulation>.json (default: not written)"},
         {"json", "FILE", "write the result JSON to FILE (default: not written)"},
         {"vtk", "DIR",
          "write the deformed line and section frames of every load step, output time or mode "
          "as VTK files and DIR/<case>_<rotation>_<formulation>.pvd for ParaView "
          "(docs/paraview-output.md; default: not written)"},
         {"quiet", "", "print nothing on success"},
         {"trace-newton", "", "print every Newton iteration and step cut to stderr"},
         kTimeLimitOption,
         {"estimate", "on|off",
          "estimate the discretization error with companion runs (default: the case's "
          "analysis.estimate, on; docs/error-estimates.md)"},
         {"frame", "rotbeam|beamdyn",
          "beamdyn (a BeamDyn driver file only): each step also gives its points and reactions in "
          "BeamDyn's root frame, as BeamDyn writes them (docs/beamdyn-import.md; default: "
          "rotbeam)"},
         {"accuracy", "TOL",
          "refine the discretization until every estimate is <= TOL/2 of its scale, 1e-12 <= "
          "TOL < 1 (dynamic: the mesh and the adaptive time steps, TOL/4 each; "
          "docs/accuracy-control.md; default: the case's "
          "analysis.accuracy, none)"}}};
    const ParsedArguments a = parse_arguments(spec, args);
    if (a.help) {
        std::cout << help_text(spec);
        return 0;
    }
    const std::string path = resolve_case_path(a.positional[0]);
    // A run reads the case file alone: the published references beside a catalog case are for
    // check, verify and the suite (case_loader.hpp).
    const Model model = load_with_options(path, a, CaseParts::case_file);
    const double limit = time_limit_option(a, "run");
    // --estimate overrides the case's analysis.estimate.
    const std::string estimate =
        a.value("estimate").value_or(model.analysis.estimate ? "on" : "off");
    if (estimate != "on" && estimate != "off") {
        throw InputError("run: --estimate: expected on or off, got '" + estimate + "'");
    }
    if (model.analysis.accuracy > 0.0 && estimate == "off") {
        throw InputError(
            "run: --estimate off: accuracy control (analysis.accuracy or --accuracy) needs the "
            "error estimate");
    }
    check_vtk_request(a, model);
    const std::optional<Mat3> beamdyn_dcm = beamdyn_frame_request(a, path);
    // The run's solved path: its estimate's companions start from it (add_run_estimate).
    SolvedPath solved;
    RunRequest request{path, model, a.has("trace-newton"), limit};
    if (estimate == "on") request.path = &solved;
    nlohmann::json result;
    FrameRecorder frames;
    if (model.analysis.accuracy > 0.0) {
        result = run_to_accuracy(request);
    } else {
        {
            // The frames of the run itself, not of the companion runs of its estimate.
            std::optional<ScopedFrameRecorder> recording;
            if (a.has("vtk")) recording.emplace(frames);
            result = run_case(request);
        }
        if (estimate == "on") {
            add_run_estimate(request, result);
        } else {
            result["estimate"] = estimate_off();
        }
    }
    if (beamdyn_dcm) add_beamdyn_frame(*beamdyn_dcm, result);
    write_outputs(a, result);
    if (const auto dir = a.value("vtk")) write_vtk_files(*dir, model, result, frames.snapshots);
    if (!a.has("quiet")) {
        print_run_summary(result, std::cout);
        const std::string accuracy = estimate::stated_accuracy_line(model, result);
        if (!accuracy.empty()) std::cout << accuracy << "\n";
    }
    return 0;
}

int command_reference(const Args& args) {
    const CommandSpec spec{
        "reference",
        "CASE.yaml",
        1,
        1,
        "Continuum reference solution of a static single-member case with tip loads (shooting on "
        "the Cosserat rod equations with GSL), in the same JSON contract as `run`.",
        {kSetOption,
         {"json", "FILE", "write the result JSON to FILE (default: not written)"},
         {"out", "DIR", "write DIR/<case>_continuum.json (default: not written)"},
         {"quiet", "", "print nothing"}}};
    const ParsedArguments a = parse_arguments(spec, args);
    if (a.help) {
        std::cout << help_text(spec);
        return 0;
    }
    const std::string path = resolve_case_path(a.positional[0]);
    const Model model = load_case(path, a.values("set"));
    nlohmann::json result = continuum_result_json(model, path);
    if (const auto file = a.value("json")) write_file_atomically(*file, result.dump(2) + "\n");
    if (const auto dir = a.value("out")) {
        write_file_atomically((fs::path(*dir) / (model.name + "_continuum.json")).string(),
                              result.dump(2) + "\n");
    }
    if (!a.has("quiet")) print_run_summary(result, std::cout);
    return 0;
}

int command_study(const Args& args) {
    const CommandSpec spec{
        "study",
        "NAME",
        1,
        1,
        study_help_text(),
        {{"json", "FILE", "write the study JSON to FILE (rotations; default: standard output)"},
         {"samples", "N", "angles in the sweep, 2 to 20000 (default 721, rotations)"},
         {"out", "DIR", "output folder of the static studies (default out)"},
         {"quick", "", "the static studies' smaller variant (CI smoke test)"},
         {"reduced-follower", "",
          "joined-beam-dynamics: the follower load with the --quick sweep on the full window"},
         {"shard", "I/N",
          "make only the I-th of N shards of the study's runs, for `rotbeam merge` (default: "
          "every run, no shard)"},
         {"timings", "DIR",
          "with --shard or under mpirun: balance by the run times in DIR (default: the cost "
          "model, docs/distributed-runs.md; under mpirun: --out)",
          true},
         {"jobs", "N",
          "worker threads, 1 to 256 (default: all cores): with --shard, for its runs; under "
          "mpirun, per rank (default 1); else for a study's untimed references (what a study "
          "times runs on one thread)"}}};
    const ParsedArguments a = parse_arguments(spec, args);
    if (a.help) {
        std::cout << help_text(spec);
        return 0;
    }
    // An unknown study first, then an option that does not apply to it.
    if (a.positional[0] != "rotations") check_study_name(a.positional[0]);
    for (const OptionSpec& option : spec.options) {
        if (a.has(option.name)) check_study_option(a.positional[0], option.name);
    }
    const int jobs = a.positive_int("study", "jobs", kMaxJobs)
                         .value_or(std::max(1u, std::thread::hardware_concurrency()));
    {
        Job job;
        job.command = "study";
        job.study = a.positional[0];
        job.quick = a.has("quick");
        job.reduced_follower = a.has("reduced-follower");
        if (const auto code = run_distributed(
                job, a.value("shard"),
                ShardSettings{{}, a.value("out").value_or("out"), jobs, false, a.values("timings")},
                a.has("jobs"))) {
            return *code;
        }
    }
    if (a.has("timings"))
        throw InputError("rotbeam study: --timings: only with --shard I/N or under mpirun");
    if (a.positional[0] != "rotations") {
        run_named_study(a.positional[0],
                        StudyOptions{a.value("out").value_or("out"), a.has("quick"),
                                     a.has("reduced-follower"), jobs});
        return 0;
    }
    const int samples = a.positive_int("study", "samples", kMaxSamples, 2).value_or(721);
    const nlohmann::json study = param::rotation_study(samples);
    if (const auto file = a.value("json")) {
        write_file_atomically(*file, study.dump(1) + "\n");
        std::cout << "wrote " << *file << "\n";
    } else {
        std::cout << study.dump(1) << "\n";
    }
    return 0;
}

}  // namespace rotbeam::cli
