#include "engine/solve/trigonometric.h"

#include "engine/solve/eliminate.h"

#include <cln/integer.h>
#include <cln/rational.h>
#include <cln/real.h>
#include <fmt/format.h>

namespace impact::engine {
namespace {

bool named(const GiNaC::ex& e, const char* name)
{
    return GiNaC::is_a<GiNaC::function>(e) && GiNaC::ex_to<GiNaC::function>(e).get_name() == name;
}

bool trigonometric(const GiNaC::ex& e)
{
    return named(e, "sin") || named(e, "cos") || named(e, "tan");
}

// A real constant: no symbol in it, and a real number when evaluated.
bool constant(const GiNaC::ex& e)
{
    for (GiNaC::const_preorder_iterator i = e.preorder_begin(); i != e.preorder_end(); ++i)
        if (GiNaC::is_a<GiNaC::symbol>(*i))
            return false;
    const GiNaC::ex value = GiNaC::evalf(e);
    return GiNaC::is_a<GiNaC::numeric>(value) && value.info(GiNaC::info_flags::real);
}

// The least integer ≥ q (rounded = ceiling) or the greatest ≤ q (floor) of a real constant:
// exactly for a rational (the quarter turns of a domain in π are), from 40 digits else.
cln::cl_I whole(const GiNaC::ex& q, bool ceiling)
{
    GiNaC::ex e = GiNaC::normal(q);
    if (!GiNaC::is_a<GiNaC::numeric>(e) || !e.info(GiNaC::info_flags::rational)) {
        const long saved = GiNaC::Digits;
        GiNaC::Digits = 40;
        e = GiNaC::evalf(e);
        GiNaC::Digits = saved;
    }
    const cln::cl_R x = cln::the<cln::cl_R>(GiNaC::ex_to<GiNaC::numeric>(e).to_cl_N());
    return ceiling ? cln::ceiling1(x) : cln::floor1(x);
}

// One end of an interval, or none (infinite).
struct end {
    std::optional<GiNaC::ex> at;
    bool open = true;
};

// What the sign prover shows of e, or nothing known when it cannot work it out.
sign_set proven_sign(const GiNaC::ex& e, const assumptions& given)
{
    try {
        return prove_sign(e, given).sign;
    } catch (const std::exception&) {
        return sign_set::any();
    }
}

bool proven_positive(const sign_set& s) { return !s.negative && !s.zero; }
bool proven_nonnegative(const sign_set& s) { return !s.negative; }

std::string end_text(const end& low, const end& high, const assumptions& given)
{
    return fmt::format("{}{}, {}{}", low.open ? '(' : '[', low.at ? given.text(*low.at) : "-infinity",
                       high.at ? given.text(*high.at) : "infinity", high.open ? ')' : ']');
}

// A family of roots x = principal + k·period, the principal value within [low, high].
struct family {
    GiNaC::ex principal;
    end low, high;
};

// The inverse function of w, and the interval it lies in (the why of every root).
struct inverse_range {
    GiNaC::ex value;
    end low, high;
};

} // namespace

std::optional<trigonometric_equation> trigonometric_form(const GiNaC::ex& p, const GiNaC::ex& u)
{
    // The one sin, cos or tan that holds u.
    std::optional<GiNaC::ex> call;
    for (GiNaC::const_preorder_iterator i = p.preorder_begin(); i != p.preorder_end(); ++i) {
        if (!trigonometric(*i) || !i->has(u))
            continue;
        if (call && !call->is_equal(*i))
            return std::nullopt;
        call = *i;
    }
    if (!call)
        return std::nullopt;
    const GiNaC::ex argument = GiNaC::expand(call->op(0));
    if (!argument.is_polynomial(u) || argument.degree(u) != 1)
        return std::nullopt;
    const GiNaC::symbol standing("f_");
    const GiNaC::ex q = GiNaC::expand(p.subs(GiNaC::exmap{{*call, standing}}, GiNaC::subs_options::no_pattern));
    if (q.has(u) || !q.is_polynomial(standing) || q.degree(standing) != 1)
        return std::nullopt;
    trigonometric_equation eq;
    eq.function = *call;
    eq.name = GiNaC::ex_to<GiNaC::function>(*call).get_name();
    eq.a = argument.coeff(u, 1);
    eq.b = argument.coeff(u, 0);
    eq.value = GiNaC::normal(-q.coeff(standing, 0) / q.coeff(standing, 1));
    return eq;
}

std::vector<trigonometric_root> trigonometric_roots(const trigonometric_equation& eq, const GiNaC::ex& u,
                                                    const domain& range, const assumptions& given,
                                                    std::string& no_root)
{
    const GiNaC::ex& w = eq.value;
    const bool bounded_value = eq.name != "tan";   // sin and cos take values in [-1, 1] only
    const std::string equation = fmt::format("{} = {}", given.text(eq.function), given.text(w));

    // The interval of w: what its sign and 1 - w, 1 + w are proven to be.
    end low, high;
    std::string existence;
    const sign_set sign = proven_sign(w, given);
    if (bounded_value) {
        const sign_set below_one = proven_sign(1 - w, given), above_minus_one = proven_sign(1 + w, given);
        if (!below_one.positive && !below_one.zero) {
            no_root = fmt::format("{} has no real root: {} > 1", equation, given.text(w));
            return {};
        }
        if (!above_minus_one.positive && !above_minus_one.zero) {
            no_root = fmt::format("{} has no real root: {} < -1", equation, given.text(w));
            return {};
        }
        low = {GiNaC::ex(-1), proven_positive(above_minus_one)};
        high = {GiNaC::ex(1), proven_positive(below_one)};
        existence = proven_nonnegative(below_one) && proven_nonnegative(above_minus_one)
                        ? fmt::format("-1 <= {} <= 1 is proven", given.text(w))
                        : fmt::format("a root exists where -1 <= {} <= 1, which is not proven: it is the "
                                      "condition of the value",
                                      given.text(w));
    }
    if (!sign.negative)
        low = {GiNaC::ex(0), !sign.zero};
    if (!sign.positive)
        high = {GiNaC::ex(0), !sign.zero};
    if (constant(w))
        low = high = {w, false};

    // Each family of roots, its principal value within the image of w's interval: the
    // inverse functions are increasing but for acos, which decreases.
    const auto image = [](GiNaC::ex (*inverse)(const GiNaC::ex&), const end& e, const end& infinite) {
        return e.at ? end{inverse(*e.at), e.open} : infinite;
    };
    const auto asin = [](const GiNaC::ex& v) -> GiNaC::ex { return GiNaC::asin(v); };
    const auto acos = [](const GiNaC::ex& v) -> GiNaC::ex { return GiNaC::acos(v); };
    const auto atan = [](const GiNaC::ex& v) -> GiNaC::ex { return GiNaC::atan(v); };
    const auto shifted = [](const end& e, const GiNaC::ex& by, bool negated) {
        return end{by + (negated ? -*e.at : *e.at), e.open};
    };
    std::vector<family> families;
    GiNaC::ex period = 2 * GiNaC::Pi;
    inverse_range inverse;
    if (eq.name == "sin") {
        const end l = image(asin, low, {}), h = image(asin, high, {});
        inverse = {asin(w), l, h};
        families.push_back({asin(w), l, h});
        families.push_back({GiNaC::Pi - asin(w), shifted(h, GiNaC::Pi, true), shifted(l, GiNaC::Pi, true)});
    } else if (eq.name == "cos") {
        const end l = image(acos, high, {}), h = image(acos, low, {});
        inverse = {acos(w), l, h};
        families.push_back({acos(w), l, h});
        families.push_back({-acos(w), shifted(h, 0, true), shifted(l, 0, true)});
    } else {
        period = GiNaC::Pi;
        const end l = image(atan, low, {-GiNaC::Pi / 2, true}), h = image(atan, high, {GiNaC::Pi / 2, true});
        inverse = {atan(w), l, h};
        families.push_back({atan(w), l, h});
    }

    const std::string unknown = given.text(u);
    if (range.what != domain::kind::interval)
        throw unsolvable(fmt::format("{} has infinitely many roots in the domain of {} ({}), one in each period "
                                     "{} of its argument; declare a bounded domain for {} (e.g. domain = \"(0, "
                                     "Pi/2)\") to solve it there",
                                     equation, unknown, range.to_string(), given.text(period), unknown));
    if (!constant(eq.a) || !constant(eq.b) || sign_of_constant(eq.a) == 0)
        throw unsolvable(fmt::format("the roots of {} in the domain of {} cannot be told: its argument {} is not "
                                     "a number times {} plus a number",
                                     equation, unknown, given.text(eq.a * u + eq.b), unknown));

    // The argument x = a u + b over the closure of u's domain, and each family's k there.
    const bool rising = sign_of_constant(eq.a) > 0;
    const GiNaC::ex x_low = eq.a * (rising ? range.exact_lower() : range.exact_upper()) + eq.b;
    const GiNaC::ex x_high = eq.a * (rising ? range.exact_upper() : range.exact_lower()) + eq.b;
    constexpr long most_roots = 24;
    std::vector<trigonometric_root> roots;
    for (const family& f : families) {
        const cln::cl_I from = whole((x_low - *f.high.at) / period, true);
        const cln::cl_I count = whole((x_high - *f.low.at) / period, false) - from;   // one less than the k's
        if (count >= cln::cl_I(most_roots) || cln::abs(from) > cln::cl_I(1L << 40))
            throw unsolvable(fmt::format("{} has more than {} roots in the domain of {} ({}); narrow its domain",
                                         equation, most_roots, unknown, range.to_string()));
        const long first = cln::cl_I_to_long(from), last = first + cln::cl_I_to_long(count);
        for (long k = first; k <= last; ++k) {
            const GiNaC::ex turn = k * period;
            const GiNaC::ex x = f.principal + turn;
            trigonometric_root r;
            r.unknown = u;
            r.value = GiNaC::expand((x - eq.b) / eq.a);
            const bool duplicate = std::any_of(roots.begin(), roots.end(), [&](const trigonometric_root& other) {
                return GiNaC::normal(other.value - r.value).is_zero();
            });
            if (duplicate)
                continue;   // a double root (sin x = 1), once
            const GiNaC::ex from = GiNaC::expand((*f.low.at + turn - eq.b) / eq.a);
            const GiNaC::ex to = GiNaC::expand((*f.high.at + turn - eq.b) / eq.a);
            r.low = rising ? from : to;
            r.high = rising ? to : from;
            r.low_open = rising ? f.low.open : f.high.open;
            r.high_open = rising ? f.high.open : f.low.open;
            r.why = constant(w) ? fmt::format("{} = {}", given.text(eq.a * u + eq.b), given.text(x))
                                : fmt::format("{} = {}, where {} lies in {} as {} lies in {}",
                                              given.text(eq.a * u + eq.b), given.text(x), given.text(inverse.value),
                                              end_text(inverse.low, inverse.high, given), given.text(w),
                                              end_text(low, high, given));
            r.existence = existence;
            roots.push_back(std::move(r));
        }
    }
    return roots;
}

interval_placement place_interval(const trigonometric_root& root, const domain& range)
{
    if (range.what != domain::kind::interval)
        return interval_placement::across;
    const GiNaC::ex lower = range.exact_lower(), upper = range.exact_upper();
    // Outside: it ends below the domain's start, or starts past its end (touching at an
    // end either leaves open).
    const int below = sign_of_constant(root.high - lower), above = sign_of_constant(root.low - upper);
    if (below < 0 || (below == 0 && (root.high_open || range.lower_open)) || above > 0 ||
        (above == 0 && (root.low_open || range.upper_open)))
        return interval_placement::outside;
    const int from = sign_of_constant(root.low - lower), to = sign_of_constant(upper - root.high);
    if ((from > 0 || (from == 0 && (root.low_open || !range.lower_open))) &&
        (to > 0 || (to == 0 && (root.high_open || !range.upper_open))))
        return interval_placement::inside;
    return interval_placement::across;
}

std::string interval_text(const GiNaC::ex& low, bool low_open, const GiNaC::ex& high, bool high_open,
                          const assumptions& given)
{
    return end_text({low, low_open}, {high, high_open}, given);
}

GiNaC::ex quarter_turns_reduced(const GiNaC::ex& e)
{
    struct reduce : GiNaC::map_function {
        GiNaC::ex operator()(const GiNaC::ex& x) override
        {
            const GiNaC::ex inner = x.map(*this);
            if (!trigonometric(inner))
                return inner;
            // The argument as y + q π, q rational.
            const GiNaC::ex argument = GiNaC::expand(inner.op(0));
            const GiNaC::ex q = argument.coeff(GiNaC::Pi, 1);
            if (!argument.is_polynomial(GiNaC::Pi) || argument.degree(GiNaC::Pi) > 1 ||
                !GiNaC::is_a<GiNaC::numeric>(q) || !(2 * q).info(GiNaC::info_flags::integer))
                return inner;
            GiNaC::ex y = argument.coeff(GiNaC::Pi, 0);
            const long m = ((GiNaC::ex_to<GiNaC::numeric>(2 * q).to_long() % 4) + 4) % 4;   // quarter turns
            // y = -z with z written without the sign (GiNaC leaves sin(-asin w) as it is):
            // sin and tan odd, cos even.
            int odd = 1;
            if (GiNaC::is_a<GiNaC::mul>(y))
                for (const GiNaC::ex& factor : y)
                    if (GiNaC::is_a<GiNaC::numeric>(factor) && GiNaC::ex_to<GiNaC::numeric>(factor).is_negative()) {
                        y = -y;
                        odd = -1;
                        break;
                    }
            if (named(inner, "sin"))
                return m == 0   ? odd * GiNaC::sin(y)
                       : m == 1 ? GiNaC::cos(y)
                       : m == 2 ? -odd * GiNaC::sin(y)
                                : -GiNaC::cos(y);
            if (named(inner, "cos"))
                return m == 0   ? GiNaC::cos(y)
                       : m == 1 ? -odd * GiNaC::sin(y)
                       : m == 2 ? -GiNaC::cos(y)
                                : odd * GiNaC::sin(y);
            return m % 2 == 0 ? odd * GiNaC::tan(y) : inner;   // tan has period π
        }
    } reduced;
    return reduced(e);
}

} // namespace impact::engine
