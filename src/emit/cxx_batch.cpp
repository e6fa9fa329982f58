// The batch kernel over structure-of-arrays data: a loop without branches that compilers
// vectorise, run over blocks that ask for their data ahead, or skewed for arrays that
// crowd one page offset (those block loops, the loop's parameters and the scalar kernel's
// `settle` are in cxx_batch_blocks.cpp; the arrays of a batch in one allocation in
// cxx_batch_arrays.cpp).
#include "emit/cxx_batch_blocks.h"
#include "emit/cxx_parts.h"
#include "emit/program_cxx.h"

#include <fmt/format.h>

#include <algorithm>
#include <functional>
#include <iterator>
#include <set>
#include <stdexcept>

namespace impact::emit::cxx_detail {
namespace {

// The batch loop's form: the comparisons, then one test for every value that must be
// finite. x * 0 is 0 for a finite x and NaN for an infinite or NaN one, so a sum of such
// products is 0 exactly when every x is finite (detail::zero_if_finite, which tests the bits
// where the compiler may take every value as finite). Fused, a value costs one operation, where
// std::isfinite costs two and a merge of the results (the guards were a third of the
// loop's instructions). The sum is a balanced tree, not a chain: the test gates the loop's
// division and its stores, and a chain of 12 dependent operations delayed both (docs/design-kernels.md,
// "How the batch loops were shaped", has the measurements).
// Each term of the sum is written as `term` gives it (in place by default).
using term_writer = std::function<std::string(const std::string& term, bool is_sum)>;

std::string in_place(const std::string& term, bool is_sum)
{
    return is_sum ? "(" + term + ")" : term;
}

std::string all_finite(const std::vector<std::string>& values, const term_writer& term = in_place)
{
    if (values.size() == 1)
        return fmt::format("detail::finite({})", values.front());
    std::vector<std::string> terms;  // x * 0 + y * 0 for the values two by two
    for (std::size_t v = 0; v < values.size(); v += 2)
        terms.push_back(term(v + 1 < values.size()
                                 ? fmt::format("detail::zero_if_finite({}, {})", values[v], values[v + 1])
                                 : fmt::format("detail::zero_if_finite({})", values[v]),
                             false));
    while (terms.size() > 1) {
        std::vector<std::string> sums;
        for (std::size_t t = 0; t < terms.size(); t += 2)
            sums.push_back(t + 1 < terms.size() ? term(terms[t] + " + " + terms[t + 1], true) : terms[t]);
        terms = std::move(sums);
    }
    return fmt::format("({} == Real(0))", terms.front());
}

// The sum of `terms` as a balanced tree: ((a + b) + (c + d)) ...
std::string balanced_sum(std::vector<std::string> terms)
{
    while (terms.size() > 1) {
        std::vector<std::string> sums;
        for (std::size_t t = 0; t < terms.size(); t += 2)
            sums.push_back(t + 1 < terms.size() ? "(" + terms[t] + " + " + terms[t + 1] + ")" : terms[t]);
        terms = std::move(sums);
    }
    return terms.front();
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

// The values a batch loop's arithmetic can hold at once: AVX-512 has 32 vector registers,
// and the loop also holds constants (0, 1, a divisor's bounds) and statuses. A program
// that holds more in the order it was compiled in is printed in an order for registers
// (ordered_for_registers): the compiler loads a value it cannot keep in a register again
// from its array, and spills others. The 3D collide holds 29 values at once as compiled,
// 21 ordered, and gains by the order; the 2D collide (21) keeps its own, one operation
// across every coordinate, then the next, which gives the processor more independent work
// side by side (docs/design-kernels.md, "How the batch loops were shaped").
constexpr std::size_t batch_registers = 24;

} // namespace

// The batch kernel: a loop without branches, so that compilers vectorise it. Each pair's
// status is decided as the scalar kernel decides it (the guards in reverse order, so that
// the first failing one wins); every pair is computed, one not resolved dividing by 1 (no
// division by zero) and its results discarded. A resolved pair runs the scalar kernel's
// operations on the same values: the same results, bit for bit, under the same
// floating-point contraction.
void print_batch(std::string& out, const kernel_plan& plan, form which)
{
    const engine::kernel& k = *plan.kernel;
    const std::size_t n = dimension(k);
    const std::vector<lane_input> inputs = lane_inputs(k);
    const bool fast = which == form::fast;
    // The fast loop's name ends in `_fast`, which no accurate loop's (`_<n>d`, `_loop`) does.
    // (`_loop` for a kernel of scalars alone.)
    const std::string loop =
        n ? fmt::format("{}_batch_{}d{}", k.name, n, fast ? "_fast" : "") : fmt::format("{}_batch_loop{}", k.name, fast ? "_fast" : "");

    // The arithmetic's inputs by name (an output's own array is none of them), and every
    // array's field of the batch data.
    std::vector<std::string> element_names, plain_names, arguments;
    for (const lane_input& in : inputs) {
        if (!in.fresh) {
            element_names.push_back(in.name + "_[i]");
            plain_names.push_back(in.name);
        }
        arguments.push_back(in.field);
    }
    const bool with_status = !k.guards.empty();
    // The arithmetic, every lane computed (a lane not resolved divides by 1), of the outputs
    // only: the guards' values are computed with the status.
    compile::program outputs_only = plan.code;
    outputs_only.outputs.erase(outputs_only.outputs.begin(),
                               outputs_only.outputs.begin() + static_cast<long>(plan.guard_values));
    const bool for_registers = compile::most_live(outputs_only) > batch_registers;
    const compile::program arithmetic = for_registers ? compile::ordered_for_registers(outputs_only) : outputs_only;
    const std::vector<bool> for_outputs = compile::needed_by(arithmetic, 0, arithmetic.outputs.size());
    const cxx_code code = program_cxx(arithmetic, plain_names, with_status ? "usable" : "",
                                      with_status ? for_outputs : std::vector<bool>{}, true);
    // A loop that settles (print_settle) always writes statuses, into the caller's array or a
    // block's own, and is compiled once. Only a loop that does not is a template of whether the
    // caller wants statuses (`with_status`), which it then writes or not: compiled twice, the
    // settling loops' one body doubled the compilers' time on the rough spheres' kernels.
    const bool settles = with_status && (!code.underflows.empty() || !k.limits.empty());
    const bool by_status = with_status && !settles;

    out += "\nnamespace detail {\n\n";
    if (with_status)
        print_input_k(out, loop, plan);
    out += fmt::format("// The loop of {}_batch{}, without branches; inlined where it is called, so that a\n"
                       "// block's call runs one pass of 8 pairs.\n", k.name, n ? fmt::format(" in {}D", n) : "");
    out += fmt::format("template <class Real{}>\nIMPACT_ALWAYS_INLINE void {}(std::size_t count, {}) noexcept\n{{\n"
                       "    IMPACT_INDEPENDENT_ITERATIONS\n    for (std::size_t i = 0; i < count; ++i) {{\n",
                       by_status ? ", bool with_status" : "", loop, loop_parameters(inputs, with_status));

    // The status, from the guards on the values as given.
    const std::vector<bool> for_guards = needed_by(plan.code, 0, plan.guard_values);
    std::vector<domain_test> sure_domains;  // the domains' tests, as the sure loop prints them
    std::string sure_conditions;            // the conditions' statuses, as the sure loop decides them
    if (with_status) {
        // The scalar kernel tests the inputs' domains first, then the conditions computed
        // from them; a lane whose inputs are refused divides by 1 in those computations.
        std::vector<const engine::kernel_guard*> domains, conditions;
        for (const engine::kernel_guard& g : k.guards)
            (g.condition ? conditions : domains).push_back(&g);
        out += "        // The status, as the scalar kernel decides it: the first guard that fails.\n"
               "        // (x * 0 is 0 for a finite x and NaN otherwise: one sum tests many values.)\n"
               "        impact::status outcome = status::ok;\n        {\n";
        // `fails |= test`, not `||`, and the status blended, not chosen by `?:`: no branch,
        // so that the loop vectorises (detail::blend). Every condition is an int64, one mask
        // as wide as a double in vectors: GCC vectorised selects between booleans only with
        // AVX-512.
        bool declared = false;
        auto fail_with = [&](const std::vector<std::string>& failures, const std::string& status, const char* into) {
            for (std::size_t f = 0; f < failures.size(); ++f)
                out += fmt::format("            {} {};\n", f == 0 ? (declared ? "fails =" : "std::int64_t fails =") : "fails |=",
                                   failures[f]);
            out += fmt::format("            {0} = detail::blend(fails, status::{1}, {0});\n", into, status);
            declared = true;
        };
        for (auto g = domains.rbegin(); g != domains.rend(); ++g)
            for (const domain_test& t : guard_tests(k, **g, "_[i]"))
                sure_domains.push_back(t);
        for (auto g = domains.rbegin(); g != domains.rend(); ++g)
            fail_with(batch_failures(guard_tests(k, **g, "_[i]")), (*g)->status, "outcome");
        if (!conditions.empty()) {
            // A separate status for the conditions, taken where the domains admit the
            // inputs (GCC vectorises this, not `fails &= admitted`).
            out += "            const std::int64_t admitted = outcome == status::ok;\n"
                   "            impact::status condition = status::ok;\n";
            const cxx_code given = program_cxx(plan.code, element_names, "admitted", {}, true);
            for (std::size_t s = 0; s < given.statements.size(); ++s)
                if (for_guards[given.statement_values[s]])
                    out += "            " + given.statements[s] + "\n";
            for (std::size_t c = conditions.size(); c-- > 0;)
                fail_with({condition_failure(given.outputs[c], *conditions[c])}, conditions[c]->status, "condition");
            out += "            outcome = detail::blend(admitted, condition, outcome);\n";
            sure_conditions = "            impact::status condition = status::ok;\n";
            for (std::size_t s = 0; s < given.statements.size(); ++s)
                if (for_guards[given.statement_values[s]])
                    sure_conditions += "            " + given.statements[s] + "\n";
            for (std::size_t c = conditions.size(); c-- > 0;)
                sure_conditions += fmt::format("            condition = detail::blend({}, status::{}, condition);\n",
                                               condition_failure(given.outputs[c], *conditions[c]), conditions[c]->status);
            sure_conditions += "            outcome = condition;\n";
        }
        out += "        }\n";
        if (!k.limits.empty()) {
            // A fixed sphere (a mass +infinity) is left to the scalar kernel, which takes its
            // limit: marked as a pair the loop leaves to it (status underflow, then `settle`),
            // so that the loop stays one program without branches.
            std::vector<std::string> infinite;
            for (const engine::kernel& f : k.limits)
                infinite.push_back(fmt::format("{}_[i] == std::numeric_limits<Real>::infinity()", f.fixed_mass));
            out += fmt::format("        // A fixed sphere, a mass +infinity, is left to the scalar kernel (`settle`).\n"
                               "        outcome = detail::blend(detail::either({}), status::{}, outcome);\n",
                               fmt::join(infinite, ", "), underflow);
        }
        out += "        const std::int64_t resolved = outcome == status::ok;\n";
    }

    if (with_status)
        out += "        // Every pair is computed; one not resolved divides by 1, and its results are discarded.\n";
    // The inputs the arithmetic reads (a wall's point and centre only its guards read).
    std::vector<bool> read(inputs.size(), false);
    for (std::size_t v = 0; v < arithmetic.code.size(); ++v)
        if (arithmetic.code[v].op == compile::opcode::input && for_outputs[v])
            read.at(static_cast<std::size_t>(arithmetic.code[v].input)) = true;
    std::string range_test;  // printed after the arithmetic
    if (with_status && !code.underflows.empty()) {
        // The scalar kernel's underflow test costs about as much as the loop's arithmetic,
        // and a least magnitude of the values it tests more than half of it: the loop
        // tests the inputs' range only (detail::<loop>_k), and leaves a pair outside it
        // to the scalar kernel (status underflow here, then `settle`). An input 0 passes
        // (detail::magnitude_or). Tested after the arithmetic: tested as the inputs are
        // read, the loops ran slower (2D 0.69 of the loop before any test, against 0.79).
        // (The sure block tests the values compile::cut_for_range chooses.)
        std::vector<std::string> low, high;
        for (const compile::instruction& in : arithmetic.code)
            if (in.op == compile::opcode::input && for_outputs[&in - arithmetic.code.data()]) {
                low.push_back(fmt::format("detail::magnitude_or({}, lowest)", plain_names[in.input]));
                high.push_back(fmt::format("std::fabs({})", plain_names[in.input]));
            }
        range_test = fmt::format("        std::int64_t doubtful = 0;\n        if constexpr ({0}_k<Real> >= 0) {{\n"
                           "            constexpr Real lowest = detail::power_of_2<Real>(-{0}_k<Real>), highest = detail::power_of_2<Real>({0}_k<Real>);\n"
                           "            doubtful = !detail::both(detail::at_least({1}, lowest), detail::at_most({2}, highest));\n"
                           "        }}\n",
                           loop, balanced("detail::least", low), balanced("detail::most", high));
    }
    // A resolved pair is divided only by divisors in range (`usable`), and its results are
    // written only if finite (`written`), as the scalar kernel decides. (`&`, not `&&`: with
    // `&&`, GCC tested a divisor's range only where the tests before it held, a comparison
    // that may trap made conditional, and did not vectorise without -fno-trapping-math.)
    // Divisors that need a division (compile::grouped_divisors) are tested once all are
    // computed, in `usable_late`, which is `usable` from there on.
    const bool late = !code.late_divisors.empty();
    const std::string usable = late ? "usable_late" : "usable";
    // `bounded`: every divisor not 0 known to be in range (a sure block's).
    const auto declare_usable = [&](std::string& into, std::size_t known, bool bounded) {
        if (known == code.divisors_known) {
            std::vector<std::string> in_range{"resolved"};
            for (const std::string& test : divisors_in_range(code, false, bounded))
                in_range.push_back(test);
            into += fmt::format("        const std::int64_t usable = {};\n", fmt::join(in_range, " & "));
        }
        if (late && known == code.late_divisors_known)
            into += fmt::format("        const std::int64_t usable_late = usable & {};\n",
                                fmt::join(divisors_in_range(code, true, bounded), " & "));
    };
    // The inputs read, the divisors' tests and the statements, as the loop and the sure loop print them.
    const auto print_reads = [&](std::string& into) {
        for (std::size_t in = 0; in < inputs.size(); ++in)
            if (read[in])
                into += fmt::format("        const Real {0} = {0}_[i];\n", inputs[in].name);
    };
    const auto print_arithmetic = [&](std::string& into, bool bounded) {
        print_reads(into);
        if (with_status)
            declare_usable(into, 0, bounded);
        for (std::size_t s = 0; s < code.statements.size(); ++s) {
            if (for_outputs[code.statement_values[s]])
                into += "        " + code.statements[s] + "\n";
            if (with_status)
                declare_usable(into, s + 1, bounded);
        }
    };
    print_arithmetic(out, false);
    // Each output component's array and value. An output named after an input is written over
    // that input, and keeps it where the pair is not resolved; any other is written into its
    // own array, and is 0 there, as the scalar kernel returns it.
    struct write {
        std::string target, value, kept;
    };
    std::vector<write> writes;
    std::size_t value = 0;
    for (const engine::kernel_output& o : k.outputs) {
        const engine::kernel_parameter* same = k.find_parameter(o.member);
        for (std::size_t c = 0; c < o.values.size(); ++c, ++value) {
            const std::string target = same ? same->components.at(c).name : o.own_array_name(c);
            writes.push_back({target, code.outputs[value], same ? target + "_[i]" : "Real(0)"});
        }
    }
    if (with_status) {
        std::vector<std::string> results = code.arguments;  // functions' arguments tested as results are
        for (const write& w : writes) {
            out += fmt::format("        const Real {}_out = {};\n", w.target, w.value);
            results.push_back(w.target + "_out");
        }
        // In a loop ordered for registers, the results' test is computed for every pair, in
        // statements of its own. As a condition after `usable &&` (before the conditions
        // were int64 flags), GCC computed it only where `usable` held, and the ordered 3D loop loaded more vectors of the arrays
        // than it needs, each a miss out of cache. The 2D loop, in its own order, runs better
        // with the test in place.
        int names = 0;
        const std::string finite = all_finite(results, [&](const std::string& term, bool is_sum) {
            if (!for_registers)
                return in_place(term, is_sum);
            const std::string name = fmt::format("finite{}", names++);
            out += fmt::format("        const Real {} = {};\n", name, term);
            return name;
        });
        // Written only in range and where nothing underflowed, as the scalar kernel decides:
        // out_of_range first, then underflow.
        if (code.underflows.empty()) {
            out += fmt::format("        const std::int64_t written = {} & {};\n", usable, finite);
        } else {
            out += fmt::format("        const std::int64_t finite = {};\n", finite);
            out += range_test;
            // Where the format has no range (k = -1), the least magnitude of the values tested.
            out += fmt::format("        if constexpr ({}_k<Real> < 0)\n"
                               "            doubtful = !detail::at_least({}, std::numeric_limits<Real>::min());\n",
                               loop, least_magnitude(code));
            out += fmt::format("        const std::int64_t written = {} & finite & !doubtful;\n", usable);
        }
        // Every pair's velocities stored, the old ones where not written: a store only
        // where `written` held needs a masked store (AArch64 has none), and GCC made one of
        // `v_[i] = written ? v_out : v_[i]`.
        for (const write& w : writes)
            out += fmt::format("        {0}_[i] = detail::blend(written, {0}_out, {1});\n", w.target, w.kept);
        if (code.underflows.empty() && k.limits.empty())
            out += fmt::format("        if constexpr (with_status)\n"
                               "            status_[i] = detail::blend(resolved & !written, status::{}, outcome);\n",
                               out_of_range);
        else if (code.underflows.empty())  // always: a fixed sphere is found by its status (`settle`)
            out += fmt::format("        status_[i] = detail::blend(resolved & !written, status::{}, outcome);\n", out_of_range);
        else  // always: a doubtful pair is found by its status (`settle`)
            out += fmt::format("        status_[i] = detail::blend(resolved & !written, detail::blend({} & finite, status::{}, status::{}), outcome);\n",
                               usable, underflow, out_of_range);
    } else {
        for (const write& w : writes)
            out += fmt::format("        {}_[i] = {};\n", w.target, w.value);
    }
    out += "    }\n}\n";
    if (settles)
        print_settle(out, k, loop, inputs, which);
    // The sure loop: a block of pairs whose values are all in range, where the loop needs
    // neither the scalar kernel nor a blended status; for a kernel with a range in double
    // (batch_formats[1]), the type its loops are vectorised and measured in (the rough
    // spheres' have none: every block goes to the loop there).
    const compile::range_cut cut = compile::cut_for_range(arithmetic, for_outputs);
    std::vector<int> sure_ks;
    for (const compile::float_format& f : batch_formats)
        sure_ks.push_back(compile::cut_exponent_bound(arithmetic, for_outputs, cut, f));
    const bool sure = with_status && !code.underflows.empty() && sure_ks.at(1) >= 0;
    if (sure) {
        // The domains' tests, but the finiteness of an input the arithmetic reads: tested, or
        // added to or subtracted from another, and then the sum tested (range_cut), no value
        // outside [2^-k, 2^k] passes, NaN and the infinities among them.
        std::set<std::string> in_range;
        for (std::size_t in = 0; in < inputs.size(); ++in)
            if (read[in])
                in_range.insert(inputs[in].name + "_[i]");
        // A fixed sphere's mass, +infinity, is outside the range too.
        std::vector<domain_test> tests;
        std::copy_if(sure_domains.begin(), sure_domains.end(), std::back_inserter(tests),
                     [&](const domain_test& t) { return t.finite.empty() || in_range.count(t.finite) == 0; });
        // The first pass tests the domains and the range only: of the inputs, sums and
        // differences of two inputs that range_cut chose, by the values' bits where the format
        // has them (detail::outside_by_bits with 64-bit integer minima, detail::below_range
        // without), the largest magnitude otherwise by a sum of squares, which NaN and the
        // infinities, lost in a tree of maxima (a < b ? b : a), make fail. Where a comparison
        // with NaN is not reliably false (-ffinite-math-only), the values' finiteness is
        // tested too (detail::zero_if_finite), and the least magnitude taken without NaN
        // (detail::magnitude_or).
        // A tested input that a domain wants above 0 (a mass) or not below it (eps) is tested
        // for its sign by its bits too, where the range test reads bits (detail::positive_bits,
        // detail::non_negative_bits): that domain's comparison is then the bits test's, and
        // made as before elsewhere. The 2D batch in cache (AVX-512, AMD EPYC Zen 5, 3 Dec
        // 2026): fast 0.375 of the plain loop, from 0.362; accurate 0.222 alike (with the
        // comparisons made part of `doubtful` on AVX2 too, its fast loop lost 0.303 -> 0.295).
        std::vector<std::string> folded, values, bits, low, squares;
        for (int v : cut.tested) {
            const compile::instruction& in = arithmetic.code[static_cast<std::size_t>(v)];
            const auto name = [&](int input) { return plain_names.at(static_cast<std::size_t>(arithmetic.code[static_cast<std::size_t>(input)].input)); };
            values.push_back(in.op == compile::opcode::input ? name(v)
                                                             : fmt::format("({} {} {})", name(in.a), in.op == compile::opcode::add ? '+' : '-', name(in.b)));
            std::string as_bits = fmt::format("detail::any_sign_bits({})", values.back());
            const auto sign = std::find_if(tests.begin(), tests.end(), [&](const domain_test& t) {
                return in.op == compile::opcode::input && t.sign_of == name(v) + "_[i]";
            });
            if (sign != tests.end()) {
                folded.push_back(sign->failure);
                as_bits = fmt::format("detail::{}_bits({})", sign->positive ? "positive" : "non_negative", values.back());
                tests.erase(sign);
            }
            bits.push_back(as_bits);
            low.push_back(fmt::format("detail::magnitude_or({}, lowest)", values.back()));
            squares.push_back(fmt::format("{0} * {0}", values.back()));
        }
        std::string tested = "        std::int64_t refused = 0;\n";
        for (const std::string& refusal : batch_failures(tests))
            tested += fmt::format("        refused |= {};\n", refusal);
        if (!folded.empty()) {
            tested += "        if constexpr (!detail::range_by_bits<Real>) {\n";
            for (const std::string& refusal : folded)
                tested += fmt::format("            refused |= {};\n", refusal);
            tested += "        }\n";
        }
        print_reads(tested);
        tested += fmt::format("        constexpr Real lowest = detail::power_of_2<Real>(-{0}_sure_k<Real>), highest = detail::power_of_2<Real>({0}_sure_k<Real>);\n"
                              "        std::int64_t doubtful;\n"
                              "        if constexpr (detail::range_by_bits<Real>)\n"
                              "            doubtful = detail::outside_by_bits(lowest, highest, {5});\n"
                              "        else if constexpr (detail::has_magnitude_bits<Real>)\n"
                              "            doubtful = detail::below_range(lowest, {1}) | !detail::at_most({2}, highest * highest);\n"
                              "        else\n"
                              "            doubtful = detail::either(!detail::both(detail::at_least({3}, lowest), detail::at_most({2}, highest * highest)),\n"
                              "                                      !detail::nan_compares_false && !{4});\n"
                              "        left |= refused | doubtful;\n",
                              loop, fmt::join(values, ", "), balanced_sum(squares), balanced("detail::least", low), all_finite(values),
                              fmt::join(bits, ", "));
        // The second computes the pairs as the loop does, the guards' values in braces of their
        // own (the arithmetic's names follow); a condition that divides does so by 1 where the
        // domains refuse (`admitted`, as in the loop), and here every pair is admitted.
        std::string written = "        impact::status outcome = status::ok;\n";
        if (!sure_conditions.empty())
            written += std::string("        {\n") +
                       (sure_conditions.find("admitted") != std::string::npos ? "            const std::int64_t admitted = 1;\n" : "") +
                       sure_conditions + "        }\n";
        written += "        const std::int64_t resolved = outcome == status::ok;\n";
        // A divisor is tested only for 0 where, in every format the sure block runs in, the
        // range bounds each one not 0 within [detail::smallest_divisor, max] (the loop's test
        // of its magnitude, two comparisons, then decides as this one does): the 2D batch in
        // cache (AMD EPYC Zen 5, 3 Dec 2026), fast, 0.303 of the plain loop from 0.293 on AVX2,
        // 0.362 from 0.346 on AVX-512; accurate 0.160 from 0.156 and 0.222 from 0.213.
        std::vector<int> divisors = code.divisor_values;
        divisors.insert(divisors.end(), code.late_divisor_values.begin(), code.late_divisor_values.end());
        bool bounded = true;
        for (std::size_t f = 0; f < std::size(batch_formats); ++f) {
            const compile::float_format& format = batch_formats[f];
            if (sure_ks[f] >= 0 && 2 * sure_ks[f] < format.max_exponent)
                bounded = bounded && compile::cut_bounds_within(arithmetic, for_outputs, cut, sure_ks[f], format, divisors,
                                                                format.min_exponent - 2 + format.digits, format.max_exponent - 1);
        }
        print_arithmetic(written, bounded);
        for (const write& w : writes)
            written += fmt::format("        const Real {}_out = {};\n", w.target, w.value);
        // Within the range no value the arithmetic computes overflows (range_cut bounds every
        // one above) but the results that add an untested input (a velocity) to an impulse:
        // those are tested, as the loop tests them (out_of_range where one is not finite).
        std::vector<std::string> summed;
        for (int o : cut.summed)
            summed.push_back(writes.at(static_cast<std::size_t>(o)).target + "_out");
        const std::string stored = summed.empty() ? usable : "written";
        if (!summed.empty())
            written += fmt::format("        const std::int64_t written = {} & {};\n", usable, all_finite(summed));
        for (const write& w : writes)
            written += fmt::format("        {0}_[i] = detail::blend({1}, {0}_out, {2});\n", w.target, stored, w.kept);
        // A divisor out of range, or a result not finite, as in the loop: the velocities kept,
        // status out of range.
        written += fmt::format("        status_[i] = detail::blend(resolved & !{}, status::{}, outcome);\n", stored, out_of_range);
        out += fmt::format(
            "\n// The range of what {0}_sure tests, within which every value {0} computes stays in\n"
            "// the normal range but its results that add a velocity: where each of {2} is 0\n"
            "// or of magnitude within [2^-k, 2^k], derived by Impact as {0}_k is, from these values\n"
            "// instead of the inputs (an input only added or subtracted, as a velocity, is finite\n"
            "// where its differences and those results are). For 24, 53, 64 and 113 mantissa\n"
            "// digits: k = {1}.\n"
            "template <class Real>\nconstexpr int {0}_sure_k = input_k<Real>({1});\n",
            loop, fmt::join(sure_ks, ", "), fmt::join(values, ", "));
        // Two passes over the block, the first testing, the second computing and storing:
        // against one pass that kept the results in arrays of the block until all were tested,
        // and left a block with a divisor out of range to the loop, the fast 2D block ran
        // 0.28 of the plain loop in cache on AVX2, from 0.23, and alike on AVX-512 (0.32, 0.34).
        // One pass again (3 Dec 2026, AMD EPYC Zen 5), the results in the block's arrays and
        // copied after the test: inlined in the block loop, GCC stored each lane of them apart,
        // and the fast 2D batch ran 0.26 of the plain loop on AVX2 against 0.29 (0.35 alike on
        // AVX-512); copies of both alone in a loop of blocks, compiled outside
        // IMPACT_PRECISE_BEGIN (products fused), ran 0.44 against 0.38 there.
        out += fmt::format(
            "\n// A block of 8 pairs resolved at once (true) where every pair's values are in range\n"
            "// ({0}_sure_k) and admitted by the domains: nothing then underflows, no sphere is fixed,\n"
            "// each status is ok, a condition's or out of range, and each result is {0}'s bit for\n"
            "// bit, without its blended statuses and the scalar kernel after it. Otherwise (false)\n"
            "// the block is left as it was, to {0}.\n"
            "template <class Real>\nIMPACT_ALWAYS_INLINE bool {0}_sure({1}) noexcept\n{{\n"
            "    // A format without a range, or one whose largest square (2^2k) overflows: every block\n"
            "    // left to the loop.\n"
            "    if constexpr ({0}_sure_k<Real> < 0 || 2 * {0}_sure_k<Real> >= std::numeric_limits<Real>::max_exponent)\n"
            "        return false;\n"
            "    constexpr std::size_t block = 8;\n"
            "    std::int64_t left = 0;  // a pair the block leaves to the loop\n"
            "    IMPACT_KEEP_LOOP\n    IMPACT_INDEPENDENT_ITERATIONS\n    for (std::size_t i = 0; i < block; ++i) {{\n{2}    }}\n"
            "    if (left)\n        return false;\n"
            "    IMPACT_KEEP_LOOP\n    IMPACT_INDEPENDENT_ITERATIONS\n    for (std::size_t i = 0; i < block; ++i) {{\n{3}    }}\n"
            "    return true;\n}}\n",
            loop, loop_parameters(inputs, true), tested, written);
    }
    print_blocks(out, loop, inputs, with_status, settles, sure);
    // A loop with a sure block reads its arrays as they are: skewed, the 3D collide's ran out
    // of cache with its arrays at one offset at 0.63 of the plain loop (accurate, AVX-512)
    // and 0.65 (fast, AVX2), against 0.93 and 0.87 read as they are (2 Dec 2026).
    const bool skewed = skews(k) && !sure;
    if (skewed)
        print_skewed_blocks(out, loop, inputs, with_status, settles, sure);
    out += "\n} // namespace detail\n";

    // The public entry point.
    if (fast)
        out += fmt::format("\n/// {0}_batch(data, impact::fast): {0}_batch in the fast form, each result bit for bit\n"
                           "/// the scalar {0}(..., impact::fast)'s (compiled alike, e.g. -ffp-contract=off).\n",
                           k.name);
    else
        out += fmt::format("\n/// {0} over `count` collisions stored as structure of arrays: outputs named after\n"
                           "/// inputs are updated in place{2}.{1}\n"
                           "/// The loop has no branches, so that compilers vectorise it; each result is bit for\n"
                           "/// bit the scalar {0}'s (compiled alike, e.g. -ffp-contract=off). The arrays written\n"
                           "/// must not overlap any other array.\n",
                           k.name, with_status ? " `status` (if not null) receives each status." : "",
                           std::any_of(inputs.begin(), inputs.end(), [](const lane_input& in) { return in.fresh; })
                               ? ",\n/// the others written into arrays of their own (0 where a pair is refused)"
                               : "");
    out += fmt::format("template <class Real>\ninline void {0}_batch(const {0}_batch_data<Real, {1}>& data{2}) noexcept\n{{\n",
                       k.name, n, fast ? ", fast_t" : "");
    if (skewed) {
        std::vector<std::string> read_starts;
        for (const lane_input& in : read_only(inputs))
            read_starts.push_back(in.field);
        const std::string skewed =
            by_status ? fmt::format("            if (data.status)\n                detail::{0}_skewed<Real, true>(data.count, {1}, data.status);\n"
                                      "            else\n                detail::{0}_skewed<Real, false>(data.count, {1}, nullptr);\n",
                                      loop, fmt::join(arguments, ", "))
                      : fmt::format("            detail::{}_skewed<Real>(data.count, {}{});\n", loop, fmt::join(arguments, ", "),
                                    with_status ? ", data.status" : "");
        out += fmt::format("    // Arrays of doubles that crowd one page offset are read skewed (the blocks and the\n"
                           "    // distances are a double's; other types keep the plain loop).\n"
                           "    if constexpr (sizeof(Real) == sizeof(double))\n"
                           "        if (detail::crowded(std::array<const void*, {0}>{{{1}}})) {{\n{2}            return;\n        }}\n",
                           read_starts.size(), fmt::join(read_starts, ", "), skewed);
    }
    if (by_status)
        out += fmt::format("    if (data.status)\n        detail::{0}_ahead<Real, true>(data.count, {1}, data.status);\n"
                           "    else\n        detail::{0}_ahead<Real, false>(data.count, {1}, nullptr);\n",
                           loop, fmt::join(arguments, ", "));
    else
        out += fmt::format("    detail::{}_ahead<Real>(data.count, {}{});\n", loop, fmt::join(arguments, ", "),
                           with_status ? ", data.status" : "");
    out += "}\n";
}

} // namespace impact::emit::cxx_detail
