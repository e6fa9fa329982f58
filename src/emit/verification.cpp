#include "emit/verification.h"

#include "emit/cxx_parts.h"

#include "engine/expr/infix.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <map>

namespace impact::emit {
namespace {

std::string scale_text(const engine::kernel_output& o, const engine::term_order& order)
{
    if (o.error == engine::kernel_output::scale::relative)
        return "its exact value";
    if (o.scale_factor.is_equal(1))
        return "the largest velocity";
    return "the largest velocity × " + engine::ginac_syntax(o.scale_factor, order);
}

// Text in a cell of a Markdown table: a `|` (a regime named |g_t|/g_n) written \|.
std::string table_cell(const std::string& text)
{
    std::string out;
    for (char c : text) {
        if (c == '|')
            out += '\\';
        out += c;
    }
    return out;
}

// One row of a form's accuracy table: an output component in one type.
struct accuracy_row {
    std::string output;
    const char* type = "";
    const verify::accuracy* measured = nullptr;
    double bound = 0;
    bool set = false;    ///< the bound set by the derivation file
    std::string scale;
    std::string form;
};

// The rows of one form's table: each output in each type, against `bound`.
std::vector<accuracy_row> accuracy_rows(const verify::kernel_plan& plan, const std::vector<verify::emitted_accuracy>& emitted,
                                        std::array<double, 3> engine::kernel_output::*bound,
                                        std::array<std::string, 3> engine::kernel_output::*because,
                                        std::size_t verify::component_plan::*form, const engine::term_order& order)
{
    const engine::kernel& k = *plan.kernel;
    std::vector<accuracy_row> rows;
    const auto components = verify::components(k);
    for (std::size_t i = 0; i < plan.components.size(); ++i) {
        const verify::component_plan& cp = plan.components[i];
        const engine::kernel_output& o = k.outputs[components[i].first];
        const verify::emitted_accuracy& measured = emitted[i];
        const verify::accuracy* in_type[] = {&measured.in_float, &measured.in_double, &measured.in_long_double};
        for (std::size_t t = 0; t < 3; ++t)
            rows.push_back({cp.name, engine::kernel_output::types[t], in_type[t], (o.*bound)[t], !(o.*because)[t].empty(),
                            scale_text(o, order), cp.candidates[cp.*form].label});
    }
    return rows;
}

// The table of one form's outputs, in Markdown.
std::string accuracy_table(const verify::kernel_plan& plan, const std::vector<verify::emitted_accuracy>& emitted,
                           std::array<double, 3> engine::kernel_output::*bound,
                           std::array<std::string, 3> engine::kernel_output::*because,
                           std::size_t verify::component_plan::*form, const engine::term_order& order)
{
    std::string out = "| output | type | samples | mean ulps | max ulps | bound | worst regime | scale | form |\n"
                      "| --- | --- | --- | --- | --- | --- | --- | --- | --- |\n";
    for (const accuracy_row& r : accuracy_rows(plan, emitted, bound, because, form, order))
        out += fmt::format("| `{}` | {} | {} | {:.3f} | {:.2f} | {:g}{} | {} | {} | {} |\n", r.output, r.type,
                           r.measured->samples, r.measured->mean_ulps, r.measured->max_ulps, r.bound, r.set ? " (set)" : "",
                           table_cell(r.measured->worst_regime), table_cell(r.scale), table_cell(r.form));
    return out;
}

// Text escaped for HTML.
std::string html_text(const std::string& text)
{
    std::string out;
    for (char c : text)
        out += c == '&' ? "&amp;" : c == '<' ? "&lt;" : c == '>' ? "&gt;" : c == '"' ? "&quot;" : std::string(1, c);
    return out;
}

// The same table in HTML, each output's first row anchored `kernel-<kernel>-<output>`
// (`anchor` the kernel's part).
std::string accuracy_table_html(const std::vector<accuracy_row>& rows, const std::string& anchor)
{
    std::string out = "<div class=\"table\"><table class=\"accuracy\">\n<thead><tr><th>output</th><th>type</th>"
                      "<th>samples</th><th>mean ulps</th><th>max ulps</th><th>bound</th><th>worst regime</th>"
                      "<th>scale</th><th>form</th></tr></thead>\n<tbody>\n";
    std::string previous;
    for (const accuracy_row& r : rows) {
        const std::string id = r.output != previous && !anchor.empty()
                                   ? fmt::format(" id=\"{}-{}\"", anchor, html_text(r.output))
                                   : std::string();
        previous = r.output;
        out += fmt::format("<tr{}><td><code>{}</code></td><td>{}</td><td>{}</td><td>{:.3f}</td><td>{:.2f}</td>"
                           "<td>{:g}{}</td><td>{}</td><td>{}</td><td>{}</td></tr>\n",
                           id, html_text(r.output), r.type, r.measured->samples, r.measured->mean_ulps,
                           r.measured->max_ulps, r.bound, r.set ? " (set)" : "", html_text(r.measured->worst_regime),
                           html_text(r.scale), html_text(r.form));
    }
    return out + "</tbody>\n</table></div>\n";
}

// One form's point on the kernel's speed/accuracy frontier: its cost, counted, and its
// largest error in each type over every output.
std::string frontier_row(const char* form, const compile::program& code,
                         const std::vector<verify::emitted_accuracy>& emitted)
{
    const compile::cost cost = compile::cost_of(code);
    double worst[3] = {0, 0, 0};
    for (const verify::emitted_accuracy& e : emitted) {
        worst[0] = std::max(worst[0], e.in_float.max_ulps);
        worst[1] = std::max(worst[1], e.in_double.max_ulps);
        worst[2] = std::max(worst[2], e.in_long_double.max_ulps);
    }
    return fmt::format("| {} | {} | {} | {} | {:.2f} | {:.2f} | {:.2f} |\n", form, cost.operations, cost.divisions,
                       cost.square_roots, worst[0], worst[1], worst[2]);
}

// The section on the proofs Z3 re-checked: the counts per derivation and in all, then
// every proven claim it did not confirm, with why.
std::string proofs_section(const verify::proof_checks& z3)
{
    std::string out = fmt::format(
        "\n## Every proof re-checked by Z3\n\n"
        "Each check Impact reports proven is written as SMT-LIB 2 problems (`proofs/<id>.smt2`: the "
        "declared domains, the abbreviations' definitions, where the sides are defined, the conditions and "
        "the case assumed, then the claim negated) and run through Z3 {} in-process, each problem under "
        "Z3's resource limit of {} steps (`rlimit`: the same answer on every machine). Confirmed: every "
        "problem of the claim is unsat. `z3 proofs/<id>.smt2` prints the same answers, one per problem.\n\n"
        "**Z3 confirmed {} of the {} proven claims** ({} of {} problems unsat).\n\n"
        "| derivation | proven claims | confirmed by Z3 | problems | unsat |\n"
        "| --- | --- | --- | --- | --- |\n",
        verify::z3_version(), verify::z3_rlimit, z3.confirmed, z3.proven, z3.unsat, z3.problems);
    for (const verify::derivation_proofs& d : z3.derivations)
        out += fmt::format("| `{}` | {} | {} | {} | {} |\n", d.id, d.checks.size(), d.confirmed, d.problems, d.unsat);
    out += fmt::format("| all | {} | {} | {} | {} |\n", z3.proven, z3.confirmed, z3.problems, z3.unsat);
    std::string missed;
    for (const verify::derivation_proofs& d : z3.derivations)
        for (const verify::proof_check& c : d.checks)
            if (!c.confirmed())
                missed += fmt::format("- `{}`: {}: {}\n", d.id, table_cell(c.label), c.status);
    if (!missed.empty())
        out += "\nProven claims Z3 did not confirm, with why:\n\n" + missed;
    return out;
}

} // namespace

std::string verification_markdown(const std::vector<const verify::kernel_plan*>& plans, const std::string& folder,
                                  bool of_the_paper, const verify::proof_checks* z3)
{
    // The paper's folder: kernels of collisions, sampled where collisions are hard. A folder
    // of one's own: its kernels, sampled where their inputs make them hard, in words that
    // name no collision (errata.md and the report speak of one's own folder so too).
    const std::string drawn =
        of_the_paper
            ? "Every output of every generated kernel, run on inputs drawn from the regimes where "
              "collisions are hard to compute, each kernel's listed under its name: the positive "
              "inputs (masses, radii, friction) over 12 decades, each input of an interval (eps, beta, "
              "q) near each of its ends (1e-12 to 1e-1 of its width from it), nearly grazing and "
              "nearly head-on hits where the kernel has a line of approach (two centres, or a "
              "wall's normal), nearly equal "
              "velocities where it has two, and the regimes its derivation file declares (a ratio "
              "over decades, a boundary between cases approached within a hair); "
            : "Every output of every kernel generated from the derivation files in `" + folder +
                  "`, run on inputs drawn from the regimes where its value is hard to compute, each "
                  "kernel's listed under its name: its positive inputs over 12 decades, each input of an "
                  "interval near each of its ends (1e-12 to 1e-1 of its width from it), and the regimes its "
                  "derivation file declares (a ratio over decades, a boundary between cases approached "
                  "within a hair); ";
    const std::string scale =
        of_the_paper ? "scale: its exact value, or the largest velocity magnitude among the inputs and the "
                       "exact outputs (times the reduced mass for the impulse J). "
                     : "scale, which its table names: its exact value, or the largest velocity magnitude "
                       "among the inputs and the exact outputs, times the factor given. ";
    std::string out = "<!-- Generated by Impact from " + folder + "; do not edit. -->\n"
                      "# Kernel verification\n\n" +
                      drawn +
                      "compared with "
                      "the derived result evaluated by CLN to 60 significant digits (about 199 bits: the "
                      "inputs are exact in it, and so are products of two or three of them) at the same inputs rounded "
                      "to the type. A C library function a kernel calls (`std::atan2`) is taken correctly rounded "
                      "from CLN, so that these figures are the same on every machine; the C library a "
                      "kernel runs with adds its own error to that call (its last bit differs between "
                      "libraries and CPUs: glibc's manual lists its bounds under \"Errors in Math "
                      "Functions\"). Errors are in ulps of the output's " +
                      scale +
                      "Every output must stay "
                      "within its bound, 4 ulps unless its derivation file sets another with a reason, in "
                      "every type, or the regeneration fails; in the fast form (`impact::fast`), its fast bound, "
                      "16 ulps unless the file sets another. The programs are measured "
                      "exactly as emitted (one operation at a time, no FMA contraction: kernels are compiled "
                      "with -ffp-contract=off in the tests).\n";
    for (const verify::kernel_plan* plan : plans) {
        const engine::kernel& k = *plan->kernel;
        const engine::term_order order(k.input_symbols());
        if (k.limit_of.empty())
            out += fmt::format("\n## `{}`\n\n", k.name);
        else  // a fixed sphere's kernel, beside the finite one
            out += fmt::format("\n## `{}` with `{}` = +infinity (a fixed sphere: the limit {} -> infinity)\n\n",
                               k.limit_of, k.fixed_mass, k.fixed_mass);
        std::vector<std::string> regimes;
        for (const std::string& r : verify::regime_names(k, order))
            regimes.push_back(table_cell(r));
        out += fmt::format("Samples drawn in turn in {} regimes: {}.\n\n", regimes.size(), fmt::join(regimes, "; "));
        out += accuracy_table(*plan, plan->emitted, &engine::kernel_output::bound_ulps,
                              &engine::kernel_output::bound_because, &verify::component_plan::chosen, order);
        // A bound the derivation file sets, with its reason.
        for (const engine::kernel_output& o : k.outputs) {
            const auto& types = engine::kernel_output::types;
            for (std::size_t t = 0; t < 3; ++t) {
                if (!o.bound_because[t].empty())
                    out += fmt::format("\nBound of `{}` in {} set to {:g} ulps by the derivation file: {}\n",
                                       o.member, types[t], o.bound_ulps[t], o.bound_because[t]);
                if (!o.fast_bound_because[t].empty())
                    out += fmt::format("\nFast form's bound of `{}` in {} set to {:g} ulps by the derivation file: {}\n",
                                       o.member, types[t], o.fast_bound_ulps[t], o.fast_bound_because[t]);
            }
        }
        // The fast form (impact::fast), and both forms as points of cost and error.
        out += "\nThe fast form (`impact::fast`): each output in its cheapest candidate within its fast bound (16 ulps "
               "unless the derivation file sets another), the same guards and statuses.";
        if (verify::fast_is_accurate(*plan)) {
            out += " Within those bounds in double no form is cheaper than the accurate one: the fast form is the "
                   "accurate one.\n";
        } else {
            out += "\n\n";
            out += accuracy_table(*plan, plan->fast_emitted, &engine::kernel_output::fast_bound_ulps,
                                  &engine::kernel_output::fast_bound_because, &verify::component_plan::fastest, order);
        }
        out += "\nCost (operations counted in the emitted program, guards' conditions included) and largest error "
               "over the outputs, in ulps:\n\n"
               "| form | operations | divisions | square roots | float | double | long double |\n"
               "| --- | --- | --- | --- | --- | --- | --- |\n";
        out += frontier_row("accurate", plan->code, plan->emitted);
        out += frontier_row("fast", plan->fast_code, plan->fast_emitted);
        out += "\nCandidates in double (maximum ulps; the accurate form's is marked, the fast form's followed by "
               "\"(fast)\"):\n\n";
        for (const verify::component_plan& cp : plan->components) {
            std::vector<std::string> items;
            for (std::size_t c = 0; c < cp.candidates.size(); ++c)
                items.push_back(fmt::format("{}{} {:.2f}{}{}", c == cp.chosen ? "**" : "", cp.candidates[c].label,
                                            cp.candidates[c].double_accuracy.max_ulps, c == cp.chosen ? "**" : "",
                                            c == cp.fastest ? " (fast)" : ""));
            out += fmt::format("- `{}`: {}", cp.name, fmt::join(items, "; "));
            if (cp.pruned)
                out += fmt::format(" ({} more left behind on the first sixth of the samples)", cp.pruned);
            if (cp.heavier)
                out += fmt::format(" ({} forms not built on the kernel's shared values, or with a square root or "
                                   "division more than needed, not considered)",
                                   cp.heavier);
            out += "\n";
        }
    }
    if (z3)
        out += proofs_section(*z3);
    return out;
}

namespace {

// A kernel's anchor on its derivation's page: `kernel-<name>`, `kernel-<name>-fixed-<mass>`
// for a fixed sphere's.
std::string kernel_anchor(const engine::kernel& k)
{
    return k.limit_of.empty() ? "kernel-" + k.name : fmt::format("kernel-{}-fixed-{}", k.limit_of, k.fixed_mass);
}

} // namespace

std::map<std::string, std::string> verification_html(const std::vector<const engine::derivation*>& derivations,
                                                    const std::vector<const verify::kernel_plan*>& plans)
{
    std::map<std::string, std::string> pages;
    for (const engine::derivation* d : derivations) {
        std::string out;
        for (const verify::kernel_plan* plan : plans) {
            const engine::kernel& k = *plan->kernel;
            if (k.where.file != d->source.file)
                continue;
            const engine::term_order order(k.input_symbols());
            const std::string anchor = kernel_anchor(k);
            out += k.limit_of.empty()
                       ? fmt::format("<h4 id=\"{}\"><code>impact::{}</code></h4>\n", anchor, html_text(k.name))
                       : fmt::format("<h4 id=\"{}\"><code>impact::{}</code> with <code>{}</code> = +infinity (a fixed "
                                     "sphere)</h4>\n",
                                     anchor, html_text(k.limit_of), html_text(k.fixed_mass));
            out += "<p>Each output measured against CLN to 60 digits on inputs drawn where it is hard to compute, in "
                   "ulps of its scale (<a href=\"../verification.md\">verification.md</a> holds every kernel's, with the "
                   "regimes drawn and the candidates each form was chosen from).</p>\n";
            out += accuracy_table_html(accuracy_rows(*plan, plan->emitted, &engine::kernel_output::bound_ulps,
                                                     &engine::kernel_output::bound_because,
                                                     &verify::component_plan::chosen, order),
                                       anchor);
            if (verify::fast_is_accurate(*plan)) {
                out += "<p>The fast form (<code>impact::fast</code>) is the accurate one.</p>\n";
            } else {
                out += "<p>The fast form (<code>impact::fast</code>):</p>\n";
                out += accuracy_table_html(accuracy_rows(*plan, plan->fast_emitted, &engine::kernel_output::fast_bound_ulps,
                                                         &engine::kernel_output::fast_bound_because,
                                                         &verify::component_plan::fastest, order),
                                           "");
            }
        }
        if (!out.empty())
            pages[d->id()] = "<h3 id=\"kernels\">Kernels.</h3>\n<p>Generated from this derivation into "
                             "<code>output/kernels/impact/</code>, verified as below.</p>\n" +
                             out;
    }
    // The index's summary: each kernel's largest error over its outputs, in each type and form.
    std::string rows;
    for (const engine::derivation* d : derivations)
        for (const verify::kernel_plan* plan : plans) {
            const engine::kernel& k = *plan->kernel;
            if (k.where.file != d->source.file)
                continue;
            double worst[2][3] = {};
            for (int form = 0; form < 2; ++form)
                for (const verify::emitted_accuracy& e : form ? plan->fast_emitted : plan->emitted) {
                    worst[form][0] = std::max(worst[form][0], e.in_float.max_ulps);
                    worst[form][1] = std::max(worst[form][1], e.in_double.max_ulps);
                    worst[form][2] = std::max(worst[form][2], e.in_long_double.max_ulps);
                }
            const std::size_t n = cxx_detail::dimension(k);
            const std::string name = (k.limit_of.empty() ? k.name : fmt::format("{} ({} fixed)", k.limit_of, k.fixed_mass)) +
                                     (n ? fmt::format(", {}D", n) : "");
            const std::string anchor = kernel_anchor(k);
            rows += fmt::format("<tr><td><a href=\"{}.html#{}\"><code>{}</code></a></td><td>{}</td><td>{:.2f}</td>"
                                "<td>{:.2f}</td><td>{:.2f}</td><td>{:.2f}</td><td>{:.2f}</td><td>{:.2f}</td></tr>\n",
                                html_text(d->id()), html_text(anchor), html_text(name), k.outputs.size(), worst[0][0],
                                worst[0][1], worst[0][2], worst[1][0], worst[1][1], worst[1][2]);
        }
    if (!rows.empty())
        pages[""] = "<p>Every kernel's largest error over its outputs, in ulps of their scales, measured against CLN "
                    "(each output's bound is 4 ulps in the accurate form and 16 in the fast one unless its derivation "
                    "file sets another):</p>\n<div class=\"table\"><table class=\"accuracy\">\n<thead><tr>"
                    "<th>kernel</th><th>outputs</th><th>float</th><th>double</th><th>long double</th><th>fast, float</th>"
                    "<th>fast, double</th><th>fast, long double</th></tr></thead>\n<tbody>\n" +
                    rows + "</tbody>\n</table></div>\n";
    return pages;
}

} // namespace impact::emit
