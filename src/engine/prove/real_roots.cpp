// The points where an inequality may fail although random points miss them: y^8 + y^3 >=
// 2 y^5 fails only for y in about (0.82, 1), and (3 + z)^2 + 1 > 1 only at z = -3. With
// every symbol but one at a value, the difference of the sides is a rational function N/D
// of that one, whose sign is constant between the real roots of N D: they are isolated by
// Sturm's theorem (sturm.h) in exact rationals, and one point of each gap, the roots of N's
// factors of degree 1 and 2 over the rationals, and the domain's ends are the points to
// try (find_counterexample, sampling.cpp).
#include "engine/prove/prove_internal.h"
#include "engine/prove/sturm.h"

#include <algorithm>

namespace impact::engine {
namespace {

// Polynomials of higher degree are left to the sampler: their roots cost more than the
// claim is worth (and none of the paper's claims come near).
constexpr int max_degree = 24;

// One real root, within (low, high] (low == high: the root itself, a rational).
struct bracket {
    GiNaC::numeric low, high;
    bool exact() const { return low == high; }
};

// A polynomial in s with rational coefficients, without its repeated roots, and its Sturm
// sequence (sturm.h).
class square_free {
public:
    square_free(const GiNaC::ex& p, const GiNaC::ex& s)
        : s_(s),
          p_(GiNaC::expand(GiNaC::quo(p, GiNaC::gcd(p, GiNaC::diff(p, GiNaC::ex_to<GiNaC::symbol>(s))), s))),
          sequence_(sturm_sequence(p_, s))
    {}

    bool root_at(const GiNaC::numeric& x) const { return p_.subs(s_ == x).is_zero(); }

    // Its distinct roots in (a, b].
    int roots(const GiNaC::numeric& a, const GiNaC::numeric& b) const
    {
        return sign_changes(sequence_, s_, a, false) - sign_changes(sequence_, s_, b, true);
    }

    // A bound beyond the absolute value of every real root (Cauchy's, plus one).
    GiNaC::numeric root_bound() const
    {
        const GiNaC::numeric lead = GiNaC::ex_to<GiNaC::numeric>(p_.lcoeff(s_));
        GiNaC::numeric largest = 0;
        for (int k = 0; k < p_.degree(s_); ++k) {
            const GiNaC::numeric c = GiNaC::abs(GiNaC::ex_to<GiNaC::numeric>(p_.coeff(s_, k)) / lead);
            if (c > largest)
                largest = c;
        }
        return largest + 2;
    }

    // Its roots in (low, high], `count` of them, each alone in its bracket, in increasing
    // order.
    void isolate(const GiNaC::numeric& low, const GiNaC::numeric& high, int count, std::vector<bracket>& found) const
    {
        if (count <= 0)
            return;
        if (count == 1) {
            found.push_back(root_at(high) ? bracket{high, high} : bracket{low, high});
            return;
        }
        const GiNaC::numeric middle = (low + high) / 2;
        const int below = roots(low, middle);
        isolate(low, middle, below, found);
        isolate(middle, high, count - below, found);
    }

    // A bracket halved, keeping its root.
    void narrow(bracket& b) const
    {
        if (b.exact())
            return;
        const GiNaC::numeric middle = (b.low + b.high) / 2;
        if (root_at(middle))
            b = {middle, middle};
        else if (roots(b.low, middle) == 1)
            b.high = middle;
        else
            b.low = middle;
    }

private:
    GiNaC::ex s_, p_;
    std::vector<GiNaC::ex> sequence_;
};

// A numerator or denominator in s alone, of a degree worth isolating.
bool usable(const GiNaC::ex& p, const GiNaC::ex& s)
{
    return rational_polynomial_in(p, s) && p.ldegree(s) >= 0 && p.degree(s) <= max_degree;
}

// The roots of p's factors over the rationals of degree 1 and 2, exactly (radicals).
std::vector<GiNaC::ex> roots_of_small_factors(const GiNaC::ex& p, const GiNaC::ex& s)
{
    std::vector<GiNaC::ex> roots;
    const GiNaC::ex factored = GiNaC::factor(p);
    const auto add = [&](const GiNaC::ex& f) {
        const GiNaC::ex base = GiNaC::is_a<GiNaC::power>(f) ? f.op(0) : f;
        if (!base.is_polynomial(s))
            return;
        const GiNaC::ex a = base.coeff(s, 2), b = base.coeff(s, 1), c = base.coeff(s, 0);
        if (base.degree(s) == 1) {
            roots.push_back(-c / b);
        } else if (base.degree(s) == 2) {
            const GiNaC::ex discriminant = b * b - 4 * a * c;
            if (GiNaC::ex_to<GiNaC::numeric>(discriminant).is_negative())
                return;
            for (const int sign : {-1, 1})
                roots.push_back(GiNaC::normal((-b + sign * GiNaC::sqrt(discriminant)) / (2 * a)));
        }
    };
    if (GiNaC::is_a<GiNaC::mul>(factored))
        for (const GiNaC::ex& f : factored)
            add(f);
    else
        add(factored);
    return roots;
}

} // namespace

std::vector<GiNaC::ex> points_beside_roots(const GiNaC::ex& difference, const GiNaC::ex& s, const domain& range)
{
    const GiNaC::ex nd = GiNaC::numer_denom(GiNaC::normal(difference));
    const GiNaC::ex numerator = GiNaC::expand(nd.op(0)), denominator = GiNaC::expand(nd.op(1));
    if (!usable(numerator, s) || !usable(denominator, s) || numerator.is_zero() ||
        (numerator.degree(s) < 1 && denominator.degree(s) < 1))
        return {};   // not a rational function of s alone, or constant in it
    std::vector<GiNaC::ex> tries = roots_of_small_factors(numerator, s);
    // Breakpoints: the roots of N D inside the domain's closure (or beyond every root).
    const square_free breaks(GiNaC::expand(numerator * denominator), s);
    const closed_interval closure = closure_of(range);
    const GiNaC::numeric bound = breaks.root_bound();
    const GiNaC::numeric low = closure.lower ? *closure.lower : -bound, high = closure.upper ? *closure.upper : bound;
    std::vector<bracket> roots;
    if (low < high)
        breaks.isolate(low, high, breaks.roots(low, high), roots);
    if (!roots.empty() && roots.back().exact() && roots.back().low == high)
        roots.pop_back();   // the domain's end, tried as one
    tries.push_back(closure.lower ? low : low - 1);
    tries.push_back(closure.upper ? high : high + 1);
    GiNaC::numeric previous = low;
    for (std::size_t k = 0; k < roots.size(); ++k) {
        bracket& r = roots[k];
        // Each bracket narrowed until it lies strictly between the breakpoints beside it,
        // so that the point between them is no root.
        while (!r.exact() && r.low <= previous)
            breaks.narrow(r);
        tries.push_back((previous + r.low) / 2);
        const GiNaC::numeric next = k + 1 < roots.size() ? roots[k + 1].low : high;
        while (!r.exact() && r.high >= next)
            breaks.narrow(r);
        previous = r.high;
    }
    tries.push_back((previous + high) / 2);
    std::vector<GiNaC::ex> inside;
    for (const GiNaC::ex& x : tries)
        if (range.contains(x) && std::none_of(inside.begin(), inside.end(), [&](const GiNaC::ex& y) { return y.is_equal(x); }))
            inside.push_back(x);
    return inside;
}

} // namespace impact::engine
