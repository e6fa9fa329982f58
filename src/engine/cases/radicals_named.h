// Square roots that are abbreviations, named as quantities of their own, for the proofs of a
// claim in a case (in_case.cpp) and of continuity (continuity.cpp).
#pragma once

#include "engine/derivation/derivation.h"

#include <ginac/ginac.h>

#include <map>
#include <string>
#include <vector>

namespace impact::engine::cases_detail {

// Each square root that is an abbreviation's definition (d = sqrt(r.r), G_t = sqrt(G_t.G_t))
// written as a quantity of its own, named as the abbreviation: a new symbol (the
// abbreviation's own would be replaced by its definition again), >= 0, or > 0 where its
// radicand is proven positive. A claim proven under a case's condition for every value
// of such a quantity is proven for its own value in particular, and the proof never
// expands the radicand's square (in space a polynomial of hundreds of terms).
class radicals_named : public GiNaC::map_function {
public:
    // Only roots of radicands proven >= 0 (a sum of squares): a radicand that may be
    // negative, written as the square of its root, would be taken for >= 0.
    radicals_named(const symbol_table& symbols, const assumptions& given);

    GiNaC::ex operator()(const GiNaC::ex& part) override;

    /// `given` with the domains of the roots used: >= 0, > 0 where declared or where the
    /// radicand is proven > 0.
    assumptions with_domains(const assumptions& given, std::vector<std::string>& words) const;

    bool any_used() const;

private:
    struct root {
        GiNaC::ex radicand;   // in the inputs, expanded
        quantity of;
        GiNaC::ex atom;
        bool used;
    };
    std::vector<root> roots_;
    std::map<GiNaC::ex, std::size_t, GiNaC::ex_is_less> match_;
};

} // namespace impact::engine::cases_detail
