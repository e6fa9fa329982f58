#include "compile/program.h"

#include "engine/cases/cases.h"

#include <fmt/format.h>

#include <cln/cln.h>

#include <algorithm>
#include <limits>
#include <map>
#include <optional>
#include <sstream>

namespace impact::compile {
namespace {

class compiler {
public:
    compiler(program& p, const engine::term_order& order, compile_options options, const let_values& lets)
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

    void set_options(compile_options options) { options_ = options; }

    // The output of an expression under the current options.
    int output(const GiNaC::ex& e)
    {
        if (!options_.compensated)
            return value(e);
        return rounded(compensated(e));
    }

    int value(const GiNaC::ex& e)
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
    int options_key() const
    {
        return (options_.fma ? 1 : 0) | (options_.compensated ? 2 : 0) | (options_.compensated_lets ? 4 : 0) |
               (in_condition_ ? 8 : 0) | (branch_key_ << 4);
    }

private:
    // Compensated arithmetic: a value carried as hi + lo (lo < 0 means lo = 0), with the
    // error-free transformations TwoSum and TwoProduct (through std::fma), so that an
    // expression comes out within about one rounding of its exact value. A sum is
    // renormalised (it may cancel, leaving lo as large as hi); a product or quotient is
    // not (its lo is within an ulp of hi, all the next operation needs). A value is rounded
    // to one double, hi + lo, only where it leaves the compensated arithmetic.
    struct pair {
        int hi;
        int lo = -1;
    };

    int add_lo(int a, int b) { return a < 0 ? b : b < 0 ? a : op(opcode::add, a, b); }

    int rounded(pair a) { return add_lo(a.hi, a.lo); }

    // s + e with |e| small next to s: renormalised.
    pair fast_two_sum(int s, int e)
    {
        const int h = op(opcode::add, s, e);
        return {h, op(opcode::sub, e, op(opcode::sub, h, s))};
    }

    // The TwoSum s + e of the leading parts, with the sum of the operands' lo parts `lo`:
    // renormalised, unless there is no lo (TwoSum of two doubles is normalised: s = fl(s + e)).
    pair sum_with_lo(int s, int e, int lo) { return lo < 0 ? pair{s, e} : fast_two_sum(s, add_lo(e, lo)); }

    pair dd_add(pair a, pair b)
    {
        const int s = op(opcode::add, a.hi, b.hi);
        const int bb = op(opcode::sub, s, a.hi);
        const int e = op(opcode::add, op(opcode::sub, a.hi, op(opcode::sub, s, bb)), op(opcode::sub, b.hi, bb));
        return sum_with_lo(s, e, add_lo(a.lo, b.lo));
    }

    // a - b, as dd_add(a, -b) computes it but without the negations (the same values).
    pair dd_sub(pair a, pair b)
    {
        const int s = op(opcode::sub, a.hi, b.hi);
        const int bb = op(opcode::sub, s, a.hi);
        const int e = op(opcode::sub, op(opcode::sub, a.hi, op(opcode::sub, s, bb)), op(opcode::add, b.hi, bb));
        return sum_with_lo(s, e, b.lo < 0 ? a.lo : a.lo < 0 ? op(opcode::neg, b.lo) : op(opcode::sub, a.lo, b.lo));
    }

    pair dd_neg(pair a) { return {op(opcode::neg, a.hi), a.lo < 0 ? -1 : op(opcode::neg, a.lo)}; }

    pair dd_mul(pair a, pair b)
    {
        const int p = op(opcode::mul, a.hi, b.hi);
        correcting_ = true;
        int e = op(opcode::fma, a.hi, b.hi, op(opcode::neg, p));
        if (b.lo >= 0)
            e = op(opcode::fma, a.hi, b.lo, e);
        if (a.lo >= 0)
            e = op(opcode::fma, a.lo, b.hi, e);
        correcting_ = false;
        return {p, e};
    }

    // q1 = a/b, corrected by the remainder a - q1 b over b: its leading part a.hi - q1 b.hi
    // is exact through fma (q1 being a.hi/b.hi rounded). Two divisions, not one through 1/b:
    // a reciprocal overflows where the quotient need not. b.hi may itself need a division
    // (a compensated |g_t| built on |n|, whose root is corrected by one): a kernel then tests
    // it after its first divisions (compile::grouped_divisors), not before them all, for
    // that value computed plainly can be far off (of the other sign, where a sum cancels).
    pair dd_div(pair a, pair b)
    {
        const int q1 = op(opcode::div, a.hi, b.hi);
        correcting_ = true;
        const int minus_q1 = op(opcode::neg, q1);
        int r = add_lo(op(opcode::fma, minus_q1, b.hi, a.hi), a.lo);
        if (b.lo >= 0)
            r = op(opcode::fma, minus_q1, b.lo, r);
        const int lo = op(opcode::div, r, b.hi);
        correcting_ = false;
        return {q1, lo};
    }

    // sqrt(a) = h + (a - h^2)/(2h).
    pair dd_sqrt(pair a)
    {
        const int h = op(opcode::sqrt, a.hi);
        // In a condition of cases, no division: the kernel's divisors there are selected by
        // the condition, and must all come before its first division. The root of the leading
        // part, uncorrected: the one the rest of the kernel takes too (rounding the radicand
        // first would cost a square root of its own, for no better figure in verification.md).
        if (in_condition_)
            return {h, -1};
        correcting_ = true;
        const int r = add_lo(op(opcode::fma, op(opcode::neg, h), h, a.hi), a.lo);
        const int lo = op(opcode::div, r, op(opcode::add, h, h));
        correcting_ = false;
        return {h, lo};
    }

    pair dd_constant(const GiNaC::numeric& n)
    {
        if (n.is_integer() && GiNaC::abs(n) < GiNaC::numeric(1L << 52))
            return {constant(n), -1};
        // p/q = hi + lo with lo = (p - hi q) / q, the remainder exact through fma.
        const int p = constant(n.numer()), q = constant(n.denom());
        const int hi = op(opcode::div, p, q);
        correcting_ = true;
        const int lo = op(opcode::div, op(opcode::fma, op(opcode::neg, hi), q, p), q);
        correcting_ = false;
        return {hi, lo};
    }

    pair compensated(const GiNaC::ex& e)
    {
        auto& known = known_pairs_[options_key()];
        const auto found = known.find(e);
        if (found != known.end())
            return found->second;
        const pair v = compute_pair(e);
        known_pairs_[options_key()].emplace(e, v);
        return v;
    }

    pair compute_pair(const GiNaC::ex& e)
    {
        if (GiNaC::is_a<GiNaC::numeric>(e)) {
            const GiNaC::numeric n = GiNaC::ex_to<GiNaC::numeric>(e);
            return n.is_negative() ? dd_neg(dd_constant(-n)) : dd_constant(n);
        }
        if (GiNaC::is_a<GiNaC::symbol>(e)) {
            if (const auto let = lets_.find(e); let != lets_.end())
                return compensated(let->second);
            return {value(e), -1};
        }
        if (GiNaC::is_a<GiNaC::add>(e)) {
            pair acc{-1, -1};
            for (const GiNaC::ex& term : order_.terms(e)) {
                const bool negative = order_.negative(term);
                const pair v = compensated(negative ? -term : term);
                acc = acc.hi < 0 ? (negative ? dd_neg(v) : v) : negative ? dd_sub(acc, v) : dd_add(acc, v);
            }
            return acc;
        }
        if (GiNaC::is_a<GiNaC::mul>(e)) {
            const engine::term_order::fraction f = order_.split(e);
            pair top{-1, -1}, bottom{-1, -1};
            for (const auto& t : f.numerator)
                top = top.hi < 0 ? compensated_factor(t) : dd_mul(top, compensated_factor(t));
            if (top.hi < 0)
                top = {constant(1), -1};
            for (const auto& t : f.denominator)
                bottom = bottom.hi < 0 ? compensated_factor(t) : dd_mul(bottom, compensated_factor(t));
            const pair v = bottom.hi < 0 ? top
                                         : dd_div(top, bottom);
            return f.negated ? dd_neg(v) : v;
        }
        if (GiNaC::is_a<GiNaC::power>(e)) {
            bool negated = false;
            const pair v = compensated_factor(order_.oriented(e, negated));
            return negated ? dd_neg(v) : v;
        }
        if (engine::is_select(e)) {
            // A quantity defined by cases: each branch compensated, the pair selected, and
            // the condition compensated too: near the cases' boundary its plain value can
            // take the wrong sign, and the case taken would then be off by the rounding of
            // the condition (several ulps of the output where the cases meet). Its square
            // roots are not corrected (that needs a division, see dd_sqrt). An output of the
            // same kernel compiled plainly tests the plain condition, and may take the other
            // case a hair from the boundary: the cases meet there, so that costs ulps only.
            const bool outer = in_condition_;
            in_condition_ = true;
            const int condition = rounded(compensated(e.op(0)));
            in_condition_ = outer;
            const pair taken = compensated_in_branch(condition, true, e.op(1));
            const pair discarded = compensated_in_branch(condition, false, e.op(2));
            const int hi = op(opcode::select, condition, taken.hi, discarded.hi);
            if (taken.lo < 0 && discarded.lo < 0)
                return {hi, -1};
            correcting_ = true;
            const int lo = op(opcode::select, condition, taken.lo < 0 ? constant(0) : taken.lo,
                              discarded.lo < 0 ? constant(0) : discarded.lo);
            correcting_ = false;
            return {hi, lo};
        }
        // |x|: the pair's sign is its leading part's. As a select, |+0| is -0 (std::fabs gives
        // +0, but a call costs more where it is a divisor: the plain one is then computed
        // apart); |x| is compared and divided by, where a zero's sign changes nothing taken
        // (a zero slip sticks, and the sliding case that divides by it is discarded).
        if (GiNaC::is_a<GiNaC::function>(e) && GiNaC::ex_to<GiNaC::function>(e).get_name() == "abs") {
            const pair x = compensated(e.op(0));
            const pair negated = dd_neg(x);
            const int hi = op(opcode::select, x.hi, x.hi, negated.hi);
            if (x.lo < 0)
                return {hi, -1};
            correcting_ = true;
            const int lo = op(opcode::select, x.hi, x.lo, negated.lo);
            correcting_ = false;
            return {hi, lo};
        }
        // Other functions: evaluated on the leading part.
        return {value(e), -1};
    }

    pair compensated_factor(const engine::term_order::power_term& t)
    {
        if (t.exponent.is_equal(1))
            return compensated(t.base);
        if (GiNaC::is_a<GiNaC::numeric>(t.exponent)) {
            const GiNaC::numeric n = GiNaC::ex_to<GiNaC::numeric>(t.exponent);
            if (n.is_negative()) {
                const pair b = compensated_factor({t.base, -n});
                return dd_div({constant(1), -1}, b);
            }
            if (n.is_integer() && n <= 4) {
                const pair x = compensated(t.base);
                pair r = x;
                for (int i = 1; i < n.to_int(); ++i)
                    r = dd_mul(r, x);
                return r;
            }
            if (n == GiNaC::numeric(1, 2))
                return dd_sqrt(compensated(t.base));
            if (n == GiNaC::numeric(3, 2))   // x sqrt(x), as `power` computes it
                return dd_mul(compensated(t.base), dd_sqrt(compensated(t.base)));
        }
        return {power(t), -1};
    }

    // The value of `e` in the branch of `condition` taken where it is positive (or not).
    int in_branch(int condition, bool positive, const GiNaC::ex& e)
    {
        enter_branch(condition, positive);
        const int v = value(e);
        leave_branch();
        return v;
    }

    pair compensated_in_branch(int condition, bool positive, const GiNaC::ex& e)
    {
        enter_branch(condition, positive);
        const pair v = compensated(e);
        leave_branch();
        return v;
    }

    void enter_branch(int condition, bool positive)
    {
        branch_.emplace_back(condition, positive);
        const auto known = branch_keys_.emplace(branch_, static_cast<int>(branch_keys_.size()) + 1).first;
        outer_keys_.push_back(branch_key_);
        branch_key_ = known->second;
    }

    void leave_branch()
    {
        branch_.pop_back();
        branch_key_ = outer_keys_.back();
        outer_keys_.pop_back();
    }

    int emit(instruction in)
    {
        p_.code.push_back(std::move(in));
        return static_cast<int>(p_.code.size()) - 1;
    }

    int op(opcode code, int a, int b = -1, int c = -1)
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

    int constant(const GiNaC::numeric& n)
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

    int call(const std::string& function, std::vector<int> arguments)
    {
        instruction in;
        in.op = opcode::call;
        in.function = function;
        in.a = arguments.size() > 0 ? arguments[0] : -1;
        in.b = arguments.size() > 1 ? arguments[1] : -1;
        return emit(in);
    }

    int compute(const GiNaC::ex& e)
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
        if (GiNaC::is_a<GiNaC::function>(e)) {
            std::vector<int> arguments;
            for (std::size_t i = 0; i < e.nops(); ++i)
                arguments.push_back(value(e.op(i)));
            return call(GiNaC::ex_to<GiNaC::function>(e).get_name(), arguments);
        }
        throw std::invalid_argument("a kernel cannot compute " + order_symbolless(e));
    }

    static std::string order_symbolless(const GiNaC::ex& e)
    {
        std::ostringstream out;
        out << e;
        return out.str();
    }

    // A sum left to right in print order; a product term may be fused: acc + a*b.
    int sum(const GiNaC::ex& e)
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
    int product(const GiNaC::ex& e)
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
    int product_of(const std::vector<engine::term_order::power_term>& factors)
    {
        int v = -1;
        for (const auto& t : factors)
            v = v < 0 ? factor(t) : op(opcode::mul, v, factor(t));
        return v;
    }

    int factor(const engine::term_order::power_term& t)
    {
        if (t.exponent.is_equal(1))
            return value(t.base);
        return power(t);
    }

    int power(const engine::term_order::power_term& t)
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

    program& p_;
    const engine::term_order& order_;
    compile_options options_;
    std::map<GiNaC::ex, int, GiNaC::ex_is_less> inputs_;
    std::map<int, std::map<GiNaC::ex, int, GiNaC::ex_is_less>> known_;
    std::map<GiNaC::ex, GiNaC::ex, GiNaC::ex_is_less> lets_;
    std::map<int, std::map<GiNaC::ex, pair, GiNaC::ex_is_less>> known_pairs_;
    std::map<GiNaC::numeric, int, std::less<>> constants_;
    std::map<std::tuple<int, int, int, int>, int> ops_;
    bool correcting_ = false;  // the operations made now are corrections
    bool in_condition_ = false;  // compiling the condition of cases, compensated without divisions
    std::vector<std::pair<int, bool>> branch_;  // the branches being compiled: condition, taken where positive
    std::map<std::vector<std::pair<int, bool>>, int> branch_keys_;
    int branch_key_ = 0;       // 0 outside every branch
    std::vector<int> outer_keys_;
};

} // namespace

program compile_program(const std::vector<GiNaC::ex>& outputs, const std::vector<GiNaC::ex>& inputs,
                const engine::term_order& order, compile_options options, const let_values& lets)
{
    program p;
    p.inputs = inputs;
    compiler c(p, order, options, lets);
    for (const GiNaC::ex& e : outputs)
        p.outputs.push_back(c.output(e));
    return p;
}

program compile_program(const std::vector<std::pair<GiNaC::ex, compile_options>>& outputs,
                const std::vector<GiNaC::ex>& inputs, const engine::term_order& order, const let_values& lets)
{
    program p;
    p.inputs = inputs;
    compiler c(p, order, {}, lets);
    for (const auto& [e, options] : outputs) {
        c.set_options(options);
        p.outputs.push_back(c.output(e));
    }
    return p;
}

std::size_t count(const program& p, opcode op)
{
    std::size_t n = 0;
    for (const instruction& in : p.code)
        n += in.op == op ? 1 : 0;
    return n;
}

cost cost_of(const program& p)
{
    cost c;
    for (const instruction& in : p.code) {
        c.operations += is_leaf(in) ? 0 : 1;
        c.divisions += in.op == opcode::div ? 1 : 0;
        c.square_roots += in.op == opcode::sqrt ? 1 : 0;
    }
    return c;
}

bool cheaper(const cost& a, const cost& b)
{
    if (a.square_roots != b.square_roots)
        return a.square_roots < b.square_roots;
    if (a.divisions != b.divisions)
        return a.divisions < b.divisions;
    return a.operations < b.operations;
}

bool is_leaf(const instruction& in)
{
    return in.op == opcode::input || in.op == opcode::constant;
}

operand_list operands(const instruction& in)
{
    operand_list of;
    for (int operand : {in.a, in.b, in.c})
        if (operand >= 0)
            of.value[of.count++] = operand;
    return of;
}

bool can_underflow(const instruction& in)
{
    return !in.correction && (in.op == opcode::mul || in.op == opcode::div || in.op == opcode::fma || in.op == opcode::call);
}

// A division by a value that is not a constant: one whose divisor a kernel names and tests.
bool divides(const program& p, const instruction& in)
{
    return in.op == opcode::div && p.code[in.b].op != opcode::constant;
}

divisor_groups grouped_divisors(const program& p)
{
    std::vector<bool> needs_division(p.code.size(), false);
    for (std::size_t i = 0; i < p.code.size(); ++i) {
        needs_division[i] = divides(p, p.code[i]);
        for (int operand : operands(p.code[i]))
            needs_division[i] = needs_division[i] || needs_division[operand];
    }
    divisor_groups groups;
    for (int d : divisors(p))
        (needs_division[static_cast<std::size_t>(d)] ? groups.late : groups.early).push_back(d);
    return groups;
}

namespace {

int last_of(const std::vector<int>& values)
{
    return values.empty() ? -1 : *std::max_element(values.begin(), values.end());
}

} // namespace

bool divisor_groups::is_late(int value) const
{
    return std::find(late.begin(), late.end(), value) != late.end();
}

int divisor_groups::last_early() const
{
    return last_of(early);
}

int divisor_groups::last_late() const
{
    return last_of(late);
}

bool divides_early(const program& p)
{
    const divisor_groups groups = grouped_divisors(p);
    const int last_early = groups.last_early(), last_late = groups.last_late();
    for (std::size_t i = 0; i < p.code.size(); ++i) {
        if (!divides(p, p.code[i]))
            continue;
        const int at = static_cast<int>(i);
        if (at < last_early || (groups.is_late(p.code[i].b) && at < last_late))
            return true;
    }
    return false;
}

std::vector<int> divisors(const program& p)
{
    std::vector<int> found;
    for (const instruction& in : p.code)
        if (divides(p, in) && std::find(found.begin(), found.end(), in.b) == found.end())
            found.push_back(in.b);
    return found;
}

std::vector<bool> needed_by(const program& p, std::size_t first, std::size_t last)
{
    std::vector<bool> needed(p.code.size(), false);
    for (std::size_t o = first; o < last; ++o)
        needed[p.outputs[o]] = true;
    for (std::size_t i = p.code.size(); i-- > 0;)
        if (needed[i])
            for (int operand : operands(p.code[i]))
                needed[operand] = true;
    return needed;
}

namespace {

// `x` (finite) exactly, as a rational: its fraction in [1/2, 1) is the sum of at most three
// doubles, each the nearest to what the ones before left (for 24, 53, 64 or 113 bits).
template <class Real>
cln::cl_RA exactly(Real x)
{
    int exponent = 0;
    Real fraction = std::frexp(x, &exponent);
    cln::cl_RA sum = 0;
    while (fraction != 0) {
        const double part = static_cast<double>(fraction);
        sum = sum + cln::rational(cln::cl_DF(part));
        fraction -= static_cast<Real>(part);
    }
    return sum * cln::expt(cln::cl_RA(2), exponent);
}

// std::`function`(a, b) for a >= 0 (atan, atan2: odd in a; the caller gives a's sign back):
// exactly where it is rational (pow to an integer power), else to 60 digits, as a rational;
// nullopt for infinities and NaN (which the kernels' guards refuse before they compute),
// atan2(0, 0), arguments outside the function's domain and pow of 0, left to the C library.
template <class Real>
std::optional<cln::cl_RA> value_of(const std::string& function, Real a, Real b)
{
    if (!std::isfinite(a) || !std::isfinite(b))
        return std::nullopt;
    const cln::float_format_t digits = cln::float_format(60);
    const auto rational = [&](const cln::cl_R& v) { return cln::rational(cln::cl_float(v, digits)); };
    const cln::cl_RA x = exactly(a), y = exactly(b);
    if (function == "atan")
        return rational(cln::atan(cln::cl_float(x, digits)));
    if (function == "atan2" && !(a == 0 && b == 0))
        return rational(cln::atan(cln::cl_float(y, digits), cln::cl_float(x, digits)));  // the point (b, a)
    if (function == "acos" && a >= -1 && a <= 1)
        return rational(cln::realpart(cln::acos(cln::cl_float(x, digits))));
    if (function == "pow" && a != 0) {
        if (cln::denominator(y) == 1 && cln::abs(y) <= 4096)  // exactly: a tie is then rounded to even
            return cln::expt(x, cln::numerator(y));
        if (a > 0)
            return rational(cln::exp(cln::cl_float(y, digits) * cln::ln(cln::cl_float(x, digits))));
    }
    return std::nullopt;
}

// `q` rounded to the nearest `Real`, ties to even, subnormals included (a negative one that
// rounds to zero is -0); nullopt when it overflows.
template <class Real>
std::optional<Real> nearest(const cln::cl_RA& q)
{
    using limits = std::numeric_limits<Real>;
    if (cln::zerop(q))
        return Real(0);
    const cln::cl_RA size = cln::abs(q);
    // 2^(exponent - 1) <= |q| < 2^exponent.
    long exponent = static_cast<long>(cln::integer_length(cln::numerator(size))) -
                    static_cast<long>(cln::integer_length(cln::denominator(size)));
    if (size >= cln::expt(cln::cl_RA(2), exponent))
        ++exponent;
    if (exponent > limits::max_exponent)
        return std::nullopt;
    const long shift = limits::digits - std::max<long>(exponent, limits::min_exponent);
    const cln::cl_I magnitude = cln::round1(size * cln::expt(cln::cl_RA(2), shift));
    Real value = 0;  // its 32-bit pieces, high first: each partial sum fits the type's digits
    for (long piece = (cln::integer_length(magnitude) + 31) / 32 - 1; piece >= 0; --piece)
        value = value * Real(4294967296.0) +
                static_cast<Real>(cln::cl_I_to_ulong(cln::ldb(magnitude, cln::cl_byte(32, 32 * piece))));
    value = std::ldexp(value, static_cast<int>(-shift));
    return cln::minusp(q) ? -value : value;
}

template <class Real>
Real library_call(const std::string& function, Real a, Real b)
{
    if (function == "acos")
        return std::acos(a);
    if (function == "atan")
        return std::atan(a);
    if (function == "atan2")
        return std::atan2(a, b);
    if (function == "pow")
        return std::pow(a, b);
    throw std::invalid_argument("no interpreter for std::" + function);
}

template <class Real>
Real rounded_call(const std::string& function, Real a, Real b)
{
    // atan and atan2 are odd in a: computed for |a|, a's sign (of a zero too) given back.
    const bool odd = function == "atan" || function == "atan2";
    if (const std::optional<cln::cl_RA> exact = value_of(function, odd ? std::fabs(a) : a, b))
        if (const std::optional<Real> value = nearest<Real>(*exact))
            return odd ? std::copysign(*value, a) : *value;
    return library_call(function, a, b);
}

} // namespace

// From 60 digits (about 199 bits) to the type's 24, 53, 64 or 113: a second rounding only
// within 2^-199 of the value's size from a tie (none for pow to an integer power, exact).
float correctly_rounded(const std::string& function, float a, float b)
{
    return rounded_call(function, a, b);
}

double correctly_rounded(const std::string& function, double a, double b)
{
    return rounded_call(function, a, b);
}

long double correctly_rounded(const std::string& function, long double a, long double b)
{
    return rounded_call(function, a, b);
}

} // namespace impact::compile
