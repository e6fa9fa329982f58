#include "engine/prove/seen_at_points.h"

#include "engine/algebra/polynomial.h"
#include "engine/prove/prove_internal.h"

#include <algorithm>
#include <random>
#include <string>
#include <utility>

namespace impact::engine {
namespace {

// Values of a domain to draw from: simple numbers of both sizes, and of both signs where
// it holds them; an interval's ends and inner points.
std::vector<GiNaC::numeric> values_to_draw(const domain& range)
{
    if (range.what == domain::kind::interval)
        return simple_values(range);
    std::vector<GiNaC::numeric> values = {1, 2, GiNaC::numeric(1, 2), 3, GiNaC::numeric(1, 3), GiNaC::numeric(5, 2),
                                          GiNaC::numeric(2, 5), 7, GiNaC::numeric(1, 7), 10};
    if (range.what == domain::kind::real)
        for (std::size_t i = 0, n = values.size(); i < n; ++i)
            values.push_back(-values[i]);
    if (range.what != domain::kind::positive)
        values.push_back(0);
    return values;
}

// Whether `value`, a number or a rational multiple of the square root of one (an
// abbreviation's definition at a point), lies in `range`, decided exactly; such a root in
// an interval is not decided, and does not count as inside.
bool in_range(const GiNaC::ex& value, const domain& range)
{
    if (GiNaC::is_a<GiNaC::numeric>(value))
        return GiNaC::ex_to<GiNaC::numeric>(value).is_real() && range.contains(value);
    const auto root_of = [](const GiNaC::ex& x) {
        return GiNaC::is_a<GiNaC::power>(x) && x.op(1).is_equal(GiNaC::numeric(1, 2)) &&
               GiNaC::is_a<GiNaC::numeric>(x.op(0)) && GiNaC::ex_to<GiNaC::numeric>(x.op(0)).is_rational() &&
               GiNaC::ex_to<GiNaC::numeric>(x.op(0)).is_positive();
    };
    int sign = 0;
    if (root_of(value))
        sign = 1;
    else if (GiNaC::is_a<GiNaC::mul>(value) && value.nops() == 2 && root_of(value.op(0)) &&
             GiNaC::is_a<GiNaC::numeric>(value.op(1)) && GiNaC::ex_to<GiNaC::numeric>(value.op(1)).is_rational())
        sign = GiNaC::ex_to<GiNaC::numeric>(value.op(1)).csgn();
    else
        return false;
    switch (range.what) {
    case domain::kind::real: return true;
    case domain::kind::nonnegative: return sign >= 0;
    case domain::kind::positive: return sign > 0;
    case domain::kind::interval: return false;
    }
    return false;
}

} // namespace

std::vector<GiNaC::exmap> points_of_domains(const GiNaC::ex& e, const assumptions& given, int count)
{
    GiNaC::exset in_e;
    gather_symbols(e, in_e);
    std::vector<std::pair<std::string, GiNaC::ex>> named;
    for (const GiNaC::ex& s : in_e)
        named.emplace_back(given.text(s), s);
    std::sort(named.begin(), named.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<std::vector<GiNaC::numeric>> values;
    for (const auto& [name, s] : named) {
        const auto range = given.domains.find(s);
        if (range == given.domains.end())
            return {};
        values.push_back(values_to_draw(range->second));
        if (values.back().empty())
            return {};
    }
    // The abbreviations defined in e's symbols bound the points; one defined in others
    // alone bounds what e does not hold. (An abbreviation's own symbol in e, which a proof
    // with its roots named holds, is a symbol of its domain like the others.)
    std::vector<const assumptions::assumed_sign*> bounding;
    for (const assumptions::assumed_sign& a : given.assumed) {
        GiNaC::exset in_definition;
        gather_symbols(a.definition, in_definition);
        const auto shared = std::count_if(in_definition.begin(), in_definition.end(),
                                          [&](const GiNaC::ex& s) { return in_e.count(s) != 0; });
        if (shared != 0 && shared != static_cast<std::ptrdiff_t>(in_definition.size()))
            return {};
        if (shared != 0)
            bounding.push_back(&a);
    }
    std::minstd_rand draw(1);
    std::vector<GiNaC::exmap> points;
    for (int k = 0; k < count; ++k) {
        GiNaC::exmap at;
        for (std::size_t i = 0; i < named.size(); ++i)
            at[named[i].second] = values[i][draw() % values[i].size()];
        if (std::all_of(bounding.begin(), bounding.end(), [&](const assumptions::assumed_sign* a) {
                return in_range(a->definition.subs(at, GiNaC::subs_options::no_pattern), a->range);
            }))
            points.push_back(std::move(at));
    }
    return points;
}

std::optional<GiNaC::numeric> exact_value(const GiNaC::ex& e, const GiNaC::exmap& at)
{
    try {
        const GiNaC::ex value = e.subs(at, GiNaC::subs_options::no_pattern);
        if (GiNaC::is_a<GiNaC::numeric>(value) && GiNaC::ex_to<GiNaC::numeric>(value).is_rational())
            return GiNaC::ex_to<GiNaC::numeric>(value);
    } catch (const std::exception&) {
        // a pole: 1/0
    }
    return std::nullopt;
}

bool seen_of_both_signs(const GiNaC::ex& e, const assumptions& given)
{
    constexpr int points = 24;
    if (!e.info(GiNaC::info_flags::rational_polynomial))
        return false;
    bool positive = false, negative = false;
    for (const GiNaC::exmap& at : points_of_domains(e, given, points)) {
        if (const auto v = exact_value(e, at)) {
            positive = positive || v->is_positive();
            negative = negative || v->is_negative();
            if (positive && negative)
                return true;
        }
    }
    return false;
}

bool seen_against(const GiNaC::ex& e, bool positive, const assumptions& given)
{
    constexpr int points = 24;
    if (!e.info(GiNaC::info_flags::rational_function))
        return false;
    for (const GiNaC::exmap& at : points_of_domains(e, given, points))
        if (const auto v = exact_value(e, at); v && (v->is_negative() || (positive && v->is_zero())))
            return true;
    return false;
}

} // namespace impact::engine
