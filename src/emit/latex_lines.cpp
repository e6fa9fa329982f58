// Line breaking for displayed equations, and the widths it decides by.
#include "emit/latex.h"

#include "emit/latex_parts.h"

#include <algorithm>
#include <map>
#include <sstream>

namespace impact::emit {

using namespace detail;

namespace {


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

} // namespace

std::vector<std::string> latex_lines(const GiNaC::ex& e, const term_order& order, const written_form* written,
                                     double width)
{
    register_print_functions();
    std::ostringstream unused;
    const print_tex c(unused, order, written && !written->empty() ? written : nullptr);
    return break_lines(e, c, width, width);
}

std::vector<std::string> latex_lines(const GiNaC::ex& e, const term_order& order, const written_form* written,
                                     double first_width, double other_width)
{
    register_print_functions();
    std::ostringstream unused;
    const print_tex c(unused, order, written && !written->empty() ? written : nullptr);
    return break_lines(e, c, first_width, other_width);
}

double latex_width(const std::string& math)
{
    // The glyph table is rough; this factor makes it agree, within a few per cent, with
    // widths pdflatex measured for formulas of the report (\settowidth).
    return 1.1 * width_reader(math).all();
}

} // namespace impact::emit
