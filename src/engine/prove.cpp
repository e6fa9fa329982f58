#include "engine/prove.h"

#include <fmt/format.h>

#include <cln/real.h>
#include <cln/rational.h>

#include <cmath>

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
verdict sample(const GiNaC::ex& lhs, const GiNaC::ex& rhs, const GiNaC::ex& residual,
               const symbol_table& symbols)
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
            if (!GiNaC::is_a<GiNaC::numeric>(a) || !GiNaC::is_a<GiNaC::numeric>(b))
                continue;
            const double scale = std::max({1.0, std::abs(GiNaC::ex_to<GiNaC::numeric>(a).to_double()),
                                           std::abs(GiNaC::ex_to<GiNaC::numeric>(b).to_double())});
            const GiNaC::numeric gap = GiNaC::abs(GiNaC::ex_to<GiNaC::numeric>(a - b));
            if (gap.to_double() > 1e-30 * scale) {
                GiNaC::Digits = saved_digits;
                v.what = verdict::status::failed;
                v.samples = tested + 1;
                v.method = fmt::format("differs at a sampled point by {:.3g}", gap.to_double());
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
    v.method = tested > 0 ? fmt::format("GiNaC could not normalise the difference to zero; it vanishes "
                                        "at {} sampled points ({} digits)",
                                        tested, sample_digits)
                          : "no sampled point could be evaluated";
    return v;
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
    const GiNaC::ex a = lhs.subs(abbreviations).subs(abbreviations);
    const GiNaC::ex b = rhs.subs(abbreviations).subs(abbreviations);
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
    return sample(a, b, residual, symbols);
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
