#include "emit/latex.h"

#include "emit/latex_parts.h"

#include "engine/expr/infix.h"
#include "spec/latex_name.h"

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

namespace detail {


// A symbol's LaTeX name: the one its derivation file gives, or one made from its name
// when it has none (spec::latex_of_name: eps → \epsilon, v_M_after → v'_{M}, r_x → r_{x}).
std::string symbol_latex(const GiNaC::symbol& s)
{
    const std::string given = s.get_TeX_name();
    return given.empty() ? spec::latex_of_name(s.get_name()) : given;
}

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

// Pi as \pi: GiNaC's own LaTeX for its constants.
void print_constant(const GiNaC::constant& k, const print_tex& c, unsigned) { k.print(GiNaC::print_latex(c.s)); }

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

bool is_trigonometric_of_symbol(const GiNaC::ex& e);

// Whether a symbol reads like a function (\cos\theta), or is one: what follows it is set apart.
bool reads_like_function(const GiNaC::ex& base)
{
    if (is_trigonometric_of_symbol(base))
        return true;
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

// cos, sin or tan of a symbol, which a textbook writes without parentheses: \cos\theta.
bool is_trigonometric_of_symbol(const GiNaC::ex& e)
{
    if (!GiNaC::is_a<GiNaC::function>(e) || e.nops() != 1 || !GiNaC::is_a<GiNaC::symbol>(e.op(0)))
        return false;
    const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
    return name == "cos" || name == "sin" || name == "tan";
}

// A function's argument: in parentheses, or for cos, sin and tan of a symbol set after
// the name as a textbook does (\cos\theta, \sin x); a symbol whose name is two words
// (\Delta E_K) keeps its parentheses.
std::string function_argument(const GiNaC::ex& f, const std::string& rendered)
{
    if (!is_trigonometric_of_symbol(f) || rendered.find(' ') != std::string::npos)
        return parenthesised(rendered);
    return rendered.rfind("\\", 0) == 0 ? rendered : " " + rendered;
}

const std::map<std::string, std::string>& function_names()
{
    static const std::map<std::string, std::string> names = {
        {"acos", "\\arccos"}, {"asin", "\\arcsin"}, {"atan", "\\arctan"}, {"cos", "\\cos"},
        {"sin", "\\sin"},     {"tan", "\\tan"},     {"exp", "\\exp"},     {"log", "\\ln"},
    };
    return names;
}

std::string partial_derivative(const std::string& f, const std::string& x, bool named)
{
    if (named)
        return "\\frac{\\partial " + f + "}{\\partial " + x + "}";
    return "\\frac{\\partial}{\\partial " + x + "} " + parenthesised(f);
}

// base^exponent, the base never rebuilt into a GiNaC power (see engine/expr/order.h).
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
            c.s << known->second << "^{" << power << "}" << function_argument(base, render(base.op(0), c, 0));
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
    if (name == "diff") {
        c.s << partial_derivative(render(f.op(0), c, 0), render(f.op(1), c, 0), GiNaC::is_a<GiNaC::symbol>(f.op(0)));
        return;
    }
    const auto known = function_names().find(name);
    std::string args;
    for (std::size_t i = 0; i < f.nops(); ++i)
        args += (i > 0 ? ", " : "") + render(f.op(i), c, 0);
    c.s << (known != function_names().end() ? known->second : "\\operatorname{" + name + "}")
        << function_argument(f, args);
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
        GiNaC::set_print_func<GiNaC::constant, print_tex>(print_constant);
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

} // namespace detail

using detail::print_operand;
using detail::register_print_functions;

std::string latex(const GiNaC::ex& e, const term_order& order, const written_form* written)
{
    register_print_functions();
    std::ostringstream out;
    const print_tex c(out, order, written && !written->empty() ? written : nullptr);
    print_operand(e, c, 0);
    return out.str();
}

} // namespace impact::emit
