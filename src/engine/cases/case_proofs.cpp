// What the proofs about cases share (case_proofs.h): a condition as C >= 0, the ratio of
// two conditions, the weakest verdict of parts, and whether a case cannot arise.
#include "engine/cases/case_proofs.h"

#include "engine/prove/condition_proof.h"
#include "engine/expr/infix.h"
#include "engine/prove/limit.h"
#include "engine/expr/normal_form.h"
#include "engine/prove/prove.h"
#include "engine/solve/solve.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <map>

namespace impact::engine::cases_detail {

nonnegative_form condition_form(const case_value& c)
{
    const bool upper = c.op == relation::less_equal || c.op == relation::less;
    return {upper ? c.rhs - c.lhs : c.lhs - c.rhs, c.op == relation::less || c.op == relation::greater};
}

std::optional<GiNaC::numeric> constant_ratio(const GiNaC::ex& a, const GiNaC::ex& b)
{
    if (b.is_zero())
        return std::nullopt;
    const GiNaC::ex ratio = GiNaC::normal(a / b);
    if (!GiNaC::is_a<GiNaC::numeric>(ratio) || ratio.is_zero())
        return std::nullopt;
    const GiNaC::numeric k = GiNaC::ex_to<GiNaC::numeric>(ratio);
    if (!k.is_real())
        return std::nullopt;
    return k;
}

verdict combined(const std::vector<check_result::part>& parts, const std::string& what)
{
    verdict v;
    v.what = verdict::status::proven;
    v.residual = 0;
    std::vector<std::string> lines;
    for (const check_result::part& p : parts) {
        if (p.outcome.what == verdict::status::failed) {
            v.what = verdict::status::failed;
            v.residual = p.outcome.residual;
        } else if (p.outcome.what == verdict::status::sampled && v.what == verdict::status::proven) {
            v.what = verdict::status::sampled;
            v.samples = p.outcome.samples;
        }
        lines.push_back(fmt::format("{}: {} ({})", p.under, to_string(p.outcome), p.outcome.method));
    }
    v.method = fmt::format("{}: {}", what, fmt::join(lines, "; "));
    return v;
}

bool cannot_arise(const case_value& c, const symbol_table& symbols, const assumptions& given)
{
    constexpr std::size_t most_terms = 4;
    const auto few_terms = [&](const GiNaC::ex& product) {
        const auto short_enough = [&](GiNaC::ex factor) {
            if (GiNaC::is_a<GiNaC::power>(factor))
                factor = factor.op(0);
            return !GiNaC::is_a<GiNaC::add>(factor) || factor.nops() <= most_terms ||
                   assumed_multiple(factor, given).has_value();
        };
        if (!GiNaC::is_a<GiNaC::mul>(product))
            return short_enough(product);
        for (std::size_t i = 0; i < product.nops(); ++i)
            if (!short_enough(product.op(i)))
                return false;
        return true;
    };
    const nonnegative_form f = condition_form(c);
    const GiNaC::ex value = without_abs(GiNaC::normal(f.value.subs(symbols.abbreviations(), GiNaC::subs_options::no_pattern)), given);
    if (!few_terms(value.numer())) {
        const GiNaC::ex top = GiNaC::expand(value.numer());
        if (GiNaC::is_a<GiNaC::add>(top) && top.nops() > most_terms &&
            !few_terms(given.run ? factor_polynomial(top, *given.run) : factor_polynomial(top)))
            return false;
    }
    const sign_set s = prove_sign(value, given).sign;
    return f.strict ? !s.positive : (!s.positive && !s.zero);
}

} // namespace impact::engine::cases_detail
