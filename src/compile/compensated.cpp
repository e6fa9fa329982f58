// The compiler's compensated arithmetic (compile_options::compensated, compensated_lets):
// a value carried as a pair hi + lo of the program's values, built from error-free
// transformations (compiler.h has the pair and its design; compiler.cpp the plain
// arithmetic that the pairs' operations are made of).
#include "compile/compiler.h"

#include "engine/cases/cases.h"

namespace impact::compile::detail {

int compiler::add_lo(int a, int b) { return a < 0 ? b : b < 0 ? a : op(opcode::add, a, b); }

int compiler::rounded(pair a) { return add_lo(a.hi, a.lo); }

// s + e with |e| small next to s: renormalised.
compiler::pair compiler::fast_two_sum(int s, int e)
{
    const int h = op(opcode::add, s, e);
    return {h, op(opcode::sub, e, op(opcode::sub, h, s))};
}

// The TwoSum s + e of the leading parts, with the sum of the operands' lo parts `lo`:
// renormalised, unless there is no lo (TwoSum of two doubles is normalised: s = fl(s + e)).
compiler::pair compiler::sum_with_lo(int s, int e, int lo) { return lo < 0 ? pair{s, e} : fast_two_sum(s, add_lo(e, lo)); }

compiler::pair compiler::dd_add(pair a, pair b)
{
    const int s = op(opcode::add, a.hi, b.hi);
    const int bb = op(opcode::sub, s, a.hi);
    const int e = op(opcode::add, op(opcode::sub, a.hi, op(opcode::sub, s, bb)), op(opcode::sub, b.hi, bb));
    return sum_with_lo(s, e, add_lo(a.lo, b.lo));
}

// a - b, as dd_add(a, -b) computes it but without the negations (the same values).
compiler::pair compiler::dd_sub(pair a, pair b)
{
    const int s = op(opcode::sub, a.hi, b.hi);
    const int bb = op(opcode::sub, s, a.hi);
    const int e = op(opcode::sub, op(opcode::sub, a.hi, op(opcode::sub, s, bb)), op(opcode::add, b.hi, bb));
    return sum_with_lo(s, e, b.lo < 0 ? a.lo : a.lo < 0 ? op(opcode::neg, b.lo) : op(opcode::sub, a.lo, b.lo));
}

compiler::pair compiler::dd_neg(pair a) { return {op(opcode::neg, a.hi), a.lo < 0 ? -1 : op(opcode::neg, a.lo)}; }

compiler::pair compiler::dd_mul(pair a, pair b)
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
compiler::pair compiler::dd_div(pair a, pair b)
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
compiler::pair compiler::dd_sqrt(pair a)
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

compiler::pair compiler::dd_constant(const GiNaC::numeric& n)
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

compiler::pair compiler::compensated(const GiNaC::ex& e)
{
    auto& known = known_pairs_[options_key()];
    const auto found = known.find(e);
    if (found != known.end())
        return found->second;
    const pair v = compute_pair(e);
    known_pairs_[options_key()].emplace(e, v);
    return v;
}

compiler::pair compiler::compute_pair(const GiNaC::ex& e)
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

compiler::pair compiler::compensated_factor(const engine::term_order::power_term& t)
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

compiler::pair compiler::compensated_in_branch(int condition, bool positive, const GiNaC::ex& e)
{
    enter_branch(condition, positive);
    const pair v = compensated(e);
    leave_branch();
    return v;
}

} // namespace impact::compile::detail
