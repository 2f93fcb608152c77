#include "core/child_process.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <mutex>
#include <set>

extern char** environ;  // POSIX: the process environment, passed on to the child

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

std::multiset<std::string>& registered_side_files() {
    static auto* files = new std::multiset<std::string>;
    return *files;
}

// rotbeam's environment with spec.environment's variables replacing those of the same name.
std::vector<std::string> child_environment(const std::vector<std::string>& replaced) {
    std::vector<std::string> environment;
    for (char** e = environ; *e != nullptr; ++e) {
        const std::string variable(*e);
        bool kept = true;
        for (const std::string& r : replaced) {
            const std::string name = r.substr(0, r.find('=') + 1);
            kept = kept && variable.rfind(name, 0) != 0;
        }
        if (kept) environment.push_back(variable);
    }
    environment.insert(environment.end(), replaced.begin(), replaced.end());
    return environment;
}

std::vector<char*> child_c_strings(std::vector<std::string>& strings) {
    std::vector<char*> p;
    for (std::string& s : strings) p.push_back(s.data());
    p.push_back(nullptr);
    return p;
}

// Started and registered at once (with its side files): a stop either comes first (this start
// then waits for the exit) or finds the child registered. 0 when it could not be started.
pid_t start_registered(const ChildSpec& spec) {
    std::vector<std::string> arguments = spec.arguments;
    std::vector<std::string> environment = child_environment(spec.environment);
    const std::vector<char*> argv = child_c_strings(arguments);
    const std::vector<char*> envp = child_c_strings(environment);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    if (!spec.output_path.empty()) {
        posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, spec.output_path.c_str(),
                                         O_WRONLY | O_CREAT | O_TRUNC, 0600);
    }
    if (!spec.error_path.empty()) {
        posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, spec.error_path.c_str(),
                                         O_WRONLY | O_CREAT | O_TRUNC, 0600);
    }
    pid_t pid = 0;
    {
        const std::lock_guard<std::mutex> lock(children_mutex());
        if (::posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), envp.data()) != 0) {
            pid = 0;
        } else {
            running_children().insert(pid);
            registered_side_files().insert(spec.side_files.begin(), spec.side_files.end());
        }
    }
    posix_spawn_file_actions_destroy(&actions);
    return pid;
}

}  // namespace

ChildExit run_child_process(const ChildSpec& spec) {
    ChildExit end;
    if (spec.arguments.empty()) return end;
    const pid_t pid = start_registered(spec);
    if (pid == 0) {
        // The file actions may have created the output files before the program was not found.
        for (const std::string& file : spec.side_files) ::unlink(file.c_str());
        return end;
    }
    while (::wait4(pid, &end.status, 0, &end.usage) < 0) {
        if (errno != EINTR) {
            end.status = -1;
            break;
        }
    }
    {
        const std::lock_guard<std::mutex> lock(children_mutex());
        running_children().erase(pid);
    }
    if (spec.read) spec.read(end);
    const std::lock_guard<std::mutex> lock(children_mutex());
    for (const std::string& file : spec.side_files) {
        ::unlink(file.c_str());
        registered_side_files().erase(registered_side_files().find(file));
    }
    return end;
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
    // Only once every child has ended: none can create its file again.
    for (const std::string& file : registered_side_files()) ::unlink(file.c_str());
}

}  // namespace rotbeam
