#include "engine/expr/dimensional.h"

#include <fmt/format.h>

namespace impact::engine {
namespace {

// "a momentum (mass*length/time)", or the dimension's text when it has no familiar name.
std::string named(const dimension& d)
{
    if (d.is_pure_number())
        return "a pure number";
    const auto name = d.familiar_name();
    return name ? fmt::format("{} ({})", *name, d.to_string()) : d.to_string();
}

// Expressions in messages in the symbols' declaration order, the same on every run.
expression_text written_by(const symbol_table& symbols)
{
    return [&symbols](const GiNaC::ex& e) { return symbols.text(e); };
}

} // namespace

void add_dimensions(symbol_table& symbols, const std::vector<spec::dimension>& added)
{
    dimension_names& words = symbols.dimension_words();
    for (const spec::dimension& d : added) {
        if (d.as)
            words.add(d.name.value, words.parse(d.as->value, d.as->where), d.name.where);
        else
            words.add_base(d.name.value, d.name.where);
    }
}

void infer_definitions(symbol_table& symbols, const spec::derivation& source)
{
    // A definition may use abbreviations declared after it: repeat until nothing changes.
    for (bool changed = true; changed;) {
        changed = false;
        for (const spec::symbol& declaration : source.symbols) {
            if (!declaration.definition)
                continue;
            const quantity& q = symbols.at(declaration.name);
            // Zero is a value of every dimension.
            if (!q.definition || q.definition->is_zero())
                continue;
            const auto found = dimension_of(*q.definition, symbols.dimensions(), declaration.definition->where,
                                              written_by(symbols));
            if (!found)
                continue;
            if (q.dim_declared && *found != *q.dim)
                throw error(declaration.definition->where,
                            fmt::format("'{}' is declared {} but its definition {} is {}", q.name, named(*q.dim),
                                        declaration.definition->value, named(*found)));
            if (!q.dim) {
                symbols.infer_dimension(q.symbol, *found);
                changed = true;
            }
        }
    }
}

void check_relation(const symbol_table& symbols, const GiNaC::ex& relation, const source_location& where)
{
    dimension_of_relation(relation, symbols.dimensions(), where, written_by(symbols));
}

std::optional<dimension> check_expression(const symbol_table& symbols, const GiNaC::ex& e,
                                          const source_location& where)
{
    return dimension_of(e, symbols.dimensions(), where, written_by(symbols));
}

void check_value(symbol_table& symbols, const GiNaC::ex& symbol, const GiNaC::ex& value,
                 const source_location& where, const char* what)
{
    if (value.is_zero())
        return;   // zero is a value of every dimension
    const auto found = dimension_of(value, symbols.dimensions(), where, written_by(symbols));
    if (!found)
        return;
    for (const quantity& q : symbols.all()) {
        if (!q.symbol.is_equal(symbol))
            continue;
        if (q.dim && *q.dim != *found)
            throw error(where, fmt::format("'{}' is {} but {}, {}, is {}", q.name, named(*q.dim), what,
                                           symbols.text(value), named(*found)));
        if (!q.dim)
            symbols.infer_dimension(symbol, *found);
        return;
    }
}

std::optional<finding> printed_dimension_finding(const symbol_table& symbols, const GiNaC::ex& printed,
                                                 const GiNaC::ex& derived)
{
    const dimension_map known = symbols.dimensions();
    std::optional<dimension> of_printed;
    try {
        of_printed = dimension_of(printed, known, {}, written_by(symbols));
    } catch (const dimension_clash& e) {
        const bool sum = e.how == dimension_clash::kind::adds;
        return finding()
            .say(sum ? "dimensionally inconsistent: it adds " : "dimensionally inconsistent: it sets ")
            .math(e.first)
            .say(", ")
            .of_dimension(e.first_dim)
            .say(sum ? ", to " : ", against ")
            .math(e.second)
            .say(", ")
            .of_dimension(e.second_dim)
            .say(sum ? ": the terms of a sum share one dimension" : ": both sides share one dimension");
    } catch (const error& e) {
        return finding::words(fmt::format("dimensionally inconsistent: it {}", e.message()));
    }
    std::optional<dimension> of_derived;
    try {
        of_derived = dimension_of(derived, known, {}, written_by(symbols));
    } catch (const error&) {
        return std::nullopt;   // the derived side is the engine's; its own check reports it
    }
    if (GiNaC::is_a<GiNaC::relational>(printed) && GiNaC::is_a<GiNaC::relational>(derived))
        return std::nullopt;   // a relation's sides were compared above
    if (!of_printed || !of_derived || *of_printed == *of_derived)
        return std::nullopt;
    return finding()
        .say("dimensionally inconsistent: ")
        .of_dimension(*of_printed)
        .say(" where ")
        .of_dimension(*of_derived)
        .say(" belongs");
}

std::vector<std::string> symbols_without_dimension(const symbol_table& symbols)
{
    std::vector<std::string> names;
    for (const quantity& q : symbols.all())
        if (!q.dim)
            names.push_back(q.name);
    return names;
}

} // namespace impact::engine
