// The scalar kernel: its result structure, its documentation (what each status means),
// its guards as early returns, and its arithmetic, the plan's program statement by
// statement.
#include "emit/cxx_parts.h"
#include "emit/program_cxx.h"

#include <fmt/format.h>

#include <algorithm>
#include <functional>
#include <iterator>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string_view>

namespace impact::emit::cxx_detail {
namespace {

// The scalar kernel's form of the tests: a finite value tested with detail::finite (from its
// bits: under -ffinite-math-only, std::isfinite may be folded to true).
std::vector<std::string> scalar_failures(const std::vector<domain_test>& tests)
{
    std::vector<std::string> failures;
    for (const domain_test& t : tests)
        failures.push_back(t.finite.empty() ? t.failure : fmt::format("!detail::finite({})", t.finite));
    return failures;
}

// The scalar kernel's early return when any of `failures` holds: the result as it stands
// (inputs unchanged) with `status`, or, from a kernel returning one scalar, a quiet NaN
// (the status then named in a comment).
// `or_else` joins the failures (a line each, for a long list).
void print_refusal(std::string& out, const engine::kernel& k, const std::vector<std::string>& failures,
                   const std::string& status, const char* or_else = " || ")
{
    if (returns_scalar(k))
        out += fmt::format("    if ({}) {{\n        return std::numeric_limits<Real>::quiet_NaN();  // {}\n    }}\n",
                           fmt::join(failures, or_else), status);
    else
        out += fmt::format("    if ({}) {{\n        out.status = status::{};\n        return out;\n    }}\n",
                           fmt::join(failures, or_else), status);
}

// What a value outside a domain is, in words: "not positive and finite".
std::string outside(const engine::domain& range)
{
    switch (range.what) {
    case engine::domain::kind::positive: return range.infinity_included ? "not positive" : "not positive and finite";
    case engine::domain::kind::nonnegative: return range.infinity_included ? "negative or NaN" : "negative or not finite";
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
    std::vector<std::string> fixed;
    for (const engine::kernel& f : k.limits)
        if (std::find(g.parameters.begin(), g.parameters.end(), f.fixed_mass) != g.parameters.end())
            fixed.push_back(f.fixed_mass);
    if (!fixed.empty())
        parts.back() += fmt::format(" (+infinity allowed for {}{})", fmt::join(fixed, " or "),
                                    fixed.size() > 1 ? ", not both" : "");
    return fmt::format("{}", fmt::join(parts, "; "));
}

// The documentation of a kernel's guards: what each status means, and what is returned.
// `divides`: whether the kernel divides by a value it computes (then tested for range);
// `calls`: whether it calls a function (its arguments tested).
void print_guards_documentation(std::string& out, const engine::derivation& d, const engine::kernel& k, bool divides,
                                bool calls)
{
    if (k.guards.empty())
        return;
    const bool others = std::any_of(k.outputs.begin(), k.outputs.end(),
                                    [&](const engine::kernel_output& o) { return !k.find_parameter(o.member); });
    const bool same = std::any_of(k.outputs.begin(), k.outputs.end(),
                                  [&](const engine::kernel_output& o) { return k.find_parameter(o.member) != nullptr; });
    if (returns_scalar(k))
        out += "/// A quiet NaN when the inputs are refused, for the first of these reasons that applies:\n";
    else
        out += fmt::format("/// When the inputs are refused, `status` says why, the first of these that applies,\n"
                           "/// and {}:\n",
                           same && others ? "each output named after an input is that input (a velocity\n/// "
                                            "unchanged), the others 0"
                           : same         ? "each output is the input it is named after (the velocities\n/// "
                                            "unchanged)"
                                          : "the outputs are 0");
    for (const engine::kernel_guard& g : k.guards)
        out += fmt::format("///   {}: {}\n", g.status, guard_meaning(d, k, g));
    out += fmt::format("///   {}: the values leave the type's range ({}{}a result not finite).\n", out_of_range,
                       divides ? "a divisor below\n///     detail::smallest_divisor or infinite, " : "",
                       calls ? "an argument of a function\n///     or " : "");
    out += fmt::format("///   {}: a value of the arithmetic below (a product, quotient, fused\n"
                       "///     multiply-add or function; not a correction of compensated arithmetic) is\n"
                       "///     below std::numeric_limits<Real>::min() but not 0, or is 0 where what it\n"
                       "///     multiplies or divides is not: it lost digits, and the result could be\n"
                       "///     imprecise. Zero inputs are ordinary.\n",
                       underflow);
}

// What a kernel with fixed spheres does with an infinite mass, and how accurate it is then.
void print_fixed_documentation(std::string& out, const std::vector<const kernel_plan*>& fixed)
{
    if (fixed.empty())
        return;
    std::vector<std::string> masses;
    for (const kernel_plan* f : fixed)
        masses.push_back(f->kernel->fixed_mass);
    out += fmt::format("/// {} may be +infinity{}: a fixed sphere, an obstacle the impulse does not move. Every\n"
                       "/// output is then its limit as that mass grows without bound, derived and proven\n"
                       "/// (momentum is not conserved: the obstacle takes the impulse).\n",
                       fmt::join(masses, " or "), masses.size() > 1 ? ", one at a time" : "");
    for (const kernel_plan* f : fixed)
        for (const verify::component_plan& cp : f->components) {
            const verify::candidate_result& c = cp.candidates[cp.chosen];
            out += fmt::format("/// With {} = +infinity, {} is computed in the form \"{}\": at most {:.2f} ulps in double.\n",
                               f->kernel->fixed_mass, cp.name, c.label, c.double_accuracy.max_ulps);
        }
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

// The parameters of a kernel as C++ (`Real M, ..., const std::array<Real, 2>& v_M, ...`),
// and their names.
std::vector<std::string> parameter_list(const engine::kernel& k)
{
    std::vector<std::string> parameters;
    for (const engine::kernel_parameter& p : k.parameters)
        parameters.push_back(parameter_type(p) + " " + p.name);
    return parameters;
}

std::vector<std::string> parameter_names(const engine::kernel& k)
{
    std::vector<std::string> names;
    for (const engine::kernel_parameter& p : k.parameters)
        names.push_back(p.name);
    return names;
}

// The fast form's documentation: what it is, what it costs beside the accurate form, and
// how each output is computed and how accurate it is.
void print_fast_documentation(std::string& out, const kernel_plan& fast, const kernel_plan& accurate,
                              const char* comment)
{
    const engine::kernel& k = *fast.kernel;
    const compile::cost cost = compile::cost_of(fast.code), accurate_cost = compile::cost_of(accurate.code);
    out += fmt::format("\n{0} {1}({2}, impact::fast): the fast form of {1}{3}, with the\n"
                       "{0} same guards and statuses, each output in its cheapest candidate form within its fast\n"
                       "{0} bound (verification.md): {4} operations with the guards' conditions, of them {5}\n"
                       "{0} division(s) and {6} square root(s) (the accurate form: {7}, {8} and {9}).\n",
                       comment, k.limit_of.empty() ? k.name : k.limit_of, fmt::join(parameter_names(k), ", "),
                       k.limit_of.empty() ? "" : fmt::format(" with {} = +infinity", k.fixed_mass), cost.operations,
                       cost.divisions, cost.square_roots, accurate_cost.operations, accurate_cost.divisions,
                       accurate_cost.square_roots);
    for (const verify::component_plan& cp : fast.components) {
        const verify::candidate_result& c = cp.candidates[cp.chosen];
        out += fmt::format("{} {} is computed in the form \"{}\": at most {:.2f} ulps in double on {} samples.\n",
                           comment, cp.name, c.label, c.double_accuracy.max_ulps, c.double_accuracy.samples);
    }
}

// The fast form of a kernel whose fast form is its accurate one, and of its fixed
// spheres' kernels: an overload that calls the accurate form (and its batch's).
void print_fast_forwarding(std::string& out, const kernel_plan& plan)
{
    const engine::kernel& k = *plan.kernel;
    const char* comment = k.limit_of.empty() ? "///" : "//";
    out += fmt::format("\n{0} {1}({2}, impact::fast): the fast form of {1}, which is\n"
                       "{0} its accurate form: no form within the fast bounds is cheaper than it (verification.md).\n",
                       comment, k.name, fmt::join(parameter_names(k), ", "));
    out += fmt::format("template <class Real>\ninline {} {}({}, fast_t) noexcept\n{{\n    return {}<Real>({});\n}}\n",
                       result_type(k), k.name, fmt::join(parameter_list(k), ", "), k.name,
                       fmt::join(parameter_names(k), ", "));
    if (k.batch)
        out += fmt::format("\n/// {0}_batch(data, impact::fast): the fast form of {0}_batch, which is its accurate form.\n"
                           "template <class Real>\ninline void {0}_batch(const {0}_batch_data<Real, {1}>& data, fast_t) noexcept\n"
                           "{{\n    {0}_batch(data);\n}}\n",
                           k.name, dimension(k));
}

} // namespace

void print_kernel(std::string& out, const engine::derivation& d, const kernel_plan& given,
                  const std::vector<const kernel_plan*>& fixed, form which)
{
    const bool fast = which == form::fast;
    // The fast form: the plans' fast forms, printed as the accurate ones are; an overload
    // that calls the accurate form where every one of them is the accurate one.
    if (fast && verify::fast_is_accurate(given) &&
        std::all_of(fixed.begin(), fixed.end(), [](const kernel_plan* f) { return verify::fast_is_accurate(*f); })) {
        print_fast_forwarding(out, given);
        return;
    }
    const kernel_plan fast_plan = fast ? verify::fast_form(given) : kernel_plan{};
    const kernel_plan& plan = fast ? fast_plan : given;
    const engine::kernel& k = *plan.kernel;
    const std::size_t n = dimension(k);
    const bool is_limit = !k.limit_of.empty();

    if (!returns_scalar(k) && n == 0 && !is_limit && !fast) {
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
    // With a status, the values the results need are tested for underflow.
    const bool with_status = !k.guards.empty();  // a status, or a NaN for a scalar
    const cxx_code code =
        program_cxx(plan.code, component_names, "",
                    with_status ? needed_by(plan.code, plan.guard_values, plan.code.outputs.size()) : std::vector<bool>{});

    // The fixed spheres' kernels first, which this one calls.
    if (!fixed.empty()) {
        out += "\nnamespace detail {\n";
        for (const kernel_plan* f : fixed)
            print_kernel(out, d, *f, {}, which);
        out += "\n} // namespace detail\n";
    }

    // Documentation: inputs, and how each output is computed and how accurate it is.
    const std::vector<std::string> names = parameter_names(k);
    if (fast) {
        print_fast_documentation(out, plan, given, is_limit ? "//" : "///");
    } else if (is_limit) {
        out += fmt::format("\n// {} with {} = +infinity, a fixed sphere: every output the limit of {}'s as {} grows\n"
                           "// without bound (derived by the engine, each form proven equal to the limit).\n",
                           k.limit_of, k.fixed_mass, k.limit_of, k.fixed_mass);
        for (const verify::component_plan& cp : plan.components) {
            const verify::candidate_result& c = cp.candidates[cp.chosen];
            out += fmt::format("// {} is computed in the form \"{}\": at most {:.2f} ulps in double on {} samples.\n",
                               cp.name, c.label, c.double_accuracy.max_ulps, c.double_accuracy.samples);
        }
    } else {
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
        print_fixed_documentation(out, fixed);
        print_guards_documentation(out, d, k, !code.divisors.empty(), !code.arguments.empty());
    }

    std::vector<std::string> parameters = parameter_list(k);
    if (fast)
        parameters.push_back("fast_t");
    out += fmt::format("template <class Real>\ninline {} {}({}) noexcept\n{{\n", result_type(k), k.name,
                       fmt::join(parameters, ", "));

    // A fixed sphere: its mass +infinity (a mass -infinity or NaN is refused below).
    for (const kernel_plan* f : fixed) {
        std::vector<std::string> arguments = parameter_names(*f->kernel);
        if (fast)
            arguments.push_back("fast_t{}");
        out += fmt::format("    if ({} == std::numeric_limits<Real>::infinity()) {{\n"
                           "        return detail::{}<Real>({});\n    }}\n",
                           f->kernel->fixed_mass, f->kernel->name, fmt::join(arguments, ", "));
    }

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
    // Divisors computed without a division tested before the first division; those that
    // need one, once all are computed (compile::grouped_divisors).
    const auto refuse_divisors_out_of_range = [&](bool late) {
        std::vector<std::string> failures;
        for (const std::string& test : with_status ? divisors_in_range(code, late) : std::vector<std::string>{})
            failures.push_back("!" + test);
        if (!failures.empty())
            print_refusal(out, k, failures, out_of_range);
    };
    const auto refuse_known = [&](std::size_t known) {
        for (const bool late : {false, true})
            if (known == (late ? code.late_divisors_known : code.divisors_known))
                refuse_divisors_out_of_range(late);
    };
    for (std::size_t known = 0; known <= s; ++known)
        refuse_known(known);
    for (; s < code.statements.size(); ++s) {
        out += "    " + code.statements[s] + "\n";
        refuse_known(s + 1);
    }
    std::vector<std::string> results(code.outputs.begin() + static_cast<long>(plan.guard_values), code.outputs.end());
    if (with_status) {
        std::vector<std::string> failures;
        for (const std::string& argument : code.arguments)
            failures.push_back(fmt::format("!detail::finite({})", argument));
        for (std::size_t r = 0; r < results.size(); ++r) {
            out += fmt::format("    const Real result{} = {};\n", r, results[r]);
            results[r] = fmt::format("result{}", r);
            failures.push_back(fmt::format("!detail::finite({})", results[r]));
        }
        print_refusal(out, k, failures, out_of_range);
        if (!code.underflows.empty())
            print_refusal(out, k, code.underflows, underflow, " ||\n        ");
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
        print_batch(out, plan, which);
}

} // namespace impact::emit::cxx_detail
