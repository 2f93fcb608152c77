#include "cases/loader/yaml_reader.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>

#include "cases/loader/limits.hpp"
#include "core/errors.hpp"

namespace rotbeam::cases {

std::string one_line(const std::string& text) {
    static const char digits[] = "0123456789abcdef";
    std::string out;
    for (const char c : text) {
        const auto u = static_cast<unsigned char>(c);
        if (c == '\n') {
            out += "\\n";
        } else if (c == '\r') {
            out += "\\r";
        } else if (c == '\t') {
            out += "\\t";
        } else if (u < 0x20 || u == 0x7f) {
            out += std::string("\\x") + digits[u >> 4] + digits[u & 15];
        } else {
            out += c;
        }
    }
    return out;
}

std::string child_key(const std::string& parent, const std::string& child) {
    return parent.empty() ? child : parent + "." + child;
}

namespace {

std::string join(const std::vector<std::string>& items) {
    std::string s;
    for (size_t i = 0; i < items.size(); ++i) s += (i ? ", " : "") + items[i];
    return s;
}

// A scalar as the user wrote it, shortened for messages.
std::string quoted(const std::string& text) {
    std::string t = text.size() > 40 ? text.substr(0, 37) + "..." : text;
    return "'" + t + "'";
}

}  // namespace

bool YamlReader::overridden(const std::string& key) const {
    // `--set` addresses a list item as a segment (`points.tip.0`), a message as `points.tip[0]`.
    std::string path;
    for (const char c : key) {
        if (c == '[') {
            path += '.';
        } else if (c != ']') {
            path += c;
        }
    }
    for (const std::string& o : overridden_) {
        if (path == o || path.rfind(o + ".", 0) == 0) return true;
    }
    return false;
}

void YamlReader::index(const YAML::Node& node, const std::string& path, int depth) {
    if ((node.IsMap() || node.IsSequence()) && depth > kMaxYamlDepth) {
        throw InputError(file_ + ":" + std::to_string(node.Mark().line + 1) +
                         ": (yaml): nested deeper than " + std::to_string(kMaxYamlDepth) +
                         " levels (the limit of a case file)");
    }
    if (node.IsMap()) {
        for (const auto& item : node) {
            if (!item.first.IsScalar()) continue;
            const std::string k = child_key(path, item.first.Scalar());
            if (!item.first.Mark().is_null()) lines_[k] = item.first.Mark().line;
            index(item.second, k, depth + 1);
        }
    } else if (node.IsSequence()) {
        for (size_t i = 0; i < node.size(); ++i) {
            const std::string k = path + "[" + std::to_string(i) + "]";
            if (!node[i].Mark().is_null()) lines_[k] = node[i].Mark().line;
            index(node[i], k, depth + 1);
        }
    }
}

std::string YamlReader::where(const YAML::Node& node, const std::string& key) const {
    if (overridden(key)) return file_ + ":--set:";
    // The key's own line, else (a missing key) the line of its closest parent key.
    for (std::string k = key; !k.empty();) {
        const auto it = lines_.find(k);
        if (it != lines_.end()) return file_ + ":" + std::to_string(it->second + 1) + ":";
        const size_t cut = k.find_last_of(".[");
        k = cut == std::string::npos ? std::string() : k.substr(0, cut);
    }
    const YAML::Mark mark = node.Mark();
    if (mark.is_null() || mark.line < 0) return file_ + ":--set:";
    return file_ + ":" + std::to_string(mark.line + 1) + ":";
}

void YamlReader::fail(const YAML::Node& node, const std::string& key,
                      const std::string& problem) const {
    throw InputError(
        one_line(where(node, key) + " " + (key.empty() ? "(file)" : key) + ": " + problem));
}

std::string YamlReader::kind_name(const YAML::Node& node) const {
    switch (node.Type()) {
        case YAML::NodeType::Map:
            return "a mapping";
        case YAML::NodeType::Sequence:
            return "a list";
        case YAML::NodeType::Null:
            return "nothing";
        case YAML::NodeType::Scalar:
            return quoted(node.Scalar());
        default:
            return "an undefined node";
    }
}

void YamlReader::expect_unique_keys(const YAML::Node& node, const std::string& key) const {
    std::set<std::string> seen;
    for (const auto& item : node) {
        if (!item.first.IsScalar()) fail(item.first, key, "keys must be plain names");
        if (!seen.insert(item.first.Scalar()).second) {
            fail(item.first, child_key(key, item.first.Scalar()), "duplicate key");
        }
    }
}

void YamlReader::expect_map(const YAML::Node& node, const std::string& key,
                            std::initializer_list<const char*> allowed) const {
    if (!node.IsMap()) fail(node, key, "expected a mapping, got " + kind_name(node));
    expect_unique_keys(node, key);
    const std::vector<std::string> names(allowed.begin(), allowed.end());
    for (const auto& item : node) {
        if (!item.first.IsScalar()) fail(item.first, key, "keys must be plain names");
        const std::string k = item.first.Scalar();
        if (std::find(names.begin(), names.end(), k) != names.end()) continue;
        const std::string suggestion = closest_match(k, names);
        fail(item.first, child_key(key, k),
             "unknown key" + (suggestion.empty() ? " (allowed: " + join(names) + ")"
                                                 : "; did you mean '" + suggestion + "'?"));
    }
}

void YamlReader::expect_named_map(const YAML::Node& node, const std::string& key) const {
    if (!node.IsMap()) fail(node, key, "expected a mapping of names, got " + kind_name(node));
    if (node.size() == 0) fail(node, key, "must name at least one entry");
    expect_unique_keys(node, key);
    for (const auto& item : node) {
        if (!item.first.IsScalar() || item.first.Scalar().empty()) {
            fail(item.first, key, "names must be non-empty plain scalars");
        }
        const std::string& n = item.first.Scalar();
        const bool ok = std::all_of(n.begin(), n.end(), [](char c) {
            return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
        });
        if (!ok)
            fail(item.first, child_key(key, n), "names may contain only letters, digits, _ and -");
    }
}

YAML::Node YamlReader::required(const YAML::Node& map, const std::string& key,
                                const char* name) const {
    const YAML::Node child = map[name];
    if (!child) fail(map, child_key(key, name), "missing required key");
    return child;
}

std::string YamlReader::scalar(const YAML::Node& node, const std::string& key,
                               const std::string& expected) const {
    if (!node.IsScalar()) fail(node, key, "expected " + expected + ", got " + kind_name(node));
    return node.Scalar();
}

double YamlReader::number(const YAML::Node& node, const std::string& key) const {
    const std::string text = scalar(node, key, "a number");
    double v = 0.0;
    try {
        v = node.as<double>();
    } catch (const YAML::Exception&) {
        fail(node, key, "expected a number, got " + quoted(text));
    }
    if (!std::isfinite(v)) fail(node, key, "must be finite, got " + quoted(text));
    return v;
}

double YamlReader::positive(const YAML::Node& node, const std::string& key) const {
    const double v = number(node, key);
    if (!(v > 0.0)) fail(node, key, "must be positive, got " + quoted(node.Scalar()));
    return v;
}

double YamlReader::non_negative(const YAML::Node& node, const std::string& key) const {
    const double v = number(node, key);
    if (v < 0.0) fail(node, key, "must not be negative, got " + quoted(node.Scalar()));
    return v;
}

int YamlReader::integer(const YAML::Node& node, const std::string& key) const {
    const std::string text = scalar(node, key, "an integer");
    try {
        return node.as<int>();
    } catch (const YAML::Exception&) {
        fail(node, key, "expected an integer, got " + quoted(text));
    }
}

int YamlReader::positive_integer(const YAML::Node& node, const std::string& key) const {
    const int v = integer(node, key);
    if (v < 1) fail(node, key, "must be a positive integer, got " + quoted(node.Scalar()));
    return v;
}

int YamlReader::positive_integer(const YAML::Node& node, const std::string& key, long limit) const {
    const int v = positive_integer(node, key);
    if (v > limit) {
        fail(node, key,
             "must be at most " + std::to_string(limit) + " (a limit of the case format), got " +
                 quoted(node.Scalar()));
    }
    return v;
}

bool YamlReader::boolean(const YAML::Node& node, const std::string& key) const {
    const std::string text = scalar(node, key, "true or false");
    try {
        return node.as<bool>();
    } catch (const YAML::Exception&) {
        fail(node, key, "expected true or false, got " + quoted(text));
    }
}

std::string YamlReader::string(const YAML::Node& node, const std::string& key) const {
    return scalar(node, key, "a string");
}

std::string YamlReader::choice(const YAML::Node& node, const std::string& key,
                               const std::vector<std::string>& choices) const {
    const std::string v = scalar(node, key, "one of " + join(choices));
    if (std::find(choices.begin(), choices.end(), v) != choices.end()) return v;
    const std::string suggestion = closest_match(v, choices);
    fail(node, key,
         quoted(v) + " is not one of " + join(choices) +
             (suggestion.empty() ? "" : "; did you mean '" + suggestion + "'?"));
}

std::string YamlReader::name_in(const YAML::Node& node, const std::string& key,
                                const std::vector<std::string>& names,
                                const std::string& what) const {
    const std::string v = scalar(node, key, "the name of a " + what);
    if (std::find(names.begin(), names.end(), v) != names.end()) return v;
    const std::string suggestion = closest_match(v, names);
    fail(node, key,
         "unknown " + what + " " + quoted(v) +
             (suggestion.empty() ? " (known: " + join(names) + ")"
                                 : "; did you mean '" + suggestion + "'?"));
}

std::vector<double> YamlReader::numbers(const YAML::Node& node, const std::string& key) const {
    if (node.IsScalar()) return {number(node, key)};
    if (!node.IsSequence()) fail(node, key, "expected a list of numbers, got " + kind_name(node));
    std::vector<double> v;
    for (size_t i = 0; i < node.size(); ++i) {
        v.push_back(number(node[i], key + "[" + std::to_string(i) + "]"));
    }
    return v;
}

Vec3 YamlReader::vec3(const YAML::Node& node, const std::string& key) const {
    if (!node.IsSequence() || node.size() != 3) {
        fail(node, key,
             "expected a list of 3 numbers, got " + kind_name(node) +
                 (node.IsSequence() ? " of " + std::to_string(node.size()) : ""));
    }
    const std::vector<double> v = numbers(node, key);
    return Vec3(v[0], v[1], v[2]);
}

Vec6 YamlReader::vec6(const YAML::Node& node, const std::string& key) const {
    if (!node.IsSequence() || node.size() != 6) {
        fail(node, key,
             "expected a list of 6 numbers, got " + kind_name(node) +
                 (node.IsSequence() ? " of " + std::to_string(node.size()) : ""));
    }
    const std::vector<double> v = numbers(node, key);
    Vec6 out;
    for (int i = 0; i < 6; ++i) out[i] = v[static_cast<size_t>(i)];
    return out;
}

Mat6 YamlReader::mat6(const YAML::Node& node, const std::string& key) const {
    if (!node.IsSequence() || node.size() != 6) {
        fail(node, key,
             "expected 6 rows of 6 numbers, got " + kind_name(node) +
                 (node.IsSequence() ? " of " + std::to_string(node.size()) : ""));
    }
    Mat6 M;
    for (int i = 0; i < 6; ++i) {
        const std::string row_key = key + "[" + std::to_string(i) + "]";
        M.row(i) = vec6(node[static_cast<size_t>(i)], row_key).transpose();
    }
    return M;
}

}  // namespace rotbeam::cases
