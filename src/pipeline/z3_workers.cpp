#include "pipeline/z3_workers.h"

#include "pipeline/workers.h"

#include "engine/algebra/forked.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <optional>
#include <stdexcept>

#include <malloc.h>
#include <poll.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

namespace impact::pipeline {
namespace {

using steady = std::chrono::steady_clock;

// Impact's side: the message `bytes` holds, once it is whole.
std::optional<std::string> whole_message(const std::string& bytes)
{
    const std::size_t line = bytes.find('\n');
    if (line == std::string::npos || line == 0 || line > 18 ||
        bytes.find_first_not_of("0123456789") != line)
        return std::nullopt;
    const std::size_t size = std::stoull(bytes.substr(0, line));
    if (bytes.size() != line + 1 + size)
        return std::nullopt;
    return bytes.substr(line + 1);
}

// A problem solved in a process of its own, forked from the worker, which has never run Z3:
// Z3 keeps state from one context to the next in a process, and what it solved before may
// change how long it takes on a problem, past any resource limit. rough_collision_frame's
// energy_never_gained was confirmed in 0.5 s, as by the `z3` command, but ran for minutes
// after the rough spheres' problem a worker happened to be given before it: which worker
// solves what depends on the problems' times, so the answer did too. The text of its
// answer, or nothing when the process ended without one.
std::optional<std::string> solved_apart(const std::string& option, const std::string& problem)
{
    int ends[2];
    if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, ends) != 0)
        return std::nullopt;
    const pid_t worker = ::getpid();
    const pid_t solver = ::fork();
    if (solver < 0) {
        ::close(ends[0]);
        ::close(ends[1]);
        return std::nullopt;
    }
    if (solver == 0) {
        ::close(ends[0]);
        engine::become_child(ends[1], worker);
        ::_exit(engine::send_message(ends[1], verify::to_text(verify::run_z3_here(option, problem))) ? 0 : 1);
    }
    ::close(ends[1]);
    std::string text;
    const bool received = engine::receive_message(ends[0], text);
    ::close(ends[0]);
    int status = 0;
    while (::waitpid(solver, &status, 0) < 0 && errno == EINTR) {
    }
    if (!received || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
        return std::nullopt;
    return text;
}

// The worker: answers each problem sent (the option, then the problem) until Impact closes
// its end, each solved apart. As the factoring child does (engine/algebra/forked.cpp):
// signals back to their default actions, none blocked, killed with Impact (and its solver
// with it), no file of Impact's kept open but the socket.
[[noreturn]] void serve(int fd, pid_t parent)
{
    engine::become_child(fd, parent);
    ::prctl(PR_SET_NAME, "impact-z3", 0, 0, 0);
    // What Z3 frees stays with the solver's process while it solves: by default glibc gives
    // back the top of its heap past 128 KB (and maps large blocks apart, to unmap them when
    // freed), and Z3 faulted the same pages in again and again.
    ::mallopt(M_MMAP_THRESHOLD, 32 << 20);
    ::mallopt(M_TRIM_THRESHOLD, 1 << 30);
    std::string option, problem;
    while (engine::receive_message(fd, option) && engine::receive_message(fd, problem)) {
        const std::optional<std::string> text = solved_apart(option, problem);
        if (!engine::send_message(fd, text ? *text : verify::to_text(verify::cut_short(false))))
            break;
    }
    ::_exit(0);
}

struct z3_worker {
    pid_t pid = -1;
    int fd = -1;
    std::optional<std::size_t> problem;   ///< the problem it is solving
    steady::time_point since;             ///< when it was sent
    std::string bytes;                    ///< of its answer, so far
};

// Forks a worker; nothing when the system refuses a process or a socket.
std::optional<z3_worker> start_worker()
{
    int fds[2];
    if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, fds) != 0)
        return std::nullopt;
    const pid_t parent = ::getpid();
    const pid_t pid = engine::locked_fork();
    if (pid < 0) {
        ::close(fds[0]);
        ::close(fds[1]);
        return std::nullopt;
    }
    if (pid == 0) {
        ::close(fds[0]);
        serve(fds[1], parent);
    }
    ::close(fds[1]);
    z3_worker w;
    w.pid = pid;
    w.fd = fds[0];
    return w;
}

void stop(z3_worker& w)
{
    ::kill(w.pid, SIGKILL);
    ::close(w.fd);
    int status = 0;
    while (::waitpid(w.pid, &status, 0) < 0 && errno == EINTR) {
    }
}

// The workers; those left at the end, or when Impact stops early (an exception), are killed
// and waited for, so that none outlives the run.
struct z3_crew {
    std::vector<z3_worker> running;
    ~z3_crew()
    {
        for (z3_worker& w : running)
            stop(w);
    }
};

double seconds_since(steady::time_point start, steady::time_point now)
{
    return std::chrono::duration<double>(now - start).count();
}

} // namespace

std::vector<verify::z3_run> run_z3_in_workers(const std::string& option, const std::vector<std::string>& problems,
                                              unsigned jobs, const std::function<void()>& finished, unsigned guard_ms,
                                              unsigned net_ms)
{
    std::vector<verify::z3_run> runs(problems.size());
    // The longest first, so that the last to finish is a short one; ties in the problems' order.
    std::vector<std::size_t> queue(problems.size());
    for (std::size_t i = 0; i < queue.size(); ++i)
        queue[i] = i;
    std::stable_sort(queue.begin(), queue.end(),
                     [&](std::size_t a, std::size_t b) { return problems[a].size() > problems[b].size(); });
    std::size_t next = 0, left = problems.size();
    const auto answered = [&](std::size_t i, verify::z3_answer answer, double seconds) {
        runs[i] = {std::move(answer), seconds};
        --left;
        if (finished)
            finished();
    };
    // A guarded problem is stopped at the guard, any other at the worker's net.
    const auto limit_of = [&](std::size_t i) {
        return std::chrono::milliseconds(verify::z3_guarded(problems[i]) ? guard_ms : net_ms);
    };
    z3_crew crew;
    while (left > 0) {
        // Each idle worker, and new ones up to `jobs`, given the next problem.
        while (next < queue.size()) {
            auto idle = std::find_if(crew.running.begin(), crew.running.end(),
                                     [](const z3_worker& w) { return !w.problem; });
            if (idle == crew.running.end() && crew.running.size() < std::max(jobs, 1u))
                if (std::optional<z3_worker> w = start_worker()) {
                    crew.running.push_back(std::move(*w));
                    idle = crew.running.end() - 1;
                }
            const std::size_t i = queue[next];
            if (idle == crew.running.end()) {
                if (!crew.running.empty())
                    break;   // another when one of those running is done
                // No process to be had: this problem here, as `run_z3` runs it.
                const steady::time_point start = steady::now();
                ++next;
                answered(i, verify::run_z3(option, problems[i]), seconds_since(start, steady::now()));
                continue;
            }
            ++next;
            idle->problem = i;
            idle->since = steady::now();
            idle->bytes.clear();
            if (!engine::send_message(idle->fd, option) || !engine::send_message(idle->fd, problems[i])) {
                // It died before it was given the problem (killed from outside): this
                // problem here, the next ones in another worker.
                stop(*idle);
                crew.running.erase(idle);
                const steady::time_point start = steady::now();
                answered(i, verify::run_z3(option, problems[i]), seconds_since(start, steady::now()));
            }
        }
        if (left == 0)
            break;
        // An answer, or the first guard to expire.
        std::vector<pollfd> watched;
        std::vector<std::size_t> busy;   // their places in crew.running
        steady::time_point deadline = steady::time_point::max();
        for (std::size_t k = 0; k < crew.running.size(); ++k) {
            const z3_worker& w = crew.running[k];
            if (!w.problem)
                continue;
            watched.push_back({w.fd, POLLIN, 0});
            busy.push_back(k);
            deadline = std::min(deadline, w.since + limit_of(*w.problem));
        }
        int wait_ms = -1;
        if (deadline != steady::time_point::max())
            wait_ms = static_cast<int>(std::max<std::chrono::milliseconds::rep>(
                0, std::chrono::ceil<std::chrono::milliseconds>(deadline - steady::now()).count()));
        if (::poll(watched.data(), watched.size(), wait_ms) < 0 && errno != EINTR)
            throw std::runtime_error(std::string("cannot wait for Z3's worker processes: ") + std::strerror(errno));
        const steady::time_point now = steady::now();
        for (std::size_t b = watched.size(); b-- > 0;) {
            const std::size_t k = busy[b];
            z3_worker& w = crew.running[k];
            const std::size_t i = *w.problem;
            if (watched[b].revents != 0) {
                char buffer[1 << 16];
                const ssize_t n = ::recv(w.fd, buffer, sizeof buffer, 0);
                if (n < 0 && errno == EINTR)
                    continue;
                if (n > 0) {
                    w.bytes.append(buffer, static_cast<std::size_t>(n));
                    if (const std::optional<std::string> text = whole_message(w.bytes)) {
                        verify::z3_answer answer;
                        if (!verify::from_text(*text, answer))
                            answer = verify::cut_short(false);
                        w.problem.reset();
                        answered(i, std::move(answer), seconds_since(w.since, now));
                    }
                    continue;
                }
                // The end of its socket: the worker died on this problem.
                answered(i, verify::cut_short(false), seconds_since(w.since, now));
            } else if (now - w.since >= limit_of(i)) {
                const auto limit = std::chrono::duration_cast<std::chrono::milliseconds>(limit_of(i)).count();
                answered(i, verify::cut_short(true, static_cast<unsigned>(limit)), seconds_since(w.since, now));
            } else {
                continue;
            }
            stop(w);
            crew.running.erase(crew.running.begin() + static_cast<std::ptrdiff_t>(k));
        }
    }
    return runs;
}

verify::z3_runner z3_runner_for(unsigned jobs)
{
    return [jobs](const std::string& option, const std::vector<std::string>& problems,
                  const std::function<void()>& finished) { return run_z3_in_workers(option, problems, jobs, finished); };
}

} // namespace impact::pipeline
