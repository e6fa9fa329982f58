#include "emit/cxx.h"

#include "emit/program_cxx.h"

#include "engine/infix.h"

#include <fmt/format.h>

#include <algorithm>
#include <functional>
#include <iterator>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string_view>

namespace impact::emit {

GINAC_IMPLEMENT_PRINT_CONTEXT(print_cxx, print_infix)

print_cxx::print_cxx() : print_infix() {}
print_cxx::print_cxx(std::ostream& os, const term_order& order)
    : print_infix(os, order, {" * ", " + ", " - ", " / ", "std::", true, true})
{
}

std::string cxx(const GiNaC::ex& e, const term_order& order)
{
    std::ostringstream out;
    engine::print_expression(e, print_cxx(out, order));
    return out.str();
}

namespace {

std::string describe(const engine::quantity& q)
{
    std::string text = q.name;
    if (!q.meaning.empty())
        text += ": " + q.meaning;
    return text + " (" + q.range.to_string() + ")";
}

bool is_output(const engine::kernel& k, const std::string& name)
{
    for (const engine::kernel_output& o : k.outputs)
        if (o.member == name)
            return true;
    return false;
}

// A kernel returning one scalar returns it directly, and a quiet NaN where a guard refuses
// its inputs (a NaN is what the arithmetic would give for most of them, and a caller tests
// one value); otherwise a struct, with a status if the kernel has guards.
bool returns_scalar(const engine::kernel& k)
{
    return k.outputs.size() == 1 && !k.outputs.front().is_array;
}

// Whether the kernel's result carries a status: one with guards that returns a struct.
bool has_status(const engine::kernel& k)
{
    return !k.guards.empty() && !returns_scalar(k);
}

std::size_t dimension(const engine::kernel& k)
{
    for (const engine::kernel_parameter& p : k.parameters)
        if (p.is_array)
            return p.components.size();
    return 0;
}

std::string result_type(const engine::kernel& k)
{
    if (returns_scalar(k))
        return "Real";
    const std::size_t n = dimension(k);
    return n ? fmt::format("{}_result<Real, {}>", k.name, n) : fmt::format("{}_result<Real>", k.name);
}

std::string parameter_type(const engine::kernel_parameter& p)
{
    return p.is_array ? fmt::format("const std::array<Real, {}>&", p.components.size()) : "Real";
}

// One test a guard makes of a value: a comparison, written as the test that fails (NaN
// fails every comparison, so each is the negation of what must hold), or that the value
// is finite.
struct domain_test {
    std::string failure;  ///< e.g. "!(M > Real(0))"; empty for a finiteness test
    std::string finite;   ///< the value that must be finite
};

std::vector<domain_test> domain_tests(const engine::quantity& q, const std::string& value)
{
    switch (q.range.what) {
    case engine::domain::kind::positive:
        return {{fmt::format("!({} > Real(0))", value), {}}, {{}, value}};
    case engine::domain::kind::nonnegative:
        return {{fmt::format("!({} >= Real(0))", value), {}}, {{}, value}};
    case engine::domain::kind::interval:
        return {{fmt::format("!({} {} Real({}))", value, q.range.lower_open ? ">" : ">=", q.range.lower), {}},
                {fmt::format("!({} {} Real({}))", value, q.range.upper_open ? "<" : "<=", q.range.upper), {}}};
    case engine::domain::kind::real: break;
    }
    return {{{}, value}};
}

// The tests of a guard on the domains of its parameters, in order.
std::vector<domain_test> guard_tests(const engine::kernel& k, const engine::kernel_guard& g, const std::string& suffix)
{
    std::vector<domain_test> tests;
    for (const std::string& name : g.parameters)
        if (const engine::kernel_parameter* p = k.find_parameter(name))
            for (const engine::quantity& q : p->components)
                for (domain_test& t : domain_tests(q, q.name + suffix))
                    tests.push_back(std::move(t));
    return tests;
}

// The scalar kernel's form of the tests: a finite value tested with std::isfinite.
std::vector<std::string> scalar_failures(const std::vector<domain_test>& tests)
{
    std::vector<std::string> failures;
    for (const domain_test& t : tests)
        failures.push_back(t.finite.empty() ? t.failure : fmt::format("!std::isfinite({})", t.finite));
    return failures;
}

// The batch loop's form: the comparisons, then one test for every value that must be
// finite. x * 0 is 0 for a finite x and NaN for an infinite or NaN one, so a sum of such
// products is 0 exactly when every x is finite. Fused, a value costs one operation, where
// std::isfinite costs two and a merge of the results (the guards were a third of the
// loop's instructions). The sum is a balanced tree, not a chain: the test gates the loop's
// division and its stores, and a chain of 12 dependent operations delayed both (3D batch,
// in cache: 166 → 172 M pairs/s with both tests as trees).
// Each term of the sum is written as `term` gives it (in place by default).
using term_writer = std::function<std::string(const std::string& term, bool is_sum)>;

std::string in_place(const std::string& term, bool is_sum)
{
    return is_sum ? "(" + term + ")" : term;
}

std::string all_finite(const std::vector<std::string>& values, const term_writer& term = in_place)
{
    if (values.size() == 1)
        return fmt::format("std::isfinite({})", values.front());
    std::vector<std::string> terms;  // x * 0 + y * 0 for the values two by two
    for (std::size_t v = 0; v < values.size(); v += 2)
        terms.push_back(term(v + 1 < values.size()
                                 ? fmt::format("std::fma({}, Real(0), {} * Real(0))", values[v], values[v + 1])
                                 : values[v] + " * Real(0)",
                             false));
    while (terms.size() > 1) {
        std::vector<std::string> sums;
        for (std::size_t t = 0; t < terms.size(); t += 2)
            sums.push_back(t + 1 < terms.size() ? term(terms[t] + " + " + terms[t + 1], true) : terms[t]);
        terms = std::move(sums);
    }
    return fmt::format("({} == Real(0))", terms.front());
}

std::vector<std::string> batch_failures(const std::vector<domain_test>& tests)
{
    std::vector<std::string> failures, finite;
    for (const domain_test& t : tests)
        if (t.finite.empty())
            failures.push_back(t.failure);
        else
            finite.push_back(t.finite);
    if (!finite.empty())
        failures.push_back("!" + all_finite(finite));
    return failures;
}

// A kernel with a status resolves a collision only inside the floating-point range: every
// divisor at least detail::smallest_divisor (its rounding errors still normal numbers, so
// that compensated arithmetic keeps its precision) and finite, every result finite.
// Otherwise the status is `out_of_range` and the velocities are unchanged.
constexpr const char* out_of_range = "out_of_range";

// What must hold of every divisor, as tests; the scalar kernel refuses a pair where one
// fails, the batch loop divides by 1 instead.
std::vector<std::string> divisors_in_range(const cxx_code& code)
{
    if (code.divides_early)
        throw std::logic_error("a kernel with a status divides before all its divisors are known");
    std::vector<std::string> tests;
    for (const std::string& d : code.divisors) {
        tests.push_back(fmt::format("(std::fabs({}) >= detail::smallest_divisor<Real>)", d));
        tests.push_back(fmt::format("(std::fabs({}) <= std::numeric_limits<Real>::max())", d));
    }
    return tests;
}

// A guard's condition (the value compared with 0), written as the test that fails.
std::string condition_failure(const std::string& value, const engine::kernel_guard& g)
{
    return fmt::format("!({} {} Real(0))", value, g.op == engine::relation::less ? "<" : ">");
}

// The scalar kernel's early return when any of `failures` holds: the result as it stands
// (inputs unchanged) with `status`, or, from a kernel returning one scalar, a quiet NaN
// (the status then named in a comment).
void print_refusal(std::string& out, const engine::kernel& k, const std::vector<std::string>& failures,
                   const std::string& status)
{
    if (returns_scalar(k))
        out += fmt::format("    if ({}) {{\n        return std::numeric_limits<Real>::quiet_NaN();  // {}\n    }}\n",
                           fmt::join(failures, " || "), status);
    else
        out += fmt::format("    if ({}) {{\n        out.status = status::{};\n        return out;\n    }}\n",
                           fmt::join(failures, " || "), status);
}

// What a value outside a domain is, in words: "not positive and finite".
std::string outside(const engine::domain& range)
{
    switch (range.what) {
    case engine::domain::kind::positive: return "not positive and finite";
    case engine::domain::kind::nonnegative: return "negative or not finite";
    case engine::domain::kind::interval: return "outside " + range.to_string();
    case engine::domain::kind::real: break;
    }
    return "not finite";
}

// What a guard refuses, in words, for the kernel's documentation: "M, m not positive and
// finite", or the condition that must hold.
std::string guard_meaning(const engine::derivation& d, const engine::kernel& k, const engine::kernel_guard& g)
{
    if (g.condition)
        return fmt::format("unless {} {} 0", d.symbols.text(*g.condition), g.op == engine::relation::less ? "<" : ">");
    std::vector<std::string> parts;  // "names: words", one per run of parameters alike
    std::vector<std::string> names;
    std::string words;
    for (const std::string& name : g.parameters) {
        const engine::kernel_parameter* p = k.find_parameter(name);
        const std::string these = outside(p->components.front().range);
        if (!names.empty() && these != words) {
            parts.push_back(fmt::format("{} {}", fmt::join(names, ", "), words));
            names.clear();
        }
        names.push_back(name);
        words = these;
    }
    if (!names.empty())
        parts.push_back(fmt::format("{} {}", fmt::join(names, ", "), words));
    return fmt::format("{}", fmt::join(parts, "; "));
}

// The documentation of a kernel's guards: what each status means, and what is returned.
// `divides`: whether the kernel divides by a value it computes (then tested for range).
void print_guards_documentation(std::string& out, const engine::derivation& d, const engine::kernel& k, bool divides)
{
    if (k.guards.empty())
        return;
    const bool others = std::any_of(k.outputs.begin(), k.outputs.end(),
                                    [&](const engine::kernel_output& o) { return !k.find_parameter(o.member); });
    if (returns_scalar(k))
        out += "/// A quiet NaN when the inputs are refused, for the first of these reasons that applies:\n";
    else
        out += fmt::format("/// When the inputs allow no collision, `status` says why, the first of these that\n"
                           "/// applies, and the velocities are returned unchanged{}:\n",
                           others ? " (the other outputs 0)" : "");
    for (const engine::kernel_guard& g : k.guards)
        out += fmt::format("///   {}: {}\n", g.status, guard_meaning(d, k, g));
    out += fmt::format("///   {}: the values leave the type's range ({}a result not finite).\n", out_of_range,
                       divides ? "a divisor below\n///     detail::smallest_divisor or infinite, " : "");
}

std::string members_initialiser(const engine::kernel& k)
{
    // Outputs named after an input start as that input: a collision not resolved leaves
    // the velocities unchanged.
    std::vector<std::string> values;
    for (const engine::kernel_output& o : k.outputs) {
        const engine::kernel_parameter* same = k.find_parameter(o.member);
        values.push_back(same ? same->name : (o.is_array ? "{}" : "Real(0)"));
    }
    if (has_status(k))
        values.push_back("status::ok");
    return fmt::format("{{{}}}", fmt::join(values, ", "));
}

// One scalar input of a batch kernel: a component, its array in the batch data, and
// whether the batch writes it.
struct lane_input {
    std::string name;
    std::string field;
    bool written = false;
};

std::vector<lane_input> lane_inputs(const engine::kernel& k)
{
    std::vector<lane_input> inputs;
    for (const engine::kernel_parameter& p : k.parameters)
        for (std::size_t c = 0; c < p.components.size(); ++c)
            inputs.push_back({p.components[c].name,
                              p.is_array ? fmt::format("data.{}[{}]", p.name, c) : "data." + p.name,
                              is_output(k, p.name)});
    return inputs;
}

// The parameters of a batch loop: a pointer per scalar input (`restrict`), and the
// status array.
std::string loop_parameters(const std::vector<lane_input>& inputs, bool with_status)
{
    std::vector<std::string> pointers;
    for (const lane_input& in : inputs)
        pointers.push_back(fmt::format("{}Real* IMPACT_RESTRICT {}_", in.written ? "" : "const ", in.name));
    if (with_status)
        pointers.push_back("impact::status* IMPACT_RESTRICT status_");
    return fmt::format("{}", fmt::join(pointers, ", "));
}

// A line of a block loop asking for an array's data 64 pairs past block b.
std::string prefetch_ahead(const lane_input& in)
{
    return fmt::format("            IMPACT_PREFETCH({}_ + b + ahead, {});\n", in.name, in.written ? 1 : 0);
}

// The arguments a block loop passes to the loop for the block at b: each array from b.
std::vector<std::string> block_arguments(const std::vector<lane_input>& inputs, bool with_status)
{
    std::vector<std::string> from_block;
    for (const lane_input& in : inputs)
        from_block.push_back(fmt::format("{}_ + b", in.name));
    if (with_status)
        from_block.push_back("with_status ? status_ + b : status_");
    return from_block;
}

constexpr const char* status_ahead = "            if constexpr (with_status)\n"
                                     "                IMPACT_PREFETCH(status_ + b + ahead, 1);\n";

// The batch loop run over blocks of 8 pairs (a cache line of doubles), each array's
// data asked for 64 pairs ahead: out of cache, the hardware's prefetching alone leaves
// the loop waiting for memory (in 3D, 16 arrays streamed at once, a quarter slower).
void print_blocks(std::string& out, const std::string& loop, const std::vector<lane_input>& inputs, bool with_status)
{
    std::vector<std::string> ahead;
    for (const lane_input& in : inputs)
        ahead.push_back(prefetch_ahead(in));
    if (with_status)
        ahead.push_back(status_ahead);
    const std::string call = fmt::format("{}<Real{}>", loop, with_status ? ", with_status" : "");
    out += fmt::format("\n// {0} over blocks of 8 pairs, each array's data asked for 64 pairs ahead: the\n"
                       "// processor's own prefetching, following so many arrays, falls behind.\n"
                       "template <class Real{1}>\ninline void {0}_ahead(std::size_t count, {2}) noexcept\n{{\n"
                       "    constexpr std::size_t block = 8, ahead = 64;\n    std::size_t b = 0;\n"
                       "    for (; b + block <= count; b += block) {{\n        if (b + ahead < count) {{\n{3}        }}\n"
                       "        {4}(block, {5});\n    }}\n    {4}(count - b, {5});\n}}\n",
                       loop, with_status ? ", bool with_status" : "", loop_parameters(inputs, with_status),
                       fmt::join(ahead, ""), call, fmt::join(block_arguments(inputs, with_status), ", "));
}

// Whether a batch kernel gets a skewed block loop too, for arrays that crowd one page
// offset: one that streams 16 arrays or more. Measured out of cache, every array at one
// offset, against the plain block loop: the 3D collide (16 arrays) 1.00 -> 1.03-1.08 of
// the hand-written loop, 89-93 % -> 89-99 % of the triad's bandwidth; the 2D collide
// (12 arrays) 0.99-1.00 -> 0.95.
bool skews(const engine::kernel& k)
{
    constexpr std::size_t skewed_from = 16;
    return k.batch && lane_inputs(k).size() + (k.guards.empty() ? 0 : 1) >= skewed_from;
}

// The read-only arrays of a batch: the ones a skewed loop reads ahead.
std::vector<lane_input> read_only(const std::vector<lane_input>& inputs)
{
    std::vector<lane_input> read;
    std::copy_if(inputs.begin(), inputs.end(), std::back_inserter(read), [](const lane_input& in) { return !in.written; });
    return read;
}

// The batch loop over blocks of 8 pairs for arrays that start at one offset within their
// pages. Pair i of every array then falls on the same cache sets; the read-only array k
// is read 2 (k + 1) blocks ahead of its turn instead, into a ring of blocks on the stack,
// so that at any time the arrays are read at offsets 128 bytes apart, as if staggered
// (see `skews`; staggered arrays lose a tenth by it, and keep the plain block loop).
void print_skewed_blocks(std::string& out, const std::string& loop, const std::vector<lane_input>& inputs,
                         bool with_status)
{
    std::vector<std::string> ahead, starts, from_block = block_arguments(inputs, with_status);
    const std::vector<std::string> at_end = from_block;
    for (std::size_t i = 0; i < inputs.size(); ++i) {
        if (inputs[i].written) {
            ahead.push_back(prefetch_ahead(inputs[i]));
            continue;
        }
        // Asked for as many blocks further ahead as it is read ahead: one line an array, as
        // the plain loop asks (a loop over `from` here ran at 0.91-1.11 of the hand-written
        // loop from run to run, these lines at 1.04-1.10).
        ahead.push_back(fmt::format("            if (b + ahead + block * lead({0}) < count)\n"
                                    "                IMPACT_PREFETCH({1}_ + b + ahead + block * lead({0}), 0);\n",
                                    starts.size(), inputs[i].name));
        from_block[i] = fmt::format("stage[{}][r]", starts.size());
        starts.push_back(inputs[i].name + "_");
    }
    if (with_status)
        ahead.push_back(status_ahead);
    std::size_t ring = 1;
    while (ring <= 2 * starts.size())  // more blocks than the farthest lead
        ring *= 2;
    const std::string call = fmt::format("{}<Real{}>", loop, with_status ? ", with_status" : "");
    out += fmt::format(
        "\n// {0} over blocks of 8 pairs for arrays that start at one offset within their pages:\n"
        "// pair i of every array then falls on the same cache sets. The read-only array k is read\n"
        "// 2 (k + 1) blocks ahead of its turn, into a ring of blocks, so that the arrays are read\n"
        "// at offsets 128 bytes apart, as if staggered.\n"
        "template <class Real{1}>\ninline void {0}_skewed(std::size_t count, {2}) noexcept\n{{\n"
        "    constexpr std::size_t block = 8, ahead = 64, ring = {3}, read_only = {4};\n"
        "    const Real* const from[read_only] = {{{5}}};\n"
        "    alignas(64) Real stage[read_only][ring][block];\n"
        "    auto lead = [](std::size_t k) {{ return 2 * (k + 1); }};\n"
        "    auto read = [&](std::size_t k, std::size_t j) {{\n"
        "        for (std::size_t i = 0; i < block; ++i)\n"
        "            stage[k][j % ring][i] = from[k][j * block + i];\n"
        "    }};\n"
        "    const std::size_t blocks = count / block;\n"
        "    for (std::size_t k = 0; k < read_only; ++k)\n"
        "        for (std::size_t j = 0; j < lead(k) && j < blocks; ++j)\n"
        "            read(k, j);\n"
        "    std::size_t b = 0;\n"
        "    for (std::size_t j = 0; j < blocks; ++j, b += block) {{\n"
        "        if (b + ahead < count) {{\n{6}        }}\n"
        "        for (std::size_t k = 0; k < read_only; ++k)\n"
        "            if (j + lead(k) < blocks)\n"
        "                read(k, j + lead(k));\n"
        "        const std::size_t r = j % ring;\n"
        "        {7}(block, {8});\n"
        "    }}\n"
        "    {7}(count - b, {9});\n}}\n",
        loop, with_status ? ", bool with_status" : "", loop_parameters(inputs, with_status), ring, starts.size(),
        fmt::join(starts, ", "), fmt::join(ahead, ""), call, fmt::join(from_block, ", "), fmt::join(at_end, ", "));
}

// The values a batch loop's arithmetic can hold at once: AVX-512 has 32 vector registers,
// and the loop also holds constants (0, 1, a divisor's bounds) and statuses. A program
// that holds more in the order it was compiled in is printed in an order for registers
// (ordered_for_registers): the compiler loads a value it cannot keep in a register again
// from its array, and spills others. The 3D collide holds 29 values at once as compiled,
// 21 ordered; ordered, its batch ran at 1.08 of the hand-written loop in cache, where it
// had run at 1.00 side by side. The 2D collide (21) keeps its order: ordered, it lost 8 %
// in cache, where the order compiled in, one operation across every coordinate, then the
// next, gives the processor more independent work side by side.
constexpr std::size_t batch_registers = 24;

// The batch kernel: a loop without branches, so that compilers vectorise it. Each pair's
// status is decided as the scalar kernel decides it (the guards in reverse order, so that
// the first failing one wins); every pair is computed, one not resolved dividing by 1 (no
// division by zero) and its results discarded. A resolved pair runs the scalar kernel's
// operations on the same values: the same results, bit for bit, under the same
// floating-point contraction.
void print_batch(std::string& out, const kernel_plan& plan)
{
    const engine::kernel& k = *plan.kernel;
    const std::size_t n = dimension(k);
    const std::vector<lane_input> inputs = lane_inputs(k);
    const std::string loop = fmt::format("{}_batch_{}d", k.name, n);

    std::vector<std::string> element_names, plain_names, arguments;
    for (const lane_input& in : inputs) {
        element_names.push_back(in.name + "_[i]");
        plain_names.push_back(in.name);
        arguments.push_back(in.field);
    }
    const bool with_status = !k.guards.empty();

    out += fmt::format("\nnamespace detail {{\n\n// The loop of {}_batch in {}D, without branches; inlined where it is called, so that a\n"
                       "// block's call runs one pass of 8 pairs.\n", k.name, n);
    out += fmt::format("template <class Real{}>\nIMPACT_ALWAYS_INLINE void {}(std::size_t count, {}) noexcept\n{{\n"
                       "    IMPACT_INDEPENDENT_ITERATIONS\n    for (std::size_t i = 0; i < count; ++i) {{\n",
                       with_status ? ", bool with_status" : "", loop, loop_parameters(inputs, with_status));

    // The status, from the guards on the values as given.
    const std::vector<bool> for_guards = needed_by(plan.code, 0, plan.guard_values);
    if (with_status) {
        // The scalar kernel tests the inputs' domains first, then the conditions computed
        // from them; a lane whose inputs are refused divides by 1 in those computations.
        std::vector<const engine::kernel_guard*> domains, conditions;
        for (const engine::kernel_guard& g : k.guards)
            (g.condition ? conditions : domains).push_back(&g);
        out += "        // The status, as the scalar kernel decides it: the first guard that fails.\n"
               "        // (x * 0 is 0 for a finite x and NaN otherwise: one sum tests many values.)\n"
               "        impact::status outcome = status::ok;\n        {\n";
        // `fails |= test`, not `||`: no branch, so that the loop vectorises.
        bool declared = false;
        auto fail_with = [&](const std::vector<std::string>& failures, const std::string& status, const char* into) {
            for (std::size_t f = 0; f < failures.size(); ++f)
                out += fmt::format("            {} {};\n", f == 0 ? (declared ? "fails =" : "bool fails =") : "fails |=",
                                   failures[f]);
            out += fmt::format("            {0} = fails ? status::{1} : {0};\n", into, status);
            declared = true;
        };
        for (auto g = domains.rbegin(); g != domains.rend(); ++g)
            fail_with(batch_failures(guard_tests(k, **g, "_[i]")), (*g)->status, "outcome");
        if (!conditions.empty()) {
            // A separate status for the conditions, taken where the domains admit the
            // inputs (GCC vectorises this, not `fails &= admitted`).
            out += "            const bool admitted = outcome == status::ok;\n"
                   "            impact::status condition = status::ok;\n";
            const cxx_code given = program_cxx(plan.code, element_names, "admitted");
            for (std::size_t s = 0; s < given.statements.size(); ++s)
                if (for_guards[given.statement_values[s]])
                    out += "            " + given.statements[s] + "\n";
            for (std::size_t c = conditions.size(); c-- > 0;)
                fail_with({condition_failure(given.outputs[c], *conditions[c])}, conditions[c]->status, "condition");
            out += "            outcome = admitted ? condition : outcome;\n";
        }
        out += "        }\n        const bool resolved = outcome == status::ok;\n";
    }

    // The arithmetic, every lane computed; a lane not resolved divides by 1.
    if (with_status)
        out += "        // Every pair is computed; one not resolved divides by 1, and its results are discarded.\n";
    for (const lane_input& in : inputs)
        out += fmt::format("        const Real {0} = {0}_[i];\n", in.name);
    compile::program outputs_only = plan.code;  // the guards' values are computed above
    outputs_only.outputs.erase(outputs_only.outputs.begin(),
                               outputs_only.outputs.begin() + static_cast<long>(plan.guard_values));
    const bool for_registers = compile::most_live(outputs_only) > batch_registers;
    const compile::program arithmetic = for_registers ? compile::ordered_for_registers(outputs_only) : outputs_only;
    const std::vector<bool> for_outputs = compile::needed_by(arithmetic, 0, arithmetic.outputs.size());
    const cxx_code code = program_cxx(arithmetic, plain_names, with_status ? "usable" : "");
    // A resolved pair is divided only by divisors in range (`usable`), and its results are
    // written only if finite (`written`), as the scalar kernel decides. (`&&` here, which
    // GCC if-converts; with `&`, it leaves the loop's conditional stores unvectorised.)
    const auto declare_usable = [&] {
        std::vector<std::string> in_range{"resolved"};
        for (const std::string& test : divisors_in_range(code))
            in_range.push_back(test);
        out += fmt::format("        const bool usable = {};\n", fmt::join(in_range, " && "));
    };
    if (with_status && code.divisors_known == 0)
        declare_usable();
    for (std::size_t s = 0; s < code.statements.size(); ++s) {
        if (for_outputs[code.statement_values[s]])
            out += "        " + code.statements[s] + "\n";
        if (with_status && s + 1 == code.divisors_known)
            declare_usable();
    }
    std::vector<std::pair<std::string, std::string>> writes;  // target, value
    std::size_t value = 0;
    for (const engine::kernel_output& o : k.outputs) {
        for (std::size_t c = 0; c < o.values.size(); ++c, ++value) {
            const engine::kernel_parameter* same = k.find_parameter(o.member);
            if (!same)
                throw std::logic_error("a batch kernel writes only outputs named after inputs");
            writes.emplace_back(same->components.at(c).name, code.outputs[value]);
        }
    }
    if (with_status) {
        std::vector<std::string> results;
        for (const auto& [target, result] : writes) {
            out += fmt::format("        const Real {}_out = {};\n", target, result);
            results.push_back(target + "_out");
        }
        // In a loop ordered for registers, the results' test is computed for every pair, in
        // statements of its own. As a condition after `usable &&`, GCC computed it only
        // where `usable` held, and the ordered 3D loop loaded 49 vectors of the arrays per
        // 8 pairs, not 45 (the hand-written loop: 36); out of cache, with every array at the
        // same page offset, where each such load misses, it ran at 0.98-0.99 of the
        // hand-written loop, not 1.01-1.02. The 2D loop, in its own order, runs better with
        // the test in place (there, 1.00-1.02 against 0.98).
        int names = 0;
        const std::string finite = all_finite(results, [&](const std::string& term, bool is_sum) {
            if (!for_registers)
                return in_place(term, is_sum);
            const std::string name = fmt::format("finite{}", names++);
            out += fmt::format("        const Real {} = {};\n", name, term);
            return name;
        });
        out += fmt::format("        const bool written = usable && {};\n", finite);
        for (const auto& [target, result] : writes)
            out += fmt::format("        {0}_[i] = written ? {0}_out : {0}_[i];\n", target);
        out += fmt::format("        if constexpr (with_status)\n"
                           "            status_[i] = resolved && !written ? status::{} : outcome;\n",
                           out_of_range);
    } else {
        for (const auto& [target, result] : writes)
            out += fmt::format("        {}_[i] = {};\n", target, result);
    }
    out += "    }\n}\n";
    print_blocks(out, loop, inputs, with_status);
    if (skews(k))
        print_skewed_blocks(out, loop, inputs, with_status);
    out += "\n} // namespace detail\n";

    // The public entry point.
    out += fmt::format("\n/// {0} over `count` collisions stored as structure of arrays: outputs named after\n"
                       "/// inputs are updated in place.{1}\n"
                       "/// The loop has no branches, so that compilers vectorise it; each result is bit for\n"
                       "/// bit the scalar {0}'s (compiled alike, e.g. -ffp-contract=off). The arrays written\n"
                       "/// must not overlap any other array.\n",
                       k.name, with_status ? " `status` (if not null) receives each status." : "");
    out += fmt::format("template <class Real>\ninline void {0}_batch(const {0}_batch_data<Real, {1}>& data) noexcept\n{{\n",
                       k.name, n);
    if (skews(k)) {
        std::vector<std::string> read_starts;
        for (const lane_input& in : read_only(inputs))
            read_starts.push_back(in.field);
        const std::string skewed =
            with_status ? fmt::format("            if (data.status)\n                detail::{0}_skewed<Real, true>(data.count, {1}, data.status);\n"
                                      "            else\n                detail::{0}_skewed<Real, false>(data.count, {1}, nullptr);\n",
                                      loop, fmt::join(arguments, ", "))
                        : fmt::format("            detail::{}_skewed<Real>(data.count, {});\n", loop, fmt::join(arguments, ", "));
        out += fmt::format("    // Arrays of doubles that crowd one page offset are read skewed (the blocks and the\n"
                           "    // distances are a double's; other types keep the plain loop).\n"
                           "    if constexpr (sizeof(Real) == sizeof(double))\n"
                           "        if (detail::crowded(std::array<const void*, {0}>{{{1}}})) {{\n{2}            return;\n        }}\n",
                           read_starts.size(), fmt::join(read_starts, ", "), skewed);
    }
    if (with_status)
        out += fmt::format("    if (data.status)\n        detail::{0}_ahead<Real, true>(data.count, {1}, data.status);\n"
                           "    else\n        detail::{0}_ahead<Real, false>(data.count, {1}, nullptr);\n",
                           loop, fmt::join(arguments, ", "));
    else
        out += fmt::format("    detail::{}_ahead<Real>(data.count, {});\n", loop, fmt::join(arguments, ", "));
    out += "}\n";
}

void print_kernel(std::string& out, const engine::derivation& d, const kernel_plan& plan)
{
    const engine::kernel& k = *plan.kernel;
    const std::size_t n = dimension(k);

    if (!returns_scalar(k) && n == 0) {
        out += fmt::format("\n/// What {} returns.\ntemplate <class Real>\nstruct {}_result {{\n", k.name, k.name);
        for (const engine::kernel_output& o : k.outputs)
            out += fmt::format("    Real {};\n", o.member);
        if (has_status(k))
            out += "    impact::status status;\n";
        out += "};\n";
    }

    // The arithmetic, the inputs' components referred to by name.
    std::vector<std::string> component_names;
    for (const engine::kernel_parameter& p : k.parameters)
        for (const engine::quantity& q : p.components)
            component_names.push_back(q.name);
    const cxx_code code = program_cxx(plan.code, component_names);

    // Documentation: inputs, and how each output is computed and how accurate it is.
    std::vector<std::string> names;
    for (const engine::kernel_parameter& p : k.parameters)
        names.push_back(p.name);
    out += fmt::format("\n/// {}({}): {}{}.\n", k.name, fmt::join(names, ", "), d.source.title.value,
                       d.source.paper ? ", " + d.source.paper->value : "");
    for (const engine::kernel_parameter& p : k.parameters)
        for (const engine::quantity& q : p.components)
            out += fmt::format("///   {}{}\n", p.is_array ? p.name + ": " : "", describe(q));
    for (const verify::component_plan& cp : plan.components) {
        const verify::candidate_result& c = cp.candidates[cp.chosen];
        out += fmt::format("/// {} is computed in the form \"{}\": at most {:.2f} ulps in double on {} samples.\n",
                           cp.name, c.label, c.double_accuracy.max_ulps, c.double_accuracy.samples);
    }
    print_guards_documentation(out, d, k, !code.divisors.empty());

    std::vector<std::string> parameters;
    for (const engine::kernel_parameter& p : k.parameters)
        parameters.push_back(parameter_type(p) + " " + p.name);
    out += fmt::format("template <class Real>\ninline {} {}({}) noexcept\n{{\n", result_type(k), k.name,
                       fmt::join(parameters, ", "));

    // Components of array parameters by name.
    for (const engine::kernel_parameter& p : k.parameters) {
        for (std::size_t c = 0; c < p.components.size(); ++c) {
            if (p.is_array)
                out += fmt::format("    const Real {} = {}[{}];\n", p.components[c].name, p.name, c);
            else if (p.components[c].name != p.name)
                out += fmt::format("    const Real {} = {};\n", p.components[c].name, p.name);
        }
    }

    if (!returns_scalar(k))
        out += fmt::format("    {} out{};\n", result_type(k), members_initialiser(k));

    // Guards on the inputs' domains, then the statements their conditions need, then
    // the conditions.
    for (const engine::kernel_guard& g : k.guards) {
        if (g.condition)
            continue;
        print_refusal(out, k, scalar_failures(guard_tests(k, g, "")), g.status);
    }
    const int last_guard_value = plan.guard_values ? plan.code.outputs[plan.guard_values - 1] : -1;
    std::size_t s = 0;
    for (; s < code.statements.size() && code.statement_values[s] <= last_guard_value; ++s)
        out += "    " + code.statements[s] + "\n";
    std::size_t condition = 0;
    for (const engine::kernel_guard& g : k.guards) {
        if (!g.condition)
            continue;
        print_refusal(out, k, {condition_failure(code.outputs[condition++], g)}, g.status);
    }
    const bool with_status = !k.guards.empty();  // a status, or a NaN for a scalar
    const auto refuse_divisors_out_of_range = [&] {
        std::vector<std::string> failures;
        for (const std::string& test : with_status ? divisors_in_range(code) : std::vector<std::string>{})
            failures.push_back("!" + test);
        if (!failures.empty())
            print_refusal(out, k, failures, out_of_range);
    };
    if (s >= code.divisors_known)
        refuse_divisors_out_of_range();
    for (; s < code.statements.size(); ++s) {
        out += "    " + code.statements[s] + "\n";
        if (s + 1 == code.divisors_known)
            refuse_divisors_out_of_range();
    }
    std::vector<std::string> results(code.outputs.begin() + static_cast<long>(plan.guard_values), code.outputs.end());
    if (with_status) {
        std::vector<std::string> failures;
        for (std::size_t r = 0; r < results.size(); ++r) {
            out += fmt::format("    const Real result{} = {};\n", r, results[r]);
            results[r] = fmt::format("result{}", r);
            failures.push_back(fmt::format("!std::isfinite({})", results[r]));
        }
        print_refusal(out, k, failures, out_of_range);
    }

    if (returns_scalar(k)) {
        out += fmt::format("    return {};\n}}\n", results.front());
    } else {
        std::size_t i = 0;
        for (const engine::kernel_output& o : k.outputs) {
            if (!o.is_array) {
                out += fmt::format("    out.{} = {};\n", o.member, results[i++]);
                continue;
            }
            std::vector<std::string> components;
            for (std::size_t c = 0; c < o.values.size(); ++c)
                components.push_back(results[i++]);
            out += fmt::format("    out.{} = {{{}}};\n", o.member, fmt::join(components, ", "));
        }
        out += "    return out;\n}\n";
    }

    if (k.batch)
        print_batch(out, plan);
}

} // namespace

std::string kernel_header_name(const engine::derivation& d)
{
    if (d.kernels.size() != 1)
        return d.id() + ".hpp";
    const engine::kernel& k = d.kernels.front();
    for (const engine::kernel_parameter& p : k.parameters)
        if (p.is_array)
            return fmt::format("{}_{}d.hpp", k.name, p.components.size());
    return k.name + ".hpp";
}

std::string kernel_header(const engine::derivation& d, const std::vector<const kernel_plan*>& plans)
{
    std::string out = fmt::format("// Generated by Impact from {}; do not edit.\n", d.source_name());
    out += fmt::format("// {}{}.\n", d.source.title.value,
                       d.source.paper ? fmt::format(" ({} of the paper)", d.source.paper->value) : "");
    out += "#pragma once\n\n#include \"common.hpp\"\n\nnamespace impact {\n";
    for (const kernel_plan* plan : plans)
        print_kernel(out, d, *plan);
    out += "\n} // namespace impact\n";
    return out;
}

// The arrays of `<name>_batch_data`, owned, in a layout that keeps a large batch fast: one
// allocation, array k starting 64 + 256 k bytes (modulo 4 KiB) past a page boundary.
void print_batch_arrays(std::string& out, const engine::kernel& k)
{
    // Each parameter's first array among all, as C++ in N: the scalars before it, and N
    // arrays for each array parameter before it.
    std::vector<std::string> first;
    std::size_t scalars = 0, arrays = 0;
    auto index = [&] {
        if (arrays == 0)
            return std::to_string(scalars);
        return fmt::format("{}{}N", scalars == 0 ? "" : std::to_string(scalars) + " + ",
                           arrays == 1 ? "" : std::to_string(arrays) + " * ");
    };
    for (const engine::kernel_parameter& p : k.parameters) {
        first.push_back(index());
        ++(p.is_array ? arrays : scalars);
    }
    const std::string reals = index();
    const bool with_status = !k.guards.empty();

    out += fmt::format(
        "\n/// The arrays of {0}_batch_data, owned: one allocation holds them all, array k starting\n"
        "/// 64 + 256 k bytes (modulo 4 KiB) past a page boundary. Arrays allocated one by one all\n"
        "/// start at one offset within their pages: pair i of every array then falls on the same\n"
        "/// cache sets, and a large batch runs about a fifth slower. Each array holds `count`\n"
        "/// values, not initialised, and starts on a 64-byte boundary. The constructor throws\n"
        "/// std::bad_alloc, or std::bad_array_new_length for a count no allocation can hold.\n"
        "/// Move-only; an object moved from holds no arrays.\n"
        "template <class Real, std::size_t N>\nclass {0}_batch_arrays {{\npublic:\n"
        "    static_assert(std::is_floating_point_v<Real>, \"{0}_batch_arrays holds floating-point values\");\n\n"
        "    explicit {0}_batch_arrays(std::size_t count) : count_(count)\n    {{\n"
        "        // Each array padded to whole pages plus `apart`; the bytes in all must not wrap around.\n"
        "        constexpr std::size_t most = (std::numeric_limits<std::size_t>::max() - first - reals * (page + apart)) / per_pair;\n"
        "        if (count > most)\n"
        "            throw std::bad_array_new_length();\n"
        "        stride_ = (count * sizeof(Real) + page - 1) / page * page + apart;\n"
        "        block_ = static_cast<unsigned char*>(::operator new(first + reals * stride_{1}, std::align_val_t{{page}}));\n"
        "        for (std::size_t a = 0; a < reals; ++a)\n"
        "            std::uninitialized_default_construct_n(at<Real>(a), count);\n",
        k.name, with_status ? " + count * sizeof(impact::status)" : "");
    if (with_status)
        out += "        std::uninitialized_default_construct_n(at<impact::status>(reals), count);\n";
    out += fmt::format(
        "    }}\n"
        "    {0}_batch_arrays({0}_batch_arrays&& other) noexcept {{ swap(other); }}\n"
        "    {0}_batch_arrays& operator=({0}_batch_arrays&& other) noexcept\n    {{\n"
        "        {0}_batch_arrays(std::move(other)).swap(*this);\n        return *this;\n    }}\n"
        "    {0}_batch_arrays(const {0}_batch_arrays&) = delete;\n"
        "    {0}_batch_arrays& operator=(const {0}_batch_arrays&) = delete;\n"
        "    ~{0}_batch_arrays()\n    {{\n"
        "        if (block_)\n            ::operator delete(block_, std::align_val_t{{page}});\n    }}\n\n"
        "    std::size_t count() const noexcept {{ return count_; }}\n",
        k.name);
    for (std::size_t i = 0; i < k.parameters.size(); ++i) {
        const engine::kernel_parameter& p = k.parameters[i];
        const std::string axis = p.is_array ? "std::size_t axis" : "";
        const std::string where = first[i] + (p.is_array ? " + axis" : "");
        out += fmt::format("    Real* {0}({1}) noexcept {{ return at<Real>({2}); }}\n"
                           "    const Real* {0}({1}) const noexcept {{ return at<Real>({2}); }}\n",
                           p.name, axis, where);
    }
    if (with_status)
        out += "    impact::status* status() noexcept { return at<impact::status>(reals); }\n"
               "    const impact::status* status() const noexcept { return at<impact::status>(reals); }\n";
    out += fmt::format("\n    /// The arrays as {0}_batch takes them.\n"
                       "    {0}_batch_data<Real, N> data() noexcept\n    {{\n"
                       "        {0}_batch_data<Real, N> d{{}};\n        d.count = count_;\n",
                       k.name);
    for (const engine::kernel_parameter& p : k.parameters) {
        if (p.is_array)
            out += fmt::format("        for (std::size_t axis = 0; axis < N; ++axis)\n"
                               "            d.{0}[axis] = {0}(axis);\n",
                               p.name);
        else
            out += fmt::format("        d.{0} = {0}();\n", p.name);
    }
    if (with_status)
        out += "        d.status = status();\n";
    out += fmt::format(
        "        return d;\n    }}\n\n"
        "private:\n"
        "    static constexpr std::size_t reals = {0};  // the arrays of Real{1}\n"
        "    static constexpr std::size_t page = 4096, apart = 256, first = 64;\n"
        "    static constexpr std::size_t per_pair = reals * sizeof(Real){2};  // bytes\n"
        "    template <class T>\n"
        "    T* at(std::size_t a) const noexcept\n    {{\n"
        "        return block_ ? reinterpret_cast<T*>(block_ + first + a * stride_) : nullptr;\n    }}\n"
        "    void swap({3}_batch_arrays& other) noexcept\n    {{\n"
        "        std::swap(count_, other.count_);\n        std::swap(stride_, other.stride_);\n"
        "        std::swap(block_, other.block_);\n    }}\n\n"
        "    std::size_t count_ = 0;\n"
        "    std::size_t stride_ = 0;  // bytes from one array's start to the next\n"
        "    unsigned char* block_ = nullptr;\n"
        "}};\n",
        reals, with_status ? ", then the statuses" : "", with_status ? " + sizeof(impact::status)" : "", k.name);
}

std::string common_header(const std::vector<const kernel_plan*>& plans)
{
    std::string out = "// Generated by Impact from derivations/; do not edit.\n"
                      "// What Impact's kernels share.\n#pragma once\n\n"
                      "#include <array>\n#include <cmath>\n#include <cstddef>\n#include <cstdint>\n#include <limits>\n"
                      "#include <memory>\n#include <new>\n#include <type_traits>\n#include <utility>\n\n"
                      "// The arrays a batch kernel writes overlap no other array (`restrict`), and its\n"
                      "// iterations are independent: compilers may vectorise its loop.\n"
                      "#if defined(__GNUC__) || defined(__clang__) || defined(_MSC_VER)\n"
                      "#define IMPACT_RESTRICT __restrict\n#else\n#define IMPACT_RESTRICT\n#endif\n"
                      "#if defined(__GNUC__) && !defined(__clang__)  // Clang needs no more than `restrict`\n"
                      "#define IMPACT_INDEPENDENT_ITERATIONS _Pragma(\"GCC ivdep\")\n"
                      "#else\n#define IMPACT_INDEPENDENT_ITERATIONS\n#endif\n"
                      "// Asks for the cache line at p ahead of its use (for writing if `write`): a batch loop\n"
                      "// streams so many arrays at once that the processor's own prefetching falls behind.\n"
                      "#if defined(__GNUC__) || defined(__clang__)\n"
                      "#define IMPACT_PREFETCH(p, write) __builtin_prefetch((p), (write))\n"
                      "#else\n#define IMPACT_PREFETCH(p, write) ((void)0)\n#endif\n"
                      "// A function inlined wherever it is called, whatever the compiler's estimate of the cost.\n"
                      "#if defined(__GNUC__) || defined(__clang__)\n"
                      "#define IMPACT_ALWAYS_INLINE inline __attribute__((always_inline))\n"
                      "#elif defined(_MSC_VER)\n#define IMPACT_ALWAYS_INLINE __forceinline\n"
                      "#else\n#define IMPACT_ALWAYS_INLINE inline\n#endif\n\n"
                      "namespace impact {\n";
    // The statuses in the order of the kernels with the most guards first (a kernel returning
    // a scalar returns NaN instead): a kernel whose guards are a subset of another's, such as
    // collide_line's of collide's, leaves the values as they were. (Values matter beyond
    // compatibility: with separating and coincident_centres swapped, GCC 12 no longer
    // vectorised the 2D batch loop for AVX-512.)
    std::vector<const engine::kernel*> guarded;
    for (const kernel_plan* plan : plans)
        if (has_status(*plan->kernel))
            guarded.push_back(plan->kernel);
    std::stable_sort(guarded.begin(), guarded.end(), [](const engine::kernel* a, const engine::kernel* b) {
        return a->guards.size() > b->guards.size();
    });
    std::vector<std::string> statuses{"ok"};
    for (const engine::kernel* k : guarded)
        for (const engine::kernel_guard& g : k->guards)
            if (std::find(statuses.begin(), statuses.end(), g.status) == statuses.end())
                statuses.push_back(g.status);
    if (statuses.size() > 1)
        statuses.push_back(out_of_range);
    out += fmt::format("\n/// Why a kernel resolved no collision; `ok` when it did.\n"
                       "/// As wide as a double, so that a vectorised batch loop over doubles keeps one\n"
                       "/// width in every lane: with a narrower status, compilers pack two vectors of\n"
                       "/// doubles per vector of statuses, and the loop runs short of registers.\n"
                       "enum class status : std::int64_t {{ {} }};\n",
                       fmt::join(statuses, ", "));
    if (statuses.size() > 1)
        out += fmt::format("\nnamespace detail {{\n\n"
                           "/// The smallest divisor a kernel divides by: below it, the divisor's rounding errors\n"
                           "/// are no longer normal numbers and compensated arithmetic loses its precision. A\n"
                           "/// smaller divisor, or a result that is not finite, gives status::{}.\n"
                           "template <class Real>\nconstexpr Real smallest_divisor =\n"
                           "    std::numeric_limits<Real>::min() / std::numeric_limits<Real>::epsilon();\n\n"
                           "}} // namespace detail\n",
                           out_of_range);

    if (std::any_of(plans.begin(), plans.end(), [](const kernel_plan* plan) { return skews(*plan->kernel); }))
        out += "\nnamespace detail {\n\n"
               "/// Whether more than half of a batch's read-only arrays start within 256 bytes of one\n"
               "/// another, modulo 4 KiB, as arrays allocated one by one do (each a page boundary plus\n"
               "/// the allocator's header): their pairs i then fall on the same cache sets.\n"
               "template <std::size_t K>\n"
               "inline bool crowded(const std::array<const void*, K>& starts) noexcept\n{\n"
               "    std::size_t most = 0;\n"
               "    for (const void* a : starts) {\n"
               "        std::size_t near = 0;\n"
               "        for (const void* b : starts)\n"
               "            if ((reinterpret_cast<std::uintptr_t>(b) - reinterpret_cast<std::uintptr_t>(a)) % 4096 < 256)\n"
               "                ++near;\n"
               "        most = near > most ? near : most;\n"
               "    }\n"
               "    return 2 * most > K;\n}\n\n"
               "} // namespace detail\n";

    // Array kernels are emitted in several dimensions; their structures are templates
    // on the dimension, written once.
    std::set<std::string> written;
    for (const kernel_plan* plan : plans) {
        const engine::kernel& k = *plan->kernel;
        if (dimension(k) == 0 || !written.insert(k.name).second)
            continue;
        out += fmt::format("\n/// What {} returns in N dimensions.\ntemplate <class Real, std::size_t N>\nstruct {}_result {{\n",
                           k.name, k.name);
        for (const engine::kernel_output& o : k.outputs)
            out += fmt::format("    {} {};\n", o.is_array ? "std::array<Real, N>" : "Real", o.member);
        if (!k.guards.empty())
            out += "    impact::status status;\n";
        out += "};\n";
        if (!k.batch)
            continue;
        out += fmt::format("\n/// Structure-of-arrays data for {}_batch: one array per scalar, N per vector.\n"
                           "/// The arrays written (velocities, status) must not overlap any other.\n"
                           "template <class Real, std::size_t N>\nstruct {}_batch_data {{\n    std::size_t count;\n",
                           k.name, k.name);
        for (const engine::kernel_parameter& p : k.parameters) {
            const std::string pointer = is_output(k, p.name) ? "Real*" : "const Real*";
            if (p.is_array)
                out += fmt::format("    std::array<{}, N> {};\n", pointer, p.name);
            else
                out += fmt::format("    {} {};\n", pointer, p.name);
        }
        if (!k.guards.empty())
            out += "    impact::status* status;\n";
        out += "};\n";
        print_batch_arrays(out, k);
    }
    out += "\n} // namespace impact\n";
    return out;
}

std::string umbrella_header(const std::vector<const engine::derivation*>& with_kernels)
{
    std::string out = "// Generated by Impact from derivations/; do not edit.\n"
                      "// Every kernel Impact emits, in one include.\n#pragma once\n\n#include \"common.hpp\"\n";
    for (const engine::derivation* d : with_kernels)
        out += fmt::format("#include \"{}\"\n", kernel_header_name(*d));
    return out;
}

std::map<std::string, std::string> kernel_files(const engine::library& lib,
                                                const std::vector<verify::kernel_plan>& plans)
{
    std::map<std::string, std::string> files;
    std::map<std::string, std::string> written_by;   // header → the derivation it is for
    std::vector<const engine::derivation*> with_kernels;
    std::vector<const verify::kernel_plan*> all;
    std::size_t next = 0;
    for (const engine::derivation* d : lib.in_order()) {
        if (d->kernels.empty())
            continue;
        with_kernels.push_back(d);
        std::vector<const verify::kernel_plan*> own;
        for (std::size_t i = 0; i < d->kernels.size(); ++i)
            own.push_back(&plans[next++]);
        all.insert(all.end(), own.begin(), own.end());
        const std::string header = "kernels/impact/" + kernel_header_name(*d);
        if (const auto taken = written_by.find(header); taken != written_by.end())
            throw error({d->source.file, 0, 0},
                        fmt::format("the kernels of derivation '{}' would be written to {}, as those of '{}' are; "
                                    "give its kernel another name",
                                    d->id(), header, taken->second));
        written_by[header] = d->id();
        files[header] = kernel_header(*d, own);
    }
    files["kernels/impact/common.hpp"] = common_header(all);
    files["kernels/impact/impact.hpp"] = umbrella_header(with_kernels);
    return files;
}

} // namespace impact::emit
