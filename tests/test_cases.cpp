// Quantities defined by cases (a `define` step with `cases`): sticking and sliding
// friction derived with its conditions, its checks proven case by case under each case's
// condition, continuity at the cases' boundary proven, and a continuity that fails
// reported failed; the cases' syntax refused at its place.
//
// The derivation files are written for these tests (tests/cases/), not the paper's; the
// expected values are closed forms typed here.
#define BOOST_TEST_MODULE test_cases
#include <boost/test/unit_test.hpp>

#include "derivation_support.h"
#include "support.h"

#include "emit/json.h"
#include "emit/latex.h"
#include "emit/terminal.h"
#include "compile/program.h"
#include "emit/program_cxx.h"
#include "engine/derivation/derivation.h"
#include "engine/expr/infix.h"
#include "engine/library/library.h"
#include "pipeline/regenerate.h"
#include "verify/choice.h"

#include <filesystem>
#include <fstream>

#include <string>

namespace {

using namespace impact;
using namespace impact::testing;

// The full message (`file:line:column: error: what`) of the error `text` raises.
std::string message_for(const std::string& text)
{
    return error_for(text).what();
}

bool proven(const engine::verdict& v)
{
    return v.what == engine::verdict::status::proven;
}

// A derivation of y by cases in x; `cases_line` is line 10 of the file, `more` follows.
std::string by_cases(const std::string& cases_line, const std::string& more = "")
{
    return "id = \"t\"\n"                 // 1
           "title = \"t\"\n"              // 2
           "[[symbol]]\n"                 // 3
           "name = \"x\"\n"               // 4
           "domain = \"positive\"\n"      // 5
           "[[symbol]]\n"                 // 6
           "name = \"y\"\n"               // 7
           "[[step]]\n"                   // 8
           "define = \"y\"\n"             // 9
           + cases_line + "\n" +          // 10
           "[[result]]\n"                 // 11
           "name = \"y\"\n" + more;       // 12
}

} // namespace

BOOST_AUTO_TEST_CASE(friction_is_derived_as_its_cases_with_their_conditions)
{
    const engine::derivation d = derive_file("tests/cases/friction.toml");
    const GiNaC::ex g_t = sym(d, "g_t"), m_t = sym(d, "m_t"), b = sym(d, "b"), mu = sym(d, "mu"),
                    m_n = sym(d, "m_n"), v_n = sym(d, "v_n"), e = sym(d, "e");
    const engine::result* j_t = d.find_result("J_t");
    BOOST_REQUIRE(j_t);
    BOOST_REQUIRE_EQUAL(j_t->cases.size(), 2u);
    // Sticking: the impulse that stops the slip (with restitution b); sliding: mu J_n, with
    // J_n = (1 + e) m_n v_n substituted.
    BOOST_TEST(equal(j_t->cases[0].value, (1 + b) * m_t * g_t));
    BOOST_TEST(equal(j_t->cases[1].value, mu * (1 + e) * m_n * v_n));
    BOOST_TEST((j_t->cases[0].op == engine::relation::less_equal));
    BOOST_TEST((j_t->cases[1].op == engine::relation::greater));
    BOOST_TEST(equal(j_t->cases[0].lhs, (1 + b) * m_t * g_t));
    BOOST_TEST(equal(j_t->cases[0].rhs, mu * (1 + e) * m_n * v_n));
    // The step proves that the two conditions cover every value.
    const engine::step_result& step = d.steps.at(1);
    BOOST_REQUIRE_EQUAL(step.cases.size(), 2u);
    BOOST_REQUIRE_EQUAL(step.checks.size(), 1u);
    BOOST_TEST(step.checks[0].name == "the cases of J_t cover every value");
    BOOST_TEST(proven(step.checks[0].outcome));
    BOOST_TEST(d.all_hold());
}

BOOST_AUTO_TEST_CASE(friction_checks_are_proven_case_by_case_under_each_condition)
{
    const engine::derivation d = derive_file("tests/cases/friction.toml");
    for (const std::string name : {"inside the friction cone", "never more than sticking needs", "opposes the slip"}) {
        BOOST_TEST_CONTEXT(name)
        {
            const engine::check_result& c = check_named(d, name);
            BOOST_TEST(c.cases_of == "J_t");
            BOOST_REQUIRE_EQUAL(c.parts.size(), 2u);
            BOOST_TEST(proven(c.parts[0].outcome));
            BOOST_TEST(proven(c.parts[1].outcome));
            BOOST_TEST(proven(c.outcome));
        }
    }
    // J_t <= mu J_n when sticking holds only by the condition: (1 + b) m_t g_t <= mu J_n
    // is not true for every value, so the proof must have used it.
    const engine::check_result& cone = check_named(d, "inside the friction cone");
    const std::string& method = cone.parts[0].outcome.method;
    BOOST_TEST(method.rfind("under g_t*m_t*(1+b) <= mu*m_n*v_n*(1+e): ", 0) == 0, method);
    BOOST_TEST(method.find("a factor > 0 times the condition's") != std::string::npos, method);
}

BOOST_AUTO_TEST_CASE(a_sum_is_proven_a_term_at_a_time_the_signed_terms_set_aside)
{
    // -(1 - e^2) m_n v_n^2/2 - J_t (g_t - J_t/(2 m_t)) <= 0: the first term is <= 0 by
    // the domains alone; sliding, the second is <= 0 because mu J_n < (1 + b) m_t g_t
    // <= 2 m_t g_t, which only the condition gives.
    const engine::derivation d = derive_file("tests/cases/friction.toml");
    const engine::check_result& c = check_named(d, "energy never gained");
    BOOST_REQUIRE_EQUAL(c.parts.size(), 2u);
    BOOST_TEST(proven(c.parts[0].outcome));
    BOOST_TEST(proven(c.parts[1].outcome));
    BOOST_TEST(proven(c.outcome));
    const std::string& sliding = c.parts[1].outcome.method;
    BOOST_TEST(sliding.rfind("the term ", 0) == 0, sliding);
    BOOST_TEST(sliding.find("under g_t*m_t*(1+b) > mu*m_n*v_n*(1+e)") != std::string::npos, sliding);
    // Without the condition the tangential term alone is not signed: its sign is the
    // condition's to give, and at a sliding impulse twice the sticking one it fails.
    std::ifstream in(IMPACT_SOURCE_DIR "/tests/cases/friction.toml");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string sliding_value = "as = \"mu*J_n\"";
    BOOST_REQUIRE(text.find(sliding_value) != std::string::npos);
    text.replace(text.find(sliding_value), sliding_value.size(), "as = \"3*(1 + b)*m_t*g_t\"");
    const engine::derivation wrong = derive_text(text);
    BOOST_TEST(!proven(check_named(wrong, "energy never gained").outcome));
}

BOOST_AUTO_TEST_CASE(a_symmetry_of_a_quantity_by_cases_is_proven_in_each_case)
{
    // J_t depends on m_t and g_t through their product only, in its values and its
    // conditions: doubling g_t and halving m_t changes nothing, case by case.
    std::ifstream in(IMPACT_SOURCE_DIR "/tests/cases/friction.toml");
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const auto with_check = [&](const std::string& claim, const std::string& left_at) {
        return text + "\n[[check]]\nname = \"scaled\"\nclaim = \"" + claim + "\"\nleft_at = { " + left_at +
               " }\nbecause = \"b\"\n";
    };
    const engine::derivation d = derive_text(with_check("J_t = J_t", "g_t = \"2*g_t\", m_t = \"m_t/2\""));
    const engine::check_result& c = check_named(d, "scaled");
    BOOST_TEST(c.cases_of == "J_t");
    BOOST_REQUIRE_EQUAL(c.parts.size(), 2u);
    BOOST_TEST(proven(c.parts[0].outcome));
    BOOST_TEST(proven(c.parts[1].outcome));
    BOOST_TEST(proven(c.outcome));
    // A false claim fails; a change that moves the conditions (g_t doubled alone) is
    // refused at the check's place: the two sides could fall in different cases.
    // A second check at the same changed inputs says them, and its cases, once.
    const std::string twice = with_check("J_t = J_t", "g_t = \"2*g_t\", m_t = \"m_t/2\"") +
                              "\n[[check]]\nname = \"scaled again\"\nclaim = \"2*J_t = 2*J_t\"\n"
                              "left_at = { g_t = \"2*g_t\", m_t = \"m_t/2\" }\nbecause = \"c\"\n";
    const std::string tex = emit::latex_fragment(derive_text(twice));
    BOOST_TEST(tex.find("Scaled again: $2 J_t = 2 J_t$, the left side taken at the same changed inputs. C. Case by "
                        "case, as the check above.") != std::string::npos,
               tex);
    const engine::derivation wrong = derive_text(with_check("J_t = 2*J_t", "g_t = \"2*g_t\", m_t = \"m_t/2\""));
    BOOST_TEST(!proven(check_named(wrong, "scaled").outcome));
    const std::string refused = message_for(with_check("J_t = 2*J_t", "g_t = \"2*g_t\""));
    BOOST_TEST(refused.find("error: check 'scaled': left_at changes the conditions of the cases of 'J_t'") !=
                   std::string::npos,
               refused);
}

BOOST_AUTO_TEST_CASE(a_symmetry_never_compares_quantities_whose_cases_differ)
{
    // J and K change at x = 1 and x = 2: at x = 3/2, J = 2 and K = 1, so J = K is false,
    // whatever left_at changes (y, which neither uses).
    const std::string two = "id = \"t\"\ntitle = \"t\"\n"
                            "[[symbol]]\nname = \"x\"\ndomain = \"positive\"\n"
                            "[[symbol]]\nname = \"y\"\ndomain = \"positive\"\n"
                            "[[symbol]]\nname = \"J\"\n[[symbol]]\nname = \"K\"\n"
                            "[[step]]\ndefine = \"J\"\ncases = [{ when = \"x <= 1\", as = \"1\" }, "
                            "{ when = \"x > 1\", as = \"2\" }]\n"
                            "[[step]]\ndefine = \"K\"\ncases = [{ when = \"x <= 2\", as = \"1\" }, "
                            "{ when = \"x > 2\", as = \"2\" }, ]\n"
                            "[[result]]\nname = \"J\"\n";
    const auto check = [&](const std::string& claim, const std::string& left_at) {
        return two + "[[check]]\nname = \"c\"\nclaim = \"" + claim + "\"\nleft_at = { " + left_at + " }\n";
    };
    for (const std::string claim : {"J = K", "J - K = 0", "K = J"}) {
        const std::string refused = message_for(check(claim, "y = \"2*y\""));
        BOOST_TEST(refused.find("defined by cases with different conditions") != std::string::npos, refused);
    }
    // A derived quantity is no input: left_at may not give it a value.
    const std::string derived = message_for(check("J = J", "J = \"5\""));
    BOOST_TEST(derived.find("left_at gives 'J' a value, but a step derives it") != std::string::npos, derived);
    // With no quantity by cases on the right, the left's cases are named as the quantity.
    const engine::derivation d = derive_text(check("J >= 1", "y = \"2*y\""));
    const engine::check_result& c = check_named(d, "c");
    BOOST_TEST(c.cases_of == "J");
    BOOST_TEST(proven(c.outcome));
    BOOST_TEST(c.parts.at(0).under.rfind("case 1 (J = 1, where x <= 1)", 0) == 0, c.parts.at(0).under);
    BOOST_TEST(emit::latex_fragment(d).find("at\\_left") == std::string::npos);
}

BOOST_AUTO_TEST_CASE(sticking_and_sliding_meet_at_the_edge_of_the_cone)
{
    const engine::derivation d = derive_file("tests/cases/friction.toml");
    const engine::check_result& c = check_named(d, "sticking and sliding meet");
    BOOST_REQUIRE_EQUAL(c.parts.size(), 1u);
    // The boundary solved for g_t, the first declared quantity it is linear in.
    BOOST_TEST(c.parts[0].under.rfind("cases 1 and 2 at g_t = ", 0) == 0, c.parts[0].under);
    BOOST_TEST(proven(c.parts[0].outcome));
    BOOST_TEST(proven(c.outcome));
}

BOOST_AUTO_TEST_CASE(a_halved_sliding_impulse_fails_continuity)
{
    const engine::derivation d = derive_file("tests/cases/discontinuous.toml");
    const engine::check_result& c = check_named(d, "sticking and sliding meet");
    BOOST_TEST((c.outcome.what == engine::verdict::status::failed));
    BOOST_TEST(!c.outcome.holds());
    BOOST_TEST(!d.all_hold());
    // At the edge, (1 + b) m_t g_t = mu J_n: the values differ by mu J_n / 2.
    const GiNaC::ex mu = sym(d, "mu"), m_n = sym(d, "m_n"), v_n = sym(d, "v_n"), e = sym(d, "e");
    const GiNaC::ex r = c.parts.at(0).outcome.residual;
    BOOST_TEST((equal(r, mu * (1 + e) * m_n * v_n / 2) || equal(r, -mu * (1 + e) * m_n * v_n / 2)), r);
    // The other checks still hold in both cases.
    BOOST_TEST(proven(check_named(d, "inside the friction cone").outcome));
    BOOST_TEST(proven(check_named(d, "never more than sticking needs").outcome));
}

BOOST_AUTO_TEST_CASE(continuity_solves_the_boundary_for_a_quantity_outside_its_radicals)
{
    // min(k sqrt(x), 1): the boundary k sqrt(x) = 1 is not a polynomial in x (GiNaC's
    // degree() threw on it) and is solved for k.
    const engine::derivation d = derive_text(
        "id = \"t\"\ntitle = \"t\"\n"
        "[[symbol]]\nname = \"x\"\ndomain = \"positive\"\n"
        "[[symbol]]\nname = \"k\"\ndomain = \"positive\"\n"
        "[[symbol]]\nname = \"y\"\n"
        "[[step]]\ndefine = \"y\"\n"
        "cases = [{ when = \"k*sqrt(x) <= 1\", as = \"k*sqrt(x)\" }, { when = \"k*sqrt(x) > 1\", as = \"1\" }]\n"
        "[[result]]\nname = \"y\"\n"
        "[[check]]\nname = \"meets\"\ncontinuity = \"y\"\n");
    const engine::check_result& meets = check_named(d, "meets");
    BOOST_REQUIRE_EQUAL(meets.parts.size(), 1u);
    BOOST_TEST(meets.parts[0].under.rfind("cases 1 and 2 at k = ", 0) == 0, meets.parts[0].under);
    BOOST_TEST(proven(meets.outcome));
}

BOOST_AUTO_TEST_CASE(a_claim_false_in_one_case_fails_in_that_case_only)
{
    const std::string text = by_cases(
        "cases = [{ when = \"x <= 1\", as = \"x\" }, { when = \"x > 1\", as = \"1\" }]",
        "[[check]]\nname = \"at most one\"\nclaim = \"y <= 1\"\n"
        "[[check]]\nname = \"at most a half\"\nclaim = \"y <= 1/2\"\n"
        "[[check]]\nname = \"meets\"\ncontinuity = \"y\"\n");
    const engine::derivation d = derive_text(text);
    // y = min(x, 1) <= 1: case 1 by its condition x <= 1, case 2 by 1 <= 1.
    const engine::check_result& one = check_named(d, "at most one");
    BOOST_TEST(proven(one.outcome));
    // y <= 1/2 is false in both cases (x = 1 in the first, 1 in the second).
    const engine::check_result& half = check_named(d, "at most a half");
    BOOST_TEST((half.parts.at(0).outcome.what == engine::verdict::status::failed));
    BOOST_TEST((half.parts.at(1).outcome.what == engine::verdict::status::failed));
    BOOST_TEST(!half.outcome.holds());
    // min(x, 1) is continuous at x = 1.
    const engine::check_result& meets = check_named(d, "meets");
    BOOST_TEST(meets.parts.at(0).under == "cases 1 and 2 at x = 1");
    BOOST_TEST(proven(meets.outcome));
}

BOOST_AUTO_TEST_CASE(cases_that_leave_their_boundary_out_are_not_exhaustive)
{
    const engine::derivation d =
        derive_text(by_cases("cases = [{ when = \"x < 1\", as = \"x\" }, { when = \"x > 1\", as = \"1\" }]"));
    const engine::check_result& c = d.steps.at(0).checks.at(0);
    BOOST_TEST((c.outcome.what == engine::verdict::status::failed));
    BOOST_TEST(c.outcome.method.find("D = 0 is in no case") != std::string::npos, c.outcome.method);
    BOOST_TEST(!d.all_hold());
    // Conditions on two different expressions are not proven to cover every value.
    const engine::derivation two = derive_text(
        by_cases("cases = [{ when = \"x <= 1\", as = \"x\" }, { when = \"x^2 > 1\", as = \"1\" }]"));
    BOOST_TEST((two.steps.at(0).checks.at(0).outcome.what == engine::verdict::status::failed));
}

BOOST_AUTO_TEST_CASE(cases_on_a_radical_of_a_radical_cover_every_value)
{
    // |g_t| of rough spheres in space is the square root of a sum of squares that holds the
    // distance sqrt(r.r): the two conditions, one the other turned, are compared as written
    // before normal() gives each radical a form of its own.
    const engine::derivation d = derive_text(
        by_cases("cases = [{ when = \"x*sqrt((1 - x*sqrt(1 + x^2))^2 + x^4) <= 1\", as = \"x\" }, "
                 "{ when = \"x*sqrt((1 - x*sqrt(1 + x^2))^2 + x^4) > 1\", as = \"1\" }]"));
    const engine::check_result& c = d.steps.at(0).checks.at(0);
    BOOST_TEST(proven(c.outcome), c.outcome.method);
    BOOST_TEST(c.outcome.method.find("D >= 0, D < 0") != std::string::npos, c.outcome.method);
}

BOOST_AUTO_TEST_CASE(a_radical_of_a_radical_is_derived_with_its_radicand_expanded)
{
    // normal() leaves such a radicand in whichever form GiNaC's order of terms gives it in a
    // run; expanded, a derived value is typeset the same in every run (|g_t| in space).
    const engine::derivation d = derive_text("id = \"t\"\ntitle = \"t\"\n[[symbol]]\nname = \"x\"\ndomain = \"positive\"\n"
                                             "[[symbol]]\nname = \"y\"\n[[step]]\ndefine = \"y\"\n"
                                             "as = \"sqrt((1 + x)*(x + sqrt(1 + x^2)))\"\n[[result]]\nname = \"y\"\n");
    const GiNaC::ex x = d.symbols.find("x")->symbol;
    const GiNaC::ex expanded = GiNaC::sqrt(x + x * x + x * GiNaC::sqrt(1 + x * x) + GiNaC::sqrt(1 + x * x));
    BOOST_TEST(d.find_result("y")->value.is_equal(expanded), d.find_result("y")->value);
}

BOOST_AUTO_TEST_CASE(bad_cases_are_refused_at_their_place)
{
    BOOST_TEST(message_for(by_cases("cases = [{ when = \"x <= 1\", as = \"x\" }]")) ==
               "test.toml:10:9: error: 'cases' of 'y' must list two cases or more, each "
               "{ when = \"lhs <= rhs\", as = \"value\" }");
    BOOST_TEST(message_for(by_cases("cases = [{ when = \"x <= 1\", as = \"x\" }, { when = \"x > 1\" }]")) ==
               "test.toml:10:41: error: a case of 'y' is missing the required field 'as'");
    BOOST_TEST(message_for(by_cases("cases = [{ when = \"x <= 1\", as = \"x\", at = \"1\" }, "
                                  "{ when = \"x > 1\", as = \"1\" }]")) ==
               "test.toml:10:39: error: unknown field 'at' in a case of 'y'");
    BOOST_TEST(message_for(by_cases("cases = [{ when = \"x = 1\", as = \"x\" }, { when = \"x > 1\", as = \"1\" }]")) ==
               "test.toml:10:19: error: condition \"x = 1\" must be an inequality 'lhs op rhs' with op one of "
               "<, <=, >, >=");
    BOOST_TEST(message_for(by_cases("as = \"x\"\ncases = [{ when = \"x <= 1\", as = \"x\" }, "
                                  "{ when = \"x > 1\", as = \"1\" }]")) ==
               "test.toml:11:9: error: step 'y' has both 'as' and 'cases': give one value or its cases");
    // A case's value must have the quantity's dimension, like any definition's.
    const std::string dimensions = "id = \"t\"\ntitle = \"t\"\n"
                                   "[[symbol]]\nname = \"x\"\ndomain = \"positive\"\ndimension = \"length\"\n"
                                   "[[symbol]]\nname = \"y\"\ndimension = \"length\"\n"
                                   "[[step]]\ndefine = \"y\"\n"
                                   "cases = [{ when = \"x <= 1\", as = \"x\" }, { when = \"x > 1\", as = \"1\" }]\n"
                                   "[[result]]\nname = \"y\"\n";
    BOOST_TEST(message_for(dimensions).rfind("test.toml:12:", 0) == 0, message_for(dimensions));
}

BOOST_AUTO_TEST_CASE(continuity_checks_are_refused_where_they_mean_nothing)
{
    const std::string cases = "cases = [{ when = \"x <= 1\", as = \"x\" }, { when = \"x > 1\", as = \"1\" }]";
    // Continuity of a quantity not defined by cases.
    BOOST_TEST(message_for(by_cases(cases, "[[check]]\nname = \"c\"\ncontinuity = \"x\"\n")) ==
               "test.toml:15:14: error: continuity of 'x': it is not defined by cases");
    BOOST_TEST(message_for(by_cases(cases, "[[check]]\nname = \"c\"\ncontinuity = \"y\"\nclaim = \"y > 0\"\n")) ==
               "test.toml:16:9: error: check 'c' has both 'claim' and 'continuity': a continuity check states its "
               "claim itself");
    // Cases on two different expressions share no boundary.
    BOOST_TEST(message_for(by_cases("cases = [{ when = \"x <= 1\", as = \"x\" }, { when = \"x^2 > 1\", as = \"1\" }]",
                                  "[[check]]\nname = \"c\"\ncontinuity = \"y\"\n")) ==
               "test.toml:15:14: error: no two cases of 'y' share a boundary (conditions that are signs of one "
               "expression): continuity cannot be checked");
}

BOOST_AUTO_TEST_CASE(a_result_by_cases_is_typeset_as_a_cases_environment)
{
    const engine::derivation d = derive_text(by_cases(
        "cases = [{ when = \"x <= 1\", as = \"x\" }, { when = \"x > 1\", as = \"1\" }]",
        "[[check]]\nname = \"meets\"\ncontinuity = \"y\"\n"));
    const std::string tex = emit::latex_fragment(d);
    const std::string cases = "\\begin{cases} x & \\text{if } x \\leq 1 \\\\ 1 & \\text{if } x > 1 \\end{cases}";
    // In the step, as written, and among the results.
    BOOST_TEST(tex.find("  y &= " + cases + "\n\\end{align*}") != std::string::npos, tex);
    BOOST_TEST(tex.find("  y &= " + cases + " \\notag\n") != std::string::npos, tex);
    BOOST_TEST(tex.find("The cases of $y$ cover every value: \\textbf{proven}.") != std::string::npos, tex);
    // A check proven case by case lists each case in mathematics.
    const engine::derivation checked = derive_text(by_cases(
        "cases = [{ when = \"x <= 1\", as = \"x\" }, { when = \"x > 1\", as = \"1\" }]",
        "[[check]]\nname = \"at most one\"\nclaim = \"y <= 1\"\n"));
    const std::string checked_tex = emit::latex_fragment(checked);
    BOOST_TEST(checked_tex.find("Case by case: case 1 ($y = x$ where $x \\leq 1$): \\textbf{proven} and case 2 "
                                "($y = 1$ where $x > 1$): \\textbf{proven}.") != std::string::npos,
               checked_tex);
    // Each check labelled, the web report's anchor for it and its proof.
    BOOST_TEST(tex.find("\\item\\label{impact:t:check:meets} \\textbf{proven} --- Meets: $y$ is continuous where its "
                        "cases meet. Where the "
                        "cases meet: cases 1 and 2 at $x = 1$: \\textbf{proven}.") != std::string::npos,
               tex);
}

BOOST_AUTO_TEST_CASE(cases_all_proven_that_would_fill_lines_are_said_once)
{
    // Two cases each shorter than a line, together longer: listed, each with its condition,
    // they would repeat what y's step displays; all proven, they are said once.
    std::string sum = "x";
    for (int k = 2; k <= 9; ++k)
        sum += " + x^" + std::to_string(k) + "/" + std::to_string(k);
    const engine::derivation d = derive_text(by_cases(
        "cases = [{ when = \"x <= 1\", as = \"" + sum + "\" }, { when = \"x > 1\", as = \"2*(" + sum + ")\" }]",
        "[[check]]\nname = \"positive\"\nclaim = \"y > 0\"\n"));
    const std::string tex = emit::latex_fragment(d);
    BOOST_TEST(tex.find("Case by case, in each of the 2 cases of $y$ (as defined above): \\textbf{proven}.") !=
                   std::string::npos,
               tex);
    BOOST_TEST(tex.find("case 1 (") == std::string::npos, tex);
    // One that fails is listed, each case with its outcome.
    const engine::derivation failing = derive_text(by_cases(
        "cases = [{ when = \"x <= 1\", as = \"" + sum + "\" }, { when = \"x > 1\", as = \"-(" + sum + ")\" }]",
        "[[check]]\nname = \"positive\"\nclaim = \"y > 0\"\n"));
    BOOST_TEST(emit::latex_fragment(failing).find("Case by case: case 1") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(a_case_as_long_as_a_line_is_referred_to_by_its_number)
{
    // The cases are displayed where y is defined; a check lists a long one by number.
    std::string sum = "x";
    for (int k = 2; k <= 40; ++k)
        sum += " + x^" + std::to_string(k) + "/" + std::to_string(k);
    const engine::derivation d = derive_text(by_cases(
        "cases = [{ when = \"x <= 1\", as = \"" + sum + "\" }, { when = \"x > 1\", as = \"" + sum + "\" }]",
        "[[check]]\nname = \"positive\"\nclaim = \"y > 0\"\n[[check]]\nname = \"meets\"\ncontinuity = \"y\"\n"));
    const std::string tex = emit::latex_fragment(d);
    BOOST_TEST(tex.find("Case by case: case 1 of $y$: \\textbf{proven} and case 2 of $y$: \\textbf{proven}.") !=
                   std::string::npos,
               tex);
    // The boundary x = 1 is short: it is shown.
    BOOST_TEST(tex.find("cases 1 and 2 at $x = 1$: \\textbf{proven}") != std::string::npos, tex);
}

BOOST_AUTO_TEST_CASE(json_and_terminal_list_the_cases)
{
    const engine::derivation d = derive_text(by_cases(
        "cases = [{ when = \"x <= 1\", as = \"x\" }, { when = \"x > 1\", as = \"1\" }]",
        "[[check]]\nname = \"at most one\"\nclaim = \"y <= 1\"\n"));
    const std::string json = emit::derivations_json({&d});
    BOOST_TEST(json.find("      \"cases\": {\n        \"y\": [\n          {\n            \"when\": \"x <= 1\",\n"
                         "            \"value\": \"x\"\n          },\n          {\n"
                         "            \"when\": \"x > 1\",\n            \"value\": \"1\"\n          }\n"
                         "        ]\n      }") != std::string::npos,
               json);
    BOOST_TEST(json.find("\"under\": \"case 2 (y = 1, where x > 1)\"") != std::string::npos, json);
    const std::string text = emit::terminal_text(d);
    BOOST_TEST(text.find("  y by cases\n    y = x    if x <= 1\n    y = 1    if x > 1\n") != std::string::npos, text);
    BOOST_TEST(text.find("      case 1 (y = x, where x <= 1): proven\n") != std::string::npos, text);
}

BOOST_AUTO_TEST_CASE(a_bound_on_one_symbol_narrows_its_domain_in_that_case)
{
    const engine::derivation d = derive_text(by_cases(
        "cases = [{ when = \"x <= 1\", as = \"x\" }, { when = \"x > 1\", as = \"1\" }]",
        "[[check]]\nname = \"narrowed\"\nclaim = \"y*(2 - y) >= 0\"\n"));
    // x (2 - x) >= 0 holds for x in (0, 1], not for every positive x: the sign of 2 - x
    // needs the case's bound.
    const engine::check_result& c = check_named(d, "narrowed");
    BOOST_REQUIRE_EQUAL(c.parts.size(), 2u);
    BOOST_TEST(proven(c.parts[0].outcome));
    BOOST_TEST(c.parts[0].outcome.method.rfind("under x <= 1, x in (0, 1]: ", 0) == 0, c.parts[0].outcome.method);
    BOOST_TEST(proven(c.outcome));
}

BOOST_AUTO_TEST_CASE(a_case_only_sampled_is_reported_sampled_never_proven)
{
    const engine::derivation d = derive_text(by_cases(
        "cases = [{ when = \"x <= 1\", as = \"x\" }, { when = \"x > 1\", as = \"1\" }]",
        "[[symbol]]\nname = \"z\"\n[[check]]\nname = \"cubic\"\nclaim = \"y^2 + y*z + z^2 > 0\"\n"));
    // x^2 + x z + z^2 > 0 for every positive x (a positive definite form), but no sign
    // argument of the prover settles it: case 1 is sampled, case 2 (1 + z + z^2 > 0, by
    // Sturm's theorem in z) proven.
    const engine::check_result& c = check_named(d, "cubic");
    BOOST_REQUIRE_EQUAL(c.parts.size(), 2u);
    BOOST_TEST((c.parts[0].outcome.what == engine::verdict::status::sampled));
    BOOST_TEST(c.parts[0].outcome.method.rfind("not proven under x <= 1; sampled over the whole domain", 0) == 0,
               c.parts[0].outcome.method);
    BOOST_TEST(proven(c.parts[1].outcome));
    BOOST_TEST((c.outcome.what == engine::verdict::status::sampled));
    BOOST_TEST(c.outcome.method.find("case 1 (y = x, where x <= 1): sampled (200 points)") != std::string::npos,
               c.outcome.method);
}

BOOST_AUTO_TEST_CASE(a_kernel_computes_cases_with_one_select_on_both_sides_of_the_boundary)
{
    const engine::derivation d = derive_file("tests/cases/friction.toml");
    BOOST_REQUIRE_EQUAL(d.kernels.size(), 1u);
    const engine::kernel& k = d.kernels.front();
    const std::vector<GiNaC::ex> inputs = k.input_symbols();
    const compile::program p =
        compile::compile_program({k.outputs.at(0).values.at(0)}, inputs, engine::term_order(inputs));
    BOOST_TEST(compile::count(p, compile::opcode::select) == 1u);
    // Inputs g_t, m_t, b, mu, m_n, v_n, e. Sticking: (1 + b) m_t g_t = 1.5 within
    // mu (1 + e) m_n v_n = 2, so J_t = 1.5; sliding at g_t = 2: 3 > 2, so J_t = 2; sliding
    // with mu = 1/4: 1.5 > 0.5, so J_t = 0.5; on the edge (b = 1): 2 = 2, both cases give 2.
    BOOST_TEST(compile::run<double>(p, {1, 1, 0.5, 1, 1, 1, 1}).at(0) == 1.5);
    BOOST_TEST(compile::run<double>(p, {2, 1, 0.5, 1, 1, 1, 1}).at(0) == 2.0);
    BOOST_TEST(compile::run<double>(p, {1, 1, 0.5, 0.25, 1, 1, 1}).at(0) == 0.5);
    BOOST_TEST(compile::run<double>(p, {1, 1, 1, 1, 1, 1, 1}).at(0) == 2.0);
    // Printed as a conditional expression on values computed before it.
    const emit::cxx_code code = emit::program_cxx(p, {"g_t", "m_t", "b", "mu", "m_n", "v_n", "e"});
    BOOST_REQUIRE_EQUAL(code.outputs.size(), 1u);
    BOOST_TEST(code.outputs[0].find(" > Real(0) ? ") != std::string::npos, code.outputs[0]);
    BOOST_TEST(code.outputs[0].find(" : ") != std::string::npos, code.outputs[0]);
    // Measured against CLN, which evaluates the case that holds at each sample.
    const verify::kernel_plan plan = verify::plan_kernel(k, engine::declaration_order(d.symbols));
    const std::vector<std::string> missed = verify::missed_bounds({plan});
    BOOST_TEST(missed.empty(), (missed.empty() ? std::string() : missed.front()));
}

namespace {

// The kernel headers `files` holds, and `program` beside them, compiled with the build's compiler
// and `flags`, then run: what the compiler and the program printed, and the program's status.
impact::testing::run_result compiled_and_run(const pipeline::file_set& files, const std::string& program,
                                             const std::string& flags)
{
    const impact::testing::temporary_folder dir("impact-test-cases-kernel");
    impact::testing::write_files(dir.root, files);
    std::ofstream(dir.root / "main.cpp") << program;
    return impact::testing::run_command(std::string(IMPACT_CXX) + " -std=c++17 " + flags + " -I" +
                                        (dir.root / "kernels").string() + " " + (dir.root / "main.cpp").string() +
                                        " -o " + (dir.root / "main").string() + " && " + (dir.root / "main").string());
}

} // namespace

BOOST_AUTO_TEST_CASE(the_emitted_kernel_compiles_and_selects_each_case)
{
    const engine::library lib = engine::derive_all({spec::read_derivation(IMPACT_SOURCE_DIR "/tests/cases/friction.toml")});
    std::vector<std::string> missed;
    const pipeline::file_set files = pipeline::generate_kernels(lib, &missed);
    BOOST_TEST(missed.empty());
    // Sticking (1.5 within 2), sliding (3 beyond 2: 2), sliding with mu = 1/4 (0.5), the edge (2);
    // its fast form (impact::fast) too.
    const std::string program = "#include \"impact/friction_impulse.hpp\"\n"
                                "int main()\n{\n"
                                "    using impact::friction_impulse;\n"
                                "    return friction_impulse<double>(1, 1, 0.5, 1, 1, 1, 1) == 1.5 &&\n"
                                "           friction_impulse<double>(2, 1, 0.5, 1, 1, 1, 1) == 2.0 &&\n"
                                "           friction_impulse<double>(1, 1, 0.5, 0.25, 1, 1, 1) == 0.5 &&\n"
                                "           friction_impulse<float>(1, 1, 1, 1, 1, 1, 1) == 2.0f &&\n"
                                "           friction_impulse<double>(2, 1, 0.5, 1, 1, 1, 1, impact::fast) == 2.0 ? 0 : 1;\n"
                                "}\n";
    const impact::testing::run_result r = compiled_and_run(files, program, "-O2");
    BOOST_TEST(r.status == 0, r.output);
}

// Two bodies on a line, not the paper's file: a kernel of scalars alone, with a batch form.
// Its velocities after the collision, typed here: v_M' = (M v_M + m v_m - eps m (v_M - v_m))/(M + m),
// v_m' = (M v_M + m v_m + eps M (v_M - v_m))/(M + m).
std::string line_kernel(const std::string& names)
{
    return "id = \"bodies_on_a_line\"\ntitle = \"t\"\n"
           "[[symbol]]\nname = \"M\"\ndomain = \"positive\"\ndimension = \"mass\"\n"
           "[[symbol]]\nname = \"m\"\ndomain = \"positive\"\ndimension = \"mass\"\n"
           "[[symbol]]\nname = \"u\"\ndimension = \"velocity\"\n"
           "[[symbol]]\nname = \"w\"\ndimension = \"velocity\"\n"
           "[[symbol]]\nname = \"eps\"\ndomain = \"[0, 1]\"\n"
           "[[symbol]]\nname = \"u_after\"\ndimension = \"velocity\"\n"
           "[[symbol]]\nname = \"w_after\"\ndimension = \"velocity\"\n"
           "[[step]]\ndefine = \"u_after\"\nas = \"(M*u + m*w - eps*m*(u - w))/(M + m)\"\n"
           "[[step]]\ndefine = \"w_after\"\nas = \"(M*u + m*w + eps*M*(u - w))/(M + m)\"\n"
           "[[result]]\nname = \"u_after\"\n[[result]]\nname = \"w_after\"\n"
           "[[kernel]]\nname = \"line\"\nbatch = true\n" + names +
           "velocities = [\"u\", \"w\"]\nerror = [\"u = velocity\", \"w = velocity\"]\n"
           "guards = [\"invalid_input = M, m, eps\", \"non_finite = u, w\"]\n";
}

BOOST_AUTO_TEST_CASE(a_batch_kernel_of_scalars_compiles_and_writes_what_its_scalar_kernel_returns)
{
    const engine::library lib = engine::derive_all({spec::parse_derivation(
        line_kernel("inputs = [\"M\", \"m\", \"u\", \"w\", \"eps\"]\noutputs = [\"u = u_after\", \"w = w_after\"]\n"),
        "line.toml")});
    std::vector<std::string> missed;
    const pipeline::file_set files = pipeline::generate_kernels(lib, &missed);
    BOOST_TEST(missed.empty(), (missed.empty() ? std::string() : missed.front()));
    // Equal masses, elastic: the velocities exchanged (0 and 1, exactly); M = 3, m = 1,
    // eps = 1/2, u = 1, w = -1: u' = (3 - 1 - 1)/4 = 1/4, w' = (2 + 3)/4 = 5/4; a mass of 0 is
    // refused, its velocities left as they were. The batch writes the scalar kernel's results.
    const std::string program =
        "#include \"impact/line.hpp\"\n"
           "int main()\n{\n"
           "    double M[3] = {1, 3, 0}, m[3] = {1, 1, 1}, u[3] = {1, 1, 1}, w[3] = {0, -1, 0}, eps[3] = {1, 0.5, 1};\n"
           "    impact::status status[3];\n"
           "    impact::line_batch_data<double, 0> data{};\n"
           "    data.count = 3;\n    data.M = M;\n    data.m = m;\n    data.u = u;\n    data.w = w;\n    data.eps = eps;\n"
           "    data.status = status;\n"
           "    const auto first = impact::line<double>(1, 1, 1, 0, 1);\n"
           "    const auto second = impact::line<double>(3, 1, 1, -1, 0.5);\n"
           "    impact::line_batch(data);\n"
           "    const bool typed = u[0] == 0 && w[0] == 1 && u[1] == 0.25 && w[1] == 1.25 && u[2] == 1 && w[2] == 0;\n"
           "    const bool as_scalar = first.u == u[0] && first.w == w[0] && second.u == u[1] && second.w == w[1];\n"
           "    const bool statuses = status[0] == impact::status::ok && status[1] == impact::status::ok &&\n"
           "                          status[2] == impact::status::invalid_input;\n"
           "    return typed && as_scalar && statuses ? 0 : 1;\n}\n";
    const impact::testing::run_result r = compiled_and_run(files, program, "-O2");
    BOOST_TEST(r.status == 0, r.output);
}

// A batch kernel that does not settle: sums and differences underflow nowhere and the kernel
// has no limit, so its loop leaves no pair to a scalar pass and is a template of whether the
// caller wants statuses (it stores them only then). 19 pairs, two blocks of 8 and a tail of 3,
// with a NaN, an infinity and an overflow among them: with statuses and without, the batch
// writes the scalar kernel's results bit for bit; s = u + w and d = u - w typed here (exact
// for these binary fractions); a refused pair is left as given.
BOOST_AUTO_TEST_CASE(a_batch_kernel_that_does_not_settle_writes_its_statuses_only_where_asked)
{
    const std::string text = "id = \"sums\"\ntitle = \"t\"\n"
                             "[[symbol]]\nname = \"u\"\ndimension = \"velocity\"\n"
                             "[[symbol]]\nname = \"w\"\ndimension = \"velocity\"\n"
                             "[[symbol]]\nname = \"s\"\ndimension = \"velocity\"\n"
                             "[[symbol]]\nname = \"d\"\ndimension = \"velocity\"\n"
                             "[[step]]\ndefine = \"s\"\nas = \"u + w\"\n[[step]]\ndefine = \"d\"\nas = \"u - w\"\n"
                             "[[result]]\nname = \"s\"\n[[result]]\nname = \"d\"\n"
                             "[[kernel]]\nname = \"sums\"\nbatch = true\ninputs = [\"u\", \"w\"]\n"
                             "outputs = [\"u = s\", \"w = d\"]\nguards = [\"non_finite = u, w\"]\n";
    const engine::library lib = engine::derive_all({spec::parse_derivation(text, "sums.toml")});
    std::vector<std::string> missed;
    const pipeline::file_set files = pipeline::generate_kernels(lib, &missed);
    BOOST_TEST(missed.empty(), (missed.empty() ? std::string() : missed.front()));
    const auto header = files.find("kernels/impact/sums.hpp");
    BOOST_TEST_REQUIRE((header != files.end()));
    // The template this test is for: a loop that settles has none.
    BOOST_TEST(header->second.find("template <class Real, bool with_status>") != std::string::npos);
    BOOST_TEST(header->second.find("_settle") == std::string::npos);
    const std::string program =
        "#include \"impact/sums.hpp\"\n#include <cstring>\n#include <limits>\n"
           "int main()\n{\n"
           "    const int n = 19;\n"
           "    double u[n], w[n], u2[n], w2[n];\n"
           "    impact::status status[n];\n"
           "    for (int i = 0; i < n; ++i) {\n"
           "        u[i] = i * 0.375 - 2;\n        w[i] = 1.5 - i * 0.125;\n"
           "    }\n"
           "    u[5] = std::numeric_limits<double>::quiet_NaN();\n"
           "    w[12] = std::numeric_limits<double>::infinity();\n"
           "    u[17] = w[17] = std::numeric_limits<double>::max();\n"
           "    double u0[n], w0[n];\n"
           "    std::memcpy(u0, u, sizeof u);\n    std::memcpy(w0, w, sizeof w);\n"
           "    std::memcpy(u2, u, sizeof u);\n    std::memcpy(w2, w, sizeof w);\n"
           "    impact::sums_batch_data<double, 0> with{}, without{};\n"
           "    with.count = without.count = n;\n"
           "    with.u = u;\n    with.w = w;\n    with.status = status;\n"
           "    without.u = u2;\n    without.w = w2;\n    without.status = nullptr;\n"
           "    impact::sums_batch(with);\n    impact::sums_batch(without);\n"
           "    int wrong = 0;\n"
           "    for (int i = 0; i < n; ++i) {\n"
           "        const auto one = impact::sums<double>(u0[i], w0[i]);\n"
           "        wrong += std::memcmp(&one.u, &u[i], sizeof(double)) != 0 || std::memcmp(&one.w, &w[i], sizeof(double)) != 0;\n"
           "        wrong += std::memcmp(&u2[i], &u[i], sizeof(double)) != 0 || std::memcmp(&w2[i], &w[i], sizeof(double)) != 0;\n"
           "        wrong += one.status != status[i];\n"
           "        const bool refused = i == 5 || i == 12 || i == 17;\n"
           "        const impact::status expected = i == 17 ? impact::status::out_of_range\n"
           "                                        : refused ? impact::status::non_finite : impact::status::ok;\n"
           "        wrong += status[i] != expected;\n"
           "        if (refused)\n"
           "            wrong += std::memcmp(&u0[i], &u[i], sizeof(double)) != 0 || std::memcmp(&w0[i], &w[i], sizeof(double)) != 0;\n"
           "        else\n"
           "            wrong += u[i] != u0[i] + w0[i] || w[i] != u0[i] - w0[i];\n"
           "    }\n"
           "    return wrong == 0 ? 0 : 1;\n}\n";
    for (const char* flags : {"-O2 -ffp-contract=off", "-O3 -march=native -ffp-contract=off"}) {
        const impact::testing::run_result r = compiled_and_run(files, program, flags);
        BOOST_TEST(r.status == 0, flags << ": " << r.output);
    }
}

// A batch whose outputs are not all named after inputs: the example of a puck pushed by a
// force (tests/examples/pushed_puck.toml), whose `push` updates v in place and writes dp (an
// array) and E_push (a scalar) into arrays of their own. 19 pairs, two blocks of 8 and a tail
// of 3, among them a pair refused by each guard: the batch writes the scalar kernel's results
// bit for bit, with and without statuses; a refused pair keeps its velocity and gets dp = 0 and
// E_push = 0. Pair 0 typed here: m = 2, t = 1, F = (1, 1/2), v = (1, 1): v' = v + F t/m =
// (3/2, 5/4), dp = F t = (1, 1/2), E_push = |F|^2 t^2/(2 m) = 5/16, exact in binary.
BOOST_AUTO_TEST_CASE(a_batch_writes_outputs_named_after_no_input_into_arrays_of_their_own)
{
    const engine::library lib =
        engine::derive_all({spec::read_derivation(IMPACT_SOURCE_DIR "/tests/examples/pushed_puck.toml")});
    std::vector<std::string> missed;
    const pipeline::file_set files = pipeline::generate_kernels(lib, &missed);
    BOOST_TEST(missed.empty(), (missed.empty() ? std::string() : missed.front()));
    const std::string program =
        "#include \"impact/pushed_puck.hpp\"\n#include <cstring>\n#include <limits>\n"
        "template <class Real>\nint wrong_pairs()\n{\n"
        "    const int n = 19;\n"
        "    Real m[n], t[n], Fx[n], Fy[n], vx[n], vy[n], vx2[n], vy2[n], dpx[n], dpy[n], E[n], dpx2[n], dpy2[n], E2[n];\n"
        "    impact::status status[n];\n"
        "    for (int i = 0; i < n; ++i) {\n"
        "        m[i] = Real(1) + Real(i) / 4;\n        t[i] = Real(1) / 2 + Real(i) / 8;\n"
        "        Fx[i] = Real(3) - Real(i) / 8;\n        Fy[i] = Real(i) / 16 - Real(1);\n"
        "        vx[i] = Real(2) + Real(i) / 32;\n        vy[i] = Real(i) / 4 - Real(3);\n"
        "        dpx[i] = dpy[i] = E[i] = dpx2[i] = dpy2[i] = E2[i] = Real(7);  // written over\n"
        "    }\n"
        "    m[0] = 2;\n    t[0] = 1;\n    Fx[0] = 1;\n    Fy[0] = Real(0.5);\n    vx[0] = 1;\n    vy[0] = 1;\n"
        "    m[3] = 0;                                                   // invalid_input\n"
        "    t[9] = -1;                                                  // invalid_input\n"
        "    vy[5] = std::numeric_limits<Real>::quiet_NaN();             // non_finite\n"
        "    Fx[11] = std::numeric_limits<Real>::infinity();             // non_finite\n"
        "    Fx[13] = -Fx[13];\n    Fy[13] = -Fy[13];                   // pulled back: F.v < 0\n"
        "    Fx[16] = 0;\n    Fy[16] = 0;                               // no force\n"
        "    Real vx0[n], vy0[n];\n"
        "    std::memcpy(vx0, vx, sizeof vx);\n    std::memcpy(vy0, vy, sizeof vy);\n"
        "    std::memcpy(vx2, vx, sizeof vx);\n    std::memcpy(vy2, vy, sizeof vy);\n"
        "    impact::push_batch_data<Real, 2> with{}, without{};\n"
        "    with.count = without.count = n;\n"
        "    with.m = without.m = m;\n    with.duration = without.duration = t;\n"
        "    with.F = without.F = {Fx, Fy};\n"
        "    with.v = {vx, vy};\n    with.dp = {dpx, dpy};\n    with.E_push = E;\n    with.status = status;\n"
        "    without.v = {vx2, vy2};\n    without.dp = {dpx2, dpy2};\n    without.E_push = E2;\n    without.status = nullptr;\n"
        "    impact::push_batch(with);\n    impact::push_batch(without);\n"
        "    auto same = [](Real a, Real b) { return std::memcmp(&a, &b, sizeof a) == 0; };\n"
        "    int wrong = 0;\n"
        "    for (int i = 0; i < n; ++i) {\n"
        "        const auto one = impact::push<Real>(m[i], t[i], {Fx[i], Fy[i]}, {vx0[i], vy0[i]});\n"
        "        wrong += !same(one.v[0], vx[i]) || !same(one.v[1], vy[i]) || !same(one.dp[0], dpx[i]) ||\n"
        "                 !same(one.dp[1], dpy[i]) || !same(one.E_push, E[i]) || one.status != status[i];\n"
        "        wrong += !same(vx2[i], vx[i]) || !same(vy2[i], vy[i]) || !same(dpx2[i], dpx[i]) ||\n"
        "                 !same(dpy2[i], dpy[i]) || !same(E2[i], E[i]);\n"
        "        const bool refused = i == 3 || i == 5 || i == 9 || i == 11 || i == 13 || i == 16;\n"
        "        const impact::status expected = i == 3 || i == 9 ? impact::status::invalid_input\n"
        "                                        : i == 5 || i == 11 ? impact::status::non_finite\n"
        "                                        : i == 13 ? impact::status::pulled_back\n"
        "                                        : i == 16 ? impact::status::no_force : impact::status::ok;\n"
        "        wrong += status[i] != expected;\n"
        "        if (refused)\n"
        "            wrong += !same(vx[i], vx0[i]) || !(vy[i] == vy0[i] || vy[i] != vy[i]) || dpx[i] != 0 ||\n"
        "                     dpy[i] != 0 || E[i] != 0;\n"
        "    }\n"
        "    wrong += vx[0] != Real(1.5) || vy[0] != Real(1.25) || dpx[0] != 1 || dpy[0] != Real(0.5) || E[0] != Real(0.3125);\n"
        "    return wrong;\n}\n"
        "int main()\n{\n    return wrong_pairs<double>() + wrong_pairs<float>() == 0 ? 0 : 1;\n}\n";
    for (const char* flags : {"-O2 -ffp-contract=off", "-O3 -march=native -ffp-contract=off"}) {
        const impact::testing::run_result r = compiled_and_run(files, program, flags);
        BOOST_TEST(r.status == 0, flags << ": " << r.output);
    }
}

BOOST_AUTO_TEST_CASE(a_name_the_kernels_cxx_declares_is_refused_where_the_file_gives_it)
{
    // An input named after a C++ keyword, the kernel's values (t0, t1, ...), its loop's
    // counters and its arrays (a name ending in _): each refused at its place, with the way out.
    const std::string refused_input = message_for(
        line_kernel("inputs = [\"M\", \"m\", \"new = u\", \"w\", \"eps\"]\noutputs = [\"u = u_after\", \"w = w_after\"]\n"));
    BOOST_TEST(refused_input.find("test.toml:39:21: error: input 'new' cannot be a name in the kernel's C++: it is a "
                                  "C++ keyword; name the input otherwise, e.g. inputs = [\"other = u\"]") !=
                   std::string::npos,
               refused_input);
    for (const char* name : {"t0", "count", "i", "Real", "m_", "_x"}) {
        const std::string text = line_kernel("inputs = [\"M\", \"m\", \"" + std::string(name) +
                                             " = u\", \"w\", \"eps\"]\noutputs = [\"u = u_after\", \"w = w_after\"]\n");
        const std::string message = message_for(text);
        BOOST_TEST(message.find("input '" + std::string(name) + "' cannot be a name in the kernel's C++") !=
                       std::string::npos,
                   message);
        BOOST_TEST(message.find("test.toml:39:21: error:") != std::string::npos, message);   // the input's place
    }
    const std::string refused_kernel = message_for(line_kernel(
        "inputs = [\"M\", \"m\", \"u\", \"w\", \"eps\"]\noutputs = [\"u = u_after\", \"w = w_after\"]\n").replace(
        line_kernel("").find("name = \"line\""), 13, "name = \"int\" "));
    BOOST_TEST(refused_kernel.find("kernel 'int' cannot be a name in the kernel's C++: it is a C++ keyword; give the "
                                   "kernel another name") != std::string::npos,
               refused_kernel);
}

BOOST_AUTO_TEST_CASE(at_special_values_a_case_that_does_not_arise_is_not_proven_against)
{
    const engine::derivation d = derive_text(by_cases(
        "cases = [{ when = \"x <= 1\", as = \"x\" }, { when = \"x > 1\", as = \"1\" }]",
        "[[check]]\nname = \"at two\"\nclaim = \"y = 1\"\nat = { x = \"2\" }\n"
        "[[check]]\nname = \"at a half\"\nclaim = \"y = 1\"\nat = { x = \"1/2\" }\n"));
    // min(2, 1) = 1: case 1 (y = 2) does not arise at x = 2, case 2 gives 1.
    const engine::check_result& two = check_named(d, "at two");
    BOOST_REQUIRE_EQUAL(two.parts.size(), 2u);
    BOOST_TEST(two.parts[0].outcome.method == "the case does not arise: its condition is false at these values");
    BOOST_TEST(proven(two.outcome));
    // min(1/2, 1) = 1/2, not 1: case 1 arises and fails.
    const engine::check_result& half = check_named(d, "at a half");
    BOOST_TEST((half.parts.at(0).outcome.what == engine::verdict::status::failed));
    BOOST_TEST(half.parts.at(1).outcome.method == "the case does not arise: its condition is false at these values");
    BOOST_TEST(!half.outcome.holds());
}

// Two quantities defined by cases with the same conditions are split on together: in each
// case both take that case's value.
BOOST_AUTO_TEST_CASE(a_check_splits_on_two_quantities_with_the_same_conditions)
{
    const engine::derivation d = derive_text(by_cases(
        "cases = [{ when = \"x <= 1\", as = \"x\" }, { when = \"x > 1\", as = \"1\" }]",
        "[[symbol]]\nname = \"z\"\n"
        "[[step]]\ndefine = \"z\"\ncases = [{ when = \"x <= 1\", as = \"1 - x\" }, { when = \"x > 1\", as = \"0\" }]\n"
        "[[check]]\nname = \"sum\"\nclaim = \"y + z = 1\"\n"));
    // x + (1 - x) = 1 where x <= 1, 1 + 0 = 1 where x > 1.
    const engine::check_result& c = check_named(d, "sum");
    BOOST_TEST(c.cases_of == "y and z");
    BOOST_REQUIRE_EQUAL(c.parts.size(), 2u);
    BOOST_TEST(c.parts[0].under.rfind("case 1 (y = x, z = 1-x, where x <= 1)", 0) == 0, c.parts[0].under);
    BOOST_TEST(proven(c.outcome));

    const std::string message = message_for(by_cases(
        "cases = [{ when = \"x <= 1\", as = \"x\" }, { when = \"x > 1\", as = \"1\" }]",
        "[[symbol]]\nname = \"z\"\n"
        "[[step]]\ndefine = \"z\"\ncases = [{ when = \"x <= 2\", as = \"1 - x\" }, { when = \"x > 2\", as = \"0\" }]\n"
        "[[check]]\nname = \"sum\"\nclaim = \"y + z = 1\"\n"));
    BOOST_TEST(message.find("both defined by cases with different conditions") != std::string::npos, message);
}

// |x| for a real x: the claim proven for x > 0, x < 0 and x = 0 apart. Clipping x to
// [-1, 1] by cases: |y| <= 1 in both cases, and in the second only through x/|x| = ±1.
BOOST_AUTO_TEST_CASE(absolute_values_are_proven_by_the_sign_of_what_is_under_them)
{
    const std::string text = "id = \"t\"\ntitle = \"t\"\n"
                             "[[symbol]]\nname = \"x\"\n"
                             "[[symbol]]\nname = \"y\"\n"
                             "[[step]]\ndefine = \"y\"\n"
                             "cases = [{ when = \"abs(x) <= 1\", as = \"x\" }, { when = \"abs(x) > 1\", as = \"x/abs(x)\" }]\n"
                             "[[result]]\nname = \"y\"\n"
                             "[[check]]\nname = \"clipped\"\nclaim = \"abs(y) <= 1\"\n"
                             "[[check]]\nname = \"same sign\"\nclaim = \"x*y >= 0\"\n";
    const engine::derivation d = derive_text(text);
    for (const std::string name : {"clipped", "same sign"}) {
        BOOST_TEST_CONTEXT(name)
        {
            const engine::check_result& c = check_named(d, name);
            BOOST_REQUIRE_EQUAL(c.parts.size(), 2u);
            BOOST_TEST(proven(c.parts[0].outcome), c.parts[0].outcome.method);
            BOOST_TEST(proven(c.parts[1].outcome), c.parts[1].outcome.method);
        }
    }
    const std::string& method = check_named(d, "clipped").parts[1].outcome.method;
    BOOST_TEST(method.find("for x > 0: proven") != std::string::npos, method);
    BOOST_TEST(method.find("for x < 0: proven") != std::string::npos, method);
    // At x = 0 the second case's condition, 0 > 1, is false.
    BOOST_TEST(method.find("for x = 0: proven (the case does not arise") != std::string::npos, method);

    // A false claim is never proven: |y| <= 1/2 fails where x = 3/4.
    const engine::derivation wrong = derive_text(text + "[[check]]\nname = \"too tight\"\nclaim = \"abs(y) <= 1/2\"\n");
    BOOST_TEST(!check_named(wrong, "too tight").outcome.holds());
}

// A claim G >= 0 under a condition C >= 0 that is neither a multiple of C nor C plus a
// term of known sign: G divided by C in the symbol C is linear in, G = q C + r with q and
// r >= 0. The tangential energy of a slipping contact, u (s - u/2) for an impulse u
// capped at (1 + b) s: (u/2)((1 + b) s - u) + (1 - b) u s / 2.
BOOST_AUTO_TEST_CASE(a_claim_is_divided_by_its_condition)
{
    const std::string text = "id = \"t\"\ntitle = \"t\"\n"
                             "[[symbol]]\nname = \"u\"\ndomain = \"positive\"\n"
                             "[[symbol]]\nname = \"s\"\ndomain = \"positive\"\n"
                             "[[symbol]]\nname = \"b\"\ndomain = \"[-1, 1]\"\n"
                             "[[symbol]]\nname = \"y\"\n"
                             "[[step]]\ndefine = \"y\"\n"
                             "cases = [{ when = \"u <= (1 + b)*s\", as = \"u\" }, { when = \"u > (1 + b)*s\", as = \"(1 + b)*s\" }]\n"
                             "[[result]]\nname = \"y\"\n"
                             "[[check]]\nname = \"energy lost\"\nclaim = \"y*(s - y/2) >= 0\"\n";
    const engine::derivation d = derive_text(text);
    const engine::check_result& c = check_named(d, "energy lost");
    BOOST_REQUIRE_EQUAL(c.parts.size(), 2u);
    BOOST_TEST(proven(c.parts[0].outcome), c.parts[0].outcome.method);
    BOOST_TEST(c.parts[0].outcome.method.find("divided by the condition's side in ") != std::string::npos,
               c.parts[0].outcome.method);
    BOOST_TEST(proven(c.parts[1].outcome), c.parts[1].outcome.method);
    // Without the cap the claim is false (u = 3 s): case 1 then fails.
    const engine::derivation uncapped = derive_text(text + "[[check]]\nname = \"uncapped\"\nclaim = \"u*(s - u/2) >= 0\"\n");
    BOOST_TEST(!check_named(uncapped, "uncapped").outcome.holds());
}

// An inequality whose difference a check has already written in closed form is proven
// through that check, as a textbook argues "by (n)".
BOOST_AUTO_TEST_CASE(an_inequality_is_proven_through_an_identity_proven_before_it)
{
    const engine::derivation d = derive_text(
        "id = \"t\"\ntitle = \"t\"\n"
        "[[symbol]]\nname = \"x\"\n[[symbol]]\nname = \"z\"\n[[symbol]]\nname = \"k\"\ndomain = \"positive\"\n"
        "[[symbol]]\nname = \"d\"\n"
        "[[step]]\ndefine = \"d\"\nas = \"k*x^2 + k*z^2 - 2*k*x*z\"\n"
        "[[result]]\nname = \"d\"\n"
        "[[check]]\nname = \"a square\"\nclaim = \"d = k*(x - z)^2\"\n"
        "[[check]]\nname = \"never negative\"\nclaim = \"d >= 0\"\n");
    const engine::check_result& c = check_named(d, "never negative");
    BOOST_TEST(proven(c.outcome));
    BOOST_TEST(c.outcome.method.rfind("by the check 'a square' the difference of the sides is k*(x-z)^2", 0) == 0,
               c.outcome.method);
}

// At a special value a case's condition may contradict the domains (0 > k for k >= 0 at
// b = -1); the case does not arise, and its value there (k/(1 + b)) is never formed.
BOOST_AUTO_TEST_CASE(a_case_the_domains_rule_out_at_a_special_value_holds_nothing)
{
    const engine::derivation d = derive_text(
        "id = \"t\"\ntitle = \"t\"\n"
        "[[symbol]]\nname = \"x\"\ndomain = \"positive\"\n"
        "[[symbol]]\nname = \"k\"\ndomain = \"nonnegative\"\n"
        "[[symbol]]\nname = \"b\"\ndomain = \"[-1, 1]\"\n"
        "[[symbol]]\nname = \"y\"\n"
        "[[step]]\ndefine = \"y\"\n"
        "cases = [{ when = \"(1 + b)*x <= k\", as = \"(1 + b)*x\" }, { when = \"(1 + b)*x > k\", as = \"k/(1 + b)\" }]\n"
        "[[result]]\nname = \"y\"\n"
        "[[check]]\nname = \"smooth\"\nclaim = \"y = 0\"\nat = { b = \"-1\" }\n");
    const engine::check_result& c = check_named(d, "smooth");
    BOOST_REQUIRE_EQUAL(c.parts.size(), 2u);
    BOOST_TEST(proven(c.parts[0].outcome));
    BOOST_TEST(c.parts[1].outcome.method == "the case does not arise: the domains make its condition false");
    BOOST_TEST(proven(c.outcome));
}

// An abbreviation declared with a domain is an assumption the proofs may use: s = u - w,
// declared positive (the spheres approach), rules out the case 0 > k s at b = -1, and is
// listed with its domain. Without the declaration the case is not ruled out.
BOOST_AUTO_TEST_CASE(an_abbreviation_declared_positive_is_an_assumption_the_cases_use)
{
    const auto text = [](const std::string& s_domain) {
        return "id = \"t\"\ntitle = \"t\"\n"
               "[[symbol]]\nname = \"u\"\n[[symbol]]\nname = \"w\"\n"
               "[[symbol]]\nname = \"x\"\ndomain = \"positive\"\n"
               "[[symbol]]\nname = \"k\"\ndomain = \"nonnegative\"\n"
               "[[symbol]]\nname = \"b\"\ndomain = \"[-1, 1]\"\n"
               "[[symbol]]\nname = \"s\"\n" + s_domain + "definition = \"u - w\"\n"
               "[[symbol]]\nname = \"y\"\n"
               "[[step]]\ndefine = \"y\"\n"
               "cases = [{ when = \"(1 + b)*x <= k*s\", as = \"(1 + b)*x\" }, "
               "{ when = \"(1 + b)*x > k*s\", as = \"k*s/(1 + b)\" }]\n"
               "[[result]]\nname = \"y\"\n"
               "[[check]]\nname = \"smooth\"\nclaim = \"y = 0\"\nat = { b = \"-1\" }\n";
    };
    const engine::derivation d = derive_text(text("domain = \"positive\"\n"));
    const engine::check_result& c = check_named(d, "smooth");
    BOOST_REQUIRE_EQUAL(c.parts.size(), 2u);
    BOOST_TEST(c.parts[1].outcome.method == "the case does not arise: the domains make its condition false");
    BOOST_TEST(proven(c.outcome));
    BOOST_TEST(emit::latex_fragment(d).find("\\item $s = u - w$, $s > 0$") != std::string::npos);

    const engine::derivation undeclared = derive_text(text(""));
    BOOST_TEST(!check_named(undeclared, "smooth").outcome.holds());
}

// A limit case by case leaves out a case whose condition fails near the point: sliding,
// mu k < (1 + b) x, as mu -> infinity, where its value mu k grows without bound.
BOOST_AUTO_TEST_CASE(a_case_whose_condition_fails_near_the_limit_is_left_out)
{
    const engine::derivation d = derive_text(
        "id = \"t\"\ntitle = \"t\"\n"
        "[[symbol]]\nname = \"x\"\ndomain = \"positive\"\n"
        "[[symbol]]\nname = \"k\"\ndomain = \"positive\"\n"
        "[[symbol]]\nname = \"b\"\ndomain = \"[-1, 1]\"\n"
        "[[symbol]]\nname = \"mu\"\ndomain = \"[0, +inf]\"\n"
        "[[symbol]]\nname = \"y\"\n"
        "[[step]]\ndefine = \"y\"\n"
        "cases = [{ when = \"(1 + b)*x <= mu*k\", as = \"(1 + b)*x\" }, "
        "{ when = \"(1 + b)*x > mu*k\", as = \"mu*k\" }]\n"
        "[[result]]\nname = \"y\"\n"
        "[[check]]\nname = \"sticks\"\nclaim = \"y = 2*x\"\nat = { b = \"1\" }\nlimit = \"mu -> infinity\"\n");
    const engine::check_result& c = check_named(d, "sticks");
    BOOST_REQUIRE_EQUAL(c.parts.size(), 2u);
    BOOST_TEST(proven(c.parts[0].outcome), c.parts[0].outcome.method);
    BOOST_TEST(c.parts[1].outcome.method.rfind("the case does not arise near the limit mu -> infinity", 0) == 0,
               c.parts[1].outcome.method);
    BOOST_TEST(proven(c.outcome));
}

// A square root that is an abbreviation (G = sqrt(x^2 + z^2)) is a quantity of its own in a
// proof under a case's condition: G >= 0, its radicand never expanded.
BOOST_AUTO_TEST_CASE(a_root_that_is_an_abbreviation_is_a_quantity_of_its_own_under_a_condition)
{
    const engine::derivation d = derive_text(
        "id = \"t\"\ntitle = \"t\"\n"
        "[[symbol]]\nname = \"x\"\n[[symbol]]\nname = \"z\"\n"
        "[[symbol]]\nname = \"k\"\ndomain = \"positive\"\n"
        "[[symbol]]\nname = \"b\"\ndomain = \"[-1, 1]\"\n"
        "[[symbol]]\nname = \"mu\"\ndomain = \"[0, +inf]\"\n"
        "[[symbol]]\nname = \"G\"\ndefinition = \"sqrt(x^2 + z^2)\"\n"
        "[[symbol]]\nname = \"y\"\n"
        "[[step]]\ndefine = \"y\"\n"
        "cases = [{ when = \"(1 + b)*G <= mu*k\", as = \"(1 + b)*G\" }, "
        "{ when = \"(1 + b)*G > mu*k\", as = \"mu*k\" }]\n"
        "[[result]]\nname = \"y\"\n"
        "[[check]]\nname = \"cone\"\nclaim = \"y <= mu*k\"\n"
        "[[check]]\nname = \"loss\"\nclaim = \"y*(G - y/2) >= 0\"\n");
    for (const char* name : {"cone", "loss"}) {
        const engine::check_result& c = check_named(d, name);
        BOOST_TEST(proven(c.outcome), name << ": " << c.outcome.method);
    }
    const engine::check_result& loss = check_named(d, "loss");
    BOOST_REQUIRE_EQUAL(loss.parts.size(), 2u);
    BOOST_TEST(loss.parts[1].outcome.method.find("with the square roots that are abbreviations as quantities of "
                                                 "their own (G >= 0)") != std::string::npos,
               loss.parts[1].outcome.method);
}

// G = q C proves nothing where q's denominator vanishes: with C = mu x and q = 1/mu the
// case's claim y >= 0 is proven otherwise (by the signs of y = x), never as 1/mu times C.
BOOST_AUTO_TEST_CASE(a_factor_that_divides_by_zero_is_no_argument)
{
    const engine::derivation d = derive_text(
        "id = \"t\"\ntitle = \"t\"\n"
        "[[symbol]]\nname = \"x\"\ndomain = \"positive\"\n"
        "[[symbol]]\nname = \"mu\"\ndomain = \"nonnegative\"\n"
        "[[symbol]]\nname = \"y\"\n"
        "[[step]]\ndefine = \"y\"\n"
        "cases = [{ when = \"0 <= mu*x\", as = \"x\" }, { when = \"0 > mu*x\", as = \"-x\" }]\n"
        "[[result]]\nname = \"y\"\n"
        "[[check]]\nname = \"positive\"\nclaim = \"y >= 0\"\n");
    const engine::check_result& c = check_named(d, "positive");
    BOOST_REQUIRE(!c.parts.empty());
    BOOST_TEST(proven(c.parts[0].outcome), c.parts[0].outcome.method);
    BOOST_TEST(c.parts[0].outcome.method.find("times the condition's") == std::string::npos,
               c.parts[0].outcome.method);
}

// A declared domain is an assumption only where the definition's own sign does not refute
// it: k = b - 2 with b in [-1, 1] is negative, and declaring it positive is an error (the
// definition is not checked under the assumption it makes). A root of a radicand that may
// be negative is never a quantity of its own: w = sqrt(x - z) would make x - z a square.
BOOST_AUTO_TEST_CASE(an_assumption_never_proves_its_own_definition)
{
    const std::string refuted = "id = \"t\"\ntitle = \"t\"\n"
                                "[[symbol]]\nname = \"b\"\ndomain = \"[-1, 1]\"\n"
                                "[[symbol]]\nname = \"k\"\ndomain = \"positive\"\ndefinition = \"b - 2\"\n"
                                "[[symbol]]\nname = \"y\"\n[[step]]\ndefine = \"y\"\nas = \"k\"\n"
                                "[[result]]\nname = \"y\"\n";
    BOOST_TEST(message_for(refuted).find("'k' is declared positive but its definition") != std::string::npos,
               message_for(refuted));

    const engine::derivation d = derive_text(
        "id = \"t\"\ntitle = \"t\"\n"
        "[[symbol]]\nname = \"x\"\n[[symbol]]\nname = \"z\"\n"
        "[[symbol]]\nname = \"k\"\ndomain = \"positive\"\n"
        "[[symbol]]\nname = \"mu\"\ndomain = \"nonnegative\"\n"
        "[[symbol]]\nname = \"w\"\ndefinition = \"sqrt(x - z)\"\n"
        "[[symbol]]\nname = \"y\"\n"
        "[[step]]\ndefine = \"y\"\n"
        "cases = [{ when = \"k <= mu\", as = \"k\" }, { when = \"k > mu\", as = \"mu\" }]\n"
        "[[result]]\nname = \"y\"\n"
        "[[check]]\nname = \"not a square\"\nclaim = \"y*(x - z) >= 0\"\n");
    BOOST_TEST(!check_named(d, "not a square").outcome.holds());
}
