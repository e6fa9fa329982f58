#include "engine/dimension/dimension.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <sstream>
#include <stdexcept>
#include <tuple>

namespace impact::engine {
namespace {

// The order a physicist writes the bases in; others follow by name.
int base_rank(const std::string& name)
{
    if (name == "mass")
        return 0;
    if (name == "length")
        return 1;
    if (name == "time")
        return 2;
    return 3;
}

std::string exponent_text(const GiNaC::numeric& e)
{
    std::ostringstream out;
    out << e;
    const std::string text = out.str();
    return text.find('/') == std::string::npos ? text : "(" + text + ")";
}

std::string powers(const std::vector<std::pair<std::string, GiNaC::numeric>>& bases, const char* times)
{
    std::string out;
    for (const auto& [name, e] : bases) {
        if (!out.empty())
            out += times;
        out += name;
        if (e != 1)
            out += "^" + exponent_text(e);
    }
    return out;
}

struct familiar {
    const char* name;
    const char* text;
};

// Combinations a physicist names, with the article the name takes in a sentence.
constexpr familiar familiar_dimensions[] = {
    {"a velocity", "length/time"},
    {"an acceleration", "length/time^2"},
    {"a momentum", "mass*length/time"},
    {"an energy", "mass*length^2/time^2"},
    {"a force", "mass*length/time^2"},
    {"an angular velocity", "1/time"},
    {"a moment of inertia", "mass*length^2"},
    {"an angular momentum", "mass*length^2/time"},
    {"an area", "length^2"},
};

// Names a derivation file may give a dimension by, beyond the three bases.
constexpr std::pair<const char*, const char*> named_combinations[] = {
    {"velocity", "length/time"},
    {"acceleration", "length/time^2"},
    {"momentum", "mass*length/time"},
    {"impulse", "mass*length/time"},
    {"energy", "mass*length^2/time^2"},
    {"force", "mass*length/time^2"},
    {"angular_velocity", "1/time"},
    {"moment_of_inertia", "mass*length^2"},
    {"angular_momentum", "mass*length^2/time"},
    {"area", "length^2"},
};

} // namespace

dimension dimension::base(const std::string& name)
{
    dimension d;
    d.exponents_[name] = 1;
    return d;
}

dimension dimension::operator*(const dimension& other) const
{
    dimension d = *this;
    for (const auto& [name, e] : other.exponents_) {
        const GiNaC::numeric sum = d.exponents_[name] + e;
        if (sum.is_zero())
            d.exponents_.erase(name);
        else
            d.exponents_[name] = sum;
    }
    return d;
}

dimension dimension::operator/(const dimension& other) const
{
    return *this * other.power(-1);
}

dimension dimension::power(const GiNaC::numeric& exponent) const
{
    dimension d;
    if (exponent.is_zero())
        return d;
    for (const auto& [name, e] : exponents_)
        d.exponents_[name] = e * exponent;
    return d;
}

std::string dimension::to_string() const
{
    std::vector<std::pair<std::string, GiNaC::numeric>> up, down;
    for (const auto& [name, e] : exponents_)
        (e.is_positive() ? up : down).emplace_back(name, e.is_positive() ? e : -e);
    auto by_rank = [](const auto& a, const auto& b) {
        return std::make_pair(base_rank(a.first), a.first) < std::make_pair(base_rank(b.first), b.first);
    };
    std::sort(up.begin(), up.end(), by_rank);
    std::sort(down.begin(), down.end(), by_rank);
    std::string text = up.empty() ? "1" : powers(up, "*");
    if (!down.empty())
        text += "/" + powers(down, "/");
    return text;
}

std::optional<std::string> dimension::familiar_name() const
{
    // The familiar dimensions, read once (constant data, shared by every run).
    static const std::vector<std::pair<dimension, const char*>> familiars = [] {
        const dimension_names names;
        std::vector<std::pair<dimension, const char*>> read;
        for (const familiar& f : familiar_dimensions)
            read.emplace_back(names.parse(f.text, {}), f.name);
        return read;
    }();
    for (const auto& [d, name] : familiars)
        if (d == *this)
            return name;
    return std::nullopt;
}

std::string dimension::describe() const
{
    if (is_pure_number())
        return "a pure number";
    const auto name = familiar_name();
    return name ? fmt::format("{} ({})", to_string(), *name) : to_string();
}

std::vector<std::pair<std::string, GiNaC::numeric>> dimension::si_factors() const
{
    std::vector<std::pair<std::string, GiNaC::numeric>> bases(exponents_.begin(), exponents_.end());
    std::sort(bases.begin(), bases.end(), [](const auto& a, const auto& b) {
        return std::make_pair(base_rank(a.first), a.first) < std::make_pair(base_rank(b.first), b.first);
    });
    for (auto& [name, e] : bases)
        name = name == "mass" ? "kg" : name == "length" ? "m" : name == "time" ? "s" : name;
    return bases;
}

std::string dimension::si_unit() const
{
    std::string out;
    for (const auto& [unit, e] : si_factors()) {
        if (!out.empty())
            out += " ";
        out += unit;
        if (e != 1)
            out += "^" + exponent_text(e);
    }
    return out.empty() ? "1" : out;
}

dimension_names::dimension_names()
{
    for (const char* base : {"mass", "length", "time"})
        names_[base] = dimension::base(base);
    for (const auto& [name, text] : named_combinations)
        names_[name] = parse(text, {});
}

void dimension_names::add(const std::string& name, const dimension& d, const source_location& where)
{
    if (names_.count(name))
        throw error(where, fmt::format("dimension '{}' is already known", name));
    names_[name] = d;
}

void dimension_names::add_base(const std::string& name, const source_location& where)
{
    add(name, dimension::base(name), where);
}

dimension dimension_names::parse(const std::string& text, const source_location& where) const
{
    // factor (('*' | '/') factor)*, factor = name | 1 , optionally ^ integer or ^(p/q).
    auto bad = [&](const std::string& why) -> dimension {
        throw error(where, fmt::format("dimension \"{}\" {}; write a product of powers of mass, length, time and "
                                       "named dimensions, such as mass*length^2/time^2, or 1 for a pure number",
                                       text, why));
    };
    dimension result;
    std::size_t i = 0;
    auto skip = [&] {
        while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i])))
            ++i;
    };
    bool divide = false;
    for (;;) {
        skip();
        const std::size_t start = i;
        while (i < text.size() && (std::isalnum(static_cast<unsigned char>(text[i])) || text[i] == '_'))
            ++i;
        const std::string word = text.substr(start, i - start);
        if (word.empty())
            return bad("is not understood");
        dimension factor;
        if (word != "1") {
            const auto found = names_.find(word);
            if (found == names_.end())
                return bad(fmt::format("names '{}', which is not a dimension", word));
            factor = found->second;
        }
        skip();
        if (i < text.size() && text[i] == '^') {
            ++i;
            skip();
            const bool bracket = i < text.size() && text[i] == '(';
            if (bracket)
                ++i;
            const std::size_t number_start = i;
            // A fraction only in brackets: in length^2/time the / divides.
            if (i < text.size() && text[i] == '-')
                ++i;
            while (i < text.size() &&
                   (std::isdigit(static_cast<unsigned char>(text[i])) || (bracket && text[i] == '/')))
                ++i;
            const std::string number = text.substr(number_start, i - number_start);
            if (bracket && (i >= text.size() || text[i++] != ')'))
                return bad("has an unclosed bracket");
            try {
                const GiNaC::numeric e(number.c_str());
                if (!e.is_rational() || e.is_zero())
                    return bad("has an exponent that is not a non-zero fraction");
                factor = factor.power(e);
            } catch (const std::exception&) {
                return bad(fmt::format("has an exponent '{}' that is not a number", number));
            }
        }
        result = divide ? result / factor : result * factor;
        skip();
        if (i == text.size())
            return result;
        if (text[i] != '*' && text[i] != '/')
            return bad(fmt::format("has '{}' where * or / belongs", text[i]));
        divide = text[i] == '/';
        ++i;
    }
}

namespace {

class inference {
public:
    inference(const dimension_map& known, const source_location& where, const expression_text& text)
        : known_(known), where_(where), text_(text)
    {
    }

    std::optional<dimension> of(const GiNaC::ex& e) const
    {
        if (GiNaC::is_a<GiNaC::numeric>(e) || GiNaC::is_a<GiNaC::constant>(e))
            return dimension();
        if (GiNaC::is_a<GiNaC::symbol>(e)) {
            const auto found = known_.find(e);
            if (found == known_.end())
                return std::nullopt;
            return found->second;
        }
        if (GiNaC::is_a<GiNaC::add>(e))
            return sum(e);
        if (GiNaC::is_a<GiNaC::mul>(e)) {
            std::optional<dimension> product = dimension();
            for (std::size_t i = 0; i < e.nops(); ++i) {
                const auto factor = of(e.op(i));
                product = product && factor ? std::optional<dimension>(*product * *factor) : std::nullopt;
            }
            return product;
        }
        if (GiNaC::is_a<GiNaC::power>(e))
            return power(e);
        if (GiNaC::is_a<GiNaC::function>(e))
            return function(e);
        if (GiNaC::is_a<GiNaC::relational>(e))
            return relation(e);
        return std::nullopt;
    }

private:
    std::optional<dimension> sum(const GiNaC::ex& e) const
    {
        std::vector<std::pair<GiNaC::ex, dimension>> known;
        bool all_known = true;
        for (std::size_t i = 0; i < e.nops(); ++i) {
            const auto found = of(e.op(i));
            all_known = all_known && found;
            if (found)
                known.emplace_back(e.op(i), *found);
        }
        for (const auto& [term, d] : known)
            if (d != known.front().second)
                refuse_sum(known);
        // A sum with a term of unknown dimension has an unknown dimension.
        return all_known && !known.empty() ? std::optional<dimension>(known.front().second) : std::nullopt;
    }

    // Two terms of different dimensions, named in the order of their text, not GiNaC's
    // (which depends on what else the process has made): the same message every run.
    [[noreturn]] void refuse_sum(const std::vector<std::pair<GiNaC::ex, dimension>>& known) const
    {
        std::vector<std::tuple<std::string, GiNaC::ex, dimension>> terms;
        for (const auto& [term, d] : known)
            terms.emplace_back(text(term), term, d);
        std::sort(terms.begin(), terms.end(),
                  [](const auto& a, const auto& b) { return std::get<0>(a) < std::get<0>(b); });
        const auto& [first_text, first, first_dimension] = terms.front();
        for (const auto& [written, term, d] : terms)
            if (d != first_dimension)
                throw dimension_clash(where_,
                                      fmt::format("adds {}, {}, to {}, {}: the terms of a sum share one dimension",
                                                  first_text, first_dimension.describe(), written, d.describe()),
                                      dimension_clash::kind::adds, first, first_dimension, term, d);
        throw std::logic_error("refuse_sum: the terms share one dimension");
    }

    std::optional<dimension> power(const GiNaC::ex& e) const
    {
        const auto base = of(e.op(0));
        const GiNaC::ex exponent = e.op(1);
        if (GiNaC::is_a<GiNaC::numeric>(exponent)) {
            const GiNaC::numeric n = GiNaC::ex_to<GiNaC::numeric>(exponent);
            if (!base)
                return std::nullopt;
            if (!n.is_rational()) {
                if (!base->is_pure_number())
                    throw error(where_, fmt::format("raises {}, {}, to the power {}: only a pure number takes an "
                                                    "exponent that is not a fraction",
                                                    text(e.op(0)), base->describe(), text(exponent)));
                return dimension();
            }
            return base->power(n);
        }
        const auto exponent_dimension = of(exponent);
        if (exponent_dimension && !exponent_dimension->is_pure_number())
            throw error(where_, fmt::format("has the exponent {}, {}: an exponent is a pure number",
                                            text(exponent), exponent_dimension->describe()));
        if (base && !base->is_pure_number())
            throw error(where_, fmt::format("raises {}, {}, to the power {}: a quantity with a dimension takes "
                                            "only a numeric exponent",
                                            text(e.op(0)), base->describe(), text(exponent)));
        return base && exponent_dimension ? std::optional<dimension>(dimension()) : std::nullopt;
    }

    std::optional<dimension> function(const GiNaC::ex& e) const
    {
        const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
        if (name == "abs")
            return of(e.op(0));
        // ∂f/∂x (engine/expr/derivative.h): f's dimension over x's.
        if (name == "diff") {
            const auto f = of(e.op(0)), x = of(e.op(1));
            return f && x ? std::optional<dimension>(*f / *x) : std::nullopt;
        }
        if (name == "select_positive") {
            // A quantity defined by cases: the condition's dimension is its own; the two
            // values share one, the result's.
            of(e.op(0));
            const auto a = of(e.op(1)), b = of(e.op(2));
            if (a && b && *a != *b && !e.op(1).is_zero() && !e.op(2).is_zero())
                throw error(where_, fmt::format("defines a quantity by cases as {}, {}, or {}, {}: its cases share "
                                                "one dimension",
                                                text(e.op(1)), a->describe(), text(e.op(2)), b->describe()));
            return e.op(1).is_zero() ? b : a;
        }
        if (name == "atan2") {
            const auto y = of(e.op(0)), x = of(e.op(1));
            if (y && x && *y != *x)
                throw error(where_, fmt::format("takes atan2 of {}, {}, and {}, {}: its two arguments share one "
                                                "dimension",
                                                text(e.op(0)), y->describe(), text(e.op(1)), x->describe()));
            return y && x ? std::optional<dimension>(dimension()) : std::nullopt;
        }
        // exp, log, the trigonometric and hyperbolic functions and their inverses: a pure
        // number in, a pure number out.
        bool known = true;
        for (std::size_t i = 0; i < e.nops(); ++i) {
            const auto argument = of(e.op(i));
            if (argument && !argument->is_pure_number())
                throw error(where_, fmt::format("takes {} of {}, {}: its argument is a pure number", name,
                                                text(e.op(i)), argument->describe()));
            known = known && argument;
        }
        return known ? std::optional<dimension>(dimension()) : std::nullopt;
    }

    std::optional<dimension> relation(const GiNaC::ex& e) const
    {
        const auto lhs = of(e.op(0)), rhs = of(e.op(1));
        // 0 on one side is a zero of any dimension.
        if (lhs && rhs && *lhs != *rhs && !e.op(0).is_zero() && !e.op(1).is_zero())
            throw dimension_clash(where_,
                                  fmt::format("sets {}, {}, against {}, {}: both sides share one dimension",
                                              text(e.op(0)), lhs->describe(), text(e.op(1)), rhs->describe()),
                                  dimension_clash::kind::sets, e.op(0), *lhs, e.op(1), *rhs);
        if (e.op(0).is_zero())
            return rhs;
        return lhs ? lhs : rhs;
    }

    std::string text(const GiNaC::ex& e) const
    {
        // A message must not fail for want of a printer: GiNaC's own printing then.
        if (text_) {
            try {
                return text_(e);
            } catch (const std::exception&) {
            }
        }
        std::ostringstream out;
        out << e;
        return out.str();
    }

    const dimension_map& known_;
    const source_location& where_;
    const expression_text& text_;
};

} // namespace

std::optional<dimension> dimension_of(const GiNaC::ex& e, const dimension_map& known, const source_location& where,
                                      const expression_text& text)
{
    return inference(known, where, text).of(e);
}

std::optional<dimension> dimension_of_relation(const GiNaC::ex& relation, const dimension_map& known,
                                               const source_location& where, const expression_text& text)
{
    return inference(known, where, text).of(relation);
}

} // namespace impact::engine
