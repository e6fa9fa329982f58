// Worker processes for the choice of kernel forms.
//
// GiNaC is not thread-safe, so Impact uses its second core with processes: each task
// runs in a child forked from Impact (which has derived everything already, so the child
// needs nothing passed in) and sends back its result as text through a pipe. The parent
// keeps at most `jobs` children at once and collects their texts in the tasks' order, so
// that what is written does not depend on which finished first.
//
// A child touches only what the task reads (the derived library, GiNaC's and CLN's
// state, which only the pipeline's thread ever uses) and its pipe, and leaves with
// _exit(): the report's thread and the progress line, running beside it in the parent,
// do not exist in the child, and nothing of theirs is used there.
#pragma once

#include "verify/choice.h"

#include <functional>
#include <string>
#include <vector>

namespace impact::pipeline {

/// How many tasks run at once by default: the hardware's threads (at least 1).
unsigned default_jobs();

/// Runs `tasks` in worker processes, at most `jobs` at once, and gives their texts in
/// the tasks' order; `finished()` is called (on this thread) after each. A task that
/// throws `impact::error` has it thrown here, the same error at the same place, and
/// another exception as a `std::runtime_error` with its message; a worker that dies
/// (a signal, an exit without its whole result) is an `impact::error` at the task's
/// place naming how it died. When several fail, the first in the tasks' order is thrown,
/// as a run of one task after another would have; workers still running after it are
/// stopped. With `jobs` 1 or a single task, the tasks run here, one after another;
/// otherwise the costliest (`text_task::cost`) are started first.
std::vector<std::string> run_in_workers(const std::vector<verify::text_task>& tasks, unsigned jobs,
                                        const std::function<void()>& finished = {});

/// `run_in_workers` with `jobs`, as plan_kernels takes it.
verify::task_runner worker_runner(unsigned jobs);

} // namespace impact::pipeline
