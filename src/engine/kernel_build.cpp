#include "engine/kernel_build.h"

#include "engine/dimensional.h"
#include "engine/cases.h"
#include "engine/prove.h"

#include <fmt/format.h>

#include <set>

namespace impact::engine {
namespace {

class kernel_builder {
public:
    kernel_builder(const derivation& d, const resolver& resolve, proof_cache& run)
        : d_(d), resolve_(resolve), run_(run)
    {
    }

    kernel build(const spec::kernel& spec_kernel)
    {
        kernel k;
        k.name = spec_kernel.name.value;
        k.where = spec_kernel.name.where;
        k.batch = spec_kernel.batch;
        std::set<std::string> seen;
        auto add_input = [&](const spec::text& name) {
            if (!seen.insert(name.value).second)
                throw error(name.where, fmt::format("kernel '{}' lists input '{}' twice", k.name, name.value));
            return d_.symbols.at(name);
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
        if (k.batch)
            for (const kernel_output& o : k.outputs) {
                const kernel_parameter* same = k.find_parameter(o.member);
                if (!same || same->components.size() != o.values.size())
                    throw error(spec_kernel.name.where,
                                fmt::format("kernel '{}' has batch = true, which writes each output over the input "
                                            "of its name, and '{}' is no input of its size; name the output after "
                                            "an input (v_M = ...), or give the batch to a kernel of its own",
                                            k.name, o.member));
            }
        for (const spec::error_bound& b : spec_kernel.bounds) {
            kernel_output* o = find_output(k, b.output);
            const auto& types = kernel_output::types;
            for (std::size_t t = 0; t < 3; ++t)
                if (!b.type || b.type->value == types[t]) {
                    o->bound_ulps[t] = b.ulps;
                    o->bound_because[t] = b.because.value;
                }
        }
        return k;
    }

private:
    // An error measured in units of the inputs' velocity times `scale_factor` is an
    // error of the output's own dimension (J, a momentum: velocity*M*m/(M + m)).
    void check_scale(const kernel_output& o, const spec::text& written) const
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
    GiNaC::ex in_kernel(const GiNaC::ex& e) const
    {
        return resolve_(e).subs(substitutions_, GiNaC::subs_options::no_pattern);
    }

    const kernel_parameter* find_parameter(const kernel& k, const spec::text& name) const
    {
        if (const kernel_parameter* p = k.find_parameter(name.value))
            return p;
        throw error(name.where, fmt::format("kernel '{}' has no input '{}'", k.name, name.value));
    }

    kernel_output* find_output(kernel& k, const spec::text& name) const
    {
        for (kernel_output& o : k.outputs)
            if (o.member == name.value)
                return &o;
        throw error(name.where, fmt::format("kernel '{}' has no output '{}'", k.name, name.value));
    }

    // An output's value and its candidate forms, each proven equal to the value and
    // each written in the kernel's inputs only.
    kernel_output make_output(const kernel& k, const spec::kernel_value& output, const spec::kernel& spec_kernel)
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
    verdict prove_form(const GiNaC::ex& form, const GiNaC::ex& value)
    {
        if (!has_select(form) && !has_select(value))
            return prove_equal(form, value, d_.symbols, run_);
        std::vector<GiNaC::ex> selects;
        for (const GiNaC::ex& side : {form, value})
            for (GiNaC::const_postorder_iterator it = side.postorder_begin(); it != side.postorder_end(); ++it)
                if (is_select(*it))
                    selects.push_back(*it);
        GiNaC::exmap named;
        std::vector<std::pair<GiNaC::ex, GiNaC::symbol>> classes;
        for (const GiNaC::ex& s : selects) {
            if (named.count(s))
                continue;
            const GiNaC::symbol* same = nullptr;
            for (const auto& [representative, symbol] : classes) {
                bool equal = true;
                for (std::size_t i = 0; i < 3 && equal; ++i)
                    equal = prove_equal(s.op(i), representative.op(i), d_.symbols, run_).what ==
                            verdict::status::proven;
                if (equal) {
                    same = &symbol;
                    break;
                }
            }
            if (!same) {
                classes.emplace_back(s, GiNaC::symbol(fmt::format("case_{}", classes.size())));
                same = &classes.back().second;
            }
            named[s] = *same;
        }
        return prove_equal(expanded_radicands(form.subs(named, GiNaC::subs_options::no_pattern)),
                           expanded_radicands(value.subs(named, GiNaC::subs_options::no_pattern)), d_.symbols,
                           run_);
    }

    // `e` with the base of every fractional power expanded: one radical written two ways
    // ((C_mx - C_Mx)^2 + ... and its expansion) is then one quantity to normal().
    static GiNaC::ex expanded_radicands(const GiNaC::ex& e)
    {
        if (GiNaC::is_a<GiNaC::power>(e) && GiNaC::is_a<GiNaC::numeric>(e.op(1)) &&
            !GiNaC::ex_to<GiNaC::numeric>(e.op(1)).is_integer())
            return GiNaC::pow(GiNaC::expand(expanded_radicands(e.op(0))), e.op(1));
        if (e.nops() == 0)
            return e;
        return e.map([](const GiNaC::ex& x) { return expanded_radicands(x); });
    }

    void require_inputs(const kernel& k, const GiNaC::ex& value, const std::string& member,
                        const source_location& where) const
    {
        // The symbols in `value`, gathered in one walk of it (not one walk a quantity).
        std::set<GiNaC::ex, GiNaC::ex_is_less> present;
        for (GiNaC::const_preorder_iterator it = value.preorder_begin(); it != value.preorder_end(); ++it)
            if (GiNaC::is_a<GiNaC::symbol>(*it))
                present.insert(*it);
        for (const quantity& q : d_.symbols.all()) {
            if (!present.count(q.symbol) || k.find_input(q.name))
                continue;
            throw error(where, fmt::format("kernel '{}': output '{}' depends on '{}', which is not among its inputs",
                                           k.name, member, q.name));
        }
    }

    // `status = M, m` checks inputs against their domains; `status = <expr> < 0` a condition.
    kernel_guard make_guard(const kernel& k, const spec::kernel_guard& g)
    {
        kernel_guard guard;
        guard.status = g.status.value;
        if (g.condition) {
            const claim_sides sides = d_.symbols.parse_claim(*g.condition);
            if (!sides.rhs.is_zero() || (sides.op != relation::less && sides.op != relation::greater))
                throw error(g.condition->where, "a guard condition reads '<expression> < 0' or '<expression> > 0'");
            guard.condition = in_kernel(sides.lhs);
            guard.op = sides.op;
            require_inputs(k, *guard.condition, "guard " + guard.status, g.condition->where);
            return guard;
        }
        for (const spec::text& name : g.parameters)
            guard.parameters.push_back(find_parameter(k, name)->name);
        return guard;
    }
    const derivation& d_;
    const resolver& resolve_;
    proof_cache& run_;
    /// Symbols of the results that the kernel computes from its inputs (r = C_M - C_m).
    GiNaC::exmap substitutions_;
};

} // namespace

kernel build_kernel(const spec::kernel& source, const derivation& d, const resolver& resolve, proof_cache& run)
{
    return kernel_builder(d, resolve, run).build(source);
}

} // namespace impact::engine
