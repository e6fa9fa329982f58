// π in the derivation language (domains whose ends are multiples of it, held exactly),
// `solve` through Pi, and trigonometric equations solved on the unknown's domain: every
// root that can meet the domain listed, kept or rejected by the interval its value lies in.
//
// The derivation files (tests/trig_solve/) are written for these tests, not the paper's;
// the expected roots are closed forms typed here.
#define BOOST_TEST_MODULE test_trig_solve
#include <boost/test/unit_test.hpp>

#include "derivation_support.h"

#include "engine/derivation/derivation.h"
#include "engine/expr/domain.h"

#include <cln/rational.h>
#include <cln/real.h>

#include <string>

namespace {

using namespace impact;
using namespace impact::testing;

// The rational a double is.
GiNaC::ex exactly(double x)
{
    return GiNaC::numeric(cln::cl_N(cln::rational(cln::cl_DF(x))));
}

const engine::step_result& only_step(const engine::derivation& d)
{
    BOOST_REQUIRE_EQUAL(d.steps.size(), 1u);
    return d.steps.front();
}

bool every_check_proven(const engine::step_result& s)
{
    return !s.checks.empty() && std::all_of(s.checks.begin(), s.checks.end(), [](const engine::check_result& c) {
        return c.outcome.what == engine::verdict::status::proven;
    });
}

// The solution with value `expected` for `unknown`, or none.
const engine::solution* solution_of(const engine::step_result& s, const GiNaC::ex& unknown, const GiNaC::ex& expected)
{
    for (const engine::solution& candidate : s.solutions)
        for (const auto& [u, v] : candidate.values)
            if (u.is_equal(unknown) && equal(v, expected))
                return &candidate;
    return nullptr;
}

// A derivation of t, with symbols A and y positive, t in `domain`, solved from `equation`.
std::string one_unknown(const std::string& domain, const std::string& equation)
{
    return "id = \"t\"\ntitle = \"t\"\n[[symbol]]\nname = \"A\"\ndomain = \"positive\"\n[[symbol]]\nname = \"y\"\n"
           "domain = \"positive\"\n[[symbol]]\nname = \"t\"\ndomain = \"" + domain + "\"\n[[given]]\nname = \"e\"\n"
           "equation = \"" + equation + "\"\nbecause = \"b\"\n[[step]]\nsolve = [\"e\"]\nfor = [\"t\"]\n"
           "because = \"b\"\n[[result]]\nname = \"t\"\n";
}

} // namespace

BOOST_AUTO_TEST_SUITE(test_trig_solve)

BOOST_AUTO_TEST_CASE(a_domain_of_pi_keeps_its_ends_exactly_and_its_samples_inside)
{
    const engine::domain quarter = engine::parse_domain("(0, Pi/2)", {});
    BOOST_TEST(equal(quarter.exact_lower(), 0));
    BOOST_TEST(equal(quarter.exact_upper(), GiNaC::Pi / 2));
    // The double below π/2 (none is π/2), so that no sample reaches the open end.
    BOOST_TEST(engine::sign_of_constant(GiNaC::Pi / 2 - exactly(quarter.upper)) > 0);
    BOOST_TEST(quarter.to_string() == "(0, Pi/2)");
    BOOST_TEST(quarter.to_latex() == "\\in (0, \\pi/2)");

    const engine::domain wide = engine::parse_domain("[-3*Pi/4, Pi]", {});
    BOOST_TEST(equal(wide.exact_lower(), -3 * GiNaC::Pi / 4));
    BOOST_TEST(engine::sign_of_constant(exactly(wide.lower) + 3 * GiNaC::Pi / 4) >= 0);
    BOOST_TEST(engine::sign_of_constant(GiNaC::Pi - exactly(wide.upper)) >= 0);
    BOOST_TEST(wide.to_latex() == "\\in [-3\\pi/4, \\pi]");
    engine::uniform_stream stream(7);
    for (int i = 0; i < 2000; ++i) {
        const double x = engine::draw(wide, stream);
        BOOST_REQUIRE(wide.contains(exactly(x)));
    }
    // Exact membership at the ends: Pi is in [.., Pi], Pi/2 is not in (0, Pi/2).
    BOOST_TEST(wide.contains(GiNaC::ex(GiNaC::Pi)));
    BOOST_TEST(!quarter.contains(GiNaC::Pi / 2));
    BOOST_TEST(quarter.closure_contains(GiNaC::Pi / 2));
    BOOST_TEST(engine::parse_domain("(-Pi/2, Pi/2)", {}).within(engine::parse_domain("[-Pi, 0.5*Pi]", {})));
    BOOST_TEST(!engine::parse_domain("(0, Pi)", {}).within(engine::parse_domain("(0, 3)", {})));

    for (const char* empty : {"(Pi, 3)", "(Pi/2, Pi/2)"}) {
        try {
            engine::parse_domain(empty, {"f.toml", 4, 10});
            BOOST_FAIL(std::string("no error for ") + empty);
        } catch (const impact::error& e) {
            BOOST_TEST(std::string(e.what()) == std::string("f.toml:4:10: error: domain '") + empty +
                                                     "' is an empty interval");
        }
    }
    BOOST_CHECK_THROW(engine::parse_domain("(0, Pi^2)", {}), impact::error);
}

BOOST_AUTO_TEST_CASE(bounds_of_pi_are_proven_with_pi_not_with_a_double)
{
    // phi in (0, Pi/2): 2 phi < Pi < 3.15 holds, 2 phi <= 3.14 does not (Pi > 3.14), phi^2 <
    // 2.47 holds (Pi^2/4 = 2.4674...), phi^2 <= 2.467 does not: neither is proven (sampling
    // may miss the sliver where they fail).
    const std::string text = "id = \"t\"\ntitle = \"t\"\n[[symbol]]\nname = \"phi\"\ndomain = \"(0, Pi/2)\"\n"
                             "[[symbol]]\nname = \"q\"\n[[step]]\ndefine = \"q\"\nas = \"2*phi\"\n"
                             "because = \"b\"\n[[result]]\nname = \"q\"\n"
                             "[[check]]\nname = \"below_pi\"\nclaim = \"2*phi < 3.15\"\n"
                             "[[check]]\nname = \"below_314\"\nclaim = \"2*phi <= 3.14\"\n"
                             "[[check]]\nname = \"square_below\"\nclaim = \"phi^2 < 2.47\"\n"
                             "[[check]]\nname = \"square_not_below\"\nclaim = \"phi^2 <= 2.467\"\n"
                             "[[check]]\nname = \"at_a_quarter\"\nclaim = \"2*phi = Pi/2\"\nat = { phi = \"Pi/4\" }\n"
                             "[[check]]\nname = \"towards_the_end\"\nclaim = \"4*phi = 2*Pi\"\nlimit = \"phi -> Pi/2\"\n";
    const engine::derivation d = derive_text(text);
    using status = engine::verdict::status;
    BOOST_TEST((check_named(d, "below_pi").outcome.what == status::proven));
    BOOST_TEST((check_named(d, "below_314").outcome.what != status::proven));
    BOOST_TEST((check_named(d, "square_below").outcome.what == status::proven));
    BOOST_TEST((check_named(d, "square_not_below").outcome.what != status::proven));
    BOOST_TEST((check_named(d, "at_a_quarter").outcome.what == status::proven));
    BOOST_TEST((check_named(d, "towards_the_end").outcome.what == status::proven));
    // A special value beyond Pi/2 is outside the domain.
    const impact::error outside = error_for(text + "[[check]]\nname = \"beyond\"\nclaim = \"phi = phi\"\n"
                                                   "at = { phi = \"2*Pi/3\" }\n");
    BOOST_TEST(std::string(outside.what()).find("is outside the domain of phi ((0, Pi/2))") != std::string::npos,
               outside.what());
}

BOOST_AUTO_TEST_CASE(an_angle_of_reflection_is_solved_through_pi)
{
    // theta = Pi - 2 alpha, for alpha: GiNaC's gcd refused Pi ("arguments must be
    // polynomials over the rationals").
    const engine::derivation d = derive_text(
        "id = \"t\"\ntitle = \"t\"\n[[symbol]]\nname = \"theta\"\ndomain = \"(0, Pi)\"\n[[symbol]]\nname = "
        "\"alpha\"\ndomain = \"(0, Pi/2)\"\n[[given]]\nname = \"reflection\"\nequation = \"theta = Pi - 2*alpha\"\n"
        "because = \"b\"\n[[step]]\nsolve = [\"reflection\"]\nfor = [\"alpha\"]\nbecause = \"b\"\n[[result]]\n"
        "name = \"alpha\"\n");
    BOOST_TEST(equal(value_of(d, "alpha"), GiNaC::Pi / 2 - sym(d, "theta") / 2));
    BOOST_TEST(every_check_proven(only_step(d)));
}

BOOST_AUTO_TEST_CASE(a_sine_on_a_bounded_domain_keeps_the_flat_throw_and_rejects_the_lob)
{
    const engine::derivation d = derive_file("tests/trig_solve/aimed_throw_angle.toml");
    const GiNaC::ex phi = sym(d, "phi"), w = sym(d, "D") * sym(d, "g") / GiNaC::pow(sym(d, "s"), 2);
    BOOST_TEST(equal(value_of(d, "phi"), GiNaC::asin(w) / 2));
    const engine::step_result& s = only_step(d);
    BOOST_REQUIRE_EQUAL(s.solutions.size(), 2u);
    const engine::solution* lob = solution_of(s, phi, GiNaC::Pi / 2 - GiNaC::asin(w) / 2);
    BOOST_REQUIRE(lob);
    BOOST_TEST((lob->outcome == engine::solution::fate::outside_domain));
    BOOST_TEST(lob->why.find("phi lies in [Pi/4, Pi/2), outside (0, Pi/4)") == 0, lob->why);
    // Each root substituted back is proven, the lob's sin(Pi - asin w) = w among them.
    BOOST_TEST(every_check_proven(s));
    // Where the root exists, g D/s^2 <= 1, is not proven: the value's condition.
    BOOST_TEST(!s.attached.empty());
}

BOOST_AUTO_TEST_CASE(a_double_root_of_a_sine_is_found_once)
{
    const engine::derivation d = derive_file("tests/trig_solve/widest_throw.toml");
    BOOST_TEST(equal(value_of(d, "phi"), GiNaC::Pi / 4));
    BOOST_TEST(only_step(d).solutions.size() == 1u);
    BOOST_TEST(every_check_proven(only_step(d)));
}

BOOST_AUTO_TEST_CASE(snells_law_gives_the_angle_of_refraction)
{
    const engine::derivation d = derive_file("tests/trig_solve/refraction.toml");
    const GiNaC::ex w = sym(d, "n_1") * GiNaC::sin(sym(d, "theta_1")) / sym(d, "n_2");
    BOOST_TEST(equal(value_of(d, "theta_2"), GiNaC::asin(w)));
    const engine::step_result& s = only_step(d);
    BOOST_REQUIRE_EQUAL(s.solutions.size(), 2u);
    const engine::solution* beyond = solution_of(s, sym(d, "theta_2"), GiNaC::Pi - GiNaC::asin(w));
    BOOST_REQUIRE(beyond);
    BOOST_TEST(!beyond->kept());
    BOOST_TEST(every_check_proven(s));
    BOOST_TEST((check_named(d, "normal_incidence_goes_straight_on").outcome.what == engine::verdict::status::proven));
}

BOOST_AUTO_TEST_CASE(a_cosine_on_a_bounded_domain_keeps_one_of_three_roots)
{
    const engine::derivation d = derive_file("tests/trig_solve/pendulum_angle.toml");
    const GiNaC::ex w = 1 - sym(d, "h") / sym(d, "L"), theta = sym(d, "theta");
    BOOST_TEST(equal(value_of(d, "theta"), GiNaC::acos(w)));
    const engine::step_result& s = only_step(d);
    BOOST_REQUIRE_EQUAL(s.solutions.size(), 3u);
    for (const GiNaC::ex& other : {GiNaC::ex(-GiNaC::acos(w)), 2 * GiNaC::Pi - GiNaC::acos(w)}) {
        const engine::solution* rejected = solution_of(s, theta, other);
        BOOST_REQUIRE(rejected);
        BOOST_TEST((rejected->outcome == engine::solution::fate::outside_domain));
    }
    BOOST_TEST(every_check_proven(s));
}

BOOST_AUTO_TEST_CASE(a_tangent_on_a_bounded_domain_gives_the_angle_of_repose)
{
    const engine::derivation d = derive_file("tests/trig_solve/friction_angle.toml");
    BOOST_TEST(equal(value_of(d, "alpha"), GiNaC::atan(sym(d, "mu"))));
    BOOST_TEST(only_step(d).solutions.size() == 1u);
    BOOST_TEST(every_check_proven(only_step(d)));
    // tan(3 t + Pi/4) = y on (-Pi/2, Pi/2): three roots, all in the domain, all listed.
    const impact::error three = error_for(one_unknown("(-Pi/2, Pi/2)", "tan(3*t + Pi/4) = y"));
    BOOST_TEST(std::string(three.what()).find("3 solutions are admissible") != std::string::npos, three.what());
    // sin t = 1/2 on [0, 2 Pi]: Pi/6 and 5 Pi/6.
    const impact::error two = error_for(one_unknown("[0, 2*Pi]", "sin(t) = 1/2"));
    BOOST_TEST(std::string(two.what()).find("t = Pi/6 and t = 5*Pi/6") != std::string::npos, two.what());
}

BOOST_AUTO_TEST_CASE(a_trigonometric_equation_on_an_unbounded_domain_has_infinitely_many_roots)
{
    for (const auto& [domain, equation, function] :
         {std::tuple<const char*, const char*, const char*>{"positive", "y = A*sin(2*t)", "sin(2*t) = y/A"},
          {"real", "y = A*cos(t)", "cos(t) = y/A"},
          {"nonnegative", "tan(t) = y", "tan(t) = y"}}) {
        const impact::error e = error_for(one_unknown(domain, equation));
        BOOST_TEST(std::string(e.what()) ==
                       std::string("test.toml:16:1: error: ") + function +
                           " has infinitely many roots in the domain of t (" + domain +
                           "), one in each period " + (std::string(function).rfind("tan", 0) == 0 ? "Pi" : "2*Pi") +
                           " of its argument; declare a bounded domain for t (e.g. domain = \"(0, Pi/2)\") to "
                           "solve it there",
                   e.what());
    }
    // Unless it has none: sin t = 2.
    const impact::error none = error_for(one_unknown("positive", "sin(t) = 2"));
    BOOST_TEST(std::string(none.what()).find("sin(t) = 2 has no real root: 2 > 1") != std::string::npos, none.what());
}

BOOST_AUTO_TEST_CASE(a_reject_the_domain_makes_redundant_says_so)
{
    // T > 0 rejects T = 0 already: the message said "holds for none of the solutions: T =
    // 2*s*sin(phi)/g; T = 0", which lists T = 0.
    const std::string text =
        "id = \"t\"\ntitle = \"t\"\n[[symbol]]\nname = \"g\"\ndomain = \"positive\"\n[[symbol]]\nname = \"s\"\n"
        "domain = \"positive\"\n[[symbol]]\nname = \"phi\"\ndomain = \"(0, Pi/2)\"\n[[symbol]]\nname = \"T\"\n"
        "domain = \"positive\"\n[[given]]\nname = \"landing\"\nequation = \"s*sin(phi)*T - g*T^2/2 = 0\"\n"
        "because = \"b\"\n[[step]]\nsolve = [\"landing\"]\nfor = [\"T\"]\nreject = [\"T = 0\"]\n"
        "reject_because = \"the launch\"\nbecause = \"b\"\n[[result]]\nname = \"T\"\n";
    const impact::error e = error_for(text);
    BOOST_TEST(std::string(e.what()) == "test.toml:22:11: error: the condition T = 0 is redundant: it holds only "
                                        "for T = 0, which the domain of T (positive) already rejects (T > 0, but "
                                        "T = 0); remove it from reject",
               e.what());
}

BOOST_AUTO_TEST_SUITE_END()
