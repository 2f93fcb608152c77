// A self-contained HTML page from the report's small Markdown subset (headings, paragraphs,
// pipe tables, images), with the images embedded as base64 data URIs.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "report.hpp"

namespace rotbeam::cli {

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

std::string escape(const std::string& s) {
    std::string o;
    for (char c : s) {
        if (c == '<')
            o += "&lt;";
        else if (c == '>')
            o += "&gt;";
        else if (c == '&')
            o += "&amp;";
        else
            o += c;
    }
    return o;
}

std::vector<std::string> table_cells(const std::string& line) {
    std::vector<std::string> cells;
    std::string cell;
    for (size_t i = 1; i < line.size(); ++i) {
        // A cell's escaped characters (markdown_cell, studies/study_common.hpp) are plain text.
        const bool escaped = line[i] == '\\' && i + 1 < line.size() &&
                             (line[i + 1] == '\\' || line[i + 1] == '|' || line[i + 1] == '`');
        if (escaped) {
            cell += line[++i];
        } else if (line[i] == '|') {
            const size_t a = cell.find_first_not_of(' '), b = cell.find_last_not_of(' ');
            cells.push_back(a == std::string::npos ? "" : cell.substr(a, b - a + 1));
            cell.clear();
        } else {
            cell += line[i];
        }
    }
    return cells;
}

}  // namespace

std::string markdown_page_html(const std::string& markdown, const std::string& out_dir) {
    std::ostringstream html;
    html << "<!DOCTYPE html><html><head><meta charset=\"utf-8\"><title>rotbeam report</title>"
            "<style>body{font-family:sans-serif;max-width:1200px;margin:2em auto}"
            "table{border-collapse:collapse;font-size:90%}td,th{border:1px solid #bbb;"
            "padding:2px 6px}img{max-width:100%}</style></head><body>\n";
    std::istringstream in(markdown);
    std::string line;
    bool in_table = false, header_row = false;
    while (std::getline(in, line)) {
        if (!line.empty() && line[0] == '|') {
            if (line.rfind("|---", 0) == 0) continue;
            if (!in_table) {
                html << "<table>\n";
                in_table = header_row = true;
            }
            html << "<tr>";
            for (const std::string& c : table_cells(line)) {
                html << (header_row ? "<th>" : "<td>") << escape(c)
                     << (header_row ? "</th>" : "</td>");
            }
            html << "</tr>\n";
            header_row = false;
            continue;
        }
        if (in_table) {
            html << "</table>\n";
            in_table = false;
        }
        if (line.rfind("## ", 0) == 0) {
            html << "<h2>" << escape(line.substr(3)) << "</h2>\n";
        } else if (line.rfind("# ", 0) == 0) {
            html << "<h1>" << escape(line.substr(2)) << "</h1>\n";
        } else if (line.rfind("![", 0) == 0) {
            const size_t open = line.find("](");
            const std::string file = line.substr(open + 2, line.size() - open - 3);
            std::ifstream img(std::filesystem::path(out_dir) / file, std::ios::binary);
            std::ostringstream bytes;
            bytes << img.rdbuf();
            html << "<p><img alt=\"" << escape(line.substr(2, open - 2))
                 << "\" src=\"data:image/png;base64," << base64(bytes.str()) << "\"></p>\n";
        } else if (!line.empty()) {
            html << "<p>" << escape(line) << "</p>\n";
        }
    }
    if (in_table) html << "</table>\n";
    html << "</body></html>\n";
    return html.str();
}

}  // namespace rotbeam::cli
