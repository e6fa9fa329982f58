// The single edits of a printed form that reconcile.cpp tries (reconcile.h): the sign of
// the whole or of one term, one symbol written for another, a spurious symbol, two symbols
// swapped, the squares of one dimension missing, the primes missing, a factor of 2, the
// reciprocal; each a candidate with its priority (the size of the change) and the words
// that describe it, written only for an edit that reconciles.
#pragma once

#include "engine/expr/finding.h"
#include "engine/expr/symbols.h"

#include <ginac/ginac.h>

#include <functional>
#include <set>
#include <string>

namespace impact::engine::reconcile_detail {

struct candidate {
    int priority;            ///< smaller is a smaller change
    std::function<finding()> change;  ///< described only if it reconciles (printing costs)
    GiNaC::ex edited;
};

// Every single edit of `e`; `side` prefixes the descriptions ("on the left, ").
void single_edits(const GiNaC::ex& e, const std::string& side, const std::set<std::string>& wanted,
                  const symbol_table& symbols, const std::function<void(candidate)>& emit);

} // namespace impact::engine::reconcile_detail
