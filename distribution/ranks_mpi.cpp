// The ranks of `mpirun -np N rotbeam-mpi ...` sharing a job's units (ranks.hpp). Rank 0 holds the
// queue, the units in decreasing expected time; a worker thread of any other rank asks rank 0 for
// its next one as it starts a unit, sending the unit it has just finished (for rank 0's progress
// line). Rank 0's own
// worker threads take from the queue directly, and one extra thread of rank 0 answers the requests,
// so rank 0 computes like every other rank.
//
// Every wait here is MPI_Test and a 1 ms sleep, never a blocking call: Open MPI's blocking calls
// poll a core at 100 %, which on a machine with as many ranks as cores would take that core from a
// rank that computes. A request is answered within ~1 ms; a unit takes 10 ms to minutes.
//
// Threads: only one thread calls MPI at a time (MPI_THREAD_SERIALIZED): on rank 0 the answering
// thread (the main thread waits for it before its own MPI calls), on the other ranks the worker
// that holds the request lock.
#include <mpi.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <iostream>
#include <mutex>
#include <numeric>
#include <thread>

#include "core/atomic_file.hpp"
#include "core/errors.hpp"
#include "distribution/merge.hpp"
#include "distribution/ranks.hpp"
#include "runs/progress.hpp"

namespace rotbeam::cli {

namespace fs = std::filesystem;

namespace {

constexpr int kRequestTag = 1, kDoneTag = 2, kReplyTag = 3;  // reply: kReplyTag + thread
constexpr long long kNoUnit = -1;  // a request before the first unit; the answer "no more units"

void wait_quietly(MPI_Request& request, MPI_Status* status) {
    for (int done = 0;;) {
        MPI_Test(&request, &done, status);
        if (done) return;
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
}

void barrier_quietly() {
    MPI_Request request;
    MPI_Ibarrier(MPI_COMM_WORLD, &request);
    wait_quietly(request, MPI_STATUS_IGNORE);
}

// One line naming the rank and the error, then every rank stops with main's exit code for it.
[[noreturn]] void abort_ranks(int rank, std::exception_ptr error) {
    int code = 3;
    try {
        std::rethrow_exception(error);
    } catch (const InputError& e) {
        std::cerr << e.what() << " (rank " << rank << ")\n";
        code = 2;
    } catch (const OutputError& e) {
        std::cerr << "rotbeam: " << e.what() << " (rank " << rank << ")\n";
        code = 4;
    } catch (const std::exception& e) {
        std::cerr << "rotbeam: internal error: " << e.what() << " (rank " << rank << ")\n";
    }
    MPI_Abort(MPI_COMM_WORLD, code);
    std::_Exit(code);  // MPI_Abort does not return; this says so to the compiler
}

// What one rank knows: the plan, the queue (pooled units, longest expected first), its settings.
struct Ranks {
    const JobPlan& plan;
    const std::vector<double>& expected;
    const std::vector<size_t>& queue;
    const ShardSettings& settings;
    int rank = 0, size = 1;
};

// Rank 0: its worker threads and the thread that answers the other ranks' messages: a request
// {finished unit or kNoUnit, thread} is answered with the next unit (kNoUnit when none is left)
// under the tag kReplyTag + thread; a last message {finished unit} under kDoneTag says that a
// thread has ended.
void serve_and_work(const Ranks& r, Progress& progress) {
    std::atomic<size_t> next{0};
    const auto take = [&]() -> long long {
        const size_t k = next++;
        return k < r.queue.size() ? static_cast<long long>(r.queue[k]) : kNoUnit;
    };
    const auto finished = [&](long long unit) {
        if (unit == kNoUnit) return;
        const auto i = static_cast<size_t>(unit);
        progress.finished(r.plan.units[i].label);
    };
    std::thread answering([&] {
        try {
            const long long workers = static_cast<long long>(r.size - 1) * r.settings.jobs;
            for (long long ended = 0; ended < workers;) {
                long long message[2] = {kNoUnit, 0};
                MPI_Request request;
                MPI_Status status;
                MPI_Irecv(message, 2, MPI_LONG_LONG, MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD,
                          &request);
                wait_quietly(request, &status);
                finished(message[0]);
                if (status.MPI_TAG == kDoneTag) {
                    ++ended;
                    continue;
                }
                long long unit = take();
                if (unit != kNoUnit) progress.started(r.plan.units[unit].label, r.expected[unit]);
                MPI_Send(&unit, 1, MPI_LONG_LONG, status.MPI_SOURCE,
                         kReplyTag + static_cast<int>(message[1]), MPI_COMM_WORLD);
            }
        } catch (...) {
            abort_ranks(0, std::current_exception());
        }
    });
    std::vector<std::thread> pool;
    for (int t = 0; t < r.settings.jobs; ++t) {
        pool.emplace_back([&] {
            try {
                for (long long unit = take(); unit != kNoUnit; unit = take()) {
                    const Unit& u = r.plan.units[unit];
                    progress.started(u.label, r.expected[unit]);
                    make_unit(r.plan, u, r.settings);
                    progress.finished(u.label);
                }
            } catch (...) {
                abort_ranks(0, std::current_exception());
            }
        });
    }
    for (std::thread& t : pool) t.join();
    answering.join();
}

// A rank above 0: worker threads asking rank 0 for units until it has none left. Each asks for
// its next unit when it starts one, so the answer travels while it computes (under a loaded
// machine a round trip of two 1 ms polls takes tens of ms, as long as a small unit).
void ask_and_work(const Ranks& r) {
    std::mutex mpi;
    std::vector<std::thread> pool;
    for (int t = 0; t < r.settings.jobs; ++t) {
        pool.emplace_back([&, t] {
            try {
                const auto ask = [&](long long finished, long long& unit, MPI_Request& reply) {
                    const std::lock_guard<std::mutex> lock(mpi);
                    long long message[2] = {finished, t};
                    MPI_Send(message, 2, MPI_LONG_LONG, 0, kRequestTag, MPI_COMM_WORLD);
                    MPI_Irecv(&unit, 1, MPI_LONG_LONG, 0, kReplyTag + t, MPI_COMM_WORLD, &reply);
                };
                const auto wait = [&](MPI_Request& reply) {
                    for (int done = 0;;) {
                        {
                            const std::lock_guard<std::mutex> lock(mpi);
                            MPI_Test(&reply, &done, MPI_STATUS_IGNORE);
                        }
                        if (done) return;
                        std::this_thread::sleep_for(std::chrono::milliseconds(1));
                    }
                };
                long long unit = kNoUnit, previous = kNoUnit;
                MPI_Request reply;
                ask(kNoUnit, unit, reply);
                wait(reply);
                while (unit != kNoUnit) {
                    long long next = kNoUnit;
                    ask(previous, next, reply);  // `previous` has finished, `unit` starts
                    make_unit(r.plan, r.plan.units[unit], r.settings);
                    previous = unit;
                    wait(reply);
                    unit = next;
                }
                const std::lock_guard<std::mutex> lock(mpi);
                long long message[2] = {previous, t};
                MPI_Send(message, 2, MPI_LONG_LONG, 0, kDoneTag, MPI_COMM_WORLD);
            } catch (...) {
                abort_ranks(r.rank, std::current_exception());
            }
        });
    }
    for (std::thread& t : pool) t.join();
}

}  // namespace

int launched_ranks(const std::string&) {
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"}) {
        if (const char* value = std::getenv(name)) return std::max(1, std::atoi(value));
    }
    return 1;
}

std::string mpi_description() {
    char version[MPI_MAX_LIBRARY_VERSION_STRING];
    int length = 0;
    MPI_Get_library_version(version, &length);
    std::string text(version, static_cast<size_t>(length));
    text = text.substr(0, text.find_first_of(",\n"));  // "Open MPI v4.1.4, package: ..." → name
    return "MPI: " + text;
}

int run_over_ranks(const Job& job, const ShardSettings& given) {
    ShardSettings s = given;
    const std::string out = s.dir;
    s.dir = (fs::path(out) / ".rotbeam-ranks").string();
    s.shard = {1, 1};
    // An earlier output in DIR times the units when no --timings is given.
    if (s.timings.empty()) s.timings = {out};
    // Planned before MPI starts: bad input stops every rank with its one line and exit 2.
    const JobPlan plan = plan_job(job, s.dir);
    const std::vector<double> expected = expected_unit_seconds(plan, s.timings);
    std::vector<size_t> queue, alone;
    for (size_t i = 0; i < plan.units.size(); ++i)
        (plan.units[i].timed ? alone : queue).push_back(i);
    std::stable_sort(queue.begin(), queue.end(),
                     [&](size_t a, size_t b) { return expected[a] > expected[b]; });

    int provided = 0;
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_SERIALIZED, &provided);
    int rank = 0, size = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    int code = 0;
    try {
        if (provided < MPI_THREAD_SERIALIZED)
            throw std::runtime_error("the MPI library offers no MPI_THREAD_SERIALIZED");
        const Ranks r{plan, expected, queue, s, rank, size};
        const std::string what = "rotbeam " + job.command;
        if (rank == 0) {
            fs::create_directories(s.dir);
            remove_stale_temporaries(s.dir);
            std::cout << what << ": " << plan.units.size() << " units on " << size << " ranks × "
                      << s.jobs << " threads, expected "
                      << human_seconds(std::accumulate(expected.begin(), expected.end(), 0.0))
                      << " of CPU → " << out << "\n";
        }
        barrier_quietly();  // the work folder exists before any rank writes into it
        if (rank == 0) {
            Progress progress(what, queue.size(), std::cerr, progress_options_for_stderr());
            double cost = 0.0;
            for (const size_t i : queue) cost += expected[i];
            progress.set_total_cost(cost);
            serve_and_work(r, progress);
        } else {
            ask_and_work(r);
        }
        barrier_quietly();  // every pooled unit is made
        if (rank == 0) {
            for (const size_t i : alone) make_unit(plan, plan.units[i], s);  // timed: alone
            std::vector<size_t> all(plan.units.size());
            std::iota(all.begin(), all.end(), size_t{0});
            write_shard_manifest(plan, s, all);
            code = merge_shard_folders({s.dir}, out);
            if (code == 0) fs::remove_all(s.dir);
        }
        barrier_quietly();  // the other ranks do not spin in MPI_Finalize while rank 0 works
    } catch (...) {
        abort_ranks(rank, std::current_exception());
    }
    MPI_Finalize();
    return code;
}

}  // namespace rotbeam::cli
