#include "verify/choice.h"

#include "engine/sign.h"

#include <fmt/format.h>

#include <algorithm>
#include <limits>

namespace impact::verify {
namespace {

// A seed from the kernel's name, so that each kernel has its own repeatable samples.
std::uint64_t seed_of(const std::string& name)
{
    std::uint64_t h = 1469598103934665603ULL;
    for (unsigned char c : name)
        h = (h ^ c) * 1099511628211ULL;
    return h;
}

// The candidate forms of one output component: those the engine proved, and the
// derived value expanded and factored.
std::vector<engine::form> forms_of(const engine::kernel_output& o, std::size_t c)
{
    std::vector<engine::form> forms = o.candidates[c];
    const GiNaC::ex derived = o.values[c];
    if (!engine::has_radical(derived)) {
        const GiNaC::ex nd = GiNaC::normal(derived).numer_denom();
        forms.push_back({"expanded", GiNaC::expand(nd.op(0)) / GiNaC::expand(nd.op(1))});
        forms.push_back({"factored", engine::factor_polynomial(nd.op(0)) / engine::factor_polynomial(nd.op(1))});
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

bool better(const verify::accuracy& a, const verify::accuracy& b)
{
    if (a.max_ulps != b.max_ulps)
        return a.max_ulps < b.max_ulps;
    return a.mean_ulps < b.mean_ulps;
}

} // namespace

kernel_plan plan_kernel(const engine::kernel& k, const engine::term_order& order)
{
    kernel_plan plan;
    plan.kernel = &k;
    plan.samples = verify::draw_samples(k, kernel_samples, seed_of(k.name));
    plan.double_reference = verify::compute_reference(k, plan.samples, 53);
    plan.float_reference = verify::compute_reference(k, plan.samples, 24);
    const std::vector<GiNaC::ex> inputs = k.input_symbols();

    const auto all = verify::components(k);
    for (std::size_t i = 0; i < all.size(); ++i) {
        const engine::kernel_output& o = k.outputs[all[i].first];
        component_plan cp;
        cp.name = o.is_array ? fmt::format("{}[{}]", o.member, all[i].second) : o.member;
        auto measured = [&](candidate_result r, const std::vector<verify::sample>& on, const verify::reference& ref) {
            const compile::program p = compile::compile_program({r.value}, inputs, order,
                                      {r.fma, r.compensated, r.compensated_lets}, k.lets);
            r.double_accuracy = verify::measure<double>(p, {i}, on, ref).front();
            return r;
        };

        // No square root or division that the mathematics does not need: only the forms
        // with the fewest of them (e.g. the rotation-free lab-frame form, not the
        // rotation matrix with its |r|) are candidates.
        std::vector<engine::form> forms = forms_of(o, all[i].second);
        // A kernel with `let` values computes them once for all its outputs (the one
        // division of the lab-frame collision): only forms built on them are candidates.
        if (!k.lets.empty()) {
            std::vector<engine::form> on_lets;
            for (const engine::form& f : forms)
                for (const auto& [symbol, value] : k.lets)
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
            const compile::program p = compile::compile_program({f.value}, inputs, order, {}, k.lets);
            cost.emplace_back(count(p, compile::opcode::sqrt), count(p, compile::opcode::div));
        }
        const auto leanest = *std::min_element(cost.begin(), cost.end());
        std::vector<candidate_result> plain;
        for (std::size_t f = 0; f < forms.size(); ++f) {
            if (cost[f] != leanest) {
                ++cp.heavier;
                continue;
            }
            for (bool fused : {false, true}) {
                const compile::program p = compile::compile_program({forms[f].value}, inputs, order, {fused}, k.lets);
                if (fused && count(p, compile::opcode::fma) == 0)
                    continue;  // nothing to fuse: the same program as without
                candidate_result r;
                r.label = fused ? forms[f].label + ", fma" : forms[f].label;
                r.value = forms[f].value;
                r.fma = fused;
                plain.push_back(r);
            }
        }
        // A first look on a sixth of the samples: a candidate far behind the best is not
        // measured further.
        const std::vector<verify::sample> first(plan.samples.begin(),
                                                plan.samples.begin() + static_cast<long>(plan.samples.size() / 6));
        const verify::reference first_reference = verify::prefix(plan.double_reference, first.size());
        double best_first = std::numeric_limits<double>::infinity();
        std::vector<double> first_max;
        for (const candidate_result& r : plain) {
            first_max.push_back(measured(r, first, first_reference).double_accuracy.max_ulps);
            best_first = std::min(best_first, first_max.back());
        }
        for (std::size_t c = 0; c < plain.size(); ++c) {
            if (first_max[c] > 2 * best_first + 1) {
                ++cp.pruned;
                continue;
            }
            cp.candidates.push_back(measured(plain[c], plan.samples, plan.double_reference));
        }
        auto choose = [&] {
            for (std::size_t c = 1; c < cp.candidates.size(); ++c)
                if (better(cp.candidates[c].double_accuracy, cp.candidates[cp.chosen].double_accuracy))
                    cp.chosen = c;
        };
        choose();
        // Compensated arithmetic where it pays, and no more of it than needed: first the
        // kernel's `let` values alone (shared by every output), then the whole form.
        const std::size_t measured_plainly = cp.candidates.size();
        if (cp.candidates[cp.chosen].double_accuracy.max_ulps > target_ulps && !k.lets.empty()) {
            for (std::size_t c = 0; c < measured_plainly; ++c) {
                candidate_result r = cp.candidates[c];
                r.label += ", compensated let";
                r.compensated_lets = true;
                cp.candidates.push_back(measured(r, plan.samples, plan.double_reference));
            }
            choose();
        }
        if (cp.candidates[cp.chosen].double_accuracy.max_ulps > target_ulps) {
            for (std::size_t c = 0; c < measured_plainly; ++c) {
                if (cp.candidates[c].fma)
                    continue;
                candidate_result r = cp.candidates[c];
                r.label += ", compensated";
                r.compensated = true;
                cp.candidates.push_back(measured(r, plan.samples, plan.double_reference));
            }
            choose();
        }
        plan.components.push_back(std::move(cp));
    }

    // The `let` values are computed once for the whole kernel: when one output needs
    // them compensated, every output takes its best compensated-let candidate.
    bool any_compensated_lets = false;
    for (const component_plan& cp : plan.components)
        any_compensated_lets = any_compensated_lets || cp.candidates[cp.chosen].compensated_lets;
    if (any_compensated_lets) {
        for (std::size_t i = 0; i < plan.components.size(); ++i) {
            component_plan& cp = plan.components[i];
            if (cp.candidates[cp.chosen].compensated_lets)
                continue;
            const std::size_t before = cp.candidates.size();
            for (std::size_t c = 0; c < before; ++c) {
                candidate_result r = cp.candidates[c];
                if (r.compensated || r.compensated_lets)
                    continue;
                r.label += ", compensated let";
                r.compensated_lets = true;
                const compile::program p = compile::compile_program({r.value}, inputs, order, {r.fma, false, true}, k.lets);
                r.double_accuracy = verify::measure<double>(p, {i}, plan.samples, plan.double_reference).front();
                cp.candidates.push_back(std::move(r));
            }
            std::size_t best = before;
            for (std::size_t c = before + 1; c < cp.candidates.size(); ++c)
                if (better(cp.candidates[c].double_accuracy, cp.candidates[best].double_accuracy))
                    best = c;
            if (best < cp.candidates.size())
                cp.chosen = best;
        }
    }

    // One program: the guards' conditions first (checked before anything is computed
    // from them), then the chosen form of every component, sharing what they can.
    std::vector<std::pair<GiNaC::ex, compile::compile_options>> outputs;
    for (const engine::kernel_guard& g : k.guards)
        if (g.condition)
            outputs.emplace_back(*g.condition, compile::compile_options{});
    plan.guard_values = outputs.size();
    for (const component_plan& cp : plan.components) {
        const candidate_result& chosen = cp.candidates[cp.chosen];
        outputs.emplace_back(chosen.value, compile::compile_options{chosen.fma, chosen.compensated, chosen.compensated_lets});
    }
    plan.code = compile::compile_program(outputs, inputs, order, k.lets);

    // The program as emitted, its outputs all at once, in each type.
    compile::program outputs_only = plan.code;
    outputs_only.outputs.erase(outputs_only.outputs.begin(),
                               outputs_only.outputs.begin() + static_cast<long>(plan.guard_values));
    std::vector<std::size_t> which(plan.components.size());
    for (std::size_t i = 0; i < which.size(); ++i)
        which[i] = i;
    const auto in_float = measure<float>(outputs_only, which, plan.samples, plan.float_reference);
    const auto in_double = measure<double>(outputs_only, which, plan.samples, plan.double_reference);
    const auto in_long = measure<long double>(outputs_only, which, plan.samples, plan.double_reference);
    for (std::size_t i = 0; i < which.size(); ++i)
        plan.emitted.push_back({in_float[i], in_double[i], in_long[i]});
    return plan;
}

std::vector<kernel_plan> plan_kernels(const engine::library& lib)
{
    std::vector<kernel_plan> plans;
    for (const engine::derivation* d : lib.in_order()) {
        const engine::term_order order = engine::declaration_order(d->symbols);
        for (const engine::kernel& k : d->kernels)
            plans.push_back(plan_kernel(k, order));
    }
    return plans;
}

} // namespace impact::verify
