// Dimensional analysis of a derivation: every symbol's dimension declared or inferred,
// every equation, value and claim checked for consistent dimensions, and the paper's
// printed forms compared in dimension with what they print (engine/dimension/dimension.h holds the
// algebra and the rules).
//
// A derivation file without dimensions still derives: a symbol without one makes what
// holds it of unknown dimension, and only what is known is checked.
#pragma once

#include "engine/dimension/dimension.h"
#include "engine/expr/finding.h"
#include "engine/expr/symbols.h"
#include "spec/derivation.h"

#include <ginac/ginac.h>

#include <optional>
#include <string>
#include <vector>

namespace impact::engine {

/// The derivation's own `[[dimension]]`s, added to the words its symbols may use.
void add_dimensions(symbol_table& symbols, const std::vector<spec::dimension>& added);

/// Each abbreviation (`definition`) gets the dimension of its definition; one that also
/// declares a dimension must agree with it, else an error at the definition.
void infer_definitions(symbol_table& symbols, const spec::derivation& source);

/// Both sides of an equation or inequality, and every sum in it, of one dimension.
void check_relation(const symbol_table& symbols, const GiNaC::ex& relation, const source_location& where);

/// An expression's sums, functions and powers consistent; its dimension when known.
std::optional<dimension> check_expression(const symbol_table& symbols, const GiNaC::ex& e,
                                          const source_location& where);

/// `symbol` takes `value` (a step solves or defines it, or a result's display form shows
/// it): the value's dimension must be the symbol's declared one; a symbol without one takes
/// the value's. `what` names the value in the message ("the value derived for it").
void check_value(symbol_table& symbols, const GiNaC::ex& symbol, const GiNaC::ex& value,
                 const source_location& where, const char* what = "the value derived for it");

/// A printed form (of the paper) set against what it should equal: nothing when their
/// dimensions agree or are unknown, else the finding in words, e.g. "dimensionally
/// inconsistent: a momentum (mass*length/time) where an energy (mass*length^2/time^2)
/// belongs". A printed form inconsistent in itself (a sum of two dimensions) is reported
/// with the rule it breaks.
std::optional<finding> printed_dimension_finding(const symbol_table& symbols, const GiNaC::ex& printed,
                                                     const GiNaC::ex& derived);

/// The names of the symbols that have no dimension, declared or inferred.
std::vector<std::string> symbols_without_dimension(const symbol_table& symbols);

} // namespace impact::engine
