// What the files of prove.h share (prove.cpp: equalities; inequality.cpp: inequalities;
// sampling.cpp: claims tested at points of the domains): a claim's abbreviations spelled
// out, and a claim tested at sampled points when no proof is found. Internal to
// engine/prove.
#pragma once

#include "engine/prove/prove.h"

#include <ginac/ginac.h>

#include <functional>
#include <optional>
#include <string>

namespace impact::engine {

/// `e` with its abbreviations replaced by their definitions (prove.cpp).
GiNaC::ex spelled_out(const GiNaC::ex& e, const GiNaC::exmap& abbreviations);

/// Both sides evaluated at sampled points of the declared domains where the conditions
/// `where` hold, `holds` tested on them: `failed` at the first point where it does not
/// hold, or where a side is undefined or not real, else `sampled` (sampling.cpp).
verdict sample(const GiNaC::ex& lhs, const GiNaC::ex& rhs, const GiNaC::ex& residual, const symbol_table& symbols,
               const std::function<bool(const GiNaC::numeric&, const GiNaC::numeric&)>& holds,
               const std::string& claim, const std::vector<condition>& where);

/// The simple values of a domain a reader can check by hand, in the order they are tried:
/// its ends and middle for an interval, else 1, 2, 1/2, 3 (and 0, -1, -2 where they lie in
/// it) (sampling.cpp).
std::vector<GiNaC::numeric> simple_values(const domain& range);

/// The values of `s` at which an inequality whose difference of sides is `difference`, a
/// rational function of `s` alone with rational coefficients, may fail although random
/// points miss them: the roots of its numerator's factors of degree 1 and 2, a point
/// between each two real roots of its numerator and denominator (Sturm's theorem), and the
/// domain's ends; those in `range`. None when `difference` is no such function
/// (real_roots.cpp).
std::vector<GiNaC::ex> points_beside_roots(const GiNaC::ex& difference, const GiNaC::ex& s, const domain& range);

/// Whether two numbers differ by at most 1e-30 times the larger of 1, |a| and |b| (sampling.cpp).
bool nearly_equal(const GiNaC::numeric& a, const GiNaC::numeric& b);

} // namespace impact::engine
