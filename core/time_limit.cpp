#include "core/time_limit.hpp"

#include <chrono>
#include <sstream>

namespace rotbeam {

namespace {

using Clock = std::chrono::steady_clock;

struct Limit {
    bool set = false;
    double seconds = 0.0;
    Clock::time_point deadline;
};

thread_local Limit limit;

}  // namespace

void set_time_limit(double seconds) {
    limit.set = seconds > 0.0;
    limit.seconds = seconds;
    if (limit.set) {
        limit.deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                            std::chrono::duration<double>(seconds));
    }
}

bool past_time_limit() { return limit.set && Clock::now() >= limit.deadline; }

void check_time_limit(const char* where, double value) {
    if (!past_time_limit()) return;
    std::ostringstream m;
    m << "the wall-clock limit of " << limit.seconds << " s was reached " << where << " " << value;
    throw TimeLimitReached(m.str());
}

void rethrow_with_context(const TimeLimitReached& e, const char* where, double value) {
    std::ostringstream m;
    m << e.what() << ", " << where << " " << value;
    throw TimeLimitReached(m.str());
}

}  // namespace rotbeam
