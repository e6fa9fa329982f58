// Inequalities that random points cannot refute (engine/prove/real_roots.cpp): false only
// on an interval too thin for 200 points, or at a single point, they were "sampled"; now
// they fail at a point their real roots pick out. The claims are written for these tests;
// where each fails is worked out by hand from its factors, typed in here, and the
// counterexample the engine gives is checked against it.
#include <boost/test/unit_test.hpp>

#include "derivation_support.h"
#include "engine/prove/prove.h"

#include <cmath>
#include <string>

namespace {

using namespace impact;
using namespace impact::testing;

// u real, w real, h > 0, t in [0, 1], c in [-1, 1], e in (-1, 1); `body` appended.
std::string over(const std::string& body)
{
    return "id = \"roots\"\ntitle = \"test\"\n"
           "[[symbol]]\nname = \"u\"\n"
           "[[symbol]]\nname = \"w\"\n"
           "[[symbol]]\nname = \"h\"\ndomain = \"positive\"\n"
           "[[symbol]]\nname = \"t\"\ndomain = \"[0, 1]\"\n"
           "[[symbol]]\nname = \"c\"\ndomain = \"[-1, 1]\"\n"
           "[[symbol]]\nname = \"e\"\ndomain = \"(-1, 1)\"\n"
           "[[symbol]]\nname = \"R\"\n"
           "[[step]]\ndefine = \"R\"\nas = \"u + w\"\nbecause = \"a sum\"\n"
           "[[result]]\nname = \"R\"\n" +
           body;
}

// The value the check's counterexample gives a symbol, as a double (NaN without one).
double value_at(const engine::derivation& d, const std::string& name, const std::string& symbol)
{
    const engine::check_result& c = check_named(d, name);
    if (!c.fails_at)
        return std::nan("");
    for (const auto& [s, value] : c.fails_at->point)
        if (GiNaC::ex_to<GiNaC::symbol>(s).get_name() == symbol)
            return GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(value)).to_double();
    return std::nan("");
}

} // namespace

BOOST_AUTO_TEST_SUITE(real_roots)

// (t - 0.3141)(t - 0.3142) is negative only between its roots, an interval of width 1e-4.
BOOST_AUTO_TEST_CASE(a_claim_false_on_a_thin_interval_is_refuted_inside_it)
{
    const engine::derivation d = derive_text(over(check("thin", "(t - 3141/10000)*(t - 3142/10000) >= 0")));
    BOOST_TEST(engine::to_string(check_named(d, "thin").outcome) == "failed");
    const double t = value_at(d, "thin", "t");
    BOOST_TEST(t > 0.3141);
    BOOST_TEST(t < 0.3142);
    BOOST_TEST(check_named(d, "thin").fails_at->exact);
}

// 100000 t^2 - 62830 t + 9869: discriminant 8900, not a square; negative between
// (62830 -+ sqrt(8900))/200000, that is 0.3136783... to 0.3146217...
BOOST_AUTO_TEST_CASE(between_irrational_roots_the_point_is_a_rational_inside)
{
    const engine::derivation d = derive_text(over(check("thin", "100000*t^2 - 62830*t + 9869 >= 0")));
    BOOST_TEST(engine::to_string(check_named(d, "thin").outcome) == "failed");
    const double t = value_at(d, "thin", "t");
    BOOST_TEST(t > (62830 - std::sqrt(8900.0)) / 200000);
    BOOST_TEST(t < (62830 + std::sqrt(8900.0)) / 200000);
}

// (w - 2h)^2 + 5 > 5 fails where w = 2h, a line of the plane that random points miss.
BOOST_AUTO_TEST_CASE(a_strict_claim_false_on_a_line_is_refuted_on_it)
{
    const engine::derivation d = derive_text(over(check("line", "(w - 2*h)^2 + 5 > 5")));
    BOOST_TEST(engine::to_string(check_named(d, "line").outcome) == "failed");
    const double w = value_at(d, "line", "w"), h = value_at(d, "line", "h");
    BOOST_TEST(h > 0);
    BOOST_TEST(w == 2 * h, check_named(d, "line").outcome.method);
}

// (u^2 - 2)^2 > 0 fails at u = -sqrt(2) and sqrt(2) alone, where no rational lies: the
// counterexample is the root itself, and both sides are 0 there, exactly.
BOOST_AUTO_TEST_CASE(a_strict_claim_false_at_an_irrational_point_fails_at_the_root)
{
    const engine::derivation d = derive_text(over(check("at_root", "(u^2 - 2)^2 > 0")));
    const engine::check_result& c = check_named(d, "at_root");
    BOOST_TEST(engine::to_string(c.outcome) == "failed");
    BOOST_TEST(std::abs(std::abs(value_at(d, "at_root", "u")) - std::sqrt(2.0)) < 1e-15, c.outcome.method);
    BOOST_REQUIRE(c.fails_at);
    BOOST_TEST(c.fails_at->exact);
    BOOST_TEST(c.fails_at->lhs.is_zero());
}

// c^2 < 1 fails at the closed ends of [-1, 1] only; on (-1, 1) it holds.
BOOST_AUTO_TEST_CASE(a_closed_end_of_the_domain_is_a_point_to_try)
{
    const engine::derivation d = derive_text(over(check("closed", "c^2 < 1") + check("open", "e^2 < 1")));
    BOOST_TEST(engine::to_string(check_named(d, "closed").outcome) == "failed");
    BOOST_TEST(std::abs(value_at(d, "closed", "c")) == 1.0, check_named(d, "closed").outcome.method);
    BOOST_TEST(check_named(d, "open").outcome.holds(), check_named(d, "open").outcome.method);
}

// (u - 1)^3/(u - 1) > 0 is said where u != 1, and its normal form (u - 1)^2 vanishes only
// there: the point is not one the claim speaks of, so nothing refutes it.
BOOST_AUTO_TEST_CASE(a_point_outside_the_claims_conditions_refutes_nothing)
{
    const engine::derivation d = derive_text(over(check("where", "(u - 1)^3/(u - 1) > 0")));
    const engine::verdict& v = check_named(d, "where").outcome;
    BOOST_TEST(v.holds(), v.method);
    BOOST_TEST(engine::to_string(v).find("where u != 1") != std::string::npos, engine::to_string(v));
}

// True claims the roots cannot refute keep their verdicts: u^4 - u + 1 has no real root
// (its minimum, at u = 4^(-1/3), is 1 - (3/4) 4^(-1/3) > 0); (t - 1/3)^2 (t + 2) >= 0 on
// [0, 1] vanishes at 1/3 and is positive elsewhere; 2 - h^2 + h^4 > 0 everywhere.
BOOST_AUTO_TEST_CASE(true_claims_are_not_refuted)
{
    const engine::derivation d = derive_text(over(check("no_root", "u^4 - u + 1 > 0") +
                                                  check("double_root", "(t - 1/3)^2*(t + 2) >= 0") +
                                                  check("quartic", "2 - h^2 + h^4 > 0")));
    for (const char* name : {"no_root", "double_root", "quartic"})
        BOOST_TEST(check_named(d, name).outcome.holds(), name << ": " << check_named(d, name).outcome.method);
    BOOST_TEST(engine::to_string(check_named(d, "double_root").outcome) == "proven");
}

BOOST_AUTO_TEST_SUITE_END()
