// Radicals under the domains: sqrt(x^2 y) = x sqrt(y) where the sign of x is proven, one
// form for the radical of a quotient (sqrt(N)/sqrt(D) where D > 0), each simplification
// remembered under the assumptions; and radicands expanded, so that one radical written two
// ways is one quantity.
#include "engine/prove/sign_prover.h"

#include "engine/expr/order.h"

namespace impact::engine {
namespace {

// simplify_radicals, for an expression with radicals.
GiNaC::ex take_out_radicals(const GiNaC::ex& e, const assumptions& given)
{
    struct inner : GiNaC::map_function {
        const assumptions& given;
        explicit inner(const assumptions& g) : given(g) {}
        GiNaC::ex operator()(const GiNaC::ex& part) override { return simplify_radicals(part, given); }
    } recurse(given);
    const GiNaC::ex mapped = e.map(recurse);
    if (!GiNaC::is_a<GiNaC::power>(mapped) || !GiNaC::is_a<GiNaC::numeric>(mapped.op(1)))
        return mapped;
    const GiNaC::numeric n = GiNaC::ex_to<GiNaC::numeric>(mapped.op(1));
    if (n != GiNaC::numeric(1, 2) && n != GiNaC::numeric(-1, 2))
        return mapped;
    // sqrt(f^2 g) = |f| sqrt(g), and |f| = ±f where the sign of f is proven.
    const sign_prover prover(given);
    const GiNaC::ex nd = GiNaC::normal(mapped.op(0)).numer_denom();
    GiNaC::exvector parts;
    for (int part = 0; part < 2; ++part) {
        const GiNaC::ex f = factored_in(nd.op(part), given);
        const int direction = part == 0 ? 1 : -1;
        if (GiNaC::is_a<GiNaC::mul>(f)) {
            for (const GiNaC::ex& g : f)
                parts.push_back(GiNaC::pow(g, direction));
        } else {
            parts.push_back(GiNaC::pow(f, direction));
        }
    }
    // A negative number among the factors is paired with a sum, whose sign it takes:
    // sqrt(-1/(t^2 - 4)) is sqrt(1/(4 - t^2)), never I*sqrt(1/(t^2 - 4)).
    GiNaC::numeric number = 1;
    for (GiNaC::ex& f : parts) {
        if (GiNaC::is_a<GiNaC::numeric>(f)) {
            number *= GiNaC::ex_to<GiNaC::numeric>(f);
            f = 1;
        }
    }
    if (number.is_negative()) {
        for (GiNaC::ex& f : parts) {
            const bool odd_sum = GiNaC::is_a<GiNaC::power>(f) && GiNaC::is_a<GiNaC::add>(f.op(0)) &&
                                 f.op(1).info(GiNaC::info_flags::odd);
            if (odd_sum || GiNaC::is_a<GiNaC::add>(f)) {
                f = odd_sum ? GiNaC::pow(term_order::negated_sum(f.op(0)), f.op(1)) : term_order::negated_sum(f);
                number = -number;
                break;
            }
        }
    }
    parts.push_back(number);
    GiNaC::ex outside = 1, inside = 1;
    for (const GiNaC::ex& f : parts) {
        if (GiNaC::is_a<GiNaC::power>(f) && f.op(1).info(GiNaC::info_flags::even)) {
            const sign_set s = prover.sign(f.op(0)).first;
            if (!s.negative) {
                outside *= GiNaC::pow(f.op(0), f.op(1) / 2);
                continue;
            }
            if (!s.positive) {
                outside *= GiNaC::pow(-f.op(0), f.op(1) / 2);
                continue;
            }
        }
        inside *= f;
    }
    // sqrt(N/D) = sqrt(N)/sqrt(D) where D > 0: one form for every radical of a quotient,
    // whichever GiNaC's normal() happened to return.
    const GiNaC::ex inside_nd = GiNaC::normal(inside).numer_denom();
    GiNaC::ex root = GiNaC::sqrt(inside);
    if (!inside_nd.op(1).is_equal(1)) {
        const sign_set below = prover.sign(factored_in(inside_nd.op(1), given)).first;
        if (!below.negative && !below.zero)
            root = GiNaC::sqrt(inside_nd.op(0)) / GiNaC::sqrt(inside_nd.op(1));
        else if (outside.is_equal(1))
            return mapped;
    } else if (outside.is_equal(1)) {
        return mapped;
    }
    return n.is_positive() ? outside * root : 1 / (outside * root);
}

} // namespace

GiNaC::ex simplify_radicals(const GiNaC::ex& e, const assumptions& given)
{
    if (!has_radical(e))
        return e;
    // The same radicals meet again in every proof of a derivation: kept, bounded as the
    // sign cache.
    auto& radicals = given.known->radicals;
    const auto known = radicals.find(e);
    if (known != radicals.end())
        return known->second;
    const GiNaC::ex simplified = take_out_radicals(e, given);
    if (radicals.size() >= 4096)
        radicals.clear();
    radicals.emplace(e, simplified);
    return simplified;
}

GiNaC::ex expanded_radicands(const GiNaC::ex& e)
{
    struct expand_under : GiNaC::map_function {
        GiNaC::ex operator()(const GiNaC::ex& part) override
        {
            if (GiNaC::is_a<GiNaC::power>(part) && !part.op(1).info(GiNaC::info_flags::integer))
                return GiNaC::pow(GiNaC::expand((*this)(part.op(0))), part.op(1));
            return part.map(*this);
        }
    } expand;
    return expand(e);
}

} // namespace impact::engine
