// Quantities defined by cases (cases.h): the select function a kernel computes them by,
// the cases as one expression of selects, and the text of a case's condition.
#include "engine/cases/cases.h"
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

GiNaC::ex select_eval(const GiNaC::ex& c, const GiNaC::ex& a, const GiNaC::ex& b)
{
    if (GiNaC::is_a<GiNaC::numeric>(c) && GiNaC::ex_to<GiNaC::numeric>(c).is_real())
        return GiNaC::ex_to<GiNaC::numeric>(c).is_positive() ? a : b;
    return select_positive(c, a, b).hold();
}

GiNaC::ex select_evalf(const GiNaC::ex& c, const GiNaC::ex& a, const GiNaC::ex& b)
{
    const GiNaC::ex at = c.evalf();
    if (GiNaC::is_a<GiNaC::numeric>(at) && GiNaC::ex_to<GiNaC::numeric>(at).is_real())
        return GiNaC::ex_to<GiNaC::numeric>(at).is_positive() ? a.evalf() : b.evalf();
    return select_positive(at, a.evalf(), b.evalf()).hold();
}

} // namespace

REGISTER_FUNCTION(select_positive, eval_func(select_eval).evalf_func(select_evalf))

GiNaC::ex select_of(const std::vector<case_value>& cases)
{
    GiNaC::ex rest = cases.back().value;
    for (std::size_t i = cases.size() - 1; i-- > 0;) {
        const nonnegative_form f = condition_form(cases[i]);
        rest = f.strict ? select_positive(f.value, cases[i].value, rest)
                        : select_positive(-f.value, rest, cases[i].value);
    }
    return rest;
}

bool is_select(const GiNaC::ex& e)
{
    return GiNaC::is_the_function<select_positive_SERIAL>(e);
}

bool has_select(const GiNaC::ex& e)
{
    for (GiNaC::const_preorder_iterator it = e.preorder_begin(); it != e.preorder_end(); ++it)
        if (is_select(*it))
            return true;
    return false;
}

std::string condition_text(const case_value& c, const term_order& order)
{
    return fmt::format("{} {} {}", ginac_syntax(c.lhs, order), to_string(c.op), ginac_syntax(c.rhs, order));
}

bool same_conditions(const std::vector<case_value>& a, const std::vector<case_value>& b)
{
    if (a.size() != b.size())
        return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (a[i].op != b[i].op || !GiNaC::normal(a[i].lhs - b[i].lhs).is_zero() ||
            !GiNaC::normal(a[i].rhs - b[i].rhs).is_zero())
            return false;
    return true;
}

} // namespace impact::engine
