// A deterministic order for the terms and factors Impact prints.
//
// GiNaC orders the operands of sums and products by hash values that derive from
// addresses, so the same expression prints differently from one run to the next, and
// even chooses a different sign for a sum inside a product ((v_m - v_M) or
// -(v_M - v_m)). Every emitter prints through `term_order` instead: symbols rank in the
// order the derivation file declares them, numbers come first, and a sum inside a
// product or a power is written with its first term positive. Output is then
// byte-identical from run to run.
//
// A power of a sum is never rebuilt as a GiNaC power to print it: GiNaC would choose
// the sign of the base again. Factors travel as (base, exponent) pairs instead.
#pragma once

#include "engine/expr/symbols.h"

#include <ginac/ginac.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace impact::engine {

class term_order {
public:
    /// Symbols in rank order (the derivation file's declaration order).
    explicit term_order(std::vector<GiNaC::ex> symbols);

    /// The operands of a sum, ordered.
    std::vector<GiNaC::ex> terms(const GiNaC::ex& sum) const;

    /// A factor as base^exponent (exponent 1 for a plain factor).
    struct power_term {
        GiNaC::ex base;
        GiNaC::ex exponent;
    };

    /// A factor with a sum as its base (alone, or raised to an integer power) turned
    /// so that the sum's first term is positive; an odd power so turned, or a negative
    /// number, flips `negated`.
    power_term oriented(const GiNaC::ex& factor, bool& negated) const;

    /// The factors of a product, oriented and ordered; `negated` tells whether the
    /// signs moved out multiply to -1.
    std::vector<power_term> factors(const GiNaC::ex& product, bool& negated) const;

    /// A product written as ± numerator / denominator: the number's numerator and
    /// denominator first, factors with negative exponents in the denominator (with
    /// their exponents made positive).
    struct fraction {
        bool negated = false;
        std::vector<power_term> numerator;
        std::vector<power_term> denominator;
    };
    fraction split(const GiNaC::ex& product) const;

    /// The sum with every term negated, built term by term (nothing multiplied out).
    static GiNaC::ex negated_sum(const GiNaC::ex& sum);

    /// True when a term of a sum is written with a minus sign in front: a negative
    /// number, or a product whose `split` is negated.
    bool negative(const GiNaC::ex& term) const;

    /// True when a sum's first term (in this order) has a negative coefficient.
    bool leads_negative(const GiNaC::ex& sum) const;

    /// The sort key of an expression: a string that compares in print order.
    const std::string& key(const GiNaC::ex& e) const;
    std::string key(const power_term& p) const;

    /// The expression in GiNaC's syntax (as `ginac_syntax` prints it), kept once made.
    const std::string& text(const GiNaC::ex& e) const;

    /// a before b: by key, ties broken by the full text.
    bool before(const GiNaC::ex& a, const GiNaC::ex& b) const;

private:
    std::string compute_key(const GiNaC::ex& e) const;
    std::vector<power_term> sorted(std::vector<power_term> items) const;

    std::vector<GiNaC::ex> symbols_;
    // Keys and texts are asked for again and again while printing nested expressions,
    // and the emitters print the same expressions again: copies of an order share them.
    struct memo {
        std::map<GiNaC::ex, std::string, GiNaC::ex_is_less> keys;
        std::map<GiNaC::ex, std::string, GiNaC::ex_is_less> texts;
    };
    std::shared_ptr<memo> memo_ = std::make_shared<memo>();
};

/// The order of a derivation's declared symbols.
term_order declaration_order(const symbol_table& symbols);

} // namespace impact::engine
