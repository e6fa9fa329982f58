// A judge of Impact's verdicts that owes nothing to Impact's proofs: claims read from their
// text by a parser of its own (GiNaC would read exp(log(x)) as x, and hide where it is
// undefined), evaluated node by node at exact rational points of the domains with 60 digits,
// where each divisor, radicand, fractional power's base and logarithm's argument is tested
// as the text writes it. A verdict is unsound when, at a point where its attached conditions
// (`where`) hold, a side is undefined or not real, or the claim is false: a `proven` verdict
// at any such point, a `sampled` one too (docs/language.md, "What each verdict promises").
// Every refutation found at 60 digits is computed again at 120 before it is believed.
#pragma once

#include "engine/prove/prove.h"
#include "spec/derivation.h"

#include <ginac/ginac.h>

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <random>
#include <string>
#include <vector>

namespace impact::soundness {

/// An expression as a claim's text writes it, node by node.
struct term {
    /// conjugate: a condition's text may hold it (conjugate(u)*u >= 0); of a real value, itself.
    enum class op { number, symbol, add, sub, mul, div, pow, neg, sqrt, abs, exp, log, sin, cos, conjugate };
    op what = op::number;
    GiNaC::numeric value;    ///< a number's (an exact rational)
    std::string name;        ///< a symbol's
    std::vector<term> args;  ///< the operands

    static term number(const GiNaC::numeric& v);
    static term symbol(const std::string& name);
    static term of(op what, std::vector<term> args);
};

term operator+(const term& a, const term& b);
term operator-(const term& a, const term& b);
term operator*(const term& a, const term& b);
term operator/(const term& a, const term& b);
term operator-(const term& a);
term pow(const term& base, const term& exponent);
term pow(const term& base, int numerator, int denominator = 1);
term call(term::op function, const term& argument);

/// The text the parser reads back (every compound operand in parentheses).
std::string text(const term& t);

enum class relation { equal, not_equal, less, less_equal, greater, greater_equal };
std::string text(relation r);

/// `lhs rel rhs`: a claim, or a condition of a verdict (`x != y`, `1 >= u^2`).
struct relation_claim {
    term lhs;
    relation rel = relation::equal;
    term rhs;
};
std::string text(const relation_claim& c);

/// Reads `a*(b + c)^(1/3) >= sqrt(d)` (numbers, names, + - * / ^, sqrt abs exp log sin cos).
/// Throws std::runtime_error on anything else.
relation_claim parse_relation(const std::string& text);
term parse_term(const std::string& text);

/// A symbol's domain: real, positive, nonnegative, or an interval with rational ends.
struct domain {
    std::optional<GiNaC::numeric> low, high;  ///< none: unbounded
    bool low_open = true, high_open = true;
    bool contains(const GiNaC::numeric& x) const;
};
domain parse_domain(const std::string& text);

/// What the judge needs of a derivation file: its inputs with their domains, the quantities
/// it defines (`define`, by their written value), and its checks' claims as written.
struct problem {
    std::vector<std::pair<std::string, domain>> inputs;
    std::map<std::string, term> defined;
    std::map<std::string, relation_claim> claims;  ///< by the check's name
};
/// Throws std::runtime_error for what the judge does not read (a solve step, `at`, `limit`,
/// `assuming`, cases).
problem read_problem(const spec::derivation& file);

/// One verdict judged.
struct judgement {
    bool sound = true;
    std::string why;             ///< a refutation: the point, the values
    std::size_t points = 0;      ///< points where the conditions held, at which the claim was judged
    std::size_t refutable = 0;   ///< of those, points where a side is undefined or the claim false
};

struct judge_options {
    std::size_t draws = 120;     ///< points drawn at most
    std::size_t wanted = 40;     ///< points where the conditions hold, enough to stop
};

/// Judges the verdict on `claim` (a check of `p`) at points drawn with `rng`: a `failed`
/// verdict is always sound; `proven` and `sampled` ones are unsound at a point of the domains,
/// where the conditions of `outcome.where` (read from their text) hold, at which a side is
/// undefined or not real, or the claim false.
judgement judge(const problem& p, const relation_claim& claim, const engine::verdict& outcome, std::mt19937_64& rng,
                const judge_options& options = {});

/// Whether the claim holds wherever both its sides are defined, as far as `draws` points
/// show: for the tally of the true claims (a claim true by construction may be undefined on
/// its whole domain).
struct truth {
    std::size_t defined = 0;     ///< points where both sides are defined
    std::size_t false_at = 0;    ///< of those, points where the claim is false
};
truth sample_truth(const problem& p, const relation_claim& claim, std::mt19937_64& rng, std::size_t draws = 60);

/// A second opinion on a verdict, beside the judge's: Z3's, when src/verify/ has it (branch
/// `z3`). Given the file as read, the check's name and claim and Impact's verdict, a
/// refutation in words, or nothing.
using second_opinion = std::function<std::optional<std::string>(const problem&, const std::string& check,
                                                                const relation_claim& claim,
                                                                const engine::verdict& outcome)>;

} // namespace impact::soundness
