// Deciding whether a rational function is zero, by expanding its numerator fast.
//
// `prove_equal` brings the difference of two sides over the product of their
// denominators (no gcd) and asks whether the numerator expands to zero. GiNaC's
// expand() builds every intermediate product as an expression and evaluates it; here
// the numerator is expanded as a sparse polynomial with rational coefficients, each
// monomial a packed vector of exponents. What is not a sum, product, rational number,
// symbol or integer power (a radical, a function) stands as a variable of its own: a
// numerator that expands to zero so is zero whatever those parts are, which proves the
// function zero. A non-zero numerator settles the matter only when no such part occurs;
// otherwise GiNaC, which knows that sqrt(x)^2 = x, has to be asked.
#pragma once

#include <ginac/ginac.h>

#include <map>

namespace impact::engine {

/// What the numerator of a rational function expands to.
enum class expansion {
    zero,       ///< zero: the function is zero wherever it is defined
    nonzero,    ///< a non-zero polynomial in its symbols: the function is not zero
    undecided,  ///< a non-zero polynomial in which radicals or functions stand as variables
                ///< (they may yet cancel), or one too large to expand here
};

/// Adds to `out` the symbols `e` holds.
void gather_symbols(const GiNaC::ex& e, GiNaC::exset& out);

/// Expands the numerator of `e` over the product of its denominators, factor by factor
/// (the least common multiple of a sum's denominators, no gcd).
expansion expand_numerator(const GiNaC::ex& e);

/// GiNaC::factor(e, options) as a function of `e` alone. GiNaC's multivariate
/// factorization draws its evaluation points from std::rand(), whose state is whatever
/// the factorizations before it in the process left: the same polynomial took a second
/// in one run and a quarter of an hour in another, depending on what had been factored
/// (or taken from a cache) before. The generator is seeded alike before every call.
/// A sum that is of degree one in a symbol whose two coefficients have no common factor
/// is irreducible, and returned expanded without calling factor(). A polynomial in more
/// than one symbol is factored in a child process (factor() may never return:
/// engine/algebra/forked.h), tried in up to four orders of its terms with 1, 2, 5 and 12 s of CPU
/// time, and returned as it is if none is enough. What a call returns is kept for the
/// process (up to 20000 polynomials), and returned again when the same polynomial is asked
/// for with the same options.
GiNaC::ex factor_reproducibly(const GiNaC::ex& e, unsigned options = 0);

/// `factor(e, options)` kept for the process, by options, then polynomial (past 20 000 of
/// one options, forgotten at once, so that a long run keeps no more): the factorizations
/// the emitters and proofs ask for again and again. Each `factor` (a lambda of its caller)
/// keeps its own. Not for threads.
template <class Factor>
GiNaC::ex kept_factorization(const GiNaC::ex& e, unsigned options, Factor factor)
{
    static std::map<unsigned, std::map<GiNaC::ex, GiNaC::ex, GiNaC::ex_is_less>> kept;
    std::map<GiNaC::ex, GiNaC::ex, GiNaC::ex_is_less>& for_options = kept[options];
    if (const auto found = for_options.find(e); found != for_options.end())
        return found->second;
    if (for_options.size() >= 20000)
        for_options.clear();
    return for_options.emplace(e, factor(e, options)).first->second;
}

} // namespace impact::engine
