// Identities of sin, cos, tan, their hyperbolic kin, exp and log decided, not sampled
// (engine/prove/transcendental.h), and the signs and bounds of these functions
// (engine/prove/angles.h, sign_of_functions.cpp). The identities are textbook ones this
// file states for itself (sin 3x, cos(a+b) cos(a-b), the tangent of a sum, the range of a
// throw); each expected verdict is typed in by hand, and each false claim is one of them
// perturbed, which must not be proven and which the sampler refutes.
#include <boost/test/unit_test.hpp>

#include "derivation_support.h"
#include "engine/prove/prove.h"
#include "engine/prove/sign.h"

#include <cmath>
#include <string>

namespace {

using namespace impact;
using namespace impact::testing;

// x, a, b, t real; phi in [0, 1]; theta in [0, 3]; p, q, E, m, c positive; u in [-1, 1].
std::string over(const std::string& body)
{
    return "id = \"trig\"\ntitle = \"test\"\n"
           "[[symbol]]\nname = \"x\"\n"
           "[[symbol]]\nname = \"a\"\n"
           "[[symbol]]\nname = \"b\"\n"
           "[[symbol]]\nname = \"t\"\n"
           "[[symbol]]\nname = \"phi\"\ndomain = \"[0, 1]\"\n"
           "[[symbol]]\nname = \"theta\"\ndomain = \"[0, 3]\"\n"
           "[[symbol]]\nname = \"p\"\ndomain = \"positive\"\n"
           "[[symbol]]\nname = \"q\"\ndomain = \"positive\"\n"
           "[[symbol]]\nname = \"u\"\ndomain = \"[-1, 1]\"\n"
           "[[symbol]]\nname = \"Y\"\n"
           "[[step]]\ndefine = \"Y\"\nas = \"2*x\"\nbecause = \"a result\"\n"
           "[[result]]\nname = \"Y\"\n" +
           body;
}

std::string status(const engine::derivation& d, const std::string& name)
{
    return engine::to_string(check_named(d, name).outcome);
}

std::string method(const engine::derivation& d, const std::string& name)
{
    return check_named(d, name).outcome.method;
}

bool says(const std::string& text, const std::string& part)
{
    return text.find(part) != std::string::npos;
}

// An interval domain whose ends are written with Pi (as a file writes `(0, Pi/2)`).
engine::domain angle_domain(const std::string& low, double low_value, const std::string& high, double high_value,
                            bool low_open, bool high_open)
{
    engine::domain d;
    d.what = engine::domain::kind::interval;
    d.lower = low_value;
    d.upper = high_value;
    d.lower_text = low;
    d.upper_text = high;
    d.lower_open = low_open;
    d.upper_open = high_open;
    return d;
}

engine::sign_set sign_of(const GiNaC::ex& e, const GiNaC::symbol& angle, const engine::domain& range)
{
    engine::assumptions given{{}, engine::term_order({angle}), std::make_shared<engine::worked_out>(), nullptr};
    given.domains[angle] = range;
    return engine::prove_sign(e, given).sign;
}

} // namespace

BOOST_AUTO_TEST_SUITE(trig)

BOOST_AUTO_TEST_CASE(multiple_and_compound_angles_are_proven_over_a_basis)
{
    const engine::derivation d = derive_text(over(check("triple", "sin(3*x) = 3*sin(x) - 4*sin(x)^3") +
                                                  check("product", "cos(a+b)*cos(a-b) = cos(a)^2 - sin(b)^2") +
                                                  check("double", "sin(2*phi) = 2*sin(phi)*cos(phi)") +
                                                  check("half", "sin(theta) = 2*sin(theta/2)*cos(theta/2)") +
                                                  check("shifted", "cos(x + Pi/3) = cos(x)/2 - sqrt(3)*sin(x)/2")));
    for (const char* name : {"triple", "product", "double", "half", "shifted"})
        BOOST_TEST(status(d, name) == "proven", name);
    BOOST_TEST(method(d, "triple") == "trigonometric identity, angles over the basis {x} reduced modulo "
                                      "sin^2 + cos^2 = 1: the difference is zero");
    BOOST_TEST(says(method(d, "product"), "angles over the basis {a, b} reduced modulo sin^2 + cos^2 = 1"));
    // theta and theta/2: the base angle is theta/2, theta twice it.
    BOOST_TEST(says(method(d, "half"), "angles over the basis {theta/2}"));
    BOOST_TEST((check_named(d, "triple").outcome.how == engine::verdict::basis::decided));
}

// tan(a+b) holds where every tangent is defined and 1 - tan(a) tan(b) != 0: proven there,
// and said so.
BOOST_AUTO_TEST_CASE(the_tangent_of_a_sum_is_proven_where_its_tangents_are_defined)
{
    const engine::derivation d =
        derive_text(over(check("sum", "tan(a+b) = (tan(a) + tan(b))/(1 - tan(a)*tan(b))")));
    BOOST_TEST(status(d, "sum") == "proven, where 1 != tan(a)*tan(b), cos(a) != 0, cos(a+b) != 0, cos(b) != 0");
}

// Each identity above perturbed: never proven, and refuted at a sampled point.
BOOST_AUTO_TEST_CASE(a_perturbed_identity_is_not_proven_and_the_sampler_refutes_it)
{
    const engine::derivation d = derive_text(over(check("triple", "sin(3*x) = 3*sin(x) - 3*sin(x)^3") +
                                                  check("product", "cos(a+b)*cos(a-b) = cos(a)^2 + sin(b)^2") +
                                                  check("sum", "tan(a+b) = (tan(a) + tan(b))/(1 + tan(a)*tan(b))") +
                                                  check("double", "sin(2*phi) = sin(phi)*cos(phi)") +
                                                  check("half", "sin(theta) = 2*sin(theta/2)*cos(theta)")));
    for (const char* name : {"triple", "product", "sum", "double", "half"})
        BOOST_TEST((check_named(d, name).outcome.what == engine::verdict::status::failed), name);
}

// The range of a throw at angle phi, R = s^2 sin(2 phi)/g, derived as 2 s^2 sin(phi) cos(phi)/g:
// its display form, and the same range at the complementary angle Pi/2 - phi.
BOOST_AUTO_TEST_CASE(the_range_of_a_throw_is_the_same_at_complementary_angles)
{
    const std::string text = "id = \"throw\"\ntitle = \"test\"\n"
                             "[[symbol]]\nname = \"s\"\ndomain = \"positive\"\n"
                             "[[symbol]]\nname = \"g\"\ndomain = \"positive\"\n"
                             "[[symbol]]\nname = \"phi\"\ndomain = \"[0, 1]\"\n"
                             "[[symbol]]\nname = \"R\"\n"
                             "[[step]]\ndefine = \"R\"\nas = \"2*s^2*sin(phi)*cos(phi)/g\"\nbecause = \"range\"\n"
                             "[[result]]\nname = \"R\"\ndisplay = \"s^2*sin(2*phi)/g\"\n"
                             "[[check]]\nname = \"complementary\"\nclaim = \"R = R\"\n"
                             "left_at = { phi = \"Pi/2 - phi\" }\n"
                             "[[check]]\nname = \"not_supplementary\"\nclaim = \"R = R + s^2*cos(phi)/g\"\n"
                             "left_at = { phi = \"Pi/2 - phi\" }\n";
    const engine::derivation d = derive_text(text);
    for (const engine::check_result* c : d.all_checks())
        if (says(c->name, "display"))
            BOOST_TEST(engine::to_string(c->outcome) == "proven");
    BOOST_TEST((check_named(d, "complementary").outcome.what == engine::verdict::status::proven));
    BOOST_TEST((check_named(d, "not_supplementary").outcome.what == engine::verdict::status::failed));
}

BOOST_AUTO_TEST_CASE(hyperbolic_functions_and_exp_are_proven_as_powers_of_exp)
{
    const engine::derivation d = derive_text(over(check("pythagoras", "cosh(a)^2 - sinh(a)^2 = 1") +
                                                  check("double", "sinh(2*a) = 2*sinh(a)*cosh(a)") +
                                                  check("sum", "tanh(a+b) = (tanh(a) + tanh(b))/(1 + tanh(a)*tanh(b))") +
                                                  check("product", "exp(a+b) = exp(a)*exp(b)") +
                                                  check("wrong", "cosh(2*a) = 2*cosh(a)^2 + 1")));
    for (const char* name : {"pythagoras", "double", "sum", "product"})
        BOOST_TEST(status(d, name) == "proven", name);
    BOOST_TEST(says(method(d, "pythagoras"), "exp, sinh, cosh and tanh as powers of exp over the basis {a}"));
    BOOST_TEST(status(d, "wrong") == "failed");
}

// log(ab) = log a + log b where a, b > 0: from the domains (p, q positive), or said (a, b real).
BOOST_AUTO_TEST_CASE(the_logarithm_of_a_product_is_proven_where_its_factors_are_positive)
{
    const engine::derivation d = derive_text(over(check("positive", "log(p*q) = log(p) + log(q)") +
                                                  check("real", "log(a*b) = log(a) + log(b)") +
                                                  check("power", "log(p^3/q) = 3*log(p) - log(q)") +
                                                  check("root", "log(sqrt(p)) = log(p)/2") +
                                                  check("undone", "exp(2*log(p)) = p^2") +
                                                  check("sum", "log(p + q) = log(p) + log(q)")));
    BOOST_TEST(status(d, "positive") == "proven");
    BOOST_TEST(method(d, "positive") ==
               "logarithms of products split into logarithms of factors proven > 0: p, q: the difference is zero");
    BOOST_TEST(status(d, "real") == "proven, where a > 0, b > 0");
    BOOST_TEST(status(d, "power") == "proven");
    BOOST_TEST(status(d, "root") == "proven");
    BOOST_TEST(status(d, "undone") == "proven");
    BOOST_TEST(status(d, "sum") == "failed");
}

// asin(sin(t)) = t only on [-Pi/2, Pi/2], acos(cos(t)) = t only on [0, Pi].
BOOST_AUTO_TEST_CASE(an_inverse_function_undoes_its_function_on_the_principal_range_only)
{
    const engine::derivation d = derive_text(over(check("asin_inside", "asin(sin(phi)) = phi") +
                                                  check("asin_outside", "asin(sin(theta)) = theta") +
                                                  check("acos_inside", "acos(cos(theta)) = theta") +
                                                  check("atan_inside", "atan(tan(phi)) = phi")));
    BOOST_TEST(status(d, "asin_inside") == "proven");
    BOOST_TEST(says(method(d, "asin_inside"), "asin(sin(phi)) = phi with phi in [0, 1], within [-Pi/2, Pi/2]"));
    BOOST_TEST(status(d, "asin_outside") == "failed");   // asin(sin(3)) = Pi - 3
    BOOST_TEST(status(d, "acos_inside") == "proven");
    BOOST_TEST(status(d, "atan_inside") == "proven");
    // A check's `assuming` narrows theta to [0, 1]: there asin(sin(theta)) = theta.
    const engine::derivation narrowed = derive_text(over("[[check]]\nname = \"asin_assumed\"\n"
                                                         "claim = \"asin(sin(theta)) = theta\"\n"
                                                         "assuming = { theta = \"[0, 1]\" }\n"));
    BOOST_TEST(status(narrowed, "asin_assumed") == "proven");
}

// The principal range with Pi at its ends, through the API (t in [-Pi/2, Pi/2]).
BOOST_AUTO_TEST_CASE(asin_of_sin_is_proven_on_a_domain_with_pi_at_its_ends)
{
    const engine::derivation d = derive_text(over(""));
    engine::proof_cache run;
    const GiNaC::ex t = sym(d, "t");
    engine::assumptions under = engine::declared_assumptions(d.symbols, run);
    under.known = std::make_shared<engine::worked_out>();
    under.domains[t] = angle_domain("-Pi/2", -M_PI / 2, "Pi/2", M_PI / 2, false, false);
    const engine::verdict inside = engine::prove_equal(GiNaC::asin(GiNaC::sin(t)), t, d.symbols, run,
                                                       engine::when_unproven::give_up, {}, &under);
    BOOST_TEST(engine::to_string(inside) == "proven");
    under.known = std::make_shared<engine::worked_out>();
    under.domains[t] = angle_domain("-Pi/2", -M_PI / 2, "Pi", M_PI, false, false);
    const engine::verdict beyond = engine::prove_equal(GiNaC::asin(GiNaC::sin(t)), t, d.symbols, run,
                                                       engine::when_unproven::give_up, {}, &under);
    BOOST_TEST(engine::to_string(beyond) == "failed");
}

// sin >= 0 on [0, Pi], > 0 on (0, Pi), <= 0 on [Pi, 2 Pi]; cos > 0 on (-Pi/2, Pi/2); tan > 0
// on (0, Pi/2); nothing on [0, 4] for sin, which changes sign at Pi.
BOOST_AUTO_TEST_CASE(sin_cos_and_tan_have_their_signs_on_half_periods)
{
    const GiNaC::symbol th("theta");
    const auto sin_on = [&](const engine::domain& r) { return sign_of(GiNaC::sin(th), th, r); };
    BOOST_TEST(sin_on(angle_domain("0", 0, "Pi", M_PI, false, false)).describe() == ">= 0");
    BOOST_TEST(sin_on(angle_domain("0", 0, "Pi", M_PI, true, true)).describe() == "> 0");
    BOOST_TEST(sin_on(angle_domain("Pi", M_PI, "2*Pi", 2 * M_PI, false, false)).describe() == "<= 0");
    BOOST_TEST(sin_on(angle_domain("0", 0, "4", 4, false, false)).describe() == "of unknown sign");
    // 3.14159 < Pi: sin(theta) > 0 on (0, 3.14159]; Pi itself is not below it.
    BOOST_TEST(sin_on(angle_domain("0", 0, "3.14159", 3.14159, true, false)).describe() == "> 0");
    const engine::domain half_turn = angle_domain("-Pi/2", -M_PI / 2, "Pi/2", M_PI / 2, true, true);
    BOOST_TEST(sign_of(GiNaC::cos(th), th, half_turn).describe() == "> 0");
    BOOST_TEST(sign_of(GiNaC::cos(th), th, angle_domain("0", 0, "Pi", M_PI, false, false)).describe() ==
               "of unknown sign");
    BOOST_TEST(sign_of(GiNaC::tan(th), th, angle_domain("0", 0, "Pi/2", M_PI / 2, true, true)).describe() == "> 0");
    BOOST_TEST(sign_of(GiNaC::cos(2 * th), th, angle_domain("0", 0, "Pi/4", M_PI / 4, false, true)).describe() ==
               "> 0");
}

// |sin| <= 1, |cos| <= 1 with sin^2 + cos^2 = 1; exp > 0; log and the inverse functions
// monotone with their ranges; Compton's E' <= E, which needs 1 - cos(theta) >= 0.
BOOST_AUTO_TEST_CASE(bounds_of_sin_cos_exp_log_and_the_inverse_functions_are_proven)
{
    const engine::derivation d = derive_text(over(check("cos_below_one", "cos(t) <= 1") +
                                                  check("sin_above_minus_one", "sin(t) >= -1") +
                                                  check("one_minus_cos", "1 - cos(theta) >= 0") +
                                                  check("squares", "sin(t)^2 <= 1") +
                                                  check("sum_of_both", "2 - sin(t) - cos(t) >= 0") +
                                                  check("exp", "exp(t) > 0") +
                                                  check("sin_on_theta", "sin(theta) >= 0") +
                                                  check("log_above_one", "log(1 + p) > 0") +
                                                  check("atan_below", "atan(x) < Pi/2") +
                                                  check("acos_below", "acos(u) <= Pi") +
                                                  check("asin_sign", "asin(phi) >= 0") +
                                                  check("above_pi", "x^2 + 4 > Pi") +
                                                  check("not_above_pi", "x^2 + 3 > Pi") +
                                                  check("too_tight", "cos(t) < 1")));
    for (const char* name : {"cos_below_one", "sin_above_minus_one", "one_minus_cos", "squares", "sum_of_both",
                             "exp", "sin_on_theta", "log_above_one", "atan_below", "acos_below", "asin_sign",
                             "above_pi"})
        BOOST_TEST(status(d, name) == "proven", name);
    BOOST_TEST(says(check_named(d, "cos_below_one").outcome.proof.at(0).words, "cos(t) in [-1, 1]"));
    BOOST_TEST(says(check_named(d, "sin_on_theta").outcome.proof.at(0).words, "theta in [0, 3], where sin is >= 0"));
    BOOST_TEST(says(check_named(d, "atan_below").outcome.proof.at(0).words, "with atan(x) in (-Pi/2, Pi/2)"));
    BOOST_TEST(says(check_named(d, "above_pi").outcome.proof.at(0).words, "its numbers 4-Pi > 0"));
    BOOST_TEST(status(d, "not_above_pi") == "failed");   // 3 < Pi at x = 0
    BOOST_TEST((check_named(d, "too_tight").outcome.what != engine::verdict::status::proven));   // cos(0) = 1
}

BOOST_AUTO_TEST_CASE(compton_s_scattered_photon_has_no_more_energy_than_the_incident_one)
{
    const std::string text = "id = \"compton\"\ntitle = \"test\"\n"
                             "[[symbol]]\nname = \"E\"\ndomain = \"positive\"\n"
                             "[[symbol]]\nname = \"m\"\ndomain = \"positive\"\n"
                             "[[symbol]]\nname = \"c\"\ndomain = \"positive\"\n"
                             "[[symbol]]\nname = \"theta\"\n"
                             "[[symbol]]\nname = \"Ep\"\n"
                             "[[step]]\ndefine = \"Ep\"\nas = \"E/(1 + E/(m*c^2)*(1 - cos(theta)))\"\n"
                             "because = \"Compton\"\n"
                             "[[result]]\nname = \"Ep\"\n"
                             "[[check]]\nname = \"softer\"\nclaim = \"Ep <= E\"\n"
                             "[[check]]\nname = \"not_harder\"\nclaim = \"Ep >= E\"\n";
    const engine::derivation d = derive_text(text);
    BOOST_TEST(status(d, "softer") == "proven");
    BOOST_TEST((check_named(d, "not_harder").outcome.what != engine::verdict::status::proven));
}

BOOST_AUTO_TEST_SUITE_END()
