#include "emit/latex.h"

#include "engine/infix.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <climits>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <sstream>

namespace impact::emit {

GINAC_IMPLEMENT_PRINT_CONTEXT(print_tex, GiNaC::print_context)

print_tex::print_tex() : GiNaC::print_context(std::cout) {}
print_tex::print_tex(std::ostream& os, const term_order& order, const written_form* written)
    : GiNaC::print_context(os), order(&order), written(written)
{
}

namespace {

using power_term = term_order::power_term;

// A symbol's LaTeX name: the one its derivation file gives, or one made from its name
// when the file gives none (eps → \epsilon, v_M_after → v'_{M}, r_x → r_{x}).
std::string symbol_latex(const GiNaC::symbol& s)
{
    const std::string given = s.get_TeX_name();
    if (!given.empty())
        return given;
    static const std::set<std::string> greek = {
        "alpha", "beta", "gamma", "delta", "epsilon", "zeta", "eta", "theta", "iota", "kappa", "lambda", "mu", "nu",
        "xi", "pi", "rho", "sigma", "tau", "upsilon", "phi", "chi", "psi", "omega", "Gamma", "Delta", "Theta",
        "Lambda", "Xi", "Pi", "Sigma", "Upsilon", "Phi", "Psi", "Omega"};
    auto letter = [&](const std::string& word) {
        if (word == "eps")
            return std::string("\\epsilon");
        return greek.count(word) ? "\\" + word : word;
    };
    std::string name = s.get_name();
    bool primed = false;
    const std::string after = "_after";
    if (name.size() > after.size() && name.compare(name.size() - after.size(), after.size(), after) == 0) {
        primed = true;
        name.erase(name.size() - after.size());
    }
    const auto underscore = name.find('_');
    std::string out = letter(name.substr(0, underscore)) + (primed ? "'" : "");
    if (underscore != std::string::npos) {
        std::string sub = name.substr(underscore + 1);
        std::replace(sub.begin(), sub.end(), '_', ',');
        out += "_{" + sub + "}";
    }
    return out;
}

// Precedence levels: an operand printed at `level` is parenthesised when its own level
// is lower (a sum inside a product, a product or a negative number as a power's base).
constexpr unsigned sum_level = 10;
constexpr unsigned product_level = 20;
constexpr unsigned atom_level = 30;

void print_operand(const GiNaC::ex& e, const print_tex& c, unsigned level);

std::string render(const GiNaC::ex& e, const print_tex& c, unsigned level)
{
    std::ostringstream out;
    const print_tex sub(out, *c.order, c.written);
    print_operand(e, sub, level);
    return out.str();
}

// Something tall inside needs \left( \right); anything else plain parentheses, which
// TeX may break a line inside.
bool is_tall(const std::string& math)
{
    for (const char* tall : {"\\frac", "\\sqrt", "\\left", "\\Bigl", "\\sum"})
        if (math.find(tall) != std::string::npos)
            return true;
    return false;
}

std::string parenthesised(const std::string& math)
{
    return is_tall(math) ? "\\left(" + math + "\\right)" : "(" + math + ")";
}

// Prints `body` into `c`, in parentheses when `open`.
template <class Body>
void wrap(const print_tex& c, bool open, Body body)
{
    if (!open) {
        body(c);
        return;
    }
    std::ostringstream inner;
    const print_tex sub(inner, *c.order, c.written);
    body(sub);
    c.s << parenthesised(inner.str());
}

// A factor turned the way its author wrote it: (1 - eps) stays (1 - eps) even where
// GiNaC stores -(-1 + eps); a sum the text does not show is turned by `term_order`.
power_term oriented(const GiNaC::ex& factor, bool& negated, const print_tex& c)
{
    if (c.written) {
        GiNaC::ex base = factor, exponent = 1;
        if (GiNaC::is_a<GiNaC::power>(factor)) {
            base = factor.op(0);
            exponent = factor.op(1);
        }
        if (GiNaC::is_a<GiNaC::add>(base) && exponent.info(GiNaC::info_flags::integer)) {
            if (const auto way = c.written->as_written(base)) {
                if (*way)
                    return {base, exponent};
                if (!exponent.info(GiNaC::info_flags::even))
                    negated = !negated;
                return {term_order::negated_sum(base), exponent};
            }
        }
    }
    return c.order->oriented(factor, negated);
}

// A product as ± [leading fraction] numerator / denominator, each factor placed where
// the written product has it (numbers first, then `term_order`, when not written).
struct placed {
    power_term factor;
    int index = INT_MAX;     // the position in the written product
    std::string key;         // term_order's key, for what the text does not place
};

struct product_parts {
    bool negated = false;
    GiNaC::numeric leading = 1;   // ½ of `1/2*m*v^2`, typeset before the rest
    std::vector<placed> numerator;
    std::vector<placed> denominator;
};

product_parts split(const GiNaC::ex& product, const print_tex& c)
{
    product_parts parts;
    GiNaC::numeric coefficient = 1;
    std::vector<power_term> items;
    for (std::size_t i = 0; i < product.nops(); ++i) {
        const GiNaC::ex op = product.op(i);
        if (GiNaC::is_a<GiNaC::numeric>(op))
            coefficient *= GiNaC::ex_to<GiNaC::numeric>(op);
        else
            items.push_back(oriented(op, parts.negated, c));
    }
    if (!coefficient.is_rational())
        throw std::invalid_argument("cannot typeset an inexact number");
    if (coefficient.is_negative()) {
        parts.negated = !parts.negated;
        coefficient = -coefficient;
    }
    // GiNaC takes a number out of a sum in a product: (1/(2m) + 1/(2M)) J^2 is stored as
    // 1/2 (1/m + 1/M) J^2. Where the text writes the number inside the sum, put it back.
    if (c.written && coefficient != 1)
        for (power_term& item : items) {
            if (!GiNaC::is_a<GiNaC::add>(item.base) || !item.exponent.is_equal(1) || c.written->as_written(item.base))
                continue;
            const GiNaC::ex scaled = coefficient * item.base;
            if (const auto way = GiNaC::is_a<GiNaC::add>(scaled) ? c.written->as_written(scaled) : std::nullopt) {
                item.base = *way ? scaled : term_order::negated_sum(scaled);
                if (!*way)
                    parts.negated = !parts.negated;
                coefficient = 1;
                break;
            }
        }

    const written_form::product* written = nullptr;
    if (c.written) {
        std::vector<std::pair<GiNaC::ex, GiNaC::ex>> candidates;
        for (const power_term& item : items)
            candidates.emplace_back(item.base, item.exponent);
        written = c.written->best_product(candidates);
    }
    std::vector<bool> used(written ? written->factors.size() : 0, false);
    auto take = [&](auto fits) {
        for (std::size_t i = 0; i < used.size(); ++i)
            if (!used[i] && fits(written->factors[i])) {
                used[i] = true;
                return static_cast<int>(i);
            }
        return INT_MAX;
    };
    auto is_number = [](const written_form::factor& f) { return GiNaC::is_a<GiNaC::numeric>(f.base); };

    const GiNaC::numeric numer = coefficient.numer(), denom = coefficient.denom();
    if (written && written->leading_fraction && denom != 1) {
        parts.leading = coefficient;
        used[0] = used[1] = true;
    } else {
        if (numer != 1) {
            const int at = take([&](const written_form::factor& f) { return is_number(f) && !f.divides; });
            parts.numerator.push_back({{numer, 1}, at == INT_MAX ? -1 : at, ""});
        }
        if (denom != 1) {
            const int at = take([&](const written_form::factor& f) { return is_number(f) && f.divides; });
            parts.denominator.push_back({{denom, 1}, at == INT_MAX ? -1 : at, ""});
        }
    }

    for (const power_term& item : items) {
        placed p{item, INT_MAX, c.order->key(item)};
        const bool inverse = GiNaC::is_a<GiNaC::numeric>(item.exponent) &&
                             GiNaC::ex_to<GiNaC::numeric>(item.exponent).is_negative();
        if (written) {
            p.index = take([&](const written_form::factor& f) {
                return !f.divides && written_form::matches(f, item.base, item.exponent);
            });
            if (p.index != INT_MAX) {
                parts.numerator.push_back(p);
                continue;
            }
            p.index = take([&](const written_form::factor& f) {
                return f.divides && written_form::matches(f, item.base, item.exponent);
            });
            if (p.index != INT_MAX) {
                p.factor.exponent = -item.exponent;
                parts.denominator.push_back(p);
                continue;
            }
        }
        if (inverse && !(c.written && c.written->written_power(item.base, item.exponent))) {
            p.factor.exponent = -item.exponent;
            parts.denominator.push_back(p);
        } else {
            parts.numerator.push_back(p);
        }
    }
    // Ties of the key are broken by the full text of base^exponent, printed only then.
    auto tie = [&](const placed& p) {
        return c.order->text(p.factor.base) + "^" + c.order->text(p.factor.exponent);
    };
    auto in_order = [&](const placed& a, const placed& b) {
        if (a.index != b.index)
            return a.index < b.index;
        if (a.key != b.key)
            return a.key < b.key;
        return tie(a) < tie(b);
    };
    std::sort(parts.numerator.begin(), parts.numerator.end(), in_order);
    std::sort(parts.denominator.begin(), parts.denominator.end(), in_order);
    return parts;
}

bool is_negative_term(const GiNaC::ex& term, const print_tex& c)
{
    if (GiNaC::is_a<GiNaC::numeric>(term))
        return GiNaC::ex_to<GiNaC::numeric>(term).is_negative();
    if (GiNaC::is_a<GiNaC::mul>(term))
        return split(term, c).negated;
    if (GiNaC::is_a<GiNaC::power>(term)) {
        bool negated = false;
        oriented(term, negated, c);
        return negated;
    }
    return false;
}

void print_numeric(const GiNaC::numeric& n, const print_tex& c, unsigned level)
{
    if (!n.is_rational())
        throw std::invalid_argument("cannot typeset an inexact number");
    const bool negative = n.is_negative();
    const GiNaC::numeric a = GiNaC::abs(n);
    const bool open = (negative ? product_level : (a.is_integer() ? atom_level + 1 : atom_level)) < level;
    wrap(c, open, [&](const print_tex& c) {
        if (negative)
            c.s << '-';
        if (a.is_integer())
            c.s << a;
        else
            c.s << "\\frac{" << a.numer() << "}{" << a.denom() << '}';
    });
}

void print_symbol(const GiNaC::symbol& s, const print_tex& c, unsigned)
{
    c.s << symbol_latex(s);
}

// The terms of a sum in print order: as written where the text gives them, the rest
// (and every term of a sum not written) in `term_order`.
std::vector<GiNaC::ex> ordered_terms(const GiNaC::ex& sum, const print_tex& c)
{
    std::vector<GiNaC::ex> terms = c.order->terms(sum);
    const std::vector<GiNaC::ex>* written = c.written ? c.written->terms(sum) : nullptr;
    if (!written)
        return terms;
    std::vector<bool> used(written->size(), false);
    std::vector<std::pair<std::size_t, GiNaC::ex>> indexed;
    for (const GiNaC::ex& term : terms) {
        std::size_t at = written->size();
        for (std::size_t i = 0; i < written->size(); ++i)
            if (!used[i] && (*written)[i].is_equal(term)) {
                used[i] = true;
                at = i;
                break;
            }
        indexed.emplace_back(at, term);
    }
    std::stable_sort(indexed.begin(), indexed.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    terms.clear();
    for (const auto& item : indexed)
        terms.push_back(item.second);
    return terms;
}

// Each term with the sign it is written with: "-" for the first term when negative,
// "+ " or "- " before the others.
std::vector<std::pair<std::string, GiNaC::ex>> signed_terms(const GiNaC::ex& sum, const print_tex& c)
{
    std::vector<std::pair<std::string, GiNaC::ex>> out;
    for (const GiNaC::ex& term : ordered_terms(sum, c)) {
        const bool negative = is_negative_term(term, c);
        const char* sign = out.empty() ? (negative ? "-" : "") : (negative ? "- " : "+ ");
        out.emplace_back(sign, negative ? -term : term);
    }
    return out;
}

void print_add(const GiNaC::add& sum, const print_tex& c, unsigned level)
{
    // -(a - b) where the text writes it so.
    if (c.written && !c.written->terms(sum) && c.written->negated_group(sum)) {
        wrap(c, product_level < level, [&](const print_tex& c) {
            c.s << '-';
            print_operand(term_order::negated_sum(sum), c, product_level);
        });
        return;
    }
    wrap(c, sum_level < level, [&](const print_tex& c) {
        bool first = true;
        for (const auto& [sign, term] : signed_terms(sum, c)) {
            c.s << (first ? "" : " ") << sign;
            print_operand(term, c, sign.empty() ? sum_level : product_level);
            first = false;
        }
    });
}

std::string symbol_power(const std::string& name, const std::string& exponent);
void print_power_term(const power_term& p, const print_tex& c, unsigned level);

// Whether a symbol reads like a function (\cos\theta): what follows it is set apart.
bool reads_like_function(const GiNaC::ex& base)
{
    if (!GiNaC::is_a<GiNaC::symbol>(base))
        return false;
    const std::string name = symbol_latex(GiNaC::ex_to<GiNaC::symbol>(base));
    for (const char* f : {"\\cos", "\\sin", "\\tan"})
        if (name.rfind(f, 0) == 0)
            return true;
    return false;
}

// Factors side by side; a number after another factor needs a \cdot, and a factor
// after \cos\theta a thin space (cos θ r, not cos θr).
void print_factors(const std::vector<placed>& factors, const print_tex& c, unsigned level)
{
    for (std::size_t i = 0; i < factors.size(); ++i) {
        if (i > 0) {
            if (GiNaC::is_a<GiNaC::numeric>(factors[i].factor.base))
                c.s << " \\cdot ";
            else if (reads_like_function(factors[i - 1].factor.base))
                c.s << " \\, ";
            else
                c.s << ' ';
        }
        print_power_term(factors[i].factor, c, factors.size() == 1 ? level : product_level);
    }
}

void print_parts(const product_parts& f, const print_tex& c, unsigned level)
{
    const bool leading = f.leading != 1;
    wrap(c, product_level < level, [&](const print_tex& c) {
        if (f.negated)
            c.s << '-';
        if (leading) {
            c.s << "\\frac{" << f.leading.numer() << "}{" << f.leading.denom() << '}';
            if (!f.numerator.empty() || !f.denominator.empty())
                c.s << ' ';
        }
        if (f.denominator.empty()) {
            if (f.numerator.empty() && !leading)
                c.s << '1';
            print_factors(f.numerator, c, product_level);
            return;
        }
        c.s << "\\frac{";
        if (f.numerator.empty())
            c.s << '1';
        print_factors(f.numerator, c, 0);
        c.s << "}{";
        print_factors(f.denominator, c, 0);
        c.s << '}';
    });
}

void print_mul(const GiNaC::mul& product, const print_tex& c, unsigned level)
{
    print_parts(split(product, c), c, level);
}

const std::map<std::string, std::string>& function_names()
{
    static const std::map<std::string, std::string> names = {
        {"acos", "\\arccos"}, {"asin", "\\arcsin"}, {"atan", "\\arctan"}, {"cos", "\\cos"},
        {"sin", "\\sin"},     {"tan", "\\tan"},     {"exp", "\\exp"},     {"log", "\\ln"},
    };
    return names;
}

// base^exponent, the base never rebuilt into a GiNaC power (see engine/order.h).
void print_power_term(const power_term& p, const print_tex& c, unsigned level)
{
    const GiNaC::ex& base = p.base;
    const GiNaC::ex& exponent = p.exponent;
    if (exponent.is_equal(1)) {
        print_operand(base, c, level);
        return;
    }
    if (GiNaC::is_a<GiNaC::numeric>(exponent)) {
        const GiNaC::numeric n = GiNaC::ex_to<GiNaC::numeric>(exponent);
        if (n.is_negative() && !(c.written && c.written->written_power(base, exponent))) {
            c.s << "\\frac{1}{";
            print_power_term({base, -n}, c, 0);
            c.s << '}';
            return;
        }
        if (n == GiNaC::numeric(1, 2)) {
            c.s << "\\sqrt{";
            print_operand(base, c, 0);
            c.s << '}';
            return;
        }
    }
    const std::string power = render(exponent, c, 0);
    if (GiNaC::is_a<GiNaC::symbol>(base)) {
        c.s << symbol_power(symbol_latex(GiNaC::ex_to<GiNaC::symbol>(base)), power);
        return;
    }
    if (GiNaC::is_a<GiNaC::function>(base)) {
        // \cos^{2}\theta, as a textbook writes it.
        const auto known = function_names().find(GiNaC::ex_to<GiNaC::function>(base).get_name());
        if (known != function_names().end() && base.nops() == 1) {
            c.s << known->second << "^{" << power << "}" << parenthesised(render(base.op(0), c, 0));
            return;
        }
    }
    c.s << render(base, c, atom_level + 1) << "^{" << power << '}';
}

void print_power(const GiNaC::power& power, const print_tex& c, unsigned level)
{
    // (v_m - v_M)^2, never (-v_M + v_m)^2: a sum in the base leads with a positive term
    // (or is turned the way it was written).
    bool negated = false;
    const power_term p = oriented(power, negated, c);
    wrap(c, (negated ? product_level : atom_level) < level, [&](const print_tex& c) {
        if (negated)
            c.s << '-';
        print_power_term(p, c, negated ? product_level : level);
    });
}

void print_function(const GiNaC::function& f, const print_tex& c)
{
    const std::string name = f.get_name();
    if (name == "abs") {
        const std::string inner = render(f.op(0), c, 0);
        c.s << (is_tall(inner) ? "\\left|" + inner + "\\right|" : "|" + inner + "|");
        return;
    }
    const auto known = function_names().find(name);
    std::string args;
    for (std::size_t i = 0; i < f.nops(); ++i)
        args += (i > 0 ? ", " : "") + render(f.op(i), c, 0);
    c.s << (known != function_names().end() ? known->second : "\\operatorname{" + name + "}")
        << parenthesised(args);
}

void print_operand(const GiNaC::ex& e, const print_tex& c, unsigned level)
{
    if (GiNaC::is_a<GiNaC::function>(e)) {
        print_function(GiNaC::ex_to<GiNaC::function>(e), c);
        return;
    }
    e.print(c, level);
}

void register_print_functions()
{
    static const bool registered = [] {
        GiNaC::set_print_func<GiNaC::numeric, print_tex>(print_numeric);
        GiNaC::set_print_func<GiNaC::symbol, print_tex>(print_symbol);
        GiNaC::set_print_func<GiNaC::add, print_tex>(print_add);
        GiNaC::set_print_func<GiNaC::mul, print_tex>(print_mul);
        GiNaC::set_print_func<GiNaC::power, print_tex>(print_power);
        return true;
    }();
    (void)registered;
}

// Where a LaTeX name's trailing subscript starts (`_{M,\parallel}` of v'_{M,\parallel}),
// or npos when it has none that runs to the end.
std::size_t trailing_subscript(const std::string& name)
{
    int depth = 0;
    std::size_t at = std::string::npos;
    for (std::size_t i = 0; i < name.size(); ++i) {
        if (name[i] == '{')
            ++depth;
        else if (name[i] == '}')
            --depth;
        else if (name[i] == '_' && depth == 0)
            at = i;
    }
    if (at == std::string::npos || at + 1 >= name.size())
        return std::string::npos;
    // The subscript is one group, one command or one character, and nothing follows it.
    std::size_t end = at + 1;
    if (name[end] == '{') {
        int d = 0;
        for (; end < name.size(); ++end) {
            d += name[end] == '{' ? 1 : name[end] == '}' ? -1 : 0;
            if (d == 0)
                break;
        }
        ++end;
    } else if (name[end] == '\\') {
        ++end;
        while (end < name.size() && std::isalpha(static_cast<unsigned char>(name[end])))
            ++end;
    } else {
        ++end;
    }
    return end == name.size() ? at : std::string::npos;
}

bool has_top_level(const std::string& name, char wanted)
{
    int depth = 0;
    for (char ch : name) {
        depth += ch == '{' ? 1 : ch == '}' ? -1 : 0;
        if (depth == 0 && ch == wanted)
            return true;
    }
    return false;
}

// A symbol raised to a power as a textbook writes it: v'^{2}_{M,\parallel} (the prime
// and the exponent share the superscript), \cos^{2}\theta, and a name that is itself a
// compound (\Delta E_K, a dot product) in parentheses.
std::string symbol_power(const std::string& name, const std::string& exponent)
{
    for (const char* function : {"\\cos", "\\sin", "\\tan"}) {
        const std::string f = function;
        if (name.rfind(f, 0) == 0 && name.size() > f.size() && !std::isalpha(static_cast<unsigned char>(name[f.size()])))
            return f + "^{" + exponent + "}" + name.substr(f.size());
    }
    if (has_top_level(name, '^') || has_top_level(name, ' '))
        return "(" + name + ")^{" + exponent + "}";
    const std::size_t sub = trailing_subscript(name);
    if (sub != std::string::npos)
        return name.substr(0, sub) + "^{" + exponent + "}" + name.substr(sub);
    return name + "^{" + exponent + "}";
}

// ---- widths and line breaks ----------------------------------------------------------

// Widths in points of Computer Modern at 10 pt, display style: close enough to decide
// where a line must break.
class width_reader {
public:
    explicit width_reader(const std::string& s) : s_(s) {}
    double all()
    {
        double w = 0;
        while (i_ < s_.size())
            w += item();
        return w;
    }

private:
    double group()
    {
        if (i_ >= s_.size())
            return 0;
        if (s_[i_] != '{')
            return item();
        ++i_;
        double w = 0;
        while (i_ < s_.size() && s_[i_] != '}')
            w += item();
        ++i_;
        return w;
    }

    // A superscript and a subscript on the same base stack: the wider one counts.
    double scripts()
    {
        double w = 0;
        char last = 0;
        while (i_ < s_.size() && (s_[i_] == '^' || s_[i_] == '_') && s_[i_] != last) {
            last = s_[i_++];
            w = std::max(w, 0.7 * group());
        }
        return w;
    }

    static double letter(char ch)
    {
        if (std::isdigit(static_cast<unsigned char>(ch)))
            return 5.0;
        if (std::isupper(static_cast<unsigned char>(ch)))
            return ch == 'M' || ch == 'W' ? 9.7 : ch == 'I' || ch == 'J' ? 5.6 : 8.0;
        return ch == 'm' ? 8.8 : ch == 'w' ? 7.2 : 5.2;
    }

    double command()
    {
        std::string name;
        while (i_ < s_.size() && std::isalpha(static_cast<unsigned char>(s_[i_])))
            name += s_[i_++];
        if (name.empty()) {
            ++i_;   // \| \, \{ ...
            return 5.0;
        }
        if (name == "frac") {
            const double a = group(), b = group();
            return std::max(a, b) + 2.4;
        }
        if (name == "sqrt")
            return group() + 8.3;
        if (name == "left" || name == "right" || name == "biggl" || name == "biggr" || name == "bigl" ||
            name == "bigr" || name == "Bigl" || name == "Bigr") {
            if (i_ < s_.size() && s_[i_] == '\\') {
                ++i_;
                while (i_ < s_.size() && std::isalpha(static_cast<unsigned char>(s_[i_])))
                    ++i_;
            } else {
                ++i_;
            }
            return name.size() > 4 ? 6.0 : 4.5;
        }
        if (name == "mathrm" || name == "mathbf" || name == "operatorname" || name == "text")
            return group();
        static const std::map<std::string, double> widths = {
            {"quad", 10},     {"qquad", 20},    {"cdot", 7.2},   {"to", 15.6},    {"leq", 13.4},
            {"geq", 13.4},    {"neq", 13.4},    {"in", 12},      {"parallel", 2.8}, {"perp", 7.8},
            {"epsilon", 4.1}, {"theta", 4.7},   {"tau", 4.4},    {"Delta", 8.3},  {"cos", 13.8},
            {"sin", 10.6},    {"tan", 13.4},    {"arccos", 27},  {"arcsin", 24},  {"arctan", 27},
            {"lim", 14},      {"infty", 10},    {"ln", 8},       {"exp", 15},     {"prime", 2.8},
        };
        const auto known = widths.find(name);
        return known != widths.end() ? known->second : 6.0;
    }

    double item()
    {
        const char ch = s_[i_];
        if (ch == '{')
            return group() + scripts();
        if (ch == '^' || ch == '_')
            return scripts();
        if (ch == '\\') {
            ++i_;
            return command() + scripts();
        }
        ++i_;
        switch (ch) {
        case ' ': case '&': return 0;
        case '+': case '-': return 12.2;
        case '=': case '<': case '>': return 13.4;
        case '(': case ')': return 3.9 + scripts();
        case '|': case ',': case '\'': case '.': return 2.8 + scripts();
        default: return letter(ch) + scripts();
        }
    }

    const std::string& s_;
    std::size_t i_ = 0;
};

// The lines of `e` (see latex_lines): one when it fits in `first`, else a sum broken
// before its terms and a product around its widest sum, the lines after the first no
// wider than `rest`.
std::vector<std::string> break_lines(const GiNaC::ex& e, const print_tex& c, double first, double rest)
{
    const std::string whole = render(e, c, 0);
    if (latex_width(whole) <= first)
        return {whole};

    if (GiNaC::is_a<GiNaC::add>(e) && !(c.written && !c.written->terms(e) && c.written->negated_group(e))) {
        std::vector<std::string> lines;
        std::string current;
        auto budget = [&] { return lines.empty() ? first : rest; };
        for (const auto& [sign, term] : signed_terms(e, c)) {
            const std::string text = sign + render(term, c, sign.empty() ? sum_level : product_level);
            const std::string joined = current.empty() ? text : current + " " + text;
            if (latex_width(joined) <= budget()) {
                current = joined;
                continue;
            }
            if (!current.empty() && latex_width(text) <= rest) {
                lines.push_back(current);
                current = text;
                continue;
            }
            if (!GiNaC::is_a<GiNaC::mul>(term)) {
                if (!current.empty())
                    lines.push_back(current);
                current = text;
                continue;
            }
            // A product too wide for a line of its own: it starts where the line has room.
            double room = budget() - (current.empty() ? 0 : latex_width(current) + 12);
            if (room < budget() / 3 && !current.empty()) {
                lines.push_back(current);
                current.clear();
                room = rest;
            }
            std::vector<std::string> piece = break_lines(term, c, room - latex_width(sign), rest);
            piece.front() = sign + piece.front();
            current += (current.empty() ? "" : " ") + piece.front();
            for (std::size_t i = 1; i < piece.size(); ++i) {
                lines.push_back(current);
                current = piece[i];
            }
        }
        lines.push_back(current);
        return lines;
    }

    if (GiNaC::is_a<GiNaC::mul>(e)) {
        product_parts parts = split(e, c);
        std::size_t widest = parts.numerator.size();
        double widest_width = 0;
        for (std::size_t i = 0; i < parts.numerator.size(); ++i) {
            const power_term& f = parts.numerator[i].factor;
            if (!GiNaC::is_a<GiNaC::add>(f.base) || !f.exponent.is_equal(1))
                continue;
            const double w = latex_width(render(f.base, c, 0));
            if (w > widest_width) {
                widest = i;
                widest_width = w;
            }
        }
        if (widest == parts.numerator.size())
            return {whole};
        const GiNaC::ex sum = parts.numerator[widest].factor.base;
        parts.numerator.erase(parts.numerator.begin() + static_cast<std::ptrdiff_t>(widest));
        std::string prefix;
        if (!parts.numerator.empty() || !parts.denominator.empty() || parts.leading != 1) {
            std::ostringstream out;
            const print_tex sub(out, *c.order, c.written);
            product_parts rest_of = parts;
            rest_of.negated = false;
            print_parts(rest_of, sub, product_level);
            prefix = out.str() + " ";
        }
        // The sign, the prefix and the parentheses take room from the first line.
        const double taken = latex_width((parts.negated ? "-" : "") + prefix + "\\Bigl(\\Bigr)");
        std::vector<std::string> lines = break_lines(sum, c, std::max(first - taken, first / 3), rest - 8);
        lines.front() = (parts.negated ? "-" : "") + prefix + "\\Bigl(" + lines.front();
        lines.back() += "\\Bigr)";
        return lines;
    }
    return {whole};
}

// ---- derivation fragments ------------------------------------------------------------

const char* latex_relation(engine::relation op)
{
    switch (op) {
    case engine::relation::equal: return "=";
    case engine::relation::less_equal: return "\\leq";
    case engine::relation::less: return "<";
    case engine::relation::greater_equal: return "\\geq";
    case engine::relation::greater: return ">";
    }
    return "=";
}

// True when a \frac has another \frac inside its arguments (too tall to set inline).
bool nested_fraction(const std::string& math)
{
    for (std::size_t at = math.find("\\frac"); at != std::string::npos; at = math.find("\\frac", at + 1)) {
        // The extent of the two argument groups.
        std::size_t i = at + 5;
        for (int group = 0; group < 2 && i < math.size(); ++group) {
            int depth = 0;
            const std::size_t begin = i;
            for (; i < math.size(); ++i) {
                depth += math[i] == '{' ? 1 : math[i] == '}' ? -1 : 0;
                if (depth == 0)
                    break;
            }
            if (math.substr(begin + 1, i - begin).find("\\frac") != std::string::npos)
                return true;
            ++i;
        }
    }
    return false;
}


// "Eq. 8" → "8"; the tag of a numbered result.
std::string equation_tag(const std::string& paper)
{
    const std::string prefix = "Eq. ";
    return paper.rfind(prefix, 0) == 0 ? paper.substr(prefix.size()) : paper;
}

// "Eq. 8" → "Eq.~8" in running text.
std::string paper_text(const std::string& paper)
{
    std::string out = latex_text(paper);
    const auto space = out.find("Eq. ");
    if (space != std::string::npos)
        out.replace(space + 3, 1, "~");
    return out;
}

std::string status_text(const engine::verdict& v)
{
    switch (v.what) {
    case engine::verdict::status::proven: return "\\textbf{proven}";
    case engine::verdict::status::sampled: return fmt::format("\\textit{{sampled ({} points)}}", v.samples);
    case engine::verdict::status::failed: break;
    }
    return "\\textbf{FAILED}";
}

std::string capitalised(std::string text)
{
    if (!text.empty())
        text[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(text[0])));
    return text;
}

// momentum_conserved → "momentum conserved"
std::string words(const std::string& name)
{
    std::string out = name;
    std::replace(out.begin(), out.end(), '_', ' ');
    return out;
}

std::string sentence_end(const std::string& text)
{
    if (text.empty())
        return text;
    const char last = text.back();
    return (last == '.' || last == '?' || last == '!') ? text : text + ".";
}

// Joins items as "a, b and c".
std::string listing(const std::vector<std::string>& items)
{
    std::string out;
    for (std::size_t i = 0; i < items.size(); ++i) {
        if (i > 0)
            out += i + 1 == items.size() ? " and " : ", ";
        out += items[i];
    }
    return out;
}

// Everything the fragment of one derivation needs while it is written.
class fragment_writer {
public:
    explicit fragment_writer(const engine::derivation& d) : d_(d), order_(engine::declaration_order(d.symbols))
    {
        register_print_functions();
        int g = 0;
        for (const engine::equation& e : d.givens)
            tags_[e.name] = fmt::format("G{}", ++g);
        int s = 0;
        for (const engine::step_result& st : d.steps)
            if (st.yields)
                tags_[st.yields->name] = fmt::format("S{}", ++s);
    }

    std::string write()
    {
        std::string out = fmt::format("% Generated by Impact from {}; do not edit.\n"
                                      "% Needs \\usepackage{{amsmath,amssymb}}.\n",
                                      d_.source_name());
        out += fmt::format("\\subsection{{{}{}}}\\label{{{}}}\n", latex_text(d_.source.title.value),
                           d_.source.paper ? " (" + paper_text(d_.source.paper->value) + ")" : "", latex_label(d_));
        if (!d_.source.summary.value.empty())
            out += latex_text(d_.source.summary.value) + "\n";
        out += quantities();
        out += givens();
        out += steps();
        out += results();
        out += checks();
        out += paper();
        return out;
    }

private:
    written_form written(const std::string& text) const
    {
        return written_form::read(text, [this](const std::string& piece) { return d_.symbols.parse({piece, {}}); });
    }

    std::string math(const GiNaC::ex& e, const written_form* w = nullptr) const { return latex(e, order_, w); }

    std::string relation_math(const GiNaC::ex& r, const written_form* w = nullptr) const
    {
        return math(r.lhs(), w) + " = " + math(r.rhs(), w);
    }

    // `lhs &= rhs` rows of an align, the right side broken over lines when long; the last
    // line gets `tag`. Every line starts at the alignment point, after the widest left side
    // of the block (`align_at`, by default this one's). A left side too wide to leave room
    // gets a line of its own, the relation starting the next.
    std::string rows(const std::string& lhs, const GiNaC::ex& rhs, const written_form* w, const std::string& tag,
                     const char* relation = "=", double align_at = -1) const
    {
        // The tag, set at the right of the last line, takes about 5 pt a character and a gap.
        double tag_width = 0;
        if (const auto at = tag.find("\\tag{"); at != std::string::npos)
            tag_width = 5.0 * static_cast<double>(tag.find('}', at) - at - 5) + 25;
        const double side = align_at >= 0 ? align_at : latex_width(lhs);
        const bool own_line = side > 0.4 * content_width;
        const double indent = own_line ? 20 : side;
        const double first = content_width - indent - 14 - tag_width;
        const double others = content_width - indent - 20 - tag_width;
        register_print_functions();
        std::ostringstream unused;
        const print_tex c(unused, order_, w && !w->empty() ? w : nullptr);
        const std::vector<std::string> lines = break_lines(rhs, c, std::max(first, 150.0), std::max(others, 150.0));
        const std::string notag = tag.empty() ? "" : " \\notag";
        std::string out = own_line ? fmt::format("  & {}{} \\\\\n  &\\qquad {} {}", lhs, notag, relation, lines.front())
                                   : fmt::format("  {} &{} {}", lhs, relation, lines.front());
        for (std::size_t i = 1; i < lines.size(); ++i)
            out += fmt::format("{} \\\\\n  &\\qquad {}{{}}{}", notag, own_line ? "\\quad " : "", lines[i]);
        return out + (tag.empty() ? "" : " " + tag);
    }

    std::string ref(const std::string& equation) const
    {
        const auto tag = tags_.find(equation);
        if (tag == tags_.end())
            return latex_text(equation);
        return fmt::format("\\eqref{{{}:{}}}", latex_label(d_), equation);
    }

    const spec::check* spec_check(const std::string& name) const
    {
        for (const spec::check& c : d_.source.checks)
            if (c.name.value == name)
                return &c;
        return nullptr;
    }

    const spec::result* spec_result(const std::string& name) const
    {
        for (const spec::result& r : d_.source.results)
            if (r.name.value == name)
                return &r;
        return nullptr;
    }

    std::string quantities() const
    {
        std::string out = "\n\\paragraph{Quantities.}\n\\begin{itemize}\\setlength{\\itemsep}{0pt}\n";
        for (const engine::quantity& q : d_.symbols.all()) {
            if (q.definition) {
                const written_form w = written(definition_text(q));
                out += fmt::format("\\item ${} = {}$", math(q.symbol), math(*q.definition, &w));
            } else {
                out += fmt::format("\\item ${} {}$", math(q.symbol), q.range.to_latex());
            }
            out += q.meaning.empty() ? "\n" : ": " + latex_text(q.meaning) + "\n";
        }
        return out + "\\end{itemize}\n";
    }

    std::string definition_text(const engine::quantity& q) const
    {
        for (const spec::symbol& s : d_.source.symbols)
            if (s.name.value == q.name && s.definition)
                return s.definition->value;
        return "";
    }

    std::string givens() const
    {
        if (d_.givens.empty())
            return "";
        std::string out = "\n\\paragraph{Given.}\n";
        for (std::size_t i = 0; i < d_.givens.size(); ++i) {
            const engine::equation& g = d_.givens[i];
            const spec::given* source = nullptr;
            for (const spec::given& s : d_.source.givens)
                if (s.name.value == g.name)
                    source = &s;
            const written_form w = source ? written(source->equation.value) : written_form();
            const std::string why = capitalised(latex_text(g.because)) +
                                    (g.paper.empty() ? "" : " (" + paper_text(g.paper) + ")") + ":";
            if (i == 0)
                out += why + "\n\\begin{align}\n";
            else
                out += fmt::format("\\intertext{{{}}}\n", why);
            out += rows(math(g.relation.lhs(), &w), g.relation.rhs(), &w,
                        fmt::format("\\tag{{{}}}\\label{{{}:{}}}", tags_.at(g.name), latex_label(d_), g.name));
            out += i + 1 < d_.givens.size() ? " \\\\\n" : "\n";
        }
        return out + "\\end{align}\n";
    }

    std::string step_checks(const engine::step_result& s) const
    {
        std::string out;
        for (const engine::check_result& c : s.checks)
            out += fmt::format("{}: {}.\n", capitalised(latex_text(c.name)), status_text(c.outcome));
        return out;
    }

    std::string steps() const
    {
        if (d_.steps.empty())
            return "";
        std::string out = "\n\\paragraph{Derivation.}\n\\begin{enumerate}\n";
        for (std::size_t i = 0; i < d_.steps.size(); ++i) {
            const engine::step_result& s = d_.steps[i];
            const spec::step* source = i < d_.source.steps.size() ? &d_.source.steps[i] : nullptr;
            const std::string because = s.because.empty() ? "" : " (" + latex_text(s.because) + ")";
            out += "\\item ";
            switch (s.what) {
            case spec::step::kind::solve: out += solve_step(s, source, because); break;
            case spec::step::kind::define: out += define_step(s, source, because); break;
            case spec::step::kind::quotient: out += quotient_step(s, source, because); break;
            case spec::step::kind::rearrange: out += rearrange_step(s, source, because); break;
            }
        }
        return out + "\\end{enumerate}\n";
    }

    std::string solve_step(const engine::step_result& s, const spec::step* source, const std::string& because) const
    {
        std::vector<std::string> equations, unknowns;
        if (source)
            for (const spec::text& e : source->equations)
                equations.push_back(ref(e.value));
        for (const auto& value : s.values)
            unknowns.push_back("$" + math(value.first) + "$");
        std::string out = fmt::format("Solving {} for {}{} gives\n\\begin{{align*}}\n", listing(equations),
                                      listing(unknowns), because);
        for (std::size_t i = 0; i < s.values.size(); ++i)
            out += rows(math(s.values[i].first), s.values[i].second, nullptr, "") +
                   (i + 1 < s.values.size() ? " \\\\\n" : "\n");
        out += "\\end{align*}\n";
        const bool all_proven = std::all_of(s.checks.begin(), s.checks.end(), [](const engine::check_result& c) {
            return c.outcome.what == engine::verdict::status::proven;
        });
        if (all_proven && !s.checks.empty())
            out += fmt::format("Substituted back, the solution satisfies {}: \\textbf{{proven}}.\n",
                               equations.size() == 1 ? equations.front() : "each of " + listing(equations));
        else
            out += step_checks(s);
        return out;
    }

    std::string define_step(const engine::step_result& s, const spec::step* source, const std::string& because) const
    {
        std::string out;
        for (const auto& [symbol, value] : s.values) {
            out += fmt::format("Defining ${}${}:\n\\begin{{align*}}\n", math(symbol), because);
            // The definition as written, then what it comes to when that differs.
            std::optional<GiNaC::ex> as_written;
            written_form w;
            if (source) {
                w = written(source->expression.value);
                try {
                    as_written = d_.symbols.parse(source->expression);
                } catch (const std::exception&) {
                }
            }
            if (as_written && !as_written->is_equal(value) && math(*as_written, &w) != math(value))
                out += rows(math(symbol), *as_written, &w, "") + " \\\\\n" +
                       rows("", value, nullptr, "", "=", latex_width(math(symbol))) + "\n";
            else if (as_written)
                out += rows(math(symbol), *as_written, &w, "") + "\n";
            else
                out += rows(math(symbol), value, nullptr, "") + "\n";
            out += "\\end{align*}\n";
        }
        return out + step_checks(s);
    }

    std::string yields(const engine::step_result& s) const
    {
        if (!s.yields)
            return "";
        const std::string tag =
            fmt::format("\\tag{{{}}}\\label{{{}:{}}}", tags_.at(s.yields->name), latex_label(d_), s.yields->name);
        return "\\begin{align}\n" + rows(math(s.yields->relation.lhs()), s.yields->relation.rhs(), nullptr, tag) +
               "\n\\end{align}\n";
    }

    std::string quotient_step(const engine::step_result& s, const spec::step* source,
                              const std::string& because) const
    {
        std::string a = "an equation", b = "another";
        if (source && source->equations.size() == 2) {
            a = ref(source->equations[0].value);
            b = ref(source->equations[1].value);
        }
        std::vector<std::string> assumed;
        for (const GiNaC::ex& assumption : s.assumptions)
            assumed.push_back(fmt::format("${} \\neq {}$", math(assumption.lhs()), math(assumption.rhs())));
        std::string out = fmt::format("Dividing {} by {} side by side{}", a, b, because);
        if (!assumed.empty())
            out += fmt::format(", where {}", listing(assumed));
        return out + ", gives\n" + yields(s) + step_checks(s);
    }

    std::string rearrange_step(const engine::step_result& s, const spec::step* source,
                               const std::string& because) const
    {
        std::string out = fmt::format("Rearranging {}{} gives\n", source ? ref(source->source.value) : "", because);
        if (s.yields && source) {
            const written_form w = written(source->expression.value);
            const std::string tag =
                fmt::format("\\tag{{{}}}\\label{{{}:{}}}", tags_.at(s.yields->name), latex_label(d_), s.yields->name);
            out += "\\begin{align}\n" + rows(math(s.yields->relation.lhs(), &w), s.yields->relation.rhs(), &w, tag) +
                   "\n\\end{align}\n";
        } else {
            out += yields(s);
        }
        for (const engine::check_result& c : s.checks)
            out += fmt::format("Equivalent to {}: {}.\n", ref(source ? source->source.value : ""),
                               status_text(c.outcome));
        return out;
    }

    std::string results() const
    {
        if (d_.results.empty())
            return "";
        std::string out = "\n\\paragraph{Results.}\n\\begin{align}\n";
        double widest = 0;
        for (const engine::result& r : d_.results)
            widest = std::max(widest, latex_width(math(r.symbol)));
        std::map<std::string, int> used_tags;
        for (const engine::result& r : d_.results)
            ++used_tags[r.paper];
        std::map<std::string, int> next_letter;
        for (std::size_t i = 0; i < d_.results.size(); ++i) {
            const engine::result& r = d_.results[i];
            std::string tag = "\\notag";
            if (!r.paper.empty()) {
                std::string t = equation_tag(r.paper);
                if (used_tags[r.paper] > 1)
                    t += static_cast<char>('a' + next_letter[r.paper]++);
                tag = fmt::format("\\tag{{{}}}", latex_text(t));
            }
            const spec::result* source = spec_result(r.name);
            const written_form w = source && source->display ? written(source->display->value) : written_form();
            if (!r.paper.empty())
                tag += fmt::format("\\label{{{}:result:{}}}", latex_label(d_), r.name);
            out += rows(math(r.symbol), r.display, &w, tag, "=", widest) + (i + 1 < d_.results.size() ? " \\\\\n" : "\n");
        }
        return out + "\\end{align}\n";
    }

    // How a check was established, in words and math: the sign of each factor for an
    // inequality, the method of a limit, the sample size when not proven.
    std::string how(const engine::check_result& c) const
    {
        std::string out;
        if (c.limit && c.outcome.method.rfind("limit ", 0) == 0) {
            const std::string& m = c.outcome.method;
            const auto open = m.find(" ("), close = m.rfind("); ");
            if (open != std::string::npos && close != std::string::npos && close > open)
                out += " The limit is established " + limit_method(m.substr(open + 2, close - open - 2)) + ".";
        }
        if (!c.outcome.proof.empty()) {
            std::vector<std::string> signs;
            for (const std::string& step : c.outcome.proof)
                signs.push_back(sign_step(step));
            out += " From the signs of its factors: " + listing(signs) + ".";
        }
        if (c.outcome.what == engine::verdict::status::sampled)
            out += fmt::format(" GiNaC cannot decide it; it holds at {} sampled points of the domains (40 digits).",
                               c.outcome.samples);
        if (c.outcome.what == engine::verdict::status::failed)
            out += " Residual: $" + math(c.outcome.residual) + "$.";
        return out;
    }

    // An expression in GiNaC's syntax as math, or as text when it does not parse.
    std::string math_or_text(const std::string& text) const
    {
        try {
            return "$" + math(d_.symbols.parse({text, {}})) + "$";
        } catch (const std::exception&) {
            return latex_text(text);
        }
    }

    // "x-1 <= 0 (linear in x ...)" → "$x - 1 \leq 0$ (linear in x ...)"
    std::string sign_step(const std::string& step) const
    {
        const auto paren = step.find(" (");
        const std::string claim = step.substr(0, paren);
        std::string why = paren == std::string::npos ? "" : step.substr(paren + 2, step.size() - paren - 3);
        // "M in positive" → "declared positive"
        const auto in = why.find(" in ");
        if (in != std::string::npos && d_.symbols.find(why.substr(0, in)))
            why = "declared " + why.substr(in + 4);
        static const std::pair<const char*, const char*> relations[] = {
            {" >= ", "\\geq"}, {" <= ", "\\leq"}, {" > ", ">"}, {" < ", "<"}};
        for (const auto& [spelling, tex] : relations) {
            const auto at = claim.find(spelling);
            if (at == std::string::npos)
                continue;
            std::string lhs = math_or_text(claim.substr(0, at));
            const std::string rhs = claim.substr(at + std::string(spelling).size());
            if (lhs.front() == '$')
                return fmt::format("${} {} {}$ ({})", lhs.substr(1, lhs.size() - 2), tex, latex_text(rhs),
                                   latex_text(why));
        }
        return latex_text(step);
    }

    std::string limit_method(const std::string& method) const
    {
        // "by substitution: continuous there, its denominator D being > 0"
        const std::string substitution = "by substitution: continuous there, its denominator ";
        if (method.rfind(substitution, 0) == 0) {
            const std::string rest = method.substr(substitution.size());
            const auto being = rest.find(" being ");
            std::string sign = being == std::string::npos ? "" : rest.substr(being + 7);
            if (sign == ">= 0" || sign == "> 0" || sign == "< 0" || sign == "<= 0" || sign == "!= 0") {
                static const std::map<std::string, std::string> tex = {
                    {">= 0", "\\geq 0"}, {"> 0", "> 0"}, {"< 0", "< 0"}, {"<= 0", "\\leq 0"}, {"!= 0", "\\neq 0"}};
                return fmt::format("by substitution (continuous there: its denominator {} is ${}$)",
                                   math_or_text(rest.substr(0, being)), tex.at(sign));
            }
        }
        // "substituting s = 1/t and letting t -> 0+: the leading term in 1/s is E"
        const std::string leading = ": the leading term in 1/";
        if (method.rfind("substituting ", 0) == 0 && method.find(leading) != std::string::npos) {
            const auto eq = method.find(" = 1/t");
            const auto is = method.find(" is ", method.find(leading));
            if (eq != std::string::npos && is != std::string::npos) {
                const std::string s = math_or_text(method.substr(13, eq - 13));
                return fmt::format("by substituting {} $= 1/t$ and letting $t \\to 0^+$: the leading term is {}", s,
                                   math_or_text(method.substr(is + 4)));
            }
        }
        return latex_text(method);
    }

    // Math set inline when it is short and flat, displayed (and broken) otherwise.
    static bool wants_display(const std::string& math)
    {
        return latex_width(math) > 230 || nested_fraction(math);
    }

    std::string display(const std::string& lhs, const char* relation, const GiNaC::ex& rhs,
                        const written_form* w) const
    {
        return "\n\\begin{align*}\n" + rows(lhs, rhs, w, "", relation) + "\n\\end{align*}\n";
    }

    std::string claim_lhs(const engine::check_result& c, const written_form* w) const
    {
        std::string lhs = math(c.stated.lhs(), w);
        if (c.limit) {
            const std::string point = c.limit->to_infinity ? "\\infty" : math(c.limit->point);
            lhs = fmt::format("\\lim_{{{} \\to {}}} {}", math(c.limit->symbol), point, lhs);
        }
        return lhs;
    }

    std::string checks() const
    {
        if (d_.checks.empty())
            return "";
        std::string out = "\n\\paragraph{Checks.}\n\\begin{itemize}\n";
        for (const engine::check_result& c : d_.checks) {
            // A display form is the result typeset above: say so, do not print it again.
            if (c.name.rfind("display form of ", 0) == 0) {
                const std::string name = c.name.substr(16);
                const engine::quantity* q = d_.symbols.find(name);
                const engine::result* r = d_.find_result(name);
                // Only a numbered result has a number to refer to.
                const std::string where = r && !r->paper.empty()
                                              ? fmt::format(", \\eqref{{{}:result:{}}},", latex_label(d_), name)
                                              : "";
                out += fmt::format("\\item {} --- the display form of ${}${} equals the derived result.\n",
                                   status_text(c.outcome), q ? math(q->symbol) : latex_text(name), where);
                continue;
            }
            written_form w;
            if (const spec::check* source = spec_check(c.name))
                w = written(source->claim.value);
            out += fmt::format("\\item {} --- {}: ", status_text(c.outcome), latex_text(words(c.name)));
            const std::string inline_math = claim_math(c, order_, &w);
            const bool shown = wants_display(inline_math);
            out += shown ? display(claim_lhs(c, &w), latex_relation(c.op), c.stated.rhs(), &w)
                         : "$" + inline_math + "$";
            std::vector<std::string> conditions;
            std::vector<std::string> at;
            for (const auto& [symbol, value] : c.at)
                at.push_back(fmt::format("${} = {}$", math(symbol), math(value)));
            if (!at.empty())
                conditions.push_back("at " + listing(at));
            std::vector<std::string> assuming;
            for (const auto& [symbol, range] : c.assuming)
                assuming.push_back(fmt::format("${} \\in {}$", math(symbol), range));
            if (!assuming.empty())
                conditions.push_back("for " + listing(assuming));
            std::vector<std::string> left;
            for (const auto& [symbol, value] : c.left_at)
                left.push_back(fmt::format("${} \\to {}$", math(symbol), math(value)));
            if (!left.empty())
                conditions.push_back("the left side taken at " + listing(left));
            // After a displayed claim the text starts a new sentence.
            if (!conditions.empty())
                out += shown ? capitalised(listing(conditions)) + "."
                             : (c.left_at.empty() || !c.at.empty() ? " " : ", ") + listing(conditions) + ".";
            else if (!shown)
                out += ".";
            if (!c.because.empty())
                out += (shown && conditions.empty() ? "" : " ") + sentence_end(capitalised(latex_text(c.because)));
            out += how(c) + "\n";
        }
        return out + "\\end{itemize}\n";
    }

    // A printed or derived form: inline when short, else displayed and broken.
    bool displayed(const GiNaC::ex& e, const written_form* w) const
    {
        return wants_display(e.info(GiNaC::info_flags::relation) ? relation_math(e, w) : math(e, w));
    }

    std::string form(const GiNaC::ex& e, const written_form* w) const
    {
        if (!displayed(e, w))
            return "$" + (e.info(GiNaC::info_flags::relation) ? relation_math(e, w) : math(e, w)) + "$";
        if (e.info(GiNaC::info_flags::relation))
            return display(math(e.lhs(), w), "=", e.rhs(), w);
        return display("", "", e, w);
    }

    // Each of the paper's items: what it prints or says, the verdict, and for a
    // disagreement what is derived and the smallest change that reconciles the two.
    // Text after a displayed formula starts a new sentence.
    std::string paper() const
    {
        if (d_.paper_checks.empty())
            return "";
        std::string out = "\n\\paragraph{The paper, held to account.}\n\\begin{itemize}\n";
        for (const engine::paper_comparison& p : d_.paper_checks) {
            out += fmt::format("\\item {}, \\texttt{{{}}}: ", paper_text(p.paper), breakable(latex_text(p.subject)));
            bool after_display = false;
            if (p.what == engine::paper_comparison::kind::claim) {
                out += fmt::format("``{}''", breakable(latex_text(p.printed_text)));
            } else {
                const written_form w = written(p.printed_text);
                out += "printed " + form(p.printed, &w);
                after_display = displayed(p.printed, &w);
            }
            if (p.agrees()) {
                out += after_display ? "It agrees.\n" : " --- agrees.\n";
                continue;
            }
            out += after_display ? "It \\textbf{disagrees}: derived " : " --- \\textbf{disagrees}: derived ";
            out += form(p.derived, nullptr);
            after_display = displayed(p.derived, nullptr);
            if (!p.reconciliations.empty()) {
                const std::string change =
                    breakable(latex_text(fmt::format("{}", fmt::join(p.reconciliations, "; "))));
                out += after_display ? "Smallest change: " + change : "; smallest change: " + change;
            }
            out += after_display && p.reconciliations.empty() ? "\n" : ".\n";
        }
        return out + "\\end{itemize}\n";
    }

public:
    // The paper comparisons as rows of the report's errata table.
    std::string errata_rows() const
    {
        // Math wider than its column (printed 4.3 cm, derived 3.5 cm) is left to the
        // derivation's section: a fraction cannot be broken across lines of a table cell.
        // Set in 8 pt, inline math is about 0.75 of its displayed width (measured).
        auto cell = [&](const GiNaC::ex& e, const written_form* w, double column_pt) {
            const std::string m = e.info(GiNaC::info_flags::relation) ? relation_math(e, w) : math(e, w);
            // Inline math breaks after + - = at its outer level, never inside \frac or \sqrt.
            const bool unbreakable = m.find("\\frac") != std::string::npos || m.find("\\sqrt") != std::string::npos;
            if ((unbreakable && 0.75 * latex_width(m) > column_pt - 4) || nested_fraction(m))
                return fmt::format("\\emph{{too long for the table, see Section~\\ref{{{}}}}}", latex_label(d_));
            return "$" + m + "$";
        };
        std::string out;
        for (const engine::paper_comparison& p : d_.paper_checks) {
            std::string printed;
            if (p.what == engine::paper_comparison::kind::claim) {
                printed = "``" + breakable(latex_text(p.printed_text)) + "''";
            } else {
                const written_form w = written(p.printed_text);
                printed = cell(p.printed, &w, 122);
            }
            std::string change = "---";
            if (!p.agrees())
                change = p.reconciliations.empty()
                             ? "no single change; see the derived form"
                             : breakable(latex_text(fmt::format("{}", fmt::join(p.reconciliations, "; "))));
            out += fmt::format("{} & {} (\\ref{{{}}}) & {} & {} & {} & {} \\\\\n", paper_text(p.paper),
                               breakable(latex_text(p.subject)), latex_label(d_),
                               p.agrees() ? "agrees" : "\\textbf{disagrees}", printed,
                               p.agrees() ? "" : cell(p.derived, nullptr, 99), change);
        }
        return out;
    }

private:
    // Long names and GiNaC expressions in text may break after _ * + / , and =.
    static std::string breakable(const std::string& text)
    {
        std::string out;
        for (std::size_t i = 0; i < text.size(); ++i) {
            out += text[i];
            const bool after = text[i] == '*' || text[i] == '+' || text[i] == '/' || text[i] == ',' ||
                               text[i] == '=' || (text[i] == '_' && i > 0 && text[i - 1] == '\\');
            if (after)
                out += "\\allowbreak{}";
        }
        return out;
    }

    // The text width of the report (A4, 2 cm margins: 482 pt) less a list's indent: steps
    // and checks are items of a list.
    static constexpr double content_width = 450;

    const engine::derivation& d_;
    const term_order order_;
    std::map<std::string, std::string> tags_;
};

} // namespace

std::string claim_math(const engine::check_result& c, const term_order& order, const written_form* written)
{
    std::string lhs = latex(c.stated.lhs(), order, written);
    if (c.limit) {
        const std::string point = c.limit->to_infinity ? "\\infty" : latex(c.limit->point, order);
        lhs = fmt::format("\\lim_{{{} \\to {}}} {}", latex(c.limit->symbol, order), point, lhs);
    }
    return fmt::format("{} {} {}", lhs, latex_relation(c.op), latex(c.stated.rhs(), order, written));
}

std::string latex(const GiNaC::ex& e, const term_order& order, const written_form* written)
{
    register_print_functions();
    std::ostringstream out;
    const print_tex c(out, order, written && !written->empty() ? written : nullptr);
    print_operand(e, c, 0);
    return out.str();
}

std::vector<std::string> latex_lines(const GiNaC::ex& e, const term_order& order, const written_form* written,
                                     double width)
{
    register_print_functions();
    std::ostringstream unused;
    const print_tex c(unused, order, written && !written->empty() ? written : nullptr);
    return break_lines(e, c, width, width);
}

double latex_width(const std::string& math)
{
    // The glyph table is rough; this factor makes it agree, within a few per cent, with
    // widths pdflatex measured for formulas of the report (\settowidth).
    return 1.1 * width_reader(math).all();
}

std::string latex_text(const std::string& text)
{
    std::string out;
    for (char ch : text) {
        switch (ch) {
        case '\\': out += "\\textbackslash{}"; break;
        case '_': case '%': case '&': case '#': case '$': case '{': case '}':
            out += '\\';
            out += ch;
            break;
        // OT1 accents, not the text companion's \textasciicircum (a bitmap font without cm-super).
        case '~': out += "\\~{}"; break;
        case '^': out += "\\^{}"; break;
        case '<': out += "\\textless{}"; break;
        case '>': out += "\\textgreater{}"; break;
        case '|': out += "\\textbar{}"; break;
        default: out += ch;
        }
    }
    return out;
}

std::string latex_fragment_name(const engine::derivation& d)
{
    return d.id() + ".tex";
}

std::string latex_label(const engine::derivation& d)
{
    return "impact:" + d.id();
}

std::string latex_fragment(const engine::derivation& d)
{
    return fragment_writer(d).write();
}

std::string latex_errata_rows(const std::vector<const engine::derivation*>& derivations)
{
    std::string out;
    for (const engine::derivation* d : derivations)
        out += fragment_writer(*d).errata_rows();
    return out;
}

} // namespace impact::emit
