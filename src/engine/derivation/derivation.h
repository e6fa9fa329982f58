// A derivation once run, as plain data: its symbols, givens, steps, results, checks, the
// paper's printed forms compared, and its kernels described. `engine/derive/derive.h` makes
// one from a derivation file; every later stage reads it and nothing else of the engine's.
#pragma once

#include "engine/expr/finding.h"
#include "engine/expr/symbols.h"
#include "engine/expr/written_form.h"
#include "engine/prove/limit.h"
#include "engine/prove/prove.h"
#include "spec/derivation.h"

#include <ginac/ginac.h>

#include <array>
#include <map>
#include <optional>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace impact::engine {

/// Turns an expression in derived quantities into one in declared quantities (derived
/// values and abbreviations substituted): how a printed form, a solve's equations and a
/// kernel's outputs are written in the inputs.
using resolver = std::function<GiNaC::ex(const GiNaC::ex&)>;

/// A named equation: a given one, or one a step produced.
struct equation {
    std::string name;
    GiNaC::ex relation;       ///< lhs == rhs
    std::string because;
    std::string paper;
    source_location where;
    written_form written;     ///< how the file writes it (a given, a rearranged form)
};

/// One case of a quantity defined by cases (`define` with `cases`): its value where its
/// condition `lhs op rhs` holds. The first case whose condition holds applies.
struct case_value {
    relation op = relation::less_equal;   ///< the condition's relation (never `equal`)
    GiNaC::ex lhs;            ///< the condition's sides, in the declared quantities
    GiNaC::ex rhs;
    GiNaC::ex value;          ///< the value in this case, in the declared quantities
    GiNaC::ex written_lhs;    ///< the condition and value as the file writes them, before substitution
    GiNaC::ex written_rhs;
    GiNaC::ex as_written;
    written_form written;     ///< how the file writes the value
    source_location where;    ///< the case's table
};

/// One proven (or failed) statement.
struct check_result {
    std::string name;
    std::string statement;    ///< the claim in words or as written in the file
    GiNaC::ex stated;         ///< the claim as written (lhs == rhs), before substitution
    std::vector<std::pair<GiNaC::ex, GiNaC::ex>> at;  ///< special values it is checked at
    std::vector<std::pair<GiNaC::ex, GiNaC::ex>> left_at;  ///< inputs changed on the left only
    relation op = relation::equal;                     ///< the relation `stated` claims
    struct limit_point {
        GiNaC::ex symbol;
        GiNaC::ex point;
        bool to_infinity = false;
    };
    std::optional<limit_point> limit;                  ///< the claim is about lim lhs
    std::vector<std::pair<GiNaC::ex, std::string>> assuming;  ///< narrowed domains
    std::optional<GiNaC::ex> value;                    ///< what lhs comes to (at its point, or its limit)
    std::optional<limit_method> limit_by;              ///< how the limit was established, when it was
    std::string display_of;   ///< for the check of a result's display form: the result's name
    std::string because;
    GiNaC::ex lhs;            ///< both sides after substituting the results
    GiNaC::ex rhs;
    verdict outcome;
    source_location where;
    written_form written;     ///< how the file writes the claim
    /// A check on a quantity defined by cases is proven case by case (and a continuity
    /// check boundary by boundary): each part's verdict, with what it was proven under.
    struct part {
        std::string under;    ///< e.g. "case 1 (J_t = ...) where ... <= ...", or the boundary
        verdict outcome;
        std::size_t first = 0;        ///< the case (from 1), or the first of the two that meet
        std::size_t second = 0;       ///< continuity: the second case
        std::optional<case_value> in_case;                          ///< the case, as proven (after `at`)
        /// A check split on several quantities with the same conditions (J_t and b_eff):
        /// each quantity and its case, as proven; empty when it splits on one.
        std::vector<std::pair<GiNaC::ex, case_value>> in_cases;
        std::optional<std::pair<GiNaC::ex, GiNaC::ex>> boundary;    ///< continuity: symbol = value there
    };
    std::vector<part> parts;
    std::string cases_of;     ///< the quantity whose cases split the check, if any
    bool continuity = false;  ///< a continuity check (`continuity = "J_t"`) of `cases_of`
    /// A claim the paper says does not hold (`holds = false`): its comparison agrees when
    /// `fails_at` refutes it, and disagrees when it is proven.
    bool said_false = false;
    std::optional<counterexample> fails_at;   ///< a point where it fails, for a claim said not to hold
};

/// One solution of a `solve` step whose equations are not linear: kept, or rejected by
/// the declared domain of an unknown or by a condition the step states.
struct solution {
    std::vector<std::pair<GiNaC::ex, GiNaC::ex>> values;  ///< unknown = value
    enum class fate { kept, outside_domain, condition } outcome = fate::kept;
    GiNaC::ex unknown;        ///< outside_domain: the unknown whose domain excludes the value
    domain range;             ///< ... and that domain
    GiNaC::ex condition;      ///< condition: the step's condition (lhs == rhs) that holds for it
    std::string why;          ///< in words: the sign proven, or (condition) the step's `reject_because`
    std::vector<sign_step> proof;  ///< outside_domain (or kept within a domain): the value's sign

    bool kept() const { return outcome == fate::kept; }
};

/// What one step did.
struct step_result {
    spec::step::kind what;
    std::string description;  ///< e.g. "solve impulse_M, impulse_m, restitution for v_M_after, v_m_after, J"
    std::string because;
    std::vector<std::pair<GiNaC::ex, GiNaC::ex>> values;  ///< symbol = value, for solve and define
    std::optional<equation> yields;                        ///< the equation made, for quotient and rearrange
    std::vector<GiNaC::ex> assumptions;                    ///< relations assumed, e.g. v_m - v_m_after != 0
    std::vector<check_result> checks;
    source_location where;
    std::optional<GiNaC::ex> as_written;  ///< define: the value as the file writes it, before substitution
    written_form written;                 ///< ... and how it writes it
    /// solve, when its equations are not linear: every solution found, kept and rejected
    /// (the one kept is also in `values`; each is substituted back in `checks`).
    std::vector<solution> solutions;
    /// define with `cases`: the value in each case (`values` is then empty), and the
    /// quantity they define.
    std::vector<case_value> cases;
    GiNaC::ex cases_of;
    /// Where the values it derives are defined (engine/prove/definedness.h): the conditions
    /// not proven from the domains, attached to them, and those proven.
    std::vector<condition> attached;
    std::vector<condition> defined;
};

/// Something the paper prints or claims, compared with what is derived.
struct paper_comparison {
    enum class kind { result, given, claim };
    kind what = kind::result;
    std::string subject;      ///< the result or equation it prints, or the claim's name
    std::string paper;        ///< e.g. "Eq. 8"
    std::string printed_text; ///< as transcribed in the derivation file (for a claim: the paper's words)
    GiNaC::ex printed;        ///< the printed expression or equation (for a claim: what it states)
    GiNaC::ex derived;        ///< the derived expression or equation (for a claim: its derived value)
    verdict agreement;        ///< proven: the paper agrees; otherwise a disagreement, with the residual
    std::vector<finding> findings;            ///< the smallest edits that make the printed form right, etc.
    std::vector<std::string> reconciliations; ///< the same findings as plain text
    std::optional<check_result> test;         ///< for a claim: the check it was turned into
    source_location where;
    written_form written;     ///< how the file transcribes the printed form (not for a claim)
    /// The paper's own text of the printed form (math between dollar signs), when the file
    /// reads it in other terms; empty otherwise, and for a claim (`printed_text` is its words).
    std::string quote;
    /// For a claim: how a finding names it among the claims of its quote ("the
    /// contrapositive"); empty: by its place in the row.
    std::string label;

    bool agrees() const { return agreement.what == verdict::status::proven; }
};

struct result {
    std::string name;
    GiNaC::ex symbol;
    GiNaC::ex value;          ///< as derived, in the declared quantities
    GiNaC::ex display;        ///< the form to typeset, proven equal to `value`
    std::string paper;
    written_form written;     ///< how the file writes the display form
    /// Defined by cases: each case (then `value` and `display` are the symbol itself).
    std::vector<case_value> cases;
    /// Where its value and display form are defined: the conditions attached to it (`T =
    /// 2*w/g, where g != 0`), and those proven from the domains.
    std::vector<condition> attached;
    std::vector<condition> defined;
};

/// A parameter of a kernel: a scalar, or an array of components (`C_M = [C_Mx, C_My]`).
struct kernel_parameter {
    std::string name;
    std::vector<quantity> components;
    bool is_array = false;
};

/// One algebraically equal way of computing an output, all proven equal to the result.
struct form {
    std::string label;        ///< "display", "derived", "paper", "expanded", or the form as written
    GiNaC::ex value;
};

struct kernel_output {
    std::string member;       ///< the C++ struct member
    bool is_array = false;
    std::vector<GiNaC::ex> values;              ///< each component, in the kernel's inputs
    std::vector<std::vector<form>> candidates;  ///< each component's candidate forms
    /// How its error is scaled: relative to its own exact value, or to the largest
    /// velocity of the collision times `scale_factor`.
    enum class scale { relative, velocity } error = scale::relative;
    GiNaC::ex scale_factor = 1;
    /// The floating-point types a kernel is emitted in, in the order of `bound_ulps`.
    static constexpr const char* types[] = {"float", "double", "long double"};
    /// The largest error allowed in float, double and long double, in ulps of its scale,
    /// and why when the file sets it (`[[kernel.bound]]`); 4 ulps otherwise.
    std::array<double, 3> bound_ulps{4, 4, 4};
    std::array<std::string, 3> bound_because;
    /// The same for the fast form (`impact::fast`): 16 ulps unless the file sets another
    /// (`[[kernel.bound]]` with `form = "fast"`).
    std::array<double, 3> fast_bound_ulps{16, 16, 16};
    std::array<std::string, 3> fast_bound_because;

    /// The name of component `c`'s array in a batch, for an output named after no input:
    /// `J`, or `dp_0`, `dp_1` for an array.
    std::string own_array_name(std::size_t c) const;
};

/// A condition the inputs must meet; when one does not, the kernel returns its status.
struct kernel_guard {
    std::string status;
    std::vector<std::string> parameters;   ///< checked against their domains (and finiteness)
    std::optional<GiNaC::ex> condition;    ///< or: lhs < 0, lhs > 0 (relation in `op`)
    relation op = relation::less;
};

/// A hard region of a kernel's inputs declared by its file (`[[kernel.regime]]`): a
/// sample drawn in `start` (ordinary when empty) has its input set (the components
/// `inputs`: one for a scalar, a vector's for a vector) so that the quantity, affine in
/// them (`offsets` + `slopes` times the inputs, one row of slopes per component of the
/// quantity), is ±10^u times `denominator` (`ratio`, |quantity|/|denominator| from `from`
/// to `to`; a vector quantity along a direction it can take), or zero to within a relative
/// `to` of the input (`boundary`, a scalar). Everything is written in the kernel's inputs;
/// `offsets`, `slopes` and `denominator` are free of the inputs set.
struct sampling_regime {
    enum class kind { ratio, boundary };
    std::string name;
    source_location where;
    kind what = kind::ratio;
    std::string start;
    std::vector<GiNaC::ex> inputs;
    std::vector<GiNaC::ex> offsets;
    std::vector<GiNaC::ex> slopes;   ///< row by row: d quantity_i / d input_j
    GiNaC::ex denominator = 1;
    double from = 0;
    double to = 0;
};

struct kernel {
    std::string name;
    source_location where;                 ///< its name in the derivation file
    std::vector<kernel_parameter> parameters;
    std::vector<kernel_output> outputs;
    std::vector<kernel_guard> guards;
    std::vector<GiNaC::ex> velocities;     ///< the velocity components among the inputs
    /// Further velocities of the collision, in the inputs (a spin's rim speed `R_M*w_M`):
    /// the largest magnitude among these and `velocities` scales velocity errors.
    std::vector<GiNaC::ex> speeds;
    std::vector<std::pair<GiNaC::ex, GiNaC::ex>> lets;  ///< symbol = value in the inputs, computed once
    std::vector<sampling_regime> regimes;  ///< where its accuracy is measured, beyond the built-in regimes
    bool batch = false;
    /// A fixed sphere's kernel (`fixed = ["M"]`): the kernel `limit_of` as its input
    /// `fixed_mass` grows without bound, that mass left out of its parameters. Every output
    /// (and every candidate form) is the limit of the finite kernel's, each form proven
    /// equal to the limit of the output's value. Empty for an ordinary kernel.
    std::string limit_of;
    std::string fixed_mass;
    /// The kernels of the fixed spheres, one for each mass in `fixed`, in its order: the
    /// emitted kernel calls one where its mass is +infinity.
    std::vector<kernel> limits;

    /// Every input symbol, parameters' components in order.
    std::vector<GiNaC::ex> input_symbols() const;
    const quantity* find_input(const std::string& name) const;
    /// The parameter called `name` (an array such as `C_M`, or a scalar), or null.
    const kernel_parameter* find_parameter(const std::string& name) const;
};

/// A derivation once run: everything later stages need, with no way back to the file.
struct derivation {
    spec::derivation source;
    symbol_table symbols;
    std::vector<equation> givens;
    std::vector<step_result> steps;
    std::vector<result> results;
    std::vector<check_result> checks;
    std::vector<paper_comparison> paper_checks;
    std::vector<kernel> kernels;
    /// The wall time of each part of the derivation, in the file's order ("step 2 (solve
    /// for v_M_after)", "check energy_never_gained", "kernel collide"), in seconds: what
    /// `impact derive --timings` lists. Empty for a derivation taken from the cache.
    std::vector<std::pair<std::string, double>> timings;

    const std::string& id() const { return source.id.value; }
    /// `<folder>/<file name>`, the folder by its own name (`derivations/eq08_inelastic_line.toml`,
    /// `mine/spring.toml`): how generated files name their source, the same bytes whatever the
    /// path the file was given by (relative, absolute, from another working folder).
    std::string source_name() const;
    const result* find_result(const std::string& name) const;
    /// Every step check, display proof and check holds (proven or sampled).
    bool all_hold() const;
    /// Every check of the derivation, steps first, in order.
    std::vector<const check_result*> all_checks() const;
};

/// `<folder>/<file name>` of a derivation file, its folder by its own name whatever the path
/// gives (`../../derivations/x.toml`, `/home/u/derivations/x.toml`, `x.toml` run in
/// derivations/: `derivations/x.toml`); the file name alone where the folder has none (/).
std::string folder_and_file_name(const std::filesystem::path& file);

/// `<folder>/` of the derivation files a set of derivations was read from, named as
/// folder_and_file_name names it (a regeneration reads one folder): what files generated
/// from them all say they come from. `derivations/` for none.
std::string source_folder(const std::vector<const derivation*>& derivations);

/// Derivations already run, by id, for `[[use]]`.
using derived_by_id = std::map<std::string, derivation>;

} // namespace impact::engine
