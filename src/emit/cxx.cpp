#include "emit/cxx.h"

#include "emit/cxx_parts.h"
#include "emit/program_cxx.h"

#include "engine/expr/infix.h"

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

namespace cxx_detail {

std::string describe(const engine::quantity& q)
{
    std::string text = q.name;
    // A meaning's math, $...$ in the derivation file, as Doxygen's \f$...\f$.
    for (char c : q.meaning.empty() ? std::string() : ": " + q.meaning)
        text += c == '$' ? std::string("\\f$") : std::string(1, c);
    text += " (" + q.range.to_string();
    // The unit expected, in SI (any consistent units do, the kernel being a formula).
    if (q.dim)
        text += q.dim->is_pure_number() ? ", a pure number" : ", in " + q.dim->si_unit();
    return text + ")";
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
    // A fixed sphere's kernel returns what the kernel it is the limit of returns.
    const std::string& name = k.limit_of.empty() ? k.name : k.limit_of;
    const std::size_t n = dimension(k);
    return n ? fmt::format("{}_result<Real, {}>", name, n) : fmt::format("{}_result<Real>", name);
}

std::string parameter_type(const engine::kernel_parameter& p)
{
    return p.is_array ? fmt::format("const std::array<Real, {}>&", p.components.size()) : "Real";
}


std::vector<domain_test> domain_tests(const engine::quantity& q, const std::string& value)
{
    switch (q.range.what) {
    case engine::domain::kind::positive:
        if (q.range.infinity_included)
            return {{fmt::format("!({} > Real(0))", value), {}, value, true}};
        return {{fmt::format("!({} > Real(0))", value), {}, value, true}, {{}, value, {}, false}};
    case engine::domain::kind::nonnegative:
        if (q.range.infinity_included)
            return {{fmt::format("!({} >= Real(0))", value), {}, value, false}};
        return {{fmt::format("!({} >= Real(0))", value), {}, value, false}, {{}, value, {}, false}};
    case engine::domain::kind::interval:
        return {{fmt::format("!({} {} Real({}))", value, q.range.lower_open ? ">" : ">=", q.range.lower), {},
                 q.range.lower == 0 ? value : std::string(), q.range.lower_open},
                {fmt::format("!({} {} Real({}))", value, q.range.upper_open ? "<" : "<=", q.range.upper), {}, {}, false}};
    case engine::domain::kind::real: break;
    }
    return {{{}, value, {}, false}};
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

// What must hold of every divisor of a group (early, or `late`), as tests; the scalar
// kernel refuses a pair where one fails, the batch loop divides by 1 instead.
std::vector<std::string> divisors_in_range(const cxx_code& code, bool late, bool known)
{
    if (code.divides_early)
        throw std::logic_error("a kernel with a status divides before all its divisors are known");
    std::vector<std::string> tests;
    for (const std::string& d : late ? code.late_divisors : code.divisors) {
        if (known) {
            tests.push_back(fmt::format("({} != Real(0))", d));
            continue;
        }
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

} // namespace cxx_detail

using namespace cxx_detail;

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
    out += "#pragma once\n\n#include \"common.hpp\"\n\n"
           "// The code as written, whatever the caller's floating-point flags (common.hpp says why).\n"
           "IMPACT_PRECISE_BEGIN\n\nnamespace impact {\n";
    // Each kernel's plan, then its fixed spheres' (verify::plan_kernels' order), printed with it.
    for (std::size_t i = 0; i < plans.size(); ++i) {
        std::vector<const kernel_plan*> fixed;
        while (i + 1 + fixed.size() < plans.size() && !plans[i + 1 + fixed.size()]->kernel->limit_of.empty())
            fixed.push_back(plans[i + 1 + fixed.size()]);
        print_kernel(out, d, *plans[i], fixed);
        print_kernel(out, d, *plans[i], fixed, form::fast);
        i += fixed.size();
    }
    out += "\n} // namespace impact\n\nIMPACT_PRECISE_END\n";
    return out;
}

std::string umbrella_header(const std::vector<const engine::derivation*>& with_kernels)
{
    std::string out = "// Generated by Impact from " + engine::source_folder(with_kernels) +
                      "; do not edit.\n"
                      "// Every kernel Impact emits, in one include.\n#pragma once\n\n#include \"common.hpp\"\n";
    for (const engine::derivation* d : with_kernels)
        out += fmt::format("#include \"{}\"\n", kernel_header_name(*d));
    return out;
}

std::map<std::string, std::string> kernel_files(const engine::library& lib,
                                                const std::vector<verify::kernel_plan>& plans)
{
    std::map<std::string, std::string> files;
    // Each header, and what it holds: a derivation's kernels, or the headers they share.
    std::map<std::string, std::string> written_by = {
        {"kernels/impact/common.hpp", "which holds what the kernels share"},
        {"kernels/impact/impact.hpp", "which includes every kernel"}};
    std::vector<const engine::derivation*> with_kernels;
    std::vector<const verify::kernel_plan*> all;
    std::size_t next = 0;
    for (const engine::derivation* d : lib.in_order()) {
        if (d->kernels.empty())
            continue;
        with_kernels.push_back(d);
        std::vector<const verify::kernel_plan*> own;
        for (const engine::kernel& k : d->kernels) {
            all.push_back(&plans[next]);   // common.hpp: the kernels callers see
            for (std::size_t i = 0; i <= k.limits.size(); ++i)
                own.push_back(&plans[next++]);
        }
        const std::string header = "kernels/impact/" + kernel_header_name(*d);
        if (const auto taken = written_by.find(header); taken != written_by.end())
            throw error({d->source.file, 0, 0},
                        fmt::format("the kernels of derivation '{}' would be written to {}, {}; give its kernel "
                                    "another name",
                                    d->id(), header, taken->second));
        written_by[header] = fmt::format("as those of '{}' are", d->id());
        files[header] = kernel_header(*d, own);
    }
    files["kernels/impact/common.hpp"] = common_header(all, engine::source_folder(lib.in_order()));
    files["kernels/impact/impact.hpp"] = umbrella_header(with_kernels);
    return files;
}

} // namespace impact::emit
