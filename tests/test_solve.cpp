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
#include <cstdio>

#include "derivation_support.h"
#include "support.h"

#include "emit/json.h"
#include "emit/latex.h"
#include "emit/terminal.h"
#include "engine/derive.h"

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
               "the system is not linear in y, and eliminating the unknowns it holds linearly leaves no "
               "equation of degree 2 or less in one unknown (-x+y^3 = 0 is of degree 3 in y)");
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
    BOOST_TEST(emit::latex_fragment(e).find("rejected: $v'_M = v_M,\\ v'_m = v_m$ ($v'_M = v_M$: the spheres "
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
