#include "engine/forked.h"

#include <sys/socket.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <string>

namespace impact::engine {

std::mutex& fork_lock()
{
    static std::mutex lock;
    return lock;
}

pid_t locked_fork()
{
    const std::lock_guard<std::mutex> still(fork_lock());
    return ::fork();
}

namespace {

// Sends all of `text`; false if the socket failed (MSG_NOSIGNAL: a closed peer is an
// error here, not a SIGPIPE).
bool send_all(int fd, const std::string& text)
{
    std::size_t done = 0;
    while (done < text.size()) {
        const ssize_t n = ::send(fd, text.data() + done, text.size() - done, MSG_NOSIGNAL);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            return false;
        done += static_cast<std::size_t>(n);
    }
    return true;
}

// Receives exactly `size` bytes; false at the end of the stream or on an error.
bool receive_all(int fd, std::string& text, std::size_t size)
{
    text.resize(size);
    std::size_t done = 0;
    while (done < size) {
        const ssize_t n = ::recv(fd, text.data() + done, size - done, 0);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            return false;
        done += static_cast<std::size_t>(n);
    }
    return true;
}

// A message: its length in decimal, a newline, the text.
bool send_message(int fd, const std::string& text)
{
    return send_all(fd, std::to_string(text.size()) + "\n" + text);
}

bool receive_message(int fd, std::string& text)
{
    std::string header;
    char c = 0;
    for (;;) {
        std::string one;
        if (!receive_all(fd, one, 1))
            return false;
        c = one[0];
        if (c == '\n')
            break;
        if (c < '0' || c > '9' || header.size() > 18)
            return false;
        header += c;
    }
    return !header.empty() && receive_all(fd, text, std::stoull(header));
}

// The child that factors: a request is "<symbols> <options> <polynomial>", the polynomial
// in the symbols s0, s1, ... made in that order (so that GiNaC orders them as the parent
// orders the symbols they stand for); the answer "=" and the factorization, or "!" and
// factor()'s error. Each request may take `cpu_seconds` of CPU time: then SIGPROF ends the
// process, and the parent starts another for its next request.
[[noreturn]] void serve(int fd, unsigned cpu_seconds)
{
    std::string request;
    while (receive_message(fd, request)) {
        std::istringstream in(request);
        std::size_t count = 0;
        unsigned options = 0;
        in >> count >> options;
        std::string text;
        std::getline(in >> std::ws, text);
        GiNaC::symtab names;
        for (std::size_t i = 0; i < count; ++i) {
            const std::string name = "s" + std::to_string(i);
            names[name] = GiNaC::symbol(name);
        }
        std::string answer;
        try {
            GiNaC::parser read(names, true);
            const GiNaC::ex p = read(text);
            const itimerval limit{{0, 0}, {static_cast<time_t>(cpu_seconds), 0}};
            ::setitimer(ITIMER_PROF, &limit, nullptr);
            std::srand(1);  // factor() draws its evaluation points from std::rand()
            std::ostringstream out;
            out << GiNaC::factor(p, options);
            const itimerval off{};
            ::setitimer(ITIMER_PROF, &off, nullptr);
            answer = "=" + out.str();
        } catch (const std::exception& failure) {
            answer = std::string("!") + failure.what();
        }
        if (!send_message(fd, answer))
            break;
    }
    ::_exit(0);
}

// This process's factoring child, if it has one (a worker forked from Impact starts its own).
struct server {
    pid_t pid = -1;
    pid_t owner = -1;  // the process that started it
    int fd = -1;
};
server factorer;

void stop(server& s, bool ours)
{
    if (s.fd >= 0)
        ::close(s.fd);
    if (ours && s.pid > 0) {
        ::kill(s.pid, SIGKILL);
        int status = 0;
        while (::waitpid(s.pid, &status, 0) < 0 && errno == EINTR) {
        }
    }
    s = server{};
}

bool start(server& s, unsigned cpu_seconds)
{
    int fds[2];
    if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, fds) != 0)
        return false;
    const pid_t pid = locked_fork();
    if (pid < 0) {
        ::close(fds[0]);
        ::close(fds[1]);
        return false;
    }
    if (pid == 0) {
        ::close(fds[0]);
        serve(fds[1], cpu_seconds);
    }
    ::close(fds[1]);
    s = server{pid, ::getpid(), fds[0]};
    return true;
}

} // namespace

std::optional<GiNaC::ex> factor_in_child(const GiNaC::ex& e, unsigned options, unsigned cpu_seconds)
{
    // The symbols travel by names of their own (two symbols may share a name), numbered in
    // GiNaC's order of them.
    GiNaC::exset symbols;
    for (GiNaC::const_preorder_iterator i = e.preorder_begin(); i != e.preorder_end(); ++i)
        if (GiNaC::is_a<GiNaC::symbol>(*i))
            symbols.insert(*i);
    GiNaC::exmap named;
    GiNaC::symtab by_name;
    for (const GiNaC::ex& s : symbols) {
        const std::string name = "s" + std::to_string(named.size());
        named[s] = GiNaC::symbol(name);
        by_name[name] = s;
    }
    std::ostringstream request;
    request << symbols.size() << ' ' << options << ' ' << e.subs(named);

    if (factorer.fd >= 0 && factorer.owner != ::getpid())
        stop(factorer, false);  // a parent's, inherited by fork(): not this process's to use
    if (factorer.fd < 0 && !start(factorer, cpu_seconds))
        return std::nullopt;
    std::string answer;
    if (!send_message(factorer.fd, request.str()) || !receive_message(factorer.fd, answer) || answer.empty()) {
        stop(factorer, true);  // past its CPU time (SIGPROF), or gone
        return std::nullopt;
    }
    if (answer.front() == '!')
        throw std::runtime_error(answer.substr(1));
    GiNaC::parser read(by_name, true);  // strict: every name is one of `e`'s symbols
    return read(answer.substr(1));
}

} // namespace impact::engine
