// Square roots that are abbreviations named as quantities of their own (radicals_named.h).
#include "engine/cases/radicals_named.h"

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

namespace {

// True when `e` is, as written, a sum of products of even powers and positive numbers
// (r_x^2 + r_y^2, G_tx^2 + G_ty^2 + G_tz^2): >= 0 without expanding it.
bool sum_of_squares(const GiNaC::ex& e)
{
    if (GiNaC::is_a<GiNaC::numeric>(e))
        return !GiNaC::ex_to<GiNaC::numeric>(e).is_negative() && GiNaC::ex_to<GiNaC::numeric>(e).is_real();
    if (GiNaC::is_a<GiNaC::power>(e))
        return e.op(1).info(GiNaC::info_flags::even);
    if (GiNaC::is_a<GiNaC::add>(e) || GiNaC::is_a<GiNaC::mul>(e))
        return std::all_of(e.begin(), e.end(), [](const GiNaC::ex& part) { return sum_of_squares(part); });
    return false;
}

} // namespace

radicals_named::radicals_named(const symbol_table& symbols, const assumptions& given)
{
    for (const quantity& q : symbols.all()) {
        if (!q.definition)
            continue;
        const GiNaC::ex inputs = symbols.in_inputs(*q.definition);
        if (!GiNaC::is_a<GiNaC::power>(inputs) || !inputs.op(1).is_equal(GiNaC::numeric(1, 2)))
            continue;
        if (sum_of_squares(inputs.op(0)) || prove_sign(inputs.op(0), with_effort(given, 100)).sign.is_nonnegative())
            roots_.push_back({GiNaC::expand(inputs.op(0)), q, GiNaC::symbol(q.name, q.latex), false});
    }
}

GiNaC::ex radicals_named::operator()(const GiNaC::ex& part)
{
    if (GiNaC::is_a<GiNaC::power>(part) && part.op(1).info(GiNaC::info_flags::rational) &&
        !part.op(1).info(GiNaC::info_flags::integer) && GiNaC::ex_to<GiNaC::numeric>(part.op(1)).denom() == 2) {
        auto known = match_.find(part.op(0));
        if (known == match_.end()) {
            const GiNaC::ex radicand = GiNaC::expand(part.op(0));
            std::size_t which = roots_.size();
            for (std::size_t i = 0; i < roots_.size(); ++i)
                if (roots_[i].radicand.is_equal(radicand))
                    which = i;
            known = match_.emplace(part.op(0), which).first;
        }
        if (known->second < roots_.size()) {
            root& r = roots_[known->second];
            r.used = true;
            return GiNaC::pow(r.atom, GiNaC::ex_to<GiNaC::numeric>(part.op(1)).mul(2));
        }
    }
    // The radicand itself (d^2 written r.r): the square of its root.
    if (GiNaC::is_a<GiNaC::add>(part))
        for (root& r : roots_)
            if (GiNaC::is_a<GiNaC::add>(r.radicand) && r.radicand.nops() == part.nops() &&
                GiNaC::expand(part).is_equal(r.radicand)) {
                r.used = true;
                return GiNaC::pow(r.atom, 2);
            }
    return part.map(*this);
}

assumptions radicals_named::with_domains(const assumptions& given, std::vector<std::string>& words) const
{
    assumptions named = given;
    named.known = std::make_shared<worked_out>();
    for (const root& r : roots_) {
        if (!r.used)
            continue;
        // Declared positive (d: the centres are distinct), or a radicand proven so.
        const bool positive = r.of.range.what == domain::kind::positive ||
                              prove_sign(r.radicand, given).sign.is_positive();
        named.domains[r.atom] = domain{positive ? domain::kind::positive : domain::kind::nonnegative};
        words.push_back(fmt::format("{} {} 0", r.of.name, positive ? ">" : ">="));
    }
    return named;
}

bool radicals_named::any_used() const
{
    return std::any_of(roots_.begin(), roots_.end(), [](const root& r) { return r.used; });
}

} // namespace impact::engine::cases_detail
