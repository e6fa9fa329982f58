// The state of a derivation while its steps run, shared by the files that carry them out:
// derive.cpp reads the file in and runs its givens, steps and results; checks.cpp proves
// its checks (limits among them, case by case where quantities are defined by cases);
// paper_claims.cpp holds the paper's claims to account, and finds what holds instead
// where one fails. Nothing outside engine/derive/ uses it: derive.h is the sub-stage's face.
#pragma once

#include "engine/cases/cases.h"
#include "engine/derivation/derivation.h"
#include "engine/prove/definedness.h"
#include "engine/prove/limit.h"
#include "engine/prove/prove.h"

#include <ginac/ginac.h>

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace impact::engine::detail {

class deriver {
public:
    deriver(const spec::derivation& source, const derived_by_id& done, proof_cache& run) : done_(done), run_(run)
    {
        out_.source = source;
    }

    /// Runs the derivation (derive.cpp).
    derivation run();

private:
    // derive.cpp: the file read in, its givens, steps and results
    GiNaC::ex resolve(const GiNaC::ex& e) const;
    GiNaC::ex substituted(const GiNaC::ex& e, const GiNaC::exmap& abbreviations) const;
    void set_value(const GiNaC::ex& symbol, const GiNaC::ex& value);
    void check_derivatives(const GiNaC::ex& e, const source_location& where) const;
    void refuse_derivative(const GiNaC::ex& value, const spec::text& written, const char* where) const;
    void refuse_derived_value(const GiNaC::ex& symbol, const spec::binding& b, const std::string& check,
                              const char* field) const;
    engine::resolver resolver() const;
    GiNaC::ex symbol_of(const spec::text& name) const { return out_.symbols.at(name).symbol; }
    written_form written(const spec::text& text) const;
    void import(const spec::use& u);
    void add_given(const spec::given& g);
    const equation* find_equation(const std::string& name) const;
    const equation& equation_at(const spec::text& name) const;
    void run_step(const spec::step& st);
    void solve(const spec::step& st, step_result& r);
    void define(const spec::step& st, step_result& r);
    void define_by_cases(const spec::step& st, const GiNaC::ex& s, step_result& r);
    void quotient(const spec::step& st, step_result& r);
    void rearrange(const spec::step& st, step_result& r);
    void add_step_equation(const spec::text& name, const GiNaC::ex& relation, step_result& r,
                           written_form as_written = {});
    void add_result(const spec::result& spec_result);
    void locate_by_members();
    void add_dimension_finding(paper_comparison& p) const;

    // checks.cpp: the checks of the file, limits among them
    check_result run_check(const spec::check& spec_check, bool paper_claim = false);
    std::vector<proven_identity> proven_identities() const;
    static error different_conditions(const source_location& where, const std::string& one, const std::string& other);
    std::optional<case_split> cases_in(const GiNaC::ex& lhs, const GiNaC::ex& rhs, const source_location& where) const;
    assumptions assumptions_of(const spec::check& spec_check) const;
    check_result run_continuity(const spec::check& spec_check);
    check_result::limit_point limit_point_of(const spec::limit_point& l) const;
    void approach_numerically(const GiNaC::ex& difference, const check_result::limit_point& p,
                              const assumptions& given, verdict& v) const;
    verdict check_limit(const GiNaC::ex& lhs, const GiNaC::ex& rhs, const check_result::limit_point& p,
                        const assumptions& given, std::optional<GiNaC::ex>& value,
                        std::optional<limit_method>& how) const;

    // conditions.cpp: where derived values, results and claims are defined in the reals
    std::vector<condition> in_inputs(const std::vector<condition>& needs) const;
    std::vector<condition> needs_of(const GiNaC::ex& value, const written_form* written) const;
    std::vector<const std::vector<condition>*> needs_where(const std::function<bool(const GiNaC::ex&)>& uses) const;
    std::vector<condition> needs_of_claim(const written_form& written, const claim_sides& sides,
                                          const GiNaC::exmap& left_at, const GiNaC::exmap& at, const GiNaC::ex& lhs,
                                          const GiNaC::ex& rhs) const;

    // paper_claims.cpp: the paper's claims held to account
    paper_comparison hold_to_account(const spec::claim& claim);
    finding mended_finding(const spec::claim& claim);
    void said_not_to_hold(paper_comparison& p, const spec::check& spec_check, check_result& c);
    std::optional<finding> complement_holds(const check_result& failed);
    std::vector<finding> what_holds_instead(const spec::check& original, const check_result& failed);
    std::vector<finding> what_holds_instead_search(const spec::check& original, const check_result& failed);
    std::vector<finding> where_it_holds(const spec::check& original, const check_result& failed);
    GiNaC::ex vanishes(const GiNaC::ex& sum) const;
    GiNaC::ex collected(const GiNaC::ex& sum) const;
    std::vector<finding> other_regimes(const spec::check& original, const check_result& failed);
    void find_swapped_values(std::vector<paper_comparison>& claims) const;

    // The derivation's state while its steps run.
    const derived_by_id& done_;
    proof_cache& run_;
    derivation out_;
    std::vector<equation> equations_;
    GiNaC::exmap values_;
    std::map<GiNaC::ex, std::vector<case_value>, GiNaC::ex_is_less> cases_;   ///< quantities defined by cases
    mutable std::map<GiNaC::ex, GiNaC::ex, GiNaC::ex_is_less> resolved_;
    std::map<std::string, std::string> imported_;   ///< the names [[use]]s gave, and the results they name
    /// What each derived quantity's value needs to be defined in the reals, in the inputs:
    /// its divisors, radicands, ... as written and as derived (conditions.cpp).
    std::map<GiNaC::ex, std::vector<condition>, GiNaC::ex_is_less> needs_;
};

} // namespace impact::engine::detail
