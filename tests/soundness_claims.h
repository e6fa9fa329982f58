// Random claims for the soundness fuzzer (test_soundness.cpp): pairs of expressions equal by
// construction (A*B/B and A, sqrt(A^2) and abs(A), log(A*B) and log(A) + log(B), ...) and
// inequalities true by construction (A^2 + B^2 >= 2*A*B, exp(A) > 0, ...), over 2 to 4
// symbols with random domains, A and B drawn from a small grammar (rational functions,
// radicals, abs, exp, log); and the same perturbed (a coefficient, a sign, an exponent, the
// relation), which makes most of them false. Each is a small derivation file.
#pragma once

#include "soundness_judge.h"

#include <optional>
#include <random>
#include <string>
#include <vector>

namespace impact::soundness {

struct drawn_claim {
    std::string name;            ///< the check's name in the file
    std::string family;          ///< the identity it comes from, e.g. "log_product"
    relation_claim claim;
    bool true_by_construction = true;  ///< false: perturbed
    /// Non-empty: the left side is the value of a `define` step of that name (simplified as a
    /// step's value is, sqrt(u^2) = u for u >= 0), and the claim is `name rel rhs`.
    std::string through_step;
};

struct drawn_file {
    std::vector<std::pair<std::string, std::string>> symbols;  ///< name, domain
    std::string defined_name;    ///< a quantity a `define` step derives, or empty
    term defined_value;
    std::optional<term> abbreviation_value;  ///< `A`, a symbol with a `definition`, when drawn
    std::vector<drawn_claim> claims;

    /// The derivation file (its `[[result]]` the defined quantity, else the first symbol's copy).
    std::string toml() const;
};

/// A file of `claims` claims drawn with `rng`.
drawn_file draw_file(std::mt19937_64& rng, std::size_t claims);

} // namespace impact::soundness
