// What the proofs about cases share (cases.h): a case's condition as C >= 0, the constant
// ratio of two conditions, whether a case can arise under given domains, and the verdict
// of parts combined. Defined in case_proofs.cpp; used by exhaustive.cpp, in_case.cpp,
// case_by_case.cpp and continuity.cpp.
#pragma once

#include "engine/cases/cases.h"

#include <optional>
#include <string>
#include <vector>

namespace impact::engine::cases_detail {

// The condition as `C >= 0` (or `C > 0` when `strict`).
struct nonnegative_form {
    GiNaC::ex value;
    bool strict = false;
};

nonnegative_form condition_form(const case_value& c);

// A non-zero rational k with a = k b, if there is one.
std::optional<GiNaC::numeric> constant_ratio(const GiNaC::ex& a, const GiNaC::ex& b);

// The weakest of the parts: failed if one failed, sampled if one was sampled.
verdict combined(const std::vector<check_result::part>& parts, const std::string& what);

// The condition of `c` proven false under `given`: the case does not arise. Asked where a
// condition may have become one the domains decide (at special values, for a sign of
// what is under |.|), and only of a condition whose factors are sums of a few terms or
// multiples of an abbreviation of declared sign (the spheres approach: mu (1 + eps) D_t s_n
// at b = -1): a sign proof of a long sum that holds somewhere costs seconds and finds
// nothing.
bool cannot_arise(const case_value& c, const symbol_table& symbols, const assumptions& given);

} // namespace impact::engine::cases_detail
