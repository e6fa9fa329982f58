#include "verify/sampling.h"

#include <cmath>

namespace impact::verify {
namespace {

const char* const regimes[] = {"ordinary",        "mass ratio up to 1e12", "eps near 0", "eps near 1",
                               "nearly grazing",  "nearly head-on",        "nearly equal velocities"};

// 10^u for u uniform in [lo, hi].
double decades(engine::uniform_stream& s, double lo, double hi)
{
    return std::pow(10.0, lo + (hi - lo) * s.next());
}

double signed_magnitude(engine::uniform_stream& s, double lo, double hi)
{
    const double x = decades(s, lo, hi);
    return s.next() < 0.5 ? -x : x;
}

// The input slots of the kernel: for each parameter, the indices of its components.
struct layout {
    std::vector<std::vector<std::size_t>> slots;
    std::vector<const engine::quantity*> quantities;
};

layout layout_of(const engine::kernel& k)
{
    layout l;
    for (const engine::kernel_parameter& p : k.parameters) {
        std::vector<std::size_t> slots;
        for (const engine::quantity& q : p.components) {
            slots.push_back(l.quantities.size());
            l.quantities.push_back(&q);
        }
        l.slots.push_back(slots);
    }
    return l;
}

bool is_velocity(const engine::kernel& k, const engine::quantity& q)
{
    for (const GiNaC::ex& v : k.velocities)
        if (v.is_equal(q.symbol))
            return true;
    return false;
}

} // namespace

std::vector<sample> draw_samples(const engine::kernel& k, std::size_t count, std::uint64_t seed,
                                 const admission& admitted)
{
    const layout l = layout_of(k);
    engine::uniform_stream s(seed);
    // Parameters by role: velocity arrays (or scalars) and the other real arrays (positions).
    std::vector<std::size_t> velocity_parameters, position_parameters, positive_slots;
    for (std::size_t p = 0; p < k.parameters.size(); ++p) {
        const engine::quantity& first = k.parameters[p].components.front();
        if (is_velocity(k, first))
            velocity_parameters.push_back(p);
        else if (first.range.what == engine::domain::kind::real)
            position_parameters.push_back(p);
        for (std::size_t slot : l.slots[p])
            if (l.quantities[slot]->range.is_positive())
                positive_slots.push_back(slot);
    }

    // Two bodies, M and m: their first two velocities (and positions) are of one dimension.
    // A wall's kernel has one body: its velocity and its spin, the wall's point and normal.
    const auto same_size = [&](const std::vector<std::size_t>& parameters) {
        return parameters.size() >= 2 && l.slots[parameters[0]].size() == l.slots[parameters[1]].size();
    };
    const bool two_velocities = same_size(velocity_parameters);
    const bool two_bodies = two_velocities && same_size(position_parameters) &&
                            l.slots[velocity_parameters[0]].size() == l.slots[position_parameters[0]].size();

    std::vector<sample> samples;
    constexpr int most_draws = 64;
    for (std::size_t n = 0, draws = 0; n < count; ++draws) {
        const std::size_t regime = n % std::size(regimes);
        sample x;
        x.regime = regimes[regime];
        x.inputs.resize(l.quantities.size());
        for (std::size_t i = 0; i < l.quantities.size(); ++i) {
            const engine::domain& d = l.quantities[i]->range;
            switch (d.what) {
            case engine::domain::kind::positive:
            case engine::domain::kind::nonnegative:
                x.inputs[i] = decades(s, regime == 1 ? -6 : -2, regime == 1 ? 6 : 2);
                break;
            case engine::domain::kind::interval: {
                // ε in [0, 1]: within 10^-12 of an end in the regimes that ask for it.
                const double width = d.upper - d.lower;
                if (regime == 2)
                    x.inputs[i] = d.lower + width * decades(s, -12, -1);
                else if (regime == 3)
                    x.inputs[i] = d.upper - width * decades(s, -12, -1);
                else
                    x.inputs[i] = d.lower + width * s.next();
                break;
            }
            case engine::domain::kind::real: x.inputs[i] = signed_magnitude(s, -2, 2); break;
            }
        }
        // Nearly head-on: one positive input tiny next to another (v_perp << v_par).
        if (regime == 5 && positive_slots.size() >= 2) {
            const std::size_t small = positive_slots[static_cast<std::size_t>(s.next() * positive_slots.size())];
            x.inputs[small] *= decades(s, -12, -4);
        }
        // Nearly equal velocities: the second velocity a hair away from the first.
        if (regime == 6 && two_velocities) {
            const auto& a = l.slots[velocity_parameters[0]];
            const auto& b = l.slots[velocity_parameters[1]];
            for (std::size_t c = 0; c < a.size() && c < b.size(); ++c)
                x.inputs[b[c]] = x.inputs[a[c]] * (1 + signed_magnitude(s, -15, -6));
        }
        if (two_bodies) {
            const auto& va = l.slots[velocity_parameters[0]];
            const auto& vb = l.slots[velocity_parameters[1]];
            const auto& ca = l.slots[position_parameters[0]];
            const auto& cb = l.slots[position_parameters[1]];
            const std::size_t dim = va.size();
            auto closing = [&] {
                double dot = 0;
                for (std::size_t c = 0; c < dim; ++c)
                    dot += (x.inputs[va[c]] - x.inputs[vb[c]]) * (x.inputs[ca[c]] - x.inputs[cb[c]]);
                return dot;
            };
            if (regime == 4) {
                // Nearly grazing: the relative velocity nearly perpendicular to the line of
                // centres (its component along the line a tiny fraction of it).
                double rr = 0, dot = closing();
                for (std::size_t c = 0; c < dim; ++c)
                    rr += (x.inputs[ca[c]] - x.inputs[cb[c]]) * (x.inputs[ca[c]] - x.inputs[cb[c]]);
                const double keep = decades(s, -12, -3);
                for (std::size_t c = 0; c < dim; ++c) {
                    const double r = x.inputs[ca[c]] - x.inputs[cb[c]];
                    x.inputs[va[c]] -= (1 - keep) * dot / rr * r;
                }
            }
            // Every sample is a collision that happens: M approaches m.
            if (closing() > 0)
                for (std::size_t c = 0; c < dim; ++c) {
                    x.inputs[va[c]] = -x.inputs[va[c]];
                    x.inputs[vb[c]] = -x.inputs[vb[c]];
                }
        }
        if (admitted && !admitted(x.inputs)) {
            if (draws + 1 < most_draws)
                continue;
            // Refused 64 times in this regime: no sample here (verification.md counts them).
        } else {
            samples.push_back(std::move(x));
        }
        ++n;
        draws = static_cast<std::size_t>(-1);   // the next sample's draws count from 0
    }
    return samples;
}

} // namespace impact::verify
