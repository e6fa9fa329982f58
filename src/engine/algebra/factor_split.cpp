#include "engine/algebra/factor_split.h"

#include "engine/algebra/polynomial.h"

#include <algorithm>
#include <map>
#include <vector>

namespace impact::engine {
namespace {

// A sum `q` with rational coefficients, no symbol dividing every one of its terms,
// factored: by a symbol x of degree one in it, q = a x + b = gcd(a, b) (a x + b)/gcd(a, b),
// the second irreducible; else by factor().
GiNaC::ex split(const GiNaC::ex& q, unsigned options)
{
    // Each term's symbols with their powers, each symbol by its number.
    std::map<GiNaC::ex, std::size_t, GiNaC::ex_is_less> numbers;
    std::vector<std::vector<std::pair<std::size_t, int>>> powers(q.nops());
    for (std::size_t i = 0; i < q.nops(); ++i) {
        const GiNaC::ex t = q.op(i);
        const auto power = [&](const GiNaC::ex& f) {
            const bool raised = GiNaC::is_a<GiNaC::power>(f);
            const GiNaC::ex base = raised ? f.op(0) : f;
            if (!GiNaC::is_a<GiNaC::symbol>(base))
                return;
            const auto n = numbers.emplace(base, numbers.size()).first->second;
            powers[i].emplace_back(n, raised ? GiNaC::ex_to<GiNaC::numeric>(f.op(1)).to_int() : 1);
        };
        if (GiNaC::is_a<GiNaC::mul>(t))
            for (const GiNaC::ex& f : t)
                power(f);
        else
            power(t);
    }
    std::vector<GiNaC::ex> symbols(numbers.size());
    std::vector<int> degree(numbers.size(), 0);
    for (const auto& [s, n] : numbers)
        symbols[n] = s;
    for (const auto& term : powers)
        for (const auto& [n, k] : term)
            degree[n] = std::max(degree[n], k);
    // For each symbol x of degree one: the terms with x (a x) and those without (b).
    struct by {
        std::size_t x, size;
    };
    std::vector<by> splits;
    for (std::size_t x = 0; x < symbols.size(); ++x) {
        if (degree[x] != 1)
            continue;
        std::vector<char> in_a(symbols.size(), 0), in_b(symbols.size(), 0);
        std::size_t with = 0;
        for (const auto& term : powers) {
            const bool has_x = std::any_of(term.begin(), term.end(), [&](const auto& p) { return p.first == x; });
            with += has_x;
            for (const auto& [n, k] : term)
                (has_x ? in_a : in_b)[n] = 1;
        }
        const std::size_t without = powers.size() - with;
        // gcd(a, b) divides q, and no symbol does: when a or b is one term, a monomial
        // (all that divides it), the gcd is a number; likewise when a and b have no symbol
        // in common. Then q is irreducible.
        bool common = false;
        for (std::size_t n = 0; n < symbols.size(); ++n)
            common = common || (n != x && in_a[n] && in_b[n]);
        if (with == 1 || without == 1 || !common)
            return q;
        splits.push_back({x, with * without});
    }
    if (splits.empty())
        return factor_reproducibly(q, options);
    // gcd(a, b): each irreducible factor of the side with fewer terms that divides the
    // other, as often as it divides both (a factor that is a symbol would divide q). The
    // sides are factored the same way, and the same sides come again and again: cheaper
    // than gcd(), which took a millisecond for each of these with a factor in common.
    const by& cheapest = *std::min_element(splits.begin(), splits.end(),
                                           [](const by& l, const by& r) { return l.size < r.size; });
    const GiNaC::ex& x = symbols[cheapest.x];
    GiNaC::ex a = q.coeff(x, 1), b = q.coeff(x, 0);
    if (GiNaC::is_a<GiNaC::add>(a) && GiNaC::is_a<GiNaC::add>(b) && a.nops() > b.nops())
        std::swap(a, b);
    const GiNaC::ex factors = factor_split(a, options);
    GiNaC::ex g = 1;
    const auto common = [&](const GiNaC::ex& f) {
        const bool raised = GiNaC::is_a<GiNaC::power>(f);
        const GiNaC::ex base = raised ? f.op(0) : f;
        if (!GiNaC::is_a<GiNaC::add>(base))
            return;
        const int times = raised ? GiNaC::ex_to<GiNaC::numeric>(f.op(1)).to_int() : 1;
        GiNaC::ex quotient;
        for (int k = 0; k < times && GiNaC::divide(b, base, quotient); ++k) {
            g *= base;
            b = quotient;
        }
    };
    if (GiNaC::is_a<GiNaC::mul>(factors))
        for (const GiNaC::ex& f : factors)
            common(f);
    else
        common(factors);
    if (g.is_equal(1))
        return q;
    GiNaC::ex irreducible;
    if (!GiNaC::divide(q, g, irreducible))
        return factor_reproducibly(q, options);
    return irreducible * factor_split(g, options);
}

// factor_split, not kept.
GiNaC::ex factored(const GiNaC::ex& p, unsigned options)
{
    const GiNaC::ex e = GiNaC::expand(p);
    if (!e.info(GiNaC::info_flags::rational_polynomial))
        return factor_reproducibly(p, options);
    if (!GiNaC::is_a<GiNaC::add>(e))
        return e;   // a number, or a product of powers of symbols
    // The symbols dividing every term, and the rational number dividing every coefficient.
    GiNaC::exset symbols;
    gather_symbols(e, symbols);
    GiNaC::ex monomial = 1;
    for (const GiNaC::ex& s : symbols)
        if (const int k = e.ldegree(s); k > 0)
            monomial *= GiNaC::pow(s, k);
    const GiNaC::numeric content = e.integer_content();
    const GiNaC::ex q = GiNaC::expand(e / (monomial * content));
    return content * monomial * split(q, options);
}

} // namespace

GiNaC::ex factor_split(const GiNaC::ex& p, unsigned options)
{
    // Kept for the process, as factor_reproducibly keeps its own: the emitters ask for the
    // same coefficients again (11411 times for 2000 polynomials in the whole project).
    return kept_factorization(p, options, [](const GiNaC::ex& e, unsigned o) { return factored(e, o); });
}

} // namespace impact::engine
