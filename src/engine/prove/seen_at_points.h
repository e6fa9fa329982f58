// Expressions evaluated exactly at points of the domains, to see at once that a sign cannot
// be proven, so that the searches that would find none are not made: a polynomial > 0 at one
// point and < 0 at another is 0 between them (the domains are intervals, and the segment
// between two of their points stays in them), and e >= 0 false at one point of the domains
// is no claim a sound proof establishes. What is seen is never a proof: a sign is proven only
// by the arguments of sign.h.
#pragma once

#include "engine/prove/sign.h"

#include <ginac/ginac.h>

#include <optional>
#include <vector>

namespace impact::engine {

/// Up to `count` points of the domains of `e`'s symbols, drawn from simple values of each
/// (1, 2, 1/2, 3, 1/3, ... of both signs where the domain holds them; an interval's ends and
/// inner points) by a generator of fixed seed, the symbols taken by name: the same points on
/// every run. A point where an abbreviation declared with a domain (assumptions::assumed),
/// defined in `e`'s symbols, lies outside it is passed over. None at all when a symbol has no
/// domain (an abbreviation's own symbol has one only where a proof gives it one, as a square
/// root named), or an abbreviation is defined partly in `e`'s symbols and partly in others.
std::vector<GiNaC::exmap> points_of_domains(const GiNaC::ex& e, const assumptions& given, int count);

/// `e` at `at`, exactly: none where it is not a real rational number (a pole, a root).
std::optional<GiNaC::numeric> exact_value(const GiNaC::ex& e, const GiNaC::exmap& at);

/// Whether `e`, a polynomial, is seen > 0 at one point of the domains and < 0 at another.
bool seen_of_both_signs(const GiNaC::ex& e, const assumptions& given);

/// Whether `e`, a rational function, is seen < 0 at a point of the domains (or 0, when
/// `positive`, e > 0, is what a proof would need): then no sign proof shows e >= 0 (> 0).
bool seen_against(const GiNaC::ex& e, bool positive, const assumptions& given);

} // namespace impact::engine
