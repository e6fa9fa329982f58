// Building a kernel from its `[[kernel]]`: its names checked against C++'s, its inputs,
// lets, velocities, outputs (each candidate form proven equal to the derived value), error
// scales, guards, regimes (kernel_regimes.cpp), bounds and fixed masses (fixed_kernel.cpp).
#include "engine/kernel/kernel_build.h"

#include "engine/kernel/kernel_builder.h"

#include "engine/expr/dimensional.h"
#include "engine/cases/cases.h"
#include "engine/algebra/polynomial.h"
#include "engine/prove/prove.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <map>
#include <optional>
#include <set>
#include <string>

namespace impact::engine {
namespace {

// A name the kernels' C++ gives a kernel, parameter or member of its own: C++'s keywords,
// the names a kernel's code declares beside the file's (the type Real, loop counters and
// masks, t0, t1, ... for values computed), and what C++ reserves (a leading _, a double _);
// a name ending in _ is an input's array in a batch loop. The reason, or nothing.
std::optional<std::string> taken_in_cxx(const std::string& name)
{
    static const std::set<std::string> keywords = {
        "alignas", "alignof", "and", "and_eq", "asm", "auto", "bitand", "bitor", "bool", "break", "case", "catch",
        "char", "char8_t", "char16_t", "char32_t", "class", "compl", "concept", "const", "consteval", "constexpr",
        "constinit", "const_cast", "continue", "co_await", "co_return", "co_yield", "decltype", "default", "delete",
        "do", "double", "dynamic_cast", "else", "enum", "explicit", "export", "extern", "false", "float", "for",
        "friend", "goto", "if", "inline", "int", "long", "mutable", "namespace", "new", "noexcept", "not", "not_eq",
        "nullptr", "operator", "or", "or_eq", "private", "protected", "public", "register", "reinterpret_cast",
        "requires", "return", "short", "signed", "sizeof", "static", "static_assert", "static_cast", "struct",
        "switch", "template", "this", "thread_local", "throw", "true", "try", "typedef", "typeid", "typename",
        "union", "unsigned", "using", "virtual", "void", "volatile", "wchar_t", "while", "xor", "xor_eq"};
    static const std::set<std::string> own = {
        "Real",  "std",     "impact",  "detail",   "status",   "fast",     "fast_t",  "count",   "data",
        "i",     "block",   "ahead",   "far",      "own",      "untried",  "back_off", "left",   "refused",
        "doubtful", "lowest", "highest", "outcome", "condition", "resolved", "usable",  "written", "out",
        "chosen", "other",  "bits"};
    if (keywords.count(name))
        return std::string("a C++ keyword");
    if (own.count(name))
        return std::string("a name the kernel's own code declares");
    if (name.size() > 1 && name[0] == 't' &&
        std::all_of(name.begin() + 1, name.end(), [](char c) { return c >= '0' && c <= '9'; }))
        return std::string("a name of the values the kernel computes (t0, t1, ...)");
    if (name.front() == '_' || name.find("__") != std::string::npos)
        return std::string("reserved in C++ (a leading _ or a double _)");
    if (name.back() == '_')
        return std::string("a batch loop's name for an input's array (a name ending in _)");
    return std::nullopt;
}

// `what` names the thing ("kernel 'x'", "symbol 'x'"), `mend` the way out.
void refuse_taken_in_cxx(const std::string& name, const source_location& where, const std::string& what,
                         const std::string& mend)
{
    if (const auto why = taken_in_cxx(name))
        throw error(where, fmt::format("{} '{}' cannot be a name in the kernel's C++: it is {}; {}", what, name, *why, mend));
}

} // namespace

kernel kernel_builder::build(const spec::kernel& spec_kernel)
{
    kernel k;
    k.name = spec_kernel.name.value;
    k.where = spec_kernel.name.where;
    // The names the kernels' headers define in namespace impact beside the kernels.
    for (const char* taken : {"fast", "fast_t", "status", "detail"})
        if (k.name == taken)
            throw error(k.where, fmt::format("a kernel cannot be named '{}': the kernels' headers define "
                                             "impact::{} (give the kernel another name)",
                                             k.name, k.name));
    refuse_taken_in_cxx(k.name, k.where, "kernel", "give the kernel another name");
    const std::string rename_symbol = "rename the symbol (its latex sets how it is typeset)";
    for (const spec::kernel_value& input : spec_kernel.inputs) {
        for (const spec::text& component : input.components)
            refuse_taken_in_cxx(component.value, component.where, "symbol", rename_symbol);
        std::vector<std::string> components;
        for (const spec::text& component : input.components)
            components.push_back(component.value);
        const std::string symbols = fmt::format("{}", fmt::join(components, ", "));
        refuse_taken_in_cxx(input.name.value, input.name.where, "input",
                            fmt::format("name the input otherwise, e.g. inputs = [\"other = {}\"]",
                                        input.is_array ? "[" + symbols + "]" : symbols));
    }
    for (const spec::binding& b : spec_kernel.let)
        refuse_taken_in_cxx(b.name.value, b.name.where, "symbol", rename_symbol);
    for (const spec::kernel_value& output : spec_kernel.outputs)
        refuse_taken_in_cxx(output.name.value, output.name.where, "output",
                            "name the output otherwise, e.g. outputs = [\"other = ...\"]");
    k.batch = spec_kernel.batch;
    std::set<std::string> seen;
    auto add_input = [&](const spec::text& name) {
        if (!seen.insert(name.value).second)
            throw error(name.where, fmt::format("kernel '{}' lists input '{}' twice", k.name, name.value));
        const quantity& q = d_.symbols.at(name);
        // A quantity the derivation derives (or defines) is replaced by its value in the
        // outputs: the kernel would take it and never read it.
        const GiNaC::ex value = resolve_(q.symbol);
        if (!value.is_equal(q.symbol))
            throw error(name.where, fmt::format("kernel '{}': input '{}' is derived here ({} = {}), so its outputs "
                                                "are computed from what it is derived from and would never read "
                                                "it; list those quantities as inputs instead",
                                                k.name, name.value, name.value, d_.symbols.text(value)));
        return q;
    };
    for (const spec::kernel_value& input : spec_kernel.inputs) {
        kernel_parameter p;
        p.name = input.name.value;
        p.is_array = input.is_array;
        for (const spec::text& component : input.components)
            p.components.push_back(add_input(component));
        k.parameters.push_back(std::move(p));
    }
    for (const spec::binding& b : spec_kernel.substitute)
        substitutions_[d_.symbols.at(b.name).symbol] = d_.symbols.parse(b.expression);
    // A let may use the lets before it, computed once and shared (K_t in dv_Mx and dw_M).
    GiNaC::exmap earlier;
    for (const spec::binding& b : spec_kernel.let) {
        const GiNaC::ex symbol = d_.symbols.at(b.name).symbol;
        const GiNaC::ex value = in_kernel(d_.symbols.parse(b.expression));
        require_inputs(k, value.subs(earlier, GiNaC::subs_options::no_pattern), b.name.value, b.expression.where);
        k.lets.emplace_back(symbol, value);
        earlier[symbol] = value.subs(earlier, GiNaC::subs_options::no_pattern);
    }
    for (const spec::text& v : spec_kernel.velocities) {
        // An input (`v_M`), or an expression in the inputs that is a speed (`R_M*w_M`).
        if (const kernel_parameter* p = k.find_parameter(v.value)) {
            for (const quantity& q : p->components)
                k.velocities.push_back(q.symbol);
            continue;
        }
        const GiNaC::ex speed = in_kernel(d_.symbols.parse(v));
        require_inputs(k, speed, "velocities", v.where);
        k.speeds.push_back(speed);
    }
    for (const spec::kernel_value& output : spec_kernel.outputs)
        k.outputs.push_back(make_output(k, output, spec_kernel));
    for (const spec::error_scale& e : spec_kernel.error) {
        kernel_output* o = find_output(k, e.output);
        if (e.relative) {
            o->error = kernel_output::scale::relative;
            continue;
        }
        o->error = kernel_output::scale::velocity;
        o->scale_factor = e.factor ? in_kernel(d_.symbols.parse(*e.factor)) : GiNaC::ex(1);
        check_scale(*o, e.written);
    }
    for (const spec::kernel_guard& g : spec_kernel.guards)
        k.guards.push_back(make_guard(k, g));
    // Each regime's name names it alone in verification.md, beside the built-in ones.
    std::set<std::string> regime_names = {"ordinary", "nearly grazing", "nearly head-on", "nearly equal velocities"};
    for (const spec::sampling_regime& r : spec_kernel.regimes) {
        if (!regime_names.insert(r.name.value).second)
            throw error(r.name.where, fmt::format("kernel '{}' has a regime named '{}' already: give it a name "
                                                  "of its own",
                                                  k.name, r.name.value));
        k.regimes.push_back(make_regime(k, r));
    }
    // A batch writes an output named after an input over that input's array, and any other
    // output into an array of its own: an output named after an input of another size has
    // neither.
    std::map<std::string, std::string> fresh_arrays;  // an output's array's name -> the output
    if (k.batch) {
        // Each parameter and output is a method of `<name>_batch_arrays` too (emit's
        // print_batch_arrays), beside the members that class declares of its own.
        static const std::set<std::string> arrays_own = {"first", "page", "apart", "reals", "per_pair", "at", "swap"};
        std::vector<std::string> members;
        for (const kernel_parameter& p : k.parameters)
            members.push_back(p.name);
        for (const kernel_output& o : k.outputs)
            members.push_back(o.member);
        for (const std::string& member : members)
            if (arrays_own.count(member))
                throw error(spec_kernel.name.where,
                            fmt::format("kernel '{}' has batch = true, and '{}' would be a method of {}_batch_arrays, "
                                        "which declares a '{}' of its own; rename the input or output",
                                        k.name, member, k.name, member));
    }
    if (k.batch)
        for (const kernel_output& o : k.outputs) {
            const kernel_parameter* same = k.find_parameter(o.member);
            if (same && (same->components.size() != o.values.size() || same->is_array != o.is_array))
                throw error(spec_kernel.name.where,
                            fmt::format("kernel '{}' has batch = true, which writes each output named after an "
                                        "input over that input, and '{}' is an input of another size; name the "
                                        "output after no input (an array of its own), or after an input of its size",
                                        k.name, o.member));
            // A kernel of one scalar output and guards returns that value alone (NaN where a
            // guard refuses), with no status for a batch to report.
            if (!same && k.outputs.size() == 1 && !o.is_array && !k.guards.empty())
                throw error(spec_kernel.name.where,
                            fmt::format("kernel '{}' has batch = true and one output, '{}', named after no input: "
                                        "it returns that value alone (NaN where a guard refuses), without the status "
                                        "a batch reports for each pair; name the output after an input, or give the kernel a second output",
                                        k.name, o.member));
            // Its arrays (own_array_name) stand beside the inputs' components in the batch loop.
            for (std::size_t c = 0; !same && c < o.values.size(); ++c) {
                const std::string array = o.own_array_name(c);
                if (k.find_input(array))
                    throw error(spec_kernel.name.where,
                                fmt::format("kernel '{}' has batch = true, and the array of its output '{}' would be "
                                            "named '{}', as an input is; rename the output or the input",
                                            k.name, o.member, array));
                if (const auto [at, added] = fresh_arrays.emplace(array, o.member); !added)
                    throw error(spec_kernel.name.where,
                                fmt::format("kernel '{}' has batch = true, and the arrays of its outputs '{}' and '{}' "
                                            "would both be named '{}'; rename one of them",
                                            k.name, at->second, o.member, array));
            }
        }
    for (const spec::error_bound& b : spec_kernel.bounds) {
        kernel_output* o = find_output(k, b.output);
        const auto& types = kernel_output::types;
        const bool fast = b.form && b.form->value == "fast";
        for (std::size_t t = 0; t < 3; ++t)
            if (!b.type || b.type->value == types[t]) {
                (fast ? o->fast_bound_ulps : o->bound_ulps)[t] = b.ulps;
                (fast ? o->fast_bound_because : o->bound_because)[t] = b.because.value;
            }
    }
    std::set<std::string> fixed;
    for (const spec::text& mass : spec_kernel.fixed) {
        if (!fixed.insert(mass.value).second)
            throw error(mass.where, fmt::format("kernel '{}' lists '{}' as fixed twice", k.name, mass.value));
        k.limits.push_back(limit_kernel(k, mass));
    }
    return k;
}

// An error measured in units of the inputs' velocity times `scale_factor` is an
// error of the output's own dimension (J, a momentum: velocity*M*m/(M + m)).
void kernel_builder::check_scale(const kernel_output& o, const spec::text& written) const
{
    const auto output = check_expression(d_.symbols, o.values.front(), written.where);
    const auto factor = check_expression(d_.symbols, o.scale_factor, written.where);
    if (!output || !factor)
        return;
    const dimension scale = d_.symbols.dimension_words().parse("velocity", written.where) * *factor;
    if (scale != *output)
        throw error(written.where, fmt::format("error scale '{}' is {}, but '{}' is {}", written.value,
                                               scale.describe(), o.member, output->describe()));
}

// An expression of the derivation written in the kernel's inputs.
GiNaC::ex kernel_builder::in_kernel(const GiNaC::ex& e) const
{
    return resolve_(e).subs(substitutions_, GiNaC::subs_options::no_pattern);
}

const kernel_parameter* kernel_builder::find_parameter(const kernel& k, const spec::text& name) const
{
    if (const kernel_parameter* p = k.find_parameter(name.value))
        return p;
    throw error(name.where, fmt::format("kernel '{}' has no input '{}'", k.name, name.value));
}

kernel_output* kernel_builder::find_output(kernel& k, const spec::text& name) const
{
    for (kernel_output& o : k.outputs)
        if (o.member == name.value)
            return &o;
    throw error(name.where, fmt::format("kernel '{}' has no output '{}'", k.name, name.value));
}

// An output's value and its candidate forms, each proven equal to the value and
// each written in the kernel's inputs only.
kernel_output kernel_builder::make_output(const kernel& k, const spec::kernel_value& output, const spec::kernel& spec_kernel)
{
    kernel_output o;
    o.member = output.name.value;
    o.is_array = output.is_array;
    const std::vector<spec::text>& components = output.components;
    // Further forms name the output, or one component of an array: `v_M[0] = ...`.
    auto extra_forms = [&](std::size_t c) {
        std::vector<spec::text> extra;
        const std::string component_name = fmt::format("{}[{}]", o.member, c);
        for (const spec::binding& f : spec_kernel.forms)
            if (f.name.value == (o.is_array ? component_name : o.member))
                extra.push_back(f.expression);
        return extra;
    };
    // Each let in the inputs alone, the lets it uses written out.
    GiNaC::exmap lets;
    for (const auto& [symbol, value] : k.lets)
        lets[symbol] = value.subs(lets, GiNaC::subs_options::no_pattern);
    for (std::size_t c = 0; c < components.size(); ++c) {
        const spec::text& component = components[c];
        const result* named = d_.find_result(component.value);
        const GiNaC::ex value = in_kernel(named ? named->value : d_.symbols.parse(component));
        require_inputs(k, value, o.member, component.where);
        std::vector<form> forms;
        if (named)
            forms.push_back({"display", in_kernel(named->display)});
        forms.push_back({"derived", value});
        for (const paper_comparison& p : d_.paper_checks)
            if (named && p.what == paper_comparison::kind::result && p.subject == named->name && p.agrees())
                forms.push_back({"paper", in_kernel(p.printed)});
        for (const spec::text& e : extra_forms(c)) {
            // A form may use the kernel's `let` values; it is proven with them substituted.
            const GiNaC::ex alternative = in_kernel(d_.symbols.parse(e));
            const verdict v = prove_form(alternative.subs(lets, GiNaC::subs_options::no_pattern), value);
            if (v.what != verdict::status::proven)
                throw error(e.where, fmt::format("form \"{}\" of '{}' is not proven equal to it (residual {})",
                                                 e.value, o.member, d_.symbols.text(v.residual)));
            forms.push_back({e.value, alternative});
        }
        o.values.push_back(value);
        o.candidates.push_back(std::move(forms));
    }
    return o;
}

// A form proven equal to an output's value. A quantity defined by cases is a select in
// both; each select is named by one symbol, the same for selects whose condition and
// cases are proven equal, so that the proof is of the algebra around them (GiNaC's
// normal form of a select's arguments alone can differ between two writings of it).
// The names are kept for the whole kernel: a select met again (every output of a rough
// kernel holds the same ones) is named without proving anything again.
verdict kernel_builder::prove_form(const GiNaC::ex& form, const GiNaC::ex& value)
{
    if (!has_select(form) && !has_select(value))
        return prove_equal(form, value, d_.symbols, run_, when_unproven::give_up);
    GiNaC::exmap named;
    for (const GiNaC::ex& side : {form, value})
        for (GiNaC::const_postorder_iterator it = side.postorder_begin(); it != side.postorder_end(); ++it)
            if (is_select(*it))
                named[*it] = select_name(*it);
    return prove_equal(expanded_radicands(form.subs(named, GiNaC::subs_options::no_pattern)),
                       expanded_radicands(value.subs(named, GiNaC::subs_options::no_pattern)), d_.symbols,
                       run_, when_unproven::give_up);
}

// The symbol naming select `s`: that of a select met before whose condition and cases
// are proven equal to its own (any member of a class, in the order they were met), or
// a new one.
GiNaC::symbol kernel_builder::select_name(const GiNaC::ex& s)
{
    if (const auto known = select_names_.find(s); known != select_names_.end())
        return known->second;
    // Two selects that differ at a point of the domains are not proven equal: the proof,
    // whose expansion of two unequal conditions takes seconds, is tried only for selects
    // that agree at the points drawn (a rough kernel's fixed-mass limits meet dozens).
    const assumptions given = declared_assumptions(d_.symbols, run_);
    const auto differ = [&](const GiNaC::ex& a, const GiNaC::ex& b) {
        for (std::size_t i = 0; i < 3; ++i)
            if (nonzero_somewhere(a.op(i) - b.op(i), given, 2))
                return true;
        return false;
    };
    for (auto& [members, symbol] : select_classes_)
        for (const GiNaC::ex& member : members) {
            bool equal = !differ(s, member);
            for (std::size_t i = 0; i < 3 && equal; ++i)
                equal = prove_equal(s.op(i), member.op(i), d_.symbols, run_, when_unproven::give_up).what ==
                        verdict::status::proven;
            if (equal) {
                members.push_back(s);
                return select_names_.emplace(s, symbol).first->second;
            }
        }
    const GiNaC::symbol fresh(fmt::format("case_{}", select_classes_.size()));
    select_classes_.push_back({{s}, fresh});
    return select_names_.emplace(s, fresh).first->second;
}

void kernel_builder::require_inputs(const kernel& k, const GiNaC::ex& value, const std::string& member,
                    const source_location& where, const char* what) const
{
    // The symbols in `value`, gathered in one walk of it (not one walk a quantity).
    std::set<GiNaC::ex, GiNaC::ex_is_less> present;
    for (GiNaC::const_preorder_iterator it = value.preorder_begin(); it != value.preorder_end(); ++it)
        if (GiNaC::is_a<GiNaC::symbol>(*it))
            present.insert(*it);
    for (const quantity& q : d_.symbols.all()) {
        if (!present.count(q.symbol) || k.find_input(q.name))
            continue;
        throw error(where, fmt::format("kernel '{}': {} '{}' depends on '{}', which is not among its inputs",
                                       k.name, what, member, q.name));
    }
}

// `status = M, m` checks inputs against their domains; `status = <expr> < 0` a condition.
kernel_guard kernel_builder::make_guard(const kernel& k, const spec::kernel_guard& g)
{
    kernel_guard guard;
    guard.status = g.status.value;
    if (g.condition) {
        const claim_sides sides = d_.symbols.parse_claim(*g.condition);
        if (!sides.rhs.is_zero() || (sides.op != relation::less && sides.op != relation::greater))
            throw error(g.condition->where, "a guard condition reads '<expression> < 0' or '<expression> > 0'");
        // Its sums share a dimension, as an equation's do (h - 1000 adds a number to a length).
        check_expression(d_.symbols, sides.lhs, g.condition->where);
        guard.condition = in_kernel(sides.lhs);
        guard.op = sides.op;
        require_inputs(k, *guard.condition, "guard " + guard.status, g.condition->where);
        return guard;
    }
    for (const spec::text& name : g.parameters)
        guard.parameters.push_back(find_parameter(k, name)->name);
    return guard;
}

kernel build_kernel(const spec::kernel& source, const derivation& d, const resolver& resolve, proof_cache& run)
{
    return kernel_builder(d, resolve, run).build(source);
}

} // namespace impact::engine
