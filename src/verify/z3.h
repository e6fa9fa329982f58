// Z3 run in this process on an SMT-LIB 2 problem (smt.h), through libz3's C API: the text
// Z3 checks is the text written to output/proofs/, byte for byte.
//
// Each problem runs in a fresh context under a resource limit (`(set-option :rlimit N)`,
// part of the text): Z3 counts its own steps, so that an answer, `unknown` past the limit
// included, is the same on every run and machine with the same Z3. But not whatever the
// process ran before: Z3 keeps state from one context to the next that neither
// Z3_reset_memory nor Z3_global_param_reset_all clears, and a problem it confirms in 0.5 s
// in a new process ran for minutes, heeding no limit, after another one (rough_collision_frame's
// energy_never_gained after a rough-sphere problem). So the pipeline solves each problem in
// a process of its own, forked from one that has solved none (pipeline/z3_workers.h). A
// wall-clock guard stands behind the limit for the few procedures that count no steps (the
// process running it is killed): its answer, unknown, is kept like any other, so that a
// machine gives the same answer on every regeneration. `run_z3` runs one problem from
// Impact's own process, for the tests and when no process is to be had.
#pragma once

#include <cstddef>
#include <string>

namespace impact::verify {

/// Z3's resource limit per problem (its `rlimit` steps), measured on the paper's problems:
/// the largest Z3 confirms (rough_plane's energy_never_gained) needs 4.0 million steps (5 s
/// on the machine of docs/design.md); the limit allows twice that.
inline constexpr unsigned long z3_rlimit = 8'000'000;

/// The longest problem given to Z3, in characters: beyond it (the rough spheres' in space,
/// sums of hundreds of terms under roots) Z3 expands products before it counts a step, for
/// seconds to minutes each; such a problem is not run, and counts as past the resource
/// limit. 20,000 keeps a cold regeneration's Z3 within about a minute on two cores.
inline constexpr std::size_t z3_largest_problem = 20'000;

/// The wall-clock guard per problem, in milliseconds: a safety net behind the resource
/// limit, which a problem within `z3_largest_problem` meets first.
inline constexpr unsigned z3_guard_ms = 10'000;

/// In the pipeline's worker processes, the wall-clock net under a problem that is not guarded
/// (shorter than `z3_in_process_below`), in milliseconds. Such a problem takes well under a
/// second, and its answer is the resource limit's. But a worker's Z3, when it solved problem
/// after problem, once ran on one for more than 5 minutes in CI (see above), and the
/// regeneration waited for it. The net ends such a problem, which is then not re-checked,
/// as one the guard stopped.
inline constexpr unsigned z3_worker_net_ms = 60'000;

/// Problems shorter than this, in characters, are solved in Impact's own process by `run_z3`;
/// longer ones in a child process the guard can end. Only these longer ones are guarded.
inline constexpr std::size_t z3_in_process_below = 6'000;

/// Whether `problem` runs under the wall-clock guard (its length).
inline bool z3_guarded(const std::string& problem)
{
    return problem.size() >= z3_in_process_below;
}

struct z3_answer {
    enum class kind { confirmed, refuted, unknown, resource_limit, error };
    kind what = kind::unknown;
    std::string detail;        ///< refuted: Z3's model; unknown: its reason; error: its message
    bool guarded = false;      ///< cut short by the wall-clock guard
};

/// The first line of `(set-option :rlimit N)` every problem file starts with.
std::string rlimit_option(unsigned long rlimit = z3_rlimit);

/// Runs Z3 on `problem` (declarations, assertions, one check-sat), preceded by `option`: a
/// guarded problem in a child process forked for it, another in this process.
z3_answer run_z3(const std::string& option, const std::string& problem);

/// Z3 on `problem` in this process, in a fresh context, with no guard: what `run_z3` and
/// the pipeline's worker processes run.
z3_answer run_z3_here(const std::string& option, const std::string& problem);

/// The answer of a guarded problem whose process was stopped by the guard of `guard_ms`
/// (`stopped`), or ended without an answer.
z3_answer cut_short(bool stopped, unsigned guard_ms = z3_guard_ms);

/// "4.8.12.0": the library's version, part of the key an answer is kept under.
std::string z3_version();

/// The answer as a cache entry keeps it, and read back (nothing when not one).
std::string to_text(const z3_answer& a);
bool from_text(const std::string& text, z3_answer& a);

/// "confirmed", "refuted", "unknown (reason)", "resource limit", "error (message)".
std::string to_string(const z3_answer& a);

} // namespace impact::verify
