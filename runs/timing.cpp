#include "timing.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include "core/errors.hpp"

extern char** environ;  // POSIX: the process environment, passed on to the spawned child

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
// posix_spawn (glibc: clone with CLONE_VM | CLONE_VFORK), not fork: fork copies the page tables of
// this process, which the bench and the studies make large, and the copy was charged to the child
// (~3 ms of a 12.6 ms 45° bend run). A user's shell pays no such cost.
double run_child(const std::vector<std::string>& arguments, long& rss_kb, int& exit_code,
                 double& cpu_seconds) {
    const std::string rss_file = "/tmp/rotbeam-peak-rss-" + std::to_string(getpid()) + ".txt";
    std::vector<char*> argv;
    std::string self = "/proc/self/exe";
    argv.push_back(self.data());
    std::vector<std::string> copy = arguments;
    for (std::string& a : copy) argv.push_back(a.data());
    argv.push_back(nullptr);
    const std::string variable = std::string(kPeakRssVariable) + "=";
    std::vector<std::string> environment;
    for (char** e = environ; *e != nullptr; ++e) {
        if (std::string(*e).rfind(variable, 0) != 0) environment.emplace_back(*e);
    }
    environment.push_back(variable + rss_file);
    std::vector<char*> envp;
    for (std::string& e : environment) envp.push_back(e.data());
    envp.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
    const Clock::time_point start = Clock::now();
    pid_t pid = 0;
    const int spawned =
        posix_spawn(&pid, self.c_str(), &actions, nullptr, argv.data(), envp.data());
    posix_spawn_file_actions_destroy(&actions);
    if (spawned != 0) throw SolverError("timing: posix_spawn failed");
    int status = 0;
    rusage usage{};
    if (wait4(pid, &status, 0, &usage) != pid) throw SolverError("timing: wait4 failed");
    const double elapsed = seconds_since(start);
    std::ifstream reported(rss_file);
    rss_kb = 0;
    if (!(reported >> rss_kb)) rss_kb = usage.ru_maxrss;  // an older binary: the kernel's figure
    std::remove(rss_file.c_str());
    exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    cpu_seconds = static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
                  1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
    return elapsed;
}

Timing summarize(std::vector<double> samples) {
    Timing t;
    t.repeats = static_cast<int>(samples.size());
    t.min_seconds = *std::min_element(samples.begin(), samples.end());
    t.median_seconds = median(std::move(samples));
    return t;
}

}  // namespace

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
    for (int i = 0; i < std::max(1, repeats); ++i) {
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
    for (int i = 0; i < std::max(1, repeats); ++i) {
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
