// Where an expression is defined in the reals, and what a claim rests on.
//
// A claim holds only where both its sides are real numbers: where each divisor is not 0,
// each radicand and the base of each fractional power is ≥ 0, each logarithm's argument
// is > 0 and each acos's or asin's argument lies in [−1, 1]. These conditions are read off
// the expression twice: as the file writes it (written_form's tree, before GiNaC simplifies
// anything: exp(log(x)) is x to GiNaC, but x > 0 to the reader) and as derived (the
// divisors of a solve's solution). Each is then proven from the domains and assumptions,
// or attached to the claim: "proven, where x != y" promises the claim wherever x != y,
// and nothing where x = y.
#pragma once

#include "engine/expr/symbols.h"
#include "engine/prove/condition.h"
#include "engine/expr/written_form.h"
#include "engine/prove/sign.h"

#include <ginac/ginac.h>

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace impact::engine {

/// A condition's expression as the two sides it is written with: its positive terms on the
/// left, its negative ones, negated, on the right (x - y: x and y; -u^2 + 1: 1 and u^2).
std::pair<GiNaC::ex, GiNaC::ex> condition_sides(const GiNaC::ex& expr);

/// `x != y`, `p > 0`, `1 >= u^2`: each condition as a relation between its positive and
/// negative terms, written with `symbols` (the same text on every run).
std::string condition_text(const GiNaC::ex& expr, condition::kind need, const symbol_table& symbols);

/// The conditions under which `e` is defined in the reals, as it stands (after GiNaC has
/// simplified it): divisors, radicands, fractional powers, and the arguments of log,
/// acos, asin, acosh, atanh, tan and atan2. Texts are written with `symbols`.
std::vector<condition> definedness(const GiNaC::ex& e, const symbol_table& symbols);

/// The same conditions read off a text as written (written_form's tree): those GiNaC's
/// simplification hides (exp(log(x)) = x, (x - y)^2/(x - y) = x - y) are kept. Nothing
/// when the tree is empty.
std::vector<condition> definedness(const written_form& written, const symbol_table& symbols);

/// Appends `more` to `into`, leaving out those already there (e and -e are one divisor); of
/// one condition in two forms, the one of shorter text stays, whichever came first.
void add_conditions(std::vector<condition>& into, const std::vector<condition>& more);

/// `needs` with each condition's expression rewritten by `into` (derived quantities put
/// in, a check's special values): conditions on inputs. Those that become numbers are
/// dropped when they hold; one that fails stays (`0 != 0`), which no proof can meet.
std::vector<condition> rewritten(const std::vector<condition>& needs,
                                 const std::function<GiNaC::ex(const GiNaC::ex&)>& into, const symbol_table& symbols);

/// Conditions split into those proven from `given` and those that are not (attached to
/// what needs them): a condition on one symbol narrows its domain for those after it
/// (p >= 0 and p != 0: p > 0), so that x*y > 0 follows from x > 0 and y > 0.
struct settled_conditions {
    std::vector<condition> proven;
    std::vector<condition> attached;
    /// Attached conditions the domains prove false everywhere (sqrt(-h) for h > 0): what
    /// needs them is defined nowhere, and a claim about it is refuted, not proven.
    std::vector<condition> never;
};
settled_conditions settle(const std::vector<condition>& needs, const assumptions& given);

/// `given` narrowed by attached conditions: a symbol's domain where the condition is on
/// the symbol alone (p >= 0 with p != 0 is p > 0; x real with x > 0 is x > 0), and an
/// assumed sign for a sum. What is worked out under it starts afresh.
assumptions where(const assumptions& given, const std::vector<condition>& attached);

/// Whether every condition holds at a point (each evaluated at 40 digits): a condition
/// that cannot be evaluated there does not.
bool hold_at(const std::vector<condition>& conditions, const GiNaC::exmap& point);

/// "x != y, p > 0": the conditions' texts, joined.
std::string to_string(const std::vector<condition>& conditions);

} // namespace impact::engine
