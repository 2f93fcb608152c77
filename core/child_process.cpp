#include "core/child_process.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <mutex>
#include <set>

extern char** environ;

namespace rotbeam {

namespace {

// Never destroyed: stop_child_processes() keeps the lock until the process exits, and a locked
// mutex must not be destroyed by the exit handlers meanwhile.
std::mutex& children_mutex() {
    static auto* m = new std::mutex;
    return *m;
}

std::set<pid_t>& running_children() {
    static auto* pids = new std::set<pid_t>;
    return *pids;
}

}  // namespace

int run_child_process(const std::vector<std::string>& arguments, const std::string& error_path) {
    if (arguments.empty()) return -1;
    std::vector<char*> argv;
    for (const std::string& a : arguments) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, error_path.c_str(),
                                     O_WRONLY | O_CREAT | O_TRUNC, 0600);
    pid_t pid = 0;
    int spawned = 0;
    {
        // Started and registered at once: a stop either comes first (this start then waits for
        // the exit) or finds the child registered.
        const std::lock_guard<std::mutex> lock(children_mutex());
        spawned = ::posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), environ);
        if (spawned == 0) running_children().insert(pid);
    }
    posix_spawn_file_actions_destroy(&actions);
    if (spawned != 0) return -1;
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0) {
        if (errno != EINTR) {
            status = -1;
            break;
        }
    }
    const std::lock_guard<std::mutex> lock(children_mutex());
    running_children().erase(pid);
    return status;
}

void stop_child_processes() {
    // Locked for good: a child that would start after this waits until the process exits.
    children_mutex().lock();
    for (const pid_t pid : running_children()) ::kill(pid, SIGKILL);
    // Waited for here even when its own thread reaps it first (waitpid then fails with ECHILD,
    // but only once the child has ended).
    for (const pid_t pid : running_children()) {
        while (::waitpid(pid, nullptr, 0) < 0 && errno == EINTR) {
        }
    }
}

}  // namespace rotbeam
