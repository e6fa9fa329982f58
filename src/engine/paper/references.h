// The paper held to account in its words rather than its mathematics: the claims no
// derivation settles (undecided, with why), and the entries of its list of references,
// each checked against the places that cite it.
#pragma once

#include "spec/derivation.h"

#include <string>
#include <vector>

namespace impact::engine {

/// One row of the errata that compares words: what the paper prints there, the verdict,
/// and the finding (how agreement was established, what is wrong, or why it is undecided).
struct text_comparison {
    enum class kind { claim, reference };
    enum class outcome { agrees, disagrees, undecided };
    kind what = kind::claim;
    std::string subject;      ///< the claim's name, or "reference 4"
    std::string paper;        ///< its place, e.g. `Footnote 4`
    std::string printed;      ///< the paper's words: a claim's quote, or a reference's entry
    outcome verdict = outcome::undecided;
    std::string finding;
    source_location where;
};

/// "agrees", "disagrees" or "undecided", as the errata says it.
const char* to_string(text_comparison::outcome verdict);

/// A reference's authors: the names before the entry's first period that ends a word of
/// more than one letter ("B. Smith" keeps its initial), split at commas and "and".
std::vector<std::string> reference_authors(const std::string& entry);

/// The derivation file's words compared, in its order: its undecided claims, then its
/// references. A reference agrees when a citation of the file cites it, each citation
/// that names an author names one of its authors, it names each author once, and it
/// prints a year; otherwise it disagrees, each fault said.
std::vector<text_comparison> text_comparisons(const spec::derivation& d);

} // namespace impact::engine
