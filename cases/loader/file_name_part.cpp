#include "cases/loader/file_name_part.hpp"

#include "cases/loader/yaml_reader.hpp"

namespace rotbeam::cases {

namespace {

bool name_part_character(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' ||
           c == '_' || c == '.';
}

// A byte as a message may quote it: itself when printable ASCII, else \xHH.
std::string quoted_byte(char c) {
    static const char digits[] = "0123456789abcdef";
    const auto u = static_cast<unsigned char>(c);
    if (u >= 0x20 && u < 0x7f) return std::string(1, c);
    return std::string("\\x") + digits[u >> 4] + digits[u & 15];
}

}  // namespace

std::string file_name_part_problem(const std::string& text) {
    std::string problem;
    if (text.empty()) {
        problem = "it is empty";
    } else if (text.size() > kMaxFileNamePart) {
        problem = "it has " + std::to_string(text.size()) + " characters, more than " +
                  std::to_string(kMaxFileNamePart);
    } else if (const size_t at = text.find_first_of("/\\"); at != std::string::npos) {
        problem = "it holds '" + quoted_byte(text[at]) + "'";
    } else if (text.front() == '.') {
        problem = "it starts with '.'";
    } else if (text.find("..") != std::string::npos) {
        problem = "it holds '..'";
    } else {
        for (const char c : text) {
            if (!name_part_character(c)) {
                problem = "it holds '" + quoted_byte(c) + "'";
                break;
            }
        }
    }
    if (problem.empty()) return problem;
    // The value itself, shortened: a name far past the limit is not worth quoting whole.
    std::string shown = text;
    if (shown.size() > 40) {
        size_t cut = 37;  // not inside a UTF-8 sequence
        while (cut > 0 && (static_cast<unsigned char>(shown[cut]) & 0xc0) == 0x80) --cut;
        shown = shown.substr(0, cut) + "...";
    }
    return one_line("'" + shown + "' cannot be part of a file name: " + problem +
                    " (allowed: 1 to " + std::to_string(kMaxFileNamePart) +
                    " letters, digits, '-', '_' and '.', not starting with '.', no '..')");
}

}  // namespace rotbeam::cases
