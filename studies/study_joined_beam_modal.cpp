// `rotbeam study joined-beam-modal` (the joined-beam frequencies; docs/benchmarks.md §3, seed 002
// Table III): h-refinement of the five lowest frequencies of the undeformed joined
// beam for both formulations (displacement: order 1, 2 and 4, consistent mass; mixed: its
// second-order elements with the element-midpoint inertia of seed 002) and p-refinement of the
// displacement formulation on one element per member, for every parameterization whose modal
// analysis exists (availability is found by running: "unavailable" is reported, not skipped
// silently). Each h-series is extrapolated by Richardson from its three finest meshes with the
// observed order of each mode (study_extrapolation.hpp); errors are taken against that
// extrapolation and against the series' finest mesh; the Richardson values of every series are
// compared with the p-converged frequencies (which converge exponentially). Modes are identified
// across the meshes of a series by their shapes (MAC against the finest mesh), not by sort order.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/results.hpp"
#include "core/static_driver.hpp"
#include "joined_beam_dynamics.hpp"
#include "runs/mode_matching.hpp"
#include "studies.hpp"
#include "study_common.hpp"
#include "study_extrapolation.hpp"
#include "study_math.hpp"

namespace rotbeam::cli {

namespace {

constexpr int kModes = 5;

struct ModalRefinement {
    std::string name;                   // h-p1, h-p2, h-p4, p, h
    std::vector<int> elements, orders;  // per member; parallel lists
    int nominal_order;  // expected order of the frequency error in h (0: exponential)
};

std::vector<ModalRefinement> modal_refinements(Formulation formulation, bool quick) {
    auto h = [](int p, std::vector<int> n) {
        return ModalRefinement{"h-p" + std::to_string(p), n, std::vector<int>(n.size(), p), 2 * p};
    };
    if (formulation == Formulation::mixed) {
        const std::vector<int> n =
            quick ? std::vector<int>{5, 10, 20, 40} : std::vector<int>{5, 10, 20, 40, 80, 160, 320};
        return {ModalRefinement{"h", n, std::vector<int>(n.size(), 1), 2}};
    }
    const std::vector<int> p =
        quick ? std::vector<int>{2, 4, 6, 8} : std::vector<int>{2, 3, 4, 5, 6, 7, 8, 10, 12};
    return {h(1, quick ? std::vector<int>{2, 4, 8, 16} : std::vector<int>{2, 4, 8, 16, 32, 64}),
            h(2, quick ? std::vector<int>{1, 2, 4, 8} : std::vector<int>{1, 2, 4, 8, 16, 32}),
            h(4, quick ? std::vector<int>{1, 2, 4} : std::vector<int>{1, 2, 4, 8}),
            ModalRefinement{"p", std::vector<int>(p.size(), 1), p, 0}};
}

struct ModalSeries {
    std::string label, note;
    std::vector<double> elements, dofs, seconds;
    std::vector<std::vector<double>> f;  // f[i][k]: mesh i, mode k (empty when it failed)
    std::vector<Richardson> limit;       // per mode (h-series); p-series: the finest, invalid
};

// Modes computed per mesh: the five compared plus spares, so that a mode which a coarse mesh
// places above the fifth is still found by its shape.
constexpr int kComputedModes = kModes + 3;

ModalSeries run_modal_series(const Combination& comb, const ModalRefinement& r) {
    ModalSeries s;
    s.label = comb.formulation_name() + "/" + comb.rotation_name() + "/" + r.name;
    std::vector<std::vector<double>> computed;             // per mesh: frequencies
    std::vector<std::vector<std::vector<double>>> shapes;  // per mesh, per mode: stations
    for (size_t i = 0; i < r.elements.size(); ++i) {
        std::vector<std::string> o = {"analysis.modes=" + std::to_string(kComputedModes)};
        if (comb.formulation == Formulation::displacement) {
            o.push_back("discretization.order=" + std::to_string(r.orders[i]));
            o.push_back("discretization.mass_rule=consistent");
        }
        const nlohmann::json result = run_spec({"joined-beam", comb, o, r.elements[i]});
        if (is_unavailable(result)) {
            s.note = "unavailable: " + result.value("message", "");
            return s;
        }
        std::vector<double> f;
        std::vector<std::vector<double>> sh;
        if (has_solution(result.value("status", "")) && result.contains("modes")) {
            for (const auto& m : result["modes"]) {
                f.push_back(m["frequency_hz"].get<double>());
                sh.push_back(m["stations"].get<std::vector<double>>());
            }
        } else if (s.note.empty()) {
            s.note = result.value("status", "") + ": " + result.value("message", "").substr(0, 80);
        }
        s.elements.push_back(r.name == "p" ? r.orders[i] : r.elements[i]);
        s.dofs.push_back(result.value("dofs", 0));
        s.seconds.push_back(result.value("wall_seconds", 0.0));
        computed.push_back(f);
        shapes.push_back(sh);
    }
    // Mode k of every mesh is the one whose shape matches mode k of the finest mesh (MAC,
    // mode_matching.hpp), not the k-th in frequency; a mode without a match is missing (NaN).
    const std::vector<std::vector<double>> reference =
        shapes.empty() || shapes.back().size() < kModes
            ? std::vector<std::vector<double>>{}
            : std::vector<std::vector<double>>(shapes.back().begin(),
                                               shapes.back().begin() + kModes);
    int unmatched = 0;
    for (size_t i = 0; i < computed.size(); ++i) {
        std::vector<double> f;
        if (!reference.empty() && !computed[i].empty()) {
            const std::vector<int> m = match_modes(reference, shapes[i], kMatchMac);
            for (int k = 0; k < kModes; ++k) {
                const int c = m[static_cast<size_t>(k)];
                f.push_back(c < 0 ? kNoValue : computed[i][static_cast<size_t>(c)]);
                if (c < 0) ++unmatched;
            }
        }
        s.f.push_back(f);
    }
    if (unmatched > 0 && s.note.empty()) {
        s.note = std::to_string(unmatched) + " mode(s) of the coarse meshes without a shape match";
    }
    const size_t n = s.f.size();
    for (int k = 0; k < kModes; ++k) {
        const bool three =
            n >= 3 && !s.f[n - 1].empty() && !s.f[n - 2].empty() && !s.f[n - 3].empty();
        if (r.nominal_order > 0 && three) {
            s.limit.push_back(richardson(s.f[n - 3][k], s.f[n - 2][k], s.f[n - 1][k], 2.0));
        } else {
            const double finest = n > 0 && !s.f[n - 1].empty() ? s.f[n - 1][k] : kNoValue;
            s.limit.push_back({finest, kNoValue, false});
        }
    }
    return s;
}

// max over the modes of |f_k − g_k| / g_k (NaN when either side is missing).
double max_relative(const std::vector<double>& f, const std::vector<double>& g) {
    if (f.size() < kModes || g.size() < kModes) return kNoValue;
    double e = 0.0;
    for (int k = 0; k < kModes; ++k) {
        const double d = std::abs(f[k] - g[k]) / std::abs(g[k]);
        if (!std::isfinite(d)) return kNoValue;  // a mode without a match
        e = std::max(e, d);
    }
    return e;
}

std::vector<double> limits(const ModalSeries& s) {
    std::vector<double> v;
    for (const Richardson& r : s.limit) v.push_back(r.value);
    return v;
}

}  // namespace

namespace {

// The p-converged frequencies: the finest point of the first available displacement p-series.
std::vector<double> p_converged(const std::vector<ModalSeries>& all) {
    for (const ModalSeries& s : all) {
        if (s.label.find("displacement/") == 0 && s.label.size() > 2 &&
            s.label.substr(s.label.size() - 2) == "/p" && !s.f.empty() && !s.f.back().empty()) {
            return s.f.back();
        }
    }
    return {};
}

void write_tables(const std::vector<ModalSeries>& all, const std::vector<double>& converged,
                  std::ostringstream& md) {
    md << "| combination/refinement | meshes (per member; p: orders) | unknowns (finest) | "
          "observed order, modes 1…5 (3 finest) | finest vs Richardson (max over modes) | "
          "Richardson vs p-converged (max over modes) | note |\n|---|---|---|---|---|---|---|\n";
    for (const ModalSeries& s : all) {
        std::ostringstream orders;
        for (const Richardson& r : s.limit)
            orders << (orders.tellp() ? " " : "") << fixed(r.order, 2);
        const bool h_series = !s.limit.empty() && s.label.substr(s.label.size() - 2) != "/p";
        const std::vector<double> lim = limits(s);
        md << "| " << s.label << " | "
           << (s.elements.empty()
                   ? std::string("—")
                   : fixed(s.elements.front(), 0) + " … " + fixed(s.elements.back(), 0))
           << " | " << (s.dofs.empty() ? std::string("—") : fixed(s.dofs.back(), 0)) << " | "
           << (h_series      ? orders.str()
               : s.f.empty() ? std::string("—")
                             : std::string("exponential"))
           << " | "
           << (h_series && !s.f.empty() ? sci(max_relative(s.f.back(), lim)) : std::string("—"))
           << " | " << (h_series ? sci(max_relative(lim, converged)) : std::string("—")) << " | "
           << markdown_cell(s.note) << " |\n";
    }
    md << "\nConverged frequencies [Hz] (p-converged: displacement, one element per member at the "
          "highest order; Richardson: each h-series' extrapolation from its three finest meshes "
          "with the observed order of each mode):\n\n| source | f₁ | f₂ | f₃ | f₄ | f₅ |\n"
          "|---|---|---|---|---|---|\n| p-converged |";
    for (double f : converged) md << " " << fixed(f, 6) << " |";
    md << "\n";
    for (const ModalSeries& s : all) {
        if (s.limit.empty() || s.label.substr(s.label.size() - 2) == "/p") continue;
        if (s.label.find("/quaternion/") == std::string::npos &&
            s.label.find("mixed/wiener-milenkovic/") == std::string::npos) {
            continue;  // undeformed state: every parameterization gives the same (see JSON)
        }
        md << "| Richardson " << s.label << " |";
        for (const Richardson& r : s.limit) md << " " << fixed(r.value, 6) << " |";
        md << "\n";
    }
    md << "| seed 002 Table III, GEBT (10 el.) | 35.23 | 171.02 | 215.87 | 275.05 | 407.2 |\n"
          "| seed 002 Table III, ANSYS (10 el.) | 35.17 | 169.83 | 212.53 | 273.34 | 403.53 |\n\n";
}

}  // namespace

nlohmann::json study_joined_beam_modal(const StudyOptions& o) {
    std::vector<ModalSeries> all;
    for (const Combination& comb : all_combinations(false)) {
        for (const ModalRefinement& r : modal_refinements(comb.formulation, o.quick)) {
            all.push_back(run_modal_series(comb, r));
            if (all.back().note.rfind("unavailable", 0) == 0) break;
        }
    }
    const std::vector<double> converged = p_converged(all);
    nlohmann::json out = {{"study", "joined-beam-modal"},
                          {"quick", o.quick},
                          {"p_converged_hz", converged},
                          {"series", nlohmann::json::array()}};
    std::vector<std::string> h_files, h_titles, all_files, all_titles;
    for (const ModalSeries& s : all) {
        const bool p_series = s.label.substr(s.label.size() - 2) == "/p";
        const std::vector<double> lim = limits(s);
        Series plot_series{s.label, {}, {}, {}, {}};
        std::vector<double> vs_richardson, vs_finest;
        for (size_t i = 0; i < s.f.size(); ++i) {
            vs_richardson.push_back(max_relative(s.f[i], lim));
            vs_finest.push_back(s.f.back().empty() ? kNoValue : max_relative(s.f[i], s.f.back()));
            // The p-series' own finest point is its reference: no error to draw.
            const double e = p_series && i + 1 == s.f.size() ? kNoValue : vs_richardson.back();
            plot_series.add(s.elements[i], s.dofs[i], s.seconds[i], e);
        }
        nlohmann::json richardson_json = nlohmann::json::array();
        for (const Richardson& r : s.limit) {
            richardson_json.push_back(
                {{"value_hz", r.value},
                 {"observed_order",
                  std::isfinite(r.order) ? nlohmann::json(r.order) : nlohmann::json()},
                 {"valid", r.valid}});
        }
        out["series"].push_back({{"label", s.label},
                                 {"x", s.elements},
                                 {"x_is", p_series ? "order" : "elements per member"},
                                 {"dofs", s.dofs},
                                 {"seconds", s.seconds},
                                 {"frequencies_hz", s.f},
                                 {"richardson", richardson_json},
                                 {"error_vs_richardson", vs_richardson},
                                 {"error_vs_finest", vs_finest},
                                 {"note", s.note}});
        if (s.f.empty()) continue;
        // Every parameterization gives the same frequencies about the undeformed state; the plots
        // draw one parameterization per formulation so the curves stay readable.
        if (s.label.find("/quaternion/") == std::string::npos &&
            s.label.find("mixed/wiener-milenkovic/") == std::string::npos) {
            continue;
        }
        const std::string file = write_series(
            o, "data/joined_beam_modal_" + std::to_string(all_files.size()) + ".dat", plot_series);
        all_files.push_back(file);
        all_titles.push_back(s.label);
        if (!p_series) {
            h_files.push_back(file);
            h_titles.push_back(s.label);
        }
    }
    std::ostringstream md;
    md << "## Study: joined-beam frequencies\n\nThe five lowest frequencies of the undeformed "
          "joined beam "
          "(docs/benchmarks.md §3) under h-refinement (displacement: order 1, 2, 4 with consistent "
          "mass and the default stiffness quadrature; mixed: seed 002's element with midpoint "
          "inertia) and p-refinement (displacement, one element per member). Errors are the "
          "largest "
          "over the five modes of |f − f_R|/f_R, where f_R is the series' own Richardson "
          "extrapolation from its three finest meshes (ratio 2) with each mode's observed order; "
          "the p-series is measured against its own highest order. Every parameterization gives "
          "the same frequencies about the undeformed state (the JSON has all of them); the figures "
          "draw one per formulation.\n\n";
    write_tables(all, converged, md);
    for (const auto& [x, files, titles] : {std::tuple{"elements", h_files, h_titles},
                                           std::tuple{"unknowns", all_files, all_titles}}) {
        const std::string base = std::string("joined-beam-modal-") + x;
        plot("study_joined_beam_modal.gp",
             {{"files", join_words(files)},
              {"titles", join_words(titles)},
              {"xcol", std::string(x) == "elements" ? "1" : "2"},
              {"xlabel", std::string(x) == "elements" ? "elements per member [-]" : "unknowns [-]"},
              {"plottitle", std::string("Joined beam, five lowest frequencies: error vs ") + x},
              {"outbase", out_path(o, base)}});
        out["figures"].push_back(base + ".png");
        md << "![" << base << ".png](" << base << ".png)\n\n";
    }
    write_text(o, "study-joined-beam-modal.md", md.str());
    out["schema_version"] = kSchemaVersion;
    write_text(o, "study-joined-beam-modal.json", out.dump(1) + "\n");
    return out;
}

}  // namespace rotbeam::cli
