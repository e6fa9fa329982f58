// How the LaTeX printer (latex.cpp) sees sums and products, shared with the line breaker
// (latex_lines.cpp), which breaks a displayed equation where the printer would write a
// term or a factor; and the writer of a derivation's fragment, whose whole, quantities and
// givens (latex_fragment.cpp), steps (latex_steps.cpp), results (latex_results.cpp),
// checks (latex_claims.cpp) and paper comparisons (latex_paper.cpp) are written apart.
// Internal to emit.
#pragma once

#include "emit/latex.h"
#include "engine/paper/references.h"

#include <ginac/ginac.h>

#include <climits>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace impact::emit::detail {

/// `=`, `\\leq`, `<`, `\\geq` or `>`.
const char* latex_relation(engine::relation op);

using power_term = engine::term_order::power_term;

// Precedence levels: an operand printed at `level` is parenthesised when its own level
// is lower (a sum inside a product, a product or a negative number as a power's base).
constexpr unsigned sum_level = 10;
constexpr unsigned product_level = 20;
constexpr unsigned atom_level = 30;

/// Registers print_tex's print functions with GiNaC (once).
void register_print_functions();

/// A symbol's LaTeX name (the one its file gives, else one made from its name).
std::string symbol_latex(const GiNaC::symbol& s);

/// A symbol's LaTeX name raised to a power as a textbook writes it (v'^{2}_{M,\parallel}).
std::string symbol_power(const std::string& name, const std::string& exponent);

/// Math in parentheses, \left( \right) around something tall.
std::string parenthesised(const std::string& math);
bool is_tall(const std::string& math);

/// GiNaC's function names and their LaTeX (acos → \arccos).
const std::map<std::string, std::string>& function_names();

/// ∂f/∂x, diff(f, x) of the derivation files: \frac{\partial \theta}{\partial \epsilon} when f is
/// a quantity's name (`named`), else \frac{\partial}{\partial x} before f in parentheses.
std::string partial_derivative(const std::string& f, const std::string& x, bool named);

/// An intermediate value as a textbook shows it: factored, or collected in one quantity
/// with each coefficient factored, whichever prints shortest, when clearly shorter than
/// `value` as it is (proven equal to it); `how` says which, in LaTeX prose, and is empty
/// when the value is left as it is.
struct textbook_value {
    GiNaC::ex value;
    std::string how;
};
textbook_value textbook_form(const GiNaC::ex& e, const term_order& order);

/// `e` printed in the context of `c` at precedence `level`.
std::string render(const GiNaC::ex& e, const print_tex& c, unsigned level);

/// A product as ± [leading fraction] numerator / denominator, each factor placed where
/// the written product has it (numbers first, then `term_order`, when not written).
struct placed {
    power_term factor;
    int index = INT_MAX;     ///< the position in the written product
    std::string key;         ///< term_order's key, for what the text does not place
};

struct product_parts {
    bool negated = false;
    GiNaC::numeric leading = 1;   ///< ½ of `1/2*m*v^2`, typeset before the rest
    std::vector<placed> numerator;
    std::vector<placed> denominator;
};

/// A product split into the parts it is printed as.
product_parts split(const GiNaC::ex& product, const print_tex& c);

/// Prints the parts of a product into `c`.
void print_parts(const product_parts& f, const print_tex& c, unsigned level);

/// Each term of a sum with the sign it is written with: "-" for the first term when
/// negative, "+ " or "- " before the others.
std::vector<std::pair<std::string, GiNaC::ex>> signed_terms(const GiNaC::ex& sum, const print_tex& c);

/// "Eq. 8" → "Eq.~8" in running text.
std::string paper_text(const std::string& paper);

/// A verdict in bold (proven, FAILED) or italics (sampled, with its sample size).
std::string status_text(const engine::verdict& v, const term_order& order);

/// A condition a claim rests on, as LaTeX math: $r_x^2 + r_y^2 > 0$, $x \\neq y$.
std::string condition_latex(const engine::condition& c, const term_order& order);
/// Several, listed in words: "$a > 0$ and $b \\neq 0$".
std::string conditions_latex(const std::vector<engine::condition>& conditions, const term_order& order);

/// The text with its first letter capitalised, unless it opens with a one-letter name (a
/// symbol: "m's velocity" stays as written; the article "a" is capitalised).
std::string capitalised(std::string text);

/// Joins items as "a, b and c".
std::string listing(const std::vector<std::string>& items);

/// A dimension's SI unit, e.g. $\mathrm{kg\,m^{2}\,s^{-2}}$, or "dimensionless".
std::string si_unit_latex(const engine::dimension& d);

/// Math set inline when it is short and flat, displayed (and broken) otherwise.
bool wants_display(const std::string& math);

/// Everything the fragment of one derivation needs while it is written.
class fragment_writer {
public:
    /// `used`: the derivations derived, by id, where those `d` imports from are found (none:
    /// they are named by their ids).
    explicit fragment_writer(const engine::derivation& d, const engine::derived_by_id* used = nullptr);

    /// The whole fragment.
    std::string write();
    /// Check `c`'s proof, typeset for a reader who opens it (the web page's `<details>`):
    /// the claim, how it was established (the difference of the sides, the sign of each
    /// factor, a limit's method, each case), the conditions it holds under and those of its
    /// definedness proven. Paragraphs and a list, in the dialect of the fragments.
    std::string proof(const engine::check_result& c) const;
    /// A row (and its displays) of the report's errata table: comparisons shown together
    /// (emit::errata_rows), or a claim no derivation settles.
    void errata_row(errata_table& table, const std::vector<std::size_t>& group) const;
    void errata_row(errata_table& table, const engine::text_comparison& words) const;

private:
    // latex_fragment.cpp: the printing shared by every part, the quantities and the givens;
    // latex_steps.cpp: the steps (step_checks to rearrange_step, and the cases);
    // latex_results.cpp: the results (results, shown_as, defining_step, result_ref,
    // result_cited, places).
    std::string math(const GiNaC::ex& e, const written_form* w = nullptr) const;
    std::string relation_math(const GiNaC::ex& r, const written_form* w = nullptr,
                              engine::relation op = engine::relation::equal) const;
    std::string rows(const std::string& lhs, const GiNaC::ex& rhs, const written_form* w, const std::string& tag,
                     const char* relation = "=", double align_at = -1) const;
    std::string ref(const std::string& equation) const;
    std::string quantities() const;
    /// Where an imported quantity comes from ("the result $T$ of \emph{A mass on a spring}"),
    /// or nothing for a quantity of this derivation's own.
    std::string imported_from(const engine::quantity& q) const;
    std::string givens() const;
    std::string step_checks(const engine::step_result& s) const;
    std::string steps() const;
    /// Each step's number in the enumerated list; 0 for a step not listed (givens that state
    /// their unknowns' values, said before the list; a copy of a quantity under another name).
    std::vector<int> step_items() const;
    /// The number of the listed step among the first `before` that derives `symbol` (solves
    /// for it or defines it), or 0.
    int item_deriving(const GiNaC::ex& symbol, std::size_t before) const;
    std::string as_defined(const std::string& lhs, const GiNaC::ex& value, const written_form& w) const;
    bool givens_state(const engine::step_result& s, const spec::step& source) const;
    std::string solve_step(const engine::step_result& s, const spec::step* source, const std::string& because) const;
    std::string rejected_solutions(const engine::step_result& s) const;
    std::string cases_text(const engine::check_result& c) const;
    std::string define_step(const engine::step_result& s, const std::string& because) const;
    /// `\begin{cases} value & \text{if } condition \\ ... \end{cases}`: as the file writes
    /// them, or (`derived`) in the declared quantities.
    std::string cases_math(const std::vector<engine::case_value>& cases, bool derived) const;
    /// `lhs &= \begin{cases} ... \end{cases}` in the declared quantities when it fits the
    /// line; else each case on rows of its own under its condition, its value as a textbook
    /// shows it and broken over lines. The last row gets `tag`, the others \notag when
    /// there is a tag: one number for the block. When a case takes more than
    /// three lines or does not fit: none, or, if it `must` be shown, the cases as the file
    /// writes them.
    std::optional<std::string> derived_cases_rows(const std::string& lhs, const std::vector<engine::case_value>& cases,
                                                  const std::string& tag, bool must) const;
    /// A case's condition, `lhs \leq rhs`: in the declared quantities when short, else as
    /// the file writes it.
    std::string case_condition(const engine::case_value& c) const;
    /// A case's condition as the file writes it.
    std::string written_condition(const engine::case_value& c) const;
    std::string yields(const engine::step_result& s) const;
    std::string quotient_step(const engine::step_result& s, const spec::step* source,
                              const std::string& because) const;
    std::string rearrange_step(const engine::step_result& s, const spec::step* source,
                               const std::string& because) const;
    std::string results() const;
    const engine::result& shown_as(const engine::result& r) const;
    const engine::step_result* defining_step(const GiNaC::ex& symbol) const;
    /// `\ref` to `r` as the results number it (its paper's place), when they show it under
    /// its own tag; none otherwise.
    std::optional<std::string> result_ref(const engine::result& r) const;
    /// result_ref, and the quantity beside it when other results share its tag (Eq. 9's six
    /// rows): "Eq. (9), $v'_{M,x}$". For a step, whose reader looks below for one row.
    std::optional<std::string> result_cited(const engine::result& r) const;
    std::string places(const engine::result& first) const;

    // latex_claims.cpp: the checks; latex_paper.cpp: the paper held to account (displayed,
    // form, paper, checked_display).
    std::string how(const engine::check_result& c) const;
    std::string unsettled_text(const engine::verdict& v) const;
    std::string sign_text(const engine::sign_step& step) const;
    std::string limit_text(const engine::limit_method& how) const;
    std::string display(const std::string& lhs, const char* relation, const GiNaC::ex& rhs,
                        const written_form* w) const;
    std::string claim_lhs(const engine::check_result& c, const written_form* w) const;
    std::string checks() const;
    std::string check_label(const engine::check_result& c) const;
    bool displayed(const GiNaC::ex& e, const written_form* w) const;
    std::string form(const GiNaC::ex& e, const written_form* w) const;
    std::string paper() const;
    /// `textbook_form` of `e` in this derivation's order, kept once made: the steps, cases
    /// and results ask for the same values again (the rough spheres' cases are factored
    /// for whether they fit, then for their rows, then again in the results).
    const textbook_value& textbook(const GiNaC::ex& e) const;

    // latex_errata.cpp: the paper held to account, in the errata table.
    enum class finding_kind { all, dimensions, changes };
    std::string findings(const engine::paper_comparison& p, finding_kind which = finding_kind::all) const;
    std::string subject(const engine::paper_comparison& p) const;
    std::string shown(const GiNaC::ex& e, const written_form* w) const;
    std::string as_printed(const engine::paper_comparison& p) const;
    std::string unreconciled(const engine::paper_comparison& p, double width) const;
    std::string shown_as_printed(const engine::paper_comparison& p) const;
    std::string read_as(const engine::paper_comparison& p) const;
    std::string checked_display(const engine::check_result& t) const;
    std::pair<GiNaC::ex, const written_form*> derived_form(const engine::paper_comparison& p) const;
    // The text width of the report (A4, 2 cm margins: 482 pt) less a list's indent: steps
    // and checks are items of a list.
    static constexpr double content_width = 450;

    const engine::derivation& d_;
    const engine::derived_by_id* used_;
    const term_order order_;
    std::map<std::string, std::string> tags_;
    mutable std::map<GiNaC::ex, textbook_value, GiNaC::ex_is_less> textbooks_;
    /// `math` of an expression as it is (no written form), kept once printed: a check proven
    /// case by case prints each case's value to measure it, and the rough spheres' hundred
    /// checks share the same cases.
    mutable std::map<GiNaC::ex, std::string, GiNaC::ex_is_less> printed_;
};

} // namespace impact::emit::detail
