#include "emit/latex.h"

#include <fmt/format.h>

#include <map>
#include <sstream>

namespace impact::emit {

GINAC_IMPLEMENT_PRINT_CONTEXT(print_tex, GiNaC::print_context)

print_tex::print_tex() : GiNaC::print_context(std::cout) {}
print_tex::print_tex(std::ostream& os, const term_order& order) : GiNaC::print_context(os), order(&order) {}

namespace {

constexpr unsigned sum_level = 10;
constexpr unsigned product_level = 20;
constexpr unsigned atom_level = 30;

struct parenthesise {
    parenthesise(const print_tex& c, unsigned level, unsigned own) : c_(c), open_(own < level)
    {
        if (open_)
            c_.s << "\\left(";
    }
    ~parenthesise()
    {
        if (open_)
            c_.s << "\\right)";
    }
    const print_tex& c_;
    bool open_;
};

void print_operand(const GiNaC::ex& e, const print_tex& c, unsigned level);

void print_numeric(const GiNaC::numeric& n, const print_tex& c, unsigned level)
{
    if (!n.is_rational())
        throw std::invalid_argument("cannot typeset an inexact number");
    const bool negative = n.is_negative();
    parenthesise p(c, level, negative ? product_level : atom_level);
    if (negative)
        c.s << '-';
    const GiNaC::numeric a = GiNaC::abs(n);
    if (a.is_integer())
        c.s << a;
    else
        c.s << "\\frac{" << a.numer() << "}{" << a.denom() << '}';
}

void print_symbol(const GiNaC::symbol& s, const print_tex& c, unsigned)
{
    c.s << s.get_TeX_name();
}

void print_add(const GiNaC::add& sum, const print_tex& c, unsigned level)
{
    parenthesise p(c, level, sum_level);
    bool first = true;
    for (const GiNaC::ex& term : c.order->terms(sum)) {
        if (c.order->negative(term)) {
            c.s << (first ? "-" : " - ");
            print_operand(-term, c, product_level);
        } else {
            if (!first)
                c.s << " + ";
            print_operand(term, c, sum_level);
        }
        first = false;
    }
}

void print_power_term(const term_order::power_term& p, const print_tex& c, unsigned level);

// Factors side by side; two numbers in a row need a \cdot between them.
void print_factors(const std::vector<term_order::power_term>& factors, const print_tex& c, unsigned level)
{
    for (std::size_t i = 0; i < factors.size(); ++i) {
        if (i > 0)
            c.s << (GiNaC::is_a<GiNaC::numeric>(factors[i].base) ? " \\cdot " : " ");
        print_power_term(factors[i], c, factors.size() == 1 ? level : product_level);
    }
}

void print_mul(const GiNaC::mul& product, const print_tex& c, unsigned level)
{
    const term_order::fraction f = c.order->split(product);
    parenthesise p(c, level, product_level);
    if (f.negated)
        c.s << '-';
    if (f.denominator.empty()) {
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
}

// base^exponent, the base never rebuilt into a GiNaC power (see engine/order.h).
void print_power_term(const term_order::power_term& p, const print_tex& c, unsigned level)
{
    const GiNaC::ex& base = p.base;
    const GiNaC::ex& exponent = p.exponent;
    if (exponent.is_equal(1)) {
        print_operand(base, c, level);
        return;
    }
    if (GiNaC::is_a<GiNaC::numeric>(exponent)) {
        const GiNaC::numeric n = GiNaC::ex_to<GiNaC::numeric>(exponent);
        if (n.is_negative()) {
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
    // The base in braces: v'_M squared is {v'_M}^{2}, not a double superscript.
    c.s << '{';
    print_operand(base, c, atom_level + 1);
    c.s << "}^{";
    print_operand(exponent, c, 0);
    c.s << '}';
}

void print_power(const GiNaC::power& power, const print_tex& c, unsigned level)
{
    // (v_m - v_M)^2, never (-v_M + v_m)^2: a sum in the base leads with a positive term.
    bool negated = false;
    const term_order::power_term p = c.order->oriented(power, negated);
    parenthesise paren(c, level, negated ? product_level : atom_level + 1);
    if (negated)
        c.s << '-';
    print_power_term(p, c, negated ? atom_level : level);
}

void print_operand(const GiNaC::ex& e, const print_tex& c, unsigned level)
{
    if (GiNaC::is_a<GiNaC::function>(e)) {
        static const std::map<std::string, std::string> names = {
            {"acos", "\\arccos"}, {"asin", "\\arcsin"}, {"atan", "\\arctan"}, {"cos", "\\cos"},
            {"sin", "\\sin"},     {"tan", "\\tan"},     {"exp", "\\exp"},     {"log", "\\ln"},
        };
        const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
        if (name == "abs") {
            c.s << "\\left|";
            print_operand(e.op(0), c, 0);
            c.s << "\\right|";
            return;
        }
        const auto known = names.find(name);
        c.s << (known != names.end() ? known->second : "\\operatorname{" + name + "}") << "\\left(";
        for (std::size_t i = 0; i < e.nops(); ++i) {
            if (i > 0)
                c.s << ", ";
            print_operand(e.op(i), c, 0);
        }
        c.s << "\\right)";
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

// "Eq. 8" → "8"; the tag of a numbered result.
std::string equation_tag(const std::string& paper)
{
    const std::string prefix = "Eq. ";
    return paper.rfind(prefix, 0) == 0 ? paper.substr(prefix.size()) : paper;
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

} // namespace

std::string latex_relation(engine::relation op)
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

std::string claim_math(const engine::check_result& c, const term_order& order)
{
    std::string lhs = latex(c.stated.lhs(), order);
    if (c.limit) {
        const std::string point = c.limit->to_infinity ? "\\infty" : latex(c.limit->point, order);
        lhs = fmt::format("\\lim_{{{} \\to {}}} {}", latex(c.limit->symbol, order), point, lhs);
    }
    return fmt::format("{} {} {}", lhs, latex_relation(c.op), latex(c.stated.rhs(), order));
}

std::string latex(const GiNaC::ex& e, const term_order& order)
{
    register_print_functions();
    std::ostringstream out;
    print_tex c(out, order);
    print_operand(e, c, 0);
    return out.str();
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
        case '~': out += "\\textasciitilde{}"; break;
        case '^': out += "\\textasciicircum{}"; break;
        default: out += ch;
        }
    }
    return out;
}

std::string latex_fragment_name(const engine::derivation& d)
{
    return d.id() + ".tex";
}

std::string latex_fragment(const engine::derivation& d)
{
    const term_order order = engine::declaration_order(d.symbols);
    auto math = [&](const GiNaC::ex& e) { return latex(e, order); };
    auto relation = [&](const GiNaC::ex& r) { return math(r.lhs()) + " &= " + math(r.rhs()); };

    std::string out = fmt::format("% Generated by Impact from {}; do not edit.\n", d.source_name());
    out += fmt::format("\\subsection*{{{}{}}}\n", latex_text(d.source.title.value),
                       d.source.paper ? " (" + latex_text(d.source.paper->value) + ")" : "");
    if (!d.source.summary.value.empty())
        out += latex_text(d.source.summary.value) + "\n";

    out += "\n\\paragraph{Quantities.}\n\\begin{itemize}\n";
    for (const engine::quantity& q : d.symbols.all()) {
        if (q.definition)
            out += fmt::format("\\item ${} = {}$", q.latex, math(*q.definition));
        else
            out += fmt::format("\\item ${} {}$", q.latex, q.range.to_latex());
        out += q.meaning.empty() ? "\n" : ": " + latex_text(q.meaning) + "\n";
    }
    out += "\\end{itemize}\n";

    if (!d.givens.empty()) {
        out += "\n\\paragraph{Given.}\n\\begin{align}\n";
        for (std::size_t i = 0; i < d.givens.size(); ++i) {
            const engine::equation& g = d.givens[i];
            out += fmt::format("  {} && \\text{{{}}}{} \\notag{}\n", relation(g.relation), latex_text(g.because),
                               g.paper.empty() ? "" : " \\text{(" + latex_text(g.paper) + ")}",
                               i + 1 < d.givens.size() ? " \\\\" : "");
        }
        out += "\\end{align}\n";
    }

    if (!d.steps.empty()) {
        out += "\n\\paragraph{Steps.}\n\\begin{enumerate}\n";
        for (const engine::step_result& s : d.steps) {
            out += "\\item " + latex_text(s.description);
            if (!s.because.empty())
                out += ": " + latex_text(s.because);
            out += ".\n";
            std::vector<std::string> rows;
            for (const auto& [symbol, value] : s.values)
                rows.push_back(math(symbol) + " &= " + math(value));
            if (s.yields)
                rows.push_back(relation(s.yields->relation));
            if (!rows.empty())
                out += fmt::format("\\begin{{align*}}\n  {}\n\\end{{align*}}\n", fmt::join(rows, " \\\\\n  "));
            for (const GiNaC::ex& assumption : s.assumptions)
                out += fmt::format("Assumes ${} \\neq {}$.\n", math(assumption.lhs()), math(assumption.rhs()));
            for (const engine::check_result& c : s.checks)
                out += fmt::format("Check: {} --- {}.\n", latex_text(c.name), status_text(c.outcome));
        }
        out += "\\end{enumerate}\n";
    }

    out += "\n\\paragraph{Results.}\n\\begin{align}\n";
    std::map<std::string, int> used_tags;
    for (const engine::result& r : d.results)
        ++used_tags[r.paper];
    std::map<std::string, int> next_letter;
    for (std::size_t i = 0; i < d.results.size(); ++i) {
        const engine::result& r = d.results[i];
        std::string tag = "\\notag";
        if (!r.paper.empty()) {
            std::string t = equation_tag(r.paper);
            if (used_tags[r.paper] > 1)
                t += static_cast<char>('a' + next_letter[r.paper]++);
            tag = fmt::format("\\tag{{{}}}", t);
        }
        out += fmt::format("  {} &= {} {}{}\n", math(r.symbol), math(r.display), tag,
                           i + 1 < d.results.size() ? " \\\\" : "");
    }
    out += "\\end{align}\n";

    out += "\n\\paragraph{Checks.}\n\\begin{itemize}\n";
    for (const engine::check_result& c : d.checks) {
        out += fmt::format("\\item {}: ${}$", latex_text(c.name), claim_math(c, order));
        for (std::size_t i = 0; i < c.at.size(); ++i)
            out += fmt::format("{}${} = {}$", i == 0 ? " at " : ", ", math(c.at[i].first), math(c.at[i].second));
        for (std::size_t i = 0; i < c.assuming.size(); ++i)
            out += fmt::format("{}${} \\in {}$", i == 0 ? " for " : ", ", math(c.assuming[i].first),
                               c.assuming[i].second);
        for (std::size_t i = 0; i < c.left_at.size(); ++i)
            out += fmt::format("{}${} \\to {}$", i == 0 ? ", the left side taken at " : ", ",
                               math(c.left_at[i].first), math(c.left_at[i].second));
        out += " --- " + status_text(c.outcome);
        if (!c.because.empty())
            out += " (" + latex_text(c.because) + ")";
        out += "\n";
    }
    out += "\\end{itemize}\n";

    if (!d.paper_checks.empty()) {
        out += "\n\\paragraph{The paper, held to account.}\n\\begin{itemize}\n";
        for (const engine::paper_comparison& p : d.paper_checks) {
            out += fmt::format("\\item {}, \\texttt{{{}}}: ", latex_text(p.paper), latex_text(p.subject));
            if (p.what == engine::paper_comparison::kind::claim)
                out += fmt::format("``{}'' --- ", latex_text(p.printed_text));
            else if (p.printed.info(GiNaC::info_flags::relation))
                out += fmt::format("printed ${} = {}$ --- ", math(p.printed.lhs()), math(p.printed.rhs()));
            else
                out += fmt::format("printed ${}$ --- ", math(p.printed));
            if (p.agrees()) {
                out += "agrees.\n";
                continue;
            }
            out += "\\textbf{disagrees}: derived ";
            out += p.derived.info(GiNaC::info_flags::relation)
                       ? fmt::format("${} = {}$", math(p.derived.lhs()), math(p.derived.rhs()))
                       : fmt::format("${}$", math(p.derived));
            if (!p.reconciliations.empty())
                out += fmt::format("; reconciled by {}", latex_text(fmt::format("{}", fmt::join(p.reconciliations, "; "))));
            out += ".\n";
        }
        out += "\\end{itemize}\n";
    }
    return out;
}

} // namespace impact::emit
