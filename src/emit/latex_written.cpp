// A form typeset exactly as its derivation file transcribes it: the paper's printed lines,
// which the errata must show as printed. GiNaC would merge m v + m ε v + m v - m ε v into
// 2 m v; this printer walks the tree of the text instead (written_form::tree), so every
// term, factor, sign and parenthesis stays where the paper put it. Only the typesetting
// is Impact's: quotients as \frac, square roots, primes sharing a superscript.
#include "emit/latex.h"
#include "emit/latex_parts.h"

#include <fmt/format.h>

namespace impact::emit {
namespace {

using node = written_form::node;

const node& unwrapped(const node& n)
{
    return n.what == node::kind::group ? unwrapped(n.children[0]) : n;
}

const char* relation_tex(const std::string& op)
{
    if (op == "<=")
        return "\\leq";
    if (op == ">=")
        return "\\geq";
    if (op == "!=")
        return "\\neq";
    if (op == "<" || op == ">")
        return op == "<" ? "<" : ">";
    return "=";
}

class written_printer {
public:
    explicit written_printer(const term_order& order) : order_(order) {}

    std::string print(const node& n) const
    {
        switch (n.what) {
        case node::kind::atom: return atom(n.value);
        case node::kind::group: return detail::parenthesised(print(n.children[0]));
        case node::kind::negate: return "-" + print(n.children[0]);
        case node::kind::sum: {
            std::string out;
            for (std::size_t i = 0; i < n.children.size(); ++i)
                out += (i == 0 ? (n.flags[i] ? "-" : "") : (n.flags[i] ? " - " : " + ")) + print(n.children[i]);
            return out;
        }
        case node::kind::product: return product(n);
        case node::kind::power: return power(n);
        case node::kind::call: return call(n);
        case node::kind::relation: {
            std::string out;
            for (std::size_t i = 0; i < n.children.size(); ++i)
                out += (i == 0 ? "" : fmt::format(" {} ", relation_tex(n.name))) + print(n.children[i]);
            return out;
        }
        }
        return "";
    }

private:
    std::string atom(const GiNaC::ex& value) const
    {
        if (GiNaC::is_a<GiNaC::symbol>(value))
            return detail::symbol_latex(GiNaC::ex_to<GiNaC::symbol>(value));
        return latex(value, order_);
    }

    // What stands alone in a numerator, a denominator, an exponent or an argument needs
    // no parentheses of its own.
    std::string bare(const node& n) const { return print(unwrapped(n)); }

    // a*b/c*d/e as a textbook sets it: each run of factors over the divisors that follow
    // it, \frac{a b}{c} \frac{d}{e}; 1/2*m*v^2 as \frac{1}{2} m v^2.
    std::string product(const node& n) const
    {
        struct run {
            std::vector<const node*> over, under;
        };
        std::vector<run> runs;
        for (std::size_t i = 0; i < n.children.size(); ++i) {
            if (!n.flags[i] && (runs.empty() || !runs.back().under.empty()))
                runs.emplace_back();
            if (runs.empty())
                runs.emplace_back();
            (n.flags[i] ? runs.back().under : runs.back().over).push_back(&n.children[i]);
        }
        // `alone`: nothing else stands beside them (a ½ carried in front does), so that a
        // single factor needs no parentheses of its own.
        auto factors = [&](const std::vector<const node*>& items, bool alone = true) {
            if (items.size() == 1)
                return alone ? bare(*items[0]) : print(*items[0]);
            // A number after another factor takes a \cdot; a factor after \cos\theta a thin
            // space (cos θ r, not cos θr).
            auto reads_like_function = [&](const node& n) {
                if (n.what != node::kind::atom || !GiNaC::is_a<GiNaC::symbol>(n.value))
                    return false;
                const std::string name = atom(n.value);
                return name.rfind("\\cos", 0) == 0 || name.rfind("\\sin", 0) == 0 || name.rfind("\\tan", 0) == 0;
            };
            std::string out;
            for (std::size_t i = 0; i < items.size(); ++i) {
                const bool number = unwrapped(*items[i]).what == node::kind::atom &&
                                    GiNaC::is_a<GiNaC::numeric>(unwrapped(*items[i]).value);
                const char* gap = i == 0 ? "" : number ? " \\cdot " : reads_like_function(*items[i - 1]) ? " \\, " : " ";
                out += gap + print(*items[i]);
            }
            return out;
        };
        auto is_number = [](const node* n) {
            return unwrapped(*n).what == node::kind::atom && GiNaC::is_a<GiNaC::numeric>(unwrapped(*n).value);
        };
        // 1/2*(1 - eps)*v/(1/2*w): the leading ½ of a quotient belongs to its numerator.
        std::string carried;
        std::string out;
        for (std::size_t i = 0; i < runs.size(); ++i) {
            const run& r = runs[i];
            const bool fraction = r.over.size() == 1 && r.under.size() == 1 && is_number(r.over[0]) &&
                                  is_number(r.under[0]);
            if (fraction && i + 1 < runs.size() && !runs[i + 1].under.empty()) {
                carried = "\\frac{" + bare(*r.over[0]) + "}{" + bare(*r.under[0]) + "} ";
                continue;
            }
            if (!out.empty())
                out += " ";
            // A run without divisors stands beside another run: its one factor keeps its
            // parentheses (1/M*(a - b), not \frac{1}{M} a - b).
            if (r.under.empty())
                out += carried + factors(r.over, false);
            else
                out += "\\frac{" +
                       (r.over.empty() ? (carried.empty() ? std::string("1") : carried.substr(0, carried.size() - 1))
                                       : carried + factors(r.over, carried.empty())) +
                       "}{" + factors(r.under) + "}";
            carried.clear();
        }
        return out;
    }

    std::string power(const node& n) const
    {
        const node& base = n.children[0];
        const std::string exponent = bare(n.children[1]);
        if (base.what == node::kind::atom && GiNaC::is_a<GiNaC::symbol>(base.value))
            return detail::symbol_power(atom(base.value), exponent);
        if (base.what == node::kind::atom || base.what == node::kind::group || base.what == node::kind::call)
            return print(base) + "^{" + exponent + "}";
        return "{" + print(base) + "}^{" + exponent + "}";
    }

    std::string call(const node& n) const
    {
        std::string args;
        for (std::size_t i = 0; i < n.children.size(); ++i)
            args += (i > 0 ? ", " : "") + bare(n.children[i]);
        if (n.name == "sqrt")
            return "\\sqrt{" + args + "}";
        if (n.name == "abs")
            return detail::is_tall(args) ? "\\left|" + args + "\\right|" : "|" + args + "|";
        if (n.name == "diff" && n.children.size() == 2)
            return detail::partial_derivative(bare(n.children[0]), bare(n.children[1]),
                                              n.children[0].what == node::kind::atom &&
                                                  GiNaC::is_a<GiNaC::symbol>(n.children[0].value));
        const auto known = detail::function_names().find(n.name);
        const std::string name =
            known != detail::function_names().end() ? known->second : "\\operatorname{" + n.name + "}";
        return name + detail::parenthesised(args);
    }

    const term_order& order_;
};

// The terms of a sum with their signs, the first without "+".
std::vector<std::string> signed_terms(const node& sum, const written_printer& p)
{
    std::vector<std::string> out;
    for (std::size_t i = 0; i < sum.children.size(); ++i)
        out.push_back((i == 0 ? (sum.flags[i] ? "-" : "") : (sum.flags[i] ? "- " : "+ ")) + p.print(sum.children[i]));
    return out;
}

} // namespace

std::string latex_as_written(const written_form::node& n, const term_order& order)
{
    detail::register_print_functions();
    return written_printer(order).print(n);
}

std::vector<std::string> latex_lines_as_written(const written_form::node& n, const term_order& order,
                                                double width)
{
    detail::register_print_functions();
    const written_printer p(order);
    const std::string whole = p.print(n);
    if (latex_width(whole) <= width)
        return {whole};
    // A long sum breaks before a + or -, as many terms on a line as fit.
    const node& top = n.what == node::kind::negate ? n : unwrapped(n);
    if (top.what != node::kind::sum)
        return {whole};
    std::vector<std::string> lines;
    for (const std::string& term : signed_terms(top, p)) {
        if (!lines.empty() && latex_width(lines.back() + " " + term) <= width)
            lines.back() += " " + term;
        else
            lines.push_back(term);
    }
    return lines;
}

} // namespace impact::emit
