// The choice of one kernel's forms (plan_kernel): each output component's candidates
// measured on the kernel's samples, the best kept, and the fast form's cheapest within
// its bound; the plan's programs compiled from them (compile_chosen). Every kernel's
// plan, from the cache or measured, is in plan_kernels.cpp; the bounds they miss in
// missed_bounds.cpp.
#include "verify/choice.h"

#include "verify/cancellation.h"

#include "engine/cases/cases.h"
#include "engine/prove/sign.h"

#include <cln/integer.h>
#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <memory>
#include <optional>
#include <cstdlib>
#include <limits>
#include <stdexcept>

namespace impact::verify {
namespace {

// A seed from what the kernel computes from and gives: its inputs' and outputs' names,
// not its own name, so that a kernel renamed (or copied under another name) is measured
// on the same samples and its forms chosen alike. The FNV-1a hash.
std::uint64_t seed_of(const engine::kernel& k)
{
    std::uint64_t h = 1469598103934665603ULL;
    auto add = [&h](const std::string& text) {
        for (unsigned char c : text)
            h = (h ^ c) * 1099511628211ULL;
        h = (h ^ 0xffu) * 1099511628211ULL;   // a separator no name holds
    };
    for (const GiNaC::ex& input : k.input_symbols())
        add(GiNaC::ex_to<GiNaC::symbol>(input).get_name());
    for (const engine::kernel_output& o : k.outputs)
        add(o.member);
    return h;
}

// The candidate forms of one output component: those the engine proved, and the
// derived value expanded and factored; each also without its cancellations.
std::vector<engine::form> forms_of(const engine::kernel_output& o, std::size_t c)
{
    std::vector<engine::form> forms = o.candidates[c];
    for (const char* which : {"expanded", "factored"})
        if (auto f = derived_form(o, c, which))
            forms.push_back(*f);
    // Each without the cancellations of its functions (1 − cos θ as 2 sin²(θ/2), ...).
    const std::size_t written = forms.size();
    for (std::size_t f = 0; f < written; ++f) {
        const GiNaC::ex rewritten = without_cancellation(forms[f].value);
        if (!rewritten.is_equal(forms[f].value))
            forms.push_back({forms[f].label + ", no cancellation", rewritten});
    }
    // The same expression twice is one candidate.
    std::vector<engine::form> distinct;
    for (const engine::form& f : forms) {
        bool seen = false;
        for (const engine::form& d : distinct)
            seen = seen || d.value.is_equal(f.value);
        if (!seen)
            distinct.push_back(f);
    }
    return distinct;
}

// The divisions of p but those by a power of 2 (θ/2 in sin²(θ/2)), which are exact and which
// compilers make multiplications.
std::size_t true_divisions(const compile::program& p)
{
    return static_cast<std::size_t>(std::count_if(p.code.begin(), p.code.end(), [&](const compile::instruction& in) {
        if (in.op != compile::opcode::div)
            return false;
        const compile::instruction& by = p.code[static_cast<std::size_t>(in.b)];
        if (by.op != compile::opcode::constant || by.pi || !by.value.is_integer() || !by.value.is_positive())
            return true;
        const cln::cl_I n = cln::the<cln::cl_I>(by.value.to_cl_N());
        return cln::power2p(n) == 0;   // not a power of 2
    }));
}

bool better(const verify::accuracy& a, const verify::accuracy& b)
{
    if (a.max_ulps != b.max_ulps)
        return a.max_ulps < b.max_ulps;
    return a.mean_ulps < b.mean_ulps;
}

} // namespace

// The derived value of one output component expanded ("expanded") or factored
// ("factored"), as a quotient of polynomials; none when it has a radical.
std::optional<engine::form> derived_form(const engine::kernel_output& o, std::size_t c, const std::string& which)
{
    const GiNaC::ex derived = o.values[c];
    if (engine::has_radical(derived) || engine::has_select(derived))
        return std::nullopt;
    const GiNaC::ex nd = GiNaC::normal(derived).numer_denom();
    if (which == "expanded")
        return engine::form{"expanded", GiNaC::expand(nd.op(0)) / GiNaC::expand(nd.op(1))};
    return engine::form{"factored", engine::factor_polynomial(nd.op(0)) / engine::factor_polynomial(nd.op(1))};
}

namespace {

// A kernel with guards tests its divisors before it divides by them, in two groups
// (compile::grouped_divisors): `code` as it is when it can, else in the order that computes
// them first (the same operations on the same values, so the same results); none when no
// order can (divisions by late divisors that compute each other).
std::optional<compile::program> divisors_first(const engine::kernel& k, compile::program code)
{
    if (k.guards.empty() || !compile::divides_early(code))
        return code;
    code = compile::ordered_for_registers(code);
    if (compile::divides_early(code))
        return std::nullopt;
    return code;
}

// One program: the guards' conditions first (checked before anything is computed from
// them), then the form `which` names of every component, sharing what they can.
compile::program compile_forms(const kernel_plan& plan, const engine::kernel& k, const engine::term_order& order,
                               std::size_t component_plan::*which)
{
    std::vector<std::pair<GiNaC::ex, compile::compile_options>> outputs;
    for (const engine::kernel_guard& g : k.guards)
        if (g.condition)
            outputs.emplace_back(*g.condition, compile::compile_options{});
    for (const component_plan& cp : plan.components) {
        const candidate_result& form = cp.candidates[cp.*which];
        outputs.emplace_back(form.value, compile::compile_options{form.fma, form.compensated, form.compensated_lets});
    }
    std::optional<compile::program> code =
        divisors_first(k, compile::compile_program(outputs, k.input_symbols(), order, k.lets));
    if (!code)
        throw error(k.where, fmt::format("kernel '{}' divides by values that divisions by each other compute, so "
                                         "no order computes its divisors before it divides by them, as its guards "
                                         "need; give forms (forms = [...]) or a let that divide once",
                                         k.name));
    return *code;
}

} // namespace

bool fast_is_accurate(const kernel_plan& plan)
{
    return std::all_of(plan.components.begin(), plan.components.end(),
                       [](const component_plan& cp) { return cp.fastest == cp.chosen; });
}

void compile_chosen(kernel_plan& plan, const engine::kernel& k, const engine::term_order& order)
{
    plan.guard_values = static_cast<std::size_t>(
        std::count_if(k.guards.begin(), k.guards.end(), [](const engine::kernel_guard& g) { return g.condition.has_value(); }));
    plan.code = compile_forms(plan, k, order, &component_plan::chosen);
    plan.fast_code = fast_is_accurate(plan) ? plan.code : compile_forms(plan, k, order, &component_plan::fastest);
}

kernel_plan fast_form(const kernel_plan& plan)
{
    kernel_plan fast;
    fast.kernel = plan.kernel;
    fast.components = plan.components;
    for (component_plan& cp : fast.components)
        cp.chosen = cp.fastest;
    fast.code = plan.fast_code;
    fast.guard_values = plan.guard_values;
    fast.emitted = plan.fast_emitted;
    fast.fast_code = plan.fast_code;
    fast.fast_emitted = plan.fast_emitted;
    return fast;
}

namespace {

// Whether the kernel's guards admit the inputs: each condition `lhs < 0` or `lhs > 0`
// evaluated in double (the parameters' domains hold by how samples are drawn).
verify::admission admission(const engine::kernel& k, const engine::term_order& order)
{
    std::vector<GiNaC::ex> conditions;
    std::vector<engine::relation> relations;
    for (const engine::kernel_guard& g : k.guards)
        if (g.condition) {
            conditions.push_back(*g.condition);
            relations.push_back(g.op);
        }
    if (conditions.empty())
        return {};
    auto code = std::make_shared<compile::program>(compile::compile_program(conditions, k.input_symbols(), order));
    return [code, relations](const std::vector<double>& inputs) {
        const std::vector<double> values = compile::run<double>(*code, inputs);
        for (std::size_t i = 0; i < relations.size(); ++i)
            if (!(relations[i] == engine::relation::less ? values[i] < 0 : values[i] > 0))
                return false;
        return true;
    };
}

// The choice of one kernel's forms: each output component's candidates measured on the
// kernel's samples against the CLN reference, the best kept.
class chooser {
public:
    chooser(const engine::kernel& k, const engine::term_order& order) : k_(k), order_(order), inputs_(k.input_symbols())
    {
        plan_.kernel = &k;
        plan_.samples = verify::draw_samples(k, kernel_samples, seed_of(k), order, admission(k, order));
        plan_.double_reference = verify::compute_reference(k, plan_.samples, 53);
        plan_.float_reference = verify::compute_reference(k, plan_.samples, 24);
    }

    kernel_plan choose()
    {
        const auto all = verify::components(k_);
        for (std::size_t i = 0; i < all.size(); ++i)
            plan_.components.push_back(component(i, k_.outputs[all[i].first], all[i].second));
        compensate_lets_everywhere();
        choose_fastest();
        compile_chosen(plan_, k_, order_);
        // A fast form no cheaper than the accurate one (its candidates each cheapest alone,
        // the accurate form's sharing more) is the accurate one.
        if (!fast_is_accurate(plan_) &&
            !compile::cheaper(compile::cost_of(plan_.fast_code), compile::cost_of(plan_.code))) {
            for (component_plan& cp : plan_.components)
                cp.fastest = cp.chosen;
            compile_chosen(plan_, k_, order_);
        }
        plan_.emitted = measure_emitted(plan_.code);
        plan_.fast_emitted = fast_is_accurate(plan_) ? plan_.emitted : measure_emitted(plan_.fast_code);
        return std::move(plan_);
    }

private:
    component_plan component(std::size_t i, const engine::kernel_output& o, std::size_t c)
    {
        component_plan cp;
        cp.name = o.is_array ? fmt::format("{}[{}]", o.member, c) : o.member;
        const std::vector<candidate_result> plain = leanest_candidates(cp, forms_of(o, c));
        measure_pruned(cp, i, plain, o.fast_bound_ulps[1]);
        pick(cp);
        // Compensated arithmetic where it pays, and no more of it than needed: first the
        // kernel's `let` values alone (shared by every output), then the whole form.
        const std::size_t measured_plainly = cp.candidates.size();
        if (cp.candidates[cp.chosen].double_accuracy.max_ulps > target_ulps && !k_.lets.empty())
            add_variants(cp, i, measured_plainly, ", compensated let", &candidate_result::compensated_lets);
        if (cp.candidates[cp.chosen].double_accuracy.max_ulps > target_ulps)
            add_variants(cp, i, measured_plainly, ", compensated", &candidate_result::compensated);
        return cp;
    }

    // No square root or division that the mathematics does not need: only the forms with
    // the fewest of them (a division by a power of 2 is none) (e.g. the rotation-free lab-frame form, not the rotation matrix
    // with its |r|) are candidates, each with and without fused multiply-adds.
    std::vector<candidate_result> leanest_candidates(component_plan& cp, std::vector<engine::form> forms) const
    {
        // A kernel with `let` values computes them once for all its outputs (the one
        // division of the lab-frame collision): only forms built on them are candidates.
        if (!k_.lets.empty()) {
            std::vector<engine::form> on_lets;
            for (const engine::form& f : forms)
                for (const auto& [symbol, value] : k_.lets)
                    if (f.value.has(symbol)) {
                        on_lets.push_back(f);
                        break;
                    }
            if (!on_lets.empty()) {
                cp.heavier += forms.size() - on_lets.size();
                forms = on_lets;
            }
        }
        std::vector<std::pair<std::size_t, std::size_t>> cost;
        for (const engine::form& f : forms) {
            const compile::program p = compile::compile_program({f.value}, inputs_, order_, {}, k_.lets);
            cost.emplace_back(count(p, compile::opcode::sqrt), true_divisions(p));
        }
        const auto leanest = *std::min_element(cost.begin(), cost.end());
        std::vector<candidate_result> plain;
        for (std::size_t f = 0; f < forms.size(); ++f) {
            if (cost[f] != leanest) {
                ++cp.heavier;
                continue;
            }
            for (bool fused : {false, true}) {
                const compile::program p =
                    compile::compile_program({forms[f].value}, inputs_, order_, {fused}, k_.lets);
                if (fused && count(p, compile::opcode::fma) == 0)
                    continue;  // nothing to fuse: the same program as without
                candidate_result r;
                r.label = fused ? forms[f].label + ", fma" : forms[f].label;
                r.value = forms[f].value;
                r.fma = fused;
                plain.push_back(r);
            }
        }
        return plain;
    }

    // A first look on a sixth of the samples: a candidate far behind the best is not
    // measured further, unless it is within the fast bound there (`fast_bound`): the fast
    // form's choice measures those (choose_fastest), after the accurate form's.
    void measure_pruned(component_plan& cp, std::size_t i, const std::vector<candidate_result>& plain,
                        double fast_bound)
    {
        left_behind_.resize(std::max(left_behind_.size(), i + 1));
        const std::vector<verify::sample> first(plan_.samples.begin(),
                                                plan_.samples.begin() + static_cast<long>(plan_.samples.size() / 6));
        const verify::reference first_reference = verify::prefix(plan_.double_reference, first.size());
        double best_first = std::numeric_limits<double>::infinity();
        std::vector<double> first_max;
        for (const candidate_result& r : plain) {
            first_max.push_back(measured(r, i, first, first_reference).double_accuracy.max_ulps);
            best_first = std::min(best_first, first_max.back());
        }
        for (std::size_t c = 0; c < plain.size(); ++c) {
            if (first_max[c] > 2 * best_first + 1) {
                ++cp.pruned;
                if (first_max[c] <= fast_bound)
                    left_behind_[i].push_back(plain[c]);
                continue;
            }
            cp.candidates.push_back(measured(plain[c], i, plan_.samples, plan_.double_reference));
        }
    }

    // The first `plain` candidates again with `flag` set (fused ones excluded from whole
    // compensation, which does not fuse), then the best of all.
    void add_variants(component_plan& cp, std::size_t i, std::size_t plain, const char* label,
                      bool candidate_result::*flag) const
    {
        for (std::size_t c = 0; c < plain; ++c) {
            if (flag == &candidate_result::compensated && cp.candidates[c].fma)
                continue;
            candidate_result r = cp.candidates[c];
            r.label += label;
            r.*flag = true;
            cp.candidates.push_back(measured(r, i, plan_.samples, plan_.double_reference));
        }
        pick(cp);
    }

    static void pick(component_plan& cp)
    {
        for (std::size_t c = 1; c < cp.candidates.size(); ++c)
            if (better(cp.candidates[c].double_accuracy, cp.candidates[cp.chosen].double_accuracy))
                cp.chosen = c;
    }

    candidate_result measured(candidate_result r, std::size_t i, const std::vector<verify::sample>& on,
                              const verify::reference& ref) const
    {
        const compile::program p =
            compile::compile_program({r.value}, inputs_, order_, {r.fma, r.compensated, r.compensated_lets}, k_.lets);
        // A form whose divisions compute each other's divisors cannot be guarded
        // (divisors_first), and is never chosen.
        if (!divisors_first(k_, p)) {
            r.double_accuracy.samples = on.size();
            r.double_accuracy.max_ulps = r.double_accuracy.mean_ulps = std::numeric_limits<double>::infinity();
            r.double_accuracy.worst_regime = "its divisors not computable before its divisions";
            return r;
        }
        r.double_accuracy = verify::measure<double>(p, {i}, on, ref, !k_.guards.empty()).front();
        return r;
    }

    // The `let` values are computed once for the whole kernel: when one output needs
    // them compensated, every output takes its best compensated-let candidate.
    void compensate_lets_everywhere()
    {
        bool any_compensated_lets = false;
        for (const component_plan& cp : plan_.components)
            any_compensated_lets = any_compensated_lets || cp.candidates[cp.chosen].compensated_lets;
        if (!any_compensated_lets)
            return;
        for (std::size_t i = 0; i < plan_.components.size(); ++i) {
            component_plan& cp = plan_.components[i];
            if (cp.candidates[cp.chosen].compensated_lets)
                continue;
            const std::size_t before = cp.candidates.size();
            for (std::size_t c = 0; c < before; ++c) {
                candidate_result r = cp.candidates[c];
                if (r.compensated || r.compensated_lets)
                    continue;
                r.label += ", compensated let";
                r.compensated_lets = true;
                cp.candidates.push_back(measured(std::move(r), i, plan_.samples, plan_.double_reference));
            }
            std::size_t best = before;
            for (std::size_t c = before + 1; c < cp.candidates.size(); ++c)
                if (better(cp.candidates[c].double_accuracy, cp.candidates[best].double_accuracy))
                    best = c;
            if (best < cp.candidates.size())
                cp.chosen = best;
        }
    }

    // The fast form: each component's cheapest candidate (compile::cheaper, the candidate
    // compiled alone) within its fast bound in double, the more accurate of two that cost
    // the same. The `let` values are computed once for every output: first the candidates
    // that take them as they are, then, where a component has none within its bound, those
    // that compensate them, for every output; where a component has neither, the fast form
    // is the accurate one throughout.
    void choose_fastest()
    {
        // The candidates the accurate form's choice left behind that may be within the fast
        // bound (a candidate beyond it on a sixth of the samples is beyond it on them all).
        for (std::size_t i = 0; i < left_behind_.size(); ++i)
            for (const candidate_result& r : left_behind_[i]) {
                plan_.components[i].candidates.push_back(measured(r, i, plan_.samples, plan_.double_reference));
                --plan_.components[i].pruned;
            }
        for (const bool compensated_lets : {false, true}) {
            if (const auto fastest = cheapest_within_bounds(compensated_lets)) {
                for (std::size_t i = 0; i < fastest->size(); ++i)
                    plan_.components[i].fastest = (*fastest)[i];
                return;
            }
        }
        for (component_plan& cp : plan_.components)
            cp.fastest = cp.chosen;
    }

    // Each component's cheapest candidate within its fast bound among those that compensate
    // the `let` values or not, as `compensated_lets` says; nothing if a component has none.
    std::optional<std::vector<std::size_t>> cheapest_within_bounds(bool compensated_lets) const
    {
        const auto all = verify::components(k_);
        std::vector<std::size_t> fastest;
        for (std::size_t i = 0; i < plan_.components.size(); ++i) {
            const component_plan& cp = plan_.components[i];
            const double bound = k_.outputs[all[i].first].fast_bound_ulps[1];
            std::optional<std::size_t> best;
            compile::cost best_cost;
            for (std::size_t c = 0; c < cp.candidates.size(); ++c) {
                const candidate_result& r = cp.candidates[c];
                if (r.compensated_lets != compensated_lets || !(r.double_accuracy.max_ulps <= bound))
                    continue;
                const compile::cost cost = compile::cost_of(compile::compile_program(
                    {r.value}, inputs_, order_, {r.fma, r.compensated, r.compensated_lets}, k_.lets));
                if (!best || compile::cheaper(cost, best_cost) ||
                    (!compile::cheaper(best_cost, cost) && better(r.double_accuracy, cp.candidates[*best].double_accuracy))) {
                    best = c;
                    best_cost = cost;
                }
            }
            if (!best)
                return std::nullopt;
            fastest.push_back(*best);
        }
        return fastest;
    }

    // A program as emitted, its outputs all at once, in each type.
    std::vector<emitted_accuracy> measure_emitted(const compile::program& code) const
    {
        compile::program outputs_only = code;
        outputs_only.outputs.erase(outputs_only.outputs.begin(),
                                   outputs_only.outputs.begin() + static_cast<long>(plan_.guard_values));
        std::vector<std::size_t> which(plan_.components.size());
        for (std::size_t i = 0; i < which.size(); ++i)
            which[i] = i;
        const bool tests = !k_.guards.empty();
        const auto in_float = measure<float>(outputs_only, which, plan_.samples, plan_.float_reference, tests);
        const auto in_double = measure<double>(outputs_only, which, plan_.samples, plan_.double_reference, tests);
        const auto in_long = measure<long double>(outputs_only, which, plan_.samples, plan_.double_reference, tests);
        std::vector<emitted_accuracy> emitted;
        for (std::size_t i = 0; i < which.size(); ++i)
            emitted.push_back({in_float[i], in_double[i], in_long[i]});
        return emitted;
    }

    const engine::kernel& k_;
    const engine::term_order& order_;
    const std::vector<GiNaC::ex> inputs_;
    kernel_plan plan_;
    std::vector<std::vector<candidate_result>> left_behind_;  ///< per component: pruned, maybe within the fast bound
};

} // namespace

kernel_plan plan_kernel(const engine::kernel& k, const engine::term_order& order)
{
    try {
        return chooser(k, order).choose();
    } catch (const std::invalid_argument& e) {
        // What compile cannot turn into operations of the kernel (a constant such as Euler's):
        // the kernel's mistake, at its place in the file.
        throw error(k.where, fmt::format("kernel '{}': {} (a kernel computes with +, -, *, /, sqrt, rational "
                                         "numbers, Pi, abs, sin, cos, tan, asin, acos, atan, atan2, exp, log, "
                                         "sinh, cosh, tanh and pow; give any other constant or function as an "
                                         "input)",
                                         k.name, e.what()));
    }
}

} // namespace impact::verify
