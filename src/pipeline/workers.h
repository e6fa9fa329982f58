// Worker processes for the choice of kernel forms.
//
// GiNaC is not thread-safe, so Impact uses its second core with processes: each task
// runs in a child forked from Impact (which has derived everything already, so the child
// needs nothing passed in) and sends back its result as text through a pipe. The parent
// keeps at most `jobs` children at once and collects their texts in the tasks' order, so
// that what is written does not depend on which finished first.
//
// A child touches only what the task reads (the derived library, GiNaC's and CLN's
// state) and its pipe, and leaves with _exit(). It may start a factoring child of its own
// (engine/algebra/forked.h), which closes the pipe and dies with it.
//
// Impact forks only while no thread of its own can hold a lock: a child gets a copy of
// every lock as it was, and one held by another thread at that instant (the allocator's,
// under AddressSanitizer, whose allocator GCC 12 does not make fork-safe) is held in the
// child forever. So the report is compiled in a process of its own (`beside`), not in a
// thread, and the progress line's painter, the one thread Impact starts, holds
// `fork_lock()` while it prints.
#pragma once

#include "engine/algebra/forked.h"
#include "spec/error.h"
#include "engine/library/tasks.h"

#include <sys/types.h>

#include <cstdio>
#include <functional>
#include <mutex>
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
std::vector<std::string> run_in_workers(const std::vector<engine::text_task>& tasks, unsigned jobs,
                                        const std::function<void()>& finished = {});

/// `run_in_workers` with `jobs`, as derive_all and plan_kernels take it; no runner for one job,
/// so that they work in this process without sending their results through text.
engine::task_runner worker_runner(unsigned jobs);

/// Held by Impact's threads (the progress line's painter) while they run anything that
/// could take a lock a forked child would need, and around every fork() (the engine's
/// factorizations fork too).
using engine::fork_lock;

/// `task` run in a process forked beside this one, its text collected by `get()`: the
/// report's PDFs, compiled while the kernel forms are chosen on this thread. The child
/// writes its result to an unnamed temporary file, so that it never waits for the parent
/// to read. When no process is to be had, the task runs in `get()`. A child still running
/// when this is destroyed (the parent stopped on an error) is killed and waited for.
class beside {
public:
    beside(engine::text_task task);
    ~beside();
    beside(const beside&) = delete;
    beside& operator=(const beside&) = delete;

    /// Waits for the task: its text, or its `impact::error` (or another exception, as a
    /// `std::runtime_error`) thrown here; a child that died is an `impact::error` at the
    /// task's place naming how.
    std::string get();

private:
    engine::text_task task_;
    pid_t pid_ = -1;
    std::FILE* result_ = nullptr;
};

} // namespace impact::pipeline
