#include "engine/kernel/kernel_build.h"

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

// The limit of `e` as `s` -> +infinity, through quantities defined by cases: a select's
// condition by the sign it takes for s large (the limit of its quotient by s^k for the one
// k in 0, 1, 2 where that is finite and not 0), its values by their limits; a select inside
// another expression named by a symbol while the expression's limit is taken, its own
// limit put back after (the select is bounded: its cases' limits are finite). Nothing
// when no method establishes a finite limit.
// The limits one kernel's outputs, forms and lets need, by expression: they share their
// parts (a select of J_t, J_n, m_t) many times over.
using limit_memo = std::map<GiNaC::ex, std::optional<GiNaC::ex>, GiNaC::ex_is_less>;

std::optional<GiNaC::ex> limit_of_whole(const GiNaC::ex& e, const GiNaC::ex& s, const assumptions& given,
                                        limit_memo& memo);
std::optional<GiNaC::ex> limit_taken(const GiNaC::ex& e, const GiNaC::ex& s, const assumptions& given,
                                     limit_memo& memo);

// `memo` holds limits in this `s` under these assumptions only.
std::optional<GiNaC::ex> limit_at_infinity(const GiNaC::ex& e, const GiNaC::ex& s, const assumptions& given,
                                           limit_memo& memo)
{
    if (!e.has(s))
        return e;
    if (const auto known = memo.find(e); known != memo.end())
        return known->second;
    std::optional<GiNaC::ex> l = limit_taken(e, s, given, memo);
    memo.emplace(e, l);
    return l;
}

std::optional<GiNaC::ex> limit_taken(const GiNaC::ex& e, const GiNaC::ex& s, const assumptions& given,
                                     limit_memo& memo)
{
    if (is_select(e)) {
        // The condition divided term by term, so that the limit laws take each term's
        // limit apart (a friction cone's sides are long products, each with one factor
        // M + m): the series of the whole quotient takes seconds. A condition polynomial
        // in s is tried from its degree (at most 2) down: above its true degree (the
        // leading terms may cancel) the quotient's limit is zero, at it finite and not
        // zero, and the quotients below it, whose limits are infinite and are taken by the
        // series of the whole once the laws fail, are not tried. A limit is zero when its
        // numerator expands to zero, radicands expanded; one that does not decide is zero
        // unless found non-zero at a point of the domains (a refutation). A condition of
        // degree 3 or more, or one whose quotients all vanish, gives no limit.
        const GiNaC::ex& side = e.op(0);
        std::vector<int> powers{0, 1, 2};
        if (side.is_polynomial(s)) {
            powers.clear();
            for (int power = std::min(side.degree(s), 2); power >= 0; --power)
                powers.push_back(power);
        }
        const auto vanishes = [&](const GiNaC::ex& r) {
            if (r.is_zero())
                return true;
            switch (expand_numerator(expanded_radicands(r))) {
            case expansion::zero: return true;
            case expansion::nonzero: return false;
            case expansion::undecided: break;
            }
            return !nonzero_somewhere(r, given);
        };
        std::optional<GiNaC::ex> condition;
        for (const int power : powers) {
            if (condition)
                break;
            const GiNaC::ex scale = GiNaC::pow(s, -power);
            GiNaC::exvector terms;
            if (GiNaC::is_a<GiNaC::add>(side))
                for (const GiNaC::ex& term : side)
                    terms.push_back(term * scale);
            else
                terms.push_back(side * scale);
            const auto r = limit_at_infinity(GiNaC::add(terms), s, given, memo);
            if (r && !vanishes(*r))
                condition = *r;
        }
        const auto taken = limit_at_infinity(e.op(1), s, given, memo);
        const auto otherwise = limit_at_infinity(e.op(2), s, given, memo);
        if (!condition || !taken || !otherwise)
            return std::nullopt;
        if (GiNaC::is_a<GiNaC::numeric>(*condition))
            return GiNaC::ex_to<GiNaC::numeric>(*condition).is_positive() ? *taken : *otherwise;
        return select_positive(*condition, *taken, *otherwise);
    }
    // The limit laws, so that what the file wrote survives outside the parts that hold s:
    // a sum's limit is the sum of its terms', a product's the product of its factors', a
    // power's the power of its base's (a base whose limit is not 0 where the exponent is
    // negative), each finite. Where one is not, the terms (factors) free of s are kept as
    // they are and those with s taken to their limit together (M/(M + m) -> 1).
    if (GiNaC::is_a<GiNaC::add>(e) || GiNaC::is_a<GiNaC::mul>(e)) {
        const bool is_sum = GiNaC::is_a<GiNaC::add>(e);
        GiNaC::ex free = is_sum ? 0 : 1, with = is_sum ? 0 : 1, whole = is_sum ? 0 : 1;
        bool each = true;
        for (std::size_t i = 0; i < e.nops(); ++i) {
            const GiNaC::ex& part = e.op(i);
            if (!part.has(s)) {
                free = is_sum ? free + part : free * part;
                continue;
            }
            with = is_sum ? with + part : with * part;
            if (each) {
                const auto l = limit_at_infinity(part, s, given, memo);
                if (l)
                    whole = is_sum ? whole + *l : whole * *l;
                else
                    each = false;
            }
        }
        if (each)
            return is_sum ? free + whole : free * whole;
        if (with.is_equal(e))
            return limit_of_whole(e, s, given, memo);
        const auto l = limit_at_infinity(with, s, given, memo);
        if (!l)
            return std::nullopt;
        return is_sum ? free + *l : free * *l;
    }
    if (GiNaC::is_a<GiNaC::power>(e) && GiNaC::is_a<GiNaC::numeric>(e.op(1))) {
        const auto base = limit_at_infinity(e.op(0), s, given, memo);
        if (base && (!base->is_zero() || GiNaC::ex_to<GiNaC::numeric>(e.op(1)).is_positive()))
            return GiNaC::pow(*base, e.op(1));
    }
    return limit_of_whole(e, s, given, memo);
}

// The limit of `e` taken at once (engine::limit), a select inside it named by a symbol.
std::optional<GiNaC::ex> limit_of_whole(const GiNaC::ex& e, const GiNaC::ex& s, const assumptions& given,
                                        limit_memo& memo)
{
    if (has_select(e)) {
        // Each outermost select named by a symbol of its own, its limit kept to put back.
        struct naming : GiNaC::map_function {
            const GiNaC::ex& s;
            const assumptions& given;
            limit_memo& memo;
            GiNaC::exmap back;
            bool found = true;
            naming(const GiNaC::ex& s, const assumptions& given, limit_memo& memo) : s(s), given(given), memo(memo) {}
            GiNaC::ex operator()(const GiNaC::ex& x) override
            {
                if (!is_select(x))
                    return x.nops() == 0 ? x : x.map(*this);
                const auto l = limit_at_infinity(x, s, given, memo);
                if (!l) {
                    found = false;
                    return x;
                }
                const GiNaC::symbol z;
                back[z] = *l;
                return z;
            }
        } name(s, given, memo);
        GiNaC::exmap& back = name.back;
        const GiNaC::ex named = name(e);
        if (!name.found)
            return std::nullopt;
        const auto r = finite_limit_at_infinity(named, s, given);
        if (!r)
            return std::nullopt;
        return r->subs(back, GiNaC::subs_options::no_pattern);
    }
    return finite_limit_at_infinity(e, s, given);
}

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

    // The kernel of a fixed sphere: `k` in the limit `mass` → +∞ (an obstacle no impulse
    // moves). Each output's value is replaced by its limit, and each candidate form by its
    // own limit where that is proven equal to the value's (a form whose limit is not, or
    // has none, is left out: a let that vanishes may carry a factor that grows). The lets
    // are taken to their limits too, a later one with the earlier ones held as they are
    // (their limits finite), one whose limit is a number put into the forms that use it.
    kernel limit_kernel(const kernel& k, const spec::text& mass)
    {
        const kernel_parameter* p = k.find_parameter(mass.value);
        if (!p || p->is_array || !p->components.front().range.is_positive() ||
            p->components.front().range.infinity_included)
            throw error(mass.where, fmt::format("kernel '{}': fixed = [\"{}\"] names no scalar input of a positive, "
                                                "finite domain (a mass)",
                                                k.name, mass.value));
        const GiNaC::ex M = p->components.front().symbol;
        const assumptions given = declared_assumptions(d_.symbols, run_);
        limit_memo memo;
        kernel lk;
        lk.name = fmt::format("{}_fixed_{}", k.name, mass.value);
        lk.where = mass.where;
        lk.limit_of = k.name;
        lk.fixed_mass = mass.value;
        for (const kernel_parameter& q : k.parameters)
            if (q.name != mass.value)
                lk.parameters.push_back(q);
        auto refuse_if_on_mass = [&](const GiNaC::ex& e, const std::string& what) {
            if (e.has(M))
                throw error(mass.where, fmt::format("kernel '{}': {} depends on '{}', which fixed = [...] lets "
                                                    "grow without bound",
                                                    k.name, what, mass.value));
        };
        lk.velocities = k.velocities;
        lk.speeds = k.speeds;
        for (const GiNaC::ex& speed : k.speeds)
            refuse_if_on_mass(speed, "a velocity of its error scale");
        // The guards as they are, the fixed mass no longer among the inputs they test (the
        // kernel that calls this one tests it: +infinity).
        for (kernel_guard g : k.guards) {
            if (g.condition)
                refuse_if_on_mass(*g.condition, "guard " + g.status);
            g.parameters.erase(std::remove(g.parameters.begin(), g.parameters.end(), mass.value), g.parameters.end());
            if (g.condition || !g.parameters.empty())
                lk.guards.push_back(std::move(g));
        }
        auto limit_of = [&](const GiNaC::ex& e, const std::string& what) {
            const std::optional<GiNaC::ex> l = limit_at_infinity(e, M, given, memo);
            if (!l)
                throw error(mass.where, fmt::format("kernel '{}': no finite limit of {} as {} -> infinity", k.name,
                                                    what, mass.value));
            return *l;
        };
        // The regimes of the kernel's file in the limit: what they set the input to depends
        // on the quotients by the slope (the quantity may grow with the mass, as a friction
        // cone's sides do), so those are taken to their limits, the slope then 1.
        for (sampling_regime r : k.regimes) {
            if (r.inputs.front().is_equal(M))
                continue;   // the input it sets is no longer one
            auto regime_limit = [&](const GiNaC::ex& e) {
                const std::optional<GiNaC::ex> l = limit_at_infinity(e, M, given, memo);
                if (!l)
                    throw error(r.where, fmt::format("kernel '{}': regime '{}' has no finite limit as {} -> "
                                                     "infinity (fixed = [\"{}\"]): what it sets its input to grows "
                                                     "without bound",
                                                     k.name, r.name, mass.value, mass.value));
                return *l;
            };
            if (r.slopes.size() == 1) {
                r.offsets.front() = regime_limit(r.offsets.front() / r.slopes.front());
                if (r.what == sampling_regime::kind::ratio)
                    r.denominator = regime_limit(r.denominator / r.slopes.front());
                r.slopes.front() = 1;
            } else {
                // A vector: what it sets the inputs to is unchanged when the quantity and
                // the denominator are divided by the denominator.
                for (GiNaC::ex& e : r.offsets)
                    e = regime_limit(e / r.denominator);
                for (GiNaC::ex& e : r.slopes)
                    e = regime_limit(e / r.denominator);
                r.denominator = 1;
                if (std::all_of(r.slopes.begin(), r.slopes.end(), [](const GiNaC::ex& e) { return e.is_zero(); }))
                    throw error(r.where, fmt::format("kernel '{}': regime '{}' sets nothing as {} -> infinity "
                                                     "(fixed = [\"{}\"]): its quantity grows more slowly than "
                                                     "its denominator",
                                                     k.name, r.name, mass.value, mass.value));
            }
            lk.regimes.push_back(std::move(r));
        }
        GiNaC::exmap numbers;  // lets whose limit is a number
        for (const auto& [symbol, value] : k.lets) {
            const GiNaC::ex l = limit_of(value.subs(numbers, GiNaC::subs_options::no_pattern),
                                         "let " + d_.symbols.text(symbol));
            if (GiNaC::is_a<GiNaC::numeric>(l))
                numbers[symbol] = l;
            else
                lk.lets.emplace_back(symbol, l);
        }
        GiNaC::exmap finite_lets;  // each let of `k` in the inputs alone
        for (const auto& [symbol, value] : k.lets)
            finite_lets[symbol] = value.subs(finite_lets, GiNaC::subs_options::no_pattern);
        GiNaC::exmap lets;  // each let of the limit in the inputs alone
        for (const auto& [symbol, value] : lk.lets)
            lets[symbol] = value.subs(lets, GiNaC::subs_options::no_pattern);
        for (const kernel_output& o : k.outputs) {
            kernel_output lo = o;
            lo.values.clear();
            lo.candidates.clear();
            if (o.error == kernel_output::scale::velocity)
                lo.scale_factor = limit_of(o.scale_factor, "the error scale of " + o.member);
            for (std::size_t c = 0; c < o.values.size(); ++c) {
                const std::string name = o.is_array ? fmt::format("{}[{}]", o.member, c) : o.member;
                const GiNaC::ex value = limit_of(o.values[c], "output " + name);
                require_inputs(lk, value, o.member, mass.where);
                // A form's limit, kept where it is proven equal to the value's.
                auto limit_form = [&](const GiNaC::ex& written) -> std::optional<GiNaC::ex> {
                    const std::optional<GiNaC::ex> l = limit_at_infinity(written, M, given, memo);
                    if (!l || l->has(M) ||
                        prove_form(l->subs(lets, GiNaC::subs_options::no_pattern), value).what !=
                            verdict::status::proven)
                        return std::nullopt;
                    return l;
                };
                std::vector<form> forms;
                for (const form& f : o.candidates[c]) {
                    // With the lets of the limit; else with the finite kernel's written out
                    // (a let that vanishes times a mass that grows: k_impulse*M).
                    std::optional<GiNaC::ex> l = limit_form(f.value.subs(numbers, GiNaC::subs_options::no_pattern));
                    const GiNaC::ex written_out = f.value.subs(finite_lets, GiNaC::subs_options::no_pattern);
                    if (!l && !written_out.is_equal(f.value))
                        l = limit_form(written_out);
                    if (!l || std::any_of(forms.begin(), forms.end(),
                                          [&](const form& g) { return g.value.is_equal(*l); }))
                        continue;
                    forms.push_back({"limit of " + f.label, *l});
                }
                if (forms.empty())
                    forms.push_back({"limit of derived", value});
                lo.values.push_back(value);
                lo.candidates.push_back(std::move(forms));
            }
            lk.outputs.push_back(std::move(lo));
        }
        return lk;
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
    // The names are kept for the whole kernel: a select met again (every output of a rough
    // kernel holds the same ones) is named without proving anything again.
    verdict prove_form(const GiNaC::ex& form, const GiNaC::ex& value)
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
    GiNaC::symbol select_name(const GiNaC::ex& s)
    {
        if (const auto known = select_names_.find(s); known != select_names_.end())
            return known->second;
        for (auto& [members, symbol] : select_classes_)
            for (const GiNaC::ex& member : members) {
                bool equal = true;
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

    void require_inputs(const kernel& k, const GiNaC::ex& value, const std::string& member,
                        const source_location& where, const char* what = "output") const
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
    kernel_guard make_guard(const kernel& k, const spec::kernel_guard& g)
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
    // `[[kernel.regime]]`: the quantity that the input `set` makes take its value, written
    // in the kernel's inputs as offsets + slopes times the input's components (the input
    // must enter it so). A vector quantity is written "[A_x, A_y, A_z]"; its length is set.
    sampling_regime make_regime(const kernel& k, const spec::sampling_regime& r)
    {
        sampling_regime regime;
        regime.name = r.name.value;
        regime.where = r.name.where;
        regime.start = r.start ? r.start->value : "";
        const kernel_parameter* p = find_parameter(k, r.set);
        if (std::any_of(p->components.begin(), p->components.end(),
                        [](const quantity& c) { return c.range.what == domain::kind::interval; }))
            throw error(r.set.where, fmt::format("regime '{}' sets '{}': give a scalar input of the real line or "
                                                 "the positive numbers (an interval's ends have regimes of "
                                                 "their own), or a vector",
                                                 regime.name, r.set.value));
        if (p->is_array && r.boundary)
            throw error(r.set.where, fmt::format("regime '{}' sets the vector '{}': a boundary is approached by "
                                                 "setting one scalar input; a vector input is set by a ratio "
                                                 "(ratio = [\"[A_x, A_y, A_z]\", \"B\"])",
                                                 regime.name, r.set.value));
        for (const quantity& c : p->components)
            regime.inputs.push_back(c.symbol);
        auto same_dimension = [&](const GiNaC::ex& a, const GiNaC::ex& b, const spec::text& where) {
            const auto da = check_expression(d_.symbols, a, where.where);
            const auto db = check_expression(d_.symbols, b, where.where);
            if (da && db && *da != *db)
                throw error(where.where, fmt::format("regime '{}': {} is {}, {} is {}", regime.name,
                                                     d_.symbols.text(a), da->describe(), d_.symbols.text(b),
                                                     db->describe()));
        };
        std::vector<GiNaC::ex> quantities;
        const spec::text& written = r.boundary ? *r.boundary : r.ratio.front();
        if (r.boundary) {
            const claim_sides sides = d_.symbols.parse_claim(*r.boundary);
            if (sides.op != relation::equal)
                throw error(r.boundary->where, "a regime's boundary reads 'lhs = rhs'");
            same_dimension(sides.lhs, sides.rhs, *r.boundary);
            regime.what = sampling_regime::kind::boundary;
            quantities.push_back(in_kernel(sides.lhs - sides.rhs));
            regime.to = r.within;
        } else {
            const GiNaC::ex b = d_.symbols.parse(r.ratio[1]);
            for (const spec::text& component : vector_components(r.ratio[0])) {
                const GiNaC::ex a = d_.symbols.parse(component);
                same_dimension(a, b, r.ratio[1]);
                quantities.push_back(in_kernel(a));
            }
            regime.denominator = in_kernel(b);
            require_inputs(k, regime.denominator, regime.name, r.ratio[1].where, "regime");
            for (const GiNaC::ex& input : regime.inputs)
                if (regime.denominator.has(input))
                    throw error(r.ratio[1].where, fmt::format("regime '{}': '{}' depends on '{}', which the regime sets",
                                                              regime.name, r.ratio[1].value, r.set.value));
            regime.from = r.from;
            regime.to = r.to;
        }
        GiNaC::exmap at_zero;
        for (const GiNaC::ex& input : regime.inputs)
            at_zero[input] = 0;
        bool moves = false;
        for (const GiNaC::ex& quantity : quantities) {
            require_inputs(k, quantity, regime.name, written.where, "regime");
            for (const GiNaC::ex& input : regime.inputs) {
                const GiNaC::ex slope = quantity.diff(GiNaC::ex_to<GiNaC::symbol>(input));
                bool constant = true;
                for (const GiNaC::ex& other : regime.inputs)
                    constant = constant && !slope.has(other);
                if (!constant)
                    throw error(written.where, fmt::format("regime '{}': '{}' must enter '{}' as a multiple of it "
                                                           "plus what does not depend on it, so that one value of "
                                                           "it gives the quantity its value",
                                                           regime.name, r.set.value, written.value));
                moves = moves || !slope.is_zero();
                regime.slopes.push_back(slope);
            }
            regime.offsets.push_back(quantity.subs(at_zero, GiNaC::subs_options::no_pattern));
        }
        if (!moves)
            throw error(written.where, fmt::format("regime '{}': '{}' does not depend on '{}', which the regime sets",
                                                   regime.name, written.value, r.set.value));
        return regime;
    }

    // The components of a regime's quantity: "[a, b, c]" (commas between brackets and
    // parentheses left alone), or the one expression written.
    static std::vector<spec::text> vector_components(const spec::text& written)
    {
        const std::string& s = written.value;
        const std::size_t open = s.find_first_not_of(' ');
        const std::size_t close = s.find_last_not_of(' ');
        if (open == std::string::npos || s[open] != '[' || s[close] != ']')
            return {written};
        std::vector<spec::text> parts;
        int depth = 0;
        std::size_t start = open + 1;
        for (std::size_t i = open + 1; i <= close; ++i) {
            const char c = s[i];
            if (i == close && depth != 0)
                throw error(written.where, fmt::format("'{}' has unbalanced brackets", s));
            if (c == '(' || c == '[')
                ++depth;
            else if ((c == ')' || c == ']') && depth > 0)
                --depth;
            else if ((c == ',' && depth == 0) || i == close) {
                spec::text part = written;
                part.value = s.substr(start, i - start);
                if (part.value.find_first_not_of(' ') == std::string::npos)
                    throw error(written.where, fmt::format("'{}' has an empty component", s));
                parts.push_back(std::move(part));
                start = i + 1;
            }
        }
        return parts;
    }

    const derivation& d_;
    const resolver& resolve_;
    proof_cache& run_;
    /// Symbols of the results that the kernel computes from its inputs (r = C_M - C_m).
    GiNaC::exmap substitutions_;
    /// Each select met in a form's proof, by the symbol naming its class (`select_name`).
    std::map<GiNaC::ex, GiNaC::symbol, GiNaC::ex_is_less> select_names_;
    std::vector<std::pair<std::vector<GiNaC::ex>, GiNaC::symbol>> select_classes_;
};

} // namespace

kernel build_kernel(const spec::kernel& source, const derivation& d, const resolver& resolve, proof_cache& run)
{
    return kernel_builder(d, resolve, run).build(source);
}

} // namespace impact::engine
