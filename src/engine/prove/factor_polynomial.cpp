// Polynomials factored for the sign proofs: GiNaC's factor() made reproducible
// (engine/algebra/polynomial.h), each factor a flat sum, kept to polynomials short enough to
// factor in time, and each polynomial factored once in a run (proof_cache::factored).
#include "engine/prove/sign.h"

#include "engine/algebra/polynomial.h"

namespace impact::engine {
namespace {

// factor() cannot be interrupted: on the rough-sphere energy it ran for minutes at 120
// terms in some runs (GiNaC's order of terms differs between runs), and polynomials of 29
// to 38 terms in ten symbols took 2 to 10 s each (the energy of rough spheres claimed to
// fall with no identity for it checked first, which the fuzzer found: a minute in all,
// against half a second now). A longer polynomial is left as it is, its sign settled by
// another argument (prove_inequality_through) or sampled. Nothing in derivations/ or in
// the draft of rough spheres in space factors a longer one to be proven.
constexpr std::size_t most_terms_factored = 28;

bool worth_factoring(const GiNaC::ex& e)
{
    if (has_radical(e) || GiNaC::is_a<GiNaC::symbol>(e) || GiNaC::is_a<GiNaC::numeric>(e))
        return false;
    const GiNaC::ex expanded = GiNaC::expand(e);
    return !GiNaC::is_a<GiNaC::add>(expanded) || expanded.nops() <= most_terms_factored;
}

// factor()'s result with each factor a flat sum: factor() may leave a factor partly
// collected (t*(a^2 + b^2) + 2*a*v for t*a^2 + t*b^2 + 2*a*v), one way or the other
// depending on GiNaC's order of terms, which changes from run to run.
GiNaC::ex flattened(const GiNaC::ex& f)
{
    if (GiNaC::is_a<GiNaC::add>(f))
        return GiNaC::expand(f);
    if (GiNaC::is_a<GiNaC::mul>(f) || (GiNaC::is_a<GiNaC::power>(f) && f.op(1).info(GiNaC::info_flags::integer))) {
        struct each : GiNaC::map_function {
            GiNaC::ex operator()(const GiNaC::ex& part) override { return flattened(part); }
        } flatten;
        return f.map(flatten);
    }
    return f;
}

// factor() with Pi (and GiNaC's other constants) standing as symbols: GiNaC's factor()
// refuses a polynomial whose coefficients are not rational ("gcd: arguments must be
// polynomials over the rationals"), and Pi - x is a polynomial in x and Pi.
GiNaC::ex factored_with_constants(const GiNaC::ex& e)
{
    bool constants = false;
    for (GiNaC::const_preorder_iterator it = e.preorder_begin(); it != e.preorder_end() && !constants; ++it)
        constants = GiNaC::is_a<GiNaC::constant>(*it);
    if (!constants)
        return factor_reproducibly(e);
    static const GiNaC::symbol pi("Pi"), euler("Euler"), catalan("Catalan");
    const GiNaC::exmap in{{GiNaC::Pi, pi}, {GiNaC::Euler, euler}, {GiNaC::Catalan, catalan}};
    const GiNaC::exmap out{{pi, GiNaC::Pi}, {euler, GiNaC::Euler}, {catalan, GiNaC::Catalan}};
    return factor_reproducibly(e.subs(in, GiNaC::subs_options::no_pattern)).subs(out, GiNaC::subs_options::no_pattern);
}

} // namespace

// factor() on a polynomial; an expression with radicals is left as it is, since
// factoring under a root may pull out -1 and leave I behind.
GiNaC::ex factor_polynomial(const GiNaC::ex& e)
{
    return worth_factoring(e) ? flattened(factored_with_constants(e)) : e;
}

GiNaC::ex factor_polynomial(const GiNaC::ex& e, proof_cache& run)
{
    if (has_radical(e) || GiNaC::is_a<GiNaC::symbol>(e) || GiNaC::is_a<GiNaC::numeric>(e))
        return e;
    // factor() is the engine's most expensive call and meets the same polynomials again
    // and again (in sign proofs, in radicals, in each step's simplification).
    auto& factored = run.factored;
    const auto known = factored.find(e);
    if (known != factored.end())
        return known->second;
    const bool worth = worth_factoring(e);
    const GiNaC::ex f = worth ? flattened(factored_with_constants(e)) : e;
    if (factored.size() >= 4096)  // bounded: a long run (the fuzzer) meets ever new polynomials
        factored.clear();
    factored.emplace(e, f);
    // Its factors are irreducible: asked again (a sign proof asks of each factor), each is
    // its own factorization, not another call of factor().
    if (worth && !f.is_equal(e)) {
        const auto irreducible = [&factored](const GiNaC::ex& part) {
            const GiNaC::ex base = GiNaC::is_a<GiNaC::power>(part) ? part.op(0) : part;
            if (GiNaC::is_a<GiNaC::add>(base))
                factored.emplace(base, base);
        };
        if (GiNaC::is_a<GiNaC::mul>(f))
            for (const GiNaC::ex& part : f)
                irreducible(part);
        else
            irreducible(f);
    }
    return f;
}

} // namespace impact::engine
