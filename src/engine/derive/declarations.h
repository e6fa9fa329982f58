// What a derivation file declares must agree with itself: a definition takes values its
// symbol's domain allows, a special value (`at`) or a limit point lies where its symbol
// can be, and an assumption (`assuming`) narrows a domain rather than leaving it.
//
// Each disagreement is a mistake in the file, reported as an error at the place it is
// written, before any check is run on a premise that cannot hold.
#pragma once

#include "engine/expr/domain.h"
#include "engine/prove/sign.h"
#include "engine/expr/symbols.h"
#include "spec/derivation.h"

#include <ginac/ginac.h>

#include <map>
#include <optional>
#include <string_view>
#include <vector>

namespace impact::engine {

/// Every `[[symbol]]` with both a `definition` and a domain other than `real`: the
/// definition's sign, proven from the other symbols' domains, must not contradict it
/// (a positive `w` defined as `-x` with `x` positive is refused).
void check_definitions(const symbol_table& symbols, const spec::derivation& source, proof_cache& run);

/// The assumptions hold together: the domains given beside definitions (`s_n` positive: the
/// spheres approach; `d` positive: the centres apart) hold at one point of the inputs'
/// domains as `given` has them, or every claim proven under them would be proven of
/// nothing. A witness is searched among 2000 points drawn over twelve decades either side of
/// 1, zero and the ends of intervals among them: one found shows them consistent. When none
/// satisfies the first k in the order they are declared, the k-th is refused if its
/// definition is proven of another sign under the domains and the k - 1 before it (at its
/// domain, or at `check`, the place of a check's `assuming` whose domains `given` holds);
/// a set neither shown consistent nor proven contradictory is let through.
void check_assumptions_hold_together(const symbol_table& symbols, const spec::derivation& source,
                                     const assumptions& given,
                                     const std::optional<source_location>& check = std::nullopt);

/// `at = { x = "value" }`: a numeric value must lie in the closure of x's domain.
void check_special_value(const quantity& q, const GiNaC::ex& value, const source_location& where);

/// `left_at = { x = "value" }`, and `at` with a value not a number: a claim simplified under
/// the domains (sqrt(x^2) = x for x positive) says nothing where the values move the inputs
/// outside them. Refused where a value is proven outside its input's domain, or the values
/// move the inputs to where an assumption a definition's domain makes (`s_n` positive) is
/// proven false; where neither is shown inside, the conditions returned ("u/g >= 0") are
/// the claim's, said with it. `field` names the field in an error; `places` where each
/// value is written.
using moved_places = std::map<GiNaC::ex, source_location, GiNaC::ex_is_less>;
std::vector<std::string> check_moved_inputs(const symbol_table& symbols, const GiNaC::exmap& moved,
                                            const assumptions& given, const moved_places& places,
                                            std::string_view field);

/// `limit = "x -> point"`: a numeric point must lie in the closure of x's domain, and
/// `infinity` needs a domain unbounded above.
void check_limit_point(const quantity& q, const GiNaC::ex& point, bool to_infinity, const source_location& where);

/// `assuming = { x = "domain" }`: the domain, which must lie inside x's declared one.
domain narrowed_domain(const quantity& q, const spec::text& written);

} // namespace impact::engine
