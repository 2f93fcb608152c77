// Result schema helpers: unwrapped angles, NaN detection, atomic files.
#include <signal.h>
#include <sys/resource.h>

#include <algorithm>
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "core/results.hpp"
#include "core/so3.hpp"

using namespace rotbeam;

BOOST_AUTO_TEST_SUITE(results)

namespace {

// The OutputError message of `write` run under a file size limit of 4 KiB (SIGXFSZ ignored, as
// rotbeam does: a write past the limit fails with EFBIG), "" if it throws none; limit and signal
// restored after.
std::string output_error_under_a_4k_file_size_limit(const std::function<void()>& write) {
    const auto previous = ::signal(SIGXFSZ, SIG_IGN);
    rlimit saved{};
    getrlimit(RLIMIT_FSIZE, &saved);
    rlimit small = saved;
    small.rlim_cur = 4096;
    setrlimit(RLIMIT_FSIZE, &small);
    std::string message;
    try {
        write();
    } catch (const OutputError& e) {
        message = e.what();
    }
    setrlimit(RLIMIT_FSIZE, &saved);
    ::signal(SIGXFSZ, previous);
    return message;
}

}  // namespace

BOOST_AUTO_TEST_CASE(a_point_reports_the_norm_of_its_continued_rotation_vector) {
    Model model;
    model.points = {{"root", Vec3::Zero()}, {"tip", Vec3(12, 0, 0)}};
    std::vector<PointState> states(2);
    states[1].rotation = so3::exp_map(Vec3(0, -2.0 * kPi, 0));
    const std::vector<Vec3> continued = {Vec3::Zero(), Vec3(0, -2.0 * kPi, 0)};
    const nlohmann::json step = step_json(model, 2.0, std::nullopt, 3, states, continued);
    BOOST_TEST(std::abs(step["points"]["tip"]["rotation_angle"].get<double>() - 2.0 * kPi) < 1e-15);
    // The principal rotation vector of a full turn is the identity (round-off of sin 2π).
    BOOST_TEST(std::abs(step["points"]["tip"]["rotation_vector"][1].get<double>()) < 1e-15);
    BOOST_TEST(step["points"]["root"]["rotation_angle"].get<double>() == 0.0);
    BOOST_TEST(step["load_factor"].get<double>() == 2.0);
}

BOOST_AUTO_TEST_CASE(all_finite_detects_nan_anywhere) {
    nlohmann::json j = {{"a", 1.0}, {"b", {1.0, 2.0, {{"c", 3.0}}}}};
    BOOST_TEST(all_finite(j));
    j["b"][2]["c"] = std::nan("");
    BOOST_TEST(!all_finite(j));
}

BOOST_AUTO_TEST_CASE(atomic_write_replaces_the_file_and_leaves_no_temporary) {
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / "rotbeam_results_test";
    fs::remove_all(dir);
    const std::string path = (dir / "sub" / "r.json").string();
    write_file_atomically(path, "first");
    write_file_atomically(path, "second");
    std::ifstream in(path);
    std::string text;
    in >> text;
    BOOST_TEST(text == "second");
    int files = 0;
    for (const auto& e : fs::directory_iterator(dir / "sub")) {
        (void)e;
        ++files;
    }
    BOOST_TEST(files == 1);
    fs::remove_all(dir);
}

// A file size limit makes write() fail with EFBIG, the same path as a full disk (ENOSPC): the
// error is reported with the file's name, the old file stays as it was, and no temporary is left.
BOOST_AUTO_TEST_CASE(a_failed_write_names_the_file_and_keeps_the_old_one) {
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / "rotbeam_results_full";
    fs::remove_all(dir);
    const std::string path = (dir / "r.json").string();
    write_file_atomically(path, "old");
    const std::string message = output_error_under_a_4k_file_size_limit(
        [&] { write_file_atomically(path, std::string(10000, 'x')); });
    BOOST_TEST(message.find(path) != std::string::npos, message);
    BOOST_TEST(message.find("file size limit") != std::string::npos, message);
    std::ifstream in(path);
    std::string text;
    in >> text;
    BOOST_TEST(text == "old");
    int files = 0;
    for (const auto& e : fs::directory_iterator(dir)) {
        (void)e;
        ++files;
    }
    BOOST_TEST(files == 1);
    fs::remove_all(dir);
}

// Files written by another program under a base name (gnuplot's figures): while the writer runs,
// nothing exists under the target names; afterwards every file it wrote is there under its target
// name, and no temporary is left. A writer that fails leaves the old figures and nothing else.
BOOST_AUTO_TEST_CASE(figures_appear_complete_under_their_names_or_not_at_all) {
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / "rotbeam_results_figures";
    fs::remove_all(dir);
    const std::string base = (dir / "plot").string();
    auto files_in = [&dir] {
        std::vector<std::string> names;
        for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename());
        std::sort(names.begin(), names.end());
        return names;
    };
    write_files_atomically(base, [&](const std::string& temporary) {
        BOOST_TEST(fs::path(temporary).parent_path() == dir);
        BOOST_TEST(fs::path(temporary).filename().string().find(".rotbeam-tmp.") !=
                   std::string::npos);
        std::ofstream(temporary + ".png") << "png";
        std::ofstream(temporary + "-tip.svg") << "svg";
        BOOST_TEST(!fs::exists(base + ".png"));  // not before the writer has finished
    });
    BOOST_TEST(files_in() == (std::vector<std::string>{"plot-tip.svg", "plot.png"}));
    std::string text;
    std::ifstream(base + ".png") >> text;
    BOOST_TEST(text == "png");

    BOOST_CHECK_THROW(write_files_atomically(base,
                                             [&](const std::string& temporary) {
                                                 std::ofstream(temporary + ".png") << "half";
                                                 throw std::runtime_error("gnuplot failed");
                                             }),
                      std::runtime_error);
    BOOST_TEST(files_in() == (std::vector<std::string>{"plot-tip.svg", "plot.png"}));
    std::ifstream(base + ".png") >> text;
    BOOST_TEST(text == "png");
    fs::remove_all(dir);
}

// A writer that does not check its writes (gnuplot exits 0 after a write failed) leaves a file cut
// short at the file size limit: the completeness check refuses it before anything is renamed (the
// whole companion file included), names the target and the limit, and the old figures stay.
BOOST_AUTO_TEST_CASE(a_figure_cut_short_by_its_writer_is_refused_with_the_reason) {
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / "rotbeam_results_cut_short";
    fs::remove_all(dir);
    const std::string base = (dir / "plot").string();
    write_files_atomically(base, [](const std::string& temporary) {
        std::ofstream(temporary + ".png") << "old";
        std::ofstream(temporary + ".svg") << "old";
    });
    const std::string whole(10000, 'x');
    const auto is_whole = [&whole](const std::string& file) {
        std::ifstream in(file);
        std::string text;
        in >> text;
        return text == whole || text == "small";
    };
    const std::string message = output_error_under_a_4k_file_size_limit([&] {
        write_files_atomically(
            base,
            [&whole](const std::string& temporary) {
                std::ofstream(temporary + ".png") << whole;  // stops at 4096 bytes, unreported
                std::ofstream(temporary + ".svg") << "small";
            },
            is_whole);
    });
    BOOST_TEST(message.find(base + ".png: write failed") != std::string::npos, message);
    BOOST_TEST(message.find("file size limit") != std::string::npos, message);
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename());
    std::sort(names.begin(), names.end());
    BOOST_TEST(names == (std::vector<std::string>{"plot.png", "plot.svg"}));
    for (const char* suffix : {".png", ".svg"}) {
        std::string text;
        std::ifstream(base + suffix) >> text;
        BOOST_TEST(text == "old", suffix);
    }
    fs::remove_all(dir);
}

BOOST_AUTO_TEST_SUITE_END()
