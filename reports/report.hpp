// The suite's report: DIR/index.md and a self-contained DIR/index.html. It opens with the summary
// (a sentence per case, the matrix case × combination linked to the runs table) and the contents,
// then the runs table and the sections; plots are made by the gnuplot scripts in reports/ (PNG for
// the Markdown, SVG for the HTML) from data files the report writes.
#pragma once

#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace rotbeam::cli {

// `study_names`: the studies whose sections (DIR/study-NAME.md, when present) close the report, in
// that order. `published_checks`: `verify`'s rows for the cases run (objects with `case`,
// `reference`, `quantity`, `combination` as "formulation/rotation[/...][ key=value ...]",
// `difference`, `tolerance`, `result`), for the summary and the runs table.
void write_report(const std::string& out_dir, const std::vector<std::string>& run_files,
                  const std::vector<std::string>& study_names,
                  const nlohmann::json& published_checks = nlohmann::json::array());

// The report's Markdown (CommonMark with pipe tables) as one self-contained HTML page, figures
// embedded as SVG (report_html.cpp).
std::string markdown_page_html(const std::string& markdown, const std::string& out_dir);

// The version of the Markdown library linked in (cmark-gfm's own string, e.g. "0.29.0.gfm.6"),
// for `rotbeam --version`.
std::string markdown_library_version();

// The id of a level-2 heading titled `title` in the HTML page (lower-case letters and digits,
// other runs of characters as one '-'); `used` counts the ids given so far, in document order, and
// makes repeated titles unique (-2, -3, ...).
std::string heading_id(const std::string& title, std::map<std::string, int>& used);

}  // namespace rotbeam::cli
