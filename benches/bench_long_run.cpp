#include "bench_long_run.hpp"

#include <malloc.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "core/static_driver.hpp"
#include "core/step_observer.hpp"
#include "runs/timing.hpp"
#include "studies/joined_beam_dynamics.hpp"
#include "studies/study_common.hpp"

namespace rotbeam::cli {

namespace {

constexpr int kParts = 10;          // the run is cut into tenths ("deciles") of its time span
constexpr double kTimeStep = 1e-3;  // the case's (the paper's) Δt

// One line of /proc/self/status in kB (−1 when unreadable).
long status_kb(const char* key) {
    std::ifstream f("/proc/self/status");
    std::string line;
    const std::string prefix = std::string(key) + ":";
    while (std::getline(f, line)) {
        if (line.rfind(prefix, 0) == 0) return std::atol(line.c_str() + prefix.size());
    }
    return -1;
}

// Returns freed heap to the system, then resets VmHWM to the current VmRSS (Linux ≥ 4.0), so
// that a run's peak is its own and not an earlier run's.
void reset_peak_memory() {
    malloc_trim(0);
    std::ofstream f("/proc/self/clear_refs");
    f << "5";
}

// Bytes the heap has handed out and not had back (glibc's mallinfo2: in-use chunks, main arena
// and mmapped). Growing with the steps while the resident set grows: something is kept; the
// resident set growing alone: fragmentation of freed memory.
long heap_in_use_bytes() {
    const struct mallinfo2 m = mallinfo2();
    return static_cast<long>(m.uordblks + m.hblkhd);
}

struct Memory {
    long rss_kb = -1, hwm_kb = -1;
    long steps = 0;
    long heap_bytes = -1;
    double time = 0.0;
};

// What the step observer collects: the CPU time and counts after each notification (every
// step of the fixed-step drivers, every output interval of IDA) and the memory after each tenth.
struct Probe {
    struct Sample {
        double cpu = 0.0;
        double time = 0.0;
        long steps = 0, newton = 0, jacobians = -1;
    };
    double start = 0.0, span = 1.0;
    std::vector<Sample> samples;
    std::array<Memory, kParts> memory{};
    int next_part = 0;

    static void observe(void* context, const StepProgress& p) {
        Probe& probe = *static_cast<Probe*>(context);
        probe.samples.push_back(
            {thread_cpu_seconds(), p.time, p.steps, p.newton_iterations, p.jacobian_evaluations});
        // After each tenth of the span (the last: at the end time, within round-off of t).
        while (probe.next_part < kParts &&
               p.time >=
                   probe.start + probe.span * (probe.next_part + 1) / kParts - 1e-9 * probe.span) {
            probe.memory[static_cast<size_t>(probe.next_part++)] = {
                status_kb("VmRSS"), status_kb("VmHWM"), p.steps, heap_in_use_bytes(), p.time};
        }
    }
};

// Per tenth of the run: the median CPU cost of one step over its samples (a sample's cost is
// its CPU time over the steps it made), the mean cost and Newton iterations per step.
struct Part {
    double median_step_seconds = kNoValue, mean_step_seconds = kNoValue;
    // The 10th percentile of the samples' step costs: what a step costs when other processes
    // leave it alone (on a shared VM even CPU time counts the caches and the hypervisor's
    // stolen time they cost), so it shows a trend the load would hide in the median.
    double low_step_seconds = kNoValue;
    double newton_per_step = kNoValue;
    double jacobians_per_step = kNoValue;  // where the driver counts them
    long steps = 0;
    int samples = 0;
};

std::array<Part, kParts> split_into_parts(const Probe& probe) {
    std::array<std::vector<double>, kParts> costs;
    std::array<double, kParts> cpu{}, newton{}, jacobians{};
    std::array<Part, kParts> parts{};
    for (size_t i = 1; i < probe.samples.size(); ++i) {
        const Probe::Sample& a = probe.samples[i - 1];
        const Probe::Sample& b = probe.samples[i];
        const long steps = b.steps - a.steps;
        if (steps <= 0) continue;
        // The tenth the sample ends in (its end time slightly lowered: a step ending exactly on
        // a boundary belongs to the tenth before it).
        const double f = (b.time - probe.start - 1e-9 * probe.span) / probe.span;
        const int k = std::clamp(static_cast<int>(std::floor(f * kParts)), 0, kParts - 1);
        const size_t ks = static_cast<size_t>(k);
        costs[ks].push_back((b.cpu - a.cpu) / static_cast<double>(steps));
        cpu[ks] += b.cpu - a.cpu;
        newton[ks] += static_cast<double>(b.newton - a.newton);
        jacobians[ks] +=
            a.jacobians < 0 ? kNoValue : static_cast<double>(b.jacobians - a.jacobians);
        parts[ks].steps += steps;
    }
    for (size_t k = 0; k < parts.size(); ++k) {
        if (costs[k].empty()) continue;
        const double steps = static_cast<double>(parts[k].steps);
        parts[k].samples = static_cast<int>(costs[k].size());
        parts[k].median_step_seconds = median(costs[k]);
        std::vector<double>& c = costs[k];
        const auto p10 = c.begin() + static_cast<long>(c.size() / 10);
        std::nth_element(c.begin(), p10, c.end());
        parts[k].low_step_seconds = *p10;
        parts[k].mean_step_seconds = cpu[k] / steps;
        parts[k].newton_per_step = newton[k] / steps;
        parts[k].jacobians_per_step = jacobians[k] / steps;
    }
    return parts;
}

// Spread of the tenths' median step costs (1: all equal): a trend or a jump anywhere in the run,
// not only between its ends.
double max_over_min(const std::array<Part, kParts>& parts) {
    double lo = kNoValue, hi = kNoValue;
    for (const Part& p : parts) {
        if (!std::isfinite(p.median_step_seconds)) continue;
        if (!(p.median_step_seconds >= lo)) lo = p.median_step_seconds;
        if (!(p.median_step_seconds <= hi)) hi = p.median_step_seconds;
    }
    return hi / lo;
}

// The largest total energy (kinetic + strain) of the result's outputs in the first and in the last
// tenth of [0, end]: a scheme that creates or removes energy under the forced motion shows as a
// trend between the two (a bounded forced response keeps them within its own band).
std::pair<double, double> energy_first_last_tenth(const nlohmann::json& result, double end) {
    double first = kNoValue, last = kNoValue;
    if (!result.contains("steps")) return {first, last};
    for (const nlohmann::json& step : result["steps"]) {
        if (!step.contains("energy") || !step.contains("time")) continue;
        const double t = step["time"].get<double>();
        const double e =
            step["energy"].value("kinetic", kNoValue) + step["energy"].value("strain", kNoValue);
        if (t <= 0.1 * end && !(e <= first)) first = e;
        if (t >= 0.9 * end && !(e <= last)) last = e;
    }
    return {first, last};
}

struct Variant {
    std::string label;      // e.g. "joined-beam-dead displacement/quaternion, generalized-α"
    std::string case_name;  // a catalog case with a dynamic analysis at Δt = kTimeStep
    Combination combination;
    Integrator integrator;  // automatic (the formulation's fixed step), trapezoidal, ida
    double end_time = 0.0;
    double output_interval = 0.0;        // 0: every step
    std::vector<std::string> overrides;  // further `--set`s
    double time_step = kTimeStep;        // the fixed step (not IDA's)
};

nlohmann::json run_variant(const Variant& v) {
    RunSpec spec{v.case_name, v.combination, {}, 0};
    spec.overrides.push_back("analysis.end_time=" + std::to_string(v.end_time));
    if (v.output_interval > 0.0) {
        std::ostringstream s;
        s << "analysis.output_interval=" << v.output_interval;
        spec.overrides.push_back(s.str());
    }
    if (v.integrator != Integrator::automatic)
        spec.overrides.push_back("analysis.integrator=" + std::string(choice_name(v.integrator)));
    {
        std::ostringstream s;
        s << "analysis.time_step=" << v.time_step;
        spec.overrides.push_back(s.str());
    }
    spec.overrides.insert(spec.overrides.end(), v.overrides.begin(), v.overrides.end());
    Probe probe;
    probe.span = v.end_time;
    // Room for every sample before the run starts, so that the probe's own storage is not part of
    // the growth measured (fixed steps: one per step; IDA: one per output, fewer than its steps).
    probe.samples.reserve(static_cast<size_t>(std::ceil(v.end_time / v.time_step)) + 16);
    reset_peak_memory();
    const Memory before{status_kb("VmRSS"), status_kb("VmHWM"), 0, heap_in_use_bytes()};
    nlohmann::json result;
    const auto wall_start = std::chrono::steady_clock::now();
    const double cpu_start = thread_cpu_seconds();
    {
        const ScopedStepObserver observer(&Probe::observe, &probe);
        result = run_spec(spec);
    }
    const double cpu = thread_cpu_seconds() - cpu_start;
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
    const std::array<Part, kParts> parts = split_into_parts(probe);
    const auto [energy_first, energy_last] = energy_first_last_tenth(result, v.end_time);
    const Part& first = parts.front();
    const Part& last = parts.back();
    const Memory& m1 = probe.memory.front();
    const Memory& m10 = probe.memory.back();
    const long steps = probe.samples.empty() ? 0 : probe.samples.back().steps;
    const double growth_steps = static_cast<double>(m10.steps - m1.steps);
    const double interval = v.output_interval > 0.0 ? v.output_interval : v.time_step;
    const double outputs_between = std::round((m10.time - m1.time) / interval);
    auto num = [](double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(); };
    nlohmann::json per_part = nlohmann::json::array();
    for (size_t k = 0; k < parts.size(); ++k) {
        per_part.push_back({{"median_step_seconds", num(parts[k].median_step_seconds)},
                            {"mean_step_seconds", num(parts[k].mean_step_seconds)},
                            {"low_step_seconds", num(parts[k].low_step_seconds)},
                            {"newton_per_step", num(parts[k].newton_per_step)},
                            {"jacobians_per_step", num(parts[k].jacobians_per_step)},
                            {"steps", parts[k].steps},
                            {"samples", parts[k].samples},
                            {"rss_kb_after", probe.memory[k].rss_kb},
                            {"heap_bytes_after", probe.memory[k].heap_bytes},
                            {"hwm_kb_after", probe.memory[k].hwm_kb}});
    }
    return {
        {"combination", v.label},
        {"status", result.value("status", "error")},
        {"message", result.value("message", "")},
        {"dofs", result.value("dofs", 0)},
        {"end_time", v.end_time},
        {"output_interval", v.output_interval > 0.0 ? v.output_interval : v.time_step},
        {"outputs", result.contains("steps") ? result["steps"].size() : 0},
        {"steps", steps},
        {"newton_iterations", dynamic_newton_iterations(result)},
        {"cpu_seconds", cpu},
        {"wall_seconds", wall},
        {"first_median_step_seconds", num(first.median_step_seconds)},
        {"last_median_step_seconds", num(last.median_step_seconds)},
        {"last_over_first", num(last.median_step_seconds / first.median_step_seconds)},
        {"low_last_over_first", num(last.low_step_seconds / first.low_step_seconds)},
        // The same per Newton iteration: the response, not the code, sets the iterations a step
        // needs (the undamped forced motion grows slowly).
        {"last_over_first_per_iteration", num((last.mean_step_seconds / last.newton_per_step) /
                                              (first.mean_step_seconds / first.newton_per_step))},
        {"max_over_min_median", num(max_over_min(parts))},
        {"energy_max_first_tenth", num(energy_first)},
        {"energy_max_last_tenth", num(energy_last)},
        {"first_newton_per_step", num(first.newton_per_step)},
        {"last_newton_per_step", num(last.newton_per_step)},
        {"first_jacobians_per_step", num(first.jacobians_per_step)},
        {"last_jacobians_per_step", num(last.jacobians_per_step)},
        {"rss_kb_before", before.rss_kb},
        {"rss_kb_after_first", m1.rss_kb},
        {"rss_kb_after_last", m10.rss_kb},
        {"hwm_kb_after_first", m1.hwm_kb},
        {"hwm_kb_after_last", m10.hwm_kb},
        {"growth_bytes_per_step",
         num(growth_steps > 0.0
                 ? 1024.0 * static_cast<double>(m10.rss_kb - m1.rss_kb) / growth_steps
                 : kNoValue)},
        {"heap_growth_bytes_per_step",
         num(growth_steps > 0.0 ? static_cast<double>(m10.heap_bytes - m1.heap_bytes) / growth_steps
                                : kNoValue)},
        // Per output between the same two instants: the result's history is one entry per output.
        {"heap_growth_bytes_per_output",
         num(outputs_between > 0.0
                 ? static_cast<double>(m10.heap_bytes - m1.heap_bytes) / outputs_between
                 : kNoValue)},
        {"parts", per_part}};
}

std::vector<Variant> variants(bool quick) {
    // Fixed steps: 20 000 of the case's 1 ms (quick 2 000). IDA (the case's tolerances, 1e-6)
    // takes 50–80 steps per millisecond of this response: 0.4 s is ≥ 20 000 of its steps (quick
    // 0.1 s, ~6 000: with output every 5 ms each tenth has a sample, the first serving as the
    // start); the count is printed.
    const double fixed_end = quick ? 2.0 : 20.0;
    const double ida_end = quick ? 0.1 : 0.4;
    const Combination displacement{Formulation::displacement, param::id_of<param::Quaternion>()};
    const Combination mixed{Formulation::mixed, param::id_of<param::WienerMilenkovic>()};
    // Each scheme runs twice: output at every step, and output at a coarser interval.
    struct Scheme {
        std::string case_name;
        std::string label;
        Combination combination;
        Integrator integrator;
        double end_time;
        int output_every_steps;  // of the case's Δt (kTimeStep)
        std::vector<std::string> overrides;
        double time_step = kTimeStep;
    };
    const Integrator ga = Integrator::automatic;
    const Integrator gl2 = Integrator::gauss_legendre_2;
    const Integrator gl3 = Integrator::gauss_legendre_3;
    const std::string joined = "joined-beam-dead";
    const std::string blade = "blade-mh104";
    // ρ∞ = 0.9, not the case's 1, on the joined beam: without numerical dissipation the
    // generalized-α run grows in energy until a step fails (t = 8.3 s), docs/performance.md. The
    // Gauss–Legendre schemes conserve the energy of the free motion and need no dissipation.
    const std::vector<std::string> rho09{"analysis.rho_infinity=0.9"};
    const Integrator radau = Integrator::radau_iia_3;
    const std::vector<Scheme> schemes{
        {joined, "mixed/wiener-milenkovic, Radau IIA 3", mixed, radau, fixed_end, 100, {}},
        {blade, "mixed/wiener-milenkovic, Radau IIA 3", mixed, radau, fixed_end, 100, {}},
        {joined, "displacement/quaternion, generalized-α ρ∞ 0.9", displacement, ga, fixed_end, 100,
         rho09},
        {joined,
         "displacement/quaternion, Gauss–Legendre 2",
         displacement,
         gl2,
         fixed_end,
         100,
         {}},
        // Gauss 2 also at its own accuracy's step: at the case's 1 ms it creates energy on this
        // motion and its stage iterations grow fourfold by 20 s; at 0.5 ms, the step at which it
        // reaches the joined-beam-dynamic target's 1e-3, they stay flat
        // (docs/displacement-dynamics.md, "Why Gauss–Legendre 2's stage iterations grow").
        {joined,
         "displacement/quaternion, Gauss–Legendre 2, Δt 0.5 ms",
         displacement,
         gl2,
         fixed_end,
         100,
         {},
         0.5 * kTimeStep},
        {joined,
         "displacement/quaternion, Gauss–Legendre 3",
         displacement,
         gl3,
         fixed_end,
         100,
         {}},
        {joined,
         "mixed/wiener-milenkovic, trapezoidal",
         mixed,
         Integrator::trapezoidal,
         fixed_end,
         100,
         {}},
        {joined, "mixed/wiener-milenkovic, IDA 1e-6", mixed, Integrator::ida, ida_end, 5, {}},
        {blade, "displacement/quaternion, generalized-α", displacement, ga, fixed_end, 100, {}},
        {blade, "displacement/quaternion, Gauss–Legendre 2", displacement, gl2, fixed_end, 100, {}},
        {blade, "displacement/quaternion, Gauss–Legendre 3", displacement, gl3, fixed_end, 100, {}},
        {blade,
         "mixed/wiener-milenkovic, trapezoidal",
         mixed,
         Integrator::trapezoidal,
         fixed_end,
         100,
         {}}};
    std::vector<Variant> out;
    for (const bool sparse : {false, true}) {
        for (const Scheme& s : schemes) {
            const double every = sparse ? s.output_every_steps * kTimeStep : 0.0;
            const std::string tag =
                sparse ? ", output every " + std::to_string(std::lround(every * 1e3)) + " ms" : "";
            out.push_back({s.case_name + " " + s.label + tag, s.case_name, s.combination,
                           s.integrator, s.end_time, every, s.overrides, s.time_step});
        }
    }
    return out;
}

std::string us(double seconds) {
    if (!std::isfinite(seconds)) return "—";
    std::ostringstream s;
    s << std::fixed << std::setprecision(1) << seconds * 1e6;
    return s.str();
}

std::string mb(long kb) {
    std::ostringstream s;
    s << std::fixed << std::setprecision(1) << static_cast<double>(kb) / 1024.0;
    return s.str();
}

void print_long_run_row(const nlohmann::json& r) {
    auto d = [&](const char* key) { return r[key].is_null() ? kNoValue : r[key].get<double>(); };
    auto fixed = [](double x, int digits) {
        std::ostringstream s;
        s << std::fixed << std::setprecision(digits) << x;
        return s.str();
    };
    std::cout << "  " << std::left << std::setw(88) << r["combination"].get<std::string>()
              << std::right << std::setw(8) << r["steps"].get<long>() << std::setw(10)
              << us(d("first_median_step_seconds")) << std::setw(10)
              << us(d("last_median_step_seconds")) << std::setw(7) << fixed(d("last_over_first"), 3)
              << std::setw(7) << fixed(d("low_last_over_first"), 3) << std::setw(7)
              << fixed(d("last_over_first_per_iteration"), 3) << std::setw(7)
              << fixed(d("max_over_min_median"), 3) << std::setw(12)
              << (fixed(d("first_newton_per_step"), 2) + "/" + fixed(d("last_newton_per_step"), 2))
              << std::setw(11)
              << (std::isfinite(d("first_jacobians_per_step"))
                      ? fixed(d("first_jacobians_per_step"), 2) + "/" +
                            fixed(d("last_jacobians_per_step"), 2)
                      : std::string("—"))
              << std::setw(9) << mb(r["hwm_kb_after_first"].get<long>()) << std::setw(8)
              << mb(r["hwm_kb_after_last"].get<long>()) << std::setw(8)
              << fixed(d("growth_bytes_per_step"), 0) << std::setw(8)
              << fixed(d("heap_growth_bytes_per_output"), 0) << std::setw(7)
              << fixed(r["cpu_seconds"].get<double>(), 1) << std::setw(11)
              << sci(d("energy_max_first_tenth")) << std::setw(11)
              << sci(d("energy_max_last_tenth")) << "\n";
    if (!has_solution(r["status"].get<std::string>())) {
        std::cout << "    " << r["status"].get<std::string>() << ": "
                  << r["message"].get<std::string>() << "\n";
    }
}

}  // namespace

nlohmann::json bench_long_run(bool quick) {
    std::cout
        << "long-run (joined-beam-dead and blade-mh104, paper meshes, Δt = 1 ms; cost per step "
           "over a long run: first and last tenth)\n  "
        << std::left << std::setw(88) << "combination" << std::right << std::setw(8) << "steps"
        << std::setw(10) << "first µs" << std::setw(10) << "last µs" << std::setw(7) << "ratio"
        << std::setw(7) << "p10" << std::setw(7) << "/iter" << std::setw(7) << "spread"
        << std::setw(12) << "Newton/st." << std::setw(11) << "Jac./st." << std::setw(9) << "HWM1 MB"
        << std::setw(8) << "HWM10" << std::setw(8) << "B/step" << std::setw(8) << "B/out."
        << std::setw(7) << "CPU s" << std::setw(11) << "E max 1st" << std::setw(11) << "E max 10th"
        << "\n";
    nlohmann::json rows = nlohmann::json::array();
    for (const Variant& v : variants(quick)) {
        rows.push_back(run_variant(v));
        print_long_run_row(rows.back());
        std::cout << std::flush;
    }
    std::cout
        << "  first/last µs: median CPU cost of one step in the first/last tenth of the run "
           "(IDA: per output interval / its steps); ratio: last/first; p10: the same of the "
           "tenths' 10th "
           "percentiles (less sensitive to load); /iter: the same per "
           "Newton iteration (means); Newton/st., Jac./st.: Newton iterations and Jacobian "
           "evaluations per step, first/last tenth (—: generalized-α does not count its "
           "Jacobians); spread: largest/smallest median over the ten tenths; "
           "HWM1/HWM10: VmHWM after the first/last tenth; B/step: VmRSS growth from the "
           "first to the last tenth per step (with output every step: the result's "
           "history); B/out.: the heap in use (mallinfo2) grown over the same span per "
           "output (one history entry); E max 1st/10th: the largest kinetic + strain energy [J] "
           "of the outputs in the first/last tenth of the run\n\n";
    return {{"name", "long-run"}, {"quick", quick}, {"results", rows}};
}

}  // namespace rotbeam::cli
