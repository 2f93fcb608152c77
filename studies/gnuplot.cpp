#include "gnuplot.hpp"

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <stdexcept>
#include <thread>
#include <vector>

#include "core/atomic_file.hpp"
#include "core/child_process.hpp"

namespace rotbeam::cli {

namespace fs = std::filesystem;

namespace {

// `text` as a gnuplot string literal: single-quoted, each ' doubled (no escapes are expanded).
std::string gnuplot_string(const std::string& text) {
    std::string s = "'";
    for (char c : text) s += c == '\'' ? std::string("''") : std::string(1, c);
    return s + "'";
}

// One gnuplot run; `figure` names the figure in the failure message.
void run_once(const std::string& script, const std::map<std::string, std::string>& vars,
              const std::string& figure) {
    const fs::path errors =
        fs::temp_directory_path() /
        ("rotbeam-gnuplot-" + std::to_string(::getpid()) + "-" +
         std::to_string(std::hash<std::thread::id>()(std::this_thread::get_id())) + ".err");
    // Run as a child that a stopping rotbeam kills and waits for (core/child_process.hpp), so it
    // cannot write a figure's file after the temporaries were removed.
    std::vector<std::string> arguments{"gnuplot"};
    for (const auto& [k, v] : vars) {
        arguments.push_back("-e");
        arguments.push_back(k + "=" + gnuplot_string(v));
    }
    arguments.push_back((fs::path(ROTBEAM_REPORTS_DIR) / script).string());
    const int status = run_child_process(arguments, errors.string());
    std::string last;
    {
        std::ifstream in(errors);
        for (std::string line; std::getline(in, line);) {
            if (line.find_first_not_of(" ^") != std::string::npos) last = line;
        }
    }
    std::error_code ec;
    fs::remove(errors, ec);
    if (status != 0) {
        throw std::runtime_error("gnuplot failed on reports/" + script +
                                 (figure.empty() ? "" : " for " + figure) + " (exit status " +
                                 std::to_string(status) + "): " + last);
    }
}

// Whether a figure gnuplot wrote is whole: gnuplot does not check its writes, so on a full disk or
// past a file size limit it exits 0 with a figure cut short. A PNG ends with its IEND chunk, an SVG
// with its closing tag (and white space); the scripts write no other format.
bool gnuplot_figure_complete(const std::string& file) {
    std::ifstream in(file, std::ios::binary | std::ios::ate);
    const std::streamoff size = in.tellg();
    const std::streamoff tail_size = std::min<std::streamoff>(size, 64);
    if (!in || size <= 0) return false;
    std::string tail(static_cast<size_t>(tail_size), '\0');
    in.seekg(size - tail_size);
    in.read(tail.data(), tail_size);
    if (file.ends_with(".png")) return tail.ends_with(std::string("IEND\xae\x42\x60\x82"));
    if (file.ends_with(".svg")) {
        const size_t last = tail.find_last_not_of(" \t\r\n");
        return last != std::string::npos && tail.substr(0, last + 1).ends_with("</svg>");
    }
    return true;
}

}  // namespace

// The figures (every script writes `outbase` + a suffix) are written atomically: under a temporary
// base, checked whole (gnuplot_figure_complete) and renamed once gnuplot has finished them
// (core/atomic_file.hpp).
void run_gnuplot_script(const std::string& script, const std::map<std::string, std::string>& vars) {
    const auto outbase = vars.find("outbase");
    if (outbase == vars.end()) {
        run_once(script, vars, "");
        return;
    }
    write_files_atomically(
        outbase->second,
        [&](const std::string& temporary_base) {
            std::map<std::string, std::string> v = vars;
            v["outbase"] = temporary_base;
            run_once(script, v, outbase->second);
        },
        gnuplot_figure_complete);
}

}  // namespace rotbeam::cli
