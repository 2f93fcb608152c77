#include "timing.hpp"

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <thread>

#include "core/child_process.hpp"
#include "core/errors.hpp"

namespace rotbeam::cli {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

constexpr const char* kPeakRssVariable = "ROTBEAM_PEAK_RSS_FILE";

long read_vm_hwm_kb(const char* status_path) {
    std::ifstream in(status_path);
    std::string line;
    while (std::getline(in, line)) {
        if (line.rfind("VmHWM:", 0) == 0) return std::atol(line.c_str() + 6);
    }
    return 0;
}

void write_peak_rss() {
    const char* file = std::getenv(kPeakRssVariable);
    if (!file) return;
    if (std::FILE* f = std::fopen(file, "w")) {
        std::fprintf(f, "%ld\n", read_vm_hwm_kb("/proc/self/status"));
        std::fclose(f);
    }
}

// One child run: returns its wall time; sets the child's own peak RSS (reported through
// ROTBEAM_PEAK_RSS_FILE, see report_peak_rss_at_exit) and exit code. The child is started with
// posix_spawn (core/child_process.hpp; glibc: clone with CLONE_VM | CLONE_VFORK), not fork: fork
// copies the page tables of this process, which the bench and the studies make large, and the
// copy was charged to the child (~3 ms of a 12.6 ms 45° bend run). A user's shell pays no such
// cost. It is registered like every child, so a stopped bench leaves no run behind, nor its file.
double run_child(const std::vector<std::string>& arguments, long& rss_kb, int& exit_code,
                 double& cpu_seconds) {
    const std::string rss_file =
        (std::filesystem::temp_directory_path() /
         ("rotbeam-peak-rss-" + std::to_string(getpid()) + "-" +
          std::to_string(std::hash<std::thread::id>()(std::this_thread::get_id())) + ".txt"))
            .string();
    ChildSpec child;
    child.arguments = {"/proc/self/exe"};
    child.arguments.insert(child.arguments.end(), arguments.begin(), arguments.end());
    child.output_path = child.error_path = "/dev/null";
    child.environment = {std::string(kPeakRssVariable) + "=" + rss_file};
    child.side_files = {rss_file};
    Clock::time_point end;
    rss_kb = 0;
    child.read = [&](const ChildExit& e) {
        end = Clock::now();
        std::ifstream reported(rss_file);
        if (!(reported >> rss_kb)) rss_kb = e.usage.ru_maxrss;  // an older binary: the kernel's
    };
    const Clock::time_point start = Clock::now();
    const ChildExit e = run_child_process(child);
    if (e.status == -1) throw SolverError("timing: the rotbeam child could not be started");
    exit_code = WIFEXITED(e.status) ? WEXITSTATUS(e.status) : 128 + WTERMSIG(e.status);
    cpu_seconds = static_cast<double>(e.usage.ru_utime.tv_sec + e.usage.ru_stime.tv_sec) +
                  1e-6 * static_cast<double>(e.usage.ru_utime.tv_usec + e.usage.ru_stime.tv_usec);
    return std::chrono::duration<double>(end - start).count();
}

Timing summarize(std::vector<double> samples) {
    Timing t;
    t.repeats = static_cast<int>(samples.size());
    t.min_seconds = *std::min_element(samples.begin(), samples.end());
    t.median_seconds = median(std::move(samples));
    return t;
}

}  // namespace

int timing_repeats(int wanted) {
    const int at_least_one = std::max(1, wanted);
    const char* text = std::getenv("ROTBEAM_TIMING_REPEATS");
    if (text == nullptr) return at_least_one;
    int cap = 0;
    const char* end = text + std::strlen(text);
    const auto [stop, error] = std::from_chars(text, end, cap);
    if (error != std::errc() || stop != end || cap < 1) {
        throw InputError(
            std::string("ROTBEAM_TIMING_REPEATS: '") + text +
            "' is not a positive integer (the most timed repeats a measurement makes)");
    }
    return std::min(at_least_one, cap);
}

double median(std::vector<double> samples) {
    ROTBEAM_VERIFY(!samples.empty(), "median of no samples");
    const size_t n = samples.size();
    std::nth_element(samples.begin(), samples.begin() + n / 2, samples.end());
    const double upper = samples[n / 2];
    if (n % 2 == 1) return upper;
    const double lower = *std::max_element(samples.begin(), samples.begin() + n / 2);
    return 0.5 * (lower + upper);
}

void report_peak_rss_at_exit() {
    if (std::getenv(kPeakRssVariable)) std::atexit(write_peak_rss);
}

long peak_rss_self_kb() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_maxrss;
}

Timing time_in_process(const std::function<void()>& work, int repeats, double budget_seconds) {
    std::vector<double> samples;
    const Clock::time_point begin = Clock::now();
    const int count = timing_repeats(repeats);
    for (int i = 0; i < count; ++i) {
        const Clock::time_point start = Clock::now();
        work();
        samples.push_back(seconds_since(start));
        if (budget_seconds > 0.0 && seconds_since(begin) > budget_seconds) break;
    }
    Timing t = summarize(std::move(samples));
    t.peak_rss_kb = peak_rss_self_kb();
    return t;
}

Timing time_whole_process(const std::vector<std::string>& arguments, int repeats,
                          double budget_seconds) {
    std::vector<double> samples, cpu;
    long peak = 0;
    int exit_code = 0;
    const Clock::time_point begin = Clock::now();
    const int count = timing_repeats(repeats);
    for (int i = 0; i < count; ++i) {
        long rss = 0;
        double cpu_seconds = 0.0;
        samples.push_back(run_child(arguments, rss, exit_code, cpu_seconds));
        cpu.push_back(cpu_seconds);
        peak = std::max(peak, rss);
        if (budget_seconds > 0.0 && seconds_since(begin) > budget_seconds) break;
    }
    Timing t = summarize(std::move(samples));
    t.median_cpu_seconds = median(std::move(cpu));
    t.peak_rss_kb = peak;
    t.exit_code = exit_code;
    return t;
}

}  // namespace rotbeam::cli
