#include "engine/prove.h"

#include <fmt/format.h>

#include <cln/real.h>
#include <cln/rational.h>

#include <cmath>
#include <functional>

namespace impact::engine {
namespace {

constexpr std::size_t sample_points = 200;
constexpr int sample_digits = 40;

// The exact rational value of a double, so that sampled points carry no rounding.
GiNaC::numeric exact(double value)
{
    return GiNaC::numeric(cln::cl_N(cln::rational(cln::cl_DF(value))));
}

// Evaluates `lhs - rhs` at points of the declared domains. Returns the failing
// residual's value as a verdict, or a `sampled` verdict when every point agrees.
// Evaluates both sides at points of the declared domains and tests `holds` on them.
// Returns `failed` at the first point where it does not hold, else `sampled`.
verdict sample(const GiNaC::ex& lhs, const GiNaC::ex& rhs, const GiNaC::ex& residual, const symbol_table& symbols,
               const std::function<bool(const GiNaC::numeric&, const GiNaC::numeric&)>& holds,
               const std::string& claim)
{
    GiNaC::lst free;
    for (const quantity& q : symbols.all())
        if ((lhs - rhs).has(q.symbol))
            free.append(q.symbol);

    const auto saved_digits = GiNaC::Digits;
    GiNaC::Digits = sample_digits;
    uniform_stream stream(0x1a2b3c4d5e6f7081ULL);
    std::size_t tested = 0;
    verdict v;
    v.residual = residual;
    for (std::size_t attempt = 0; tested < sample_points && attempt < 4 * sample_points; ++attempt) {
        GiNaC::exmap point;
        for (const GiNaC::ex& s : free)
            point[s] = exact(draw(*symbols.domain_of(s), stream));
        try {
            const GiNaC::ex a = GiNaC::evalf(lhs.subs(point));
            const GiNaC::ex b = GiNaC::evalf(rhs.subs(point));
            if (!GiNaC::is_a<GiNaC::numeric>(a) || !GiNaC::is_a<GiNaC::numeric>(b) ||
                !GiNaC::ex_to<GiNaC::numeric>(a).is_real() || !GiNaC::ex_to<GiNaC::numeric>(b).is_real())
                continue;
            if (!holds(GiNaC::ex_to<GiNaC::numeric>(a), GiNaC::ex_to<GiNaC::numeric>(b))) {
                GiNaC::Digits = saved_digits;
                v.what = verdict::status::failed;
                v.samples = tested + 1;
                v.method = fmt::format("does not hold at a sampled point: {} {} vs {:.6g}",
                                       GiNaC::ex_to<GiNaC::numeric>(a).to_double(), claim,
                                       GiNaC::ex_to<GiNaC::numeric>(b).to_double());
                return v;
            }
            ++tested;
        } catch (const std::exception&) {
            continue; // a pole of either side: draw another point
        }
    }
    GiNaC::Digits = saved_digits;
    v.what = tested > 0 ? verdict::status::sampled : verdict::status::failed;
    v.samples = tested;
    v.method = tested > 0 ? fmt::format("not proven symbolically; holds at {} sampled points ({} digits)", tested,
                                        sample_digits)
                          : "no sampled point could be evaluated";
    return v;
}

bool nearly_equal(const GiNaC::numeric& a, const GiNaC::numeric& b)
{
    const double scale = std::max({1.0, std::abs(a.to_double()), std::abs(b.to_double())});
    return GiNaC::abs(a - b).to_double() <= 1e-30 * scale;
}

} // namespace

std::string to_string(const verdict& v)
{
    switch (v.what) {
    case verdict::status::proven: return "proven";
    case verdict::status::sampled: return fmt::format("sampled ({} points)", v.samples);
    case verdict::status::failed: break;
    }
    return "failed";
}

verdict prove_equal(const GiNaC::ex& lhs, const GiNaC::ex& rhs, const symbol_table& symbols)
{
    const GiNaC::exmap abbreviations = symbols.abbreviations();
    const assumptions given = declared_assumptions(symbols);
    // Radicals in one canonical form first: normal() cannot see that sqrt(1/x) = 1/sqrt(x).
    const GiNaC::ex a = simplify_radicals(lhs.subs(abbreviations).subs(abbreviations), given);
    const GiNaC::ex b = simplify_radicals(rhs.subs(abbreviations).subs(abbreviations), given);
    const GiNaC::ex residual = GiNaC::normal(GiNaC::expand(a - b));
    if (residual.is_zero()) {
        verdict v;
        v.what = verdict::status::proven;
        v.residual = residual;
        v.method = "difference normalises to zero";
        return v;
    }
    // A rational function with no radicals or functions left is decided by normal():
    // a non-zero residual is a counterexample, no sampling needed.
    bool rational = true;
    for (GiNaC::const_preorder_iterator it = residual.preorder_begin(); it != residual.preorder_end(); ++it) {
        if (GiNaC::is_a<GiNaC::function>(*it) ||
            (GiNaC::is_a<GiNaC::power>(*it) && !it->op(1).info(GiNaC::info_flags::integer)))
            rational = false;
    }
    if (rational) {
        verdict v;
        v.what = verdict::status::failed;
        v.residual = residual;
        v.method = "difference normalises to a non-zero rational function";
        return v;
    }
    return sample(a, b, residual, symbols, nearly_equal, "=");
}

verdict prove_inequality(const GiNaC::ex& lhs, relation op, const GiNaC::ex& rhs, const symbol_table& symbols,
                         const assumptions& given)
{
    const GiNaC::exmap abbreviations = symbols.abbreviations();
    const GiNaC::ex a = lhs.subs(abbreviations).subs(abbreviations);
    const GiNaC::ex b = rhs.subs(abbreviations).subs(abbreviations);
    // lhs <= rhs  <=>  rhs - lhs >= 0; strict relations need > 0.
    const bool upper = op == relation::less_equal || op == relation::less;
    const bool strict = op == relation::less || op == relation::greater;
    const GiNaC::ex difference = upper ? b - a : a - b;
    const sign_proof proof = prove_sign(difference, given);
    verdict v;
    v.residual = GiNaC::normal(difference);
    v.proof = proof.steps;
    if (!proof.sign.negative && !(strict && proof.sign.zero)) {
        v.what = verdict::status::proven;
        v.method = fmt::format("the sign of each factor of {} follows from the domains", given.text(v.residual));
        return v;
    }
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
    verdict sampled = sample(a, b, v.residual, symbols, holds, to_string(op));
    sampled.proof = proof.steps;
    return sampled;
}

verdict prove_equivalent(const GiNaC::ex& equation, const GiNaC::ex& other, const symbol_table& symbols)
{
    const GiNaC::ex d1 = equation.lhs() - equation.rhs();
    const GiNaC::ex d2 = other.lhs() - other.rhs();
    const GiNaC::ex ratio = GiNaC::normal(d1 / d2);
    if (GiNaC::is_a<GiNaC::numeric>(ratio) && !ratio.is_zero()) {
        verdict v;
        v.what = verdict::status::proven;
        v.residual = 0;
        v.method = "the two equations differ by a constant factor";
        return v;
    }
    verdict v = prove_equal(d1, d2, symbols);
    if (v.what == verdict::status::proven)
        v.method = "the two equations have the same difference of sides";
    return v;
}

} // namespace impact::engine
