// engine/algebra/factor_split.h: polynomials factored by Gauss's lemma, checked against
// factorizations typed here.
#include "engine/algebra/factor_split.h"

#include <boost/test/unit_test.hpp>

#include <utility>
#include <vector>

using namespace impact;

namespace {

// The factors of `f` that are not numbers, each as (base expanded, exponent).
std::vector<std::pair<GiNaC::ex, int>> factors_of(const GiNaC::ex& f)
{
    std::vector<std::pair<GiNaC::ex, int>> out;
    const auto one = [&](const GiNaC::ex& x) {
        if (GiNaC::is_a<GiNaC::numeric>(x))
            return;
        if (GiNaC::is_a<GiNaC::power>(x))
            out.emplace_back(GiNaC::expand(x.op(0)), GiNaC::ex_to<GiNaC::numeric>(x.op(1)).to_int());
        else
            out.emplace_back(GiNaC::expand(x), 1);
    };
    if (GiNaC::is_a<GiNaC::mul>(f))
        for (const GiNaC::ex& x : f)
            one(x);
    else
        one(f);
    return out;
}

// `f` equals `p`, and its factors are `expected`, each up to its sign and a number.
bool factored_as(const GiNaC::ex& p, const GiNaC::ex& f, const std::vector<std::pair<GiNaC::ex, int>>& expected)
{
    if (!GiNaC::expand(f - p).is_zero())
        return false;
    std::vector<std::pair<GiNaC::ex, int>> found = factors_of(f);
    if (found.size() != expected.size())
        return false;
    for (const auto& [base, times] : expected) {
        bool matched = false;
        for (auto& [b, k] : found) {
            if (k != times || b.is_zero())
                continue;
            const GiNaC::ex ratio = GiNaC::normal(b / base);
            if (GiNaC::is_a<GiNaC::numeric>(ratio)) {
                b = 0;   // each found factor matches one expected factor
                matched = true;
                break;
            }
        }
        if (!matched)
            return false;
    }
    return true;
}

} // namespace

BOOST_AUTO_TEST_SUITE(factor_split)

BOOST_AUTO_TEST_CASE(symbols_dividing_every_term_and_a_common_sum_are_split_off)
{
    // x^2 y (1 + eps) (M v + m w): x and y divide every term; in v, a = M (1 + eps) and
    // b = m w (1 + eps) share 1 + eps, and what is left, M v + m w, is irreducible.
    const GiNaC::symbol x("x"), y("y"), eps("eps"), M("M"), m("m"), v("v"), w("w");
    const GiNaC::ex p = GiNaC::expand(6 * x * x * y * (1 + eps) * (M * v + m * w));
    const GiNaC::ex f = engine::factor_split(p);
    BOOST_TEST(factored_as(p, f, {{x, 2}, {y, 1}, {1 + eps, 1}, {M * v + m * w, 1}}), f);
}

BOOST_AUTO_TEST_CASE(a_factor_shared_twice_keeps_its_power)
{
    // (1 + b)^2 (r s + t u + 1): in r, a = s (1 + b)^2 and b' = (t u + 1)(1 + b)^2.
    const GiNaC::symbol b("b"), r("r"), s("s"), t("t"), u("u");
    const GiNaC::ex p = GiNaC::expand(GiNaC::pow(1 + b, 2) * (r * s + t * u + 1));
    const GiNaC::ex f = engine::factor_split(p);
    BOOST_TEST(factored_as(p, f, {{1 + b, 2}, {r * s + t * u + 1, 1}}), f);
}

BOOST_AUTO_TEST_CASE(a_sum_of_degree_one_with_coprime_coefficients_is_one_factor)
{
    // In x: a = y + z and b = y z + 1 have no common factor (though they share y and z).
    const GiNaC::symbol x("x"), y("y"), z("z");
    const GiNaC::ex p = GiNaC::expand(x * (y + z) + y * z + 1);
    const GiNaC::ex f = engine::factor_split(p);
    BOOST_TEST(factored_as(p, f, {{p, 1}}), f);
}

BOOST_AUTO_TEST_CASE(a_sum_of_no_degree_one_symbol_is_left_to_factor)
{
    // x^2 y^2 - z^2 (each symbol squared) is (x y - z)(x y + z), times 3 a^2 split off first.
    const GiNaC::symbol a("a"), x("x"), y("y"), z("z");
    const GiNaC::ex p = GiNaC::expand(3 * a * a * (x * x * y * y - z * z));
    const GiNaC::ex f = engine::factor_split(p);
    BOOST_TEST(factored_as(p, f, {{a, 2}, {x * y - z, 1}, {x * y + z, 1}}), f);
}

BOOST_AUTO_TEST_CASE(the_shared_part_is_factored_in_turn)
{
    // (M + m)(1 - q)(v_M - v_m) + ...: in v_M, a = (M + m)(1 - q) and b = -(M + m)(1 - q) v_m
    // + (M + m)(1 - q) J: the common part (M + m)(1 - q) is split again into its two factors.
    const GiNaC::symbol M("M"), m("m"), q("q"), vM("v_M"), vm("v_m"), J("J");
    const GiNaC::ex p = GiNaC::expand((M + m) * (1 - q) * (vM - vm + J));
    const GiNaC::ex f = engine::factor_split(p);
    BOOST_TEST(factored_as(p, f, {{M + m, 1}, {1 - q, 1}, {vM - vm + J, 1}}), f);
}

BOOST_AUTO_TEST_SUITE_END()
