// What the C++ emitter's printers share: the scalar kernel (cxx_kernel.cpp), the batch
// kernel (cxx_batch.cpp, its blocks in cxx_batch_blocks.cpp) and its arrays (cxx_batch_arrays.cpp), the common header (cxx_common.cpp) and the
// headers' assembly (cxx.cpp).
#pragma once

#include "emit/cxx.h"
#include "emit/program_cxx.h"
#include "compile/range.h"

#include <map>
#include <string>
#include <vector>

namespace impact::emit::cxx_detail {

/// A quantity for the kernel's documentation: "M: mass of sphere M (positive, in kg)".
std::string describe(const engine::quantity& q);
/// Whether the kernel writes the parameter `name` (an output named after an input).
bool is_output(const engine::kernel& k, const std::string& name);
/// A kernel returning one scalar returns it directly, and a quiet NaN where a guard
/// refuses its inputs (a NaN is what the arithmetic would give for most of them, and a
/// caller tests one value); otherwise a struct, with a status if the kernel has guards.
bool returns_scalar(const engine::kernel& k);
/// Whether the kernel's result carries a status: one with guards that returns a struct.
bool has_status(const engine::kernel& k);
/// The number of components of the kernel's array parameters; 0 without arrays.
std::size_t dimension(const engine::kernel& k);
std::string result_type(const engine::kernel& k);
std::string parameter_type(const engine::kernel_parameter& p);

/// One test a guard makes of a value: a comparison, written as the test that fails (NaN
/// fails every comparison, so each is the negation of what must hold), or that the value
/// is finite.
struct domain_test {
    std::string failure;  ///< e.g. "!(M > Real(0))"; empty for a finiteness test
    std::string finite;   ///< the value that must be finite
    /// The value `failure` wants above 0 (`positive`) or not below it, when that is all it
    /// tests: a sure block may test that sign by the value's bits instead.
    std::string sign_of;
    bool positive = false;
};
std::vector<domain_test> domain_tests(const engine::quantity& q, const std::string& value);
/// The tests of a guard on the domains of its parameters, in order.
std::vector<domain_test> guard_tests(const engine::kernel& k, const engine::kernel_guard& g,
                                     const std::string& suffix);

/// A kernel with a status resolves a collision only inside the floating-point range: every
/// divisor at least detail::smallest_divisor (its rounding errors still normal numbers, so
/// that compensated arithmetic keeps its precision) and finite, every result finite.
/// Otherwise the status is `out_of_range` and the velocities are unchanged.
inline constexpr const char* out_of_range = "out_of_range";
/// A kernel with a status resolves a collision only where its arithmetic stays in the
/// normal range at the bottom too: no value of its arithmetic (a product, quotient, fused
/// multiply-add or function; not a correction of compensated arithmetic) below
/// std::numeric_limits<Real>::min() or fallen to 0 from operands that are not
/// (cxx_code::underflows). Otherwise, if no status before applies, the status is
/// `underflow` and the velocities are unchanged: a value below the normal range has lost
/// digits, and the result could be far from the exact one.
inline constexpr const char* underflow = "underflow";
/// What must hold of every divisor of a group (`late`: those that need a division, see
/// cxx_code), as tests; the scalar kernel refuses a pair where one fails, the batch loop
/// divides by 1 instead.
/// `known`: where every divisor not 0 is known to be in range (a sure block's, whose range
/// bounds them), the tests are that none is 0.
std::vector<std::string> divisors_in_range(const cxx_code& code, bool late = false, bool known = false);
/// A guard's condition (the value compared with 0), written as the test that fails.
std::string condition_failure(const std::string& value, const engine::kernel_guard& g);

/// The names of common.hpp's `impact::status`, in the order of its values, for `kernels`
/// (one per kernel callers see, in the library's order; not their fixed spheres' kernels).
std::vector<std::string> status_names(const std::vector<const engine::kernel*>& kernels);

/// The hand-written part of common.hpp: src/emit/kernel_prelude.hpp, as CMake embeds it.
extern const char* const kernel_prelude;

/// Which of a kernel's two forms is printed: the accurate one, called without a tag, or the
/// fast one, `verify::fast_form`, called with `impact::fast` (an overload of the same name
/// with a last parameter `impact::fast_t`, which forwards to the accurate form where that
/// is the fast one too).
enum class form { accurate, fast };

/// The scalar kernel, its result structure and documentation; then its batch form. `fixed`:
/// the plans of its fixed spheres' kernels, printed before it in `detail` and called where
/// their mass is +infinity. The fast form (`which`) is printed from the same plans.
void print_kernel(std::string& out, const engine::derivation& d, const kernel_plan& plan,
                  const std::vector<const kernel_plan*>& fixed = {}, form which = form::accurate);
/// The batch kernel of a kernel with `batch = true`, in the form `plan` is (`which`).
void print_batch(std::string& out, const kernel_plan& plan, form which = form::accurate);
/// `f` of `terms` as a balanced tree: f(f(a, b), f(c, d)), ...
std::string balanced(const std::string& f, std::vector<std::string> terms);
/// `detail::<loop>_k<Real>`: the exponent k of the loop's input range, per format; returns
/// them in the order of batch_formats (-1 for a format without a range).
std::vector<int> print_input_k(std::string& out, const std::string& loop, const kernel_plan& plan);
/// The least magnitude of the values `code` tests for underflow (detail::zero_as_min for
/// operands that may be 0), where a format has no input range.
std::string least_magnitude(const cxx_code& code);
/// The formats a batch loop's input range is derived for, in the order of detail::input_k's
/// arguments (common.hpp): float, double, x87's and IEEE's quadruple long double.
inline constexpr compile::float_format batch_formats[] = {{24, -125, 128}, {53, -1021, 1024}, {64, -16381, 16384}, {113, -16381, 16384}};
/// How a member of a kernel's shared structures is shaped in each dimension the kernel is
/// emitted in: its components there, 0 for a scalar. A spin is one (a scalar) in 2D and a
/// vector of three in 3D; a velocity has N components in N dimensions.
struct member_shape {
    std::map<std::size_t, std::size_t> components;  ///< dimension -> components (0: a scalar)

    /// The member's C++ type in N dimensions, `element` its scalar type ("Real", "Real*").
    std::string type(const std::string& element) const;
    /// Its number of `element`s in N dimensions, as C++: "1", "N", "(N == 2 ? 1 : 3)".
    std::string count() const;
    /// Whether it is one value in every dimension.
    bool scalar() const;
    /// Whether it has N components in N dimensions.
    bool follows_dimension() const;
};
/// The shapes of a kernel's parameters by name, over the plans of every dimension it has.
using member_shapes = std::map<std::string, member_shape>;
/// The members of `<name>_batch_data`, each an array or N: the kernel's parameters, then its
/// outputs named after no input.
std::vector<std::string> batch_members(const engine::kernel& k);
/// The arrays of `<name>_batch_data`, owned, in one allocation laid out for speed; `shapes`
/// are its parameters' (member_shape).
void print_batch_arrays(std::string& out, const engine::kernel& k, const member_shapes& shapes);
/// Whether a batch kernel gets a skewed block loop too (and common.hpp detail::crowded).
bool skews(const engine::kernel& k);

} // namespace impact::emit::cxx_detail
