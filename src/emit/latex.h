// LaTeX emitter: GiNaC expressions → LaTeX math, derivations → LaTeX fragments.
//
// `print_tex` is a GiNaC print context of Impact's own. It writes what a textbook
// writes: symbols with the LaTeX names their derivation file gives (primes, ∥ and ⊥
// subscripts, Greek letters), v'^2_{M,∥} rather than a double superscript, quotients as
// \frac, square roots as \sqrt, a sum inside a product written with its first term
// positive ((1 - ε), never (-1 + ε)), and parentheses only where precedence needs them
// (\left( \right) only around something tall). An expression read from the derivation
// file (a display form, a given equation, a claim) is printed the way its author wrote
// it, terms and factors in the written order (`written_form`); everything else in
// `term_order`, so that the text is the same on every run.
#pragma once

#include "engine/derivation/derivation.h"
#include "engine/expr/order.h"
#include "engine/expr/written_form.h"
#include "spec/outline.h"

#include <ginac/ginac.h>

#include <string>
#include <vector>

namespace impact::emit {

using engine::term_order;
using engine::written_form;

class print_tex : public GiNaC::print_context {
    GINAC_DECLARE_PRINT_CONTEXT(print_tex, GiNaC::print_context)
public:
    print_tex(std::ostream& os, const term_order& order, const written_form* written = nullptr);
    const term_order* order = nullptr;
    const written_form* written = nullptr;  ///< how the expression was written, if it was
};

/// An expression as LaTeX math (without the surrounding `$`); with `written`, in the
/// order and orientation the text it was read from gives.
std::string latex(const GiNaC::ex& e, const term_order& order, const written_form* written = nullptr);

/// The same expression broken into lines for a displayed equation, none (where it can
/// be helped) wider than `width` (in points, see `latex_width`): a
/// long sum breaks before a + or -, a long product around its widest sum, which is
/// then set in \Bigl( \Bigr). One line when it fits.
std::vector<std::string> latex_lines(const GiNaC::ex& e, const term_order& order, const written_form* written,
                                     double width);

/// The same, the first line no wider than `first_width` and the others than `other_width`.
std::vector<std::string> latex_lines(const GiNaC::ex& e, const term_order& order, const written_form* written,
                                     double first_width, double other_width);

/// The approximate printed width of LaTeX math in display style, in points of Computer
/// Modern at 10 pt: fractions count their wider part, scripts 0.7 of theirs.
double latex_width(const std::string& math);

/// A form exactly as its text writes it (`written_form::tree`): every term, factor, sign
/// and parenthesis where the text has it, nothing merged or reordered; for the paper's
/// printed forms, shown as printed.
std::string latex_as_written(const written_form::node& n, const term_order& order);

/// The same broken before a + or - of its outermost sum into lines none (where it can be
/// helped) wider than `width` points; one line when it fits.
std::vector<std::string> latex_lines_as_written(const written_form::node& n, const term_order& order,
                                                double width);

/// A check's claim as LaTeX math: `\lim_{v_\perp \to \infty} \cos\theta = 0`, `\Delta E_K \leq 0`.
std::string claim_math(const engine::check_result& c, const term_order& order, const written_form* written = nullptr);

/// What a claim of the paper was checked as, in LaTeX prose: the claim as its file writes
/// it, then its special values, narrowed domains and the inputs changed on its left side
/// ("$\frac{1}{\cos^2\theta} = \frac{1}{\cos^2\theta}$, for $\epsilon \in [0, 1)$, the left side
/// taken at $v_{1,\parallel} \to k v_{1,\parallel}$").
std::string checked_claim_latex(const engine::check_result& c, const term_order& order);

/// A check's claim as the report states it: its relation typeset (checked_claim_latex), or,
/// stated in words, the words with the quantity typeset ("$J_t$ is continuous where its
/// cases meet", "the cases of $J_t$ cover every value").
std::string claim_latex(const engine::derivation& d, const engine::check_result& c);

/// Each check of `d` (in the order of `all_checks`), its proof typeset for a reader who
/// opens it: the claim, how it was established, the sign of each factor, a limit's method,
/// the cases, the conditions (emit/latex_claims.cpp). Paragraphs and a list.
std::vector<std::string> checks_proofs_latex(const engine::derivation& d);

/// A comparison as the report shows it: a claim the paper states in degrees ("the scatter
/// angle being 90°") is answered in degrees, each rational multiple of π in what was checked
/// and found (θ = π/2, "not π/2") set as that many degrees (θ = 90°, "not 90°"). Any other
/// comparison as it is.
engine::paper_comparison in_the_papers_units(const engine::paper_comparison& p);

/// Plain text escaped for LaTeX.
std::string latex_text(const std::string& text);

/// Prose from a derivation file: plain text escaped for LaTeX, and what it writes between
/// `$` and `$` kept as LaTeX mathematics ("at $\epsilon = 1$ the collision is elastic").
std::string latex_prose(const std::string& text);

/// A finding of the engine (a smallest change, a dimensional inconsistency, the regime
/// where a claim holds instead) as LaTeX prose with its mathematics typeset.
/// With `of`, the comparison it is about: an expression the finding names that is the
/// printed form itself is set as the paper prints it.
std::string finding_latex(const engine::finding& f, const term_order& order, const written_form* written = nullptr,
                          const engine::paper_comparison* of = nullptr);

/// "agrees", "disagrees", or "undecided" when the comparison could be neither proven nor
/// refuted (only sampled, or a limit that no method established).
std::string comparison_verdict(const engine::paper_comparison& p);

/// What an agreeing or undecided comparison came to, and how, as the errata's finding:
/// "proven equal: the difference of the sides simplifies to $0$", "proven: the limit by
/// substitution, ...", "proven case by case", "neither proven nor refuted: it holds at 200
/// sampled points ...". Words, with mathematics between dollar signs; empty for a
/// disagreement, whose findings say what is wrong.
std::string agreement_text(const engine::paper_comparison& p);

/// The printed form of a disagreeing comparison with its smallest change made, when the
/// derived form the report would show, `shown`, is in variables that form does not use:
/// the derived form in the printed form's own variables, to set beside it (Eq. 9's lab
/// components through the collision frame, as the paper prints them, rather than Impact's
/// lab-frame form). Nothing when `shown` is in its variables, or when no change, or more
/// than one, reconciles the two.
std::optional<GiNaC::ex> corrected_form(const engine::paper_comparison& p, const GiNaC::ex& shown);

/// The derived form to set beside the printed form of result `r` (of derivation `d`): mended
/// in the printed form's variables (corrected_form); for an agreeing component of a vector the
/// paper prints whole under one quote (Eq. 9's R^T (...)), the printed form itself, proven
/// equal, in the paper's frame; else the result as its file displays it; with the written
/// form that orders its terms.
std::pair<GiNaC::ex, const written_form*> result_beside(const engine::derivation& d,
                                                        const engine::paper_comparison& p,
                                                        const engine::result& r);

/// The LaTeX fragment of one derivation, typeset as a derivation: its quantities, the
/// given equations with their justifications, each step and what it yields, the results
/// numbered as in the paper, the checks with their status and how each was
/// established, and the paper's printed forms compared. Needs amsmath and amssymb only.
/// A quantity imported from another derivation (`[[use]]`) is said to be that one's
/// result, the derivation named by its title from `used` (the derivations derived, by id),
/// by its id when `used` has none.
std::string latex_fragment(const engine::derivation& d, const engine::derived_by_id* used = nullptr);

/// The file name of a derivation's fragment (`<id>.tex`).
std::string latex_fragment_name(const engine::derivation& d);

/// A check's name as its label in the fragment writes it (`impact:<id>:check:<name>`), each
/// character other than a letter, a digit or _ as _: the web report's anchor `check-<name>`.
std::string check_label_name(const std::string& check);

/// The label of a derivation's fragment, for \ref (`impact:<id>`).
std::string latex_label(const engine::derivation& d);

/// The errata table of the report: a row per finding of `derivations` (where, what,
/// verdict, printed, derived or what a claim was checked as, finding; one row for a
/// misprint shared by the components of one equation, `errata_rows`; a row per claim no
/// derivation settles, undecided with why), and the forms too wide for a cell as numbered
/// items (`\item[(T1)] ...`) of a list to set under the table. The rows in the paper's order when
/// `outline` gives it (emit::errata_entries).
struct errata_table {
    std::string rows;
    std::string displays;
    std::size_t displayed = 0;
};
errata_table latex_errata(const std::vector<const engine::derivation*>& derivations,
                          const spec::paper_outline* outline = nullptr);

} // namespace impact::emit
