#include "engine/algebra/polynomial.h"

#include "engine/algebra/forked.h"

#include <cln/rational.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <iterator>
#include <map>
#include <optional>
#include <set>
#include <utility>
#include <vector>

namespace impact::engine {
namespace {

// The exponents of up to 32 variables, one byte each. An exponent stays below 128, so
// that the bytes of a product's monomial (the sums of two such) never carry into each
// other, and a high bit set says that an exponent has grown too large.
constexpr std::size_t max_variables = 32;
using monomial = std::array<std::uint64_t, max_variables / 8>;
constexpr std::uint64_t high_bits = 0x8080808080808080ULL;

// A polynomial: its terms sorted by monomial, no two alike, none zero.
struct term {
    monomial exponents;
    cln::cl_RA coefficient;
};
using polynomial = std::vector<term>;

// More variables, or a higher power, than a monomial holds.
struct too_large {};

polynomial constant(const cln::cl_RA& c)
{
    polynomial p;
    if (!cln::zerop(c))
        p.push_back({monomial{}, c});
    return p;
}

// Terms in any order, alike ones possibly repeated, made a polynomial.
polynomial collected(polynomial terms)
{
    std::sort(terms.begin(), terms.end(),
              [](const term& a, const term& b) { return a.exponents < b.exponents; });
    polynomial p;
    for (term& t : terms) {
        if (!p.empty() && p.back().exponents == t.exponents)
            p.back().coefficient = p.back().coefficient + t.coefficient;
        else
            p.push_back(std::move(t));
    }
    p.erase(std::remove_if(p.begin(), p.end(), [](const term& t) { return cln::zerop(t.coefficient); }), p.end());
    return p;
}

polynomial times(const polynomial& a, const polynomial& b)
{
    polynomial product;
    product.reserve(a.size() * b.size());
    for (const term& ta : a) {
        for (const term& tb : b) {
            monomial m;
            for (std::size_t i = 0; i < m.size(); ++i) {
                m[i] = ta.exponents[i] + tb.exponents[i];
                if (m[i] & high_bits)
                    throw too_large{};
            }
            product.push_back({m, ta.coefficient * tb.coefficient});
        }
    }
    return collected(std::move(product));
}

polynomial power(const polynomial& p, int k)
{
    polynomial result = constant(1);
    polynomial square = p;
    for (; k > 0; k >>= 1) {
        if (k & 1)
            result = times(result, square);
        if (k > 1)
            square = times(square, square);
    }
    return result;
}

// Denominators as powers of factors; a factor is named by the expression whose
// numerator it is (a number by itself), so that equal factors meet in one entry.
using denominators = std::map<GiNaC::ex, int, GiNaC::ex_is_less>;

struct fraction {
    polynomial numerator;
    denominators denominator;
};

// over_common_denominator of prove.cpp, with the numerator expanded as it is built.
class expander {
public:
    bool met_opaque() const { return opaque_; }

    // The radicands of the square roots in `e` (of x^(p/2)).
    void find_roots(const GiNaC::ex& e)
    {
        for (GiNaC::const_preorder_iterator it = e.preorder_begin(); it != e.preorder_end(); ++it)
            if (GiNaC::is_a<GiNaC::power>(*it) && it->op(1).info(GiNaC::info_flags::rational) &&
                GiNaC::ex_to<GiNaC::numeric>(it->op(1)).denom() == 2)
                radicands_.insert(it->op(0));
    }

    fraction read(const GiNaC::ex& e)
    {
        if (GiNaC::is_a<GiNaC::numeric>(e)) {
            const GiNaC::numeric& n = GiNaC::ex_to<GiNaC::numeric>(e);
            if (!n.is_rational())
                return {variable(e, true), {}};
            const cln::cl_RA value = cln::the<cln::cl_RA>(n.to_cl_N());
            if (n.is_integer())
                return {constant(value), {}};
            return {constant(cln::numerator(value)), {{n.denom(), 1}}};
        }
        if (GiNaC::is_a<GiNaC::symbol>(e))
            return {variable(e, false), {}};
        if (GiNaC::is_a<GiNaC::mul>(e)) {
            fraction r{constant(1), {}};
            for (std::size_t i = 0; i < e.nops(); ++i) {
                fraction f = read(e.op(i));
                r.numerator = times(r.numerator, f.numerator);
                for (const auto& [base, k] : f.denominator)
                    r.denominator[base] += k;
            }
            return r;
        }
        if (GiNaC::is_a<GiNaC::power>(e) && e.op(1).info(GiNaC::info_flags::integer)) {
            const int k = GiNaC::ex_to<GiNaC::numeric>(e.op(1)).to_int();
            fraction base = read(e.op(0));
            if (k < 0 && base.denominator.empty()) {
                // 1/x^k with sqrt(x) elsewhere (or sqrt(-x)): over sqrt(x)^(2k), so that a sum
                // over it is brought to a common denominator by powers of the root alone,
                // not of x.
                for (const int sign : {1, -1}) {
                    const GiNaC::ex radicand = sign * e.op(0);
                    if (!radicands_.count(radicand))
                        continue;
                    const GiNaC::ex root = GiNaC::sqrt(radicand);
                    if (!numerators_.count(root))
                        numerators_.emplace(root, variable(root, true));
                    return {constant(sign == 1 || k % 2 == 0 ? 1 : -1), {{root, -2 * k}}};
                }
            }
            if (k >= 0) {
                for (auto& [b, j] : base.denominator)
                    j *= k;
                return {power(base.numerator, k), base.denominator};
            }
            // (n / d)^-k = d^k / n^k
            polynomial top = constant(1);
            for (const auto& [b, j] : base.denominator)
                top = times(top, power(numerator_of(b), -k * j));
            numerators_.emplace(e.op(0), std::move(base.numerator));
            return {std::move(top), {{e.op(0), -k}}};
        }
        if (GiNaC::is_a<GiNaC::power>(e) && e.op(1).info(GiNaC::info_flags::rational) &&
            GiNaC::ex_to<GiNaC::numeric>(e.op(1)).denom() == 2 && !e.op(1).is_equal(GiNaC::numeric(1, 2))) {
            // x^(p/2) = x^((p-1)/2) sqrt(x), as over_common_denominator takes it.
            const GiNaC::numeric p = GiNaC::ex_to<GiNaC::numeric>(e.op(1)).numer();
            if (p.is_negative()) {
                // x^(-k/2) = 1/sqrt(x)^k: the root alone in the denominator.
                const GiNaC::ex root = GiNaC::sqrt(e.op(0));
                if (!numerators_.count(root))
                    numerators_.emplace(root, variable(root, true));
                return {constant(1), {{root, -p.to_int()}}};
            }
            fraction whole = read(GiNaC::pow(e.op(0), (p - 1) / 2));
            whole.numerator = times(whole.numerator, variable(GiNaC::sqrt(e.op(0)), true));
            return whole;
        }
        if (GiNaC::is_a<GiNaC::add>(e)) {
            std::vector<fraction> terms;
            denominators lcm;
            for (std::size_t i = 0; i < e.nops(); ++i) {
                terms.push_back(read(e.op(i)));
                for (const auto& [base, k] : terms.back().denominator)
                    lcm[base] = std::max(lcm[base], k);
            }
            polynomial top;
            for (const fraction& t : terms) {
                polynomial scaled = t.numerator;
                for (const auto& [base, k] : lcm) {
                    const auto own = t.denominator.find(base);
                    const int missing = k - (own == t.denominator.end() ? 0 : own->second);
                    if (missing > 0)
                        scaled = times(scaled, power(numerator_of(base), missing));
                }
                top.insert(top.end(), scaled.begin(), scaled.end());
            }
            return {collected(std::move(top)), std::move(lcm)};
        }
        // A radical, a function, a constant: a variable of its own.
        return {variable(e, true), {}};
    }

    static int exponent(const monomial& m, std::size_t i) { return int((m[i / 8] >> (8 * (i % 8))) & 0xff); }

    // What the square of the root standing as variable i is, when its radicand is a
    // polynomial (null otherwise: a radicand with a denominator stays opaque).
    const polynomial* square_of(std::size_t i)
    {
        auto known = squares_.find(i);
        if (known == squares_.end()) {
            GiNaC::ex root;
            for (const auto& [e, k] : variables_)
                if (k == i)
                    root = e;
            fraction radicand = read(root.op(0));
            std::optional<polynomial> square;
            if (radicand.denominator.empty())
                square = std::move(radicand.numerator);
            known = squares_.emplace(i, std::move(square)).first;
        }
        return known->second ? &*known->second : nullptr;
    }

    // `p` with every square of a square root replaced by its radicand, sqrt(x)^2 = x: a
    // numerator that vanishes only through x = sqrt(x)^2 (n = r/|r| a unit vector) is then
    // seen to vanish here, without GiNaC expanding it. Sound whatever the roots are; a
    // non-zero remainder decides nothing (sqrt(4 x) = 2 sqrt(x) is not seen).
    polynomial reduced(polynomial p)
    {
        for (std::size_t r = 0; r < roots_.size(); ++r) {
            const std::size_t i = roots_[r];
            const bool squared = std::any_of(p.begin(), p.end(), [i](const term& t) { return exponent(t.exponents, i) >= 2; });
            if (!squared)
                continue;
            const polynomial* square = square_of(i);   // may add roots: roots_ read by index
            if (!square)
                continue;
            polynomial out;
            std::map<int, polynomial> powers;
            for (term& t : p) {
                const int e = exponent(t.exponents, i);
                if (e < 2) {
                    out.push_back(std::move(t));
                    continue;
                }
                t.exponents[i / 8] -= std::uint64_t(e - e % 2) << (8 * (i % 8));
                auto known = powers.find(e / 2);
                if (known == powers.end())
                    known = powers.emplace(e / 2, power(*square, e / 2)).first;
                const polynomial product = times({std::move(t)}, known->second);
                out.insert(out.end(), product.begin(), product.end());
            }
            p = collected(std::move(out));
            r = std::size_t(-1);   // the radicands may hold roots already gone through
        }
        return p;
    }

private:
    // The polynomial a factor of a denominator stands for.
    const polynomial& numerator_of(const GiNaC::ex& factor)
    {
        auto known = numerators_.find(factor);
        if (known == numerators_.end())
            known = numerators_.emplace(factor, read(factor).numerator).first;
        return known->second;
    }

    polynomial variable(const GiNaC::ex& e, bool opaque)
    {
        opaque_ = opaque_ || opaque;
        const auto [at, added] = variables_.emplace(e, variables_.size());
        if (at->second >= max_variables)
            throw too_large{};
        if (added && GiNaC::is_a<GiNaC::power>(e) && e.op(1).is_equal(GiNaC::numeric(1, 2)))
            roots_.push_back(at->second);
        monomial m{};
        m[at->second / 8] = std::uint64_t(1) << (8 * (at->second % 8));
        return {{m, 1}};
    }

    std::map<GiNaC::ex, std::size_t, GiNaC::ex_is_less> variables_;
    std::vector<std::size_t> roots_;
    std::set<GiNaC::ex, GiNaC::ex_is_less> radicands_;
    std::map<std::size_t, std::optional<polynomial>> squares_;
    std::map<GiNaC::ex, polynomial, GiNaC::ex_is_less> numerators_;
    bool opaque_ = false;
};

} // namespace

expansion expand_numerator(const GiNaC::ex& e)
{
    try {
        expander x;
        x.find_roots(e);
        const fraction f = x.read(e);
        if (x.reduced(f.numerator).empty())
            return expansion::zero;
        return x.met_opaque() ? expansion::undecided : expansion::nonzero;
    } catch (const too_large&) {
        return expansion::undecided;
    }
}

void gather_symbols(const GiNaC::ex& e, GiNaC::exset& out)
{
    if (GiNaC::is_a<GiNaC::symbol>(e))
        out.insert(e);
    else
        for (std::size_t i = 0; i < e.nops(); ++i)
            gather_symbols(e.op(i), out);
}

namespace {

// A polynomial of degree one in some symbol x, a x + b with gcd(a, b) a number, has no
// factor but numbers: a factor would divide both a and b (Gauss's lemma). factor() takes
// 15 to 60 ms to find that of a 20-term sum in a dozen symbols; gcd() a part of it, but in
// twenty symbols, asked of each, gcd() took longer than factor(). So the symbols are tried
// cheapest first (fewest terms in a and b), and gcd() is asked only when neither answer
// is plain: a and b with no symbol in common have a number as gcd; a symbol dividing every
// term of both divides the gcd.
bool irreducible_by_degree_one(const GiNaC::ex& p)
{
    if (!GiNaC::is_a<GiNaC::add>(p))
        return false;
    // gcd() takes polynomials with rational coefficients only (not sqrt(3) x + y).
    if (!p.info(GiNaC::info_flags::rational_polynomial))
        return false;
    GiNaC::exset symbols;
    gather_symbols(p, symbols);
    struct split {
        std::size_t size;
        GiNaC::ex a, b;
    };
    std::vector<split> splits;
    for (const GiNaC::ex& x : symbols)
        if (p.degree(x) == 1 && p.ldegree(x) == 0) {
            const GiNaC::ex a = p.coeff(x, 1), b = p.coeff(x, 0);
            const auto terms = [](const GiNaC::ex& e) { return GiNaC::is_a<GiNaC::add>(e) ? e.nops() : 1; };
            splits.push_back({terms(a) * terms(b), a, b});
        }
    std::stable_sort(splits.begin(), splits.end(), [](const split& l, const split& r) { return l.size < r.size; });
    for (const split& s : splits) {
        GiNaC::exset in_a, in_b;
        gather_symbols(s.a, in_a);
        gather_symbols(s.b, in_b);
        if (std::none_of(in_a.begin(), in_a.end(), [&](const GiNaC::ex& y) { return in_b.count(y) > 0; }))
            return true;
        if (std::any_of(in_a.begin(), in_a.end(), [&](const GiNaC::ex& y) {
                return in_b.count(y) > 0 && s.a.ldegree(y) > 0 && s.b.ldegree(y) > 0;
            }))
            continue;
        if (GiNaC::is_a<GiNaC::numeric>(GiNaC::gcd(s.a, s.b)))
            return true;
    }
    return false;
}

GiNaC::ex factor_anew(const GiNaC::ex& e, unsigned options)
{
    const GiNaC::ex expanded = GiNaC::expand(e);
    if (irreducible_by_degree_one(expanded))
        return expanded;
    GiNaC::exset symbols;
    gather_symbols(expanded, symbols);
    if (symbols.size() > 1) {
        // In several symbols factor() may never return (engine/algebra/forked.h): it runs in a
        // child. Whether it does depends on the order of the terms, which depends on how
        // Impact was linked: a change to an unrelated part made one factorization of the
        // derivations take its whole 20 s in one build, and 0.1 s in the one before. So
        // a short try first, then others, longer, each in another order; a polynomial
        // none of them factors is left as it is. The factors do not depend on the try
        // that found them, but for their signs and how far factor() collected each: its
        // callers expand each factor and put its sign outside (prove/factor_polynomial.cpp's flattened(),
        // emit/latex_textbook.cpp), so that what they make of it does not depend on the try
        // either. 20 s of CPU time in all, as one try had.
        constexpr unsigned cpu_seconds[] = {1, 2, 5, 12};
        for (unsigned arrangement = 0; arrangement < std::size(cpu_seconds); ++arrangement)
            if (std::optional<GiNaC::ex> f = factor_in_child(e, options, cpu_seconds[arrangement], arrangement))
                return *f;
        return e;
    }
    std::srand(1);
    return GiNaC::factor(e, options);
}

// factor_anew with GiNaC's constants (Pi, Euler, Catalan) standing as symbols: factor()
// takes Pi for a polynomial part but its gcd() refuses it ("arguments must be polynomials
// over the rationals"), so that theta - Pi + 2 alpha could not be factored. A constant is
// transcendental, as a symbol is: the factors over the rationals are the same.
GiNaC::ex factor_with_constants(const GiNaC::ex& e, unsigned options)
{
    static const GiNaC::symbol pi_("pi_"), euler_("euler_"), catalan_("catalan_");
    GiNaC::exmap to_symbols, back;
    for (const auto& [constant, stand_in] : {std::pair<GiNaC::ex, GiNaC::ex>{GiNaC::Pi, pi_},
                                             {GiNaC::Euler, euler_},
                                             {GiNaC::Catalan, catalan_}})
        if (e.has(constant)) {
            to_symbols[constant] = stand_in;
            back[stand_in] = constant;
        }
    if (to_symbols.empty())
        return factor_anew(e, options);
    return factor_anew(e.subs(to_symbols, GiNaC::subs_options::no_pattern), options)
        .subs(back, GiNaC::subs_options::no_pattern);
}

} // namespace

// Not for threads: std::rand()'s state is the process's (Impact's workers are processes).
// Each factorization is kept for the process: the emitters try a value collected in every
// quantity, factoring each coefficient, and the same small polynomials come again and
// again (the 3D rough spheres' fragment asked 3149 times for 555 polynomials; each in a
// child process, or behind a gcd that cost as much). What is kept is what the first call
// returned, which a second call could only return again, up to the signs and collection
// of its factors that the callers normalise.
GiNaC::ex factor_reproducibly(const GiNaC::ex& e, unsigned options)
{
    return kept_factorization(e, options, [](const GiNaC::ex& p, unsigned o) { return factor_with_constants(p, o); });
}

} // namespace impact::engine
