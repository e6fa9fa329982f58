#include "engine/derive/declarations.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <vector>
#include <stdexcept>

namespace impact::engine {
namespace {

// The value of an expression without symbols, as a double; nothing for a symbolic one.
std::optional<double> numeric_value(const GiNaC::ex& e)
{
    const GiNaC::ex value = e.evalf();
    if (!GiNaC::is_a<GiNaC::numeric>(value) || !value.info(GiNaC::info_flags::real))
        return std::nullopt;
    return GiNaC::ex_to<GiNaC::numeric>(value).to_double();
}

// The signs a domain allows, as far as a sign proof can contradict them.
bool sign_allowed(const domain& range, const sign_set& proven)
{
    if (range.is_positive())
        return proven.positive;
    if (range.is_nonnegative())
        return proven.positive || proven.zero;
    if (range.what == domain::kind::interval && range.upper < 0)
        return proven.negative;
    if (range.what == domain::kind::interval && range.upper <= 0 && !range.upper_open)
        return proven.negative || proven.zero;
    return true;
}

} // namespace

void check_definitions(const symbol_table& symbols, const spec::derivation& source, proof_cache& run)
{
    // The definitions' signs under the inputs' domains alone: a definition is never
    // checked against the assumption its own domain makes.
    assumptions declared = declared_assumptions(symbols, run);
    declared.assumed.clear();
    declared.known = std::make_shared<worked_out>();
    for (const spec::symbol& declaration : source.symbols) {
        if (!declaration.definition)
            continue;
        const quantity& q = symbols.at(declaration.name);
        if (q.range.what == domain::kind::real || !q.definition)
            continue;
        const source_location& where = declaration.definition->where;
        if (const auto value = numeric_value(*q.definition)) {
            if (!q.range.contains(*q.definition))
                throw error(where, fmt::format("'{}' is declared {} but its definition {} is {}, outside it", q.name,
                                               q.range.to_string(), declaration.definition->value, *value));
            continue;
        }
        // A definition whose sign cannot be worked out is not contradicted.
        sign_proof proof;
        try {
            proof = prove_sign(*q.definition, declared);
        } catch (const std::exception&) {
            continue;
        }
        if (!sign_allowed(q.range, proof.sign))
            throw error(where, fmt::format("'{}' is declared {} but its definition {} is {} under the declared "
                                           "domains; correct the domain or the definition",
                                           q.name, q.range.to_string(), declaration.definition->value,
                                           proof.sign.describe()));
    }
}

namespace {

// A value of `range` for the search of a point where assumptions hold: over twelve decades
// either side of 1 (log-uniform), with 0 and the ends of an interval among them, so that
// an assumption holding only far from 1 (s = M - 30 > 0) or only at 0 is met too.
double search_draw(const domain& range, uniform_stream& stream)
{
    const double u = stream.next(), v = stream.next();
    const double magnitude = std::pow(10.0, -12 + 24 * v);
    switch (range.what) {
    case domain::kind::positive: return magnitude;
    case domain::kind::nonnegative: return u < 0.125 ? 0 : magnitude;
    case domain::kind::real: return u < 0.125 ? 0 : (u < 0.5625 ? magnitude : -magnitude);
    case domain::kind::interval: break;
    }
    if (u < 0.125 && !range.lower_open)
        return range.lower;
    if (u < 0.25 && !range.upper_open)
        return range.upper;
    return draw(range, stream);
}

} // namespace

void check_assumptions_hold_together(const symbol_table& symbols, const spec::derivation& source,
                                     const assumptions& given, const std::optional<source_location>& check)
{
    if (given.assumed.empty())
        return;
    // Each assumption in the inputs, with where its domain is written.
    struct premise {
        const assumptions::assumed_sign* sign;
        GiNaC::ex in_inputs;
        source_location written;
        std::string name, definition;
    };
    std::vector<premise> premises;
    for (const assumptions::assumed_sign& a : given.assumed) {
        for (const spec::symbol& declaration : source.symbols) {
            if (!declaration.definition || !symbols.find(declaration.name.value) ||
                !symbols.at(declaration.name).symbol.is_equal(a.symbol))
                continue;
            const quantity& q = symbols.at(declaration.name);
            premises.push_back({&a, symbols.in_inputs(*q.definition), check.value_or(declaration.domain.where), q.name,
                                declaration.definition->value});
        }
    }
    if (premises.empty())
        return;
    // The inputs the assumptions are written in, each with its domain.
    GiNaC::exset inputs;
    for (const premise& p : premises)
        for (GiNaC::const_preorder_iterator i = p.in_inputs.preorder_begin(); i != p.in_inputs.preorder_end(); ++i)
            if (GiNaC::is_a<GiNaC::symbol>(*i))
                inputs.insert(*i);
    const auto holds_at = [](const premise& p, const GiNaC::exmap& point) {
        try {
            const auto value = numeric_value(p.in_inputs.subs(point, GiNaC::subs_options::no_pattern));
            return value && p.sign->range.contains(*value);
        } catch (const std::exception&) {
            return false;  // a division by zero there
        }
    };
    // A witness: a point where all hold shows them consistent. `most`: how many of them, in
    // their order, one point has satisfied.
    constexpr int points = 2000;
    std::size_t most = 0;
    uniform_stream stream(0x5eed);
    for (int n = 0; n < points && most < premises.size(); ++n) {
        GiNaC::exmap point;
        for (const GiNaC::ex& x : inputs) {
            const auto range = given.domains.find(x);
            point[x] = search_draw(range == given.domains.end() ? domain{} : range->second, stream);
        }
        std::size_t k = 0;
        while (k < premises.size() && holds_at(premises[k], point))
            ++k;
        most = std::max(most, k);
    }
    if (most == premises.size())
        return;
    // None found: refused only when the first that failed is proven of another sign under the
    // domains and the assumptions before it (a sample that misses a narrow region proves
    // nothing, and the derivation goes on).
    const premise& refused = premises[most];
    assumptions before = given;
    before.known = std::make_shared<worked_out>();
    before.assumed.clear();
    std::vector<std::string> named;
    for (std::size_t i = 0; i < most; ++i) {
        before.assumed.push_back(*premises[i].sign);
        named.push_back(fmt::format("{} {}", premises[i].name, premises[i].sign->range.to_string()));
    }
    sign_proof proof;
    try {
        proof = prove_sign(refused.in_inputs, before);
    } catch (const std::exception&) {
        return;
    }
    if (sign_allowed(refused.sign->range, proof.sign))
        return;
    const std::string domains = check ? "this check's domains" : "the declared domains";
    throw error(refused.written,
                named.empty()
                    ? fmt::format("'{}' is declared {}, but its definition {} is {} under {}: an assumption that "
                                  "never holds proves anything; correct the domain or the definition",
                                  refused.name, refused.sign->range.to_string(), refused.definition,
                                  proof.sign.describe(), domains)
                    : fmt::format("'{}' is declared {}, but its definition {} is {} under {} and the assumptions "
                                  "before it ({}): assumptions that contradict each other prove anything; correct "
                                  "a domain or a definition",
                                  refused.name, refused.sign->range.to_string(), refused.definition,
                                  proof.sign.describe(), domains, fmt::join(named, ", ")));
}

void check_special_value(const quantity& q, const GiNaC::ex& value, const source_location& where)
{
    const auto number = numeric_value(value);
    if (number && !q.range.closure_contains(value))
        throw error(where, fmt::format("{} = {} is outside the domain of {} ({}): a special value must be one "
                                       "{} can take, or an end of its domain",
                                       q.name, *number, q.name, q.range.to_string(), q.name));
}

namespace {

// Where `value` lies against the closure of `range` under `given`: shown inside (nothing),
// proven outside (`outside`, with the sign that shows it), or neither (the sign unknown).
struct placement {
    bool outside = false;
    std::string why;
};
std::optional<placement> not_shown_within(const domain& range, const GiNaC::ex& value, const assumptions& given)
{
    // `e` >= 0 shown (nothing), proven < 0, or unknown.
    const auto short_of = [&](const GiNaC::ex& e, const std::string& as) -> std::optional<placement> {
        sign_set sign;
        try {
            sign = prove_sign(e, given).sign;
        } catch (const std::exception&) {
        }
        if (sign.is_nonnegative())
            return std::nullopt;
        return placement{!sign.positive && !sign.zero, fmt::format("{}{}", as, sign.describe())};
    };
    switch (range.what) {
    case domain::kind::real:
        return std::nullopt;
    case domain::kind::positive:
    case domain::kind::nonnegative:
        return short_of(value, "it is ");
    case domain::kind::interval:
        if (auto low = short_of(value - range.exact_lower(), fmt::format("minus {} it is ", range.lower_text)))
            return low;
        return short_of(range.exact_upper() - value, fmt::format("subtracted from {} it is ", range.upper_text));
    }
    return std::nullopt;
}

// `text` in the closure of `range`, as a condition: "u/g >= 0", "0 <= 1 - e <= 1".
std::string within_closure(const domain& range, const std::string& text)
{
    if (range.what == domain::kind::interval)
        return fmt::format("{} <= {} <= {}", range.lower_text, text, range.upper_text);
    return fmt::format("{} >= 0", text);
}

} // namespace

std::vector<std::string> check_moved_inputs(const symbol_table& symbols, const GiNaC::exmap& moved,
                                            const assumptions& given, const moved_places& places,
                                            std::string_view field)
{
    std::vector<std::string> conditions;
    for (const auto& [symbol, value] : moved) {
        const auto narrowed = given.domains.find(symbol);
        const domain* range = narrowed != given.domains.end() ? &narrowed->second : symbols.domain_of(symbol);
        if (!range || GiNaC::is_a<GiNaC::numeric>(value.evalf()))
            continue;   // no domain, or a number: check_special_value's
        const auto placed = not_shown_within(*range, value, given);
        if (!placed)
            continue;
        const std::string name = symbols.text(symbol);
        if (placed->outside)
            throw error(places.at(symbol),
                        fmt::format("{} gives {} the value {}, which lies outside its domain {} ({}): what is "
                                    "derived for {} in {} says nothing of it there",
                                    field, name, symbols.text(value), range->to_string(), placed->why, name,
                                    range->to_string()));
        conditions.push_back(within_closure(*range, symbols.text(value)));
    }
    for (const assumptions::assumed_sign& premise : given.assumed) {
        bool touched = false;
        for (const auto& [symbol, value] : moved)
            touched = touched || premise.definition.has(symbol);
        if (!touched)
            continue;
        const GiNaC::ex at = premise.definition.subs(moved, GiNaC::subs_options::no_pattern);
        const auto placed = not_shown_within(premise.range, at, given);
        if (!placed)
            continue;
        if (placed->outside)
            throw error(places.begin()->second,
                        fmt::format("{} moves the inputs to where {} = {}, declared {}, does not hold ({}: {}): "
                                    "what is derived under that assumption says nothing of it there",
                                    field, symbols.text(premise.symbol), symbols.text(at), premise.range.to_string(),
                                    symbols.text(at), placed->why));
        conditions.push_back(within_closure(premise.range, symbols.text(at)));
    }
    return conditions;
}

void check_limit_point(const quantity& q, const GiNaC::ex& point, bool to_infinity, const source_location& where)
{
    if (to_infinity) {
        if (!q.range.unbounded_above())
            throw error(where, fmt::format("{} -> infinity leaves the domain of {} ({})", q.name, q.name,
                                           q.range.to_string()));
        return;
    }
    const auto number = numeric_value(point);
    if (number && !q.range.closure_contains(point))
        throw error(where, fmt::format("{} -> {} approaches a point outside the domain of {} ({})", q.name,
                                       *number, q.name, q.range.to_string()));
}

domain narrowed_domain(const quantity& q, const spec::text& written)
{
    const domain narrowed = parse_domain(written.value, written.where);
    if (!narrowed.within(q.range))
        throw error(written.where, fmt::format("assuming {} in {} reaches outside its declared domain {}: an "
                                               "assumption may only narrow a domain",
                                               q.name, narrowed.to_string(), q.range.to_string()));
    return narrowed;
}

} // namespace impact::engine
