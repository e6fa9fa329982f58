// The check that the cases of a quantity leave no value out (cases.h, prove_exhaustive):
// every condition a sign of one expression D, together covering D < 0, D = 0 and D > 0.
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

check_result prove_exhaustive(const std::string& name, const std::vector<case_value>& cases,
                              const symbol_table& symbols)
{
    check_result c;
    c.name = fmt::format("the cases of {} cover every value", name);
    c.statement = c.name;
    c.because = "each value of the quantities must fall in a case";
    c.where = cases.front().where;
    c.stated = 0;
    c.lhs = 0;
    c.rhs = 0;
    c.outcome.residual = 0;
    // Each condition as a sign of D, the first condition's C. Compared as written first: a
    // condition with a radical of a radical (|g_t| in space, whose square holds the
    // distance sqrt(r.r)) may normalise to forms normal() cannot compare, though it is the
    // first's, turned.
    const GiNaC::ex first = condition_form(cases.front()).value;
    const GiNaC::ex d = normal_written_once(first, symbols.order());
    sign_set covered{false, false, false};
    std::vector<std::string> signs;
    // The same, typeset: "with D = ..., the conditions read D >= 0, D < 0".
    const GiNaC::symbol named_d("D");
    finding typeset;
    typeset.say("with ").states(named_d, relation::equal, d).say(", the conditions read ");
    for (const case_value& one : cases) {
        const nonnegative_form f = condition_form(one);
        auto k = constant_ratio(f.value, first);
        if (!k)
            k = constant_ratio(f.value, d);
        if (!k) {
            c.outcome.what = verdict::status::failed;
            c.outcome.residual = f.value;
            c.outcome.method = fmt::format("the condition {} is not a sign of {} as the first is: the cases are not "
                                           "proven to cover every value",
                                           condition_text(one, symbols.order()), ginac_syntax(d, symbols.order()));
            return c;
        }
        // C = k D >= 0 (> 0): D >= 0 for k > 0, D <= 0 for k < 0.
        const bool up = k->is_positive();
        if (up)
            covered.positive = true;
        else
            covered.negative = true;
        if (!f.strict)
            covered.zero = true;
        signs.push_back(fmt::format("D {} 0", f.strict ? (up ? ">" : "<") : (up ? ">=" : "<=")));
        typeset.say(signs.size() == 1 ? "" : ", ")
            .states(named_d, f.strict ? (up ? relation::greater : relation::less)
                                      : (up ? relation::greater_equal : relation::less_equal),
                    0);
    }
    (void)symbols;
    if (covered.negative && covered.zero && covered.positive) {
        c.outcome.what = verdict::status::proven;
        c.outcome.method = fmt::format("with D = {}, the conditions read {}: together every sign of D",
                                       ginac_syntax(d, symbols.order()), fmt::join(signs, ", "));
        c.outcome.typeset = std::move(typeset.say(": together every sign of ").math(named_d));
    } else {
        c.outcome.what = verdict::status::failed;
        c.outcome.residual = d;
        c.outcome.method = fmt::format("with D = {}, the conditions read {}: D {} is in no case",
                                       ginac_syntax(d, symbols.order()), fmt::join(signs, ", "),
                                       !covered.negative ? "< 0" : !covered.zero ? "= 0" : "> 0");
    }
    return c;
}

} // namespace impact::engine
