// The sign of an expression factor by factor (prove_sign), with the prover of
// sign_prover.h; the assumptions a proof may make (the declared domains with what the run
// has worked out under them, the effort of a try, a multiple of an abbreviation declared
// with a domain); and a set of signs in words.
#include "engine/prove/sign.h"

#include "engine/expr/infix.h"
#include "engine/prove/sign_prover.h"

#include <fmt/format.h>

#include <algorithm>
#include <optional>

namespace impact::engine {

std::optional<std::pair<GiNaC::numeric, const assumptions::assumed_sign*>> assumed_multiple(const GiNaC::ex& e,
                                                                                           const assumptions& given)
{
    if (given.assumed.empty())
        return std::nullopt;
    if (GiNaC::is_a<GiNaC::power>(e)) {   // a root: d = sqrt(r.r), declared positive
        for (const assumptions::assumed_sign& a : given.assumed)
            if (GiNaC::is_a<GiNaC::power>(a.definition) && a.definition.op(1).is_equal(e.op(1)) &&
                GiNaC::expand(e.op(0)).is_equal(a.definition.op(0)))
                return std::make_pair(GiNaC::numeric(1), &a);
        return std::nullopt;
    }
    const GiNaC::ex terms = GiNaC::expand(e);
    if (!GiNaC::is_a<GiNaC::add>(terms))
        return std::nullopt;
    for (const assumptions::assumed_sign& a : given.assumed) {
        if (!GiNaC::is_a<GiNaC::add>(a.definition) || a.definition.nops() != terms.nops())
            continue;
        // c from the first term and the definition's term of the same symbols.
        for (std::size_t i = 0; i < a.definition.nops(); ++i) {
            const GiNaC::ex ratio = terms.op(0) / a.definition.op(i);
            if (!GiNaC::is_a<GiNaC::numeric>(ratio) || !GiNaC::ex_to<GiNaC::numeric>(ratio).is_real())
                continue;
            if (GiNaC::expand(terms - ratio * a.definition).is_zero())
                return std::make_pair(GiNaC::ex_to<GiNaC::numeric>(ratio), &a);
            break;
        }
    }
    return std::nullopt;
}

assumptions with_effort(const assumptions& given, std::size_t signs)
{
    assumptions trial = given;
    trial.effort = std::make_shared<std::size_t>(signs);
    return trial;
}

bool proof_cache::empty() const
{
    return factored.empty() && declared->signs.empty() && declared->radicals.empty();
}

sign_set sign_set::exactly(int sign)
{
    return {sign < 0, sign == 0, sign > 0};
}

std::string sign_set::describe() const
{
    if (!negative && !zero && positive)
        return "> 0";
    if (!negative && zero && positive)
        return ">= 0";
    if (!negative && zero && !positive)
        return "= 0";
    if (negative && zero && !positive)
        return "<= 0";
    if (negative && !zero && !positive)
        return "< 0";
    if (!negative && !zero && !positive)
        return "undefined";
    return "of unknown sign";
}

std::string assumptions::text(const GiNaC::ex& e) const
{
    return ginac_syntax(e, order);
}

assumptions declared_assumptions(const symbol_table& symbols, proof_cache& run)
{
    // Under the declared domains the sign of an expression never changes, and GiNaC's
    // symbols are never reused (each has its own serial number), so what is worked out
    // serves every derivation of the run. Narrowed domains (a check's `assuming`) need
    // their own.
    assumptions given{{}, declaration_order(symbols), run.declared, &run};
    for (const quantity& q : symbols.all()) {
        if (!q.definition) {
            given.domains[q.symbol] = q.range;
            continue;
        }
        if (q.range.what == domain::kind::real)
            continue;
        // The definition in the inputs (an abbreviation may be written with others),
        // expanded; a root's radicand expanded under it, as assumed_multiple compares it.
        const GiNaC::ex inputs = symbols.in_inputs(*q.definition);
        given.assumed.push_back({q.symbol,
                                 GiNaC::is_a<GiNaC::power>(inputs) ? GiNaC::pow(GiNaC::expand(inputs.op(0)), inputs.op(1))
                                                                   : GiNaC::expand(inputs),
                                 q.range});
    }
    return given;
}

sign_proof prove_sign(const GiNaC::ex& e, const assumptions& given)
{
    const sign_prover prover(given);
    sign_proof proof;
    // The factored form, factor by factor: the proof a reader can follow.
    const GiNaC::ex nd = GiNaC::normal(e).numer_denom();
    std::vector<std::pair<GiNaC::ex, bool>> factors;  // factor, in the denominator
    for (int part = 0; part < 2; ++part) {
        const GiNaC::ex f = factored_in(nd.op(part), given);
        if (GiNaC::is_a<GiNaC::mul>(f)) {
            for (std::size_t i = 0; i < f.nops(); ++i)
                factors.emplace_back(f.op(i), part == 1);
        } else if (!(part == 1 && f.is_equal(1))) {
            factors.emplace_back(f, part == 1);
        }
    }
    // Listed in print order, numerator first: the proof reads the same on every run.
    std::sort(factors.begin(), factors.end(), [&](const auto& a, const auto& b) {
        if (a.second != b.second)
            return b.second;
        return given.order.before(a.first, b.first);
    });
    proof.sign = sign_set::exactly(1);
    for (const auto& [factor, below] : factors) {
        const auto [s, why] = prover.sign(factor);
        const sign_set used = below ? reciprocal(s) : s;
        proof.sign = times(proof.sign, used);
        proof.steps.push_back({below ? 1 / factor : factor, used, why,
                               below ? fmt::format("1/({}) {} ({})", given.text(factor), used.describe(), why.words)
                                     : fmt::format("{} {} ({})", given.text(factor), used.describe(), why.words)});
    }
    if (!proof.sign.is_known()) {
        // The whole expression may still have a provable sign where its factors do not.
        const auto [s, why] = prover.sign(e);
        if (s.is_known()) {
            proof.sign = s;
            proof.steps = {{e, s, why, fmt::format("{} {} ({})", given.text(e), s.describe(), why.words)}};
        }
    }
    return proof;
}

} // namespace impact::engine
