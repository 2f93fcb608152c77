// The suite's report: DIR/index.md and a self-contained DIR/index.html with the runs table and the
// plots (PNG and SVG, made by the gnuplot scripts in reports/ from data files the report writes).
#pragma once

#include <map>
#include <string>
#include <vector>

namespace rotbeam::cli {

// `study_names`: the studies whose sections (DIR/study-NAME.md, when present) close the report, in
// that order.
void write_report(const std::string& out_dir, const std::vector<std::string>& run_files,
                  const std::vector<std::string>& study_names);

// The report's Markdown (headings, paragraphs, pipe tables, images) as one self-contained HTML
// page, images embedded (report_html.cpp).
std::string markdown_page_html(const std::string& markdown, const std::string& out_dir);

}  // namespace rotbeam::cli
