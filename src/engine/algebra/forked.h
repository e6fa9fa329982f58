// Work done in a child process: GiNaC's factor(), which can loop forever.
//
// GiNaC's multivariate factor() can run without end on some polynomials in some orders of their
// terms: seen here, a 14-term polynomial in nine symbols (from a case-by-case sign proof of the
// rough spheres in the collision frame) that it factors in 0.1 s in one program ran 19 minutes
// in another, within factor_sqrfree's search for evaluation points (generate_set), until
// stopped. The order follows the addresses of GiNaC's type names, so it changes with how the
// program is linked: a change to an unrelated part of Impact made its kernel generator hang.
// GiNaC cannot be stopped within a call, so these factorizations run in a child process,
// started at the first and kept for the next, which factors each within a limit of CPU time;
// the polynomial is sent and the factorization returned as text. One past its limit ends the
// child, and the next starts another (engine/algebra/polynomial.h tries the polynomial again, its
// terms in another order, before it takes it as not factored). When the
// process that started it exits, the child is stopped and reaped (and were that process
// killed instead, the child dies with it, by PR_SET_PDEATHSIG). A child costs a fork() once; one fork() a factorization, each copying Impact's pages as it went on
// writing them, took the LaTeX stage from 0.56 s to 4.6 s.
//
// Forks happen only while no thread of Impact's holds a lock the child could need: a
// child gets a copy of every lock as it was, and one another thread held at that instant
// (the allocator's, under AddressSanitizer) stays held in the child forever. Impact's one
// thread, the progress line's painter, holds `fork_lock()` while it prints.
#pragma once

#include <ginac/ginac.h>

#include <sys/types.h>

#include <mutex>
#include <optional>
#include <string>

namespace impact::engine {

/// Held by Impact's threads while they run anything that could take a lock a forked child
/// would need, and around every fork().
std::mutex& fork_lock();

/// fork() under `fork_lock()`.
pid_t locked_fork();

/// A message between Impact and a child serving it through a stream socket (the factoring
/// child, Z3's workers): the text's length in decimal, a newline, the text. False when the
/// socket fails or is closed first.
bool send_message(int fd, const std::string& text);
bool receive_message(int fd, std::string& text);

/// What a child forked to serve through socket `fd` does first: signals back to their
/// default actions (a handler the parent installed, a test framework's that jumps back into
/// its runner or a profiler's SIGPROF, must not run in the child), none blocked; no file of
/// the parent's kept open but the socket (a worker's result pipe would otherwise stay open
/// while the child runs); killed when `parent` dies (and gone at once if it died already).
void become_child(int fd, pid_t parent);

/// GiNaC::factor(e, options) computed by this process's factoring child within
/// `cpu_seconds` of CPU time; nothing when it took longer (the child is then replaced at
/// the next call), when `e` holds a number that is not rational or more than 256 symbols,
/// or when no process or socket is to be had. An error factor() throws, a child that ends
/// otherwise, or an answer that cannot be read back is thrown as a std::runtime_error.
/// The factorization is in `e`'s own symbols. Not for threads.
///
/// `e` travels in stand-in symbols, and GiNaC orders its terms by their hash values: each
/// `arrangement` gives `e`'s symbols other stand-ins, so that the child sees the terms in
/// another order, and factor() takes another path (engine/algebra/polynomial.h tries several).
std::optional<GiNaC::ex> factor_in_child(const GiNaC::ex& e, unsigned options, unsigned cpu_seconds,
                                         unsigned arrangement = 0);

/// The process id of this process's factoring child, or -1 when it has none.
pid_t factoring_process();

/// Stops and reaps this process's factoring child, if it started one: what a process that
/// leaves with _exit() does first (a worker), since the stop at exit does not run there.
void stop_factoring();

} // namespace impact::engine
