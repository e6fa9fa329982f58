#include "engine/expr/normal_form.h"

#include <algorithm>
#include <iterator>
#include <map>
#include <tuple>
#include <vector>

namespace impact::engine {

bool has_radical(const GiNaC::ex& e)
{
    for (GiNaC::const_preorder_iterator it = e.preorder_begin(); it != e.preorder_end(); ++it)
        if (GiNaC::is_a<GiNaC::power>(*it) && !it->op(1).info(GiNaC::info_flags::integer))
            return true;
    return false;
}

namespace {

// Square roots standing as symbols, so that normal() works on a rational function whose
// numerator and denominator are unique. Left to itself, normal() puts each radical in a
// symbol of its own and back again, and which products of the radicand it then leaves
// unexpanded ((N.N) v_x beside N_x^2 v_x) and which powers it keeps ((N.N)^(5/2)/(N.N)^4
// or (N.N)^(3/2)/(N.N)^2) follows GiNaC's order of terms: that order derives from
// addresses, and the sanitized build derives another form than the normal one.
// Each radicand (inner ones first, expanded) becomes a symbol t with t^2 = radicand;
// every power of a radicand with a half-integer exponent is a power of its t.
class radicals_as_symbols : public GiNaC::map_function {
public:
    /// e with each radical a power of its symbol, and each whole power of a radicand too
    /// ((N.N)^(-1) = t^(-2)): normal() then sees the one symbol where the radicand stands.
    GiNaC::ex in_symbols(const GiNaC::ex& e)
    {
        collecting_ = true;
        (*this)(e);
        collecting_ = false;
        return (*this)(e);
    }

    GiNaC::ex operator()(const GiNaC::ex& part) override
    {
        if (GiNaC::is_a<GiNaC::power>(part) && part.op(1).info(GiNaC::info_flags::rational) &&
            !part.op(1).info(GiNaC::info_flags::integer) && GiNaC::ex_to<GiNaC::numeric>(part.op(1)).denom() == 2) {
            const GiNaC::numeric k = GiNaC::ex_to<GiNaC::numeric>(part.op(1));
            auto expanded = expanded_.find(part.op(0));
            if (expanded == expanded_.end())
                expanded = expanded_.emplace(part.op(0), GiNaC::expand(part.op(0))).first;
            const GiNaC::ex& radicand = expanded->second;
            auto found =
                std::find_if(roots_.begin(), roots_.end(), [&](const root& r) { return r.radicand.is_equal(radicand); });
            if (found == roots_.end()) {
                part.op(0).map(*this);   // its inner radicals first
                // Not a realsymbol: a radicand may be negative, and conjugate(t) = t would be wrong.
                roots_.push_back({GiNaC::symbol(), radicand, part.op(0)});
                found = std::prev(roots_.end());
            } else if (!found->written.is_equal(part.op(0))) {
                found->written = radicand;   // written two ways: which came first is GiNaC's order
            }
            return GiNaC::pow(found->symbol, k.numer());
        }
        if (!collecting_) {
            if (const root* r = radicand_of(part))   // the radicand as a factor: t^2
                return GiNaC::pow(r->symbol, 2);
            if (GiNaC::is_a<GiNaC::power>(part) && part.op(1).info(GiNaC::info_flags::integer))
                if (const root* r = radicand_of(part.op(0)))
                    return GiNaC::pow(r->symbol, 2 * part.op(1));
        }
        return part.map(*this);
    }

    /// e with each power t^k past the first written radicand^(k div 2) t^(k mod 2), where it
    /// stands (nothing multiplied out); outer radicals first, their radicands holding the inner.
    GiNaC::ex reduced(GiNaC::ex e)
    {
        for (auto r = roots_.rbegin(); r != roots_.rend(); ++r)
            e = e.subs(GiNaC::pow(r->symbol, 2) == r->written.map(*this), GiNaC::subs_options::algebraic);
        return e;
    }

    /// e with each symbol its square root again, outer radicals first.
    GiNaC::ex restored(GiNaC::ex e) const
    {
        for (auto r = roots_.rbegin(); r != roots_.rend(); ++r)
            e = e.subs(r->symbol == GiNaC::sqrt(r->written));
        return e;
    }

private:
    struct root;
    /// The root whose radicand `e` is, written as under its root or multiplied out, if any
    /// (compared as written: expanding every sum and product met would cost more than the rest).
    const root* radicand_of(const GiNaC::ex& e) const
    {
        if (!(GiNaC::is_a<GiNaC::add>(e) || GiNaC::is_a<GiNaC::mul>(e)))
            return nullptr;
        for (const root& r : roots_)
            if (r.written.is_equal(e) || r.radicand.is_equal(e))
                return &r;
        return nullptr;
    }

    bool collecting_ = false;
    struct root {
        GiNaC::ex symbol;
        GiNaC::ex radicand;   ///< expanded: the same radicand however it is written
        GiNaC::ex written;    ///< as the expression writes it, or expanded if written two ways
    };
    std::vector<root> roots_;   // in the order met, inner radicals before the outer ones
    std::map<GiNaC::ex, GiNaC::ex, GiNaC::ex_is_less> expanded_;   // radicands as written, expanded
};

// unique_numer_denom for an expression with radicals, before the sign is placed.
std::pair<GiNaC::ex, GiNaC::ex> radicals_in_symbols_numer_denom(const GiNaC::ex& e)
{
    // Not yet one form in every case: where fractions whose denominators share a factor are
    // added, normal() builds the common denominator factor by factor in GiNaC's order
    // ((x - 1)(x + 1) or x^2 - 1). Multiplying it out would settle that, but changes the
    // denominators the kernels' limit forms are built on (rough_plane's fixed spheres then
    // miss their bounds).
    radicals_as_symbols roots;
    GiNaC::ex nd = GiNaC::normal(roots.in_symbols(e)).numer_denom();
    const GiNaC::ex reduced = roots.reduced(nd);
    if (!reduced.is_equal(nd))   // a radicand came back: what it shares with the rest cancels
        nd = GiNaC::normal(reduced.op(0) / reduced.op(1)).numer_denom();
    return {roots.restored(nd.op(0)), roots.restored(nd.op(1))};
}

} // namespace

// e's numerator and denominator in a form GiNaC's order of terms does not choose: the
// radicals stand as symbols, their powers standing as factors past the first are reduced
// by t^2 = radicand (a power of a sum that holds t, as (a + t)^3, is left as it is), common
// factors cancelled, and the sign put where `order` writes the denominator's first term
// positive. Restored, a radicand beside its root merges with it (S sqrt(S) = S^(3/2)).
std::pair<GiNaC::ex, GiNaC::ex> unique_numer_denom(const GiNaC::ex& e, const term_order& order)
{
    GiNaC::ex numer, denom;
    if (!has_radical(e)) {
        const GiNaC::ex nd = GiNaC::normal(e).numer_denom();
        numer = nd.op(0);
        denom = nd.op(1);
    } else {
        std::tie(numer, denom) = radicals_in_symbols_numer_denom(e);
    }
    if (GiNaC::is_a<GiNaC::add>(denom) ? order.leads_negative(denom) : order.negative(denom)) {
        numer = -numer;
        denom = -denom;
    }
    return {numer, denom};
}

GiNaC::ex normal_written_once(const GiNaC::ex& e, const term_order& order)
{
    // With t^2 = radicand applied, a denominator may turn out 0 (1/(S^(3/2) - S sqrt(S))),
    // which normal() then refuses: the value is left as normal() alone writes it.
    try {
        const auto [numer, denom] = unique_numer_denom(e, order);
        return numer / denom;
    } catch (const std::exception&) {
        return GiNaC::normal(e);
    }
}

} // namespace impact::engine
