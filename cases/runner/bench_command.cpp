// `rotbeam bench`: runs every target of bench.cpp for every combination, the start-up timing, and
// prints the table against those targets. JSON to --json (default out/bench.json); with
// --history a copy goes to reports/history/<date>-<machine>.json (committed, compared
// like-for-like: the machine tag names host, CPU and core count).
#include <unistd.h>

#include <algorithm>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <thread>

#include "arguments.hpp"
#include "benches/bench.hpp"
#include "benches/bench_accuracy.hpp"
#include "benches/bench_joined_beam.hpp"
#include "benches/bench_long_run.hpp"
#include "cases/loader/case_loader.hpp"
#include "commands.hpp"
#include "core/errors.hpp"
#include "core/results.hpp"
#include "core/static_driver.hpp"
#include "core/version.hpp"
#include "runs/make_problem.hpp"
#include "runs/progress.hpp"
#include "runs/timing.hpp"

namespace rotbeam::cli {

namespace {

// Every name of --targets is a target (an unknown one would silently benchmark nothing).
void check_target_names(const std::string& list) {
    std::vector<std::string> known = {"joined-beam-modal", "joined-beam-dynamic",
                                      "joined-beam-dynamic-follower", "long-run",
                                      "accuracy-control"};
    for (const BenchTarget& t : bench_targets()) known.push_back(t.name);
    std::stringstream ss(list);
    for (std::string name; std::getline(ss, name, ',');) {
        if (std::find(known.begin(), known.end(), name) != known.end()) continue;
        const std::string guess = closest_match(name, known);
        std::string all;
        for (const std::string& k : known) all += (all.empty() ? "" : ", ") + k;
        throw InputError(
            "rotbeam bench: --targets: unknown target '" + name + "'" +
            (guess.empty() ? " (known: " + all + ")" : "; did you mean '" + guess + "'?"));
    }
}

}  // namespace

namespace fs = std::filesystem;

namespace {

std::string cpu_model() {
    std::ifstream in("/proc/cpuinfo");
    std::string line;
    while (std::getline(in, line)) {
        if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
    }
    return "unknown cpu";
}

nlohmann::json machine_json() {
    char host[256] = {0};
    gethostname(host, sizeof(host) - 1);
    const unsigned cores = std::thread::hardware_concurrency();
    std::string tag = std::string(host) + "-" + std::to_string(cores) + "core";
    for (char& ch : tag)
        if (!std::isalnum(static_cast<unsigned char>(ch)) && ch != '-') ch = '_';
    return {{"host", host}, {"cpu", cpu_model()}, {"cores", cores}, {"tag", tag}};
}

std::string utc(const char* format) {
    const std::time_t t = std::time(nullptr);
    std::ostringstream s;
    s << std::put_time(std::gmtime(&t), format);
    return s.str();
}

// Start-up: reading a case and building the model. Whole process: `rotbeam check` (read,
// validate, describe) against `rotbeam --version` (the bare process); in process: load_case plus
// the static problem's construction.
nlohmann::json bench_startup(int repeats) {
    const std::string path = resolve_case_path("cantilever-moment");
    const Timing bare = time_whole_process({"--version"}, repeats, 3.0);
    const Timing check = time_whole_process({"check", path}, repeats, 3.0);
    const Timing in = time_in_process([&] { make_static_problem(load_case(path)); }, repeats, 2.0);
    // The case file alone, without the published references beside it (case_loader.hpp): what
    // `rotbeam run` reads.
    const Timing in_run = time_in_process(
        [&] { make_static_problem(load_case(path, {}, CaseParts::case_file)); }, repeats, 2.0);
    return {{"case", "cantilever-moment"},
            {"whole_process_seconds", check.median_seconds},
            {"whole_process_cpu_seconds", check.median_cpu_seconds},
            {"bare_process_seconds", bare.median_seconds},
            {"in_process_seconds", in.median_seconds},
            {"in_process_run_seconds", in_run.median_seconds},
            {"peak_rss_kb", check.peak_rss_kb},
            {"target_seconds", 0.002}};
}

std::string ms(double seconds) {
    std::ostringstream s;
    s << std::fixed << std::setprecision(seconds < 0.1 ? 2 : 1) << seconds * 1e3;
    return s.str();
}

void print_row(const nlohmann::json& r, std::ostream& os) {
    os << "  " << std::left << std::setw(30)
       << (r["formulation"].get<std::string>() + "/" + r["rotation"].get<std::string>());
    const std::string status = r["status"].get<std::string>();
    if (status != "reached") {
        os << status << ": " << r.value("reason", "") << "\n";
        if (r.contains("best_error_per_budget")) {
            os << "  " << std::setw(30) << ""
               << "best error within";
            for (const auto& b : r["best_error_per_budget"]) {
                os << "  " << ms(b["budget_seconds"].get<double>()) << " ms: "
                   << (b["best_error"].is_null() ? std::string("—")
                                                 : sci(b["best_error"].get<double>()));
            }
            os << "\n";
        }
        return;
    }
    const auto& w = r["winner"];
    os << std::right << std::setw(9) << ms(r["whole_process_seconds"].get<double>()) << std::setw(9)
       << ms(r["in_process_seconds"].get<double>()) << std::setw(10)
       << sci(w["error"].get<double>()) << std::setw(5) << w["elements"].get<int>() << std::setw(4)
       << w["order"].get<int>() << std::setw(4)
       << (std::to_string(w["substeps"].get<int>()) + (w.value("mip", false) ? "m" : ""))
       << std::setw(7) << w["dofs"].get<int>() << std::setw(6) << w["newton_iterations"].get<int>()
       << std::setw(8) << r["peak_rss_kb"].get<long>() << "\n";
}

// The best whole-process time among the combinations that reached a target.
void print_target_summary(const BenchTarget& t, const nlohmann::json& rows, std::ostream& os) {
    const nlohmann::json* fastest = fastest_reaching_run(rows);
    const double best = fastest ? (*fastest)["whole_process_seconds"].get<double>() : kNoValue;
    const std::string who = fastest ? (*fastest)["formulation"].get<std::string>() + "/" +
                                          (*fastest)["rotation"].get<std::string>()
                                    : "none";
    os << "  best: " << who;
    if (std::isfinite(best)) os << " " << ms(best) << " ms";
    if (t.target_seconds > 0.0) {
        os << "   target ≤ " << ms(t.target_seconds)
           << " ms: " << (best <= t.target_seconds ? "met" : "MISSED");
    }
    os << "\n\n";
}

// One target for every combination: the table on stdout, the rows as JSON (null when the
// target's reference cannot be computed).
nlohmann::json bench_target(const BenchTarget& t, bool quick, int repeats, Progress& progress) {
    const nlohmann::json reference =
        t.case_name == "bend-45"
            ? continuum_reference(t.case_name, {kExactBendTip, "analysis.load_factors=[600]"})
            : nlohmann::json();
    if (!reference.is_null() &&
        (!has_solution(reference.value("status", "")) || reference["steps"].empty())) {
        std::cout << t.name << ": no continuum reference (" << reference.value("message", "")
                  << "); skipped\n\n";
        for (size_t i = 0; i < all_combinations(false).size(); ++i) progress.finished(t.name);
        return nlohmann::json();
    }
    std::cout << t.name << " (" << t.measure << " ≤ " << sci(t.accuracy, 0) << ")\n  " << std::left
              << std::setw(30) << "combination" << std::right << std::setw(9) << "whole ms"
              << std::setw(9) << "in ms" << std::setw(10) << "error" << std::setw(5) << "N"
              << std::setw(4) << "p" << std::setw(4) << "ss" << std::setw(7) << "dofs"
              << std::setw(6) << "iter" << std::setw(8) << "RSS kB"
              << "\n";
    nlohmann::json rows = nlohmann::json::array();
    for (const Combination& c : all_combinations(false)) {
        const std::string item = t.name + " " + c.label();
        progress.started(item);
        rows.push_back(bench_combination(t, c, reference, quick, repeats));
        progress.finished(item);
        print_row(rows.back(), std::cout);
        std::cout << std::flush;
    }
    print_target_summary(t, rows, std::cout);
    return {{"name", t.name},
            {"case", t.case_name},
            {"load_factor", t.load_factor},
            {"accuracy", t.accuracy},
            {"target_seconds", t.target_seconds},
            {"results", rows}};
}

void write_bench_outputs(const ParsedArguments& a, const nlohmann::json& out) {
    const std::string file = a.value("json").value_or("out/bench.json");
    fs::create_directories(fs::path(file).parent_path().empty() ? fs::path(".")
                                                                : fs::path(file).parent_path());
    write_file_atomically(file, out.dump(1) + "\n");
    std::cout << "wrote " << file << "\n";
    if (a.has("history")) {
        const fs::path h =
            fs::path(ROTBEAM_REPORTS_DIR) / "history" /
            (utc("%Y-%m-%d") + "-" + out["machine"]["tag"].get<std::string>() + ".json");
        fs::create_directories(h.parent_path());
        // The history keeps each combination's chosen discretization and timings, not the
        // search trail (candidates), so the committed file stays small.
        nlohmann::json summary = out;
        for (auto& target : summary["targets"]) {
            for (auto& result : target["results"]) result.erase("candidates");
        }
        write_file_atomically(h.string(), summary.dump(1) + "\n");
        std::cout << "wrote " << h.string() << "\n";
    }
}

}  // namespace

int command_bench(const Args& args) {
    const CommandSpec spec{
        "bench",
        "",
        0,
        0,
        "Benchmark the static targets: for every parameterization × formulation the "
        "cheapest discretization reaching the target accuracy (roll-up λ = 0.4, 1.6, 2.0 to "
        "‖Δu‖/L ≤ 1e-9; 45° bend P = 600 to 1e-6 of the continuum reference), median "
        "whole-process and in-process time, Newton iterations, unknowns, peak memory; start-up; "
        "the joined-beam modal (5 frequencies to 1e-6 of converged) and 0–2 s dynamic, dead and "
        "follower load (joint histories to 1e-3 of the same mesh's time-converged answer) "
        "targets; accuracy-control: "
        "`run --accuracy 1e-6` against the best hand-picked discretization (roll-up, bend).",
        {{"json", "FILE", "write the results (default out/bench.json)"},
         {"history", "", "also write reports/history/<date>-<machine>.json"},
         {"repeats", "N", "timing repeats, 1 to 1000 (default 11, --quick 5)"},
         {"quick", "", "a smaller search grid and fewer repeats"},
         {"targets", "LIST", "comma-separated target names (default: all; e.g. joined-beam-modal)"},
         {"references", "DIR",
          "cache of the joined-beam dynamic references (default: joined-beam-references beside "
          "the --json file; `rotbeam study joined-beam-dynamics --out D` writes "
          "D/joined-beam-references)"}}};
    const ParsedArguments a = parse_arguments(spec, args);
    if (a.help) {
        std::cout << help_text(spec);
        return 0;
    }
    const bool quick = a.has("quick");
    const int repeats = a.positive_int("bench", "repeats", kMaxRepeats).value_or(quick ? 5 : 11);
    check_target_names(a.value("targets").value_or(""));
    nlohmann::json out = {{"version", kGitDescribe},
                          {"schema_version", kSchemaVersion},
                          {"date", utc("%Y-%m-%d %H:%M UTC")},
                          {"machine", machine_json()},
                          {"quick", quick},
                          {"repeats", repeats}};
    out["startup"] = bench_startup(repeats);
    std::cout << "start-up (read + validate cantilever-moment): whole process "
              << ms(out["startup"]["whole_process_seconds"].get<double>()) << " ms (bare process "
              << ms(out["startup"]["bare_process_seconds"].get<double>()) << " ms), in process "
              << ms(out["startup"]["in_process_seconds"].get<double>())
              << " ms (the case file alone, as run reads it: "
              << ms(out["startup"]["in_process_run_seconds"].get<double>())
              << " ms); target ≤ 2 ms\n\n";
    std::cout << "N elements, p order, ss load sub-steps (m: the mixed-integration-point Newton, "
                 "solver.mip, without damping)\n\n";
    // ",a,b," so that every name is matched whole (an empty list selects every target).
    std::string selection(1, ',');
    selection.append(a.value("targets").value_or(""));
    selection.push_back(',');
    auto selected = [&](const std::string& name) {
        std::string whole(1, ',');
        whole.append(name);
        whole.push_back(',');
        return selection == ",," || selection.find(whole) != std::string::npos;
    };
    // Progress: one item per static target × combination and one per joined-beam target.
    size_t items = 0;
    for (const BenchTarget& t : bench_targets())
        items += selected(t.name) ? all_combinations(false).size() : 0;
    const std::vector<std::string> whole = {"joined-beam-modal", "joined-beam-dynamic",
                                            "joined-beam-dynamic-follower", "long-run",
                                            "accuracy-control"};
    for (const std::string& name : whole) items += selected(name) ? 1 : 0;
    Progress progress("rotbeam bench", items, std::cerr, progress_options_for_stderr());
    const auto whole_target = [&](const std::string& name, const auto& make) {
        if (!selected(name)) return;
        progress.started(name);
        out["targets"].push_back(make());
        progress.finished(name);
    };
    out["targets"] = nlohmann::json::array();
    for (const BenchTarget& t : bench_targets()) {
        if (!selected(t.name)) continue;
        nlohmann::json target = bench_target(t, quick, repeats, progress);
        if (!target.is_null()) out["targets"].push_back(std::move(target));
    }
    whole_target("joined-beam-modal", [&] { return bench_joined_beam_modal(quick, repeats); });
    const fs::path json_dir = fs::path(a.value("json").value_or("out/bench.json")).parent_path();
    const std::string references =
        a.value("references")
            .value_or(((json_dir.empty() ? fs::path(".") : json_dir) / "joined-beam-references")
                          .string());
    whole_target("joined-beam-dynamic",
                 [&] { return bench_joined_beam_dynamic(quick, repeats, references, "dead"); });
    whole_target("joined-beam-dynamic-follower",
                 [&] { return bench_joined_beam_dynamic(quick, repeats, references, "follower"); });
    whole_target("long-run", [&] { return bench_long_run(quick); });
    whole_target("accuracy-control", [&] { return bench_accuracy_control(quick, repeats); });
    write_bench_outputs(a, out);
    return 0;
}

}  // namespace rotbeam::cli
