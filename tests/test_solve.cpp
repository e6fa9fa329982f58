// Solving equations that are not linear: every solution found, substituted back and
// proven, kept or rejected by the unknowns' domains or by the step's `reject`
// conditions, and a system left with several admissible solutions refused.
//
// The derivation files are written for these tests (tests/solve/), not the paper's; the
// expected solutions are closed forms typed here.
#define BOOST_TEST_MODULE test_solve
#include <boost/test/unit_test.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdio>

#include "derivation_support.h"
#include "support.h"

#include "emit/json.h"
#include "emit/latex.h"
#include "emit/terminal.h"
#include "engine/derivation/derivation.h"

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace fs = std::filesystem;

namespace {

using namespace impact;
using namespace impact::testing;

// The value a solution gives `unknown`.
GiNaC::ex value_in(const engine::solution& s, const GiNaC::ex& unknown)
{
    for (const auto& [u, v] : s.values)
        if (u.is_equal(unknown))
            return v;
    BOOST_FAIL("the solution has no value for the unknown");
    throw;
}

bool every_step_check_proven(const engine::step_result& s)
{
    return !s.checks.empty() && std::all_of(s.checks.begin(), s.checks.end(), [](const engine::check_result& c) {
        return c.outcome.what == engine::verdict::status::proven;
    });
}

// The value of `e` at a point (symbol = number), to 30 digits.
double at(const GiNaC::ex& e, const GiNaC::exmap& point)
{
    return GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(e.subs(point))).to_double();
}

// A value found in the solutions of the step, whatever its order.
bool has_solution(const engine::step_result& step, const GiNaC::ex& unknown, const GiNaC::ex& expected,
                  const GiNaC::exmap& point)
{
    return std::any_of(step.solutions.begin(), step.solutions.end(), [&](const engine::solution& s) {
        return std::abs(at(value_in(s, unknown), point) - at(expected, point)) < 1e-12;
    });
}

// x > 0 and real y, with `body` appended.
std::string with_x_and_y(const std::string& body)
{
    return "id = \"t\"\ntitle = \"test\"\n[[symbol]]\nname = \"x\"\ndomain = \"positive\"\n"
           "[[symbol]]\nname = \"y\"\n" + body;
}

} // namespace

BOOST_AUTO_TEST_SUITE(test_solve)

BOOST_AUTO_TEST_CASE(ballistic_pendulum_keeps_the_positive_root)
{
    const engine::derivation d = derive_file("tests/solve/ballistic_pendulum.toml");
    const GiNaC::ex m = sym(d, "m"), M = sym(d, "M"), g = sym(d, "g"), h = sym(d, "h");
    const GiNaC::ex V = sym(d, "V"), v = sym(d, "v");
    // V = sqrt(2 g h): the swing; v = (m + M) V / m: the impact.
    BOOST_TEST(equal(value_of(d, "V"), GiNaC::sqrt(2 * g * h)));
    BOOST_TEST(equal(value_of(d, "v"), (m + M) * GiNaC::sqrt(2 * g * h) / m));

    const engine::step_result& step = d.steps.front();
    BOOST_TEST_REQUIRE(step.solutions.size() == 2u);
    const auto rejected = std::find_if(step.solutions.begin(), step.solutions.end(),
                                       [](const engine::solution& s) { return !s.kept(); });
    BOOST_TEST_REQUIRE((rejected != step.solutions.end()));
    BOOST_TEST((rejected->outcome == engine::solution::fate::outside_domain));
    BOOST_TEST(rejected->unknown.is_equal(V));
    BOOST_TEST(equal(value_in(*rejected, V), -GiNaC::sqrt(2 * g * h)));
    BOOST_TEST(equal(value_in(*rejected, v), -(m + M) * GiNaC::sqrt(2 * g * h) / m));
    BOOST_TEST(!rejected->proof.empty());
    // Both solutions, the rejected one too, substituted back into both equations.
    BOOST_TEST(step.checks.size() == 4u);
    BOOST_TEST(every_step_check_proven(step));
    BOOST_TEST(d.all_hold());
}

BOOST_AUTO_TEST_CASE(time_of_flight_rejects_the_launch_by_the_domain_of_T)
{
    const engine::derivation d = derive_file("tests/solve/projectile_flight.toml");
    const GiNaC::ex w = sym(d, "w"), g = sym(d, "g"), T = sym(d, "T");
    BOOST_TEST(equal(value_of(d, "T"), 2 * w / g));
    const engine::step_result& step = d.steps.front();
    BOOST_TEST_REQUIRE(step.solutions.size() == 2u);
    const engine::solution& launch = step.solutions[0].kept() ? step.solutions[1] : step.solutions[0];
    BOOST_TEST((launch.outcome == engine::solution::fate::outside_domain));
    BOOST_TEST(value_in(launch, T).is_zero());
    BOOST_TEST(launch.why == "T > 0, but T = 0");
    BOOST_TEST(every_step_check_proven(step));
    BOOST_TEST(d.all_hold());
}

BOOST_AUTO_TEST_CASE(elastic_collision_solved_from_momentum_and_energy_gives_eq3)
{
    const engine::derivation d = derive_file("tests/solve/elastic_from_conservation.toml");
    const GiNaC::ex M = sym(d, "M"), m = sym(d, "m"), v_M = sym(d, "v_M"), v_m = sym(d, "v_m");
    // Eq. 3 of the paper (v'_m with 2 M v_M, as Eq. 4 has it).
    BOOST_TEST(equal(value_of(d, "v_M_after"), ((M - m) * v_M + 2 * m * v_m) / (M + m)));
    BOOST_TEST(equal(value_of(d, "v_m_after"), ((m - M) * v_m + 2 * M * v_M) / (M + m)));

    const engine::step_result& step = d.steps.front();
    BOOST_TEST_REQUIRE(step.solutions.size() == 2u);
    const engine::solution& through = step.solutions[0].kept() ? step.solutions[1] : step.solutions[0];
    BOOST_TEST((through.outcome == engine::solution::fate::condition));
    BOOST_TEST(equal(value_in(through, sym(d, "v_M_after")), v_M));
    BOOST_TEST(equal(value_in(through, sym(d, "v_m_after")), v_m));
    BOOST_TEST(through.why == "the spheres would pass through each other unchanged");
    BOOST_TEST(every_step_check_proven(step));
    BOOST_TEST(d.all_hold());
}

BOOST_AUTO_TEST_CASE(equal_masses_exchange_velocities_in_the_direct_solution)
{
    const engine::derivation direct = derive_file("tests/solve/elastic_from_conservation.toml");
    const GiNaC::ex M = sym(direct, "M"), m = sym(direct, "m");
    BOOST_TEST(equal(value_of(direct, "v_M_after").subs(M == m), sym(direct, "v_m")));
    BOOST_TEST(equal(value_of(direct, "v_m_after").subs(M == m), sym(direct, "v_M")));
}

BOOST_AUTO_TEST_CASE(a_coefficient_holding_an_unknown_is_split_on_aimed_throw)
{
    // X = u T and Y = u T - g T^2/2: u = X/T leaves g T^2 = 2 (X - Y).
    const engine::derivation d = derive_file("tests/solve/aimed_throw.toml");
    const GiNaC::ex X = sym(d, "X"), Y = sym(d, "Y"), g = sym(d, "g"), u = sym(d, "u"), T = sym(d, "T");
    const GiNaC::ex time = value_of(d, "T"), speed = value_of(d, "u");
    BOOST_TEST(equal(time * time, 2 * (X - Y) / g));
    BOOST_TEST(equal(speed * speed, g * X * X / (2 * (X - Y))));
    // At X = 3, Y = 1, g = 10: T = sqrt(2/5), u = 3 sqrt(5/2), both positive.
    const GiNaC::exmap point{{X, 3}, {Y, 1}, {g, 10}};
    BOOST_TEST(at(time, point) == std::sqrt(0.4), boost::test_tools::tolerance(1e-12));
    BOOST_TEST(at(speed, point) == 3 * std::sqrt(2.5), boost::test_tools::tolerance(1e-12));
    const engine::step_result& step = d.steps.front();
    BOOST_TEST_REQUIRE(step.solutions.size() == 2u);
    BOOST_TEST(has_solution(step, T, -GiNaC::sqrt(2 * (X - Y) / g), point));
    BOOST_TEST((step.solutions.back().outcome == engine::solution::fate::outside_domain));
    BOOST_TEST(every_step_check_proven(step));
    BOOST_TEST(d.all_hold());
}

BOOST_AUTO_TEST_CASE(a_mass_weighed_by_an_elastic_collision)
{
    // Eqs. 1a and 1b for m and v'_m: v'_m = v'_M + v_M - v_m (Eq. 2), and m from momentum.
    const engine::derivation d = derive_file("tests/solve/unknown_mass.toml");
    const GiNaC::ex M = sym(d, "M"), v_M = sym(d, "v_M"), v_m = sym(d, "v_m"), after = sym(d, "v_M_after");
    BOOST_TEST(equal(value_of(d, "v_m_after"), after + v_M - v_m));
    BOOST_TEST(equal(value_of(d, "m"), M * (v_M - after) / (v_M + after - 2 * v_m)));
    // v'_m = v_m is the split's other branch: momentum then asks M v_M = M v'_M, no solution.
    BOOST_TEST(d.steps.front().solutions.size() == 1u);
    BOOST_TEST(every_step_check_proven(d.steps.front()));
    BOOST_TEST(d.all_hold());
}

BOOST_AUTO_TEST_CASE(a_resultant_finds_where_two_circles_meet)
{
    // x^2 + y^2 = R^2 and (x - d)^2 + y^2 = r^2: x = (R^2 - r^2 + d^2)/(2d), y = sqrt(R^2 - x^2).
    const engine::derivation d = derive_file("tests/solve/hung_lamp.toml");
    const GiNaC::ex R = sym(d, "R"), r = sym(d, "r"), D = sym(d, "d"), x = sym(d, "x"), y = sym(d, "y");
    const GiNaC::ex across = (R * R - r * r + D * D) / (2 * D);
    BOOST_TEST(equal(value_of(d, "x"), across));
    BOOST_TEST(equal(GiNaC::pow(value_of(d, "y"), 2), R * R - across * across));
    // R = 5, r = 4, d = 3: a right angle at the lamp, at (3, 4)... from the first hook
    // x = (25 - 16 + 9)/6 = 3, y = 4.
    const GiNaC::exmap point{{R, 5}, {r, 4}, {D, 3}};
    BOOST_TEST(at(value_of(d, "y"), point) == 4.0, boost::test_tools::tolerance(1e-12));
    // The roots of the resultant give y = ±4; x = -3 from the first circle is no root of
    // the second and is dropped: two solutions, one rejected by y's domain.
    const engine::step_result& step = d.steps.front();
    BOOST_TEST_REQUIRE(step.solutions.size() == 2u);
    BOOST_TEST(has_solution(step, y, -4, point));
    BOOST_TEST(!has_solution(step, x, -3, point));
    BOOST_TEST(every_step_check_proven(step));
    BOOST_TEST(d.all_hold());
}

BOOST_AUTO_TEST_CASE(a_throw_of_given_speed_has_two_trajectories_and_is_refused)
{
    // Through (X, 0) at speed s: X = u T, w T = g T^2/2, u^2 + w^2 = s^2, so that
    // g^2 T^4 - 4 s^2 T^2 + 4 X^2 = 0, a quadratic in T^2 with two positive roots: the
    // flat and the lobbed throw, both admissible.
    const std::string text =
        "id = \"t\"\ntitle = \"test\"\n"
        "[[symbol]]\nname = \"X\"\ndomain = \"positive\"\n[[symbol]]\nname = \"s\"\ndomain = \"positive\"\n"
        "[[symbol]]\nname = \"g\"\ndomain = \"positive\"\n[[symbol]]\nname = \"u\"\ndomain = \"positive\"\n"
        "[[symbol]]\nname = \"w\"\ndomain = \"positive\"\n[[symbol]]\nname = \"T\"\ndomain = \"positive\"\n"
        "[[given]]\nname = \"across\"\nequation = \"X = u*T\"\nbecause = \"h\"\n"
        "[[given]]\nname = \"up\"\nequation = \"0 = w*T - g*T^2/2\"\nbecause = \"h\"\n"
        "[[given]]\nname = \"speed\"\nequation = \"u^2 + w^2 = s^2\"\nbecause = \"h\"\n"
        "[[step]]\nsolve = [\"across\", \"up\", \"speed\"]\nfor = [\"u\", \"w\", \"T\"]\n"
        "[[result]]\nname = \"u\"\n";
    const std::string message = error_for(text).message();
    BOOST_TEST(message.find("2 solutions are admissible: ") == 0u, message);
    BOOST_TEST(message.find("T = sqrt(2)*sqrt(s^2+sqrt(-X^2*g^2+s^4))/g") != std::string::npos, message);
    BOOST_TEST(message.find("T = sqrt(2)*sqrt(s^2-sqrt(-X^2*g^2+s^4))/g") != std::string::npos, message);
}

BOOST_AUTO_TEST_CASE(the_flat_throw_of_given_speed_is_kept_when_the_lob_is_rejected)
{
    // The same system with reject = ["g^2*T^2 = 2*s^2 + 2*sqrt(s^4 - g^2*X^2)"]: the flat
    // throw, g^2 T^2 = 2 s^2 - 2 sqrt(s^4 - g^2 X^2), w = g T/2, u = X/T.
    const engine::derivation d = derive_file("tests/solve/throw_of_given_speed.toml");
    const GiNaC::ex X = sym(d, "X"), s = sym(d, "s"), g = sym(d, "g"), T = sym(d, "T");
    const GiNaC::exmap point{{X, 3}, {s, 10}, {g, 10}};
    const double flat = std::sqrt(2 * (100 - std::sqrt(10000.0 - 900)) / 100);
    const double lob = std::sqrt(2 * (100 + std::sqrt(10000.0 - 900)) / 100);
    BOOST_TEST(at(value_of(d, "T"), point) == flat, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(at(value_of(d, "w"), point) == 10 * flat / 2, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(at(value_of(d, "u"), point) == 3 / flat, boost::test_tools::tolerance(1e-12));
    const engine::step_result& step = d.steps.front();
    BOOST_TEST_REQUIRE(step.solutions.size() == 4u);
    const auto lobbed = std::find_if(step.solutions.begin(), step.solutions.end(), [&](const engine::solution& x) {
        return x.outcome == engine::solution::fate::condition;
    });
    BOOST_TEST_REQUIRE((lobbed != step.solutions.end()));
    BOOST_TEST(at(value_in(*lobbed, T), point) == lob, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(every_step_check_proven(step));
    BOOST_TEST(d.all_hold());
}

BOOST_AUTO_TEST_CASE(a_split_on_a_coefficient_keeps_the_solutions_where_it_vanishes)
{
    // x y = 0 and x^2 + y^2 = 1: x = 0 where y is not 0 (y = ±1), and y = 0 (x = ±1):
    // four solutions, two of them non-negative, one from each branch.
    const std::string text =
        "id = \"t\"\ntitle = \"test\"\n[[symbol]]\nname = \"x\"\ndomain = \"nonnegative\"\n"
        "[[symbol]]\nname = \"y\"\ndomain = \"nonnegative\"\n"
        "[[given]]\nname = \"a\"\nequation = \"x*y = 0\"\nbecause = \"given\"\n"
        "[[given]]\nname = \"b\"\nequation = \"x^2 + y^2 = 1\"\nbecause = \"given\"\n"
        "[[step]]\nsolve = [\"a\", \"b\"]\nfor = [\"x\", \"y\"]\n";
    const std::string message = error_for(text + "[[result]]\nname = \"x\"\n").message();
    BOOST_TEST(message.find("2 solutions are admissible: ") == 0u, message);
    BOOST_TEST(message.find("x = 0, y = 1") != std::string::npos, message);
    BOOST_TEST(message.find("x = 1, y = 0") != std::string::npos, message);
    // Rejecting y = 0 leaves x = 0, y = 1; the negative ones are outside the domains.
    const engine::derivation d =
        derive_text(text + "reject = [\"y = 0\"]\nreject_because = \"y is the one that moves\"\n"
                           "[[result]]\nname = \"x\"\n[[result]]\nname = \"y\"\n");
    BOOST_TEST(value_of(d, "x").is_zero());
    BOOST_TEST(value_of(d, "y").is_equal(1));
    BOOST_TEST(d.steps.front().solutions.size() == 4u);
    BOOST_TEST(every_step_check_proven(d.steps.front()));
}

BOOST_AUTO_TEST_CASE(a_cubic_is_solved_through_its_factors)
{
    // y^3 = x^2 y: y (y - x) (y + x) = 0; a positive y keeps x.
    const engine::derivation d = derive_text(
        "id = \"t\"\ntitle = \"test\"\n[[symbol]]\nname = \"x\"\ndomain = \"positive\"\n"
        "[[symbol]]\nname = \"y\"\ndomain = \"positive\"\n"
        "[[given]]\nname = \"g\"\nequation = \"y^3 = x^2*y\"\nbecause = \"given\"\n"
        "[[step]]\nsolve = [\"g\"]\nfor = [\"y\"]\n[[result]]\nname = \"y\"\n");
    const GiNaC::ex x = sym(d, "x"), y = sym(d, "y");
    BOOST_TEST(equal(value_of(d, "y"), x));
    const engine::step_result& step = d.steps.front();
    BOOST_TEST_REQUIRE(step.solutions.size() == 3u);
    const GiNaC::exmap point{{x, 2}};
    BOOST_TEST(has_solution(step, y, 0, point));
    BOOST_TEST(has_solution(step, y, -x, point));
    BOOST_TEST(every_step_check_proven(step));
    // Of a real y, all three are admissible: refused, each listed.
    BOOST_TEST(error_for(with_x_and_y("[[given]]\nname = \"g\"\nequation = \"y^3 = x^2*y\"\nbecause = \"given\"\n"
                                      "[[step]]\nsolve = [\"g\"]\nfor = [\"y\"]\n[[result]]\nname = \"y\"\n"))
                   .message()
                   .find("3 solutions are admissible: ") == 0u);
}

BOOST_AUTO_TEST_CASE(a_quartic_in_y_squared_is_solved_as_a_quadratic)
{
    // y^4 - x^2 y^2 - x = 0: y^2 = (x^2 ± sqrt(x^4 + 4x))/2, the minus root negative, so
    // y = ±sqrt((x^2 + sqrt(x^4 + 4x))/2), the positive one kept.
    const engine::derivation d = derive_text(
        "id = \"t\"\ntitle = \"test\"\n[[symbol]]\nname = \"x\"\ndomain = \"positive\"\n"
        "[[symbol]]\nname = \"y\"\ndomain = \"positive\"\n"
        "[[given]]\nname = \"g\"\nequation = \"y^4 = x^2*y^2 + x\"\nbecause = \"given\"\n"
        "[[step]]\nsolve = [\"g\"]\nfor = [\"y\"]\n[[result]]\nname = \"y\"\n");
    const GiNaC::ex x = sym(d, "x");
    const GiNaC::exmap point{{x, 2}};
    // At x = 2: y^2 = (4 + sqrt(24))/2 = 2 + sqrt(6).
    BOOST_TEST(at(value_of(d, "y"), point) == std::sqrt(2 + std::sqrt(6.0)), boost::test_tools::tolerance(1e-12));
    BOOST_TEST(d.steps.front().solutions.size() == 2u);
    BOOST_TEST(every_step_check_proven(d.steps.front()));
}

BOOST_AUTO_TEST_CASE(a_value_with_a_square_root_is_written_one_way)
{
    // A sphere's velocity after it hits a rough wall in the plane, its normal (a, b) of any
    // length: u = (a, b)/|(a, b)| holds a square root. The value is written one way whatever
    // order GiNaC gives the terms in this build (normal() alone leaves some products of
    // a^2 + b^2 multiplied out and others not, and which follows that order): the numerator
    // multiplied out, the square root to its first power, over a^2 + b^2.
    const engine::derivation d = derive_text(
        "id = \"t\"\ntitle = \"test\"\n"
        "[[symbol]]\nname = \"a\"\n[[symbol]]\nname = \"b\"\n"
        "[[symbol]]\nname = \"v_a\"\n[[symbol]]\nname = \"v_b\"\n"
        "[[symbol]]\nname = \"w\"\n[[symbol]]\nname = \"R\"\ndomain = \"positive\"\n"
        "[[symbol]]\nname = \"eps\"\ndomain = \"nonnegative\"\n[[symbol]]\nname = \"c\"\n"
        "[[symbol]]\nname = \"n_norm\"\ndefinition = \"sqrt(a^2 + b^2)\"\n"
        "[[symbol]]\nname = \"g_n\"\ndefinition = \"-(v_a*a + v_b*b)/n_norm\"\n"
        "[[symbol]]\nname = \"g_t\"\ndefinition = \"-v_a - g_n*a/n_norm - R*w*b/n_norm\"\n"
        "[[symbol]]\nname = \"v_a_after\"\n"
        "[[step]]\ndefine = \"v_a_after\"\nas = \"v_a + (1 + eps)*g_n*a/n_norm + c*g_t\"\nbecause = \"the impulse\"\n"
        "[[result]]\nname = \"v_a_after\"\n");
    const GiNaC::ex a = sym(d, "a"), b = sym(d, "b"), v_a = sym(d, "v_a"), v_b = sym(d, "v_b");
    const GiNaC::ex w = sym(d, "w"), R = sym(d, "R"), eps = sym(d, "eps"), c = sym(d, "c");
    // (v_a (a^2 + b^2) - (1 + eps)(v_a a + v_b b) a + c (-v_a b^2 + v_b a b - R w b sqrt(a^2 + b^2)))/(a^2 + b^2),
    // multiplied out (v_a a^2 cancels).
    const GiNaC::ex numerator = v_a * pow(b, 2) - eps * v_a * pow(a, 2) - v_b * a * b - eps * v_b * a * b -
                                c * v_a * pow(b, 2) + c * v_b * a * b - c * R * w * b * GiNaC::sqrt(pow(a, 2) + pow(b, 2));
    const GiNaC::ex value = value_of(d, "v_a_after");
    BOOST_TEST(equal(value, numerator / (pow(a, 2) + pow(b, 2))));
    BOOST_TEST(value.is_equal(numerator / (pow(a, 2) + pow(b, 2))), value);
}

BOOST_AUTO_TEST_CASE(a_value_with_a_square_root_is_written_the_same_in_any_order_of_terms)
{
    // GiNaC orders terms by hash values, which follow the order symbols are made in: the same
    // derivation with its symbols declared in another order, among others, must derive the
    // same value, written the same way. normal() alone builds the common denominator of
    // sqrt(y)/(x^2 - 1) + 1/(x + 1) + 1/(x - 1) as (x - 1)(x + 1) or x^2 - 1 by that order,
    // and puts the root in a symbol of its own; the engine's root is one symbol, and a short
    // denominator is written factored.
    const std::string steps = "[[symbol]]\nname = \"z\"\n"
                              "[[step]]\ndefine = \"z\"\nas = \"sqrt(y)/(x^2 - 1) + 1/(x + 1) + 1/(x - 1)\"\n"
                              "because = \"a sum of fractions\"\n[[result]]\nname = \"z\"\n";
    const engine::derivation first = derive_text("id = \"t\"\ntitle = \"test\"\n[[symbol]]\nname = \"x\"\n"
                                                 "[[symbol]]\nname = \"y\"\ndomain = \"positive\"\n" + steps);
    std::string others = "id = \"t\"\ntitle = \"test\"\n";
    for (int i = 0; i < 7; ++i)
        others += fmt::format("[[symbol]]\nname = \"a{}\"\n", i);
    const engine::derivation second =
        derive_text(others + "[[symbol]]\nname = \"y\"\ndomain = \"positive\"\n[[symbol]]\nname = \"x\"\n" + steps);
    const GiNaC::ex x = sym(first, "x"), y = sym(first, "y");
    const GiNaC::ex z = value_of(first, "z");
    const GiNaC::ex z_again = value_of(second, "z").subs(GiNaC::lst{sym(second, "x"), sym(second, "y")}, GiNaC::lst{x, y});
    // (sqrt(y) + 2 x)/(x^2 - 1).
    BOOST_TEST(equal(z, (GiNaC::sqrt(y) + 2 * x) / (pow(x, 2) - 1)));
    BOOST_TEST(z.is_equal(z_again), z << " and " << z_again);
}

BOOST_AUTO_TEST_CASE(a_linear_system_is_solved_as_before)
{
    const engine::derivation d = derive_text(with_x_and_y(
        "[[given]]\nname = \"g\"\nequation = \"2*y = x\"\nbecause = \"given\"\n"
        "[[step]]\nsolve = [\"g\"]\nfor = [\"y\"]\n[[result]]\nname = \"y\"\n"));
    BOOST_TEST(equal(value_of(d, "y"), sym(d, "x") / 2));
    BOOST_TEST(d.steps.front().solutions.empty());
    BOOST_TEST(d.steps.front().checks.front().name == "g holds for the solution");
}

BOOST_AUTO_TEST_CASE(quadratic_with_a_double_root_has_one_solution)
{
    const engine::derivation d = derive_text(with_x_and_y(
        "[[given]]\nname = \"g\"\nequation = \"y^2 - 2*x*y + x^2 = 0\"\nbecause = \"given\"\n"
        "[[step]]\nsolve = [\"g\"]\nfor = [\"y\"]\n[[result]]\nname = \"y\"\n"));
    BOOST_TEST(equal(value_of(d, "y"), sym(d, "x")));
    BOOST_TEST(d.steps.front().solutions.size() == 1u);
}

BOOST_AUTO_TEST_CASE(unsolvable_systems_are_refused_with_their_reason)
{
    auto solving = [](const std::string& equation, const std::string& extra = "") {
        return with_x_and_y("[[given]]\nname = \"g\"\nequation = \"" + equation +
                            "\"\nbecause = \"given\"\n[[step]]\nsolve = [\"g\"]\nfor = [\"y\"]\n" + extra +
                            "[[result]]\nname = \"y\"\n");
    };
    BOOST_TEST(error_for(solving("y^3 = x")).message() ==
               "the system is not linear in y: -x+y^3 = 0 is of degree 3 in y and has no factor over the rationals: beyond the quadratic "
               "formula (a polynomial in one unknown is solved when its factors over the rationals are of degree "
               "2 or less, or quadratic in y^2)");
    BOOST_TEST(error_for(solving("(y - x)*(y^3 - x) = 0")).message() ==
               "the system is not linear in y: x^2-x*y-x*y^3+y^4 = 0 is of degree 4 in y, and its factor -x+y^3 is of degree 3: beyond "
               "the quadratic formula (a polynomial in one unknown is solved when its factors over the rationals "
               "are of degree 2 or less, or quadratic in y^2)");
    BOOST_TEST(error_for(solving("y^2 = -x")).message() ==
               "the system has no real solution: x+y^2 = 0 has no real root (b^2 - 4 a c = -4*x < 0)");
    BOOST_TEST(error_for(solving("y^2 = x", "reject = [\"y = x\"]\nreject_because = \"why\"\n")).message() ==
               "the condition y = x holds for none of the solutions: y = sqrt(x); y = -sqrt(x)");
    const impact::error both =
        error_for(solving("y^2 = x", "reject = [\"y = sqrt(x)\", \"y = -sqrt(x)\"]\nreject_because = \"why\"\n"));
    BOOST_TEST(both.message() == "every solution is rejected: y = sqrt(x) (y = sqrt(x): why); "
                                 "y = -sqrt(x) (y = -sqrt(x): why)");
    // A reason is required for what is rejected.
    try {
        spec::parse_derivation(solving("y^2 = x", "reject = [\"y = -sqrt(x)\"]\n"), "test.toml");
        BOOST_FAIL("reject without reject_because was accepted");
    } catch (const impact::error& e) {
        BOOST_TEST(e.message() == "'reject' needs 'reject_because': why the solutions it rejects are not wanted");
    }
}

BOOST_AUTO_TEST_CASE(a_condition_keeps_the_root_a_domain_cannot)
{
    const engine::derivation d = derive_text(with_x_and_y(
        "[[given]]\nname = \"g\"\nequation = \"y^2 = x\"\nbecause = \"given\"\n"
        "[[step]]\nsolve = [\"g\"]\nfor = [\"y\"]\nreject = [\"y = -sqrt(x)\"]\n"
        "reject_because = \"y points the other way\"\n[[result]]\nname = \"y\"\n"));
    BOOST_TEST(equal(value_of(d, "y"), GiNaC::sqrt(sym(d, "x"))));
}

BOOST_AUTO_TEST_CASE(the_solutions_are_printed_with_why_each_is_rejected)
{
    const engine::derivation d = derive_file("tests/solve/projectile_flight.toml");
    const std::string terminal = emit::terminal_text(d);
    BOOST_TEST(terminal.find("       kept: T = 2*w/g (T > 0: 2*w/g > 0)\n"
                             "       rejected: T = 0 (T > 0, but T = 0)\n") != std::string::npos,
               terminal);
    const std::string latex = emit::latex_fragment(d);
    BOOST_TEST(latex.find("The equations have 2 solutions; rejected: $T = 0$ ($T > 0$).\n"
                          "Substituted back, each solution satisfies") != std::string::npos,
               latex);
    const std::string json = emit::derivations_json({&d});
    BOOST_TEST(json.find("\"values\": {\n            \"T\": \"0\"\n          },\n"
                         "          \"status\": \"outside its domain\",\n"
                         "          \"domain\": \"T in positive\",\n"
                         "          \"why\": \"T > 0, but T = 0\"") != std::string::npos,
               json);

    const engine::derivation e = derive_file("tests/solve/elastic_from_conservation.toml");
    // v_M and v_m have no `latex` in the file: typeset from their names, v_{M} and v_{m}.
    BOOST_TEST(emit::latex_fragment(e).find("rejected: $v'_M = v_{M},\\ v'_m = v_{m}$ ($v'_M = v_{M}$: the spheres "
                                            "would pass through each other unchanged).") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(two_admissible_roots_are_refused_through_impact_and_output_is_untouched)
{
    const fs::path root = fs::temp_directory_path() / ("impact-solve-" + std::to_string(::getpid()));
    fs::remove_all(root);
    fs::create_directories(root / "derivations");
    impact::testing::previous_output(root / "output");
    std::ofstream(root / "derivations" / "two_roots.toml")
        << with_x_and_y("[[given]]\nname = \"g\"\nequation = \"y^2 = x\"\nbecause = \"given\"\n"
                        "[[step]]\nsolve = [\"g\"]\nfor = [\"y\"]\n[[result]]\nname = \"y\"\n");
    const auto before = impact::testing::snapshot(root / "output");
    const auto r = impact::testing::run_command("cd '" + root.string() + "' && exec " IMPACT_BINARY
                                                " regenerate --derivations derivations --output output");
    BOOST_TEST(r.status == 2, r.output);
    BOOST_TEST(impact::testing::lines_of(r.output) ==
                   std::vector<std::string>{
                       "derivations/two_roots.toml:12:1: error: 2 solutions are admissible: y = sqrt(x) and "
                       "y = -sqrt(x); choose one by declaring a domain for y (e.g. domain = \"positive\") or by "
                       "rejecting the others in the step (reject = [\"y = ...\"], reject_because = \"why\")"},
               boost::test_tools::per_element());
    BOOST_TEST((impact::testing::snapshot(root / "output") == before), "output/ changed");
    fs::remove_all(root);
}

BOOST_AUTO_TEST_SUITE_END()
