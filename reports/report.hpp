// The suite's report: DIR/index.md and a self-contained DIR/index.html with the runs table and the
// plots (PNG and SVG, made by the gnuplot scripts in reports/ from data files the report writes).
#pragma once

#include <map>
#include <string>
#include <vector>

namespace rotbeam::cli {

void write_report(const std::string& out_dir, const std::vector<std::string>& run_files);

// The report's Markdown (headings, paragraphs, pipe tables, images) as one self-contained HTML
// page, images embedded (report_html.cpp).
std::string markdown_page_html(const std::string& markdown, const std::string& out_dir);

// Runs reports/<script> with gnuplot and string variables (-e "k='v'", any text quoted); throws
// std::runtime_error with gnuplot's message when gnuplot is missing or fails, since the report
// links the figure. Shared with the studies and the benchmark (study_common.cpp).
void run_gnuplot_script(const std::string& script, const std::map<std::string, std::string>& vars);

}  // namespace rotbeam::cli
