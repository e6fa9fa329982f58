// The C library functions a kernel calls (compile/functions.h): their values computed by CLN,
// against values typed here to 42 digits (from tables and from mpmath, an implementation of
// its own), where the arguments make them hard: an argument reduction of 10^22, cancellations
// near 0 (log1p, expm1, acos near 1, cos at the double nearest π/2), and exact values where
// they are rational. And the interpreter's calls, rounded from them, in every type.
#define BOOST_TEST_MODULE test_functions
#include <boost/test/unit_test.hpp>

#include "compile/functions.h"
#include "compile/program.h"
#include "engine/library/library.h"
#include "pipeline/regenerate.h"
#include "spec/derivation.h"
#include "verify/cancellation.h"

#include <cln/cln.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include <unistd.h>

namespace {

using namespace impact;

// A decimal typed as text ("-0.84147...", "9.99...e-21"), exactly as a rational.
cln::cl_RA decimal(const std::string& text)
{
    const std::size_t e = text.find('e');
    const std::string mantissa = text.substr(0, e);
    const long exponent = e == std::string::npos ? 0 : std::stol(text.substr(e + 1));
    const std::size_t point = mantissa.find('.');
    std::string digits = mantissa.substr(0, point) + (point == std::string::npos ? "" : mantissa.substr(point + 1));
    const long decimals = point == std::string::npos ? 0 : static_cast<long>(mantissa.size() - point - 1);
    const cln::cl_I n(digits.c_str());
    const long shift = exponent - decimals;
    return shift >= 0 ? cln::cl_RA(n * cln::expt_pos(cln::cl_I(10), shift))
                      : cln::cl_RA(n / cln::expt_pos(cln::cl_I(10), -shift));
}

cln::cl_RA ratio(long p, long q)
{
    return cln::cl_RA(p) / cln::cl_RA(q);
}

// std::f(a, b) to 40 digits agrees with `expected` (typed to 42) within 10^-38 of its size.
void agrees(const std::string& f, const cln::cl_RA& a, const cln::cl_RA& b, const std::string& expected)
{
    const std::optional<cln::cl_R> v = compile::exact_value(f, a, b, 40);
    BOOST_REQUIRE_MESSAGE(v.has_value(), f << " has no value");
    const cln::cl_RA want = decimal(expected);
    const cln::cl_RA gap = cln::abs(cln::rational(*v) - want);
    BOOST_TEST((gap <= cln::abs(want) / cln::expt_pos(cln::cl_I(10), 38)),
               f << ": " << *v << " against " << expected);
}

} // namespace

BOOST_AUTO_TEST_SUITE(test_functions)

BOOST_AUTO_TEST_CASE(each_function_is_evaluated_to_40_digits_by_cln)
{
    agrees("sin", 1, 0, "0.841470984807896506652502321630298999622563");
    agrees("cos", 1, 0, "0.54030230586813971740093660744297660373231");
    agrees("tan", 1, 0, "1.55740772465490223050697480745836017308725");
    agrees("asin", ratio(3, 10), 0, "0.30469265401539750797200296122752916695456");
    agrees("acos", ratio(3, 10), 0, "1.26610367277949911125931873041222227514402");
    agrees("atan", 3, 0, "1.24904577239825442582991707728109012307783");
    agrees("atan2", 1, -2, "2.67794504458898712224838715181828848216863");   // the point (-2, 1)
    agrees("exp", ratio(-5, 2), 0, "0.0820849986238987951695286744671598078378041");
    agrees("log", 10, 0, "2.3025850929940456840179914546843642076011");
    agrees("sinh", ratio(1, 2), 0, "0.521095305493747361622425626411491559105929");
    agrees("cosh", 2, 0, "3.76219569108363145956221347777374610829397");
    agrees("tanh", ratio(1, 4), 0, "0.244918662403709129277801131491016957506559");
    agrees("tanh", -20, 0, "-0.999999999999999991503291489416822045438558");
    agrees("pow", 3, ratio(3, 4), "2.27950705695477764199356325196363600619032");
    agrees("asin", -1, 0, "-1.57079632679489661923132169163975144209858");
}

BOOST_AUTO_TEST_CASE(hard_arguments_keep_every_digit)
{
    // sin(10^22): an argument reduction by 10^22 / 2π turns.
    agrees("sin", cln::expt_pos(cln::cl_I(10), 22), 0, "-0.852200849767188801772705893753029368261762");
    // cos at the double nearest π/2: 6.1e-17, what is left of π/2 after rounding.
    agrees("cos", cln::rational(cln::cl_DF(1.5707963267948966)), 0, "6.12323399573676588613032966137500146464038e-17");
    // Cancellations near 0: log(1 + x), exp(x) − 1, acos near 1, sinh of a tiny x.
    const cln::cl_RA tiny = cln::cl_RA(1) / cln::expt_pos(cln::cl_I(10), 20);
    agrees("log1p", tiny, 0, "9.99999999999999999995000000000000000000033e-21");
    agrees("expm1", -cln::cl_RA(1) / cln::expt_pos(cln::cl_I(10), 15), 0,
           "-9.99999999999999500000000000000166666666667e-16");
    agrees("acos", 1 - cln::cl_RA(1) / cln::expt_pos(cln::cl_I(2), 52), 0,
           "0.0000000210734242554470162834211642882121161990957");
    agrees("sinh", cln::cl_RA(1) / cln::expt_pos(cln::cl_I(10), 30), 0, "1.0e-30");
}

BOOST_AUTO_TEST_CASE(rational_values_are_exact_and_values_outside_the_domain_are_none)
{
    const auto exact = [](const std::string& f, const cln::cl_RA& a, const cln::cl_RA& b) {
        const std::optional<cln::cl_R> v = compile::exact_value(f, a, b, 40);
        BOOST_REQUIRE(v.has_value());
        BOOST_REQUIRE(cln::instanceof(*v, cln::cl_RA_ring));
        return cln::the<cln::cl_RA>(*v);
    };
    BOOST_TEST((exact("pow", ratio(1, 2), -3) == 8));
    BOOST_TEST((exact("pow", -3, 5) == -243));
    BOOST_TEST((exact("sin", 0, 0) == 0));
    BOOST_TEST((exact("log", 1, 0) == 0));
    BOOST_TEST((exact("acos", 1, 0) == 0));
    BOOST_TEST((exact("cosh", 0, 0) == 1));
    for (const auto& [f, a, b] : {std::tuple<const char*, cln::cl_RA, cln::cl_RA>{"log", 0, 0},
                                  {"log", -1, 0},
                                  {"log1p", -1, 0},
                                  {"acos", 2, 0},
                                  {"asin", ratio(-11, 10), 0},
                                  {"atan2", 0, 0},
                                  {"pow", 0, -1},
                                  {"pow", -2, ratio(1, 2)},
                                  {"exp", 1000000, 0}})
        BOOST_TEST(!compile::exact_value(f, a, b, 40).has_value(), f);
}

// The interpreter's calls, correctly rounded: against decimals typed here, which the compiler
// rounds to the nearest of each type. `big` is 10^22 rounded to the type (exactly 10^22 in
// double and long double; 9999999778196308361216 in float), `sin_big` its sine.
template <class Real>
void rounded_in(Real big, Real sin_big, Real sin_1, Real tanh_quarter, Real pi)
{
    BOOST_TEST(compile::correctly_rounded("sin", big, Real(0)) == sin_big);
    BOOST_TEST(compile::correctly_rounded("sin", Real(1), Real(0)) == sin_1);
    BOOST_TEST(compile::correctly_rounded("sin", Real(-1), Real(0)) == -sin_1);
    BOOST_TEST(compile::correctly_rounded("tanh", Real(0.25), Real(0)) == tanh_quarter);
    // exp(x) − 1 and log(1 + x) of a tiny x are x (1 ± x/2 + ...), x itself in every type,
    // where 1 + x rounds to 1.
    const Real tiny = Real(1e-30);
    BOOST_TEST(compile::correctly_rounded("expm1", tiny, Real(0)) == tiny);
    BOOST_TEST(compile::correctly_rounded("log1p", tiny, Real(0)) == tiny);
    // Zeros keep their sign, as the C library keeps it.
    for (const char* f : {"sin", "tan", "asin", "atan", "sinh", "tanh", "expm1", "log1p"}) {
        const Real z = compile::correctly_rounded(f, -Real(0), Real(0));
        BOOST_TEST((z == 0 && std::signbit(z)), f);
    }
    BOOST_TEST(compile::rounded_pi<Real>() == pi);
    BOOST_TEST(compile::correctly_rounded("acos", Real(-1), Real(0)) == pi);
    BOOST_TEST(std::isnan(compile::correctly_rounded("log", Real(-1), Real(0))));
}

BOOST_AUTO_TEST_CASE(the_interpreter_rounds_each_function_to_nearest_in_every_type)
{
    rounded_in<float>(1e22f, -0.7340815352961015259557689076928539478302f, 0.841470984807896506652502321630298999f,
                      0.244918662403709129277801131491016957f, 3.141592653589793238462643383279502884f);
    rounded_in<double>(1e22, -0.852200849767188801772705893753029368, 0.841470984807896506652502321630298999,
                       0.244918662403709129277801131491016957, 3.141592653589793238462643383279502884);
    rounded_in<long double>(1e22L, -0.852200849767188801772705893753029368L, 0.841470984807896506652502321630298999L,
                            0.244918662403709129277801131491016957L, 3.141592653589793238462643383279502884L);
}

// The forms without cancellation (verify/cancellation.h), against the identities typed here.
BOOST_AUTO_TEST_CASE(cancelling_sums_and_arguments_are_written_by_their_identities)
{
    const GiNaC::symbol E("E"), m("m"), x("x"), a("a"), b("b"), y("y");
    const auto same = [](const GiNaC::ex& got, const GiNaC::ex& want) {
        BOOST_TEST((got - want).is_zero(), got << " against " << want);
    };
    // Compton's denominator: E − E cos x + m = 2 E sin²(x/2) + m.
    same(verify::without_cancellation(m * E / (E - E * GiNaC::cos(x) + m)),
         m * E / (2 * E * GiNaC::pow(GiNaC::sin(x / 2), 2) + m));
    same(verify::without_cancellation(3 + 3 * GiNaC::cos(x)), 6 * GiNaC::pow(GiNaC::cos(x / 2), 2));
    same(verify::without_cancellation(a * GiNaC::cosh(x) - a), 2 * a * GiNaC::pow(GiNaC::sinh(x / 2), 2));
    same(verify::without_cancellation(b * GiNaC::exp(x) - b + y), b * compile::expm1(x) + y);
    same(verify::without_cancellation(GiNaC::log(1 + x)), compile::log1p(x));
    same(verify::without_cancellation(GiNaC::log(a / b)), compile::log1p((a - b) / b));
    same(verify::without_cancellation(GiNaC::acos(1 - y)), 2 * GiNaC::asin(GiNaC::sqrt(y / 2)));
    same(verify::without_cancellation(GiNaC::acos(y - 1)), GiNaC::Pi - 2 * GiNaC::asin(GiNaC::sqrt(y / 2)));
    // Nothing cancels: the same expression.
    same(verify::without_cancellation(E - m * GiNaC::cos(x)), E - m * GiNaC::cos(x));
    same(verify::without_cancellation(GiNaC::log(a)), GiNaC::log(a));
    // The identities hold: at a point, each side's value to 30 digits.
    const GiNaC::exmap at{{x, GiNaC::numeric(1, 7)}, {y, GiNaC::numeric(1, 3)}};
    for (const GiNaC::ex& e : std::vector<GiNaC::ex>{1 - GiNaC::cos(x), GiNaC::exp(x) - 1, GiNaC::log(1 + x),
                                                     GiNaC::acos(1 - y), GiNaC::acos(y - 1), GiNaC::cosh(x) - 1}) {
        const GiNaC::ex gap = GiNaC::evalf(GiNaC::abs((e - verify::without_cancellation(e)).subs(at)));
        BOOST_TEST((GiNaC::is_a<GiNaC::numeric>(gap) && GiNaC::ex_to<GiNaC::numeric>(gap) < GiNaC::numeric(1, 1000000000)),
                   e << ": " << gap);
    }
}

// cos a − cos b of two close angles: each cosine rounded, the difference keeps none of their
// digits, and no identity here writes it otherwise. The kernel is refused, naming the output.
BOOST_AUTO_TEST_CASE(a_kernel_whose_output_misses_4_ulps_is_refused_naming_it)
{
    const std::string text = "id = \"gap\"\ntitle = \"two angles\"\n"
                             "[[symbol]]\nname = \"a\"\ndomain = \"[0, 3]\"\n"
                             "[[symbol]]\nname = \"b\"\ndomain = \"[0, 3]\"\n"
                             "[[symbol]]\nname = \"d\"\n"
                             "[[step]]\ndefine = \"d\"\nas = \"cos(a) - cos(b)\"\nbecause = \"a difference\"\n"
                             "[[result]]\nname = \"d\"\n"
                             "[[kernel]]\nname = \"gap\"\ninputs = [\"a\", \"b\"]\noutputs = [\"d = d\"]\n";
    const engine::library lib = engine::derive_all({spec::parse_derivation(text, "gap.toml")});
    std::vector<std::string> missed;
    pipeline::generate_kernels(lib, &missed);
    BOOST_REQUIRE(!missed.empty());
    BOOST_TEST(missed.front().find("gap.toml:18:8: error: kernel 'gap': output 'd' misses its bound of 4 ulps in ") ==
                   0u,
               missed.front());
}

// A batch loop that calls cos, compiled with -O3 -ffast-math: GCC would make it a loop of
// glibc's vector cos (_ZGVdN4v_cos), whose last bits differ from the scalar cos's; the loop
// calls the scalar function instead (detail::scalar_cos, never inlined), and writes what the
// scalar kernel returns, bit for bit.
BOOST_AUTO_TEST_CASE(a_batch_loop_calls_the_scalar_function_and_gives_the_scalar_kernel_s_bits)
{
    namespace fs = std::filesystem;
    const std::string text = "id = \"turn\"\ntitle = \"a velocity's part along a line\"\n"
                             "[[symbol]]\nname = \"v\"\ndimension = \"velocity\"\n"
                             "[[symbol]]\nname = \"theta\"\ndomain = \"[0, 3]\"\n"
                             "[[symbol]]\nname = \"u\"\ndimension = \"velocity\"\n"
                             "[[step]]\ndefine = \"u\"\nas = \"v*cos(theta)\"\nbecause = \"the projection\"\n"
                             "[[result]]\nname = \"u\"\n"
                             "[[kernel]]\nname = \"along\"\ninputs = [\"v\", \"theta\"]\noutputs = [\"v = u\"]\n"
                             "batch = true\n";
    const engine::library lib = engine::derive_all({spec::parse_derivation(text, "turn.toml")});
    std::vector<std::string> missed;
    const pipeline::file_set files = pipeline::generate_kernels(lib, &missed);
    BOOST_TEST(missed.empty());
    const fs::path dir = fs::temp_directory_path() / ("impact_test_batch_cos_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    std::string all;
    for (const auto& [path, header] : files) {
        fs::create_directories((dir / path).parent_path());
        std::ofstream(dir / path) << header;
        all += header;
    }
    BOOST_TEST(all.find("return v * std::cos(theta);") != std::string::npos);   // the scalar kernel
    BOOST_TEST(all.find("v_[i] = v * detail::scalar_cos(theta);") != std::string::npos);   // its loop
    std::ofstream(dir / "main.cpp")
        << "#include \"impact/along.hpp\"\n#include <cstring>\n#include <vector>\n"
           "int main()\n{\n"
           "    const std::size_t n = 4099;\n"
           "    std::vector<double> v(n), theta(n), want(n);\n"
           "    for (std::size_t i = 0; i < n; ++i) {\n"
           "        v[i] = 1.0 + double(i) / 7.0;\n"
           "        theta[i] = 3.0 * double(i) / double(n);\n"
           "        want[i] = impact::along<double>(v[i], theta[i]);\n"
           "    }\n"
           "    impact::along_batch<double>({n, v.data(), theta.data()});\n"
           "    return std::memcmp(v.data(), want.data(), n * sizeof(double)) == 0 ? 0 : 1;\n}\n";
    const std::string object = (dir / "main.o").string();
    const std::string command =
        std::string(IMPACT_CXX) + " -std=c++17 -O3 -ffast-math -I" + (dir / "kernels").string() +
        " -c " + (dir / "main.cpp").string() + " -o " + object + " && ! nm " + object + " | grep -q _ZGV && " +
        IMPACT_CXX + " -ffast-math " + object + " -o " + (dir / "main").string() + " && " + (dir / "main").string();
    BOOST_TEST(std::system(command.c_str()) == 0, command);
    fs::remove_all(dir);
}

BOOST_AUTO_TEST_SUITE_END()
