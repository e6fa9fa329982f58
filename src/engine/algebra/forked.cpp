#include "engine/algebra/forked.h"

#include <sys/prctl.h>
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
#include <vector>

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

// Moves `size` bytes, `step(done)` moving some of what is left (a send or a recv) and
// retried when a signal interrupts it; false when it fails or the stream ends.
template <class Step>
bool all_of(std::size_t size, Step step)
{
    for (std::size_t done = 0; done < size;) {
        const ssize_t n = step(done);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            return false;
        done += static_cast<std::size_t>(n);
    }
    return true;
}

// Sends all of `text` (MSG_NOSIGNAL: a closed peer is an error here, not a SIGPIPE).
bool send_all(int fd, const std::string& text)
{
    return all_of(text.size(), [&](std::size_t done) {
        return ::send(fd, text.data() + done, text.size() - done, MSG_NOSIGNAL);
    });
}

// Receives exactly `size` bytes into `text`.
bool receive_all(int fd, std::string& text, std::size_t size)
{
    text.resize(size);
    return all_of(size, [&](std::size_t done) { return ::recv(fd, text.data() + done, size - done, 0); });
}

} // namespace

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

void become_child(int fd, pid_t parent)
{
    for (int signal : {SIGPROF, SIGSEGV, SIGABRT, SIGBUS, SIGILL, SIGFPE, SIGTERM, SIGINT, SIGPIPE})
        std::signal(signal, SIG_DFL);
    sigset_t none;
    sigemptyset(&none);
    ::sigprocmask(SIG_SETMASK, &none, nullptr);
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent)  // the parent died before the line above
        ::_exit(0);
    if (fd > 3)
        ::close_range(3, static_cast<unsigned>(fd) - 1, 0);
    ::close_range(static_cast<unsigned>(fd) + 1, ~0U, 0);
}

namespace {

// The symbols a polynomial travels in, s0, s1, ...: made once, before main(), so that
// Impact and its factoring child (a copy of it) hold the same ones, and GiNaC orders them
// the same way in every child and after any number of requests (a symbol's place in
// GiNaC's order follows its serial number). A polynomial in more symbols than these is
// not sent.
constexpr std::size_t stand_ins = 256;
const std::vector<GiNaC::ex>& stand_in_symbols()
{
    static const std::vector<GiNaC::ex> symbols = [] {
        std::vector<GiNaC::ex> made;
        for (std::size_t i = 0; i < stand_ins; ++i)
            made.push_back(GiNaC::symbol("s" + std::to_string(i)));
        return made;
    }();
    return symbols;
}
const bool stand_ins_made = !stand_in_symbols().empty();

// The child that factors: a request is "<options> <seconds> <polynomial>", the polynomial
// in the stand-in symbols; the answer "=" and the factorization, or "!" and factor()'s
// error. Each request may take its seconds of CPU time: then SIGPROF ends the child, and
// the parent starts another for its next request.
void serve(int fd)
{
    GiNaC::symtab names;
    for (const GiNaC::ex& s : stand_in_symbols())
        names[GiNaC::ex_to<GiNaC::symbol>(s).get_name()] = s;
    std::string request;
    while (receive_message(fd, request)) {
        std::istringstream in(request);
        unsigned options = 0, cpu_seconds = 0;
        in >> options >> cpu_seconds;
        std::string text;
        std::getline(in >> std::ws, text);
        std::string answer;
        const itimerval limit{{0, 0}, {static_cast<time_t>(cpu_seconds), 0}};
        ::setitimer(ITIMER_PROF, &limit, nullptr);
        try {
            GiNaC::parser read(names, true);
            const GiNaC::ex p = read(text);
            std::srand(1);  // factor() draws its evaluation points from std::rand()
            std::ostringstream out;
            out << GiNaC::factor(p, options);
            answer = "=" + out.str();
        } catch (const std::exception& failure) {
            answer = std::string("!") + failure.what();
        }
        const itimerval off{};
        ::setitimer(ITIMER_PROF, &off, nullptr);
        if (!send_message(fd, answer))
            break;
    }
}

// This process's factoring child, if it has one (a worker forked from Impact starts its own).
struct server {
    pid_t pid = -1;
    pid_t owner = -1;  // the process that started it
    int fd = -1;
};
server factorer;

// Closes the socket and, for this process's own child, kills it and gives how it ended.
int stop(server& s, bool ours)
{
    int status = 0;
    if (s.fd >= 0)
        ::close(s.fd);
    if (ours && s.pid > 0) {
        ::kill(s.pid, SIGKILL);
        while (::waitpid(s.pid, &status, 0) < 0 && errno == EINTR) {
        }
    }
    s = server{};
    return status;
}

// At exit, this process's own child is stopped and reaped: none is left behind (without it
// the child, killed as its parent dies, lingers a moment, or as a zombie where nothing reaps).
struct stop_at_exit {
    ~stop_at_exit()
    {
        if (factorer.fd >= 0 && factorer.owner == ::getpid())
            stop(factorer, true);
    }
};
const stop_at_exit stopper;

bool start(server& s)
{
    int fds[2];
    if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, fds) != 0)
        return false;
    const pid_t parent = ::getpid();
    const pid_t pid = locked_fork();
    if (pid < 0) {
        ::close(fds[0]);
        ::close(fds[1]);
        return false;
    }
    if (pid == 0) {
        try {
            ::close(fds[0]);
            become_child(fds[1], parent);
            serve(fds[1]);
        } catch (...) {
            ::_exit(1);  // never back into the parent's code
        }
        ::_exit(0);
    }
    ::close(fds[1]);
    s = server{pid, ::getpid(), fds[0]};
    return true;
}

} // namespace

std::optional<GiNaC::ex> factor_in_child(const GiNaC::ex& e, unsigned options, unsigned cpu_seconds,
                                         unsigned arrangement)
{
    // The symbols travel as the stand-ins (two symbols may share a name), numbered in
    // GiNaC's order of them from a place `arrangement` sets; the numbers, rational, as
    // GiNaC prints them.
    GiNaC::exset symbols;
    for (GiNaC::const_preorder_iterator i = e.preorder_begin(); i != e.preorder_end(); ++i) {
        if (GiNaC::is_a<GiNaC::symbol>(*i))
            symbols.insert(*i);
        else if (GiNaC::is_a<GiNaC::numeric>(*i) && !i->info(GiNaC::info_flags::rational))
            return std::nullopt;  // a float or a complex number: not sent
    }
    if (symbols.size() > stand_ins)
        return std::nullopt;
    GiNaC::exmap named;
    GiNaC::symtab by_name;
    for (const GiNaC::ex& s : symbols) {
        const GiNaC::ex& stand_in = stand_in_symbols()[(101 * arrangement + named.size()) % stand_ins];
        named[s] = stand_in;
        by_name[GiNaC::ex_to<GiNaC::symbol>(stand_in).get_name()] = s;
    }
    std::ostringstream request;
    request << options << ' ' << cpu_seconds << ' ' << e.subs(named);

    if (factorer.fd >= 0 && factorer.owner != ::getpid())
        stop(factorer, false);  // a parent's, inherited by fork(): not this process's to use
    if (factorer.fd < 0 && !start(factorer))
        return std::nullopt;
    std::string answer;
    if (!send_message(factorer.fd, request.str()) || !receive_message(factorer.fd, answer) || answer.empty()) {
        const int status = stop(factorer, true);
        if (WIFSIGNALED(status) && WTERMSIG(status) == SIGPROF)
            return std::nullopt;  // past its CPU time
        throw std::runtime_error(WIFSIGNALED(status)
                                     ? "the process factoring a polynomial ended by signal " + std::to_string(WTERMSIG(status))
                                     : "the process factoring a polynomial ended with status " + std::to_string(WEXITSTATUS(status)));
    }
    if (answer.front() == '!')
        throw std::runtime_error(answer.substr(1));
    try {
        GiNaC::parser read(by_name, true);  // strict: every name is one of `e`'s symbols
        return read(answer.substr(1));
    } catch (const std::exception& failure) {
        throw std::runtime_error("the factorization of a polynomial could not be read back: " +
                                 std::string(failure.what()));
    }
}

pid_t factoring_process()
{
    return factorer.owner == ::getpid() ? factorer.pid : -1;
}

void stop_factoring()
{
    if (factorer.fd >= 0 && factorer.owner == ::getpid())
        stop(factorer, true);
}

} // namespace impact::engine
