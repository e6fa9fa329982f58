// The emitters: exact text for C++, LaTeX and GiNaC syntax, in a fixed order.
#define BOOST_TEST_MODULE test_emit
#include <boost/test/unit_test.hpp>

#include "emit/cxx.h"
#include "engine/infix.h"

using namespace impact;

namespace {

// Symbols of Eq. 8, ranked as declared: M, m, v_M, v_m, eps.
struct eq8_symbols {
    GiNaC::possymbol M{"M", "M"}, m{"m", "m"};
    GiNaC::realsymbol vM{"v_M", "v_{M}"}, vm{"v_m", "v_{m}"}, eps{"eps", "\\epsilon"};
    GiNaC::realsymbol vMp{"v_M_after", "v'_{M}"};
    engine::term_order order{{M, m, vM, vm, eps, vMp}};
};

} // namespace

BOOST_FIXTURE_TEST_SUITE(cxx, eq8_symbols)

BOOST_AUTO_TEST_CASE(eq8_is_written_numerator_over_denominator)
{
    BOOST_TEST(emit::cxx((M * vM + m * vm + eps * m * (vm - vM)) / (M + m), order) ==
               "(M * v_M + m * v_m - m * eps * (v_M - v_m)) / (M + m)");
    BOOST_TEST(emit::cxx(M * m * (1 + eps) * (vM - vm) / (M + m), order) ==
               "M * m * (Real(1) + eps) * (v_M - v_m) / (M + m)");
}

BOOST_AUTO_TEST_CASE(powers_roots_and_functions_use_the_standard_library)
{
    BOOST_TEST(emit::cxx(GiNaC::pow(vM, 2), order) == "v_M * v_M");
    BOOST_TEST(emit::cxx(GiNaC::pow(vM + vm, 2), order) == "(v_M + v_m) * (v_M + v_m)");
    BOOST_TEST(emit::cxx(GiNaC::sqrt(M + m), order) == "std::sqrt(M + m)");
    BOOST_TEST(emit::cxx(1 / GiNaC::sqrt(M), order) == "Real(1) / std::sqrt(M)");
    BOOST_TEST(emit::cxx(GiNaC::pow(M, 7), order) == "std::pow(M, Real(7))");
    BOOST_TEST(emit::cxx(GiNaC::acos(eps), order) == "std::acos(eps)");
}

BOOST_AUTO_TEST_CASE(numbers_are_literals_of_the_kernel_type)
{
    BOOST_TEST(emit::cxx(vM / 2, order) == "v_M / Real(2)");
    BOOST_TEST(emit::cxx(-3 * M * vM, order) == "-Real(3) * M * v_M");
    BOOST_TEST(emit::cxx(vM - 1, order) == "v_M - Real(1)");
    BOOST_TEST(emit::cxx(1 - eps * eps, order) == "Real(1) - eps * eps");
    BOOST_TEST(emit::cxx(GiNaC::numeric(-1, 2), order) == "-Real(1) / Real(2)");
}

BOOST_AUTO_TEST_SUITE_END()


BOOST_AUTO_TEST_CASE(order_does_not_depend_on_how_gi_nac_stored_the_expression)
{
    // The same sum built from symbols made in a different order prints identically.
    GiNaC::realsymbol b("b"), a("a"), c("c");
    const engine::term_order order({a, b, c});
    BOOST_TEST(engine::ginac_syntax(c * (b - a) + b * a, order) == "a*b-c*(a-b)");
    BOOST_TEST(engine::ginac_syntax((a - b) * c + a * b, order) == "a*b+c*(a-b)");
    BOOST_TEST(engine::ginac_syntax(GiNaC::pow(a, 2) / (b + c), order) == "a^2/(b+c)");
}
