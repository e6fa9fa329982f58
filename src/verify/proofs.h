// Every proof of Impact's re-checked by Z3 (issue 59): each check a derivation reports
// `proven` written as SMT-LIB 2 problems (smt.h), one per check, or one per part of a
// check proven case by case, and run through Z3 (z3.h), each answer kept in the cache by
// the problem's text. What comes out: output/proofs/<id>.smt2, which `z3` runs with the
// same answers, and a status per check for derivations.json, verification.md and the report.
#pragma once

#include "engine/derivation/derivation.h"
#include "verify/smt.h"
#include "verify/z3.h"

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace impact::cache {
class store;
}

namespace impact::verify {

/// One problem of a proven check: the whole check, or one of its parts.
struct proof_problem {
    std::string part;             ///< the part's `under` (case 1 ...), empty for the whole check
    smt_claim claim;
    smt_problem smt;
    z3_answer answer;             ///< when `smt.text` is a problem
    /// Not given to `z3` in proofs/<id>.smt2 (written there as a comment): too large to
    /// run, or stopped by the wall-clock guard, so that the file's answers come quickly.
    bool left_out() const { return answer.guarded; }
};

/// A proven check and what Z3 made of it.
struct proof_check {
    const engine::check_result* check = nullptr;
    std::string label;            ///< "check <name>", or "paper claim <name>"
    std::vector<proof_problem> problems;
    /// "confirmed" (every problem unsat), "refuted" (one sat: Impact's proof is wrong),
    /// "resource limit", "unknown (...)", or "not expressible: ..." (the first problem not confirmed).
    std::string status;
    bool confirmed() const { return status == "confirmed"; }
    bool refuted() const { return status == "refuted"; }
};

struct derivation_proofs {
    std::string id;
    std::string source;           ///< derivations/<file>.toml
    std::vector<proof_check> checks;
    std::size_t confirmed = 0;
    std::size_t problems = 0;     ///< problems written (expressible)
    std::size_t unsat = 0;        ///< problems Z3 answered unsat
};

struct proof_checks {
    std::vector<derivation_proofs> derivations;
    std::size_t proven = 0, confirmed = 0, problems = 0, unsat = 0;
    double seconds = 0;           ///< Z3's time, problems run (not from the cache)
    std::size_t run = 0;          ///< problems run (the rest from the cache)

    /// The status of a check, when it was proven (and re-checked); null otherwise.
    const std::string* status(const engine::check_result& c) const;
    /// One line per refuted check, with Z3's model: a proof of Impact's that is wrong.
    std::vector<std::string> refuted() const;
};

/// One problem's answer from Z3 and the seconds it took.
struct z3_run {
    z3_answer answer;
    double seconds = 0;
};

/// Runs Z3 on each of `problems`, preceded by `option`, as `run_z3` would (the same guard,
/// the same answers), and gives the answers in the problems' order, calling `finished()`
/// after each. The pipeline gives one that runs them in worker processes.
using z3_runner = std::function<std::vector<z3_run>(const std::string& option, const std::vector<std::string>& problems,
                                                    const std::function<void()>& finished)>;

/// The proven checks of `d` as problems (not yet run): its steps' checks and checks
/// (derivation::all_checks), then the paper's claims it proves. `done` holds the derivations
/// it uses (`[[use]]`), whose results a display form may name.
std::vector<proof_check> proof_checks_of(const engine::derivation& d, const engine::derived_by_id& done = {});

/// Runs each problem of `check` through Z3 (the answer taken from `store` when kept) and
/// sets its status.
void run_proof_check(proof_check& check, cache::store* store, proof_checks* totals = nullptr);

/// Every proven check of `derivations` re-checked (`done`: every derivation by id, for their
/// `[[use]]`s). The problems whose answers `store` does not hold are run together, each text
/// once, by `runner` (by default one after another, `run_z3`); `told` hears of each answered.
proof_checks check_proofs(const std::vector<const engine::derivation*>& derivations, const engine::derived_by_id& done,
                          cache::store* store, const std::function<void(std::size_t done, std::size_t all)>& told = {},
                          const z3_runner& runner = {});

/// output/proofs/<id>.smt2: the rlimit, then each problem in a (push) ... (check-sat-using) (pop)
/// block after a comment naming its check (and part); checks not stated, as comments.
std::string smt2_file(const derivation_proofs& d);

} // namespace impact::verify
