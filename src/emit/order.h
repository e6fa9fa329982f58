// A deterministic order for the terms and factors Impact prints.
//
// GiNaC orders the operands of sums and products by hash values that derive from
// addresses, so the same expression prints differently from one run to the next, and
// even chooses a different sign for a sum inside a product ((v_m - v_M) or
// -(v_M - v_m)). Every emitter prints through `term_order` instead: symbols rank in the
// order the derivation file declares them, numbers come first, and a sum inside a
// product is written with its first term positive. Output is then byte-identical
// from run to run.
#pragma once

#include "engine/derive.h"

#include <ginac/ginac.h>

#include <string>
#include <vector>

namespace impact::emit {

class term_order {
public:
    /// Symbols in rank order (the derivation file's declaration order).
    explicit term_order(std::vector<GiNaC::ex> symbols);

    /// The operands of a sum, ordered.
    std::vector<GiNaC::ex> terms(const GiNaC::ex& sum) const;

    /// The factors of a product, ordered, with each sum factor raised to an odd integer
    /// power written with its first term positive; `negated` tells whether the signs
    /// so moved multiply to -1.
    std::vector<GiNaC::ex> factors(const GiNaC::ex& product, bool& negated) const;

    /// A product written as ± numerator / denominator: the number's numerator and
    /// denominator first, factors with negative exponents in the denominator.
    struct fraction {
        bool negated = false;
        std::vector<GiNaC::ex> numerator;
        std::vector<GiNaC::ex> denominator;
    };
    fraction split(const GiNaC::ex& product) const;

    /// True when a term of a sum is written with a minus sign in front: a negative
    /// number, or a product whose `split` is negated.
    bool negative(const GiNaC::ex& term) const;

    /// True when a sum's first term (in this order) has a negative coefficient.
    bool leads_negative(const GiNaC::ex& sum) const;

    /// The sort key of an expression: a string that compares in print order.
    std::string key(const GiNaC::ex& e) const;

private:
    std::vector<GiNaC::ex> symbols_;
};

/// The order of a derivation's declared symbols.
term_order declaration_order(const engine::derivation& d);

} // namespace impact::emit
