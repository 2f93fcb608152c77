#include "core/atomic_file.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <set>
#include <vector>

#include "core/errors.hpp"

namespace rotbeam {

namespace fs = std::filesystem;

namespace {

// Temporaries are hidden files next to their target: ".NAME.rotbeam-tmp.PID.N".
constexpr const char* kTemporaryMarker = ".rotbeam-tmp.";

std::mutex& in_flight_mutex() {
    static std::mutex m;
    return m;
}

std::set<std::string>& in_flight() {
    static std::set<std::string> paths;
    return paths;
}

fs::path temporary_for(const fs::path& target) {
    static std::atomic<unsigned long> counter{0};
    // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on "literal" + std::string&&.
    std::string name = ".";
    name += target.filename().string();
    name += kTemporaryMarker;
    name += std::to_string(static_cast<long>(::getpid()));
    name += ".";
    name += std::to_string(counter++);
    return target.parent_path() / name;
}

std::string reason(int error) {
    if (error == ENOSPC) return "no space left on the device";
    if (error == EFBIG) return "file too large (file size limit, ulimit -f)";
    return std::strerror(error);
}

// Writes all of `text` to `fd`, then fsync; returns 0 or the errno of the first failure.
int write_all(int fd, const std::string& text) {
    const char* p = text.data();
    size_t left = text.size();
    while (left > 0) {
        const ssize_t n = ::write(fd, p, left);
        if (n < 0) {
            if (errno == EINTR) continue;
            return errno;
        }
        p += n;
        left -= static_cast<size_t>(n);
    }
    if (::fsync(fd) != 0) return errno;
    return 0;
}

// Makes the rename itself durable. A directory that cannot be opened or synced (some file
// systems refuse) does not make the file incomplete, so this is best effort.
void sync_directory(const fs::path& directory) {
    const int fd = ::open(directory.empty() ? "." : directory.c_str(), O_RDONLY | O_DIRECTORY);
    if (fd < 0) return;
    ::fsync(fd);
    ::close(fd);
}

// The files in `temporary`'s directory whose name starts with its name: the files written under a
// temporary base (write_files_atomically), in name order.
std::vector<fs::path> with_prefix(const fs::path& temporary) {
    std::vector<fs::path> files;
    const std::string prefix = temporary.filename().string();
    const fs::path directory = temporary.has_parent_path() ? temporary.parent_path() : ".";
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(directory, ec)) {
        if (entry.path().filename().string().rfind(prefix, 0) == 0) files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());
    return files;
}

// Why another program's file came out cut short: the file size limit it reached (EFBIG), a full
// disk (no block left for an unprivileged writer), else the writer's own failure.
std::string incomplete_file_reason(const fs::path& file) {
    struct rlimit limit {};
    struct stat status {};
    if (::getrlimit(RLIMIT_FSIZE, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY &&
        ::stat(file.c_str(), &status) == 0 &&
        static_cast<rlim_t>(status.st_size) >= limit.rlim_cur) {
        return reason(EFBIG);
    }
    struct statvfs disk {};
    const fs::path directory = file.has_parent_path() ? file.parent_path() : ".";
    if (::statvfs(directory.c_str(), &disk) == 0 && disk.f_bavail == 0) return reason(ENOSPC);
    return "cut short by the program that wrote it";
}

void remove_with_prefix(const fs::path& temporary) {
    for (const fs::path& file : with_prefix(temporary)) ::unlink(file.c_str());
}

class InFlight {
  public:
    explicit InFlight(const std::string& path) : path_(path) {
        std::lock_guard<std::mutex> lock(in_flight_mutex());
        in_flight().insert(path_);
    }
    // The same, creating the temporary file under the lock: a stop either comes first (this
    // write then waits for the exit) or finds the file there to remove. Sets `fd` and, when the
    // file could not be created, `error`.
    InFlight(const std::string& path, int& fd, int& error) : path_(path) {
        std::lock_guard<std::mutex> lock(in_flight_mutex());
        in_flight().insert(path_);
        fd = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
        error = fd < 0 ? errno : 0;
    }
    ~InFlight() {
        std::lock_guard<std::mutex> lock(in_flight_mutex());
        in_flight().erase(path_);
    }
    InFlight(const InFlight&) = delete;
    InFlight& operator=(const InFlight&) = delete;

  private:
    std::string path_;
};

}  // namespace

void write_file_atomically(const std::string& path, const std::string& text) {
    const fs::path target(path);
    if (target.has_parent_path()) {
        std::error_code ec;
        fs::create_directories(target.parent_path(), ec);
        if (ec) throw OutputError(path + ": cannot create the directory: " + ec.message());
    }
    const fs::path temporary = temporary_for(target);
    int fd = -1;
    int error = 0;
    const InFlight guard(temporary.string(), fd, error);
    if (fd < 0) throw OutputError(path + ": cannot write: " + reason(error));
    error = write_all(fd, text);
    if (::close(fd) != 0 && error == 0) error = errno;
    if (error == 0 && ::rename(temporary.c_str(), target.c_str()) != 0) error = errno;
    if (error != 0) {
        ::unlink(temporary.c_str());
        throw OutputError(path + ": write failed, nothing written: " + reason(error));
    }
    sync_directory(target.parent_path());
}

void write_files_atomically(const std::string& target_base,
                            const std::function<void(const std::string& temporary_base)>& write,
                            const std::function<bool(const std::string& file)>& complete) {
    const fs::path target(target_base);
    if (target.has_parent_path()) {
        std::error_code ec;
        fs::create_directories(target.parent_path(), ec);
        if (ec) throw OutputError(target_base + ": cannot create the directory: " + ec.message());
    }
    // Ended by '_', so that the files of ".NAME.rotbeam-tmp.PID.1_" are not taken for those of
    // ".NAME.rotbeam-tmp.PID.12_".
    const fs::path temporary = temporary_for(target).string() + "_";
    const InFlight guard(temporary.string());
    try {
        write(temporary.string());
    } catch (...) {
        remove_with_prefix(temporary);
        throw;
    }
    const std::vector<fs::path> files = with_prefix(temporary);
    const auto final_path_of = [&](const fs::path& file) {
        return target_base + file.filename().string().substr(temporary.filename().string().size());
    };
    for (const fs::path& file : complete ? files : std::vector<fs::path>{}) {
        if (!complete(file.string())) {
            const std::string why = incomplete_file_reason(file);
            remove_with_prefix(temporary);
            throw OutputError(final_path_of(file) + ": write failed, nothing written: " + why);
        }
    }
    int error = 0;
    std::string failed;
    for (const fs::path& file : files) {
        const std::string final_path = final_path_of(file);
        const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
        if (fd < 0 || ::fsync(fd) != 0) error = errno;
        if (fd >= 0) ::close(fd);
        if (error == 0) {
            // Under the lock: once the program is stopping, no figure appears any more.
            const std::lock_guard<std::mutex> lock(in_flight_mutex());
            if (::rename(file.c_str(), final_path.c_str()) != 0) error = errno;
        }
        if (error != 0) {
            failed = final_path;
            break;
        }
    }
    if (error != 0) {
        remove_with_prefix(temporary);
        throw OutputError(failed + ": write failed, nothing written: " + reason(error));
    }
    sync_directory(target.parent_path());
}

void stop_writes_and_remove_temporaries() {
    // Locked for good: a write that starts after this blocks until the process exits.
    in_flight_mutex().lock();
    for (const std::string& p : in_flight()) {
        ::unlink(p.c_str());
        remove_with_prefix(p);  // the files of a figure's writer
    }
}

int remove_stale_temporaries(const std::string& directory) {
    std::vector<fs::path> stale;
    std::error_code ec;
    for (const auto& entry : fs::recursive_directory_iterator(directory, ec)) {
        const std::string name = entry.path().filename().string();
        const size_t at = name.find(kTemporaryMarker);
        if (at == std::string::npos || name.front() != '.') continue;
        const std::string rest = name.substr(at + std::strlen(kTemporaryMarker));
        char* end = nullptr;
        const long pid = std::strtol(rest.c_str(), &end, 10);
        if (end == rest.c_str() || *end != '.') continue;
        // A live process (this one, or another rotbeam writing into the same folder) keeps its
        // temporaries.
        if (::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH) continue;
        stale.push_back(entry.path());
    }
    int removed = 0;
    for (const fs::path& p : stale) removed += fs::remove(p, ec) ? 1 : 0;
    return removed;
}

}  // namespace rotbeam
