#include "engine/symbols.h"

#include "engine/infix.h"
#include "engine/order.h"

#include <fmt/format.h>

#include <cctype>
#include <sstream>

namespace impact::engine {
namespace {

bool is_identifier(const std::string& name)
{
    if (name.empty() || !(std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '_'))
        return false;
    for (char c : name)
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_'))
            return false;
    return true;
}

// GiNaC's parser messages read "GiNaC: parse error at line 0, column 0: <what>\n[<where in
// GiNaC>]"; keep <what>, which is the part a reader of the derivation file needs.
std::string clean_parser_message(std::string message)
{
    const std::string prefix = "parse error at line ";
    if (auto at = message.find(prefix); at != std::string::npos) {
        if (auto colon = message.find(": ", at); colon != std::string::npos)
            message = message.substr(colon + 2);
    }
    if (auto bracket = message.find("\n["); bracket != std::string::npos)
        message = message.substr(0, bracket);
    const std::string unknown = "find_or_insert_symbol: symbol \"";
    if (message.rfind(unknown, 0) == 0) {
        const auto end = message.find('"', unknown.size());
        return fmt::format("undeclared symbol '{}' (declare it in a [[symbol]] table)",
                           message.substr(unknown.size(), end - unknown.size()));
    }
    return message;
}

} // namespace

std::string ginac_text(const GiNaC::ex& e)
{
    std::ostringstream out;
    out << e;
    return out.str();
}

void rethrow_at(const source_location& where, const std::string& what)
{
    try {
        throw;
    } catch (const error&) {
        throw;
    } catch (const GiNaC::pole_error&) {
        throw error(where, fmt::format("{}: division by zero", what));
    } catch (const std::exception& e) {
        throw error(where, fmt::format("{}: {}", what, clean_parser_message(e.what())));
    }
}

const quantity& symbol_table::declare(const spec::symbol& declaration)
{
    const std::string& name = declaration.name.value;
    if (!is_identifier(name))
        throw error(declaration.name.where,
                    fmt::format("symbol name '{}' is not an identifier (letters, digits and _)", name));
    if (const quantity* earlier = find(name))
        throw error(declaration.name.where,
                    fmt::format("symbol '{}' is declared twice (first at line {})", name, earlier->where.line));

    quantity q;
    q.name = name;
    q.range = parse_domain(declaration.domain.value, declaration.domain.where);
    q.latex = declaration.latex.value;
    q.meaning = declaration.meaning.value;
    q.where = declaration.name.where;
    if (q.range.is_positive())
        q.symbol = GiNaC::possymbol(name, q.latex);
    else
        q.symbol = GiNaC::realsymbol(name, q.latex);
    if (declaration.definition)
        q.definition = parse(*declaration.definition);
    table_[name] = q.symbol;
    quantities_.push_back(std::move(q));
    return quantities_.back();
}

const quantity& symbol_table::adopt(const quantity& other)
{
    if (const quantity* mine = find(other.name))
        return *mine;
    quantity q = other;
    if (q.range.is_positive())
        q.symbol = GiNaC::possymbol(q.name, q.latex);
    else
        q.symbol = GiNaC::realsymbol(q.name, q.latex);
    table_[q.name] = q.symbol;
    quantities_.push_back(std::move(q));
    return quantities_.back();
}

const quantity* symbol_table::find(const std::string& name) const
{
    for (const quantity& q : quantities_)
        if (q.name == name)
            return &q;
    return nullptr;
}

const quantity& symbol_table::at(const spec::text& name) const
{
    if (const quantity* q = find(name.value))
        return *q;
    throw error(name.where, fmt::format("undeclared symbol '{}' (declare it in a [[symbol]] table)", name.value));
}

GiNaC::ex symbol_table::parse(const spec::text& text) const
{
    if (text.value.find_first_not_of(" \t\r\n") == std::string::npos)
        throw error(text.where, "empty expression");
    try {
        GiNaC::parser reader(table_, /*strict=*/true);
        return reader(text.value);
    } catch (const GiNaC::pole_error&) {
        // GiNaC evaluates as it reads: x/(z - z) fails while parsing, though it parses.
        throw error(text.where, fmt::format("expression \"{}\": division by zero", text.value));
    } catch (...) {
        rethrow_at(text.where, fmt::format("expression \"{}\" does not parse", text.value));
    }
}

GiNaC::ex symbol_table::parse_equation(const spec::text& text) const
{
    // Exactly one '=' separates the sides; '==' or '<=' are not equations.
    const auto equals = text.value.find('=');
    if (equals == std::string::npos || text.value.find('=', equals + 1) != std::string::npos ||
        (equals > 0 && std::string("<>!").find(text.value[equals - 1]) != std::string::npos))
        throw error(text.where, fmt::format("equation \"{}\" must read 'lhs = rhs' with a single '='", text.value));
    // Each side is trimmed and located in the file: one column past the opening quote.
    auto side = [&](std::size_t begin, std::size_t end) {
        const std::string raw = text.value.substr(begin, end - begin);
        const auto first = raw.find_first_not_of(" \t");
        const auto last = raw.find_last_not_of(" \t");
        spec::text part{first == std::string::npos ? std::string() : raw.substr(first, last - first + 1), text.where};
        if (part.where.column > 0)
            part.where.column += static_cast<std::uint32_t>(1 + begin + (first == std::string::npos ? 0 : first));
        return part;
    };
    return parse(side(0, equals)) == parse(side(equals + 1, text.value.size()));
}

std::string symbol_table::text(const GiNaC::ex& e) const
{
    return ginac_syntax(e, declaration_order(*this));
}

std::string to_string(relation r)
{
    switch (r) {
    case relation::equal: return "=";
    case relation::less_equal: return "<=";
    case relation::less: return "<";
    case relation::greater_equal: return ">=";
    case relation::greater: return ">";
    }
    return "?";
}

claim_sides symbol_table::parse_claim(const spec::text& text) const
{
    static const std::pair<const char*, relation> operators[] = {
        {"<=", relation::less_equal}, {">=", relation::greater_equal}, {"<", relation::less}, {">", relation::greater}};
    for (const auto& [spelling, op] : operators) {
        const auto at = text.value.find(spelling);
        if (at == std::string::npos)
            continue;
        const std::string width(std::string(spelling).size(), ' ');
        // Read as an equation with the operator written as '=' (same columns).
        spec::text as_equation = text;
        as_equation.value.replace(at, width.size(), width.size() == 2 ? " =" : "=");
        const GiNaC::ex sides = parse_equation(as_equation);
        return {op, sides.lhs(), sides.rhs()};
    }
    const GiNaC::ex sides = parse_equation(text);
    return {relation::equal, sides.lhs(), sides.rhs()};
}

GiNaC::exmap symbol_table::abbreviations() const
{
    GiNaC::exmap map;
    for (const quantity& q : quantities_)
        if (q.definition)
            map[q.symbol] = *q.definition;
    return map;
}

const domain* symbol_table::domain_of(const GiNaC::ex& symbol) const
{
    for (const quantity& q : quantities_)
        if (q.symbol.is_equal(symbol))
            return &q.range;
    return nullptr;
}

} // namespace impact::engine
