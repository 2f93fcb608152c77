#include "interrupt.hpp"

#include <signal.h>
#include <unistd.h>

#include <cstring>
#include <string>
#include <thread>

#include "core/atomic_file.hpp"
#include "core/child_process.hpp"

namespace rotbeam::cli {

namespace {

constexpr int kStopSignals[] = {SIGINT, SIGTERM, SIGHUP};

bool ignored_by_parent(int signal) {
    struct sigaction current {};
    return sigaction(signal, nullptr, &current) == 0 && current.sa_handler == SIG_IGN;
}

[[noreturn]] void stop(int signal) {
    // The children first: a gnuplot still drawing would otherwise create a figure's temporary
    // after they were removed.
    stop_child_processes();
    stop_writes_and_remove_temporaries();
    const std::string line = std::string("\nrotbeam: stopped by SIG") + sigabbrev_np(signal) +
                             "; finished results are kept, no partial file was left\n";
    (void)!::write(STDERR_FILENO, line.data(), line.size());
    ::_exit(128 + signal);
}

}  // namespace

void install_interrupt_handling() {
    ::signal(SIGXFSZ, SIG_IGN);
    sigset_t set;
    sigemptyset(&set);
    for (const int s : kStopSignals) {
        if (!ignored_by_parent(s)) sigaddset(&set, s);
    }
    pthread_sigmask(SIG_BLOCK, &set, nullptr);
    std::thread([set] {
        int signal = 0;
        while (sigwait(&set, &signal) != 0) {
        }
        stop(signal);
    }).detach();
}

}  // namespace rotbeam::cli
