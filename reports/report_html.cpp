// The report's Markdown as one self-contained HTML page, converted by cmark-gfm (CommonMark with
// GitHub's pipe tables). Every image is the SVG of the figure the Markdown links as PNG (the
// gnuplot scripts write both), embedded as a data URI; a figure without its SVG stops the report.
// Level-2 headings get the ids that heading_id() gives, so the contents' links land on them.
#include <cmark-gfm-core-extensions.h>
#include <cmark-gfm.h>

#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "report.hpp"

namespace rotbeam::cli {

namespace fs = std::filesystem;

namespace {

std::string base64(const std::string& bytes) {
    static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    size_t i = 0;
    for (; i + 2 < bytes.size(); i += 3) {
        const unsigned v = (static_cast<unsigned char>(bytes[i]) << 16) |
                           (static_cast<unsigned char>(bytes[i + 1]) << 8) |
                           static_cast<unsigned char>(bytes[i + 2]);
        for (int k = 3; k >= 0; --k) out += table[(v >> (6 * k)) & 63];
    }
    if (i < bytes.size()) {
        unsigned v = static_cast<unsigned char>(bytes[i]) << 16;
        if (i + 1 < bytes.size()) v |= static_cast<unsigned char>(bytes[i + 1]) << 8;
        out += table[(v >> 18) & 63];
        out += table[(v >> 12) & 63];
        out += i + 1 < bytes.size() ? table[(v >> 6) & 63] : '=';
        out += '=';
    }
    return out;
}

// The figure `png` (a file name in out_dir) as an SVG data URI.
std::string svg_data_uri(const std::string& png, const std::string& out_dir) {
    fs::path svg = fs::path(out_dir) / png;
    svg.replace_extension(".svg");
    std::ifstream in(svg, std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    if (!in || bytes.str().empty()) {
        throw std::runtime_error("report: the HTML page shows figures as SVG, and " + svg.string() +
                                 " (the SVG of " + png +
                                 ") is missing or empty: its gnuplot script must write both");
    }
    return "data:image/svg+xml;base64," + base64(bytes.str());
}

// The literal text of a node's inline children (a heading's words without their markup).
std::string text_of(cmark_node* node) {
    std::string text;
    for (cmark_node* c = cmark_node_first_child(node); c; c = cmark_node_next(c)) {
        const char* literal = cmark_node_get_literal(c);
        text += literal ? std::string(literal) : text_of(c);
    }
    return text;
}

struct Parser {
    cmark_parser* p;
    Parser() : p(cmark_parser_new(CMARK_OPT_DEFAULT)) {}
    ~Parser() { cmark_parser_free(p); }
    Parser(const Parser&) = delete;
    Parser& operator=(const Parser&) = delete;
};

constexpr const char* kStyle =
    "body{font-family:sans-serif;max-width:1400px;margin:2em auto;padding:0 1em}"
    "table{border-collapse:collapse;font-size:90%;margin:1em 0;display:block;overflow-x:auto}"
    "td,th{border:1px solid #bbb;padding:2px 6px;vertical-align:top}"
    "img{max-width:100%}code{background:#f4f4f4}"
    "td a{text-decoration:none}";

}  // namespace

std::string heading_id(const std::string& title, std::map<std::string, int>& used) {
    std::string id;
    for (unsigned char c : title) {
        if (std::isalnum(c)) {
            id += static_cast<char>(std::tolower(c));
        } else if (!id.empty() && id.back() != '-') {
            id += '-';
        }
    }
    while (!id.empty() && id.back() == '-') id.pop_back();
    if (id.empty()) id = "section";
    const int n = ++used[id];
    return n == 1 ? id : id + "-" + std::to_string(n);
}

std::string markdown_library_version() { return cmark_version_string(); }

std::string markdown_page_html(const std::string& markdown, const std::string& out_dir) {
    cmark_gfm_core_extensions_ensure_registered();
    Parser parser;
    cmark_syntax_extension* table = cmark_find_syntax_extension("table");
    if (!table || !cmark_parser_attach_syntax_extension(parser.p, table)) {
        throw std::runtime_error("report: cmark-gfm has no table extension");
    }
    cmark_parser_feed(parser.p, markdown.data(), markdown.size());
    const std::unique_ptr<cmark_node, void (*)(cmark_node*)> document(cmark_parser_finish(parser.p),
                                                                      cmark_node_free);

    // Figures as embedded SVG; each level-2 heading with its id (an empty anchor before its text:
    // cmark-gfm writes no attributes on headings).
    std::map<std::string, int> used;
    cmark_iter* it = cmark_iter_new(document.get());
    std::vector<cmark_node*> headings;
    for (cmark_event_type e; (e = cmark_iter_next(it)) != CMARK_EVENT_DONE;) {
        cmark_node* node = cmark_iter_get_node(it);
        if (e != CMARK_EVENT_ENTER) continue;
        if (cmark_node_get_type(node) == CMARK_NODE_IMAGE) {
            const std::string url = cmark_node_get_url(node);
            cmark_node_set_url(node, svg_data_uri(url, out_dir).c_str());
        } else if (cmark_node_get_type(node) == CMARK_NODE_HEADING &&
                   cmark_node_get_heading_level(node) == 2) {
            headings.push_back(node);
        }
    }
    cmark_iter_free(it);
    for (cmark_node* h : headings) {
        cmark_node* anchor = cmark_node_new(CMARK_NODE_HTML_INLINE);
        const std::string html = "<a id=\"" + heading_id(text_of(h), used) + "\"></a>";
        cmark_node_set_literal(anchor, html.c_str());
        cmark_node_prepend_child(h, anchor);
    }
    // CMARK_OPT_UNSAFE keeps the raw HTML: the anchors above, and the row anchors the report
    // writes into its tables (report text is escaped where it enters a table, markdown_cell).
    char* body = cmark_render_html(document.get(), CMARK_OPT_UNSAFE,
                                   cmark_parser_get_syntax_extensions(parser.p));
    std::ostringstream html;
    html << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
            "<title>rotbeam report</title><style>"
         << kStyle << "</style></head><body>\n"
         << body << "</body></html>\n";
    std::free(body);
    return html.str();
}

}  // namespace rotbeam::cli
