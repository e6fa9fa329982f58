// A proven claim written as an SMT-LIB 2 problem, for Z3 to check again (issue 59).
//
// The problem asserts what the claim may assume and then the claim's negation; `unsat`
// means no real values meet the assumptions and break the claim. What it asserts:
//
// - each symbol's declared domain (positive: x > 0, an interval by its exact bounds), a
//   check's narrowed domains (`assuming`), and each abbreviation it uses as its definition
//   (s = definition) with the abbreviation's own domain; an abbreviation declared with a
//   domain is an assumption of every claim (s_n > 0: the spheres approach), asserted in
//   every problem, used or not;
// - where the sides are defined: every divisor B != 0 and every radicand X >= 0, the
//   claim being about the values where both sides are real (what Impact's proofs promise;
//   the definedness conditions a verdict proves, `verdict::defined`, are checked as goals);
// - the hypotheses: the conditions a verdict is promised under (`verdict::where`) and the
//   condition of the case a part is proven in;
// - the negation: (not (lhs op rhs)), or'ed with the negation of each goal;
// - `(check-sat-using qfnra-nlsat)`: Z3's procedure for nonlinear real arithmetic, named so
//   that no wall-clock switch between procedures decides the answer.
//
// Z3's real arithmetic has no sin, log or Pi: a claim with them is "not expressible", with
// the first such thing named. 1/B is a fresh variable q with B != 0 => q*B = 1 (SMT-LIB's
// division by a non-constant is unspecified at 0, so `/` divides only numbers); X^(p/q) a
// fresh r >= 0 with X >= 0 => r^q = X^p; |x| an ite on the sign of x. The text is the same
// on every run: terms and factors in the derivation's declaration order (engine::term_order).
#pragma once

#include "engine/expr/symbols.h"
#include "engine/prove/definedness.h"

#include <ginac/ginac.h>

#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace impact::verify {

/// A relation `lhs op rhs` that a problem assumes.
struct smt_relation {
    GiNaC::ex lhs;
    engine::relation op = engine::relation::equal;
    GiNaC::ex rhs;
};

/// What one problem checks: the claim `lhs op rhs` in the declared quantities (abbreviations
/// may remain), under `hypotheses`, together with `goals` (conditions the claim's proof says
/// hold, each checked as the claim is).
struct smt_claim {
    GiNaC::ex lhs;
    engine::relation op = engine::relation::equal;
    GiNaC::ex rhs;
    std::vector<std::pair<GiNaC::ex, std::string>> assuming;   ///< narrowed domains, as check_result::assuming
    std::vector<smt_relation> hypotheses;                      ///< a case's condition
    std::vector<engine::condition> where;                      ///< verdict::where: assumed
    std::vector<engine::condition> goals;                      ///< verdict::defined: checked
    /// When not empty, the claim is that one of these holds (the cases of a quantity
    /// cover every value), and `lhs op rhs` is not used.
    std::vector<smt_relation> any_of;
    /// Quantities that have no value of their own in a problem (derived ones, defined by
    /// cases): one left in the claim makes it not expressible rather than free.
    std::set<std::string> derived;
};

/// The problem, or why Z3's real arithmetic cannot state it.
struct smt_problem {
    std::string text;             ///< declarations, assertions and (check-sat); empty when not expressible
    std::string not_expressible;  ///< e.g. "not expressible: acos"; empty when `text` is the problem
};

/// `claim` as an SMT-LIB 2 problem over `symbols` (its domains and abbreviations).
smt_problem smt_problem_of(const smt_claim& claim, const engine::symbol_table& symbols);

} // namespace impact::verify
