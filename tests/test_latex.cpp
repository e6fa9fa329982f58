// The LaTeX printer: results written as a textbook writes them, exact strings.
//
// Every expected string below is typed from how the paper (or a textbook) sets the
// formula, not read back from the printer.
#define BOOST_TEST_MODULE test_latex
#include <boost/test/unit_test.hpp>

#include "derivation_support.h"
#include "emit/errata.h"
#include "emit/latex.h"
#include "emit/latex_parts.h"
#include "engine/expr/derivative.h"
#include "engine/expr/written_form.h"
#include "engine/library/library.h"
#include "spec/derivation.h"

#include <fmt/format.h>

#include <map>
#include <string>

using namespace impact;

namespace {

// The symbols of Eq. 8 with the paper's names, ranked as Eq. 8's file declares them.
struct eq8_symbols {
    GiNaC::possymbol M{"M", "M"}, m{"m", "m"};
    GiNaC::realsymbol vM{"v_M", "v_{M,\\parallel}"}, vm{"v_m", "v_{m,\\parallel}"}, eps{"eps", "\\epsilon"};
    GiNaC::realsymbol vMp{"v_M_after", "v'_{M,\\parallel}"}, vmp{"v_m_after", "v'_{m,\\parallel}"};
    GiNaC::realsymbol J{"J", "J"}, m_eff{"m_eff", "m_{\\mathrm{eff}}"};
    GiNaC::possymbol vpar{"v_1par", "v_{1,\\parallel}"}, vperp{"v_1perp", "v_{1,\\perp}"};
    GiNaC::realsymbol cos_theta{"cos_theta", "\\cos\\theta"};
    engine::term_order order{{M, m, vM, vm, eps, vMp, vmp, J, m_eff, vpar, vperp, cos_theta}};

    GiNaC::ex parse(const std::string& text) const
    {
        GiNaC::symtab table;
        for (const GiNaC::ex& s : GiNaC::lst{M, m, vM, vm, eps, vMp, vmp, J, m_eff, vpar, vperp, cos_theta})
            table[GiNaC::ex_to<GiNaC::symbol>(s).get_name()] = s;
        GiNaC::parser reader(table, true);
        return reader(text);
    }

    // The expression as its text gives it, printed as written.
    std::string as_written(const std::string& text) const
    {
        const engine::written_form w =
            engine::written_form::read(text, [this](const std::string& t) { return parse(t); });
        return emit::latex(parse(text), order, &w);
    }
};

// Each derivation of derivations/ with those it uses, derived when first asked for: the
// folder's slower proofs (the rough spheres') are not needed by every test.
const engine::derivation& derived(const std::string& id)
{
    static const std::vector<spec::derivation> sources = engine::read_directory(IMPACT_SOURCE_DIR "/derivations");
    static std::map<std::string, engine::library> by_id;
    auto found = by_id.find(id);
    if (found == by_id.end())
        found = by_id.emplace(id, engine::derive_all(sources, id)).first;
    return found->second.derived.at(id);
}

bool contains(const std::string& text, const std::string& part)
{
    return text.find(part) != std::string::npos;
}

} // namespace

BOOST_FIXTURE_TEST_SUITE(display_forms, eq8_symbols)

BOOST_AUTO_TEST_CASE(a_form_as_written_keeps_every_term_the_text_has)
{
    // GiNaC merges m v + m v into 2 m v and cancels m ε v - m ε v; as written, nothing is.
    const std::string text = "(M*v_M + M*v_M + M*eps*v_M - M*eps*v_M)/(2*(M + m))";
    const engine::written_form w = engine::written_form::read(text, [this](const std::string& t) { return parse(t); });
    BOOST_TEST_REQUIRE(w.tree().has_value());
    BOOST_TEST(emit::latex_as_written(*w.tree(), order) ==
               "\\frac{M v_{M,\\parallel} + M v_{M,\\parallel} + M \\epsilon v_{M,\\parallel} - M \\epsilon v_{M,\\parallel}}"
               "{2 (M + m)}");
    BOOST_TEST(emit::latex(parse(text), order, &w) == "\\frac{M v_{M,\\parallel}}{M + m}");
    // ½ in front of a product, a power of a primed symbol, an equation.
    const engine::written_form e = engine::written_form::read(
        "1/2*M*v_M_after^2 = -m_eff^(-1)*(1 + eps)", [this](const std::string& t) { return parse(t); });
    BOOST_TEST(emit::latex_as_written(*e.tree(), order) ==
               "\\frac{1}{2} M v'^{2}_{M,\\parallel} = -m^{-1}_{\\mathrm{eff}} (1 + \\epsilon)");
    // A sum after a quotient keeps its parentheses: Carnot's theorem, (1 - ε)/(1 + ε) times
    // the whole of the kinetic energy of the changes, and ½ times a sum.
    const auto written = [this](const std::string& text) {
        return emit::latex_as_written(
            *engine::written_form::read(text, [this](const std::string& t) { return parse(t); }).tree(), order);
    };
    BOOST_TEST(written("(1 - eps)/(1 + eps)*(1/2*M*v_M^2 + 1/2*m*v_m^2)") ==
               "\\frac{1 - \\epsilon}{1 + \\epsilon} \\left(\\frac{1}{2} M v^{2}_{M,\\parallel} + \\frac{1}{2} m v^{2}_{m,\\parallel}\\right)");
    BOOST_TEST(written("1/2*(1 - eps)") == "\\frac{1}{2} (1 - \\epsilon)");
    BOOST_TEST(written("1/M*(v_M - v_m)") == "\\frac{1}{M} (v_{M,\\parallel} - v_{m,\\parallel})");
}

BOOST_AUTO_TEST_CASE(eq8_is_printed_in_the_order_its_display_form_gives)
{
    // Eq. 8 as the paper prints it: ε m (v_m − v_M), not m ε (v_M − v_m) with a minus.
    BOOST_TEST(as_written("(M*v_M + m*v_m + eps*m*(v_m - v_M))/(M + m)") ==
               "\\frac{M v_{M,\\parallel} + m v_{m,\\parallel} + \\epsilon m (v_{m,\\parallel} - v_{M,\\parallel})}"
               "{M + m}");
    BOOST_TEST(as_written("(1 + eps)*M*m*(v_M - v_m)/(M + m)") ==
               "\\frac{(1 + \\epsilon) M m (v_{M,\\parallel} - v_{m,\\parallel})}{M + m}");
}

BOOST_AUTO_TEST_CASE(a_sign_gi_nac_moves_into_a_sum_comes_back_out)
{
    // GiNaC stores -(1 - eps^2)*x as (-1 + eps^2)*x; the text says -(1 - ε²).
    BOOST_TEST(as_written("-(1 - eps^2)*M*m*(v_m - v_M)^2/(2*(M + m))") ==
               "-\\frac{(1 - \\epsilon^{2}) M m (v_{m,\\parallel} - v_{M,\\parallel})^{2}}{2 (M + m)}");
    BOOST_TEST(as_written("-(v_M - v_m)") == "-(v_{M,\\parallel} - v_{m,\\parallel})");
}

BOOST_AUTO_TEST_CASE(a_written_half_stays_a_half_in_front)
{
    // Appendix A: ½ m v'²_m + ½ M v'²_M, with the primes sharing the superscript.
    BOOST_TEST(as_written("1/2*m*v_m_after^2 + 1/2*M*v_M_after^2") ==
               "\\frac{1}{2} m v'^{2}_{m,\\parallel} + \\frac{1}{2} M v'^{2}_{M,\\parallel}");
    // Written as a quotient it is a quotient, and 1/(2m) is not ½ · 1/m.
    BOOST_TEST(as_written("m*v_m_after^2/2") == "\\frac{m v'^{2}_{m,\\parallel}}{2}");
    BOOST_TEST(as_written("(v_m - v_M)*J + (1/(2*m) + 1/(2*M))*J^2") ==
               "(v_{m,\\parallel} - v_{M,\\parallel}) J + \\left(\\frac{1}{2 m} + \\frac{1}{2 M}\\right) J^{2}");
    // A half carried into a quotient's numerator keeps the parentheses of the sum it
    // multiplies: ½ (M + m)/(m M), never (½ M + m)/(m M) (Appendix A, line 6).
    auto tree_of = [this](const std::string& text) {
        const engine::written_form w =
            engine::written_form::read(text, [this](const std::string& t) { return parse(t); });
        return emit::latex_as_written(*w.tree(), order);
    };
    BOOST_TEST(tree_of("1/(2*m) + 1/(2*M) = 1/2*(M + m)/(m*M)") ==
               "\\frac{1}{2 m} + \\frac{1}{2 M} = \\frac{\\frac{1}{2} (M + m)}{m M}");
    BOOST_TEST(tree_of("1/2*(1 - eps)/M") == "\\frac{\\frac{1}{2} (1 - \\epsilon)}{M}");
    BOOST_TEST(tree_of("1/2*M*(1 - eps)/m") == "\\frac{\\frac{1}{2} M (1 - \\epsilon)}{m}");
    BOOST_TEST(as_written("1/2*(M + m)/(m*M)") == "\\frac{1}{2} \\frac{M + m}{m M}");
}

BOOST_AUTO_TEST_CASE(a_power_written_as_a_power_is_not_turned_into_a_fraction)
{
    // The paper's Eq. 8 for J: -m_eff^{-1}(1 + ε)(v_m − v_M).
    BOOST_TEST(as_written("-m_eff^(-1)*(1 + eps)*(v_m - v_M)") ==
               "-m^{-1}_{\\mathrm{eff}} (1 + \\epsilon) (v_{m,\\parallel} - v_{M,\\parallel})");
}

BOOST_AUTO_TEST_CASE(eq14_roots_and_subscripts)
{
    BOOST_TEST(as_written("(1 - eps)*v_1par/sqrt((1 - eps)^2*v_1par^2 + 4*v_1perp^2)") ==
               "\\frac{(1 - \\epsilon) v_{1,\\parallel}}{\\sqrt{(1 - \\epsilon)^{2} v^{2}_{1,\\parallel} + "
               "4 v^{2}_{1,\\perp}}}");
}

BOOST_AUTO_TEST_CASE(tall_contents_get_sized_parentheses_and_flat_ones_plain)
{
    BOOST_TEST(as_written("(1/M + 1/m)*J") == "\\left(\\frac{1}{M} + \\frac{1}{m}\\right) J");
    BOOST_TEST(as_written("(M + m)*J") == "(M + m) J");
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_FIXTURE_TEST_SUITE(without_a_written_form, eq8_symbols)

BOOST_AUTO_TEST_CASE(no_minus_one_plus_epsilon_artefacts)
{
    // A sum inside a product leads with a positive constant: (1 − ε), never (−1 + ε).
    BOOST_TEST(emit::latex((eps - 1) * M, order) == "-M (1 - \\epsilon)");
    BOOST_TEST(emit::latex(GiNaC::pow(eps - 1, 2), order) == "(1 - \\epsilon)^{2}");
    BOOST_TEST(emit::latex(eps - 1, order) == "\\epsilon - 1");
}

BOOST_AUTO_TEST_CASE(no_one_half_times_artefacts)
{
    BOOST_TEST(emit::latex(GiNaC::numeric(1, 2) * M * vM * vM, order) == "\\frac{M v^{2}_{M,\\parallel}}{2}");
    BOOST_TEST(emit::latex(GiNaC::numeric(-1, 2) * M * (1 - eps * eps), order) == "-\\frac{M (1 - \\epsilon^{2})}{2}");
}

BOOST_AUTO_TEST_CASE(primes_greek_letters_and_functions)
{
    BOOST_TEST(emit::latex(GiNaC::pow(vMp, 2), order) == "v'^{2}_{M,\\parallel}");
    BOOST_TEST(emit::latex(GiNaC::pow(cos_theta, 2), order) == "\\cos^{2}\\theta");
    BOOST_TEST(emit::latex(GiNaC::acos(cos_theta), order) == "\\arccos(\\cos\\theta)");
    BOOST_TEST(emit::latex(GiNaC::acos(vperp / vpar), order) == "\\arccos\\left(\\frac{v_{1,\\perp}}{v_{1,\\parallel}}\\right)");
    BOOST_TEST(emit::latex(GiNaC::pow(m_eff, -1), order) == "\\frac{1}{m_{\\mathrm{eff}}}");
}

BOOST_AUTO_TEST_CASE(a_derivative_is_typeset_as_a_partial_derivative)
{
    // diff(f, x) of a derivation file, held as written (engine/expr/derivative.h): a quantity's
    // name over the variable, anything else after the operator in parentheses.
    BOOST_TEST(emit::latex(engine::derivative(cos_theta, eps), order) == "\\frac{\\partial \\cos\\theta}{\\partial \\epsilon}");
    BOOST_TEST(emit::latex(engine::derivative(vperp / vpar, vpar), order) ==
               "\\frac{\\partial}{\\partial v_{1,\\parallel}} \\left(\\frac{v_{1,\\perp}}{v_{1,\\parallel}}\\right)");
    BOOST_TEST(as_written("diff(cos_theta, eps)") == "\\frac{\\partial \\cos\\theta}{\\partial \\epsilon}");
    const auto written = [this](const std::string& text) {
        return emit::latex_as_written(
            *engine::written_form::read(text, [this](const std::string& t) { return parse(t); }).tree(), order);
    };
    BOOST_TEST(written("diff(M*v_M + m*v_m, eps) = 0") ==
               "\\frac{\\partial}{\\partial \\epsilon} (M v_{M,\\parallel} + m v_{m,\\parallel}) = 0");
}

BOOST_AUTO_TEST_CASE(cosine_sine_and_tangent_of_a_symbol_as_a_textbook_writes_them)
{
    const GiNaC::realsymbol theta("theta", "\\theta"), x("x"), dE("dE", "\\Delta E_K");
    const engine::term_order by{{theta, x, dE}};
    BOOST_TEST(emit::latex(GiNaC::cos(theta), by) == "\\cos\\theta");
    BOOST_TEST(emit::latex(GiNaC::sin(x), by) == "\\sin x");
    BOOST_TEST(emit::latex(GiNaC::pow(GiNaC::tan(theta), 2), by) == "\\tan^{2}\\theta");
    // A symbol named in two words keeps its parentheses, and so does anything but a symbol.
    BOOST_TEST(emit::latex(GiNaC::cos(dE), by) == "\\cos(\\Delta E_K)");
    BOOST_TEST(emit::latex(GiNaC::cos(2 * theta), by) == "\\cos(2 \\theta)");
}

BOOST_AUTO_TEST_CASE(no_parentheses_where_precedence_does_not_need_them)
{
    BOOST_TEST(emit::latex(vM - J / M, order) == "v_{M,\\parallel} - \\frac{J}{M}");
    BOOST_TEST(emit::latex(M * vM + m * vm, order) == "M v_{M,\\parallel} + m v_{m,\\parallel}");
    BOOST_TEST(emit::latex(-J, order) == "-J");
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_FIXTURE_TEST_SUITE(line_breaking, eq8_symbols)

BOOST_AUTO_TEST_CASE(a_short_expression_stays_on_one_line)
{
    const auto lines = emit::latex_lines(M * vM + m * vm, order, nullptr, 300);
    BOOST_TEST(lines.size() == 1u);
}

BOOST_AUTO_TEST_CASE(a_long_sum_breaks_before_a_term_and_every_line_fits)
{
    GiNaC::ex sum = 0;
    for (const GiNaC::ex& a : GiNaC::lst{M, m, J})
        for (const GiNaC::ex& b : GiNaC::lst{vM, vm, vMp, vmp})
            sum += a * b;
    const auto lines = emit::latex_lines(sum, order, nullptr, 150);
    BOOST_TEST(lines.size() > 1u);
    for (std::size_t i = 0; i < lines.size(); ++i) {
        BOOST_TEST(emit::latex_width(lines[i]) <= 150.0, lines[i]);
        if (i > 0)
            BOOST_TEST((lines[i].rfind("+ ", 0) == 0 || lines[i].rfind("- ", 0) == 0), lines[i]);
    }
}

BOOST_AUTO_TEST_CASE(a_long_product_breaks_inside_its_widest_sum_in_big_parentheses)
{
    GiNaC::ex sum = 0;
    for (const GiNaC::ex& a : GiNaC::lst{M, m, J})
        for (const GiNaC::ex& b : GiNaC::lst{vM, vm, vMp})
            sum += a * b;
    const auto lines = emit::latex_lines(eps * sum / (M + m), order, nullptr, 150);
    BOOST_TEST_REQUIRE(lines.size() > 1u);
    BOOST_TEST(lines.front().rfind("\\frac{\\epsilon}{M + m} \\Bigl(", 0) == 0, lines.front());
    BOOST_TEST(lines.back().substr(lines.back().size() - 6) == "\\Bigr)");
}

BOOST_AUTO_TEST_CASE(widths_count_the_wider_part_of_a_fraction)
{
    BOOST_TEST(emit::latex_width("\\frac{a}{b}") < emit::latex_width("ab"));
    BOOST_TEST(emit::latex_width("\\frac{abcdef}{b}") > emit::latex_width("abcde"));
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(fragments)

BOOST_AUTO_TEST_CASE(special_values_the_reason_states_are_said_once)
{
    // Eq. 11's check at eps = 0, whose reason opens "at eps = 0": said once, by the reason.
    const std::string tex = emit::latex_fragment(derived("energy_loss"));
    BOOST_TEST(!contains(tex, "At $\\epsilon = 0$. At $\\epsilon = 0$"));
    BOOST_TEST(contains(tex, "At $\\epsilon = 0$ all the kinetic energy of the relative motion is lost."));
    // A reason that does not say them keeps them with the claim.
    const std::string bounce = emit::latex_fragment(derived("inelastic_line"));
    BOOST_TEST(contains(bounce, " at $\\epsilon = "), bounce);
}

BOOST_AUTO_TEST_CASE(eq8_fragment_is_a_derivation_with_the_papers_numbers)
{
    const std::string tex = emit::latex_fragment(derived("inelastic_line"));
    // Givens with their justifications, numbered and labelled for the steps.
    // (prose from the file, its $...$ mathematics kept as mathematics)
    BOOST_TEST(contains(tex, "The impulse $J$ changes the momentum of $M$ by $-J$ (Eq.~(6)):\n\\begin{align}"));
    BOOST_TEST(contains(tex, "\\tag{G1}\\label{impact:inelastic_line:impulse_M}"));
    // The step refers to the equations it solves.
    BOOST_TEST(contains(tex, "Solving \\eqref{impact:inelastic_line:impulse_M}, "
                             "\\eqref{impact:inelastic_line:impulse_m} and "
                             "\\eqref{impact:inelastic_line:restitution} for"));
    // The results in their display forms, numbered by the lines of Eq. 8 that print them.
    BOOST_TEST(contains(tex, "v'_{M,\\parallel} &= \\frac{M v_{M,\\parallel} + m v_{m,\\parallel} + \\epsilon m "
                             "(v_{m,\\parallel} - v_{M,\\parallel})}{M + m} \\tag*{Eq.~(8), right, first line}"));
    BOOST_TEST(contains(tex, "J &= \\frac{(1 + \\epsilon) M m (v_{M,\\parallel} - v_{m,\\parallel})}{M + m} \\tag*{Eq.~(8), right, third line}"));
    // Checks with status; the paper's Eq. 7 found wanting.
    BOOST_TEST(contains(tex, "\\item\\label{impact:inelastic_line:check:momentum_conserved} \\textbf{proven} --- "
                             "Momentum conserved: $M v_{M,\\parallel} + m v_{m,\\parallel} "
                             "= M v'_{M,\\parallel} + m v'_{m,\\parallel}$."));
    // Eq. 7 as the paper prints it, in its own symbols, then as read, its parentheses kept:
    // (v_M - v_m) = -eps(v_M - v_m).
    BOOST_TEST(contains(tex, "Eq.~(7), restitution (equation): printed $(v_M - v_m) = -\\epsilon(v_M - v_m)$, read as "
                             "$(v_{M,\\parallel} - v_{m,\\parallel}) = -\\epsilon (v_{M,\\parallel} - v_{m,\\parallel})$ --- "
                             "\\textbf{disagrees}"));
    BOOST_TEST(contains(tex, "smallest change: on the left, the primes missing."));
}

BOOST_AUTO_TEST_CASE(printed_forms_are_shown_as_the_paper_prints_them)
{
    // Eq. 12, line 2, typed from the paper: its denominator mv + mεv + mv − mεv, which
    // GiNaC would merge into 2mv.
    const std::string eq12 = emit::latex_fragment(derived("billiard_transfer"));
    BOOST_TEST(contains(eq12, "Eq.~(12), second line, $\\tau$: printed $\\frac{m v_{1,\\parallel} + m \\epsilon v_{1,\\parallel}}"
                              "{m v_{1,\\parallel} + m \\epsilon v_{1,\\parallel} + m v_{1,\\parallel} - m \\epsilon v_{1,\\parallel}}$"));
    // Eq. 14, line 2, first member: ½(1 − ε)v∥ over ½√(((1 − ε)v∥)² + 4v⊥²), the halves kept.
    const std::string eq14 = emit::latex_fragment(derived("scatter_angle"));
    BOOST_TEST(contains(eq14, "\\frac{\\frac{1}{2} (1 - \\epsilon) v_{1,\\parallel}}{\\frac{1}{2} "
                              "\\sqrt{((1 - \\epsilon) v_{1,\\parallel})^{2} + 4 v^{2}_{1,\\perp}}}"));
    // The errata table shows the same printed forms.
    std::vector<const engine::derivation*> all = {&derived("billiard_transfer")};
    BOOST_TEST(contains(emit::latex_errata(all).rows,
                        "{m v_{1,\\parallel} + m \\epsilon v_{1,\\parallel} + m v_{1,\\parallel} - m \\epsilon v_{1,\\parallel}}"));
}

BOOST_AUTO_TEST_CASE(a_line_read_in_other_terms_is_shown_in_the_papers_own_text_first)
{
    // Eq. 4's second line prints v_M^(L)' = R^T v_M^(C)'; the file reads its rows, one
    // component each. The paper's text comes first, then the row as read (typed from the
    // paper: the first row of R^T is (r_x/|r|, -r_y/|r|)).
    const std::string tex = emit::latex_fragment(derived("elastic_plane"));
    BOOST_TEST(contains(tex, "Eq.~(4), second line, $v'_{M,x}$: printed $v_M^{(L)\\prime} = \\mathbf{R}^T "
                             "\\mathbf{v}_M^{(C)\\prime}$, read as"));
    BOOST_TEST(contains(tex, "\\frac{r_{mM,x}}{\\|r_{mM}\\|} \\frac{(M - m) v_{M,\\parallel} + 2 m v_{m,\\parallel}}{M + m} - "
                             "\\frac{r_{mM,y}}{\\|r_{mM}\\|} v_{M,\\perp}"));
    std::vector<const engine::derivation*> all = {&derived("elastic_plane")};
    const std::string rows = emit::latex_errata(all).rows;
    BOOST_TEST(contains(emit::latex_errata(all).displays, "printed $v_M^{(L)\\prime} = \\mathbf{R}^T "
                                                          "\\mathbf{v}_M^{(C)\\prime}$, read as"));
    // An agreeing row sets the derived form beside the printed one too: Eq. 4's v'_{M,perp}.
    BOOST_TEST(contains(rows, "& $v'_{M,\\perp}$ & agrees & $v_{M,\\perp}$ & $v_{M,\\perp}$ &"));
    // A lab component of R^T v, agreeing, is set beside the printed one in the paper's own
    // variables (the collision frame's v_par, v_perp and r/|r|), not in the lab frame's
    // v_{M,x}, v_{M,y} the derivation displays: each of its four components.
    const std::string displays = emit::latex_errata(all).displays;
    for (const char* component : {"$v'_{M,x}$", "$v'_{M,y}$", "$v'_{m,x}$", "$v'_{m,y}$"}) {
        const std::size_t at = displays.find(std::string("Eq.~(4), second line, ") + component);
        BOOST_TEST_REQUIRE(at != std::string::npos, component);
        const std::size_t derived_at = displays.find("Derived", at);
        const std::string beside = displays.substr(derived_at, displays.find("\\item", derived_at) - derived_at);
        BOOST_TEST(contains(beside, "\\|r_{mM}\\|"), beside);
        BOOST_TEST(contains(beside, "\\perp}"), beside);
        BOOST_TEST((!contains(beside, "v_{M,x}") && !contains(beside, "v_{m,y}")), beside);
    }
}

BOOST_AUTO_TEST_CASE(a_claim_the_paper_states_in_degrees_is_answered_in_degrees)
{
    // A derivation of its own: a pendulum's angle from its cosine, c = 1/(1 + x) for x > 0.
    // The text says "60°" at x = 1, where it is 60°; and "45°" as x grows, where it is 90°
    // (and nowhere else 45°: no regime mends it, so the derived value is the finding).
    // The cosine's bound c <= 1 is a number, not an angle: it stays 1.
    const engine::derivation d = impact::testing::derive_text(
        "id = \"pendulum\"\ntitle = \"t\"\n[[symbol]]\nname = \"x\"\ndomain = \"positive\"\n"
        "[[symbol]]\nname = \"c\"\n[[symbol]]\nname = \"phi\"\nlatex = \"\\\\varphi\"\n"
        "[[step]]\ndefine = \"c\"\nas = \"1/(1 + x)\"\n[[step]]\ndefine = \"phi\"\nas = \"acos(c)\"\n"
        "[[result]]\nname = \"phi\"\n"
        "[[claim]]\nname = \"sixty\"\npaper = \"p. 1\"\nquote = \"at $x = 1$ it swings to $60^\\\\circ$\"\n"
        "claim = \"phi = Pi/3\"\nat = { x = \"1\" }\n"
        "[[claim]]\nname = \"flat\"\npaper = \"p. 1\"\nquote = \"as $x$ grows it tends to 45\u00b0\"\n"
        "claim = \"phi = Pi/4\"\nlimit = \"x -> infinity\"\n"
        "[[claim]]\nname = \"bounded\"\npaper = \"p. 1\"\nquote = \"the angle stays below $90^\\\\circ$\"\n"
        "claim = \"c <= 1\"\n"
        "[[claim]]\nname = \"short\"\npaper = \"p. 1\"\nquote = \"$30^\\\\circ$ short of a right angle\"\n"
        "claim = \"phi - Pi/2 = -Pi/6\"\nat = { x = \"1\" }\n");
    const std::string table = emit::errata_markdown({&d});
    BOOST_TEST(contains(table, "checked: $\\varphi = 60^\\circ$, at $x = 1$"), table);
    BOOST_TEST(contains(table, "the derived value is $90^\\circ$, not $45^\\circ$"), table);
    BOOST_TEST(contains(table, "checked: $c \\leq 1$"), table);
    // A negative multiple of pi is the angle with its sign outside.
    BOOST_TEST(contains(table, "checked: $\\varphi - 90^\\circ = -30^\\circ$, at $x = 1$"), table);
    BOOST_TEST(!contains(table, "\\pi"), table);
    // The engine's own values stay in radians.
    BOOST_TEST(d.paper_checks.at(1).test->value->is_equal(GiNaC::Pi / 2));
}

BOOST_AUTO_TEST_CASE(a_value_with_roots_and_absolute_values_is_shown_collected)
{
    // A derivation of the tests', not the paper's: the values carry |a| = sqrt(a_x^2 + a_y^2)
    // and |v'_t - v_t|. Typed from the solution worked by hand: v'_t = (R q w (1 + b) |a| +
    // (1 - q b)(a_x v - a_y u)) / ((1 + q)|a|), the six-term sum collected in R; and k with
    // the absolute value's argument factored and the rest collected in mu.
    const std::string tex = emit::latex_fragment(impact::testing::derive_file("tests/solve/tilted_spin.toml"));
    BOOST_TEST(contains(tex, "v'_t &= \\frac{R q \\omega (1 + \\beta) \\sqrt{a^{2}_{x} + a^{2}_{y}} + (1 - q \\beta) (a_{x} v - a_{y} u)}"
                             "{(1 + q) \\sqrt{a^{2}_{x} + a^{2}_{y}}}"),
               tex);
    BOOST_TEST(contains(tex, "\\mu g (1 + q) (1 + \\beta)"), tex);
    BOOST_TEST(!contains(tex, "R q \\beta \\omega"), tex);
}

BOOST_AUTO_TEST_CASE(a_result_repeated_for_several_printed_lines_is_shown_once)
{
    // Eq. 12's second and fourth lines give the paper's tau = 1/2 - eps/2; the third line's
    // form, without its spurious m, is (v - eps v)/(2 v): one chain, tau written once.
    const std::string tex = emit::latex_fragment(derived("billiard_transfer"));
    BOOST_TEST(contains(tex, "\\tau &= \\frac{v_{1,\\parallel} - \\epsilon v_{1,\\parallel}}{2 v_{1,\\parallel}} "
                             "\\tag*{Eq.~(12), third line}"));
    BOOST_TEST(contains(tex, "   &= \\frac{1}{2} - \\frac{1}{2} \\epsilon \\tag*{Eq.~(12), second and fourth lines}"));
    const std::string results = tex.substr(tex.find("\\paragraph{Results.}"));
    BOOST_TEST(results.find("\\tau &=") == results.rfind("\\tau &="), "tau is shown more than once");
    // No step that merely copies tau under another name, and tau listed once as a quantity.
    BOOST_TEST(!contains(tex, "\\tau &= \\tau"));
    const std::string quantities = tex.substr(0, tex.find("\\paragraph{Given.}"));
    BOOST_TEST(quantities.find("\\item $\\tau") == quantities.rfind("\\item $\\tau"), "tau is listed more than once");
}

BOOST_AUTO_TEST_CASE(one_quantity_in_two_forms_is_named_once)
{
    // Eq. 10 gives the change of the relative velocity with J and with eps: one quantity,
    // listed once, derived once, its two forms one chain of results.
    const std::string tex = emit::latex_fragment(derived("relative_velocity_change"));
    const auto count = [&tex](const std::string& s) {
        std::size_t n = 0;
        for (auto at = tex.find(s); at != std::string::npos; at = tex.find(s, at + 1))
            ++n;
        return n;
    };
    BOOST_TEST(count("\\item $\\Delta v_\\Delta") == 1u);
    BOOST_TEST(count("Defining $\\Delta v_\\Delta$") == 1u);
    BOOST_TEST(count("\\Delta v_\\Delta &=") == 2u);  // the step, and the first result
    BOOST_TEST(contains(tex, "   &= -(1 + \\epsilon) (v_{M,\\parallel} - v_{m,\\parallel}) \\tag*{Eq.~(10), second line}"));
    // Its definition as the file writes it, the relative velocities in parentheses.
    BOOST_TEST(contains(tex, "\\Delta v_\\Delta &= (v'_{M,\\parallel} - v'_{m,\\parallel}) - (v_{M,\\parallel} - v_{m,\\parallel})"));
    // The check `impulse_form` states the first result's display form: one item, its reason
    // given there: the form typeset in the result and the comparison with the paper (the
    // step refers to the result), not a third time.
    BOOST_TEST(count("-\\left(\\frac{1}{M} + \\frac{1}{m}\\right) J") == 2u);
    BOOST_TEST(contains(tex, "Its value is the result below (\\ref{impact:relative_velocity_change:result:"));
    BOOST_TEST(count("Impulse form") == 1u);
    BOOST_TEST(contains(tex, "equals the derived result. Impulse form states the same: each velocity changes"));
}

BOOST_AUTO_TEST_CASE(givens_that_state_their_values_are_not_a_step_to_follow)
{
    // Billiards: M = m, v_M = 0, v_m = v_1 are the givens themselves; solving them for M,
    // v_M and v_m restates them, so the step says so in words.
    const std::string tex = emit::latex_fragment(derived("billiard_transfer"));
    BOOST_TEST(!contains(tex, "Solving \\eqref{impact:billiard_transfer:equal_masses}"));
    BOOST_TEST(contains(tex, "give $M$, $v_{M,\\parallel}$ and $v_{m,\\parallel}$ directly"));
    BOOST_TEST(!contains(tex, "  M &= m \\\\"));
    // Said before the steps, not numbered as a step without an equation.
    BOOST_TEST(!contains(tex, "\\item \\eqref{impact:billiard_transfer:equal_masses}"));
    // No numbered step of any of the paper's derivations is without its equations.
    for (const char* id : {"elastic_line", "elastic_plane", "inelastic_line", "inelastic_plane", "energy_loss",
                           "billiard_transfer", "scatter_angle", "energy_loss_impulse"}) {
        const std::string fragment = emit::latex_fragment(derived(id));
        const std::size_t from = fragment.find("\\paragraph{Derivation.}");
        const std::size_t to = fragment.find("\\end{enumerate}", from);
        BOOST_TEST_REQUIRE(to != std::string::npos, id << " has no numbered steps");
        const std::string steps = fragment.substr(from, to - from);
        for (std::size_t at = steps.find("\\item "); at != std::string::npos;) {
            const std::size_t next = steps.find("\\item ", at + 1);
            const std::string step = steps.substr(at, next == std::string::npos ? std::string::npos : next - at);
            // Its equations set out, or the numbered results it gives referred to.
            BOOST_TEST((contains(step, "\\begin{align") || contains(step, "gives the results below (\\ref{")),
                       id << ": " << step);
            at = next;
        }
    }
}

BOOST_AUTO_TEST_CASE(a_step_shows_its_value_collected_not_expanded)
{
    // E'_K with Eq. 8's velocities, typed from the closed form
    // ((M v_M + m v_m)^2 + eps^2 M m (v_M - v_m)^2) / (2 (M + m)): collected in eps.
    const std::string tex = emit::latex_fragment(derived("energy_loss_impulse"));
    BOOST_TEST(contains(tex, "&= \\frac{M m \\epsilon^{2} (v_{M,\\parallel} - v_{m,\\parallel})^{2} + "
                             "(M v_{M,\\parallel} + m v_{m,\\parallel})^{2}}{2 (M + m)}\n\\end{align*}\n"
                             "The value is shown collected in $\\epsilon$, each coefficient factored."));
    // |v'_1| = sqrt(v^2 (1 - eps)^2 + 4 v_perp^2)/2, not an expanded sum under the root.
    const std::string angle = emit::latex_fragment(derived("scatter_angle"));
    BOOST_TEST(contains(angle, "\\sqrt{v^{2}_{1,\\parallel} (1 - \\epsilon)^{2} + 4 v^{2}_{1,\\perp}}"));
    // Nor in the proofs: the factors whose signs prove 0 <= cos(theta) <= 1, the root and one
    // over it, are shown with that argument too, never v^2 - 2 v^2 eps + v^2 eps^2 + 4 v_perp^2.
    BOOST_TEST(!contains(angle, "2 v^{2}_{1,\\parallel} \\epsilon"));
    BOOST_TEST(contains(angle, "$\\frac{1}{\\sqrt{v^{2}_{1,\\parallel} (1 - \\epsilon)^{2} + 4 v^{2}_{1,\\perp}}} > 0$ "
                               "(a square root)"));
}

BOOST_AUTO_TEST_CASE(checks_are_headed_in_words_not_identifiers)
{
    const std::string tex = emit::latex_fragment(derived("inelastic_plane"));
    BOOST_TEST(contains(tex, "--- Momentum conserved ($x$ component): "));
    BOOST_TEST(contains(tex, "--- Exchange symmetry ($M$, $x$ component): "));
    BOOST_TEST(!contains(tex, "momentum conserved x"));
    // The claim as the file writes it, not as GiNaC merges it (0 = 0).
    const std::string plane = emit::latex_fragment(derived("elastic_plane"));
    BOOST_TEST(contains(plane, "--- Rows of the rotation are perpendicular: $\\cos\\theta \\, (-\\sin\\theta) + "
                               "\\sin\\theta \\, \\cos\\theta = 0$."));
    const std::string space = emit::latex_fragment(derived("inelastic_space"));
    BOOST_TEST(contains(space, "--- $n$ is a unit vector: "));
    BOOST_TEST(contains(space, "--- Energy loss is Eq.~11: "));
    // A Greek letter's name as the letter, typed here from the check's name elastic_tau.
    const std::string transfer = emit::latex_fragment(derived("billiard_transfer"));
    BOOST_TEST(contains(transfer, "--- Elastic $\\tau$: $\\tau = 0$"));
    BOOST_TEST(!contains(transfer, "Elastic tau"));
}

BOOST_AUTO_TEST_CASE(prose_keeps_its_mathematics_and_escapes_the_rest)
{
    BOOST_TEST(emit::latex_prose("at $\\epsilon = 1$ the loss is 100%") == "at $\\epsilon = 1$ the loss is 100\\%");
    BOOST_TEST(emit::latex_prose("a_b costs $5") == "a\\_b costs \\$5");
}

BOOST_AUTO_TEST_CASE(limits_and_inequalities_say_how_they_were_established)
{
    const std::string tex = emit::latex_fragment(derived("scatter_angle"));
    BOOST_TEST(contains(tex, "$\\lim_{\\epsilon \\to 1} \\cos\\theta = 0$."));
    BOOST_TEST(contains(tex, "The limit is established by substitution"));
    BOOST_TEST(contains(tex, "$\\lim_{v_{1,\\perp} \\to \\infty} \\cos\\theta = 0$."));
    BOOST_TEST(contains(tex, "by substituting $v_{1,\\perp} = 1/t$ and letting $t \\to 0^+$"));
    BOOST_TEST(contains(tex, "$\\cos\\theta \\geq 0$."));
    BOOST_TEST(contains(tex, "From the signs of its factors: "));
}

BOOST_AUTO_TEST_CASE(a_fragment_prints_the_written_forms_it_is_handed_and_never_reads_the_file)
{
    const std::string text = "id = \"w\"\ntitle = \"w\"\n"
                             "[[symbol]]\nname = \"x\"\ndomain = \"positive\"\n"
                             "[[symbol]]\nname = \"eps\"\nlatex = \"\\\\epsilon\"\ndomain = \"[0, 1]\"\n"
                             "[[symbol]]\nname = \"y\"\n"
                             "[[step]]\ndefine = \"y\"\nas = \"(1 - eps)*x\"\n"
                             "[[result]]\nname = \"y\"\ndisplay = \"(1 - eps)*x\"\n";
    engine::derivation d = engine::derive(spec::parse_derivation(text, "w.toml"), {});
    // The engine read how the display form is written: (1 - eps), not -(eps - 1), first.
    BOOST_TEST_REQUIRE(!d.results.at(0).written.empty());
    const std::string tex = emit::latex_fragment(d);
    BOOST_TEST(contains(tex, "y &= (1 - \\epsilon) x \\notag"), tex);

    // The file's text changed after the derivation: the fragment is what it was.
    d.source.results.at(0).display->value = "x*(1 - eps)";
    d.source.steps.at(0).expression.value = "x*(1 - eps)";
    BOOST_TEST(emit::latex_fragment(d) == tex);

    // The written form the engine hands over changed: the fragment follows it.
    d.results.at(0).written = engine::written_form::read(
        "x*(1 - eps)", [&](const std::string& piece) { return d.symbols.parse({piece, {}}); });
    BOOST_TEST(contains(emit::latex_fragment(d), "y &= x (1 - \\epsilon) \\notag"));
}

BOOST_AUTO_TEST_CASE(fragments_are_the_same_on_every_run)
{
    const engine::derivation& d = derived("energy_loss_impulse");
    BOOST_TEST(emit::latex_fragment(d) == emit::latex_fragment(d));
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_CASE(one_misprint_in_several_components_is_one_item_of_the_fragment)
{
    // Eq. 9 prints v'_m with the sign of eps M (v_M - v_m) turned: in its collision-frame
    // component and so in both lab components. One item, the others named.
    const std::string tex = emit::latex_fragment(derived("inelastic_plane"));
    // In the report the fragment says where the rows are, with the count (one finding,
    // printed once, in the errata table); alone it lists them.
    const std::string held = tex.substr(tex.find("\\paragraph{The paper, held to account.}"));
    BOOST_TEST(contains(held, "\\ifdefined\\impacterratatable\n"));
    // Eq. 9's misprint is one row; the others are Sec. III's "frictional forces along the line
    // of action" and Sec. III A's force "opposite to the direction of motion", read as each
    // sphere's own motion.
    BOOST_TEST(contains(held, "3 disagree (Eq.~(9); Sec. III, 4th paragraph; Sec. III A, 1st paragraph)"));
    // Rows, not places, are counted: the planar Eq. 2's first line prints two misprinted
    // equations, its second line one.
    BOOST_TEST(contains(emit::latex_fragment(derived("elastic_plane")),
                        "3 disagree (Sec. II B, planar Eq.~(2), first line; Sec. II B, planar Eq.~(2), second line)."));
    const std::string paper = held.substr(held.find("\\else\n"));
    std::size_t disagree = 0;
    for (auto at = paper.find("disagrees"); at != std::string::npos; at = paper.find("disagrees", at + 1))
        ++disagree;
    BOOST_TEST(disagree == 3u);
    BOOST_TEST(contains(paper, "The same misprint, with the same smallest change, is in $v'_{m,x}$ and $v'_{m,y}$."));
    // No empty sentence left behind.
    BOOST_TEST(!contains(emit::latex_fragment(derived("elastic_plane")), "\n.\n"));
}

BOOST_AUTO_TEST_CASE(a_result_by_cases_too_long_to_write_out_is_shown_as_written)
{
    // A result defined by cases whose values, written out in the declared quantities, would
    // take pages (the 3D rough spheres' |J_t| spells out the radicand of |G_t|): the results
    // show the cases as the file writes them, the quantity G kept by name.
    std::string radicand;
    for (int i = 1; i <= 24; ++i)
        radicand += fmt::format("{}a{}*b{}*c{}", i > 1 ? " + " : "", i, i, i);
    std::string symbols;
    for (int i = 1; i <= 24; ++i)
        for (const char* s : {"a", "b", "c"})
            symbols += fmt::format("[[symbol]]\nname = \"{}{}\"\ndomain = \"positive\"\n", s, i);
    const std::string text = "id = \"long_cases\"\ntitle = \"Long cases\"\n" + symbols +
                             "[[symbol]]\nname = \"k\"\ndomain = \"positive\"\n"
                             "[[symbol]]\nname = \"G\"\ndefinition = \"sqrt(" + radicand + ")\"\n"
                             "[[symbol]]\nname = \"y\"\n"
                             "[[step]]\ndefine = \"y\"\n"
                             "cases = [{ when = \"G <= k\", as = \"G/2\" }, { when = \"G > k\", as = \"k/2\" }]\n"
                             "because = \"half the smaller\"\n"
                             "[[result]]\nname = \"y\"\n";
    const engine::derivation d = engine::derive(spec::parse_derivation(text, "long_cases.toml"), {});
    const std::string tex = emit::latex_fragment(d);
    const std::string results = tex.substr(tex.find("\\paragraph{Results.}"));
    BOOST_TEST(contains(results, "\\text{if } G \\leq k"), results);
    BOOST_TEST(contains(results, "y &= \\frac{G}{2}"), results);
    BOOST_TEST(!contains(results, "a_{24}"), results);
}

BOOST_AUTO_TEST_CASE(an_intermediate_quantity_too_long_written_out_is_used_by_name)
{
    // A derivation of the test's own: the squared lengths of two sums of six products,
    // u = a_1 b_1 + ... + a_6 b_6 and w = c_1 d_1 + ... + c_6 d_6, and g = u^2 + w^2 - u w,
    // which written out in the a, b, c, d is a sum of over a hundred products: its step says
    // so and goes on with g by name. h = u + w, written out in two short lines, is shown.
    std::string symbols, u = "", w = "";
    for (int i = 1; i <= 6; ++i) {
        for (const char* letter : {"a", "b", "c", "d"})
            symbols += fmt::format("[[symbol]]\nname = \"{}_{}\"\n", letter, i);
        u += fmt::format("{}a_{}*b_{}", i == 1 ? "" : " + ", i, i);
        w += fmt::format("{}c_{}*d_{}", i == 1 ? "" : " + ", i, i);
    }
    const engine::derivation d = impact::testing::derive_text(
        "id = \"lengths\"\ntitle = \"t\"\n" + symbols +
        "[[symbol]]\nname = \"u\"\n[[symbol]]\nname = \"w\"\n[[symbol]]\nname = \"g\"\n[[symbol]]\nname = \"h\"\n"
        "[[step]]\ndefine = \"u\"\nas = \"" + u + "\"\n[[step]]\ndefine = \"w\"\nas = \"" + w + "\"\n"
        "[[step]]\ndefine = \"g\"\nas = \"u^2 + w^2 - u*w\"\n[[step]]\ndefine = \"h\"\nas = \"u + w\"\n"
        "[[result]]\nname = \"h\"\n[[result]]\nname = \"g\"\n");
    const std::string tex = emit::latex_fragment(d);
    BOOST_TEST(contains(tex, "Written out in the declared quantities, it would take more than three lines; what "
                             "follows uses $g$ by name."),
               tex);
    BOOST_TEST(!contains(tex, "uses $h$ by name"), tex);
    // h's step shows what it comes to: a_1 b_1 appears in it, besides u's own step and the results.
    const std::size_t h_step = tex.find("Defining $h$");
    BOOST_TEST_REQUIRE(h_step != std::string::npos);
    BOOST_TEST(tex.substr(h_step, tex.find("\\end{align*}", h_step) - h_step).find("a_{1} b_{1} + c_{1} d_{1}") != std::string::npos,
               tex);
}

BOOST_AUTO_TEST_CASE(a_step_that_solves_for_the_numbered_results_refers_to_them)
{
    // Eq. 8: solving the two impulse equations and Newton's law for v'_M, v'_m and J gives
    // exactly the three results the paper numbers Eq. 8, right: the step refers to them by
    // their tags and does not set them out a second time.
    const std::string tex = emit::latex_fragment(derived("inelastic_line"));
    const std::size_t step = tex.find("\\item Solving");
    BOOST_TEST_REQUIRE(step != std::string::npos);
    const std::string said = tex.substr(step, tex.find("\\paragraph{Results.}") - step);
    BOOST_TEST(contains(said, "gives the results below (\\ref{impact:inelastic_line:result:v_M_after}; "
                              "\\ref{impact:inelastic_line:result:v_m_after}; \\ref{impact:inelastic_line:result:J})."),
               said);
    BOOST_TEST(!contains(said, "\\begin{align"), said);
    BOOST_TEST(contains(said, "Substituted back, the solution satisfies each of"), said);
}

BOOST_AUTO_TEST_CASE(a_sentence_opening_with_a_sphere_s_name_keeps_its_case)
{
    // Footnote 10's givens and checks explain m's velocity: the sentence opens with the
    // sphere's name, which is not capitalised into the other sphere, M. A sentence opening
    // with the article is.
    const std::string tex = emit::latex_fragment(derived("inelastic_space"));
    BOOST_TEST(contains(tex, "m's velocity along the line of action is its component along"), tex);
    BOOST_TEST(contains(tex, "m's velocity across the line of action, along $\\mathbf{t}$, is untouched"), tex);
    BOOST_TEST(emit::detail::capitalised("a smooth wall") == "A smooth wall");
    BOOST_TEST(emit::detail::capitalised("m's velocity") == "m's velocity");
    BOOST_TEST(emit::detail::capitalised("the impulse") == "The impulse");
}

BOOST_AUTO_TEST_CASE(a_result_defined_as_another_quantity_by_name_shows_its_value)
{
    // Eq. 4: v'_{M,par} is defined as Eq. 3's v'_M of the parallel components; the step shows
    // what that is, ((M - m) v_{M,par} + 2 m v_{m,par})/(M + m), typed from the paper's Eq. 4,
    // rather than only referring to the result.
    const std::string tex = emit::latex_fragment(derived("elastic_plane"));
    const std::size_t step = tex.find("Defining $v'_{M,\\parallel}$");
    BOOST_TEST_REQUIRE(step != std::string::npos);
    const std::string said = tex.substr(step, tex.find("\\item", step) - step);
    BOOST_TEST(contains(said, "\\frac{(M - m) v_{M,\\parallel} + 2 m v_{m,\\parallel}}{M + m}"), said);
    BOOST_TEST(!contains(said, "Its value is the result below"), said);
}

BOOST_AUTO_TEST_CASE(a_solve_for_numbered_results_of_any_derivation_refers_to_them)
{
    // A derivation of the test's own: two numbers from their sum a and difference b,
    // p = (a + b)/2 and q = (a - b)/2, both numbered results ("p. 1"): the step refers to
    // them. The same with q not numbered: the step sets the values out.
    const auto fragment = [](const std::string& q_paper) {
        const std::string text =
            "id = \"halves\"\ntitle = \"t\"\n"
            "[[symbol]]\nname = \"a\"\n[[symbol]]\nname = \"b\"\n[[symbol]]\nname = \"p\"\n[[symbol]]\nname = \"q\"\n"
            "[[given]]\nname = \"sum\"\nequation = \"p + q = a\"\nbecause = \"s\"\n"
            "[[given]]\nname = \"difference\"\nequation = \"p - q = b\"\nbecause = \"d\"\n"
            "[[step]]\nsolve = [\"sum\", \"difference\"]\nfor = [\"p\", \"q\"]\n"
            "[[result]]\nname = \"p\"\ndisplay = \"(a + b)/2\"\npaper = \"p. 1\"\n"
            "[[result]]\nname = \"q\"\ndisplay = \"(a - b)/2\"\n" + q_paper;
        return emit::latex_fragment(engine::derive(spec::parse_derivation(text, "halves.toml"), {}));
    };
    const std::string numbered = fragment("paper = \"p. 2\"\n");
    BOOST_TEST(contains(numbered, "gives the results below (\\ref{impact:halves:result:p}; "
                                  "\\ref{impact:halves:result:q})."),
               numbered);
    const std::string unnumbered = fragment("");
    BOOST_TEST(!contains(unnumbered, "gives the results below"), unnumbered);
    BOOST_TEST(contains(unnumbered, "gives\n\\begin{align*}"), unnumbered);
}

BOOST_AUTO_TEST_CASE(a_symbol_without_latex_is_typeset_from_its_name)
{
    // A file that gives no `latex`: each name is typeset the way a physicist would write it
    // (spec::latex_of_name), never with its underscores or digits left in the text as typed.
    const std::string text =
        "id = \"names\"\ntitle = \"t\"\n"
        "[[symbol]]\nname = \"a_10\"\n[[symbol]]\nname = \"r_x_1\"\n[[symbol]]\nname = \"v1\"\n"
        "[[symbol]]\nname = \"theta_2\"\n[[symbol]]\nname = \"t_top\"\n[[symbol]]\nname = \"vel_after\"\n"
        "[[symbol]]\nname = \"u_perp\"\n[[symbol]]\nname = \"c\"\n"
        "[[step]]\ndefine = \"c\"\nas = \"a_10 + r_x_1 + v1 + theta_2 + t_top + vel_after + u_perp\"\n"
        "because = \"the sum\"\n"
        "[[result]]\nname = \"c\"\n";
    const std::string tex = emit::latex_fragment(engine::derive(spec::parse_derivation(text, "names.toml"), {}));
    for (const char* typeset : {"a_{10}", "r_{x,1}", "v_{1}", "\\theta_{2}", "t_{\\mathrm{top}}", "\\mathit{vel}'",
                                "u_{\\perp}"})
        BOOST_TEST(contains(tex, typeset), typeset << " in\n" << tex);
    for (const char* raw : {"a_10", "r_x_1", "v1", "theta_2", "t_top", "vel_after", "u_perp"})
        BOOST_TEST(!contains(tex, raw), raw << " in\n" << tex);
}

BOOST_AUTO_TEST_CASE(results_that_share_a_tag_are_cited_with_their_quantity)
{
    // The halves again, both results printed on one page of a text ("p. 1", as Eq. 9 prints
    // six rows): the tag alone would not tell the reader which row, so the quantity is named.
    // A quantity defined as one an earlier step derives (r = p) refers to that step for its
    // value instead of setting it out again.
    const std::string text =
        "id = \"halves\"\ntitle = \"t\"\n"
        "[[symbol]]\nname = \"a\"\n[[symbol]]\nname = \"b\"\n[[symbol]]\nname = \"p\"\n[[symbol]]\nname = \"q\"\n"
        "[[symbol]]\nname = \"r\"\n"
        "[[given]]\nname = \"sum\"\nequation = \"p + q = a\"\nbecause = \"s\"\n"
        "[[given]]\nname = \"difference\"\nequation = \"p - q = b\"\nbecause = \"d\"\n"
        "[[step]]\nsolve = [\"sum\", \"difference\"]\nfor = [\"p\", \"q\"]\n"
        "[[step]]\ndefine = \"r\"\nas = \"p\"\n"
        "[[result]]\nname = \"p\"\ndisplay = \"(a + b)/2\"\npaper = \"p. 1\"\n"
        "[[result]]\nname = \"q\"\ndisplay = \"(a - b)/2\"\npaper = \"p. 1\"\n"
        "[[result]]\nname = \"r\"\n";
    const std::string tex = emit::latex_fragment(engine::derive(spec::parse_derivation(text, "halves.toml"), {}));
    BOOST_TEST(contains(tex, "gives the results below (\\ref{impact:halves:result:p}, $p$; "
                             "\\ref{impact:halves:result:q}, $q$)."),
               tex);
    const std::size_t step = tex.find("Defining $r$");
    BOOST_TEST_REQUIRE(step != std::string::npos);
    const std::string said = tex.substr(step, tex.find("\\end{enumerate}", step) - step);
    BOOST_TEST(contains(said, "r &= p\n\\end{align*}\nStep~1 gives $p$."), said);
    BOOST_TEST(!contains(said, "\\frac{a + b}{2}"), said);
}

BOOST_AUTO_TEST_CASE(a_result_long_written_out_is_shown_as_its_step_defines_it)
{
    // A derivation of the test's own: k a long sum of products, and the result w = k/(k + a_1),
    // which written out in the declared quantities breaks over lines; its step's k/(k + a_1)
    // is one line. The results show that, and say so; a short result stays written out.
    std::string symbols, sum;
    for (int i = 1; i <= 9; ++i) {
        symbols += fmt::format("[[symbol]]\nname = \"a_{0}\"\n[[symbol]]\nname = \"b_{0}\"\n[[symbol]]\nname = \"c_{0}\"\n", i);
        sum += fmt::format("{}a_{}*b_{}*c_{}", i > 1 ? " + " : "", i, i, i);
    }
    const std::string text = "id = \"long\"\ntitle = \"t\"\n" + symbols +
                             "[[symbol]]\nname = \"k\"\n[[symbol]]\nname = \"w\"\n[[symbol]]\nname = \"u\"\n"
                             "[[step]]\ndefine = \"k\"\nas = \"" + sum + "\"\n"
                             "[[step]]\ndefine = \"w\"\nas = \"k/(k + a_1)\"\n"
                             "[[step]]\ndefine = \"u\"\nas = \"a_1 + a_2\"\n"
                             "[[result]]\nname = \"w\"\n[[result]]\nname = \"u\"\n";
    const std::string tex = emit::latex_fragment(engine::derive(spec::parse_derivation(text, "long.toml"), {}));
    const std::size_t results = tex.find("\\paragraph{Results.}");
    BOOST_TEST_REQUIRE(results != std::string::npos);
    const std::string shown = tex.substr(results);
    BOOST_TEST(contains(shown, "w &= \\frac{k}{k + a_{1}}"), shown);
    BOOST_TEST(contains(shown, "u &= a_{1} + a_{2}"), shown);
    BOOST_TEST(contains(shown, "$w$ is shown as its step defines it, in the quantities named there"), shown);
    BOOST_TEST(!contains(shown, "$u$ is shown"), shown);
}

BOOST_AUTO_TEST_CASE(a_quantity_imported_from_another_derivation_is_said_to_be_its_result)
{
    // The pendulum of tests/examples/ imports the spring's period T as T_spring: its item says
    // whose result it is, the spring's derivation by its title, the result by its symbol there.
    const engine::library lib = engine::derive_all(engine::read_directory(IMPACT_SOURCE_DIR "/tests/examples"),
                                                   "pendulum");
    const std::string tex = emit::latex_fragment(lib.derived.at("pendulum"), &lib.derived);
    BOOST_TEST(contains(tex, "\\item $T_\\mathrm{spring} \\in \\mathbb{R}$ ($\\mathrm{s}$): period of a mass m on a "
                             "spring of stiffness k; the result $T$ of \\emph{A mass on a spring}\n"),
               tex);
    // The pendulum's own quantities say nothing of the kind.
    BOOST_TEST(contains(tex, "\\item $T \\in \\mathbb{R}$ ($\\mathrm{s}$): period of the pendulum\n"), tex);
    // Handed no derivations, the fragment names the other by its id.
    BOOST_TEST(contains(emit::latex_fragment(lib.derived.at("pendulum")),
                        "stiffness k; the result T of the derivation \\texttt{spring}\n"));
}

BOOST_AUTO_TEST_CASE(a_result_imported_from_the_paper_is_cited_by_its_place_there)
{
    // Eq. 11's derivation takes Eq. 8's final velocities (inelastic_line's results, which the
    // paper prints on the two lines of Eq. 8's right side), under the same symbols.
    const engine::library lib = engine::derive_all(engine::read_directory(IMPACT_SOURCE_DIR "/derivations"),
                                                   "energy_loss");
    const std::string tex = emit::latex_fragment(lib.derived.at("energy_loss"), &lib.derived);
    BOOST_TEST(contains(tex, "velocity of M along the line of action after the collision (Eq. 8); the result of "
                             "\\emph{Inelastic collision along the line of action}, Eq.~(8), right, first line\n"),
               tex);
}

BOOST_AUTO_TEST_CASE(a_result_defined_by_cases_is_one_numbered_equation)
{
    // Cases too wide for one line are set row by row under their conditions: one equation
    // still, numbered once (the paper's Eq. 7, on its last row), no row numbered apart.
    const std::string text =
        "id = \"wide\"\ntitle = \"t\"\n"
        "[[symbol]]\nname = \"F\"\ndomain = \"positive\"\n[[symbol]]\nname = \"m\"\ndomain = \"positive\"\n"
        "[[symbol]]\nname = \"g\"\ndomain = \"positive\"\n"
        "[[symbol]]\nname = \"mu\"\nlatex = \"\\\\mu\"\ndomain = \"positive\"\n"
        "[[symbol]]\nname = \"alpha\"\nlatex = \"\\\\alpha\"\ndomain = \"positive\"\n"
        "[[symbol]]\nname = \"beta\"\nlatex = \"\\\\beta\"\ndomain = \"positive\"\n"
        "[[symbol]]\nname = \"f\"\n"
        "[[step]]\ndefine = \"f\"\ncases = [\n"
        "  { when = \"F*(1 + alpha)*(1 + beta) <= mu*m*g*(1 + alpha^2)*(1 + beta^2)\", "
        "as = \"F*(1 + alpha)*(1 + beta)/((1 + alpha^2)*(1 + beta^2))\" },\n"
        "  { when = \"F*(1 + alpha)*(1 + beta) > mu*m*g*(1 + alpha^2)*(1 + beta^2)\", as = \"mu*m*g\" },\n]\n"
        "because = \"static friction holds up to a bound\"\n"
        "[[result]]\nname = \"f\"\npaper = \"Eq. 7\"\n";
    const std::string tex = emit::latex_fragment(engine::derive(spec::parse_derivation(text, "wide.toml"), {}));
    const std::size_t results = tex.find("\\paragraph{Results.}");
    BOOST_TEST_REQUIRE(results != std::string::npos);
    const std::string shown = tex.substr(results, tex.find("\\end{align}", results) - results);
    BOOST_TEST(shown ==
                   "\\paragraph{Results.}\n\\begin{align}\n"
                   "  & \\text{if } F (1 + \\alpha) (1 + \\beta) \\leq m g \\mu (1 + \\alpha^{2}) (1 + \\beta^{2}): "
                   "\\notag \\\\\n"
                   "  f &= \\frac{F (1 + \\alpha) (1 + \\beta)}{(1 + \\alpha^{2}) (1 + \\beta^{2})} \\notag \\\\\n"
                   "  & \\text{if } F (1 + \\alpha) (1 + \\beta) > m g \\mu (1 + \\alpha^{2}) (1 + \\beta^{2}): "
                   "\\notag \\\\\n"
                   "  f &= m g \\mu \\tag*{Eq.~(7)}\\label{impact:wide:result:f}\n",
               shown);
}

BOOST_AUTO_TEST_CASE(a_limit_taken_by_its_series_is_typeset)
{
    // sin(x)/x and sin(x)^2/x at 0, and sin(x - 1)/(x - 1) at 1, are 0/0 there: their limits
    // are the leading terms of their series, said in mathematics, not in the proof's words.
    const std::string text =
        "id = \"series\"\ntitle = \"t\"\n"
        "[[symbol]]\nname = \"x\"\ndomain = \"positive\"\n"
        "[[symbol]]\nname = \"f\"\n[[symbol]]\nname = \"q\"\n[[symbol]]\nname = \"s\"\n"
        "[[step]]\ndefine = \"f\"\nas = \"sin(x)/x\"\n"
        "[[step]]\ndefine = \"q\"\nas = \"sin(x)^2/x\"\n"
        "[[step]]\ndefine = \"s\"\nas = \"sin(x - 1)/(x - 1)\"\n"
        "[[result]]\nname = \"f\"\n"
        "[[check]]\nname = \"sinc_at_zero\"\nclaim = \"f = 1\"\nlimit = \"x -> 0\"\n"
        "[[check]]\nname = \"vanishing\"\nclaim = \"q = 0\"\nlimit = \"x -> 0\"\n"
        "[[check]]\nname = \"shifted\"\nclaim = \"s = 1\"\nlimit = \"x -> 1\"\n";
    const std::string tex = emit::latex_fragment(engine::derive(spec::parse_derivation(text, "series.toml"), {}));
    BOOST_TEST(contains(tex, "$\\lim_{x \\to 0} f = 1$. The limit is established by the leading term of its "
                             "series in $x$, $1$.\n"),
               tex);
    BOOST_TEST(contains(tex, "$\\lim_{x \\to 0} q = 0$. The limit is established by the leading term of its "
                             "series in $x$, $x$.\n"),
               tex);
    BOOST_TEST(contains(tex, "$\\lim_{x \\to 1} s = 1$. The limit is established by the leading term of its "
                             "series in $x - 1$, $1$.\n"),
               tex);
    BOOST_TEST(!contains(tex, "->"), tex);
    BOOST_TEST(!contains(tex, "\\^{}"), tex);
}
