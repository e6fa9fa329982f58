// The compiler of expressions into a straight-line program (compile/program.h): each
// distinct subexpression computed once under each set of options, in the order of
// `term_order`, sums left to right, products as one division, a quantity defined by
// cases as both branches and a select. Its compensated arithmetic (double-double) is in
// compensated.cpp; the class, shared by both, in compiler.h.
#include "compile/compiler.h"

#include "compile/functions.h"
#include "engine/cases/cases.h"

#include <cln/cln.h>
#include <fmt/format.h>

#include <sstream>
#include <stdexcept>

namespace impact::compile {
namespace detail {

compiler::compiler(program& p, const engine::term_order& order, compile_options options, const let_values& lets)
    : p_(p), order_(order), options_(options)
{
    for (const auto& [symbol, value] : lets)
        lets_.emplace(symbol, value);
    for (std::size_t i = 0; i < p.inputs.size(); ++i) {
        instruction in;
        in.op = opcode::input;
        in.input = static_cast<int>(i);
        inputs_[p.inputs[i]] = emit(in);
    }
}

// The output of an expression under the current options.
int compiler::output(const GiNaC::ex& e)
{
    if (!options_.compensated)
        return value(e);
    return rounded(compensated(e));
}

int compiler::value(const GiNaC::ex& e)
{
    // Each distinct subexpression is computed once under each set of options (shared
    // across options it would be computed differently from what was measured).
    auto& known = known_[options_key()];
    const auto found = known.find(e);
    if (found != known.end())
        return found->second;
    const int v = compute(e);
    known_[options_key()].emplace(e, v);
    return v;
}

// The options and the branch of a quantity defined by cases being compiled: a value
// computed inside a branch may divide by a divisor selected there (see `op`), so it is
// not the same value as outside it.
int compiler::options_key() const
{
    return (options_.fma ? 1 : 0) | (options_.compensated ? 2 : 0) | (options_.compensated_lets ? 4 : 0) |
           (in_condition_ ? 8 : 0) | (branch_key_ << 4);
}

// The value of `e` in the branch of `condition` taken where it is positive (or not).
int compiler::in_branch(int condition, bool positive, const GiNaC::ex& e)
{
    enter_branch(condition, positive);
    const int v = value(e);
    leave_branch();
    return v;
}

void compiler::enter_branch(int condition, bool positive)
{
    branch_.emplace_back(condition, positive);
    const auto known = branch_keys_.emplace(branch_, static_cast<int>(branch_keys_.size()) + 1).first;
    outer_keys_.push_back(branch_key_);
    branch_key_ = known->second;
}

void compiler::leave_branch()
{
    branch_.pop_back();
    branch_key_ = outer_keys_.back();
    outer_keys_.pop_back();
}

int compiler::emit(instruction in)
{
    p_.code.push_back(std::move(in));
    return static_cast<int>(p_.code.size()) - 1;
}

int compiler::op(opcode code, int a, int b, int c)
{
    // A division in a branch of a quantity defined by cases divides by its divisor where
    // the branch is taken and by 1 where it is discarded: a kernel tests every divisor
    // before it divides, and a divisor that is 0 in the other case (|g_t| where the
    // contact sticks with g_t = 0) would refuse a collision it resolves.
    if (code == opcode::div && p_.code[b].op != opcode::constant)
        for (auto level = branch_.rbegin(); level != branch_.rend(); ++level)
            b = level->second ? op(opcode::select, level->first, b, constant(1))
                              : op(opcode::select, level->first, constant(1), b);
    instruction in;
    in.op = code;
    in.a = a;
    in.b = b;
    in.c = c;
    in.correction = correcting_;
    // The same operation on the same operands is the same value (a correction only if
    // it is one wherever it is used).
    const auto key = std::make_tuple(static_cast<int>(code), a, b, c);
    const auto found = ops_.find(key);
    if (found != ops_.end()) {
        p_.code[found->second].correction = p_.code[found->second].correction && correcting_;
        return found->second;
    }
    const int v = emit(in);
    ops_.emplace(key, v);
    return v;
}

int compiler::constant(const GiNaC::numeric& n)
{
    if (!n.is_rational())
        throw std::invalid_argument("a kernel constant must be rational");
    const auto found = constants_.find(n);
    if (found != constants_.end())
        return found->second;
    instruction in;
    in.op = opcode::constant;
    in.value = n;
    const int v = emit(in);
    constants_.emplace(n, v);
    return v;
}

// π: a constant of its own, rounded to the type where it is run or printed (rounded_pi,
// detail::pi<Real>()); its value, kept for the bounds of a range and the exact reference,
// within 10^-80 of it.
int compiler::pi()
{
    if (pi_ >= 0)
        return pi_;
    instruction in;
    in.op = opcode::constant;
    in.pi = true;
    in.value = GiNaC::numeric(cln::cl_N(cln::rational(cln::pi(cln::float_format(80)))));
    pi_ = emit(in);
    return pi_;
}

int compiler::call(const std::string& function, std::vector<int> arguments)
{
    instruction in;
    in.op = opcode::call;
    in.function = function;
    in.a = arguments.size() > 0 ? arguments[0] : -1;
    in.b = arguments.size() > 1 ? arguments[1] : -1;
    return emit(in);
}

int compiler::compute(const GiNaC::ex& e)
{
    if (GiNaC::is_a<GiNaC::numeric>(e)) {
        const GiNaC::numeric n = GiNaC::ex_to<GiNaC::numeric>(e);
        return n.is_negative() ? op(opcode::neg, constant(-n)) : constant(n);
    }
    if (const auto let = lets_.find(e); let != lets_.end())
        return options_.compensated_lets ? rounded(compensated(let->second)) : value(let->second);
    if (const auto input = inputs_.find(e); input != inputs_.end())
        return input->second;
    if (GiNaC::is_a<GiNaC::symbol>(e))
        throw std::invalid_argument(fmt::format("the kernel has no input '{}'",
                                                GiNaC::ex_to<GiNaC::symbol>(e).get_name()));
    if (GiNaC::is_a<GiNaC::add>(e))
        return sum(e);
    if (GiNaC::is_a<GiNaC::mul>(e))
        return product(e);
    if (GiNaC::is_a<GiNaC::power>(e)) {
        bool negated = false;
        const engine::term_order::power_term t = order_.oriented(e, negated);
        const int v = power(t);
        return negated ? op(opcode::neg, v) : v;
    }
    if (engine::is_select(e)) {
        // Both branches are computed; each divides by its divisors only where it is the
        // one taken, and by 1 where it is discarded (see `op`).
        const int condition = value(e.op(0));
        const int taken = in_branch(condition, true, e.op(1));
        const int discarded = in_branch(condition, false, e.op(2));
        return op(opcode::select, condition, taken, discarded);
    }
    if (e.is_equal(GiNaC::Pi))
        return pi();
    if (GiNaC::is_a<GiNaC::function>(e)) {
        const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
        if (!is_library_function(name))
            throw std::invalid_argument(fmt::format("a kernel cannot compute {}: {} is not among its functions",
                                                    order_symbolless(e), name));
        std::vector<int> arguments;
        for (std::size_t i = 0; i < e.nops(); ++i)
            arguments.push_back(value(e.op(i)));
        return call(name, arguments);
    }
    throw std::invalid_argument("a kernel cannot compute " + order_symbolless(e));
}

std::string compiler::order_symbolless(const GiNaC::ex& e)
{
    std::ostringstream out;
    out << e;
    return out.str();
}

// A sum left to right in print order; a product term may be fused: acc + a*b.
int compiler::sum(const GiNaC::ex& e)
{
    int acc = -1;
    for (const GiNaC::ex& term : order_.terms(e)) {
        const bool negative = order_.negative(term);
        const GiNaC::ex magnitude = negative ? -term : term;
        if (acc >= 0 && options_.fma && GiNaC::is_a<GiNaC::mul>(magnitude)) {
            const engine::term_order::fraction f = order_.split(magnitude);
            if (f.denominator.empty() && f.numerator.size() >= 2 && !f.negated) {
                // acc ± x*y = fma(±x, y, acc), the rest of the product folded into y.
                int x = factor(f.numerator[0]);
                int y = factor(f.numerator[1]);
                for (std::size_t i = 2; i < f.numerator.size(); ++i)
                    y = op(opcode::mul, y, factor(f.numerator[i]));
                acc = op(opcode::fma, negative ? op(opcode::neg, x) : x, y, acc);
                continue;
            }
        }
        const int v = value(magnitude);
        if (acc < 0)
            acc = negative ? op(opcode::neg, v) : v;
        else
            acc = op(negative ? opcode::sub : opcode::add, acc, v);
    }
    return acc;
}

// numerator / denominator: one division for the whole product.
int compiler::product(const GiNaC::ex& e)
{
    const engine::term_order::fraction f = order_.split(e);
    int top = product_of(f.numerator);
    if (top < 0)
        top = constant(1);
    const int bottom = product_of(f.denominator);
    int v = bottom < 0 ? top : op(opcode::div, top, bottom);
    return f.negated ? op(opcode::neg, v) : v;
}

// The product of `factors` left to right; none (-1) for no factor.
int compiler::product_of(const std::vector<engine::term_order::power_term>& factors)
{
    int v = -1;
    for (const auto& t : factors)
        v = v < 0 ? factor(t) : op(opcode::mul, v, factor(t));
    return v;
}

int compiler::factor(const engine::term_order::power_term& t)
{
    if (t.exponent.is_equal(1))
        return value(t.base);
    return power(t);
}

int compiler::power(const engine::term_order::power_term& t)
{
    if (GiNaC::is_a<GiNaC::numeric>(t.exponent)) {
        const GiNaC::numeric n = GiNaC::ex_to<GiNaC::numeric>(t.exponent);
        if (n.is_negative())
            return op(opcode::div, constant(1), power({t.base, -n}));
        if (n.is_integer() && n <= 4) {
            // x^2 = x*x, x^3 = x*x*x, x^4 = (x*x)*(x*x)
            const int x = value(t.base);
            if (n == 1)
                return x;
            const int square = op(opcode::mul, x, x);
            if (n == 2)
                return square;
            if (n == 3)
                return op(opcode::mul, square, x);
            return op(opcode::mul, square, square);
        }
        if (n == GiNaC::numeric(1, 2))
            return op(opcode::sqrt, value(t.base));
        // |n|^3 = (n.n)^(3/2) as n.n sqrt(n.n): a square root and a product, which every
        // compiler vectorises, not a call of pow, which GCC does not (nor is it exact).
        if (n == GiNaC::numeric(3, 2)) {
            const int x = value(t.base);
            return op(opcode::mul, x, op(opcode::sqrt, x));
        }
    }
    return call("pow", {value(t.base), value(t.exponent)});
}

} // namespace detail

program compile_program(const std::vector<GiNaC::ex>& outputs, const std::vector<GiNaC::ex>& inputs,
                const engine::term_order& order, compile_options options, const let_values& lets)
{
    program p;
    p.inputs = inputs;
    detail::compiler c(p, order, options, lets);
    for (const GiNaC::ex& e : outputs)
        p.outputs.push_back(c.output(e));
    return p;
}

program compile_program(const std::vector<std::pair<GiNaC::ex, compile_options>>& outputs,
                const std::vector<GiNaC::ex>& inputs, const engine::term_order& order, const let_values& lets)
{
    program p;
    p.inputs = inputs;
    detail::compiler c(p, order, {}, lets);
    for (const auto& [e, options] : outputs) {
        c.set_options(options);
        p.outputs.push_back(c.output(e));
    }
    return p;
}

} // namespace impact::compile
