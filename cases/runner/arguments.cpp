#include "arguments.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <utility>

#include "core/errors.hpp"

namespace rotbeam::cli {

std::optional<std::string> ParsedArguments::value(const std::string& name) const {
    const auto it = values_.find(name);
    if (it == values_.end() || it->second.empty()) return std::nullopt;
    return it->second.back();
}

std::vector<std::string> ParsedArguments::values(const std::string& name) const {
    const auto it = values_.find(name);
    return it == values_.end() ? std::vector<std::string>{} : it->second;
}

std::optional<int> ParsedArguments::positive_int(const std::string& command,
                                                 const std::string& name, int max, int min) const {
    const std::optional<std::string> v = value(name);
    if (!v) return std::nullopt;
    size_t used = 0;
    long n = 0;
    try {
        n = std::stol(*v, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used != v->size() || v->empty() || !std::isdigit(static_cast<unsigned char>(v->front())) ||
        n < min || n > max) {
        throw InputError("rotbeam " + command + ": --" + name + ": expected an integer from " +
                         std::to_string(min) + " to " + std::to_string(max) + ", got '" + *v + "'");
    }
    return static_cast<int>(n);
}

std::optional<double> ParsedArguments::positive_number(const std::string& command,
                                                       const std::string& name, double max) const {
    const std::optional<std::string> v = value(name);
    if (!v) return std::nullopt;
    char* end = nullptr;
    const double x = v->empty() ? 0.0 : std::strtod(v->c_str(), &end);
    if (v->empty() || end != v->c_str() + v->size() || !std::isfinite(x) || !(x > 0.0) || x > max) {
        std::ostringstream m;
        m << "rotbeam " << command << ": --" << name << ": expected a number in (0, " << max
          << "], got '" << *v << "'";
        throw InputError(m.str());
    }
    return x;
}

const OptionSpec kTimeLimitOption{
    "time-limit", "SECONDS",
    "stop each run after this wall-clock time with the status time-limit; a stopped run keeps no "
    "numbers, is made again on a rerun and is left out of scripts/compare-results.py (default: no "
    "limit)"};

double time_limit_option(const ParsedArguments& a, const std::string& command) {
    return a.positive_number(command, "time-limit", kMaxTimeLimit).value_or(0.0);
}

namespace {

const OptionSpec* find_option(const CommandSpec& spec, const std::string& name) {
    for (const OptionSpec& o : spec.options) {
        if (o.name == name) return &o;
    }
    return nullptr;
}

}  // namespace

ParsedArguments parse_arguments(const CommandSpec& spec, const std::vector<std::string>& args) {
    if (spec_capture != nullptr) {
        spec_capture->push_back(spec);
        throw SpecCaptured{};
    }
    ParsedArguments parsed;
    const std::string prefix = "rotbeam " + spec.name + ": ";
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        if (a == "--help" || a == "-h") {
            parsed.help = true;
            continue;
        }
        if (a.rfind("--", 0) != 0 || a.size() == 2) {
            parsed.positional.push_back(a);
            continue;
        }
        std::string name = a.substr(2);
        std::optional<std::string> inline_value;
        if (const size_t eq = name.find('='); eq != std::string::npos) {
            inline_value = name.substr(eq + 1);
            name = name.substr(0, eq);
        }
        const OptionSpec* option = find_option(spec, name);
        if (!option) {
            std::vector<std::string> names;
            for (const OptionSpec& o : spec.options) names.push_back(o.name);
            const std::string guess = closest_match(name, names);
            throw InputError(prefix + "unknown option '--" + name + "'" +
                             (guess.empty() ? "" : " (did you mean '--" + guess + "'?)") +
                             "; see 'rotbeam " + spec.name + " --help'");
        }
        if (option->value_name.empty()) {
            if (inline_value) throw InputError(prefix + "--" + name + " takes no value");
            parsed.values_[name].push_back("true");
            continue;
        }
        std::string value;
        if (inline_value) {
            value = *inline_value;
        } else {
            if (i + 1 >= args.size()) {
                throw InputError(prefix + "--" + name + " needs a value (" + option->value_name +
                                 ")");
            }
            value = args[++i];
        }
        if (!option->repeatable && parsed.values_.count(name)) {
            throw InputError(prefix + "--" + name + " given more than once");
        }
        parsed.values_[name].push_back(value);
    }
    if (parsed.help) return parsed;
    const int n = static_cast<int>(parsed.positional.size());
    if (n < spec.min_positional) {
        throw InputError(prefix + "missing " + spec.positional + "; see 'rotbeam " + spec.name +
                         " --help'");
    }
    if (spec.max_positional >= 0 && n > spec.max_positional) {
        throw InputError(prefix + "unexpected argument '" + parsed.positional.back() + "'");
    }
    return parsed;
}

std::string help_text(const CommandSpec& spec) {
    std::ostringstream s;
    s << "usage: rotbeam " << spec.name;
    if (!spec.positional.empty()) s << " " << spec.positional;
    if (!spec.options.empty()) s << " [options]";
    s << "\n\n" << spec.summary << "\n";
    if (spec.min_positional > 0) s << "\narguments:\n  " << spec.positional << " (required)\n";
    if (!spec.options.empty()) s << "\noptions:\n";
    for (const OptionSpec& o : spec.options) {
        std::string left = "  --" + o.name + (o.value_name.empty() ? "" : " " + o.value_name);
        if (left.size() < 30) left.resize(30, ' ');
        s << left << " " << o.help << (o.repeatable ? " (repeatable)" : "")
          << (o.value_name.empty() ? " (default: off)" : "") << "\n";
    }
    s << "  --help                       print this help\n";
    return s.str();
}

const std::vector<Shorthand>& run_shorthands() {
    static const std::vector<Shorthand> shorthands = {
        {"rotation", "discretization.rotation"},
        {"formulation", "discretization.formulation"},
        {"order", "discretization.order"},
        {"elements", "members.*.elements"},
        {"interpolation", "discretization.interpolation"},
        {"accuracy", "analysis.accuracy"}};
    return shorthands;
}

std::vector<std::string> case_overrides(const ParsedArguments& a) {
    std::vector<std::string> overrides;
    for (const auto& [option, key] : run_shorthands()) {
        if (const auto v = a.value(option)) overrides.push_back(std::string(key) + "=" + *v);
    }
    for (const std::string& s : a.values("set")) overrides.push_back(s);
    return overrides;
}

}  // namespace rotbeam::cli
