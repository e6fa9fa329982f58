// Choosing how a kernel computes each output.
//
// Every output has algebraically equal forms (the display form, the derived value, the
// paper's form, forms given in the derivation file, expanded, factored), each of which
// may also be compiled with fused multiply-adds. Each candidate is compiled and measured
// in double against CLN on samples from the hard regions; the most accurate (smallest
// maximum error, then smallest mean) is emitted, and the choice and the measurements
// are kept for the verification report.
//
// Beside it, each kernel has a fast form (`impact::fast`): each output in its cheapest
// candidate (compile::cheaper) within the output's fast bound, measured and reported alike.
#pragma once

#include "compile/program.h"
#include "engine/derivation/derivation.h"
#include "engine/library/library.h"
#include "verify/measure.h"
#include "verify/sampling.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace impact::cache {
class store;
}

namespace impact::verify {

struct candidate_result {
    std::string label;          ///< e.g. "display", "expanded, fma"
    GiNaC::ex value;
    bool fma = false;
    bool compensated = false;
    bool compensated_lets = false;
    verify::accuracy double_accuracy;
};

struct component_plan {
    std::string name;           ///< `v_M` or `v_M[0]`
    std::vector<candidate_result> candidates;
    std::size_t chosen = 0;     ///< index into candidates
    std::size_t fastest = 0;    ///< the fast form's candidate: the cheapest within the fast bound
    std::size_t heavier = 0;    ///< forms left out for a square root or division more than needed
    std::size_t pruned = 0;     ///< candidates left out after the first sixth of the samples
};

/// The emitted program's accuracy for one output component, in each floating-point type.
struct emitted_accuracy {
    accuracy in_float;
    accuracy in_double;
    accuracy in_long_double;
};

struct kernel_plan {
    const engine::kernel* kernel = nullptr;
    std::vector<component_plan> components;      ///< in verify::components(kernel) order
    compile::program code;               ///< guards' values first, then every output component
    std::size_t guard_values = 0;                ///< how many of code.outputs are guard conditions
    std::vector<verify::sample> samples;
    verify::reference double_reference;
    verify::reference float_reference;
    std::vector<emitted_accuracy> emitted;       ///< per component: `code` as emitted, measured
    /// The fast form: the `fastest` candidates compiled as `code` is (the same guards' values
    /// first), and measured alike.
    compile::program fast_code;
    std::vector<emitted_accuracy> fast_emitted;
};

/// Samples used to choose forms and to report accuracy.
constexpr std::size_t kernel_samples = 4200;

/// The accuracy every output should reach in double, in ulps of its scale.
constexpr double target_ulps = 4;

/// Measures every candidate form of every output, compiles the chosen ones into one
/// program and measures it, all outputs at once, in float, double and long double.
kernel_plan plan_kernel(const engine::kernel& k, const engine::term_order& order);

/// The derived value of output `o`'s component `c` as a quotient of polynomials,
/// `which` = "expanded" or "factored"; nothing when it has a radical.
std::optional<engine::form> derived_form(const engine::kernel_output& o, std::size_t c, const std::string& which);

/// The plan's programs, `code` and `fast_code`: the guards' conditions first, then the
/// chosen (or fastest) form of every component, sharing what they can, in an order that
/// computes its divisors before it divides by them, as a kernel with guards tests them
/// (compile::grouped_divisors). Throws `impact::error` at the kernel where no order does.
void compile_chosen(kernel_plan& plan, const engine::kernel& k, const engine::term_order& order);

/// The fast form of a plan as a plan of its own, for the emitters: `fast_code` as its
/// code, each component's `fastest` candidate as its chosen one, `fast_emitted` as its
/// accuracy (no samples).
kernel_plan fast_form(const kernel_plan& plan);

/// Whether the fast form is the accurate one: every component's fastest candidate its chosen one.
bool fast_is_accurate(const kernel_plan& plan);

/// Work whose result is text (engine/library/tasks.h): a kernel's forms measured in another process.
using engine::task_runner;
using engine::text_task;

/// Every kernel's plan, derivation by derivation in the library's order, each kernel's
/// fixed spheres' kernels (`engine::kernel::limits`) right after it.
///
/// With a `store`, a kernel whose description (inputs and their domains, outputs and
/// their candidate forms, guards, `let`s) and Impact's build are those of a plan measured
/// before takes that plan's choice (its candidates, flags, accuracies and the emitted
/// program's accuracy) instead of measuring again; such a plan has no `samples` and no
/// references. `done(k, n)` is called after each of the n kernels.
///
/// With a `runner`, the kernels not taken from the store are measured as its tasks, each
/// giving its choice as `encode_choice` writes it, read back as from the store: the plans
/// are those of a run without one, in the same order.
std::vector<kernel_plan> plan_kernels(const engine::library& lib, cache::store* store = nullptr,
                                      const std::function<void(std::size_t, std::size_t)>& done = {},
                                      const task_runner& runner = {});

/// Every output that misses its bound (`engine::kernel_output::bound_ulps`, and
/// `fast_bound_ulps` in the fast form) in float, double or long double, one line each:
/// `file:line:column: error: kernel 'k': output 'J' misses its bound ...`, naming the
/// error, the regime and how to raise the bound.
std::vector<std::string> missed_bounds(const std::vector<kernel_plan>& plans);

/// The text a kernel's plan depends on, the key of its cache entry.
std::string choice_key(const engine::kernel& k, const engine::term_order& order);

/// A plan's choice as text, and back: nothing when the text does not describe a
/// choice among `k`'s candidates (it was made for another kernel or is damaged).
std::string encode_choice(const kernel_plan& plan, const engine::term_order& order);
std::optional<kernel_plan> decode_choice(const std::string& text, const engine::kernel& k,
                                         const engine::term_order& order);

} // namespace impact::verify
