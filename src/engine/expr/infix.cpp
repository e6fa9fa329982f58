#include "engine/expr/infix.h"

#include "engine/expr/symbols.h"

#include <fmt/format.h>

#include <sstream>

namespace impact::engine {

GINAC_IMPLEMENT_PRINT_CONTEXT(print_infix, GiNaC::print_context)

GINAC_IMPLEMENT_PRINT_CONTEXT(print_ginac_syntax, print_infix)

print_infix::print_infix() : GiNaC::print_context(std::cout) {}
print_infix::print_infix(std::ostream& os, const term_order& order, infix_style style)
    : GiNaC::print_context(os), order(&order), style(style)
{
}

print_ginac_syntax::print_ginac_syntax() : print_infix() {}
print_ginac_syntax::print_ginac_syntax(std::ostream& os, const term_order& order)
    : print_infix(os, order, {"*", "+", "-", "/", "", false, false})
{
}

namespace {

// Precedences of the text written: a parent asks for at least `level` and a child
// with a lower precedence puts itself in parentheses.
constexpr unsigned sum_level = 10;
constexpr unsigned product_level = 20;
constexpr unsigned atom_level = 30;

struct parenthesise {
    parenthesise(const print_infix& c, unsigned level, unsigned own) : c_(c), open_(own < level)
    {
        if (open_)
            c_.s << '(';
    }
    ~parenthesise()
    {
        if (open_)
            c_.s << ')';
    }
    const print_infix& c_;
    bool open_;
};

void print_operand(const GiNaC::ex& e, const print_infix& c, unsigned level);

void print_integer(const GiNaC::numeric& n, const print_infix& c)
{
    if (c.style.typed_numbers)
        c.s << "Real(" << n << ')';
    else
        c.s << n;
}

void print_numeric(const GiNaC::numeric& n, const print_infix& c, unsigned level)
{
    if (!n.is_rational())
        throw std::invalid_argument(fmt::format("cannot print the inexact number {} exactly",
                                                ginac_text(n)));
    const bool negative = n.is_negative();
    parenthesise p(c, level, negative || !n.is_integer() ? product_level : atom_level);
    if (negative)
        c.s << '-';
    print_integer(GiNaC::abs(n.numer()), c);
    if (!n.is_integer()) {
        c.s << c.style.divide;
        print_integer(n.denom(), c);
    }
}

void print_symbol(const GiNaC::symbol& s, const print_infix& c, unsigned)
{
    c.s << s.get_name();
}

void print_add(const GiNaC::add& sum, const print_infix& c, unsigned level)
{
    parenthesise p(c, level, sum_level);
    bool first = true;
    for (const GiNaC::ex& term : c.order->terms(sum)) {
        if (c.order->negative(term)) {
            c.s << (first ? "-" : c.style.minus);
            print_operand(-term, c, product_level);
        } else {
            if (!first)
                c.s << c.style.plus;
            print_operand(term, c, sum_level);
        }
        first = false;
    }
}

void print_power_term(const term_order::power_term& p, const print_infix& c, unsigned level);

void print_factors(const std::vector<term_order::power_term>& factors, const print_infix& c)
{
    for (std::size_t i = 0; i < factors.size(); ++i) {
        if (i > 0)
            c.s << c.style.times;
        print_power_term(factors[i], c, product_level);
    }
}

// A product as numerator / denominator, with integer numbers of the coefficient
// written in place: 2 * m * v_m / (M + m).
void print_mul(const GiNaC::mul& product, const print_infix& c, unsigned level)
{
    const term_order::fraction f = c.order->split(product);
    parenthesise p(c, level, product_level);
    if (f.negated)
        c.s << '-';
    if (f.numerator.empty())
        print_integer(1, c);
    print_factors(f.numerator, c);
    if (f.denominator.empty())
        return;
    c.s << c.style.divide;
    if (f.denominator.size() == 1) {
        print_power_term(f.denominator.front(), c, atom_level);
    } else {
        c.s << '(';
        print_factors(f.denominator, c);
        c.s << ')';
    }
}

// base^exponent, the base never rebuilt into a GiNaC power (see engine/expr/order.h).
void print_power_term(const term_order::power_term& p, const print_infix& c, unsigned level)
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
            // x^-k = 1 / x^k
            parenthesise p(c, level, product_level);
            print_integer(1, c);
            c.s << c.style.divide;
            print_power_term({base, -n}, c, atom_level);
            return;
        }
        if (n.is_integer() && n <= 4 && c.style.powers_as_products) {
            // Small integer powers as products: x * x * x.
            parenthesise p(c, level, product_level);
            for (int i = 0; i < n.to_int(); ++i) {
                if (i > 0)
                    c.s << c.style.times;
                print_operand(base, c, atom_level);
            }
            return;
        }
        if (n == GiNaC::numeric(1, 2)) {
            c.s << c.style.functions << "sqrt(";
            print_operand(base, c, 0);
            c.s << ')';
            return;
        }
    }
    if (c.style.powers_as_products) {
        c.s << c.style.functions << "pow(";
        print_operand(base, c, 0);
        c.s << ", ";
        print_operand(exponent, c, 0);
        c.s << ')';
        return;
    }
    parenthesise paren(c, level, atom_level);
    print_operand(base, c, atom_level + 1);
    c.s << '^';
    print_operand(exponent, c, atom_level);
}

void print_power(const GiNaC::power& power, const print_infix& c, unsigned level)
{
    // (v_m - v_M)^2, never (-v_M + v_m)^2: a sum in the base leads with a positive term.
    bool negated = false;
    const term_order::power_term p = c.order->oriented(power, negated);
    parenthesise paren(c, level, negated ? product_level : atom_level + 1);
    if (negated)
        c.s << '-';
    print_power_term(p, c, negated ? atom_level : level);
}

// Functions are named in the style's way (std::acos), which GiNaC's function printing
// cannot be told.
void print_operand(const GiNaC::ex& e, const print_infix& c, unsigned level)
{
    if (GiNaC::is_a<GiNaC::function>(e)) {
        c.s << c.style.functions << GiNaC::ex_to<GiNaC::function>(e).get_name() << '(';
        for (std::size_t i = 0; i < e.nops(); ++i) {
            if (i > 0)
                c.s << ", ";
            print_operand(e.op(i), c, 0);
        }
        c.s << ')';
        return;
    }
    e.print(c, level);
}

void print_relational(const GiNaC::relational& r, const print_infix& c, unsigned)
{
    print_operand(r.lhs(), c, 0);
    c.s << (r.info(GiNaC::info_flags::relation_equal) ? " = " : " != ");
    print_operand(r.rhs(), c, 0);
}

// The print functions are registered once, before the first use of the context.
void register_print_functions()
{
    static const bool registered = [] {
        GiNaC::set_print_func<GiNaC::relational, print_infix>(print_relational);
        GiNaC::set_print_func<GiNaC::numeric, print_infix>(print_numeric);
        GiNaC::set_print_func<GiNaC::symbol, print_infix>(print_symbol);
        // Pi (and GiNaC's other constants) by the name GiNaC's parser reads back.
        GiNaC::set_print_func<GiNaC::constant, print_infix>(
            +[](const GiNaC::constant& k, const print_infix& c, unsigned) { k.print(GiNaC::print_dflt(c.s)); });
        GiNaC::set_print_func<GiNaC::add, print_infix>(print_add);
        GiNaC::set_print_func<GiNaC::mul, print_infix>(print_mul);
        GiNaC::set_print_func<GiNaC::power, print_infix>(print_power);
        return true;
    }();
    (void)registered;
}

} // namespace

void print_expression(const GiNaC::ex& e, const print_infix& c)
{
    register_print_functions();
    print_operand(e, c, 0);
}

std::string ginac_syntax(const GiNaC::ex& e, const term_order& order)
{
    return order.text(e);
}

} // namespace impact::engine
