#include "engine/solve/eliminate.h"

#include "engine/algebra/polynomial.h"

#include <cln/rational.h>
#include <cln/real.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace impact::engine {
namespace {

bool has_any(const GiNaC::ex& e, const std::vector<GiNaC::ex>& symbols)
{
    for (const GiNaC::ex& s : symbols)
        if (e.has(s))
            return true;
    return false;
}

// √n = k√r for a positive rational n, k the largest square taken out of it by trial
// division (numbers in derivations are small): √8 = 2√2, √(9/2) = 3√2/2.
GiNaC::ex root_of_number(const GiNaC::numeric& n)
{
    if (!n.is_rational() || !n.is_positive())
        return GiNaC::sqrt(GiNaC::ex(n));   // GiNaC::sqrt(numeric) would be a float
    GiNaC::numeric whole = n.numer() * n.denom(), outside = 1;
    for (GiNaC::numeric k = 2; k < 1000 && k * k <= whole; ++k) {
        while (GiNaC::irem(whole, k * k).is_zero()) {
            whole = GiNaC::iquo(whole, k * k);
            outside *= k;
        }
    }
    return outside * GiNaC::sqrt(GiNaC::ex(whole)) / n.denom();
}

// The factors of a product, or the expression as its one factor.
GiNaC::exvector factors_of(const GiNaC::ex& f)
{
    GiNaC::exvector factors;
    if (GiNaC::is_a<GiNaC::mul>(f))
        factors.assign(f.begin(), f.end());
    else
        factors.push_back(f);
    return factors;
}

// The sign of a polynomial's coefficient of its first monomial, the monomials ordered by
// the names and powers of their symbols (not by GiNaC's order of terms, which changes from
// run to run).
int first_sign(const GiNaC::ex& sum)
{
    std::string first;
    int sign = 1;
    bool any = false;
    const GiNaC::ex expanded = GiNaC::expand(sum);
    const GiNaC::exvector terms =
        GiNaC::is_a<GiNaC::add>(expanded) ? GiNaC::exvector(expanded.begin(), expanded.end()) : GiNaC::exvector{expanded};
    for (const GiNaC::ex& term : terms) {
        std::vector<std::string> powers;
        GiNaC::numeric coefficient = 1;
        for (const GiNaC::ex& f : factors_of(term)) {
            if (GiNaC::is_a<GiNaC::numeric>(f))
                coefficient *= GiNaC::ex_to<GiNaC::numeric>(f);
            else if (GiNaC::is_a<GiNaC::symbol>(f))
                powers.push_back(GiNaC::ex_to<GiNaC::symbol>(f).get_name() + "^1");
            else if (GiNaC::is_a<GiNaC::power>(f) && GiNaC::is_a<GiNaC::symbol>(f.op(0)) &&
                     f.op(1).info(GiNaC::info_flags::integer))
                powers.push_back(GiNaC::ex_to<GiNaC::symbol>(f.op(0)).get_name() + "^" +
                                 std::to_string(GiNaC::ex_to<GiNaC::numeric>(f.op(1)).to_int()));
        }
        std::sort(powers.begin(), powers.end());
        std::string key;
        for (const std::string& p : powers)
            key += p + "*";
        if (!any || key < first) {
            first = key;
            sign = coefficient.is_negative() ? -1 : 1;
            any = true;
        }
    }
    return sign;
}

// The number of nodes of an expression's tree: its size, whatever the order of its terms.
std::size_t size_of(const GiNaC::ex& e)
{
    std::size_t n = 1;
    for (std::size_t i = 0; i < e.nops(); ++i)
        n += size_of(e.op(i));
    return n;
}

// Rather too many branches than a search that does not end.
constexpr int deepest = 40;

} // namespace

GiNaC::ex polynomial_of(const GiNaC::ex& e)
{
    const GiNaC::ex difference = GiNaC::is_a<GiNaC::relational>(e) ? e.lhs() - e.rhs() : e;
    return GiNaC::expand(GiNaC::normal(difference).numer_denom().op(0));
}

GiNaC::ex root_up_to_sign(const GiNaC::ex& d, proof_cache& run)
{
    // The square of each factor is taken out whatever the factor's sign, since both
    // roots ±√d are taken.
    const GiNaC::ex nd = GiNaC::normal(d).numer_denom();
    GiNaC::ex outside = 1, inside = 1;
    for (int part = 0; part < 2; ++part) {
        for (const GiNaC::ex& g : factors_of(factor_polynomial(nd.op(part), run))) {
            GiNaC::ex base = g;
            GiNaC::numeric k = 1;
            if (GiNaC::is_a<GiNaC::power>(g) && g.op(1).info(GiNaC::info_flags::posint)) {
                base = g.op(0);
                k = GiNaC::ex_to<GiNaC::numeric>(g.op(1));
            }
            const GiNaC::numeric half = k.is_even() ? k / 2 : (k - 1) / 2;
            const GiNaC::ex out = GiNaC::pow(base, half), in = GiNaC::pow(base, k - 2 * half);
            outside = part == 0 ? outside * out : outside / out;
            inside = part == 0 ? inside * in : inside / in;
        }
    }
    // A positive number comes out of the root as far as it is a square; the rest of
    // the root is kept whole. Each sum in it is given its sign by its own terms, not by
    // factor() (whose choice follows GiNaC's order of terms, which follows addresses and
    // changes from run to run), so that the number's sign, and the radicand, do not.
    GiNaC::numeric number = 1;
    GiNaC::ex rest = 1;
    for (const GiNaC::ex& f : factors_of(inside)) {
        if (GiNaC::is_a<GiNaC::numeric>(f)) {
            number *= GiNaC::ex_to<GiNaC::numeric>(f);
            continue;
        }
        const bool below = GiNaC::is_a<GiNaC::power>(f) && f.op(1).is_equal(-1);
        const GiNaC::ex base = below ? f.op(0) : f;
        if (GiNaC::is_a<GiNaC::add>(base) && first_sign(base) < 0) {
            number = -number;
            rest *= below ? 1 / GiNaC::expand(-base) : GiNaC::expand(-base);
        } else {
            rest *= f;
        }
    }
    if (!number.is_real() || number.is_zero())
        return outside * GiNaC::sqrt(inside);
    // A negative number's sign stays inside, with the rest factored or expanded, whichever
    // is the smaller: √(s⁴ − g²X²) rather than √(−(Xg + s²)(Xg − s²)), but
    // √(−(R + r + d)(R + r − d)(R − r + d)(R − r − d)) as Heron has it.
    if (number.is_negative()) {
        number = -number;
        const GiNaC::ex expanded = GiNaC::expand(-rest);
        rest = size_of(expanded) < size_of(-rest) ? expanded : -rest;
    }
    return outside * root_of_number(number) * GiNaC::sqrt(rest);
}

void eliminator::branch(const std::vector<GiNaC::ex>& equations, const std::vector<GiNaC::ex>& unknowns,
                        const GiNaC::exmap& values, bool unverified, int depth)
{
    if (depth > deepest)
        throw unsolvable(fmt::format("eliminating {} takes more than {} steps", names(unknowns), deepest));
    std::vector<GiNaC::ex> left;
    for (const GiNaC::ex& e : equations) {
        const GiNaC::ex p = polynomial_of(e);
        if (p.is_zero())
            continue;
        if (!has_any(p, unknowns)) {
            ++dead_ends;
            return;
        }
        left.push_back(p);
    }
    if (unknowns.empty()) {
        found.push_back({values, unverified});
        return;
    }
    if (left.empty())
        throw unsolvable(
            fmt::format("the equations do not determine {}: the system is underdetermined", names(unknowns)));
    // 1. An unknown that an equation holds linearly, with a coefficient free of the
    // unknowns: u = −c₀/c₁, substituted everywhere.
    for (const GiNaC::ex& p : left) {
        for (const GiNaC::ex& u : unknowns) {
            if (!p.is_polynomial(u) || p.degree(u) != 1 || has_any(p.coeff(u, 1), unknowns))
                continue;
            eliminate(left, p, unknowns, u, -p.coeff(u, 0) / p.coeff(u, 1), values, unverified, depth);
            return;
        }
    }
    // 2. An equation in one unknown: of degree two first, then any other.
    for (const bool any_degree : {false, true}) {
        for (const GiNaC::ex& p : left) {
            std::vector<GiNaC::ex> in;
            for (const GiNaC::ex& u : unknowns)
                if (p.has(u))
                    in.push_back(u);
            if (in.size() == 1 && p.is_polynomial(in.front()) &&
                solve_in_one(left, p, in.front(), unknowns, values, unverified, depth, any_degree))
                return;
        }
    }
    // 2'. An equation in one unknown that holds it in sin, cos or tan alone.
    for (const GiNaC::ex& p : left) {
        std::vector<GiNaC::ex> in;
        for (const GiNaC::ex& u : unknowns)
            if (p.has(u))
                in.push_back(u);
        if (in.size() == 1 && !p.is_polynomial(in.front()) &&
            solve_trigonometric(left, p, in.front(), unknowns, values, unverified, depth))
            return;
    }
    // 3. Linear in u with a coefficient c₁ that holds other unknowns: c₁ ≠ 0 and u =
    // −c₀/c₁, or c₁ = 0 and then c₀ = 0 too.
    for (const GiNaC::ex& p : left) {
        for (const GiNaC::ex& u : unknowns) {
            if (!p.is_polynomial(u) || p.degree(u) != 1)
                continue;
            const GiNaC::ex c1 = p.coeff(u, 1), c0 = p.coeff(u, 0);
            eliminate(left, p, unknowns, u, -c0 / c1, values, true, depth);
            std::vector<GiNaC::ex> degenerate;
            for (const GiNaC::ex& q : left)
                if (!q.is_equal(p))
                    degenerate.push_back(q);
            degenerate.push_back(c1);
            degenerate.push_back(c0);
            branch(degenerate, unknowns, values, unverified, depth + 1);
            return;
        }
    }
    // 4. Two equations sharing an unknown: the second replaced by their resultant in it.
    for (std::size_t i = 0; i < left.size(); ++i) {
        for (std::size_t j = i + 1; j < left.size(); ++j) {
            for (const GiNaC::ex& u : unknowns) {
                if (!left[i].has(u) || !left[j].has(u) || !left[i].is_polynomial(u) || !left[j].is_polynomial(u))
                    continue;
                const GiNaC::ex r = GiNaC::expand(GiNaC::resultant(left[i], left[j], u));
                if (r.is_zero())
                    continue;   // a common factor: no resultant of use
                std::vector<GiNaC::ex> reduced = left;
                reduced[j] = r;
                branch(reduced, unknowns, values, true, depth + 1);
                return;
            }
        }
    }
    std::string degrees;
    for (const GiNaC::ex& p : left)
        for (const GiNaC::ex& u : unknowns)
            if (p.has(u))
                degrees += fmt::format("{}{} = 0 is {} in {}", degrees.empty() ? "" : "; ", symbols_.text(p),
                                       p.is_polynomial(u) ? fmt::format("of degree {}", p.degree(u))
                                                          : std::string("not polynomial"),
                                       symbols_.text(u));
    throw unsolvable(fmt::format("the system is not linear in {}, and eliminating the unknowns it holds "
                                 "linearly leaves no equation of degree 2 or less in one unknown, nor one "
                                 "linear in sin, cos or tan of an expression linear in one unknown ({})",
                                 names(unknowns), degrees));
}

bool eliminator::solve_trigonometric(const std::vector<GiNaC::ex>& left, const GiNaC::ex& p, const GiNaC::ex& u,
                                     const std::vector<GiNaC::ex>& unknowns, const GiNaC::exmap& values,
                                     bool unverified, int depth)
{
    const std::optional<trigonometric_equation> eq = trigonometric_form(p, u);
    if (!eq)
        return false;
    const auto narrowed = given_.domains.find(u);
    const domain* declared = symbols_.domain_of(u);
    const domain range = narrowed != given_.domains.end() ? narrowed->second : declared ? *declared : domain{};
    std::string no_root;
    const std::vector<trigonometric_root> roots = trigonometric_roots(*eq, u, range, given_, no_root);
    if (!no_root.empty())
        complex.push_back(no_root);
    for (const trigonometric_root& r : roots) {
        trigonometric.push_back(r);
        eliminate(left, p, unknowns, u, r.value, values, unverified, depth);
    }
    if (roots.empty() && no_root.empty())
        complex.push_back(fmt::format("{} = {} has no root in the domain of {} ({})", symbols_.text(eq->function),
                                      symbols_.text(eq->value), symbols_.text(u), range.to_string()));
    return true;
}

bool eliminator::solve_in_one(const std::vector<GiNaC::ex>& left, const GiNaC::ex& p, const GiNaC::ex& u,
                              const std::vector<GiNaC::ex>& unknowns, const GiNaC::exmap& values, bool unverified,
                              int depth, bool any_degree)
{
    const int degree = p.degree(u);
    if (degree == 2) {
        quadratic(left, p, u, unknowns, values, unverified, depth, p.coeff(u, 2), p.coeff(u, 1), p.coeff(u, 0), false);
        return true;
    }
    if (!any_degree)
        return false;
    // Of a higher degree: its factors over the rationals, each solved (T³ − 2wT²/g: T = 0
    // twice and T = 2w/g).
    auto squared = [&](const GiNaC::ex& f) {
        const GiNaC::ex e = GiNaC::expand(f);
        return e.degree(u) == 4 && e.coeff(u, 3).is_zero() && e.coeff(u, 1).is_zero();
    };
    const GiNaC::ex factored = factor_polynomial(p, *given_.run);
    std::vector<GiNaC::ex> parts;
    for (const GiNaC::ex& f : factors_of(factored)) {
        const GiNaC::ex base = GiNaC::is_a<GiNaC::power>(f) && f.op(1).info(GiNaC::info_flags::posint) ? f.op(0) : f;
        if (!base.has(u))
            continue;
        // Each factor written with a positive leading coefficient in u (GiNaC's factor
        // may give either sign).
        GiNaC::ex e = GiNaC::expand(base);
        if (first_sign(e.lcoeff(u)) < 0)
            e = GiNaC::expand(-e);
        if (e.degree(u) > 2 && !squared(e))
            throw unsolvable(fmt::format(
                "the system is not linear in {}: {} = 0 is of degree {} in {}{}: beyond the quadratic formula (a "
                "polynomial in one unknown is solved when its factors over the rationals are of degree 2 or less, "
                "or quadratic in {}^2)",
                names(unknowns), symbols_.text(p), degree, symbols_.text(u),
                e.is_equal(p) ? std::string(" and has no factor over the rationals")
                              : fmt::format(", and its factor {} is of degree {}", symbols_.text(e), e.degree(u)),
                symbols_.text(u)));
        parts.push_back(e);
    }
    for (const GiNaC::ex& e : parts) {
        if (e.degree(u) == 1)
            eliminate(left, p, unknowns, u, -e.coeff(u, 0) / e.coeff(u, 1), values, unverified, depth);
        else if (e.degree(u) == 2)
            quadratic(left, p, u, unknowns, values, unverified, depth, e.coeff(u, 2), e.coeff(u, 1), e.coeff(u, 0),
                      false);
        else
            quadratic(left, p, u, unknowns, values, unverified, depth, e.coeff(u, 4), e.coeff(u, 2), e.coeff(u, 0),
                      true);
    }
    return true;
}

void eliminator::quadratic(const std::vector<GiNaC::ex>& left, const GiNaC::ex& p, const GiNaC::ex& u,
                           const std::vector<GiNaC::ex>& unknowns, const GiNaC::exmap& values, bool unverified,
                           int depth, const GiNaC::ex& a_given, const GiNaC::ex& b_given, const GiNaC::ex& c_given,
                           bool squared)
{
    // a of one sign whatever the run, so that the roots (−b + √Δ)/(2a), (−b − √Δ)/(2a)
    // come in one order.
    const int turn = first_sign(a_given);
    const GiNaC::ex a = turn * a_given, b = turn * b_given, c = turn * c_given;
    const GiNaC::ex discriminant = GiNaC::expand(b * b - 4 * a * c);
    const sign_set s = prove_sign(discriminant, given_).sign;
    const std::string of = squared ? fmt::format(" (a quadratic in {})", symbols_.text(GiNaC::pow(u, 2))) : "";
    if (!s.positive && !s.zero) {
        complex.push_back(fmt::format("{} = 0{} has no real root (b^2 - 4 a c = {} < 0)", symbols_.text(p), of,
                                      symbols_.text(discriminant)));
        return;
    }
    const GiNaC::ex root = discriminant.is_zero() ? GiNaC::ex(0) : root_up_to_sign(discriminant, *given_.run);
    std::vector<GiNaC::ex> roots = {(-b + root) / (2 * a)};
    if (!root.is_zero())
        roots.push_back((-b - root) / (2 * a));
    if (!squared) {
        for (const GiNaC::ex& r : roots)
            eliminate(left, p, unknowns, u, r, values, unverified, depth);
        return;
    }
    // u² = w: u = ±√w for a w not proven negative.
    for (const GiNaC::ex& w : roots) {
        const sign_set of_w = prove_sign(w, given_).sign;
        if (!of_w.positive && !of_w.zero) {
            complex.push_back(fmt::format("{}^2 = {} < 0 has no real root", symbols_.text(u), symbols_.text(w)));
            continue;
        }
        const GiNaC::ex r = has_radical(w) ? GiNaC::sqrt(w) : root_up_to_sign(w, *given_.run);
        eliminate(left, p, unknowns, u, r, values, unverified, depth);
        if (!w.is_zero())
            eliminate(left, p, unknowns, u, -r, values, unverified, depth);
    }
}

void eliminator::eliminate(const std::vector<GiNaC::ex>& left, const GiNaC::ex& used,
                           const std::vector<GiNaC::ex>& unknowns, const GiNaC::ex& u, const GiNaC::ex& value,
                           const GiNaC::exmap& values, bool unverified, int depth)
{
    const GiNaC::exmap one{{u, value}};
    std::vector<GiNaC::ex> rest;
    GiNaC::exmap now;
    try {
        for (const GiNaC::ex& p : left)
            if (!p.is_equal(used))
                rest.push_back(p.subs(one, GiNaC::subs_options::no_pattern));
        for (const auto& [symbol, earlier] : values)
            now[symbol] = earlier.subs(one, GiNaC::subs_options::no_pattern);
    } catch (const std::exception&) {
        // A value −c₀/c₁ of stage 3 whose c₁ this value makes zero: that case is the
        // branch c₁ = 0.
        ++dead_ends;
        return;
    }
    std::vector<GiNaC::ex> others;
    for (const GiNaC::ex& v : unknowns)
        if (!v.is_equal(u))
            others.push_back(v);
    now[u] = value;
    branch(rest, others, now, unverified, depth + 1);
}

std::string eliminator::names(const std::vector<GiNaC::ex>& unknowns) const
{
    std::string out;
    for (const GiNaC::ex& u : unknowns)
        out += (out.empty() ? "" : ", ") + symbols_.text(u);
    return out;
}

bool may_vanish(const GiNaC::ex& residual, const assumptions& given)
{
    if (GiNaC::normal(residual).is_zero())
        return true;
    switch (expand_numerator(residual)) {
    case expansion::zero: return true;
    case expansion::nonzero: return false;
    case expansion::undecided: break;
    }
    // Exact rationals for the symbols, drawn from their domains (reproducibly), and the
    // value to 60 digits: a real number far from zero shows the residual is not zero. A
    // point where a radical is not real shows nothing; a few are tried.
    const long saved = GiNaC::Digits;
    GiNaC::Digits = 60;
    bool vanishes = true;
    uniform_stream stream(20261125);
    for (int attempt = 0; attempt < 32 && vanishes; ++attempt) {
        GiNaC::exmap point;
        for (const auto& [s, range] : given.domains)
            if (residual.has(s))
                point[s] = GiNaC::numeric(cln::cl_N(cln::rational(cln::cl_DF(draw(range, stream)))));
        try {
            const GiNaC::ex value = GiNaC::evalf(residual.subs(point, GiNaC::subs_options::no_pattern));
            if (GiNaC::is_a<GiNaC::numeric>(value) && GiNaC::ex_to<GiNaC::numeric>(value).is_real() &&
                std::abs(GiNaC::ex_to<GiNaC::numeric>(value).to_double()) > 1e-30)
                vanishes = false;
        } catch (const std::exception&) {
            // a pole at this point: try another
        }
    }
    GiNaC::Digits = saved;
    return vanishes;
}

} // namespace impact::engine
