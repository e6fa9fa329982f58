// The kernel of a fixed sphere (`fixed = ["M"]`): a kernel in the limit of one mass ->
// +infinity, its outputs, forms, lets, guards and regimes taken to their limits; the limits
// through quantities defined by cases (a select's condition by its sign for the mass large).
#include "engine/kernel/kernel_builder.h"

#include "engine/cases/cases.h"
#include "engine/algebra/polynomial.h"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <optional>
#include <string>

namespace impact::engine {
namespace {

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

} // namespace

// The kernel of a fixed sphere: `k` in the limit `mass` → +∞ (an obstacle no impulse
// moves). Each output's value is replaced by its limit, and each candidate form by its
// own limit where that is proven equal to the value's (a form whose limit is not, or
// has none, is left out: a let that vanishes may carry a factor that grows). The lets
// are taken to their limits too, a later one with the earlier ones held as they are
// (their limits finite), one whose limit is a number put into the forms that use it.
kernel kernel_builder::limit_kernel(const kernel& k, const spec::text& mass)
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

} // namespace impact::engine
