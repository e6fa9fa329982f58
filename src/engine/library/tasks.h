// Work whose result is text, so that another process may do it: deriving a file (the
// derivation as engine/store/stored.h writes it), measuring a kernel's forms (verify/choice.h).
// The pipeline runs such tasks in worker processes (pipeline/workers.h); the stages that
// make them only say what each task is.
#pragma once

#include "spec/error.h"

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace impact::engine {

/// A piece of work whose result is text, so that it may run in another process.
struct text_task {
    std::string what;              ///< e.g. "kernel 'collide_line'", for a worker that dies
    source_location where;         ///< where that is in a derivation file
    std::function<std::string()> run;
    std::size_t cost = 0;          ///< a guess at its work: the costliest are started first
    /// What a worker doing it does, and what Impact's own process would do instead, for a
    /// message about a worker's death: "choosing its forms", "choose them".
    std::string doing = "doing its work";
    std::string instead = "do it";
};

/// Runs every task (perhaps several at once, in worker processes) and gives their texts
/// in the tasks' order, calling `finished()` after each; a task's `impact::error` is
/// thrown as it is, that of the first failing task in their order.
using task_runner =
    std::function<std::vector<std::string>(const std::vector<text_task>&, const std::function<void()>& finished)>;

} // namespace impact::engine
