#include "engine/prove/condition_proof.h"

#include "engine/expr/normal_form.h"

#include <fmt/format.h>

#include <algorithm>

namespace impact::engine {

// |x y| = |x| |y|, and |x| = x or -x where the sign of x is proven: the absolute values
// a case's value and condition hold, taken out where the domains allow.
GiNaC::ex without_abs(const GiNaC::ex& e, const assumptions& given)
{
    if (!e.has(GiNaC::abs(GiNaC::wild())))
        return e;
    if (GiNaC::is_a<GiNaC::function>(e) && GiNaC::ex_to<GiNaC::function>(e).get_name() == "abs") {
        const GiNaC::ex inside = without_abs(e.op(0), given);
        const sign_set s = prove_sign(inside, given).sign;
        if (!s.negative)
            return inside;
        if (!s.positive)
            return -inside;
        if (GiNaC::is_a<GiNaC::mul>(inside)) {
            GiNaC::ex product = 1;
            for (std::size_t i = 0; i < inside.nops(); ++i)
                product *= without_abs(GiNaC::abs(inside.op(i)), given);
            return product;
        }
        if (GiNaC::is_a<GiNaC::power>(inside) && inside.op(1).info(GiNaC::info_flags::integer))
            return GiNaC::pow(without_abs(GiNaC::abs(inside.op(0)), given), inside.op(1));
        return GiNaC::abs(inside);
    }
    struct inside : GiNaC::map_function {
        const assumptions& given;
        explicit inside(const assumptions& g) : given(g) {}
        GiNaC::ex operator()(const GiNaC::ex& x) override { return without_abs(x, given); }
    } each(given);
    return e.map(each);
}

// The real symbols of unknown sign whose absolute value `e` takes.
void symbols_under_abs(const GiNaC::ex& e, const assumptions& given, std::vector<GiNaC::ex>& found)
{
    for (GiNaC::const_preorder_iterator it = e.preorder_begin(); it != e.preorder_end(); ++it) {
        if (!GiNaC::is_a<GiNaC::function>(*it) || GiNaC::ex_to<GiNaC::function>(*it).get_name() != "abs" ||
            !GiNaC::is_a<GiNaC::symbol>(it->op(0)))
            continue;
        const GiNaC::ex x = it->op(0);
        const auto d = given.domains.find(x);
        if ((d == given.domains.end() || !d->second.is_nonnegative()) &&
            std::find_if(found.begin(), found.end(), [&x](const GiNaC::ex& y) { return y.is_equal(x); }) == found.end())
            found.push_back(x);
    }
}

// The claim G >= 0 (> 0) from the condition C >= 0 (> 0) by dividing G's numerator by
// C's in a symbol x that C is linear in, a term at a time: G = q C + r with q and r
// proven non-negative, as a textbook bounds a quadratic by the condition it lies under.
std::optional<verdict> divided_by_condition(const GiNaC::ex& g, bool strict, const GiNaC::ex& condition,
                                            bool condition_strict, const assumptions& given)
{
    const GiNaC::ex gnd = GiNaC::normal(g).numer_denom();
    const GiNaC::ex cnd = GiNaC::normal(condition).numer_denom();
    const GiNaC::ex top = GiNaC::expand(gnd.op(0)), bottom = gnd.op(1);
    const GiNaC::ex c_top = GiNaC::expand(cnd.op(0)), c_bottom = cnd.op(1);
    std::vector<GiNaC::ex> xs;
    for (GiNaC::const_preorder_iterator it = c_top.preorder_begin(); it != c_top.preorder_end(); ++it)
        if (GiNaC::is_a<GiNaC::symbol>(*it) &&
            std::find_if(xs.begin(), xs.end(), [&it](const GiNaC::ex& y) { return y.is_equal(*it); }) == xs.end())
            xs.push_back(*it);
    // In the order of their names: the order GiNaC meets them in changes with the build, and
    // the first that divides is the one the proof tells.
    std::sort(xs.begin(), xs.end(), [](const GiNaC::ex& a, const GiNaC::ex& b) {
        return GiNaC::ex_to<GiNaC::symbol>(a).get_name() < GiNaC::ex_to<GiNaC::symbol>(b).get_name();
    });
    for (const GiNaC::ex& x : xs) {
        // Polynomials in x first: degree() throws on x under a radical.
        if (!c_top.is_polynomial(x) || !top.is_polynomial(x) || c_top.degree(x) != 1 || top.degree(x) < 1 ||
            top.ldegree(x) < 0)
            continue;
        const GiNaC::ex lead = c_top.coeff(x, 1);
        // The quotient holds 1/lead: where lead vanishes G = q C + r says nothing.
        if (prove_sign(lead, given).sign.zero)
            continue;
        GiNaC::ex q = 0, r = top;
        for (int k = top.degree(x); k >= 1; --k) {
            const GiNaC::ex t = GiNaC::normal(r.coeff(x, k) / lead) * GiNaC::pow(x, k - 1);
            q += t;
            r = GiNaC::normal(GiNaC::expand(top - q * c_top));
            // G = (q c_bottom / bottom) C + r / bottom.
            const GiNaC::ex factor = normal_written_once(q * c_bottom / bottom, given.order);
            const GiNaC::ex rest = normal_written_once(r / bottom, given.order);
            const sign_proof pq = prove_sign(factor, given);
            if (pq.sign.negative)
                continue;
            const sign_proof pr = prove_sign(rest, given);
            if (pr.sign.negative)
                continue;
            if (strict && !(pr.sign.is_positive() || (pq.sign.is_positive() && condition_strict)))
                continue;
            verdict v;
            v.what = verdict::status::proven;
            v.residual = 0;
            v.proof = pq.steps;
            v.proof.insert(v.proof.end(), pr.steps.begin(), pr.steps.end());
            v.method = fmt::format("{} = ({})*({}) + {}, divided by the condition's side in {}: a factor {} times "
                                   "it plus a remainder {}",
                                   given.text(g), given.text(factor), given.text(condition), given.text(rest),
                                   given.text(x), pq.sign.describe(), pr.sign.describe());
            return v;
        }
    }
    return std::nullopt;
}

} // namespace impact::engine
