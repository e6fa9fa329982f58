// Identities of sin, cos, tan, sinh, cosh, tanh, exp and log decided (transcendental.h):
// angles over a Q-basis, expanded by the addition theorems and reduced modulo
// sin^2 + cos^2 = 1; exponents over a basis, as powers of exp; logarithms of products split
// where the factors are proven > 0; inverse functions undone on their principal ranges.
#include "engine/prove/transcendental.h"

#include "engine/prove/angles.h"
#include "engine/prove/sign_prover.h"

#include <fmt/format.h>

#include <algorithm>
#include <functional>
#include <map>
#include <set>

namespace impact::engine {
namespace {

using ex_map = std::map<GiNaC::ex, GiNaC::numeric, GiNaC::ex_is_less>;

// Past this many nodes an expression is left to the sampler: the expansions grow as powers.
constexpr std::size_t largest = 4000;
// The largest multiple of a base angle written out (sin(32 x) is a polynomial of degree 32).
constexpr long largest_multiple = 32;

bool is_call(const GiNaC::ex& e, std::initializer_list<const char*> names)
{
    if (!GiNaC::is_a<GiNaC::function>(e))
        return false;
    const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
    return std::any_of(names.begin(), names.end(), [&](const char* n) { return name == n; });
}

bool is_trig(const GiNaC::ex& e) { return is_call(e, {"sin", "cos", "tan"}) && e.nops() == 1; }
bool is_hyperbolic(const GiNaC::ex& e) { return is_call(e, {"exp", "sinh", "cosh", "tanh"}) && e.nops() == 1; }

bool has_any(const GiNaC::ex& e, bool (*which)(const GiNaC::ex&))
{
    for (GiNaC::const_preorder_iterator it = e.preorder_begin(); it != e.preorder_end(); ++it)
        if (which(*it))
            return true;
    return false;
}

bool is_log(const GiNaC::ex& e) { return is_call(e, {"log"}) && e.nops() == 1; }
bool is_inverse_of_trig(const GiNaC::ex& e)
{
    return is_call(e, {"asin", "acos", "atan"}) && e.nops() == 1 && is_trig(e.op(0));
}

std::size_t size_of(const GiNaC::ex& e)
{
    std::size_t n = 0;
    for (GiNaC::const_preorder_iterator it = e.preorder_begin(); it != e.preorder_end() && n <= largest; ++it)
        ++n;
    return n;
}

// An angle (or exponent) as a rational combination of its parts: atoms (a symbol, a
// product of symbols, a function, the number 1) with rational coefficients, and a rational
// multiple of Pi apart when `pi_apart`. None when a coefficient is not rational.
struct linear_form {
    ex_map parts;
    GiNaC::numeric pi = 0;
};

std::optional<linear_form> linear_form_of(const GiNaC::ex& u, bool pi_apart)
{
    linear_form out;
    const GiNaC::ex terms = GiNaC::expand(u);
    const std::size_t n = GiNaC::is_a<GiNaC::add>(terms) ? terms.nops() : 1;
    for (std::size_t i = 0; i < n; ++i) {
        const GiNaC::ex t = GiNaC::is_a<GiNaC::add>(terms) ? terms.op(i) : terms;
        GiNaC::numeric coefficient = 1;
        GiNaC::ex atom = 1;
        const std::size_t factors = GiNaC::is_a<GiNaC::mul>(t) ? t.nops() : 1;
        for (std::size_t j = 0; j < factors; ++j) {
            const GiNaC::ex f = GiNaC::is_a<GiNaC::mul>(t) ? t.op(j) : t;
            if (GiNaC::is_a<GiNaC::numeric>(f))
                coefficient *= GiNaC::ex_to<GiNaC::numeric>(f);
            else
                atom *= f;
        }
        if (!coefficient.is_rational())
            return std::nullopt;
        if (pi_apart && atom.is_equal(GiNaC::Pi))
            out.pi += coefficient;
        else
            out.parts[atom] += coefficient;
    }
    return out;
}

// The base angles of one kind of function (trigonometric or exponential): for each atom,
// the rational gcd g of its coefficients, the base g*atom, every coefficient an integer
// multiple of g.
struct basis {
    std::vector<GiNaC::ex> atoms;                 // in the order of their texts
    ex_map step;                                  // atom -> g
    std::map<GiNaC::ex, std::pair<GiNaC::ex, GiNaC::ex>, GiNaC::ex_is_less> values;   // atom -> (cos, sin) or (exp, -)
    std::vector<base_angle> bases;
};

GiNaC::numeric rational_gcd(const GiNaC::numeric& a, const GiNaC::numeric& b)
{
    return GiNaC::gcd(a.numer(), b.numer()) / GiNaC::lcm(a.denom(), b.denom());
}

// Collects the linear forms of the arguments of the functions `which` picks, not looking
// inside them; false when one is not a linear form.
bool collect(const GiNaC::ex& e, bool (*which)(const GiNaC::ex&), bool pi_apart, ex_map& steps,
             std::vector<linear_form>& forms)
{
    if (which(e)) {
        const auto form = linear_form_of(e.op(0), pi_apart);
        if (!form)
            return false;
        forms.push_back(*form);
        for (const auto& [atom, k] : form->parts) {
            if (k.is_zero())
                continue;
            auto [at, fresh] = steps.emplace(atom, GiNaC::abs(k));
            if (!fresh)
                at->second = rational_gcd(at->second, k);
        }
        return true;
    }
    for (std::size_t i = 0; i < e.nops(); ++i)
        if (!collect(e.op(i), which, pi_apart, steps, forms))
            return false;
    return true;
}

std::string text_of(const GiNaC::ex& e, const assumptions& given) { return given.text(e); }

// cos(k*b) and sin(k*b) from cos(b) and sin(b) by the addition theorem, k an integer.
std::pair<GiNaC::ex, GiNaC::ex> multiple(long k, const GiNaC::ex& c, const GiNaC::ex& s)
{
    GiNaC::ex ck = 1, sk = 0;
    for (long i = 0; i < std::abs(k); ++i) {
        const GiNaC::ex next_c = GiNaC::expand(ck * c - sk * s);
        sk = GiNaC::expand(sk * c + ck * s);
        ck = next_c;
    }
    return {ck, k < 0 ? GiNaC::ex(-sk) : sk};
}

// `e` with `f` applied to each of its operands.
GiNaC::ex map_operands(const GiNaC::ex& e, const std::function<GiNaC::ex(const GiNaC::ex&)>& f)
{
    struct applied : GiNaC::map_function {
        const std::function<GiNaC::ex(const GiNaC::ex&)>& f;
        explicit applied(const std::function<GiNaC::ex(const GiNaC::ex&)>& g) : f(g) {}
        GiNaC::ex operator()(const GiNaC::ex& x) override { return f(x); }
    } each(f);
    return e.nops() == 0 ? e : e.map(each);
}

// sin, cos and tan through the trigonometric basis; exp, sinh, cosh and tanh through the
// exponential one (none: left as they are).
class rewriter {
public:
    rewriter(const basis& trig, const basis* hyperbolic) : trig_(trig), hyperbolic_(hyperbolic) {}

    GiNaC::ex operator()(const GiNaC::ex& e) const
    {
        if (is_trig(e)) {
            const auto [c, s] = cos_sin(e.op(0));
            const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
            return name == "sin" ? s : name == "cos" ? c : s / c;
        }
        if (is_hyperbolic(e)) {
            if (!hyperbolic_)
                return e;
            const GiNaC::ex x = exp_of(e.op(0));
            const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
            if (name == "exp")
                return x;
            if (name == "sinh")
                return (x - 1 / x) / 2;
            if (name == "cosh")
                return (x + 1 / x) / 2;
            return (x - 1 / x) / (x + 1 / x);
        }
        return map_operands(e, [this](const GiNaC::ex& x) { return (*this)(x); });
    }

private:
    // (cos u, sin u) through the base angles: a multiple of Pi first, then each part.
    std::pair<GiNaC::ex, GiNaC::ex> cos_sin(const GiNaC::ex& u) const
    {
        const linear_form form = *linear_form_of(u, true);
        GiNaC::ex c = GiNaC::cos(form.pi * GiNaC::Pi), s = GiNaC::sin(form.pi * GiNaC::Pi);
        for (const GiNaC::ex& atom : trig_.atoms) {
            const auto at = form.parts.find(atom);
            if (at == form.parts.end() || at->second.is_zero())
                continue;
            const long k = (at->second / trig_.step.at(atom)).to_long();
            const auto& [cb, sb] = trig_.values.at(atom);
            const auto [ck, sk] = multiple(k, cb, sb);
            const GiNaC::ex next_c = GiNaC::expand(c * ck - s * sk);
            s = GiNaC::expand(s * ck + c * sk);
            c = next_c;
        }
        return {c, s};
    }

    // exp u as a product of powers of exp of the base exponents (exp(k log p) = p^k).
    GiNaC::ex exp_of(const GiNaC::ex& u) const
    {
        const linear_form form = *linear_form_of(u, false);
        GiNaC::ex x = 1;
        for (const auto& [atom, k] : form.parts) {
            if (k.is_zero())
                continue;
            if (is_log(atom))
                x *= GiNaC::pow(atom.op(0), k);
            else
                x *= GiNaC::pow(hyperbolic_->values.at(atom).first, (k / hyperbolic_->step.at(atom)).to_long());
        }
        return x;
    }

    const basis& trig_;
    const basis* hyperbolic_;
};

// The basis of the collected steps: sines and cosines (or exponentials) of each base.
basis basis_of(const ex_map& steps, bool trigonometric, const assumptions& given)
{
    basis out;
    for (const auto& [atom, g] : steps)
        out.atoms.push_back(atom);
    std::sort(out.atoms.begin(), out.atoms.end(),
              [&](const GiNaC::ex& a, const GiNaC::ex& b) { return text_of(a, given) < text_of(b, given); });
    for (const GiNaC::ex& atom : out.atoms) {
        const GiNaC::numeric g = steps.at(atom);
        out.step[atom] = g;
        const GiNaC::ex angle = g * atom;
        base_angle b{angle, 0, 0, false};
        if (trigonometric) {
            b.sine = GiNaC::sin(angle);
            b.cosine = GiNaC::cos(angle);
            if (is_trig(b.sine) || is_trig(b.cosine)) {
                const std::string at = text_of(angle, given);
                b.sine = GiNaC::symbol("sin(" + at + ")", "\\sin(" + at + ")");
                b.cosine = GiNaC::symbol("cos(" + at + ")", "\\cos(" + at + ")");
                b.symbols = true;
            }
            out.values[atom] = {b.cosine, b.sine};
        } else if (is_log(atom)) {
            continue;   // exp(k log p) = p^k: no base of its own
        } else {
            const std::string at = text_of(angle, given);
            b.sine = GiNaC::possymbol("exp(" + at + ")", "e^{" + at + "}");
            out.values[atom] = {b.sine, 0};
        }
        out.bases.push_back(b);
    }
    return out;
}

// Whether every multiple of a base angle the forms need is at most largest_multiple.
bool multiples_fit(const ex_map& steps, const std::vector<linear_form>& forms)
{
    for (const linear_form& form : forms)
        for (const auto& [atom, k] : form.parts)
            if (!k.is_zero() && GiNaC::abs(k / steps.at(atom)) > largest_multiple)
                return false;
    return true;
}

// What the decision did before comparing: the facts it used, in words.
struct facts {
    std::vector<std::string> inverses;   // "asin(sin(phi)) = phi, phi in [0, 1]"
    std::vector<finding> inverses_typeset;
    std::map<std::string, GiNaC::ex> positive;   // factors of logarithms' arguments proven > 0, by their texts
};

// asin(sin(u)) = u for u in [-Pi/2, Pi/2], acos(cos(u)) = u for u in [0, Pi], atan(tan(u))
// = u for u in [-Pi/2, Pi/2] (tan undefined at the ends).
GiNaC::ex undo_inverses(const GiNaC::ex& e, const assumptions& given, facts& used)
{
    if (!has_any(e, is_inverse_of_trig))
        return e;
    const GiNaC::ex mapped =
        map_operands(e, [&](const GiNaC::ex& x) { return undo_inverses(x, given, used); });
    if (!is_inverse_of_trig(mapped))
        return mapped;
    const std::string outer = GiNaC::ex_to<GiNaC::function>(mapped).get_name();
    const std::string inner = GiNaC::ex_to<GiNaC::function>(mapped.op(0)).get_name();
    const GiNaC::ex u = mapped.op(0).op(0);
    const auto r = range_of(u, given);
    if (!r)
        return mapped;
    const bool acos = outer == "acos";
    const GiNaC::ex low = acos ? GiNaC::ex(0) : -GiNaC::Pi / 2, high = acos ? GiNaC::Pi : GiNaC::Pi / 2;
    if (inner != outer.substr(1) || !within(*r, low, false, high, false))
        return mapped;
    used.inverses.push_back(fmt::format("{}({}({})) = {} with {} in {}, within [{}, {}]", outer, inner,
                                        given.text(u), given.text(u), given.text(u), r->to_string(given),
                                        given.text(low), given.text(high)));
    finding typeset;
    interval_said(typeset.states(mapped, relation::equal, u).say(" with ").math(u).say(" in "), *r, given);
    exact_interval principal;
    principal.low = low;
    principal.high = high;
    interval_said(typeset.say(", within "), principal, given);
    used.inverses_typeset.push_back(std::move(typeset));
    return u;
}

// The prime factors of a positive integer (trial division, small numbers only).
std::optional<std::vector<std::pair<GiNaC::numeric, int>>> primes_of(GiNaC::numeric n)
{
    std::vector<std::pair<GiNaC::numeric, int>> out;
    if (n > GiNaC::numeric(1000000000))
        return std::nullopt;
    for (long p = 2; GiNaC::numeric(p * p) <= n; ++p) {
        int k = 0;
        while (GiNaC::irem(n, GiNaC::numeric(p)).is_zero()) {
            n = n / p;
            ++k;
        }
        if (k > 0)
            out.emplace_back(p, k);
    }
    if (n > 1)
        out.emplace_back(n, 1);
    return out;
}

// The argument of a logarithm as factors and their exponents: products and powers
// flattened, sums factored under the domains, rationals into primes.
void factors_of(const GiNaC::ex& u, const GiNaC::ex& exponent, const assumptions& given,
                std::vector<std::pair<GiNaC::ex, GiNaC::ex>>& out, int depth = 0)
{
    if (GiNaC::is_a<GiNaC::mul>(u)) {
        for (std::size_t i = 0; i < u.nops(); ++i)
            factors_of(u.op(i), exponent, given, out, depth);
        return;
    }
    if (GiNaC::is_a<GiNaC::power>(u)) {
        factors_of(u.op(0), exponent * u.op(1), given, out, depth);
        return;
    }
    if (GiNaC::is_a<GiNaC::numeric>(u) && GiNaC::ex_to<GiNaC::numeric>(u).is_rational() &&
        GiNaC::ex_to<GiNaC::numeric>(u).is_positive()) {
        const GiNaC::numeric q = GiNaC::ex_to<GiNaC::numeric>(u);
        const auto top = primes_of(q.numer()), bottom = primes_of(q.denom());
        if (!top || !bottom) {
            out.emplace_back(u, exponent);
            return;
        }
        for (const auto& [p, k] : *top)
            out.emplace_back(p, exponent * k);
        for (const auto& [p, k] : *bottom)
            out.emplace_back(p, -exponent * k);
        return;
    }
    if (GiNaC::is_a<GiNaC::add>(u) && depth == 0) {
        const GiNaC::ex nd = GiNaC::normal(u).numer_denom();
        const GiNaC::ex top = factored_in(nd.op(0), given), bottom = factored_in(nd.op(1), given);
        if (!top.is_equal(u)) {
            factors_of(top, exponent, given, out, depth + 1);
            factors_of(bottom, -exponent, given, out, depth + 1);
            return;
        }
    }
    out.emplace_back(u, exponent);
}

// log(u) = sum e_i log(f_i) over the factors f_i of u proven > 0, plus log of the rest
// (positive too, where log(u) is defined).
GiNaC::ex split_logs(const GiNaC::ex& e, const assumptions& given, facts& used)
{
    if (!has_any(e, is_log))
        return e;
    if (!is_log(e))
        return map_operands(e, [&](const GiNaC::ex& x) { return split_logs(x, given, used); });
    std::vector<std::pair<GiNaC::ex, GiNaC::ex>> factors;
    factors_of(e.op(0), 1, given, factors);
    // The rest is the argument divided by the factors split off, not the product of the
    // others: sqrt(a b) is not sqrt(a) sqrt(b) where a, b < 0.
    GiNaC::ex sum = 0, rest = e.op(0);
    std::size_t split = 0;
    for (const auto& [f, k] : factors) {
        const bool positive = GiNaC::is_a<GiNaC::numeric>(f) ? GiNaC::ex_to<GiNaC::numeric>(f).is_positive()
                                                             : prove_sign(f, given).sign.is_positive();
        if (!positive)
            continue;
        rest *= GiNaC::pow(f, -k);
        sum += k * GiNaC::log(f);
        ++split;
        if (!GiNaC::is_a<GiNaC::numeric>(f))
            used.positive.emplace(given.text(f), f);
    }
    if (split == 0)
        return e;
    rest = GiNaC::normal(rest);
    if (!rest.is_equal(1))
        sum += GiNaC::log(rest);
    return sum;
}

} // namespace

std::optional<through_bases> through_base_angles(const GiNaC::ex& e, const assumptions& given)
{
    if (!has_any(e, is_trig) || size_of(e) > largest)
        return std::nullopt;
    ex_map steps;
    std::vector<linear_form> forms;
    if (!collect(e, is_trig, true, steps, forms) || !multiples_fit(steps, forms))
        return std::nullopt;
    try {
        const basis trig = basis_of(steps, true, given);
        return through_bases{rewriter(trig, nullptr)(e), trig.bases};
    } catch (const std::exception&) {
        return std::nullopt;
    }
}

GiNaC::ex reduced_modulo_circle(const GiNaC::ex& polynomial, const std::vector<base_angle>& bases)
{
    GiNaC::ex p = GiNaC::expand(polynomial);
    for (const base_angle& b : bases) {
        if (!b.symbols || !p.has(b.cosine))
            continue;
        // c^j = c^(j mod 2) (1 - s^2)^(j div 2)
        GiNaC::ex out = 0;
        const int degree = p.degree(b.cosine);
        for (int j = p.ldegree(b.cosine); j <= degree; ++j) {
            const GiNaC::ex coefficient = p.coeff(b.cosine, j);
            if (!coefficient.is_zero())
                out += coefficient * GiNaC::pow(b.cosine, j % 2) * GiNaC::pow(1 - GiNaC::pow(b.sine, 2), j / 2);
        }
        p = GiNaC::expand(out);
    }
    return p;
}

std::optional<verdict> decide_transcendental(const GiNaC::ex& lhs, const GiNaC::ex& rhs, const assumptions& given)
{
    const GiNaC::ex difference = lhs - rhs;
    const bool any = has_any(difference, is_trig) || has_any(difference, is_hyperbolic) ||
                     has_any(difference, is_log) || has_any(difference, is_inverse_of_trig);
    if (!any || size_of(difference) > largest)
        return std::nullopt;
    try {
        facts used;
        GiNaC::ex d = split_logs(undo_inverses(difference, given, used), given, used);
        ex_map trig_steps, exp_steps;
        std::vector<linear_form> trig_forms, exp_forms;
        if (!collect(d, is_trig, true, trig_steps, trig_forms) || !collect(d, is_hyperbolic, false, exp_steps, exp_forms) ||
            !multiples_fit(trig_steps, trig_forms) || !multiples_fit(exp_steps, exp_forms))
            return std::nullopt;
        const basis trig = basis_of(trig_steps, true, given), hyperbolic = basis_of(exp_steps, false, given);
        d = rewriter(trig, &hyperbolic)(d);
        const GiNaC::ex top = GiNaC::normal(d).numer_denom().op(0);
        if (!reduced_modulo_circle(top, trig.bases).is_zero())
            return std::nullopt;
        std::vector<std::string> how;
        finding typeset;
        const auto next = [&] {
            if (!typeset.parts.empty())
                typeset.say("; ");
        };
        // The basis in words, and typeset: each angle, "and" before the last.
        const auto listed = [&](const basis& b) {
            std::vector<std::string> texts;
            for (std::size_t i = 0; i < b.bases.size(); ++i) {
                texts.push_back(given.text(b.bases[i].angle));
                typeset.say(i == 0 ? "" : i + 1 == b.bases.size() ? " and " : ", ").math(b.bases[i].angle);
            }
            return fmt::format("{{{}}}", fmt::join(texts, ", "));
        };
        if (!trig.bases.empty()) {
            typeset.say("a trigonometric identity: the angles written over ");
            how.push_back(fmt::format("trigonometric identity, angles over the basis {} reduced modulo "
                                      "sin^2 + cos^2 = 1",
                                      listed(trig)));
            typeset.say(", reduced modulo ");
            for (std::size_t i = 0; i < trig.bases.size(); ++i) {
                const GiNaC::ex& a = trig.bases[i].angle;
                typeset.say(i == 0 ? "" : i + 1 == trig.bases.size() ? " and " : ", ")
                    .states(GiNaC::pow(GiNaC::sin(a), 2) + GiNaC::pow(GiNaC::cos(a), 2), relation::equal, 1);
            }
        }
        if (!hyperbolic.bases.empty()) {
            next();
            typeset.say("exp, sinh, cosh and tanh as powers of exp over ");
            how.push_back(fmt::format("exp, sinh, cosh and tanh as powers of exp over the basis {}",
                                      listed(hyperbolic)));
        }
        if (!used.positive.empty()) {
            next();
            typeset.say("logarithms of products split into logarithms of factors proven positive: ");
            std::vector<std::string> texts;
            for (const auto& [text, factor] : used.positive) {
                typeset.say(texts.empty() ? "" : ", ").math(factor);
                texts.push_back(text);
            }
            how.push_back(fmt::format("logarithms of products split into logarithms of factors proven > 0: {}",
                                      fmt::join(texts, ", ")));
        }
        for (std::size_t i = 0; i < used.inverses.size(); ++i) {
            next();
            how.push_back(used.inverses[i]);
            typeset.parts.insert(typeset.parts.end(), used.inverses_typeset[i].parts.begin(),
                                 used.inverses_typeset[i].parts.end());
        }
        if (how.empty())
            return std::nullopt;
        verdict v;
        v.what = verdict::status::proven;
        v.residual = 0;
        v.how = verdict::basis::decided;
        v.method = fmt::format("{}: the difference is zero", fmt::join(how, "; "));
        v.typeset = std::move(typeset.say(": the difference of the sides is zero"));
        return v;
    } catch (const std::exception&) {
        return std::nullopt;
    }
}

} // namespace impact::engine
