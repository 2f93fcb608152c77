#include "cases/loader/beamdyn_lines.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>

#include "cases/loader/limits.hpp"
#include "cases/loader/yaml_reader.hpp"
#include "core/errors.hpp"

namespace rotbeam::cases {

namespace {

std::string lower(std::string_view s) {
    std::string out(s);
    std::transform(out.begin(), out.end(), out.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return out;
}

// What the message quotes of a token: short, printable.
std::string quoted(const std::string& token) {
    std::string t = token.substr(0, 40);
    for (char& c : t) {
        if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f) c = '?';
    }
    return "'" + t + (token.size() > 40 ? "...'" : "'");
}

}  // namespace

std::vector<std::string> split_deck_tokens(std::string_view line) {
    std::vector<std::string> tokens;
    size_t i = 0;
    while (i < line.size()) {
        const char c = line[i];
        if (c == ' ' || c == '\t' || c == '\r' || c == ',') {
            ++i;
        } else if (c == '"' || c == '\'') {
            const size_t end = line.find(c, i + 1);
            const size_t stop = end == std::string_view::npos ? line.size() : end;
            tokens.emplace_back(line.substr(i + 1, stop - i - 1));
            i = stop + 1;
        } else {
            size_t j = i;
            while (j < line.size() && line[j] != ' ' && line[j] != '\t' && line[j] != '\r' &&
                   line[j] != ',') {
                ++j;
            }
            tokens.emplace_back(line.substr(i, j - i));
            i = j;
        }
    }
    return tokens;
}

DeckLines::DeckLines(std::string name, const std::string& text) : name_(std::move(name)) {
    if (text.size() > kMaxFileBytes) {
        throw InputError(name_ + ":1: (file): larger than " + std::to_string(kMaxFileBytes) +
                         " bytes (a limit of the case format)");
    }
    int line = 1;
    for (size_t i = 0; i < text.size(); ++i) {
        const auto c = static_cast<unsigned char>(text[i]);
        if (c == '\n') ++line;
        if (c == 0 || (c < 0x20 && c != '\n' && c != '\r' && c != '\t') || c == 0x7f) {
            throw InputError(name_ + ":" + std::to_string(line) +
                             ": (file): not a text input file (control byte at offset " +
                             std::to_string(i) + ")");
        }
    }
    size_t start = 0;
    while (start <= text.size()) {
        const size_t end = text.find('\n', start);
        if (end == std::string::npos) {
            if (start < text.size()) lines_.push_back(text.substr(start));
            break;
        }
        lines_.push_back(text.substr(start, end - start));
        start = end + 1;
    }
}

void DeckLines::fail(std::string_view key, const std::string& problem) const {
    throw InputError(one_line(name_ + ":" + std::to_string(std::max(next_, 1)) + ": " +
                              std::string(key) + ": " + problem));
}

std::vector<std::string> DeckLines::take(std::string_view key) {
    if (at_end()) {
        ++next_;
        fail(key, "the file ends before this line");
    }
    return split_deck_tokens(lines_[static_cast<size_t>(next_++)]);
}

void DeckLines::comment(std::string_view what) { take(what); }

std::string DeckLines::peek_label() const {
    if (at_end()) return "";
    const auto tokens = split_deck_tokens(lines_[static_cast<size_t>(next_)]);
    return tokens.size() >= 2 ? tokens[1] : "";
}

std::vector<std::string> DeckLines::value_line(std::string_view key) {
    auto tokens = take(key);
    if (tokens.empty()) fail(key, "expected a value, found an empty line");
    if (tokens.size() < 2 || lower(tokens[1]) != lower(key)) {
        fail(key,
             "expected the value of '" + std::string(key) + "' on this line, found " +
                 (tokens.size() < 2 ? std::string("no label") : "the label " + quoted(tokens[1])) +
                 " (BeamDyn reads its files by position)");
    }
    return tokens;
}

double DeckLines::to_number(const std::string& token, std::string_view key) const {
    std::string t = token;
    for (char& c : t) {
        if (c == 'd' || c == 'D') c = 'E';  // Fortran double-precision exponent
    }
    const char* begin = t.c_str();
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(begin, &end);
    if (t.empty() || end != begin + t.size() || errno == ERANGE || !std::isfinite(v) ||
        t.find_first_of("xXnNiI") != std::string::npos) {
        fail(key, "expected a finite number, got " + quoted(token));
    }
    return v;
}

double DeckLines::number(std::string_view key) { return to_number(value_line(key)[0], key); }

int DeckLines::integer(std::string_view key, int min, int max) {
    const std::string token = value_line(key)[0];
    const double v = to_number(token, key);
    if (v != std::floor(v) || v < min || v > max) {
        fail(key, "expected a whole number from " + std::to_string(min) + " to " +
                      std::to_string(max) + ", got " + quoted(token));
    }
    return static_cast<int>(v);
}

bool DeckLines::flag(std::string_view key) {
    const std::string token = value_line(key)[0];
    const std::string t = lower(token);
    if (t == "true" || t == "t" || t == ".true." || t == ".t.") return true;
    if (t == "false" || t == "f" || t == ".false." || t == ".f.") return false;
    fail(key, "expected True or False, got " + quoted(token));
}

std::string DeckLines::text(std::string_view key) { return value_line(key)[0]; }

bool DeckLines::number_or_default(std::string_view key, double& value) {
    const std::string token = value_line(key)[0];
    if (lower(token) == "default") return false;
    value = to_number(token, key);
    return true;
}

std::vector<double> DeckLines::row(std::string_view key, int count) {
    const auto tokens = take(key);
    if (static_cast<int>(tokens.size()) < count) {
        fail(key, "expected " + std::to_string(count) + " numbers on this line, found " +
                      std::to_string(tokens.size()));
    }
    std::vector<double> values;
    values.reserve(static_cast<size_t>(count));
    for (int i = 0; i < count; ++i)
        values.push_back(to_number(tokens[static_cast<size_t>(i)], key));
    return values;
}

}  // namespace rotbeam::cases
