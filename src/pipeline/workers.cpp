#include "pipeline/workers.h"

#include "spec/error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <thread>

#include <fcntl.h>
#include <poll.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

namespace impact::pipeline {
namespace {

// What a worker sends back: its kind ("text", "error", "failure"), then fields, each
// written with its length in front (`5:hello\n`), so that a worker that died part way
// is told from one that finished.
std::string field(const std::string& s)
{
    return fmt::format("{}:{}\n", s.size(), s);
}

struct fields_reader {
    const std::string& in;
    std::size_t at = 0;
    std::optional<std::string> next()
    {
        const std::size_t colon = in.find(':', at);
        if (colon == std::string::npos || colon == at || colon - at > 15)
            return std::nullopt;
        const std::string digits = in.substr(at, colon - at);
        if (digits.find_first_not_of("0123456789") != std::string::npos)
            return std::nullopt;
        const std::size_t n = std::strtoull(digits.c_str(), nullptr, 10);
        if (colon + 1 + n >= in.size() || in[colon + 1 + n] != '\n')
            return std::nullopt;
        std::string s = in.substr(colon + 1, n);
        at = colon + 2 + n;
        return s;
    }
};

bool write_all(int fd, const std::string& bytes)
{
    for (std::size_t at = 0; at < bytes.size();) {
        const ssize_t n = ::write(fd, bytes.data() + at, bytes.size() - at);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            return false;
        at += static_cast<std::size_t>(n);
    }
    return true;
}

// The child's side: runs the task and sends what came of it.
[[noreturn]] void be_worker(const engine::text_task& task, int fd)
{
    std::string message;
    try {
        message = field("text") + field(task.run());
    } catch (const error& e) {
        message = field("error") + field(e.where().file) + field(std::to_string(e.where().line)) +
                  field(std::to_string(e.where().column)) + field(e.message());
    } catch (const std::exception& e) {
        message = field("failure") + field(e.what());
    } catch (...) {
        message = field("failure") + field("an unknown exception");
    }
    // _exit: no static destructors or atexit handlers of the parent's run here, and no
    // buffered output of the parent's written twice; the factoring child it may have
    // started is stopped first, so that none is left behind as a zombie.
    const bool sent = write_all(fd, message);
    engine::stop_factoring();
    ::_exit(sent ? 0 : 3);
}

// What came of one task: its text, or the exception to throw for it.
struct outcome {
    std::string text;
    std::exception_ptr failed;
};

// `process` names the child in a message about its death ("the worker process choosing
// its forms"), and `advice` follows it.
outcome read_outcome(const engine::text_task& task, const std::string& bytes, int status,
                     const std::string& process, const std::string& advice = "")
{
    auto died = [&](const std::string& how) {
        return outcome{{}, std::make_exception_ptr(
                               error(task.where, fmt::format("{}: {} {}{}", task.what, process, how, advice)))};
    };
    if (WIFSIGNALED(status))
        return died(fmt::format("was killed by signal {} ({})", WTERMSIG(status), ::strsignal(WTERMSIG(status))));
    fields_reader r{bytes};
    const auto kind = r.next();
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || !kind)
        return died(fmt::format("ended (status {}) without sending its result", WIFEXITED(status)
                                                                                   ? WEXITSTATUS(status)
                                                                                   : -1));
    if (*kind == "text") {
        if (auto text = r.next(); text && r.at == bytes.size())
            return {std::move(*text), nullptr};
    } else if (*kind == "error") {
        const auto file = r.next(), line = r.next(), column = r.next(), message = r.next();
        if (message && r.at == bytes.size()) {
            const source_location where{*file, static_cast<std::uint32_t>(std::strtoul(line->c_str(), nullptr, 10)),
                                        static_cast<std::uint32_t>(std::strtoul(column->c_str(), nullptr, 10))};
            return {{}, std::make_exception_ptr(error(where, *message))};
        }
    } else if (*kind == "failure") {
        if (const auto message = r.next(); message && r.at == bytes.size())
            return {{}, std::make_exception_ptr(std::runtime_error(*message))};
    }
    return died("sent back a result that is not whole");
}

struct worker {
    std::size_t task;
    pid_t pid;
    int fd;
    std::string bytes;
    bool stopped = false;   ///< killed: its task comes after one that failed
};

// The workers running; those left when the parent stops early (an error, an exception)
// are killed and waited for, so that none outlives the run.
struct crew {
    std::vector<worker> running;
    ~crew()
    {
        for (worker& w : running) {
            ::kill(w.pid, SIGKILL);
            ::close(w.fd);
            int status = 0;
            while (::waitpid(w.pid, &status, 0) < 0 && errno == EINTR) {
            }
        }
    }
};

// Forks a worker for `task`; nothing when the system refuses a process or a pipe.
std::optional<worker> start(const engine::text_task& task, std::size_t index)
{
    int fds[2];
    // Close-on-exec: a pdflatex the report's thread starts meanwhile does not hold the
    // pipe open (the parent would wait for it to see the worker's end).
    if (::pipe2(fds, O_CLOEXEC) != 0)
        return std::nullopt;
    const pid_t pid = engine::locked_fork();
    if (pid < 0) {
        ::close(fds[0]);
        ::close(fds[1]);
        return std::nullopt;
    }
    if (pid == 0) {
        ::close(fds[0]);
        // Named apart from Impact itself and from the report's pdflatex (whose shell is
        // forked from Impact too, named `impact` until it runs): `ps` and `top` show
        // `impact-worker`.
        ::prctl(PR_SET_NAME, "impact-worker", 0, 0, 0);
        be_worker(task, fds[1]);
    }
    ::close(fds[1]);
    return worker{index, pid, fds[0], {}, false};
}

} // namespace

unsigned default_jobs()
{
    return std::max(1u, std::thread::hardware_concurrency());
}

std::vector<std::string> run_in_workers(const std::vector<engine::text_task>& tasks, unsigned jobs,
                                        const std::function<void()>& finished)
{
    std::vector<std::string> texts(tasks.size());
    if (jobs <= 1 || tasks.size() <= 1) {
        for (std::size_t i = 0; i < tasks.size(); ++i) {
            texts[i] = tasks[i].run();
            if (finished)
                finished();
        }
        return texts;
    }
    std::vector<outcome> outcomes(tasks.size());
    // The costliest first, so that the last to finish is a short one; ties in the tasks' order.
    std::vector<std::size_t> queue(tasks.size());
    for (std::size_t i = 0; i < queue.size(); ++i)
        queue[i] = i;
    std::stable_sort(queue.begin(), queue.end(),
                     [&](std::size_t a, std::size_t b) { return tasks[a].cost > tasks[b].cost; });
    std::size_t next = 0;
    std::size_t first_failure = tasks.size();
    crew workers;
    while (true) {
        while (workers.running.size() < jobs && next < queue.size()) {
            const std::size_t i = queue[next];
            if (i > first_failure) {
                ++next;   // after a failure: it cannot change what is reported
                continue;
            }
            if (auto w = start(tasks[i], i)) {
                workers.running.push_back(std::move(*w));
            } else if (workers.running.empty()) {
                // No process to be had: this task here, as with --jobs 1.
                try {
                    outcomes[i].text = tasks[i].run();
                } catch (...) {
                    outcomes[i].failed = std::current_exception();
                    first_failure = std::min(first_failure, i);
                }
                if (finished)
                    finished();
            } else {
                break;   // another when one of those running is done
            }
            ++next;
        }
        if (workers.running.empty())
            break;
        std::vector<pollfd> watched;
        for (const worker& w : workers.running)
            watched.push_back({w.fd, POLLIN, 0});
        if (::poll(watched.data(), watched.size(), -1) < 0) {
            if (errno == EINTR)
                continue;
            throw std::runtime_error(fmt::format("cannot wait for the worker processes: {}", std::strerror(errno)));
        }
        for (std::size_t i = watched.size(); i-- > 0;) {
            if (watched[i].revents == 0)
                continue;
            worker& w = workers.running[i];
            char buffer[1 << 16];
            const ssize_t n = ::read(w.fd, buffer, sizeof buffer);
            if (n < 0 && errno == EINTR)
                continue;
            if (n > 0) {
                w.bytes.append(buffer, static_cast<std::size_t>(n));
                continue;
            }
            // The end of its pipe: the worker has finished (or died).
            ::close(w.fd);
            int status = 0;
            while (::waitpid(w.pid, &status, 0) < 0 && errno == EINTR) {
            }
            outcomes[w.task] =
                read_outcome(tasks[w.task], w.bytes, status, "the worker process " + tasks[w.task].doing,
                             " (run again with --jobs 1 to " + tasks[w.task].instead + " in Impact's own process)");
            if (outcomes[w.task].failed)
                first_failure = std::min(first_failure, w.task);
            workers.running.erase(workers.running.begin() + static_cast<std::ptrdiff_t>(i));
            if (finished)
                finished();
        }
        // Those after the first failure cannot change what is reported: stopped (by the
        // crew, which kills and waits for them) once no task before it is left.
        if (first_failure < tasks.size()) {
            for (worker& w : workers.running)
                if (w.task > first_failure && !w.stopped) {
                    ::kill(w.pid, SIGKILL);
                    w.stopped = true;
                }
            bool earlier_left = false;
            for (const worker& w : workers.running)
                earlier_left = earlier_left || w.task < first_failure;
            for (std::size_t q = next; q < queue.size(); ++q)
                earlier_left = earlier_left || queue[q] < first_failure;
            if (!earlier_left)
                break;
        }
    }
    if (first_failure < tasks.size())
        std::rethrow_exception(outcomes[first_failure].failed);
    for (std::size_t i = 0; i < tasks.size(); ++i)
        texts[i] = std::move(outcomes[i].text);
    return texts;
}

beside::beside(engine::text_task task) : task_(std::move(task))
{
    result_ = std::tmpfile();
    if (!result_)
        return;
    pid_ = engine::locked_fork();
    if (pid_ == 0) {
        ::prctl(PR_SET_NAME, "impact-report", 0, 0, 0);
        be_worker(task_, ::fileno(result_));
    }
    if (pid_ < 0) {
        std::fclose(result_);
        result_ = nullptr;
    }
}

beside::~beside()
{
    if (pid_ > 0) {
        ::kill(pid_, SIGKILL);
        int status = 0;
        while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
        }
    }
    if (result_)
        std::fclose(result_);
}

std::string beside::get()
{
    if (pid_ <= 0)
        return task_.run();   // no process to be had: run here
    int status = 0;
    while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
    }
    pid_ = -1;
    std::string bytes;
    std::rewind(result_);
    char buffer[1 << 16];
    for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, result_)) > 0;)
        bytes.append(buffer, n);
    std::fclose(result_);
    result_ = nullptr;
    outcome o = read_outcome(task_, bytes, status, "the process compiling it");
    if (o.failed)
        std::rethrow_exception(o.failed);
    return std::move(o.text);
}

engine::task_runner worker_runner(unsigned jobs)
{
    if (jobs <= 1)
        return {};
    return [jobs](const std::vector<engine::text_task>& tasks, const std::function<void()>& finished) {
        return run_in_workers(tasks, jobs, finished);
    };
}

} // namespace impact::pipeline
