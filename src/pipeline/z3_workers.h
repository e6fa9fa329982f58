// The proofs' problems run through Z3 in worker processes (issue 61).
//
// A cold regeneration gives Z3 about 500 problems (output/proofs/), most answered in
// milliseconds, some in seconds. Run from Impact's own process, one after another, they took
// 70 s where a small process of their own takes half that: Impact forked a child for each
// guarded problem (verify/z3.h), whose writes and Impact's copied Impact's pages one by one.
// Here at most `jobs` workers are forked, once each, and given one problem after another,
// the longest first (a guess at the costliest: the 3D rough spheres' before the rest). A
// worker solves none itself: it forks a solver for each, from its own state, in which Z3 has
// solved nothing, so that an answer depends on its problem alone, not on the problems a
// worker happened to be given before it (verify/z3.h says why). Each solver costs about
// 20 ms more than a problem solved in a process that solved others (the pages Z3's memory
// needs, faulted in again).
//
// The wall-clock guard is kept as `run_z3` keeps it: a guarded problem (z3_guarded) not
// answered within `z3_guard_ms` of being sent has its worker killed and the guard's answer;
// any other problem, within the workers' net (`z3_worker_net_ms`, a minute) alike. A worker
// that dies gives the answer of a process that ended without one. Another worker is forked
// for the problems left.
#pragma once

#include "verify/proofs.h"

#include <functional>
#include <string>
#include <vector>

namespace impact::pipeline {

/// Z3 on each of `problems` (preceded by `option`), at most `jobs` at once in worker
/// processes; the answers in the problems' order, each the one `verify::run_z3` gives.
/// `finished()` is called after each. When no process is to be had, the problems run here.
/// `guard_ms`: the wall-clock guard, `net_ms` the net under the problems it does not guard
/// (the tests give shorter ones).
std::vector<verify::z3_run> run_z3_in_workers(const std::string& option, const std::vector<std::string>& problems,
                                              unsigned jobs, const std::function<void()>& finished = {},
                                              unsigned guard_ms = verify::z3_guard_ms,
                                              unsigned net_ms = verify::z3_worker_net_ms);

/// `run_z3_in_workers` with `jobs` as check_proofs takes it; with `jobs` 1, one worker (not
/// Impact's own process, where a problem's answer could depend on those solved before it).
verify::z3_runner z3_runner_for(unsigned jobs);

} // namespace impact::pipeline
