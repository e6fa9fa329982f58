#include "engine/declarations.h"

#include <fmt/format.h>

#include <optional>
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
            if (!q.range.contains(*value))
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

void check_special_value(const quantity& q, const GiNaC::ex& value, const source_location& where)
{
    const auto number = numeric_value(value);
    if (number && !q.range.closure_contains(*number))
        throw error(where, fmt::format("{} = {} is outside the domain of {} ({}): a special value must be one "
                                       "{} can take, or an end of its domain",
                                       q.name, *number, q.name, q.range.to_string(), q.name));
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
    if (number && !q.range.closure_contains(*number))
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
