// Errata emitter: every printed equation and claim of the paper with its verdict,
// as `output/errata.md`.
#pragma once

#include "engine/derivation/derivation.h"
#include "engine/paper/references.h"
#include "spec/outline.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace impact::emit {

/// The errata table in Markdown: a row per finding, that is per claim of the text and
/// per printed form, the components of one equation that one misprint explains together
/// in one row (`errata_rows`), and a row per claim no derivation settles (undecided); in
/// the paper's order when `outline` gives it (errata_entries).
std::string errata_markdown(const std::vector<const engine::derivation*>& derivations,
                            const spec::paper_outline* outline = nullptr);

/// One row of the errata: comparisons of one derivation shown together (`errata_rows`),
/// or one comparison of its words (a claim no derivation settles, a reference).
struct errata_entry {
    const engine::derivation* derivation = nullptr;
    std::vector<std::size_t> comparisons;   ///< into `paper_checks`; empty for `words`
    std::optional<engine::text_comparison> words;

    /// Its place in the paper ("Eq. 8, right, line 1").
    const std::string& place() const;
};

/// Every row of the errata. With an outline, in the order of the places it lists, as the
/// paper prints them (rows at one place in derivation order); a row at a place the outline
/// does not list is an error at its comparison in the derivation file. Without one,
/// derivation by derivation, each's comparisons then its undecided claims.
std::vector<errata_entry> errata_entries(const std::vector<const engine::derivation*>& derivations,
                                         const spec::paper_outline* outline);

/// The rows of the errata for one derivation's comparisons (`paper_checks`), each the
/// indices of the comparisons it shows: one comparison, the components of one printed
/// equation that disagree with the same finding (one misprint, Eq. 9's lab components),
/// or, with `claims_of_one_quote`, the claims checked of one quote at one place (the Fig. 2
/// caption's "increasing values", checked panel against panel; Appendix A's chains,
/// member against member), one finding about what the paper says there.
std::vector<std::vector<std::size_t>> errata_rows(const engine::derivation& d, bool claims_of_one_quote = true);

/// What the claims checked of one quote come to, from what each check came to ("proven",
/// "as checked, it does not hold", ...): said once when all are the same ("both proven",
/// "as checked, neither holds"), else each in turn ("the 1st check: ...; the 2nd check: ...").
/// With `agrees` (one per check), when some agree and some do not: only those that do not,
/// then the others named ("...; the 1st and 3rd checks agree with the paper"). With
/// `labels` (one per check, "" for none), a labelled check is named by its label ("the
/// contrapositive: it holds, ...").
std::string one_finding(const std::vector<std::string>& each, const std::vector<bool>& agrees = {},
                        const std::vector<std::string>& labels = {});

/// one_finding of the claims of one quote, what each came to said by `change_of`, with
/// whether each agrees and its label.
std::string one_finding(const std::vector<const engine::paper_comparison*>& claims,
                        const std::function<std::string(const engine::paper_comparison&)>& change_of);

/// The verdict of a row: "disagrees" when one of its comparisons disagrees, otherwise
/// "undecided" when one is, otherwise "agrees".
std::string row_verdict(const engine::derivation& d, const std::vector<std::size_t>& row);

/// The paper's lines and claims as the derivation files account for them.
struct paper_count {
    std::size_t lines = 0;      ///< places compared and places listed as not compared
    std::size_t compared = 0;   ///< places compared (checked, or a claim no derivation settles)
    std::size_t rows = 0;       ///< rows of the errata: findings
    std::size_t agree = 0;
    std::size_t disagree = 0;
    std::size_t undecided = 0;  ///< sampled only, or a claim no derivation settles
    std::vector<const spec::not_compared*> not_compared;
};
paper_count count_paper(const std::vector<const engine::derivation*>& derivations);

/// True where a derivation has a place in the paper (a top-level `paper`): the errata and
/// the report are then the paper's; otherwise those of a folder of one's own, which speak
/// of "the text" its files transcribe (a textbook's claims, say), not of the paper.
bool of_the_paper(const std::vector<const engine::derivation*>& derivations);

/// " Not compared: <place> (<why>); <place> (<why>)." for the lines `n` counts as not
/// compared, each place and reason set by `place` and `why` (plain, or LaTeX); empty when
/// every line is compared.
std::string not_compared_sentence(const paper_count& n, const std::function<std::string(const std::string&)>& place,
                                  const std::function<std::string(const std::string&)>& why);

/// How many printed lines and claims of the paper `derivations` compare: the distinct
/// places (`paper`) their comparisons and their undecided claims name. A place is one printed line of a displayed
/// equation ("Eq. 12, line 2"), an equation or a sentence of the text ("Sec. III C,
/// after Eq. 14, 5th sentence"), a footnote; several comparisons may name one place (a
/// vector's components, two claims of one sentence). The lines no derivation compares are
/// named by `[[not_compared]]`; tests/test_paper_lines.cpp lists them all, typed from the
/// paper.
std::size_t compared_places(const std::vector<const engine::derivation*>& derivations);

} // namespace impact::emit
