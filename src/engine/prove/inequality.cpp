// Proving an inequality (prove.h): from the signs of the factors of the difference of its
// sides (sign.h), or through an identity proven before it whose other side's sign is
// proven, else sampled (sampling.cpp).
#include "engine/prove/prove_internal.h"

#include <fmt/format.h>

#include <optional>

namespace impact::engine {
namespace {

// False when `e` is certainly not identically zero: its exact value at one point of
// rationals is a non-zero number. True otherwise (zero there, or not a number there: a
// radical of rationals, a pole), when only normal() can tell. A cheap test before
// normal() on large expressions that are mostly not equal.
bool may_vanish(const GiNaC::ex& e)
{
    GiNaC::exmap point;
    long k = 0;
    for (GiNaC::const_preorder_iterator it = e.preorder_begin(); it != e.preorder_end(); ++it)
        if (GiNaC::is_a<GiNaC::symbol>(*it) && !point.count(*it)) {
            ++k;
            point[*it] = GiNaC::numeric(2 * k + 3, k + 7);  // distinct, positive, below 1 after 4
        }
    try {
        const GiNaC::ex value = e.subs(point, GiNaC::subs_options::no_pattern);
        return !(GiNaC::is_a<GiNaC::numeric>(value) && GiNaC::ex_to<GiNaC::numeric>(value).is_rational() &&
                 !value.is_zero());
    } catch (const std::exception&) {
        return true;
    }
}

} // namespace

std::optional<verdict> prove_inequality_by_signs(const GiNaC::ex& lhs, relation op, const GiNaC::ex& rhs,
                                                 const symbol_table& symbols, const assumptions& given)
{
    const GiNaC::exmap abbreviations = symbols.abbreviations();
    const bool upper = op == relation::less_equal || op == relation::less;
    const bool strict = op == relation::less || op == relation::greater;
    const GiNaC::ex a = spelled_out(lhs, abbreviations), b = spelled_out(rhs, abbreviations);
    const GiNaC::ex difference = upper ? b - a : a - b;
    const sign_proof proof = prove_sign(difference, given);
    if (proof.sign.negative || (strict && proof.sign.zero))
        return std::nullopt;
    verdict v;
    v.residual = GiNaC::normal(difference);
    v.proof = proof.steps;
    v.what = verdict::status::proven;
    v.method = fmt::format("the sign of each factor of {} follows from the domains", given.text(v.residual));
    v.how = verdict::basis::signs;
    return v;
}

verdict prove_inequality(const GiNaC::ex& lhs, relation op, const GiNaC::ex& rhs, const symbol_table& symbols,
                         const assumptions& given)
{
    const GiNaC::exmap abbreviations = symbols.abbreviations();
    const GiNaC::ex a = spelled_out(lhs, abbreviations);
    const GiNaC::ex b = spelled_out(rhs, abbreviations);
    // lhs <= rhs  <=>  rhs - lhs >= 0; strict relations need > 0.
    const bool upper = op == relation::less_equal || op == relation::less;
    const GiNaC::ex difference = upper ? b - a : a - b;
    if (auto proven = prove_inequality_by_signs(lhs, op, rhs, symbols, given))
        return *proven;
    const sign_proof proof = prove_sign(difference, given);   // worked out: the steps it got to
    verdict v;
    v.residual = GiNaC::normal(difference);
    auto holds = [&](const GiNaC::numeric& x, const GiNaC::numeric& y) {
        switch (op) {
        case relation::less_equal: return x <= y;
        case relation::less: return x < y;
        case relation::greater_equal: return x >= y;
        case relation::greater: return x > y;
        case relation::equal: break;
        }
        return nearly_equal(x, y);
    };
    verdict sampled = sample(a, b, v.residual, symbols, holds, to_string(op), given.where);
    sampled.proof = proof.steps;
    return sampled;
}

namespace {

// `given` with each abbreviation of `e` an atom of the sign its definition is proven to
// have (m_t > 0 for a tangential mass): a sum of terms in m_t, g_n and g_t keeps its few
// terms instead of being spelled out over a common denominator.
assumptions with_abbreviations_as_atoms(const GiNaC::ex& e, const GiNaC::exmap& abbreviations,
                                        const assumptions& given)
{
    assumptions atoms = given;
    atoms.known = std::make_shared<worked_out>();
    for (const auto& [symbol, definition] : abbreviations) {
        if (!e.has(symbol) || atoms.domains.count(symbol))
            continue;
        const sign_set s = prove_sign(spelled_out(definition, abbreviations), given).sign;
        domain range;
        if (s.is_positive())
            range.what = domain::kind::positive;
        else if (s.is_nonnegative())
            range.what = domain::kind::nonnegative;
        atoms.domains[symbol] = range;
    }
    return atoms;
}

} // namespace

std::optional<verdict> prove_inequality_through(const GiNaC::ex& lhs, relation op, const GiNaC::ex& rhs,
                                                const std::vector<proven_identity>& identities,
                                                const symbol_table& symbols, const assumptions& given)
{
    const GiNaC::exmap abbreviations = symbols.abbreviations();
    const bool upper = op == relation::less_equal || op == relation::less;
    const bool strict = op == relation::less || op == relation::greater;
    const GiNaC::ex difference = spelled_out(upper ? rhs - lhs : lhs - rhs, abbreviations);
    for (const proven_identity& identity : identities) {
        const GiNaC::ex sides[2] = {identity.lhs, identity.rhs};
        for (int side = 0; side < 2; ++side) {
            for (const int s : {1, -1}) {
                const GiNaC::ex same = spelled_out(s * sides[side], abbreviations);
                if (!may_vanish(difference - same) || !GiNaC::normal(difference - same).is_zero())
                    continue;
                const GiNaC::ex other = s * sides[1 - side];
                const auto settled = [strict](const sign_proof& p) {
                    return strict ? p.sign.is_positive() : p.sign.is_nonnegative();
                };
                GiNaC::ex proven = other;
                sign_proof proof = prove_sign(other, with_abbreviations_as_atoms(other, abbreviations, given));
                if (!settled(proof)) {
                    proven = spelled_out(other, abbreviations);
                    proof = prove_sign(proven, given);
                }
                if (!settled(proof))
                    continue;
                verdict v;
                v.what = verdict::status::proven;
                v.residual = proven;   // the difference the signs of whose factors decide it
                v.proof = proof.steps;
                v.method = fmt::format("by {} the difference of the sides is {}, and the sign of each factor of "
                                       "that follows from the domains",
                                       identity.name, given.text(other));
                v.typeset.say("through an identity proven before it (" + identity.name + "), the difference of the "
                              "sides is ")
                    .math(proven)
                    .say(", and the sign of each of its factors follows from the domains");
                v.how = verdict::basis::identity;
                return v;
            }
        }
    }
    return std::nullopt;
}

} // namespace impact::engine
