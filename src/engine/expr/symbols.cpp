#include "engine/expr/symbols.h"

#include "engine/expr/infix.h"
#include "engine/expr/order.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <utility>

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

// GiNaC's parser recurses once per bracket and per sign in front of an operand: an
// expression nested thousands deep would overflow the stack, so it is refused first.
void refuse_deep_nesting(const source_location& where, const std::string& text)
{
    constexpr int max_depth = 200;
    int brackets = 0;
    int signs = 0;
    for (const char c : text) {
        if (c == '(' || c == '[' || c == '{')
            ++brackets;
        else if (c == ')' || c == ']' || c == '}')
            brackets = std::max(0, brackets - 1);
        if (c == '+' || c == '-')
            ++signs;
        else if (c != ' ' && c != '\t' && c != '(')
            signs = 0;
        if (brackets + signs > max_depth)
            throw error(where, fmt::format("expression \"{}...\" nests brackets or signs more than {} deep",
                                           text.substr(0, 20), max_depth));
    }
}

// Where the token of an expression's text that starts at `i` ends: a name (letters, digits
// and _), a number (digits, and a fraction's digits after a point), or one character.
std::size_t token_end(const std::string& text, std::size_t i)
{
    const auto digit = [&](std::size_t k) { return k < text.size() && std::isdigit(static_cast<unsigned char>(text[k])); };
    const auto in_name = [&](std::size_t k) {
        return k < text.size() && (std::isalnum(static_cast<unsigned char>(text[k])) || text[k] == '_');
    };
    std::size_t end = i + 1;
    if (std::isalpha(static_cast<unsigned char>(text[i])) || text[i] == '_') {
        while (in_name(end))
            ++end;
    } else if (digit(i)) {
        while (digit(end))
            ++end;
        if (end < text.size() && text[end] == '.' && digit(end + 1))
            for (++end; digit(end);)
                ++end;
    }
    return end;
}

// GiNaC computes with numbers as it reads them: 2^(10^9) or factorial(10^7) would take
// the machine's time and memory before any check ran. So an expression is first read
// with each number replaced by a placeholder symbol, where nothing is computed, and the
// size of what reading it for real would compute is bounded (the bounds are far beyond
// any physics: powers up to the 1000th, numbers up to some 30 000 digits).
class number_bounds {
public:
    static constexpr double max_bits = 1e5;
    static constexpr double max_exponent = 1000;

    number_bounds(const GiNaC::symtab& declared, const std::string& text) : declared_(declared)
    {
        for (std::size_t i = 0; i < text.size();) {
            const std::size_t end = token_end(text, i);
            if (std::isdigit(static_cast<unsigned char>(text[i]))) {
                const GiNaC::symbol placeholder("impact_number_" + std::to_string(literals_.size()) + "_");
                placeholders_.push_back(placeholder);
                literals_.emplace(placeholder, text.substr(i, end - i));
                shape_ += " " + placeholder.get_name() + " ";
                i = end;
                continue;
            }
            shape_ += text.substr(i, end - i);
            i = end;
        }
    }

    /// True when the text writes no number: its shape is then the text itself.
    bool literal_free() const { return literals_.empty(); }

    // Throws `error` at `where` when the expression would compute too large a number.
    void check(const source_location& where, const std::string& text) const
    {
        GiNaC::symtab table = declared_;
        for (const GiNaC::symbol& placeholder : placeholders_)
            table[placeholder.get_name()] = placeholder;
        GiNaC::ex shape;
        try {
            shape = GiNaC::parser(table, /*strict=*/true)(shape_);
        } catch (...) {
            return;  // reading it for real reports what is wrong
        }
        size(shape, where, text);
    }

    // The same for a text without numbers, already read (its shape): a constant such as
    // Pi may still be raised too high.
    void check_read(const GiNaC::ex& shape, const source_location& where, const std::string& text) const
    {
        size(shape, where, text);
    }

private:
    // Bits of the exact number a subexpression of numbers only comes to; nullopt when it
    // holds a declared quantity (then nothing is computed until a substitution).
    std::optional<double> size(const GiNaC::ex& e, const source_location& where, const std::string& text) const
    {
        if (GiNaC::is_a<GiNaC::symbol>(e)) {
            const auto literal = literals_.find(e);
            if (literal == literals_.end())
                return std::nullopt;
            const std::string& digits = literal->second;
            if (digits.find('.') != std::string::npos)
                return 64.0;  // a float: its size does not grow
            return digits.size() <= 15 ? std::log2(std::max(1.0, std::stod(digits))) : 3.33 * digits.size();
        }
        if (GiNaC::is_a<GiNaC::numeric>(e)) {
            const GiNaC::numeric n = GiNaC::ex_to<GiNaC::numeric>(e);
            return n.is_rational() ? double(n.numer().int_length() + n.denom().int_length()) : 64.0;
        }
        if (GiNaC::is_a<GiNaC::constant>(e))
            return 64.0;
        if (GiNaC::is_a<GiNaC::power>(e)) {
            const auto base = size(e.op(0), where, text);
            const auto exponent = size(e.op(1), where, text);
            if (!exponent)
                return std::nullopt;
            const double power = *exponent > 64 ? HUGE_VAL : std::abs(value(e.op(1)));
            if (!base && power > max_exponent)
                throw error(where, fmt::format("expression \"{}\" raises to a power above {}", text, max_exponent));
            if (!base)
                return std::nullopt;
            return bounded(*base * std::max(1.0, power), where, text);
        }
        if (GiNaC::is_a<GiNaC::function>(e)) {
            // Integer functions GiNaC evaluates exactly: factorial(n) has about n log2(n) bits.
            static const std::set<std::string> exact = {"factorial", "binomial", "tgamma", "lgamma", "zeta",
                                                        "psi", "beta", "doublefactorial", "bernoulli"};
            bool pure = true;
            for (const GiNaC::ex& argument : e) {
                const auto bits = size(argument, where, text);
                pure = pure && bits;
                if (bits && exact.count(GiNaC::ex_to<GiNaC::function>(e).get_name()) &&
                    (*bits > 64 || std::abs(value(argument)) > max_exponent))
                    throw error(where, fmt::format("expression \"{}\" takes {} of a number above {}", text,
                                                   GiNaC::ex_to<GiNaC::function>(e).get_name(), max_exponent));
            }
            return pure ? std::optional<double>(64.0) : std::nullopt;
        }
        // Sums and products: the sizes add up (a sum of n terms gains log2(n) bits more).
        double bits = std::log2(double(e.nops()) + 1);
        bool pure = GiNaC::is_a<GiNaC::add>(e) || GiNaC::is_a<GiNaC::mul>(e);
        for (const GiNaC::ex& operand : e) {
            const auto operand_bits = size(operand, where, text);
            pure = pure && operand_bits;
            bits += operand_bits.value_or(0);
        }
        bounded(bits, where, text);
        return pure ? std::optional<double>(bits) : std::nullopt;
    }

    double bounded(double bits, const source_location& where, const std::string& text) const
    {
        if (bits > max_bits)
            throw error(where, fmt::format("expression \"{}\" computes a number of more than 30 000 digits", text));
        return bits;
    }

    // The value of a small subexpression of numbers only.
    double value(const GiNaC::ex& e) const
    {
        try {
            GiNaC::exmap numbers;
            for (const auto& [placeholder, literal] : literals_)
                if (e.has(placeholder))
                    numbers[placeholder] = GiNaC::numeric(literal.c_str());
            const GiNaC::ex v = GiNaC::evalf(e.subs(numbers));
            if (GiNaC::is_a<GiNaC::numeric>(v) && GiNaC::ex_to<GiNaC::numeric>(v).is_real())
                return GiNaC::ex_to<GiNaC::numeric>(v).to_double();
        } catch (const std::exception&) {
            // 1/0 and the like: reading it for real reports it
        }
        return 0;
    }

    const GiNaC::symtab& declared_;
    std::vector<GiNaC::symbol> placeholders_;
    std::map<GiNaC::ex, std::string, GiNaC::ex_is_less> literals_;
    std::string shape_;
};

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
    // GiNaC's parser reads these as its constants whatever the table holds: a symbol so
    // named would silently be i, pi, Euler's or Catalan's constant in every expression.
    for (const auto& [constant, what] : {std::pair<const char*, const char*>{"I", "the imaginary unit"},
                                         {"Pi", "the constant pi"},
                                         {"Euler", "Euler's constant"},
                                         {"Catalan", "Catalan's constant"}})
        if (name == constant)
            throw error(declaration.name.where,
                        fmt::format("a symbol cannot be named '{}': in expressions {} is {}; name it otherwise "
                                    "(e.g. {}_s) and give it latex = \"{}\" to typeset it as {}",
                                    name, name, what, name, name, name));

    quantity q;
    q.name = name;
    q.range = parse_domain(declaration.domain.value, declaration.domain.where);
    q.latex = declaration.latex.value;
    q.meaning = declaration.meaning.value;
    q.where = declaration.name.where;
    if (declaration.dimension) {
        q.dim = dimension_words_.parse(declaration.dimension->value, declaration.dimension->where);
        q.dim_declared = true;
    }
    if (q.range.is_positive())
        q.symbol = GiNaC::possymbol(name, q.latex);
    else
        q.symbol = GiNaC::realsymbol(name, q.latex);
    if (declaration.definition) {
        // Read before its own name is in the table, a definition that uses it would be
        // refused as using an undeclared symbol: say what is wrong instead.
        const std::string& text = declaration.definition->value;
        for (std::size_t i = 0; i < text.size();) {
            const std::size_t end = token_end(text, i);
            if (text.compare(i, end - i, name) == 0)
                throw error(declaration.definition->where,
                            fmt::format("the definition of '{}' uses '{}' itself: a definition is an abbreviation, "
                                        "replaced by its expression wherever the symbol is used; write it in other "
                                        "symbols, or state the relation as a [[given]] equation",
                                        name, name));
            i = end;
        }
        q.definition = parse(*declaration.definition);
        q.written = written_form::read(declaration.definition->value,
                                       [this](const std::string& piece) { return parse({piece, {}}); });
    }
    table_[name] = q.symbol;
    quantities_.push_back(std::move(q));
    order_.reset();
    reader_.reset();
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
    order_.reset();
    reader_.reset();
    return quantities_.back();
}

dimension_map symbol_table::dimensions() const
{
    dimension_map map;
    for (const quantity& q : quantities_)
        if (q.dim)
            map.emplace(q.symbol, *q.dim);
    return map;
}

void symbol_table::infer_dimension(const GiNaC::ex& symbol, const dimension& d)
{
    for (quantity& q : quantities_)
        if (q.symbol.is_equal(symbol))
            q.dim = d;
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

namespace {

// `text` with each decimal number written as the fraction it means exactly: 0.5 as (5/10),
// 2.25 as (225/100). A physicist's 0.5 is one half, and GiNaC would read it as a
// floating-point number, which no identity is proven of and no LaTeX prints exactly.
std::string exact_decimals(const std::string& text)
{
    std::string out;
    for (std::size_t i = 0; i < text.size();) {
        const std::size_t end = token_end(text, i);
        const std::string token = text.substr(i, end - i);
        const auto point = token.find('.');
        if (std::isdigit(static_cast<unsigned char>(token[0])) && point != std::string::npos) {
            const std::size_t places = token.size() - point - 1;
            std::string digits = token.substr(0, point) + token.substr(point + 1);
            digits.erase(0, std::min(digits.find_first_not_of('0'), digits.size() - 1));
            out += "(" + digits + "/1" + std::string(places, '0') + ")";
            i = end;
            continue;
        }
        out += text.substr(i, end - i);
        i = end;
    }
    return out;
}

} // namespace

GiNaC::ex symbol_table::parse(const spec::text& text) const
{
    const auto known = parsed_.find(text.value);
    if (known != parsed_.end())
        return known->second;
    if (text.value.find_first_not_of(" \t\r\n") == std::string::npos)
        throw error(text.where, "empty expression");
    // A character beyond ASCII (v², ε, ·, −): the parser would name half of it.
    if (const auto beyond = std::find_if(text.value.begin(), text.value.end(),
                                         [](char c) { return static_cast<unsigned char>(c) >= 0x80; });
        beyond != text.value.end()) {
        std::size_t end = static_cast<std::size_t>(beyond - text.value.begin()) + 1;
        while (end < text.value.size() && (static_cast<unsigned char>(text.value[end]) & 0xC0) == 0x80)
            ++end;   // the rest of its UTF-8 bytes
        const std::size_t at = static_cast<std::size_t>(beyond - text.value.begin());
        throw error(text.where, fmt::format("expression \"{}\" holds '{}', which expressions do not use: write "
                                            "names in letters, digits and _ (eps, not ε; its latex sets how it is "
                                            "typeset), powers with ^ (v^2), products with *, minus as -",
                                            text.value, text.value.substr(at, end - at)));
    }
    refuse_deep_nesting(text.where, text.value);
    const std::string exact = exact_decimals(text.value);
    const number_bounds bounds(table_, exact);
    if (!bounds.literal_free())
        bounds.check(text.where, text.value);
    try {
        if (!reader_)
            reader_ = std::make_shared<GiNaC::parser>(table_, /*strict=*/true);
        const GiNaC::ex e = (*reader_)(exact);
        if (bounds.literal_free())
            bounds.check_read(e, text.where, text.value);
        parsed_.emplace(text.value, e);
        return e;
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
    return ginac_syntax(e, order());
}

const term_order& symbol_table::order() const
{
    if (!order_) {
        std::vector<GiNaC::ex> ranked;
        for (const quantity& q : quantities_)
            ranked.push_back(q.symbol);
        order_ = std::make_shared<const term_order>(std::move(ranked));
    }
    return *order_;
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

GiNaC::ex symbol_table::in_inputs(const GiNaC::ex& e) const
{
    const GiNaC::exmap map = abbreviations();
    GiNaC::ex now = e;
    for (int depth = 0; depth < 8; ++depth) {
        const GiNaC::ex next = now.subs(map, GiNaC::subs_options::no_pattern);
        if (next.is_equal(now))
            break;
        now = next;
    }
    return now;
}

const domain* symbol_table::domain_of(const GiNaC::ex& symbol) const
{
    for (const quantity& q : quantities_)
        if (q.symbol.is_equal(symbol))
            return &q.range;
    return nullptr;
}

} // namespace impact::engine
