#include "verify/z3.h"

#include <fmt/format.h>

#include <z3.h>

#include <cerrno>
#include <chrono>
#include <memory>

#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

namespace impact::verify {

namespace {

// Z3's default handler ends the process on an error; the answers' texts say it instead.
void ignore_error(Z3_context, Z3_error_code) {}

std::string trimmed(std::string s)
{
    while (!s.empty() && (s.back() == '\n' || s.back() == ' '))
        s.pop_back();
    return s;
}

} // namespace

std::string rlimit_option(unsigned long rlimit)
{
    return fmt::format("(set-option :rlimit {})\n", rlimit);
}

std::string z3_version()
{
    return Z3_get_full_version();
}

z3_answer run_z3_here(const std::string& option, const std::string& problem)
{
    Z3_config config = Z3_mk_config();
    const std::unique_ptr<_Z3_context, void (*)(Z3_context)> context(Z3_mk_context(config), Z3_del_context);
    Z3_del_config(config);
    Z3_context ctx = context.get();
    Z3_set_error_handler(ctx, ignore_error);

    z3_answer answer;
    // Only the last line is check-sat's answer: declarations and assertions print nothing
    // unless they fail.
    const std::string said = trimmed(Z3_eval_smtlib2_string(ctx, (option + problem).c_str()));
    const std::size_t last = said.rfind('\n');
    const std::string result = last == std::string::npos ? said : said.substr(last + 1);
    if (result == "unsat") {
        answer.what = z3_answer::kind::confirmed;
    } else if (result == "sat") {
        answer.what = z3_answer::kind::refuted;
        answer.detail = trimmed(Z3_eval_smtlib2_string(ctx, "(get-model)"));
    } else if (result == "unknown") {
        std::string reason = trimmed(Z3_eval_smtlib2_string(ctx, "(get-info :reason-unknown)"));
        // (:reason-unknown "max. resource limit exceeded")
        const std::size_t open = reason.find('"'), close = reason.rfind('"');
        if (open != std::string::npos && close > open)
            reason = reason.substr(open + 1, close - open - 1);
        answer.what = reason.find("resource limit") != std::string::npos ? z3_answer::kind::resource_limit
                                                                          : z3_answer::kind::unknown;
        answer.detail = reason;
    } else {
        answer.what = z3_answer::kind::error;
        answer.detail = said;
    }
    return answer;
}

z3_answer cut_short(bool stopped, unsigned guard_ms)
{
    z3_answer answer;
    answer.what = z3_answer::kind::unknown;
    answer.detail = stopped ? fmt::format("stopped by the wall-clock guard of {:g} s", guard_ms / 1000.0)
                            : std::string("Z3's process ended without an answer");
    answer.guarded = true;
    return answer;
}

z3_answer run_z3(const std::string& option, const std::string& problem)
{
    // A short problem (most of them: a derivation's identities over a few symbols) in this
    // process: it meets its resource limit long before any guard is needed, and a child
    // process would cost more than Z3's answer (its copy of Impact's memory, page by page).
    if (!z3_guarded(problem))
        return run_z3_here(option, problem);
    // In a child process: a few of Z3's procedures (expanding products of long sums before
    // nlsat starts) count no steps against the limit and heed no interrupt, so the guard
    // must be able to end them; and each problem starts from a Z3 that has solved nothing.
    int pipe_ends[2];
    if (pipe(pipe_ends) != 0)
        return run_z3_here(option, problem);
    const pid_t child = fork();
    if (child < 0) {
        close(pipe_ends[0]);
        close(pipe_ends[1]);
        return run_z3_here(option, problem);
    }
    if (child == 0) {
        close(pipe_ends[0]);
        const std::string text = to_text(run_z3_here(option, problem));
        for (std::size_t sent = 0; sent < text.size();) {
            const ssize_t n = write(pipe_ends[1], text.data() + sent, text.size() - sent);
            if (n <= 0)
                _exit(1);
            sent += static_cast<std::size_t>(n);
        }
        _exit(0);
    }
    close(pipe_ends[1]);
    std::string text;
    bool stopped = false;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(z3_guard_ms);
    for (char buffer[4096];;) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
        pollfd ready{pipe_ends[0], POLLIN, 0};
        const int polled = left.count() > 0 ? poll(&ready, 1, static_cast<int>(left.count())) : 0;
        if (polled < 0 && errno == EINTR)
            continue;
        if (polled <= 0) {
            stopped = true;
            kill(child, SIGKILL);
            break;
        }
        const ssize_t n = read(pipe_ends[0], buffer, sizeof buffer);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            break;
        text.append(buffer, static_cast<std::size_t>(n));
    }
    close(pipe_ends[0]);
    int status = 0;
    while (waitpid(child, &status, 0) < 0 && errno == EINTR) {
    }
    z3_answer answer;
    if (stopped || !from_text(text, answer))
        return cut_short(stopped);
    return answer;
}

std::string to_text(const z3_answer& a)
{
    return fmt::format("{}\n{}", static_cast<int>(a.what), a.detail);
}

bool from_text(const std::string& text, z3_answer& a)
{
    const std::size_t line = text.find('\n');
    if (line != 1 || text[0] < '0' || text[0] > '4')
        return false;
    a.what = static_cast<z3_answer::kind>(text[0] - '0');
    a.detail = text.substr(2);
    a.guarded = false;
    return true;
}

std::string to_string(const z3_answer& a)
{
    switch (a.what) {
    case z3_answer::kind::confirmed: return "confirmed";
    case z3_answer::kind::refuted: return "refuted";
    case z3_answer::kind::resource_limit:
        return a.detail.rfind("a problem of", 0) == 0 ? fmt::format("resource limit ({})", a.detail) : "resource limit";
    case z3_answer::kind::unknown: return a.detail.empty() ? "unknown" : fmt::format("unknown ({})", a.detail);
    case z3_answer::kind::error: return fmt::format("error ({})", a.detail);
    }
    return "unknown";
}

} // namespace impact::verify
