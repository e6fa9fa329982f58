// Proving the sign of an expression from the declared domains.
//
// An inequality such as ΔE ≤ 0 is proven, never sampled, when the sign of the
// expression follows from the signs of its parts: the expression is normalised and
// factored, and each factor's sign is derived from the domains (a positive mass, an
// interval ε ∈ [0, 1], a square, a square root, a sum of terms of one sign, a linear
// function of one bounded symbol at the ends of its interval, a polynomial of degree
// one in a bounded symbol or its square, whatever its other symbols, by its signs at
// the ends (1 − b² on [−1, 1]; a sum −(1 − e²)A − (1 − b²)B expanded over one
// denominator), a polynomial in one symbol by Sturm's theorem or in a bounded symbol by
// its monotonicity (sign_arguments.h), or A − B with A, B ≥ 0 through A² − B²). The
// derivation of each factor's sign is kept as the proof text.
#pragma once

#include "engine/expr/finding.h"
#include "engine/expr/normal_form.h"

#include "engine/expr/order.h"
#include "engine/expr/symbols.h"
#include "engine/prove/condition.h"

#include <ginac/ginac.h>

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace impact::engine {

/// The signs an expression can take: a subset of {negative, zero, positive}.
struct sign_set {
    bool negative = true;
    bool zero = true;
    bool positive = true;

    static sign_set any() { return {}; }
    static sign_set exactly(int sign);
    bool is_known() const { return !(negative && positive); }
    bool is_nonnegative() const { return !negative; }              ///< proven >= 0
    bool is_positive() const { return !negative && !zero; }        ///< proven > 0
    std::string describe() const;   ///< "> 0", ">= 0", "= 0", "<= 0", "< 0" or "of unknown sign"
};

/// Domains by GiNaC symbol; a check may narrow the declared ones (e.g. ε ∈ [0, 1)).
using domain_map = std::map<GiNaC::ex, domain, GiNaC::ex_is_less>;

/// Why an expression has its sign. `words` says it ("an even power", "M in positive");
/// where the sign comes from a symbol's declared domain, `declared` names the symbol and
/// `domain` the domain, so that a printer can say so in its own way.
struct sign_reason {
    sign_reason() = default;
    sign_reason(std::string text) : words(std::move(text)) {}   // NOLINT: a reason is its words
    sign_reason(const char* text) : words(text) {}             // NOLINT

    std::string words;
    finding typeset;                    ///< the same words with their mathematics, when it has any
    std::optional<GiNaC::ex> declared;
    std::string domain;
};

/// What is worked out under one set of domains: signs with their reasons, and radicals
/// simplified.
struct worked_out {
    std::map<GiNaC::ex, std::pair<sign_set, sign_reason>, GiNaC::ex_is_less> signs;
    std::map<GiNaC::ex, GiNaC::ex, GiNaC::ex_is_less> radicals;
};

/// What the proofs of one run have worked out, so that it is not worked out twice:
/// polynomials factored (true under any domains), and signs and radicals under the
/// declared domains. Whoever runs the proofs owns it (`derive_all` one for a run of the
/// library, `derive` one for a derivation) and it dies with them: two runs share nothing.
struct proof_cache {
    std::map<GiNaC::ex, GiNaC::ex, GiNaC::ex_is_less> factored;
    std::shared_ptr<worked_out> declared = std::make_shared<worked_out>();
    /// For a real symbol x under |.|, the positive symbol y with x = ±y or 0 that a proof
    /// by the sign of x writes (engine/cases/in_case.cpp): one per x, so that what is worked out
    /// about y is kept.
    std::map<GiNaC::ex, GiNaC::ex, GiNaC::ex_is_less> magnitudes;
    /// For the boundary of two cases (the numerator of their condition, expanded), the
    /// quantity it is solved for and its value there (engine/cases/continuity.cpp),
    /// or none: the components of one vector meet on the same boundary.
    std::map<GiNaC::ex, std::optional<std::pair<GiNaC::ex, GiNaC::ex>>, GiNaC::ex_is_less> boundaries;

    /// Nothing worked out yet.
    bool empty() const;
};

/// What a proof may assume: the domains, and the order in which its text is written.
struct assumptions {
    domain_map domains;
    term_order order;
    std::string text(const GiNaC::ex& e) const;

    /// What is already worked out under these domains: the run's, for the declared ones;
    /// domains narrowed (a check's `assuming`) need one of their own.
    std::shared_ptr<worked_out> known = std::make_shared<worked_out>();
    /// The run's polynomials factored; none, and each is factored again.
    proof_cache* run = nullptr;
    /// For a try that another argument may replace: how many more signs it may work out
    /// (none: as many as it takes). A sign not worked out within it is unknown, and is not
    /// remembered. It keeps a search whose length depends on the order GiNaC gives the
    /// terms, which changes with the program's build, from running for minutes.
    std::shared_ptr<std::size_t> effort{};
    /// An abbreviation declared with a domain is an assumption on the inputs: `s_n`, the
    /// spheres' normal relative velocity times their distance, declared positive (the
    /// spheres approach). A sum that is a constant multiple of its definition (written in
    /// the inputs, expanded) has the sign the domain gives it.
    struct assumed_sign {
        GiNaC::ex symbol;
        GiNaC::ex definition;
        domain range;
    };
    std::vector<assumed_sign> assumed{};
    /// The conditions a claim is said to hold under (definedness.h: attached, not proven):
    /// a sample is drawn where they hold, and a point there where the claim is undefined
    /// refutes it.
    std::vector<condition> where{};
};

/// `e` as c times an abbreviation declared with a domain (assumptions::assumed), c a real
/// number: c and the abbreviation; none when it is no such multiple.
std::optional<std::pair<GiNaC::numeric, const assumptions::assumed_sign*>> assumed_multiple(const GiNaC::ex& e,
                                                                                           const assumptions& given);

/// `given` with an effort of `signs` for a try (see assumptions::effort).
assumptions with_effort(const assumptions& given, std::size_t signs);

/// The declared domains of a derivation's symbols, with what `run` has worked out under them.
assumptions declared_assumptions(const symbol_table& symbols, proof_cache& run);

/// One step of a sign proof: `factor` (a factor of the expression, or 1/factor for one
/// of its denominator) has the sign `sign`, because `why`.
struct sign_step {
    GiNaC::ex factor;
    sign_set sign;
    sign_reason why;
    std::string words;   ///< the step in one line: "1+eps > 0 (a sum of terms of one sign)"
};

struct sign_proof {
    sign_set sign;
    std::vector<sign_step> steps;   ///< one per factor
};

/// The sign of `e` as far as it follows from `domains`.
sign_proof prove_sign(const GiNaC::ex& e, const assumptions& given);

/// GiNaC's factor() for an expression without radicals; one with radicals is returned
/// as it is (factoring under a root may pull out -1 and leave I behind).
GiNaC::ex factor_polynomial(const GiNaC::ex& e);
/// factor_polynomial, each polynomial factored once in `run`.
GiNaC::ex factor_polynomial(const GiNaC::ex& e, proof_cache& run);

/// `sqrt(x^2 y)` → `x sqrt(y)` wherever the sign of x is proven: radicals of squares
/// taken out under the domains.
GiNaC::ex simplify_radicals(const GiNaC::ex& e, const assumptions& given);

/// Each radicand expanded (√(−(Xg + s²)(Xg − s²)) = √(s⁴ − g²X²)): one radical written two
/// ways (a condition in the author's form and a solution's; a friction cone's |g_t| at
/// velocities shifted by u and at the velocities themselves) becomes one quantity.
GiNaC::ex expanded_radicands(const GiNaC::ex& e);

} // namespace impact::engine
