#include "progress.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "runs/time_left.hpp"

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
    : what_(std::move(what)),
      total_(total),
      out_(out),
      options_(std::move(options)),
      pooled_left_(static_cast<double>(total)) {
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

void Progress::started(const std::string& item, double cost, bool alone) {
    const std::lock_guard<std::mutex> lock(mutex_);
    running_.push_back({item, now(), costs_known_ ? cost : 1.0, alone});
    print_locked(false);
}

void Progress::finished(const std::string& item) { end(item, true); }

void Progress::skipped(const std::string& item) { end(item, false); }

void Progress::end(const std::string& item, bool worked) {
    const std::lock_guard<std::mutex> lock(mutex_);
    // An item that never started is the caller's way to say that it had nothing to do: it tells
    // nothing of the speed either, nor does one without an expected cost.
    Running r{item, now(), costs_known_ ? 0.0 : 1.0, false};
    const auto it = std::find_if(running_.begin(), running_.end(),
                                 [&](const Running& e) { return e.item == item; });
    if (it != running_.end()) {
        r = *it;
        running_.erase(it);
    } else {
        worked = false;
    }
    ++done_;
    (r.alone ? alone_left_ : pooled_left_) -= r.cost;
    if (worked && r.cost > 0.0) {
        finished_cost_ += r.cost;
        finished_seconds_ += now() - r.start;
    }
    print_locked(false);
}

void Progress::set_total_cost(double pooled_seconds, double alone_seconds) {
    const std::lock_guard<std::mutex> lock(mutex_);
    costs_known_ = true;
    pooled_left_ = pooled_seconds;
    alone_left_ = alone_seconds;
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
        s << ", running " << running_.back().item;
        if (running_.size() > 1) s << " (+" << running_.size() - 1 << " more)";
    }
    s << ", " << human_seconds(elapsed) << " elapsed, ";
    if (done_ >= total_) {
        s << "nothing left";
        return s.str();
    }
    WorkSoFar w;
    w.elapsed = elapsed;
    w.pooled_cost_left = pooled_left_;
    w.alone_cost_left = alone_left_;
    w.finished_cost = finished_cost_;
    w.finished_seconds = finished_seconds_;
    for (const Running& r : running_) w.running.push_back({r.cost, now() - r.start, r.alone});
    w.workers = options_.workers;
    w.cost_in_seconds = costs_known_;
    const std::optional<TimeLeft> left = estimate_time_left(w);
    if (!left) {
        s << "time left not yet known";
    } else {
        s << "about " << human_seconds(left->seconds) << " left"
          << (left->expected ? " (expected)" : "");
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
