// A derivation file read into plain data.
//
// This is the first stage of Impact: `derivations/*.toml` → these structs. Nothing
// here knows GiNaC; expressions stay text, each with the place it was written so
// that later stages can point at it when it is wrong. The file format is described
// in docs/language.md.
#pragma once

#include "spec/error.h"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace impact::spec {

/// Text from the file together with where it was written.
struct text {
    std::string value;
    source_location where;
};

/// `name = expression`, as used for kernel outputs and imported results.
struct binding {
    text name;
    text expression;
};

/// A symbol of the derivation: a quantity with a domain, or an abbreviation.
struct symbol {
    text name;            ///< identifier used in expressions, e.g. `v_M_after`
    text latex;           ///< how it is typeset, e.g. `v'_M`
    text domain;          ///< `real`, `positive`, `nonnegative`, or an interval `[0, 1]`
    text meaning;         ///< a few words for the reader
    std::optional<text> definition; ///< set for abbreviations such as `m_eff = 1/m + 1/M`
    std::optional<text> dimension;  ///< e.g. `mass`, `velocity`, `mass*length^2/time^2`, `1`
};

/// A dimension a derivation adds: a new base (`angle`), or a name for a combination
/// (`spin` as `angle/time`).
struct dimension {
    text name;
    std::optional<text> as;
};

/// A given equation with its justification in words.
struct given {
    text name;
    text equation;        ///< `lhs = rhs`
    text because;
    std::optional<text> paper; ///< the paper's equation it is taken from, e.g. `Eq. 6`
    std::optional<text> printed; ///< the equation as the paper prints it, compared for equivalence
    std::optional<text> quote;   ///< the paper's own text of it, when `printed` had to read it in other terms
};

/// One case of a value defined by cases: `{ when = "lhs <= rhs", as = "expression" }`.
struct case_of {
    text when;                     ///< the condition, an inequality `lhs op rhs` (op one of <, <=, >, >=)
    text as;                       ///< the value in that case
    source_location where;         ///< the case's table
};

/// One step of a derivation. Exactly one of the kinds is filled in.
struct step {
    enum class kind { solve, define, quotient, rearrange };
    kind what = kind::solve;
    source_location where;
    text because;

    std::vector<text> equations;   ///< solve, quotient: the equations it works on
    std::vector<text> unknowns;    ///< solve: the unknowns it solves for
    text name;                     ///< define, quotient, rearrange: what the step yields
    text expression;               ///< define: the expression; rearrange: the equation's new form
    text source;                   ///< rearrange: the equation brought to a new form
    std::vector<text> reject;      ///< solve: conditions (`lhs = rhs`) whose solutions are not wanted
    text reject_because;           ///< solve: why the solutions `reject` names are not wanted
    std::vector<case_of> cases;    ///< define: the value by cases, in place of `expression` (empty otherwise)
};

/// A named result with the form to display and what the paper prints.
struct result {
    text name;
    std::optional<text> display;   ///< the form to typeset; must be proven equal to the result
    std::optional<text> paper;     ///< e.g. `Eq. 8`
    std::optional<text> printed;   ///< the paper's printed form, transcribed
    /// The paper's own text of that form, math between dollar signs, when `printed` had
    /// to read it in other terms: one component of a vector it prints whole (R^T v^(C)'),
    /// a name for a symbol it prints otherwise, an operator Impact writes as a product.
    std::optional<text> quote;
};

/// A claim that must hold once the results are substituted: an identity, an
/// inequality, or a limit.
/// `symbol -> point` (the point an expression, or `infinity`).
struct limit_point {
    text written;                  ///< as the file writes it
    text symbol;
    text point;                    ///< empty when `to_infinity`
    bool to_infinity = false;
};

struct check {
    text name;
    text claim;                    ///< `lhs = rhs`, or `lhs <= rhs` (also <, >=, >); empty for `continuity`
    std::optional<text> continuity;///< a quantity defined by cases: its cases agree where their conditions meet
    text because;
    std::vector<binding> at;       ///< special values, e.g. `eps = 1`
    std::vector<binding> left_at;  ///< inputs changed on the left side only, e.g. `v_M = v_M + w`
    std::optional<limit_point> limit;///< `v_perp -> 0` or `v_perp -> infinity`: the claim is about lim lhs
    std::vector<binding> assuming; ///< narrower domains for this check, e.g. `eps = "[0, 1)"`
};

/// Something the paper's text claims, in checkable form: held to account like a
/// printed equation (a disagreement is a finding about the paper, not a failure).
struct claim {
    text paper;                    ///< where the paper says it, e.g. `Sec. III C`
    text quote;                    ///< the paper's words
    check test;                    ///< what the words claim, as a check (name, claim, at, limit, assuming)
    bool holds = true;             ///< false: the paper says this does not hold (`holds = false`)
    /// The claim as the file mends the words (`mended`, e.g. "final" for "incident"): proven,
    /// it is the finding of a claim that does not hold.
    std::optional<text> mended;
    std::optional<text> label;     ///< how a finding names it among the claims of its quote ("the contrapositive")
};

/// Something the paper's text claims that no derivation can settle: a statement about
/// experiment, or an assumption the model makes about real bodies. `[[claim]]` with
/// `undecided` (why) in place of `claim`; it is compared, and reported undecided with
/// its reason, never as agreeing or disagreeing.
struct open_claim {
    text name;
    text paper;                    ///< where the paper says it
    text quote;                    ///< the paper's words
    text undecided;                ///< why no derivation settles it
};

/// A printed line of the paper that nothing compares (the references), with why:
/// `[[not_compared]]`. The errata counts it among the paper's lines.
struct not_compared {
    text paper;                    ///< its place, e.g. `Footnotes 1 to 8, 12 and 13`
    text because;
};

/// An entry of the paper's list of references, as printed: `[[reference]]`. Compared with
/// the citations of it (`[[citation]]` of the same file) and checked for what an entry
/// needs: authors each named once (the names before the entry's first period), and a year.
struct reference {
    text paper;                    ///< its place, e.g. `Footnote 4`
    int number = 0;                ///< the mark the text cites it by
    text entry;                    ///< the entry as printed: authors. Title. Where, year.
    source_location where;
};

/// A place of the paper that cites a reference by its number: `[[citation]]`.
struct citation {
    text paper;                    ///< where, e.g. `Sec. I A`
    text quote;                    ///< the words beside the mark
    int cites = 0;                 ///< the reference's number
    std::optional<text> names;     ///< the author the words name beside the mark, e.g. `Čepič`
    source_location where;
};

/// A C++ kernel to emit: a function of `inputs` returning `outputs`.
/// A kernel's input or output: a scalar (`M`, or `v_par = v_1par` under another name)
/// or an array of components (`C_M = [C_Mx, C_My]`).
struct kernel_value {
    text name;                     ///< the C++ parameter or struct member
    std::vector<text> components;  ///< symbols (inputs) or results and expressions (outputs)
    bool is_array = false;
};

/// `status = M, m` checks inputs against their domains; `status = <expr> < 0` (or > 0)
/// a condition.
struct kernel_guard {
    text status;
    std::vector<text> parameters;
    std::optional<text> condition;
};

/// How an output's error is measured: relative to itself, or in units of the largest
/// input velocity times a factor (`velocity*M*m/(M + m)` for an impulse).
struct error_scale {
    text output;
    bool relative = true;
    std::optional<text> factor;    ///< with `velocity*<factor>`
    text written;
};

/// An output's accuracy bound set in the file (`[[kernel.bound]]`), in ulps of its error
/// scale, with the reason; without one an output must reach 4 ulps.
struct error_bound {
    text output;
    std::optional<text> type;      ///< `float`, `double` or `long double`; all three without
    /// `accurate` (the default) or `fast`: the bound of the accurate form (`impact::collide`)
    /// or of the fast one (`impact::collide(..., impact::fast)`, 16 ulps without a bound)
    std::optional<text> form;
    double ulps = 4;
    source_location ulps_where;
    text because;
};

/// A hard region of the inputs where the kernel's accuracy is also measured
/// (`[[kernel.regime]]`), beside the regimes every kernel gets: each sample is drawn as in
/// the regime `start` (ordinary without it), then the input `set` is given the value that
/// makes `ratio`'s two quantities A = ±10^u B, |A/B| from `from` to `to` (u uniform), or
/// that puts the sample within a relative `within` of where `boundary` (`lhs = rhs`) holds.
struct sampling_regime {
    text name;
    text set;
    std::vector<text> ratio;
    std::optional<text> boundary;
    double from = 0;
    double to = 0;
    double within = 0;
    std::optional<text> start;
};

struct kernel {
    text name;
    std::vector<kernel_value> inputs;
    std::vector<kernel_value> outputs;
    std::vector<text> velocities;  ///< inputs whose largest magnitude scales velocity errors
    std::vector<error_scale> error;
    std::vector<error_bound> bounds;
    std::vector<binding> forms;    ///< further candidate forms of an output: `J = <expr>` (proven equal)
    std::vector<kernel_guard> guards;
    std::vector<binding> substitute; ///< symbols of the results written in the inputs: `r_x = C_Mx - C_mx`
    std::vector<binding> let;      ///< values computed once in the kernel, usable in forms: `k = ...`
    /// Masses that may be +infinity, one at a time (`fixed = ["M", "m"]`): a fixed sphere,
    /// computed by the limit of every output as that mass grows without bound.
    std::vector<text> fixed;
    bool batch = false;            ///< also emit `<name>_batch` over structure-of-arrays data
    std::vector<sampling_regime> regimes;
};

/// Results taken from another derivation, renamed for use in this one.
struct use {
    text derivation;               ///< the id of the derivation used
    std::vector<binding> results;  ///< local name = result name in that derivation
};

/// One derivation file.
struct derivation {
    std::string file;              ///< path as given, used in messages and banners
    std::string contents;          ///< the file's bytes: what a derivation kept between runs is keyed by
    text id;
    text title;
    std::optional<text> paper;
    text summary;
    std::vector<use> uses;
    std::vector<dimension> dimensions;
    std::vector<symbol> symbols;
    std::vector<given> givens;
    std::vector<step> steps;
    std::vector<result> results;
    std::vector<check> checks;
    std::vector<claim> claims;
    std::vector<open_claim> open_claims;  ///< claims read with `undecided`, in the file's order
    std::vector<not_compared> uncompared;   ///< `[[not_compared]]`: lines of the paper nothing compares
    std::vector<reference> references;      ///< `[[reference]]`: the paper's list of references
    std::vector<citation> citations;        ///< `[[citation]]`: where the text cites them
    std::vector<kernel> kernels;
};

/// The bytes of a file Impact reads (a derivation file, the paper's order of places): at
/// most a megabyte, anything larger being a mistake. Throws `impact::error`.
std::string read_input_file(const std::string& path);

/// Reads and validates the structure of one derivation file. Throws `impact::error`.
derivation read_derivation(const std::string& path);

/// Reads a derivation from text; `file` names it in messages.
derivation parse_derivation(const std::string& contents, const std::string& file);

/// The TOML of a derivation file without what cannot change a derivation (comments, spacing,
/// the order of a table's keys), for keying cached results; none when it is not TOML.
std::optional<std::string> meaningful_content(const std::string& contents);

} // namespace impact::spec
