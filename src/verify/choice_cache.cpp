// A kernel plan's choice as the text of a cache entry, and back (verify/choice.h).
#include "verify/choice.h"

#include "cache/store.h"
#include "verify/cancellation.h"

#include <fmt/format.h>

#include <cstdlib>
#include <limits>

namespace impact::verify {
namespace {

// The cache entries' text: one field a line, strings with their length in front
// (`5:label`), numbers as the shortest text that reads back to the same double.
struct entry_writer {
    std::string out;
    void text(const std::string& s) { out += fmt::format("{}:{}\n", s.size(), s); }
    void number(double x) { out += fmt::format("{}\n", x); }
    void count(std::size_t n) { out += fmt::format("{}\n", n); }
    void measured(const accuracy& a)
    {
        count(a.samples);
        number(a.mean_ulps);
        number(a.max_ulps);
        text(a.worst_regime);
        count(a.refused);
        text(a.first_refused_regime);
    }
};

struct reader {
    const std::string& in;
    std::size_t at = 0;
    bool ok = true;
    std::string line()
    {
        const std::size_t end = in.find('\n', at);
        if (end == std::string::npos) {
            ok = false;
            return {};
        }
        std::string l = in.substr(at, end - at);
        at = end + 1;
        return l;
    }
    std::string text()
    {
        const std::size_t colon = in.find(':', at);
        if (colon == std::string::npos || colon == at || colon - at > 12) {
            ok = false;
            return {};
        }
        const std::size_t n = std::strtoull(in.substr(at, colon - at).c_str(), nullptr, 10);
        if (colon + 1 + n >= in.size() || in[colon + 1 + n] != '\n') {
            ok = false;
            return {};
        }
        std::string s = in.substr(colon + 1, n);
        at = colon + 2 + n;
        return s;
    }
    double number()
    {
        const std::string l = line();
        char* end = nullptr;
        const double x = std::strtod(l.c_str(), &end);
        ok = ok && !l.empty() && end == l.c_str() + l.size();
        return x;
    }
    std::size_t count()
    {
        const std::string l = line();
        ok = ok && !l.empty() && l.find_first_not_of("0123456789") == std::string::npos && l.size() < 19;
        return ok ? std::stoull(l) : 0;
    }
    accuracy measured()
    {
        accuracy a;
        a.samples = count();
        a.mean_ulps = number();
        a.max_ulps = number();
        a.worst_regime = text();
        a.refused = count();
        a.first_refused_regime = text();
        return a;
    }
};

} // namespace

std::string choice_key(const engine::kernel& k, const engine::term_order& order)
{
    // Everything plan_kernel reads of the kernel, printed in the derivation's term order
    // (GiNaC's own printing changes from run to run), and the build that measures.
    entry_writer w;
    w.text("kernel choice, format 6");
    w.text(cache::program_fingerprint());
    w.count(kernel_samples);
    w.number(target_ulps);
    w.text(k.name);
    w.count(k.batch);
    for (const engine::kernel_parameter& p : k.parameters) {
        w.text(p.name);
        w.count(p.is_array);
        for (const engine::quantity& q : p.components) {
            w.text(q.name);
            w.text(order.text(q.symbol));
            w.count(static_cast<std::size_t>(q.range.what));
            w.number(q.range.lower);
            w.number(q.range.upper);
            w.count(q.range.lower_open);
            w.count(q.range.upper_open);
        }
    }
    w.text("velocities");
    for (const GiNaC::ex& v : k.velocities)
        w.text(order.text(v));
    for (const GiNaC::ex& v : k.speeds)
        w.text(order.text(v));
    for (const engine::kernel_output& o : k.outputs) {
        w.text(o.member);
        w.count(o.is_array);
        w.count(static_cast<std::size_t>(o.error));
        w.text(order.text(o.scale_factor));
        w.number(o.fast_bound_ulps[1]);   // the fast form's choice is made in double
        for (std::size_t c = 0; c < o.values.size(); ++c) {
            w.text(order.text(o.values[c]));
            for (const engine::form& f : o.candidates.at(c)) {
                w.text(f.label);
                w.text(order.text(f.value));
            }
        }
    }
    for (const engine::kernel_guard& g : k.guards) {
        w.text(g.status);
        for (const std::string& p : g.parameters)
            w.text(p);
        w.text(g.condition ? order.text(*g.condition) : "no condition");
        w.count(static_cast<std::size_t>(g.op));
    }
    for (const auto& [symbol, value] : k.lets) {
        w.text(order.text(symbol));
        w.text(order.text(value));
    }
    for (const engine::sampling_regime& r : k.regimes) {
        w.text(r.name);
        w.count(static_cast<std::size_t>(r.what));
        w.text(r.start);
        for (const std::vector<GiNaC::ex>* part : {&r.inputs, &r.offsets, &r.slopes}) {
            w.count(part->size());
            for (const GiNaC::ex& e : *part)
                w.text(order.text(e));
        }
        w.text(order.text(r.denominator));
        w.number(r.from);
        w.number(r.to);
    }
    return w.out;
}

std::string encode_choice(const kernel_plan& plan, const engine::term_order& order)
{
    const engine::kernel& k = *plan.kernel;
    const auto all = verify::components(k);
    entry_writer w;
    w.count(plan.components.size());
    for (std::size_t i = 0; i < plan.components.size(); ++i) {
        const component_plan& cp = plan.components[i];
        const engine::kernel_output& o = k.outputs[all[i].first];
        const std::size_t component = all[i].second;
        std::optional<engine::form> expanded, factored;
        // Where a candidate's form comes from (one of the engine's forms, or the derived value
        // expanded or factored, or one of those without its cancellations), so that reading
        // it back does not factor every output again; and its text, to check it against.
        const auto origin_of = [&](const GiNaC::ex& value) {
            for (const bool rewritten : {false, true}) {
                const auto as = [&](const GiNaC::ex& e) { return rewritten ? without_cancellation(e) : e; };
                const std::string prefix = rewritten ? "no cancellation: " : "";
                for (std::size_t j = 0; j < o.candidates[component].size(); ++j)
                    if (as(o.candidates[component][j].value).is_equal(value))
                        return prefix + fmt::format("engine {}", j);
                if (!expanded)
                    expanded = derived_form(o, component, "expanded");
                if (expanded && as(expanded->value).is_equal(value))
                    return prefix + "expanded";
                if (!rewritten)
                    continue;   // factored, unless it is a rewritten form
                if (!factored)
                    factored = derived_form(o, component, "factored");
                if (factored && as(factored->value).is_equal(value))
                    return prefix + "factored";
            }
            return std::string("factored");
        };
        w.text(cp.name);
        w.count(cp.chosen);
        w.count(cp.fastest);
        w.count(cp.heavier);
        w.count(cp.pruned);
        w.count(cp.candidates.size());
        for (const candidate_result& r : cp.candidates) {
            w.text(origin_of(r.value));
            w.text(order.text(r.value));
            w.text(r.label);
            w.count(r.fma);
            w.count(r.compensated);
            w.count(r.compensated_lets);
            w.measured(r.double_accuracy);
        }
        w.measured(plan.emitted.at(i).in_float);
        w.measured(plan.emitted.at(i).in_double);
        w.measured(plan.emitted.at(i).in_long_double);
        w.measured(plan.fast_emitted.at(i).in_float);
        w.measured(plan.fast_emitted.at(i).in_double);
        w.measured(plan.fast_emitted.at(i).in_long_double);
    }
    w.text("end");
    return w.out;
}

std::optional<kernel_plan> decode_choice(const std::string& text, const engine::kernel& k,
                                         const engine::term_order& order)
{
    const auto all = verify::components(k);
    reader r{text};
    kernel_plan plan;
    plan.kernel = &k;
    if (r.count() != all.size() || !r.ok)
        return std::nullopt;
    for (std::size_t i = 0; i < all.size(); ++i) {
        const engine::kernel_output& o = k.outputs[all[i].first];
        const std::size_t component = all[i].second;
        std::map<std::string, GiNaC::ex> derived;
        component_plan cp;
        cp.name = r.text();
        cp.chosen = r.count();
        cp.fastest = r.count();
        cp.heavier = r.count();
        cp.pruned = r.count();
        const std::size_t n = r.count();
        if (!r.ok || n == 0 || cp.chosen >= n || cp.fastest >= n || n > 64 * (o.candidates[component].size() + 2))
            return std::nullopt;
        for (std::size_t c = 0; c < n; ++c) {
            candidate_result cr;
            std::string origin = r.text();
            const std::string value_text = r.text();
            if (!r.ok)
                return std::nullopt;
            const std::string rewritten = "no cancellation: ";
            const bool is_rewritten = origin.rfind(rewritten, 0) == 0;
            if (is_rewritten)
                origin = origin.substr(rewritten.size());
            if (origin.rfind("engine ", 0) == 0) {
                const std::size_t j = std::strtoull(origin.c_str() + 7, nullptr, 10);
                if (j >= o.candidates[component].size())
                    return std::nullopt;
                cr.value = o.candidates[component][j].value;
            } else if (origin == "expanded" || origin == "factored") {
                if (!derived.count(origin)) {
                    const auto f = derived_form(o, component, origin);
                    if (!f)
                        return std::nullopt;
                    derived[origin] = f->value;
                }
                cr.value = derived.at(origin);
            } else {
                return std::nullopt;
            }
            if (is_rewritten)
                cr.value = without_cancellation(cr.value);
            if (order.text(cr.value) != value_text)
                return std::nullopt;
            cr.label = r.text();
            cr.fma = r.count() != 0;
            cr.compensated = r.count() != 0;
            cr.compensated_lets = r.count() != 0;
            cr.double_accuracy = r.measured();
            cp.candidates.push_back(std::move(cr));
        }
        emitted_accuracy e;
        e.in_float = r.measured();
        e.in_double = r.measured();
        e.in_long_double = r.measured();
        plan.emitted.push_back(e);
        emitted_accuracy fast;
        fast.in_float = r.measured();
        fast.in_double = r.measured();
        fast.in_long_double = r.measured();
        plan.fast_emitted.push_back(fast);
        plan.components.push_back(std::move(cp));
    }
    if (r.text() != "end" || !r.ok || r.at != text.size())
        return std::nullopt;
    compile_chosen(plan, k, order);
    return plan;
}

} // namespace impact::verify
