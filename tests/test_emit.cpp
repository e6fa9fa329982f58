// The emitters: exact text for C++, LaTeX and GiNaC syntax, in a fixed order.
#define BOOST_TEST_MODULE test_emit
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <limits>

#include "emit/cxx.h"
#include "emit/errata.h"
#include "compile/program.h"
#include "compile/range.h"
#include "emit/program_cxx.h"
#include "engine/expr/infix.h"

using namespace impact;

BOOST_AUTO_TEST_CASE(order_does_not_depend_on_how_gi_nac_stored_the_expression)
{
    // The same sum built from symbols made in a different order prints identically.
    GiNaC::realsymbol b("b"), a("a"), c("c");
    const engine::term_order order({a, b, c});
    BOOST_TEST(engine::ginac_syntax(c * (b - a) + b * a, order) == "a*b-c*(a-b)");
    BOOST_TEST(engine::ginac_syntax((a - b) * c + a * b, order) == "a*b+c*(a-b)");
    BOOST_TEST(engine::ginac_syntax(GiNaC::pow(a, 2) / (b + c), order) == "a^2/(b+c)");
}


// Straight-line programs written instruction by instruction, to test their ordering for
// registers against what a hand count of the live values gives.
namespace {

struct program_builder {
    compile::program p;

    explicit program_builder(std::size_t inputs)
    {
        for (std::size_t i = 0; i < inputs; ++i) {
            p.inputs.push_back(GiNaC::symbol());
            compile::instruction in;
            in.op = compile::opcode::input;
            in.input = static_cast<int>(i);
            p.code.push_back(in);
        }
    }

    int operator()(compile::opcode op, int a, int b = -1, int c = -1)
    {
        compile::instruction in;
        in.op = op;
        in.a = a;
        in.b = b;
        in.c = c;
        p.code.push_back(in);
        return static_cast<int>(p.code.size()) - 1;
    }

    int constant(long value)
    {
        compile::instruction in;
        in.op = compile::opcode::constant;
        in.value = value;
        p.code.push_back(in);
        return static_cast<int>(p.code.size()) - 1;
    }
};

// The operations in order: + for an addition, * for a multiplication, / for a division,
// r for a square root, f for a fused multiply-add.
std::string operations(const compile::program& p)
{
    std::string ops;
    for (const compile::instruction& in : p.code)
        switch (in.op) {
        case compile::opcode::add: ops += '+'; break;
        case compile::opcode::mul: ops += '*'; break;
        case compile::opcode::div: ops += '/'; break;
        case compile::opcode::sqrt: ops += 'r'; break;
        case compile::opcode::fma: ops += 'f'; break;
        default: break;
        }
    return ops;
}

// Every operand of every instruction comes before it.
bool operands_first(const compile::program& p)
{
    for (std::size_t i = 0; i < p.code.size(); ++i)
        for (int operand : {p.code[i].a, p.code[i].b, p.code[i].c})
            if (operand >= static_cast<int>(i))
                return false;
    return true;
}

} // namespace

BOOST_AUTO_TEST_SUITE(programs)

BOOST_AUTO_TEST_CASE(ordered_for_registers_finishes_with_values_before_reading_more)
{
    // (a + b) (a b) + (c + d) (c d), every sum first as compiled: a, b, c, d, a + b and
    // c + d are live at once (6). Ordered, a and b are done with before c and d are read:
    // at most c, d, c + d and the first product (4).
    using compile::opcode;
    program_builder in(4);
    const int a = 0, b = 1, c = 2, d = 3;
    const int s1 = in(opcode::add, a, b);
    const int s2 = in(opcode::add, c, d);
    const int p1 = in(opcode::mul, a, b);
    const int p2 = in(opcode::mul, c, d);
    const int q1 = in(opcode::mul, s1, p1);
    const int q2 = in(opcode::mul, s2, p2);
    in.p.outputs.push_back(in(opcode::add, q1, q2));
    BOOST_TEST(compile::most_live(in.p) == 6u);

    const compile::program ordered = compile::ordered_for_registers(in.p);
    BOOST_TEST(compile::most_live(ordered) == 4u);
    BOOST_TEST(operations(in.p) == "++****+");
    BOOST_TEST(operations(ordered) == "+**+**+");  // a + b, a b, their product, then c and d
    BOOST_TEST(operands_first(ordered));
    const std::vector<double> values{1.5, -2.25, 3.125, 0.75};  // (-0.75)(-3.375) + 3.875 * 2.34375
    BOOST_TEST(compile::run<double>(ordered, values).front() == 0.75 * 3.375 + 3.875 * 2.34375);

    // A second output, computed early (c + d): each output is still the value it names.
    in.p.outputs.push_back(s2);
    BOOST_TEST(compile::most_live(in.p) == 6u);
    const std::vector<double> both = compile::run<double>(compile::ordered_for_registers(in.p), values);
    BOOST_TEST(both.size() == 2u);
    BOOST_TEST(both[0] == 0.75 * 3.375 + 3.875 * 2.34375);
    BOOST_TEST(both[1] == 3.875);
}

BOOST_AUTO_TEST_CASE(input_range_keeps_every_product_normal_and_no_wider)
{
    // a b with |a|, |b| in [2^-k, 2^k] is within [2^-2k, 2^2k]: normal in double up to
    // k = 511 (2^-1022 is the least normal number, 2^1023 below the largest), in float up to
    // 63 (2^-126, 2^127).
    using compile::opcode;
    const compile::float_format single{24, -125, 128}, twice{53, -1021, 1024};
    program_builder product(2);
    product.p.outputs.push_back(product(opcode::mul, 0, 1));
    const std::vector<bool> all(product.p.code.size(), true);
    BOOST_TEST(compile::input_exponent_bound(product.p, all, twice) == 511);
    BOOST_TEST(compile::input_exponent_bound(product.p, all, single) == 63);

    // (a - b)^2: a difference not 0 of numbers of at least 2^-k is at least their ulp,
    // 2^(-k - 52) in double, its square 2^(-2k - 104): normal up to k = 459. At k = 460 it
    // can be below the normal range: a = 2^-460 (1 + 2^-52), b = 2^-460.
    program_builder square(2);
    const int difference = square(opcode::sub, 0, 1);
    square.p.outputs.push_back(square(opcode::mul, difference, difference));
    const std::vector<bool> every(square.p.code.size(), true);
    BOOST_TEST(compile::input_exponent_bound(square.p, every, twice) == 459);
    BOOST_TEST(compile::input_exponent_bound(square.p, every, single) == 40);  // 2^(-2k - 46) >= 2^-126
    const double b = std::ldexp(1.0, -460), a = b + std::ldexp(1.0, -512);
    BOOST_TEST(compile::run<double>(square.p, {a, b}).front() < std::numeric_limits<double>::min());
    BOOST_TEST(compile::run<double>(square.p, {2 * a, 2 * b}).front() == std::numeric_limits<double>::min());
}

// A sure block's cut (compile::cut_for_range): x and y enter only through x - y and x is
// added to an output, so the block tests x - y, s and w, and the output x is added to; the
// bounds then start from x - y itself, not from x and y: (x - y)^2 s within [2^-3k, 2^3k],
// normal in double up to k = 340 (from the inputs, x - y is only a multiple of 2^(-k - 52),
// and the product normal up to k = 306). An input added to a product but to no other input
// is tested itself, and a cut no cheaper than the inputs is the inputs.
BOOST_AUTO_TEST_CASE(a_sure_block_tests_differences_of_inputs_where_that_tests_fewer_values)
{
    using compile::opcode;
    const compile::float_format twice{53, -1021, 1024};
    program_builder in(4);
    const int x = 0, y = 1, s = 2, w = 3;
    const int d = in(opcode::sub, x, y);
    const int r = in(opcode::mul, in(opcode::mul, d, d), s);
    in.p.outputs.push_back(in(opcode::add, r, x));
    in.p.outputs.push_back(in(opcode::mul, w, s));
    const std::vector<bool> all(in.p.code.size(), true);
    const compile::range_cut cut = compile::cut_for_range(in.p, all);
    BOOST_TEST((cut.tested == std::vector<int>{s, w, d}));
    BOOST_TEST((cut.summed == std::vector<int>{0}));
    BOOST_TEST(compile::cut_exponent_bound(in.p, all, cut, twice) == 340);
    BOOST_TEST(compile::input_exponent_bound(in.p, all, twice) == 306);
    // Within the cut's range at k = 100, (x - y)^2 s is 0 or within [2^-300, 2^300], and no
    // narrower; the output x is added to has no bound (x is not tested).
    BOOST_TEST(compile::cut_bounds_within(in.p, all, cut, 100, twice, {r}, -300, 300));
    BOOST_TEST(!compile::cut_bounds_within(in.p, all, cut, 100, twice, {r}, -299, 300));
    BOOST_TEST(!compile::cut_bounds_within(in.p, all, cut, 100, twice, {r}, -300, 299));
    BOOST_TEST(!compile::cut_bounds_within(in.p, all, cut, 100, twice, {in.p.outputs[0]}, -2000, 2000));
    BOOST_TEST(compile::cut_bounds_within(in.p, all, cut, 100, twice, {in.p.outputs[1]}, -200, 200));

    program_builder plain(2);
    plain.p.outputs.push_back(plain(opcode::add, 0, plain(opcode::mul, 1, 1)));
    const std::vector<bool> every(plain.p.code.size(), true);
    const compile::range_cut inputs = compile::cut_for_range(plain.p, every);
    BOOST_TEST((inputs.tested == std::vector<int>{0, 1}));
    BOOST_TEST(inputs.summed.empty());
    BOOST_TEST(compile::cut_exponent_bound(plain.p, every, inputs, twice) == compile::input_exponent_bound(plain.p, every, twice));
}

BOOST_AUTO_TEST_CASE(ordered_for_registers_divides_only_once_every_divisor_is_known)
{
    // b / (b + c) + d / (e + f): once b + c is known, b / (b + c) needs no new input and
    // would come next, before e + f; it waits for that divisor, so that a batch loop can
    // test every divisor's range before its first division.
    using compile::opcode;
    program_builder in(5);
    const int b = 0, c = 1, d = 2, e = 3, f = 4;
    const int bc = in(opcode::add, b, c);
    const int ef = in(opcode::add, e, f);
    const int q1 = in(opcode::div, b, bc);
    const int q2 = in(opcode::div, d, ef);
    in.p.outputs.push_back(in(opcode::add, q1, q2));
    BOOST_TEST(!emit::program_cxx(in.p, {"b", "c", "d", "e", "f"}).divides_early);

    const compile::program ordered = compile::ordered_for_registers(in.p);
    BOOST_TEST(operations(ordered) == "++//+");  // not "+/+/+"
    BOOST_TEST(!emit::program_cxx(ordered, {"b", "c", "d", "e", "f"}).divides_early);
}

BOOST_AUTO_TEST_CASE(ordered_for_registers_takes_a_square_root_once_every_divisor_is_known)
{
    // sqrt(a + b) + c / (d + e): the root would follow a + b at once; it waits for d + e,
    // since a batch loop decides from the divisors which lanes' roots it takes.
    using compile::opcode;
    program_builder in(5);
    const int a = 0, b = 1, c = 2, d = 3, e = 4;
    const int ab = in(opcode::add, a, b);
    const int root = in(opcode::sqrt, ab);
    const int de = in(opcode::add, d, e);
    const int q = in(opcode::div, c, de);
    in.p.outputs.push_back(in(opcode::add, root, q));
    BOOST_TEST(operations(in.p) == "+r+/+");

    const compile::program ordered = compile::ordered_for_registers(in.p);
    BOOST_TEST(operations(ordered) == "++r/+");
    BOOST_TEST(operands_first(ordered));
    const std::vector<double> values{1.5, 0.75, 3.0, 0.5, 1.0};  // sqrt(2.25) + 3 / 1.5
    BOOST_TEST(compile::run<double>(ordered, values).front() == 3.5);
}

BOOST_AUTO_TEST_CASE(a_batch_takes_a_root_that_is_a_divisor_before_it_knows_its_lanes)
{
    // a / sqrt(b): the root is the last divisor, computed before `usable` is known from it;
    // blended with `usable` it would read the flag before its declaration. And
    // a / (b + 1/sqrt(b)): after the early divisor sqrt(b), b + 1/sqrt(b) is a late one,
    // divided by only where `usable_late` holds.
    using compile::opcode;
    program_builder in(2);
    const int a = 0, b = 1;
    const int root = in(opcode::sqrt, b);
    in.p.outputs.push_back(in(opcode::div, a, root));
    const emit::cxx_code code = emit::program_cxx(in.p, {"a", "b"}, "usable");
    BOOST_TEST_REQUIRE(code.statements.size() == 1u);
    BOOST_TEST(code.statements[0] == "const Real t0 = std::sqrt(b);");
    BOOST_TEST(code.divisors_known == 1u);

    program_builder late(2);
    const int late_root = late(opcode::sqrt, b);
    const int one = late.constant(1);
    const int inverse = late(opcode::div, one, late_root);
    const int sum = late(opcode::add, b, inverse);
    late.p.outputs.push_back(late(opcode::div, a, sum));
    const emit::cxx_code late_code = emit::program_cxx(late.p, {"a", "b"}, "usable");
    BOOST_TEST(late_code.divisors.size() == 1u);
    BOOST_TEST_REQUIRE(late_code.late_divisors.size() == 1u);
    BOOST_TEST(!late_code.divides_early);
    BOOST_TEST(late_code.outputs.front().find("detail::blend(usable_late, ") != std::string::npos,
               late_code.outputs.front());
}

BOOST_AUTO_TEST_CASE(ordered_for_registers_waits_for_an_fma_s_addend)
{
    // a b, c d, e + g, fma(a, b, c d), a b + fma, + (e + g): once c d is known the fma reads
    // nothing new and comes before e + g; until then it waits, its factors known and old,
    // for its addend.
    using compile::opcode;
    program_builder in(6);
    const int a = 0, b = 1, c = 2, d = 3, e = 4, g = 5;
    const int ab = in(opcode::mul, a, b);
    const int cd = in(opcode::mul, c, d);
    const int eg = in(opcode::add, e, g);
    const int f = in(opcode::fma, a, b, cd);
    const int sum = in(opcode::add, ab, f);
    in.p.outputs.push_back(in(opcode::add, sum, eg));
    BOOST_TEST(operations(in.p) == "**+f++");

    const compile::program ordered = compile::ordered_for_registers(in.p);
    BOOST_TEST(operations(ordered) == "**f+++");
    BOOST_TEST(operands_first(ordered));
    const std::vector<double> values{1.5, 2.0, 0.5, 0.25, 1.0, 0.5};  // 3 + (3 + 0.125) + 1.5
    BOOST_TEST(compile::run<double>(ordered, values).front() == 7.625);
}

BOOST_AUTO_TEST_CASE(ordered_for_registers_tests_late_divisors_after_the_early_divisions)
{
    // p = a / b and q = c / d; then e / (p + a) and g / (q + c). b and d are early divisors,
    // p + a and q + c late ones (compile::grouped_divisors): the divisions by b and d wait for
    // b and d only, those by p + a and q + c for both of them. Unconstrained, p + a follows p.
    using compile::opcode;
    program_builder in(6);
    const int a = 0, b = 1, c = 2, d = 3, e = 4, g = 5;
    const int p = in(opcode::div, a, b);
    const int q = in(opcode::div, c, d);
    const int pa = in(opcode::add, p, a);
    const int qc = in(opcode::add, q, c);
    const int r = in(opcode::div, e, pa);
    const int s = in(opcode::div, g, qc);
    in.p.outputs.push_back(in(opcode::add, r, s));
    const compile::divisor_groups groups = compile::grouped_divisors(in.p);
    BOOST_TEST(groups.early == std::vector<int>({b, d}));
    BOOST_TEST(groups.late == std::vector<int>({pa, qc}));
    BOOST_TEST(!compile::divides_early(in.p));

    const compile::program ordered = compile::ordered_for_registers(in.p);
    BOOST_TEST(operations(ordered) == "/+/+//+");
    BOOST_TEST(!compile::divides_early(ordered));
    const std::vector<double> values{1, 2, 3, 4, 3, 3.75};  // 3/1.5 + 3.75/3.75
    BOOST_TEST(compile::run<double>(ordered, values).front() == 3.0);
}

BOOST_AUTO_TEST_CASE(ordered_for_registers_keeps_a_program_no_order_can_serve)
{
    // l = a / b + c, a late divisor; r = d / l; m = r + e, a late divisor too, which needs the
    // division by l; then g / m. A division by a late divisor waits for every late divisor
    // that does not need it: d / l for m, which needs d / l. No order serves: the program is
    // kept as it is, and it divides early.
    using compile::opcode;
    program_builder in(6);
    const int a = 0, b = 1, c = 2, d = 3, e = 4, g = 5;
    const int ab = in(opcode::div, a, b);
    const int l = in(opcode::add, ab, c);
    const int r = in(opcode::div, d, l);
    const int m = in(opcode::add, r, e);
    in.p.outputs.push_back(in(opcode::div, g, m));
    BOOST_TEST(compile::divides_early(in.p));

    const compile::program kept = compile::ordered_for_registers(in.p);
    BOOST_TEST(operations(kept) == "/+/+/");
    BOOST_TEST(kept.code.size() == in.p.code.size());
    for (std::size_t i = 0; i < kept.code.size(); ++i) {
        BOOST_TEST(kept.code[i].a == in.p.code[i].a);
        BOOST_TEST(kept.code[i].b == in.p.code[i].b);
    }
    BOOST_TEST(kept.outputs == in.p.outputs);
    BOOST_TEST(compile::divides_early(kept));
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_CASE(the_claims_of_one_quote_come_to_one_finding)
{
    using impact::emit::one_finding;
    BOOST_TEST(one_finding({"proven", "proven"}) == "both proven");
    BOOST_TEST(one_finding({"proven", "proven", "proven"}) == "all proven");
    BOOST_TEST(one_finding({"as checked, it does not hold", "as checked, it does not hold"}) ==
               "as checked, neither holds");
    BOOST_TEST(one_finding({"as checked, it does not hold", "as checked, it does not hold",
                            "as checked, it does not hold"}) == "as checked, none holds");
    // Outcomes that differ are said check by check.
    BOOST_TEST(one_finding({"proven", "neither proven nor refuted"}) ==
               "the 1st check: proven; the 2nd check: neither proven nor refuted");
    BOOST_TEST(one_finding({"proven", "proven", "proven", "as checked, it does not hold"}) ==
               "the 1st check: proven; the 2nd check: proven; the 3rd check: proven; the 4th check: as checked, it "
               "does not hold");
    // One finding of different values (Fig. 2's restitutions said to increase): said once.
    BOOST_TEST(one_finding({"the reverse holds: $a < b$", "the reverse holds: $b < c$"}) ==
               "the reverse holds in each check: $a < b$ and $b < c$");
    // In a row that disagrees, the checks that agree are named, not told again.
    BOOST_TEST(one_finding({"proven", "it holds only where $a = b$", "refuted, as the paper says"},
                           {true, false, true}) ==
               "the 2nd check: it holds only where $a = b$; the 1st and 3rd checks agree with the paper");
    BOOST_TEST(one_finding({"proven", "as checked, it does not hold"}, {true, false}) ==
               "the 2nd check: as checked, it does not hold; the 1st check agrees with the paper");
    BOOST_TEST(one_finding({"proven", "proven"}, {true, true}) == "both proven");
    // Labelled checks are named by their labels (Footnote 11's contrapositive and converse).
    BOOST_TEST(one_finding({"it holds, where the paper says it does not", "refuted", "proven"}, {false, true, true},
                           {"the contrapositive", "the converse", ""}) ==
               "the contrapositive: it holds, where the paper says it does not; the converse and the 3rd check "
               "agree with the paper");
    BOOST_TEST(one_finding({"proven", "as checked, it does not hold"}, {}, {"the first reading", ""}) ==
               "the first reading: proven; the 2nd check: as checked, it does not hold");
    BOOST_TEST(one_finding({"the reverse holds: $a < b$", "derived, $z = 0$"}) ==
               "the 1st check: the reverse holds: $a < b$; the 2nd check: derived, $z = 0$");
}

// The interpreter's C library calls, correctly rounded so that a measurement is the same on
// every machine: against decimal expansions typed here, which the compiler rounds to nearest.
template <class Real>
void library_calls_are_correctly_rounded(Real quarter_pi, Real three_quarters_pi, Real pi, Real third_pi)
{
    BOOST_TEST(compile::correctly_rounded("atan2", Real(1), Real(1)) == quarter_pi);
    BOOST_TEST(compile::correctly_rounded("atan2", Real(-1), Real(-1)) == -three_quarters_pi);
    BOOST_TEST(compile::correctly_rounded("atan2", Real(3), Real(3)) == quarter_pi);
    BOOST_TEST(compile::correctly_rounded("atan", Real(1), Real(0)) == quarter_pi);
    BOOST_TEST(compile::correctly_rounded("acos", Real(-1), Real(0)) == pi);
    BOOST_TEST(compile::correctly_rounded("acos", Real(0.5), Real(0)) == third_pi);
    // sqrt is correctly rounded by IEEE 754, 2^(1/2) must be the same.
    BOOST_TEST(compile::correctly_rounded("pow", Real(2), Real(0.5)) == std::sqrt(Real(2)));
    // atan(x) = x - x^3/3 + ...: a tiny x, and the smallest subnormal, are their own atan.
    BOOST_TEST(compile::correctly_rounded("atan", Real(1e-30), Real(0)) == Real(1e-30));
    const Real tiny = std::numeric_limits<Real>::denorm_min();
    BOOST_TEST(compile::correctly_rounded("atan2", tiny, Real(1)) == tiny);
    // Signed zeros kept: atan2(-0, -1) = -pi; -denorm_min/2, a tie, rounds to even: -0.
    BOOST_TEST(compile::correctly_rounded("atan2", Real(0), Real(-1)) == pi);
    BOOST_TEST(compile::correctly_rounded("atan2", -Real(0), Real(-1)) == -pi);
    BOOST_TEST(compile::correctly_rounded("atan2", Real(1), Real(0)) == pi / 2);
    BOOST_TEST(compile::correctly_rounded("acos", Real(0), Real(0)) == pi / 2);
    const Real half_tiny = compile::correctly_rounded("atan2", -tiny, Real(2));
    BOOST_TEST((half_tiny == 0 && std::signbit(half_tiny)));
    // An integer power exactly: (-3)^5.
    BOOST_TEST(compile::correctly_rounded("pow", Real(-3), Real(5)) == Real(-243));
    // Outside the domain: the C library's NaN.
    BOOST_TEST(std::isnan(compile::correctly_rounded("acos", Real(2), Real(0))));
    // A function no kernel calls (compile/functions.h) has no interpreter.
    BOOST_CHECK_THROW(compile::correctly_rounded("asinh", Real(1), Real(0)), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(the_interpreter_s_library_calls_are_correctly_rounded_in_every_type)
{
    library_calls_are_correctly_rounded<float>(0.785398163397448309615660845819875721f,
                                               2.356194490192344928846982537459627163f,
                                               3.141592653589793238462643383279502884f,
                                               1.047197551196597746154214461093167628f);
    library_calls_are_correctly_rounded<double>(0.785398163397448309615660845819875721,
                                                2.356194490192344928846982537459627163,
                                                3.141592653589793238462643383279502884,
                                                1.047197551196597746154214461093167628);
    // 1601^5 = 10518568985608001, odd and of 54 bits: halfway between two doubles, rounded to
    // the even one (exp(5 ln 1601) at 60 digits would fall on either side of the tie).
    BOOST_TEST(compile::correctly_rounded("pow", 1601.0, 5.0) == 10518568985608000.0);
    library_calls_are_correctly_rounded<long double>(0.785398163397448309615660845819875721L,
                                                     2.356194490192344928846982537459627163L,
                                                     3.141592653589793238462643383279502884L,
                                                     1.047197551196597746154214461093167628L);
}
