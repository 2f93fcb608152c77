#include "progress.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace rotbeam::cli {

namespace {

// The terminal ticker's period: often enough for a live clock, rarely enough to cost nothing.
constexpr auto kTick = std::chrono::seconds(1);

}  // namespace

ProgressOptions progress_options_for_stderr() {
    ProgressOptions o;
    o.terminal = isatty(STDERR_FILENO) != 0;
    o.clock = [] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
            .count();
    };
    return o;
}

std::string human_seconds(double seconds) {
    const long s = std::lround(std::max(0.0, seconds));
    char text[32];
    if (s < 60) {
        std::snprintf(text, sizeof text, "%ld s", s);
    } else if (s < 3600) {
        std::snprintf(text, sizeof text, "%ld min %02ld s", s / 60, s % 60);
    } else {
        std::snprintf(text, sizeof text, "%ld h %02ld min", s / 3600, (s % 3600) / 60);
    }
    return text;
}

Progress::Progress(std::string what, size_t total, std::ostream& out, ProgressOptions options)
    : what_(std::move(what)), total_(total), out_(out), options_(std::move(options)) {
    if (!options_.clock) options_.clock = progress_options_for_stderr().clock;
    start_ = now();
    if (options_.ticker) {
        ticker_ = std::thread([this] {
            std::unique_lock<std::mutex> lock(mutex_);
            while (!stop_signal_.wait_for(lock, kTick, [this] { return stopping_; })) {
                print_locked(false);
            }
        });
    }
}

Progress::~Progress() {
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        stopping_ = true;
    }
    stop_signal_.notify_all();
    if (ticker_.joinable()) ticker_.join();
    const std::lock_guard<std::mutex> lock(mutex_);
    if (options_.terminal && last_print_ >= 0.0) {
        print_locked(true);
        out_ << "\n" << std::flush;
    }
}

double Progress::now() const { return options_.clock(); }

void Progress::started(const std::string& item) {
    const std::lock_guard<std::mutex> lock(mutex_);
    running_.push_back(item);
    print_locked(false);
}

void Progress::finished(const std::string& item, double cost) {
    const std::lock_guard<std::mutex> lock(mutex_);
    const auto it = std::find(running_.begin(), running_.end(), item);
    if (it != running_.end()) running_.erase(it);
    ++done_;
    cost_done_ += cost;
    print_locked(false);
}

void Progress::set_total_cost(double cost) {
    const std::lock_guard<std::mutex> lock(mutex_);
    total_cost_ = cost;
}

void Progress::poll() {
    const std::lock_guard<std::mutex> lock(mutex_);
    print_locked(false);
}

std::string Progress::line() const {
    const std::lock_guard<std::mutex> lock(mutex_);
    return line_locked();
}

std::string Progress::line_locked() const {
    const double elapsed = now() - start_;
    std::ostringstream s;
    s << what_ << ": " << done_ << "/" << total_ << " done";
    if (!running_.empty()) {
        // The most recently started item is the current one; the others are counted.
        s << ", running " << running_.back();
        if (running_.size() > 1) s << " (+" << running_.size() - 1 << " more)";
    }
    s << ", " << human_seconds(elapsed) << " elapsed, ";
    if (done_ >= total_) {
        s << "nothing left";
    } else if (done_ == 0 && total_cost_ > elapsed) {
        // Nothing finished yet: the caller's expected cost (in seconds) is all there is.
        s << "about " << human_seconds(total_cost_ - elapsed) << " left (expected)";
    } else if (done_ == 0) {
        s << "time left not yet known";
    } else {
        const bool by_cost = total_cost_ > 0.0 && cost_done_ > 0.0;
        const double left =
            by_cost ? elapsed * (total_cost_ - cost_done_) / cost_done_
                    : elapsed / static_cast<double>(done_) * static_cast<double>(total_ - done_);
        s << "about " << human_seconds(left) << " left";
    }
    return s.str();
}

void Progress::print_locked(bool force) {
    const double t = now();
    if (options_.terminal) {
        // \r and "clear to the end of the line" (ECMA-48 EL): the line is redrawn in place; the
        // cursor goes back to its start, so that a line the command prints meanwhile on stdout
        // starts at the left margin instead of after the progress text.
        out_ << "\r" << line_locked() << "\033[K\r" << std::flush;
        last_print_ = t;
        return;
    }
    if (!force && last_print_ >= 0.0 && t - last_print_ < options_.interval_seconds) return;
    out_ << line_locked() << "\n" << std::flush;
    last_print_ = t;
}

}  // namespace rotbeam::cli
