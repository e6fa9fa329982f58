// Every output a plan's emitted program measures past its bound, as one error line each
// (verify/choice.h, missed_bounds).
#include "verify/choice.h"

#include <fmt/format.h>

#include <array>

namespace impact::verify {

namespace {

// How far a measured form is from its bound: its largest error, or the collisions it refuses.
std::string worst_of(const accuracy& a)
{
    if (a.refused > 0)
        return fmt::format("it refuses {} of {} samples as out_of_range (a divisor below "
                           "detail::smallest_divisor or infinite, an argument outside its function's domain, such "
                           "as a square root's below 0 by rounding, or a result not finite; first in the regime "
                           "'{}')",
                           a.refused, a.samples, a.first_refused_regime);
    return fmt::format("{:.3g} ulps at worst ({})", a.max_ulps, a.worst_regime);
}

} // namespace

std::vector<std::string> missed_bounds(const std::vector<kernel_plan>& plans)
{
    std::vector<std::string> missed;
    for (const kernel_plan& plan : plans) {
        const engine::kernel& k = *plan.kernel;
        const auto all = components(k);
        // The accurate form, then the fast one (the accurate one again, where it is the
        // fast one too, against the fast bounds).
        for (const bool fast : {false, true}) {
            for (std::size_t i = 0; i < plan.components.size(); ++i) {
                const engine::kernel_output& o = k.outputs[all[i].first];
                const component_plan& cp = plan.components[i];
                const emitted_accuracy& e = (fast ? plan.fast_emitted : plan.emitted)[i];
                const std::array<double, 3>& bound = fast ? o.fast_bound_ulps : o.bound_ulps;
                // One line an output, naming the type where it is furthest past its bound.
                const auto& types = engine::kernel_output::types;
                const accuracy* measured[] = {&e.in_float, &e.in_double, &e.in_long_double};
                std::size_t worst = 3;
                for (std::size_t t = 0; t < 3; ++t)
                    if (measured[t]->max_ulps > bound[t] &&
                        (worst == 3 || measured[t]->max_ulps / bound[t] > measured[worst]->max_ulps / bound[worst]))
                        worst = t;
                if (worst == 3)
                    continue;
                // A refused sample is no error a bound admits: the form must stay in range.
                const std::string refusing =
                    "; a bound admits no refused sample: give a form that stays in range where they were drawn "
                    "(forms = [...]; a difference that cancels under a square root, 1 - s^2, written (1 - s)*(1 + s))";
                if (measured[worst]->refused > 0)
                    missed.push_back(fmt::format("{}: error: kernel '{}': output '{}' misses its {}bound in {}: {}{}",
                                                 to_string(k.where), k.name, cp.name, fast ? "fast " : "",
                                                 types[worst], worst_of(*measured[worst]), refusing));
                else if (fast)
                    missed.push_back(fmt::format(
                        "{}: error: kernel '{}': output '{}' misses its fast bound of {:g} ulps in {}: {}, in the "
                        "fast form's candidate ({}, {}); give a cheaper form that is accurate "
                        "enough (forms = [...]) or raise the fast bound with [[kernel.bound]] output = \"{}\", "
                        "form = \"fast\", type, ulps, because",
                        to_string(k.where), k.name, cp.name, bound[worst], types[worst], worst_of(*measured[worst]),
                        cp.candidates[cp.fastest].label,
                        cp.candidates[cp.fastest].double_accuracy.max_ulps <= bound[1]
                            ? "the cheapest within the bound in double"
                            : "the accurate form's: none is within the bound in double",
                        o.member));
                else
                    missed.push_back(fmt::format(
                        "{}: error: kernel '{}': output '{}' misses its bound of {:g} ulps in {}: {}, with the best "
                        "of {} candidate forms ({}); give a more accurate form (forms = [...]) "
                        "or, if this is the best it can do, raise the bound with [[kernel.bound]] output = \"{}\", "
                        "type, ulps, because",
                        to_string(k.where), k.name, cp.name, bound[worst], types[worst], worst_of(*measured[worst]),
                        cp.candidates.size(), cp.candidates[cp.chosen].label, o.member));
            }
        }
    }
    return missed;
}

} // namespace impact::verify
