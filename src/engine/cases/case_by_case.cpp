// A check proven case by case (cases.h, prove_case_by_case): each case's values put in, the
// claim proven under its condition, a case that cannot arise (at special values, near a
// limit) holding nothing to prove; the parts' verdicts combined.
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

namespace impact::engine {

using namespace cases_detail;

namespace {

// The case's condition C >= 0 (> 0) false as x -> infinity: C polynomial in x (mu J_n
// beside a sticking impulse free of mu) tends to -infinity where its leading coefficient,
// its k-th derivative in x, the first free of x, is proven negative. No expansion (C holds
// the slip's length, a root of hundreds of terms in space), and nothing decided where the
// coefficient's sign is not proven at once (the masses' limits: every case arises).
bool cannot_arise_near(const case_value& c, const check_result::limit_point& near, const symbol_table& symbols,
                       const assumptions& given)
{
    constexpr std::size_t effort = 100;
    const GiNaC::ex value = condition_form(c).value.subs(symbols.abbreviations());
    if (!near.to_infinity || !value.has(near.symbol) || !value.is_polynomial(near.symbol))
        return false;
    GiNaC::ex derivative = value;
    for (int k = 1; k <= 8 && derivative.has(near.symbol); ++k)
        derivative = derivative.diff(GiNaC::ex_to<GiNaC::symbol>(near.symbol));
    // A sum with square roots is normalised before its sign is sought, which takes seconds
    // in space; a coefficient whose sign shows is a product (the masses' is a difference).
    if (derivative.has(near.symbol) || (GiNaC::is_a<GiNaC::add>(derivative) && has_radical(derivative)))
        return false;
    const sign_set s = prove_sign(derivative, with_effort(given, effort)).sign;
    return !s.positive && !s.zero;
}

} // namespace

void prove_case_by_case(check_result& c, const case_split& split, const GiNaC::exmap& at,
                        const symbol_table& symbols, const assumptions& given, proof_cache& run,
                        const std::function<verdict(const GiNaC::ex&, const GiNaC::ex&)>& prove,
                        const std::optional<check_result::limit_point>& near)
{
    std::vector<std::string> names;
    for (const GiNaC::ex& s : split.symbols)
        names.push_back(ginac_syntax(s, symbols.order()));
    const std::size_t named = std::min(split.named, names.size());
    c.cases_of = fmt::format("{}", fmt::join(names.begin(), names.begin() + static_cast<std::ptrdiff_t>(named), " and "));
    const std::size_t count = split.pieces.front().size();
    for (std::size_t i = 0; i < count; ++i) {
        case_value one = split.pieces.front()[i];
        check_result::part part;
        part.first = i + 1;
        if (!at.empty()) {
            one.lhs = one.lhs.subs(at);
            one.rhs = one.rhs.subs(at);
        }
        // A value at special values where its case does not arise may not exist (k/(1 + b)
        // at b = -1): it is worked out only where the case arises.
        GiNaC::exmap in_case;
        std::vector<std::string> values;
        for (std::size_t k = 0; k < split.symbols.size(); ++k) {
            GiNaC::ex value = split.pieces[k][i].value;
            try {
                if (!at.empty())
                    value = value.subs(at);
            } catch (const std::exception&) {
                value = split.pieces[k][i].value;
            }
            in_case[split.symbols[k]] = value;
            if (k >= named)
                continue;
            values.push_back(fmt::format("{} = {}", names[k], given.text(value)));
            if (named > 1) {
                case_value each = split.pieces[k][i];
                each.value = value;
                each.lhs = one.lhs;
                each.rhs = one.rhs;
                part.in_cases.emplace_back(split.symbols[k], std::move(each));
            }
        }
        one.value = in_case[split.symbols.front()];
        part.in_case = one;
        part.under = fmt::format("case {} ({}, where {})", i + 1, fmt::join(values, ", "),
                                 condition_text(one, given.order));
        // At special values a condition may be a comparison of numbers, or one the domains
        // contradict: a case whose condition is false holds nothing to prove.
        const GiNaC::ex gap = GiNaC::normal(one.rhs - one.lhs);
        bool arises = true;
        if (GiNaC::is_a<GiNaC::numeric>(gap) && GiNaC::ex_to<GiNaC::numeric>(gap).is_real()) {
            const GiNaC::numeric g = GiNaC::ex_to<GiNaC::numeric>(gap);   // rhs - lhs
            arises = one.op == relation::less_equal      ? g >= 0
                     : one.op == relation::less          ? g > 0
                     : one.op == relation::greater_equal ? g <= 0
                                                         : g < 0;
            if (!arises)
                part.outcome.method = "the case does not arise: its condition is false at these values";
        } else if (!at.empty() && cannot_arise(one, symbols, given)) {
            arises = false;
            part.outcome.method = "the case does not arise: the domains make its condition false";
        } else if (near && cannot_arise_near(one, *near, symbols, given)) {
            arises = false;
            part.outcome.method = fmt::format("the case does not arise near the limit {} -> {}: its condition is "
                                              "false there",
                                              given.text(near->symbol),
                                              near->to_infinity ? "infinity" : given.text(near->point));
        }
        if (!arises) {
            part.outcome.what = verdict::status::proven;
            part.outcome.residual = 0;
        } else {
            const GiNaC::ex lhs = c.lhs.subs(in_case, GiNaC::subs_options::no_pattern);
            const GiNaC::ex rhs = c.rhs.subs(in_case, GiNaC::subs_options::no_pattern);
            part.outcome = prove                    ? prove(lhs, rhs)
                           : c.op == relation::equal ? prove_equal(lhs, rhs, symbols, run)
                                                     : prove_in_case(lhs, c.op, rhs, one, symbols, given);
        }
        c.parts.push_back(std::move(part));
    }
    c.outcome = combine_cases(c.parts);
}

verdict combine_cases(const std::vector<check_result::part>& parts)
{
    return combined(parts, "case by case");
}

} // namespace impact::engine
