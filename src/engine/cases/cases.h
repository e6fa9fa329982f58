// Quantities defined by cases (`define` with `cases`): what is proven about them.
//
// A value such as sticking and sliding friction, J_t = (1 + b) m_t g_t where
// (1 + b) m_t g_t <= mu J_n and mu J_n otherwise, is kept as its cases, each a value and
// a condition `lhs op rhs` (an inequality of the derivation's quantities). Three things
// are proven about it:
//
// - that the cases leave no value out: the conditions are proven exhaustive when every
//   one is the sign of one expression D (each condition's lhs − rhs a non-zero constant
//   multiple of D) and together they cover D < 0, D = 0 and D > 0; otherwise the step's
//   check fails, saying so. Where conditions overlap (<= and >=) the first case listed
//   applies, as the kernel's select does;
// - a check that involves the quantity, case by case: the case's value substituted, the
//   claim proven under the case's condition (see prove_in_case);
// - continuity, where a check asks for it: for each two cases whose conditions share
//   their boundary D = 0, D is solved for a symbol in which it is linear, and the two
//   values, substituted there, are proven equal.
#pragma once

#include "engine/derivation/derivation.h"

#include <functional>
#include <string>
#include <vector>

namespace impact::engine {

/// `select_positive(c, a, b)`: a where c > 0, b otherwise. A kernel computes a quantity
/// defined by cases as nested selects (see select_of), compiled to the `select` operation.
DECLARE_FUNCTION_3P(select_positive)

/// The cases as one expression of selects, the first case whose condition holds chosen:
/// a strict condition C > 0 as select_positive(C, value, rest), a non-strict C >= 0 as
/// select_positive(-C, rest, value); the last case is what is left (the step proves the
/// cases exhaustive).
GiNaC::ex select_of(const std::vector<case_value>& cases);

/// Whether `e` is a select_positive, and whether it holds one.
bool is_select(const GiNaC::ex& e);
bool has_select(const GiNaC::ex& e);


/// The check that the conditions of `cases` (for the quantity `name`) cover every value.
check_result prove_exhaustive(const std::string& name, const std::vector<case_value>& cases,
                              const symbol_table& symbols);

/// Decides `lhs op rhs` in the case `c` (the case's value already substituted): proven
/// when it follows from the domains alone, or from the condition C >= 0 (or > 0, with C
/// its lhs − rhs turned the right way) through the claim's difference G as G = q·C with
/// q's sign proven non-negative (positive for a strict claim from a non-strict
/// condition), or G = C + r with r's sign proven non-negative, or, when the condition is
/// a bound of one symbol by a number (`x <= 1`), from the signs under that symbol's
/// domain narrowed by it (x in (0, 1] for a positive x); otherwise the verdict of
/// the domains alone: sampled when samples of the whole domain hold (never proven), failed
/// when they do not (which may be outside the case: the method says the claim was not
/// proven under the condition).
verdict prove_in_case(const GiNaC::ex& lhs, relation op, const GiNaC::ex& rhs, const case_value& c,
                      const symbol_table& symbols, const assumptions& given);

/// The continuity check of the quantity `name`: its values agree where two cases meet.
/// Throws `impact::error` at `where` when no two cases share a boundary.
check_result prove_continuity(const std::string& name, const std::vector<case_value>& cases,
                              const symbol_table& symbols, proof_cache& run, const source_location& where);

/// The quantities a check splits on: one defined by cases, or several whose cases have
/// the same conditions (J_t and the effective restitution of sticking and sliding).
struct case_split {
    std::vector<GiNaC::ex> symbols;
    std::vector<std::vector<case_value>> pieces;   ///< each symbol's cases, in its order
    /// How many of `symbols` are named in each case's text; those after them are the same
    /// quantities at a symmetry's changed inputs (`left_at`), in the same case.
    std::size_t named = static_cast<std::size_t>(-1);
};

/// True when the two lists of cases have the same conditions, in the same order.
bool same_conditions(const std::vector<case_value>& a, const std::vector<case_value>& b);

/// Proves the check `c` (its sides already resolved) case by case: in each case every
/// quantity of `split` replaced by its value there (and `at`'s special values put into
/// the case), the claim proven under the case's condition. A case whose condition is
/// proven false (at the special values, or under the domains) holds nothing to prove.
/// `prove`, when given, decides each case's claim (its sides with the case's values) in
/// place of an identity or inequality: a limit, proven in every case that arises near its
/// point, whatever its condition. A case whose condition's side (C in C >= 0) tends to
/// -infinity or to a negative value there does not arise near it (sliding as mu -> infinity).
void prove_case_by_case(check_result& c, const case_split& split, const GiNaC::exmap& at,
                        const symbol_table& symbols, const assumptions& given, proof_cache& run,
                        const std::function<verdict(const GiNaC::ex&, const GiNaC::ex&)>& prove = {},
                        const std::optional<check_result::limit_point>& near = std::nullopt);

/// The verdict of a check proven case by case: failed if a case failed, sampled if one was
/// sampled, proven if every case was; its method lists each case's.
verdict combine_cases(const std::vector<check_result::part>& parts);

/// "lhs <= rhs" in the file's syntax.
std::string condition_text(const case_value& c, const term_order& order);

} // namespace impact::engine
