#include "verify/sampling.h"

#include "compile/program.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <stdexcept>

namespace impact::verify {
namespace {

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

// What a regime does to an ordinary draw.
enum class shape {
    ordinary,
    spread,          // positive inputs over 12 decades, not 4
    near_lower,      // one interval input within 10^-12 .. 10^-1 of its lower end
    near_upper,      // ... of its upper end
    grazing,         // the approach speed a tiny fraction of the relative velocity
    head_on,         // the relative velocity nearly along the direction of approach
    one_tiny,        // one positive input 10^-12 .. 10^-4 of its draw
    equal_velocities,
    declared,        // a regime of the kernel's file
};

struct regime {
    regime(std::string l, shape w = shape::ordinary, std::size_t s = 0) : label(std::move(l)), what(w), slot(s) {}
    std::string label;
    shape what = shape::ordinary;
    std::size_t slot = 0;                            // near_lower, near_upper: the input
    const engine::sampling_regime* file = nullptr;   // declared
    shape start = shape::ordinary;                   // declared: drawn first as in this
    std::shared_ptr<compile::program> values;        // declared: offsets, slopes, denominator
};

// How a kernel's samples are drawn: its inputs' roles and its regimes, in the order they
// take turns.
class sampler {
public:
    sampler(const engine::kernel& k, const engine::term_order& order) : k_(k), l_(layout_of(k))
    {
        find_roles(order);
        regimes_.emplace_back("ordinary");
        std::vector<std::string> positive_names;   // "M, m, R_M, R_m, mu"
        for (std::size_t i : positive_slots_)
            positive_names.push_back(parameter_name(i));
        const std::string positive = fmt::format("{}", fmt::join(positive_names, ", "));
        if (!positive_slots_.empty())
            regimes_.emplace_back(positive + " over 12 decades", shape::spread);
        // Each interval input near each end: one input at a time where there are several
        // (the restitution near 1 with the tangential restitution anywhere).
        for (std::size_t i = 0; i < l_.quantities.size(); ++i) {
            const engine::domain& d = l_.quantities[i]->range;
            if (d.what != engine::domain::kind::interval)
                continue;
            const std::string name = parameter_name(i);
            regimes_.emplace_back(fmt::format("{} near {}", name, d.lower_text), shape::near_lower, i);
            regimes_.emplace_back(fmt::format("{} near {}", name, d.upper_text), shape::near_upper, i);
        }
        if (has_geometry()) {
            regimes_.emplace_back("nearly grazing", shape::grazing);
            regimes_.emplace_back("nearly head-on", shape::head_on);
        } else if (!two_velocities_ && positive_slots_.size() >= 2) {
            // No bodies, positive inputs (a velocity's parts along and across the line of
            // centres): one tiny next to the others.
            regimes_.emplace_back("one of " + positive + " 1e-12 to 1e-4 of its draw", shape::one_tiny);
        }
        if (two_velocities_)
            regimes_.emplace_back("nearly equal velocities", shape::equal_velocities);
        for (const engine::sampling_regime& r : k.regimes) {
            regime x{r.name, shape::declared};
            x.file = &r;
            if (r.start == "nearly head-on" || r.start == "nearly grazing") {
                if (!has_geometry())
                    throw error(r.where, fmt::format("regime '{}' starts {}, but kernel '{}' has no line of "
                                                     "approach (two bodies' positions, or a guard on the "
                                                     "velocity's approach) to draw it along",
                                                     r.name, r.start, k.name));
                x.start = r.start == "nearly head-on" ? shape::head_on : shape::grazing;
            }
            std::vector<GiNaC::ex> values = r.offsets;
            values.insert(values.end(), r.slopes.begin(), r.slopes.end());
            values.push_back(r.denominator);
            x.values = std::make_shared<compile::program>(compile::compile_program(values, k.input_symbols(), order));
            for (const GiNaC::ex& input : r.inputs)
                inputs_of_[&r].push_back(slot_of(input));
            regimes_.push_back(std::move(x));
        }
    }

    std::vector<std::string> names() const
    {
        std::vector<std::string> out;
        for (const regime& r : regimes_)
            out.push_back(r.label);
        return out;
    }

    std::vector<sample> draw(std::size_t count, std::uint64_t seed, const admission& admitted)
    {
        engine::uniform_stream s(seed);
        std::vector<sample> samples;
        constexpr int most_draws = 64;
        for (std::size_t n = 0, draws = 0; n < count; ++draws) {
            const regime& r = regimes_[n % regimes_.size()];
            sample x;
            x.regime = r.label;
            x.inputs = ordinary(s, r);
            bool drawn = true;
            if (r.what == shape::declared) {
                reshape(s, x.inputs, r.start);
                approaching(x.inputs);
                drawn = set_declared(s, x.inputs, r);
            } else {
                reshape(s, x.inputs, r.what);
                approaching(x.inputs);
            }
            if (!drawn || (admitted && !admitted(x.inputs))) {
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

private:
    // Velocities (or scalars), positions, positive inputs; whether the kernel has two bodies
    // (two velocities and two positions of one dimension), or one body whose approach a
    // guard tests (a sphere and a wall: `v . N < 0`).
    void find_roles(const engine::term_order& order)
    {
        for (std::size_t p = 0; p < k_.parameters.size(); ++p) {
            const engine::quantity& first = k_.parameters[p].components.front();
            if (is_velocity(k_, first))
                velocity_parameters_.push_back(p);
            else if (first.range.what == engine::domain::kind::real)
                position_parameters_.push_back(p);
            // Positive (or non-negative) inputs of no bounded interval: masses, radii, μ.
            for (std::size_t slot : l_.slots[p]) {
                const engine::domain::kind what = l_.quantities[slot]->range.what;
                if (what == engine::domain::kind::positive || what == engine::domain::kind::nonnegative)
                    positive_slots_.push_back(slot);
            }
        }
        const auto same_size = [&](const std::vector<std::size_t>& parameters) {
            return parameters.size() >= 2 && l_.slots[parameters[0]].size() == l_.slots[parameters[1]].size();
        };
        two_velocities_ = same_size(velocity_parameters_);
        two_bodies_ = two_velocities_ && same_size(position_parameters_) &&
                      l_.slots[velocity_parameters_[0]].size() == l_.slots[position_parameters_[0]].size();
        if (two_bodies_ || velocity_parameters_.empty())
            return;
        // One body: the guard on its velocity's approach, a linear function of it.
        const auto& v = l_.slots[velocity_parameters_[0]];
        const std::vector<GiNaC::ex> inputs = k_.input_symbols();
        for (const engine::kernel_guard& g : k_.guards) {
            if (!g.condition || v.size() < 2)
                continue;
            std::vector<GiNaC::ex> gradient;
            bool linear = true;
            for (std::size_t slot : v) {
                const GiNaC::ex d = g.condition->diff(GiNaC::ex_to<GiNaC::symbol>(inputs[slot]));
                linear = linear && !d.has(inputs[slot]);
                for (std::size_t other : v)
                    linear = linear && !d.has(inputs[other]);
                gradient.push_back(d);
            }
            if (!linear || std::all_of(gradient.begin(), gradient.end(), [](const GiNaC::ex& d) { return d.is_zero(); }))
                continue;
            std::vector<GiNaC::ex> values{*g.condition};
            values.insert(values.end(), gradient.begin(), gradient.end());
            approach_ = std::make_shared<compile::program>(compile::compile_program(values, inputs, order));
            return;
        }
    }

    bool has_geometry() const { return (two_bodies_ && l_.slots[velocity_parameters_[0]].size() >= 2) || approach_; }

    std::string parameter_name(std::size_t slot) const
    {
        for (std::size_t p = 0; p < l_.slots.size(); ++p)
            for (std::size_t c = 0; c < l_.slots[p].size(); ++c)
                if (l_.slots[p][c] == slot)
                    return k_.parameters[p].is_array ? fmt::format("{}[{}]", k_.parameters[p].name, c)
                                                     : k_.parameters[p].name;
        return l_.quantities[slot]->name;
    }

    std::size_t slot_of(const GiNaC::ex& symbol) const
    {
        for (std::size_t i = 0; i < l_.quantities.size(); ++i)
            if (l_.quantities[i]->symbol.is_equal(symbol))
                return i;
        throw std::logic_error("a kernel's regime sets no input of it");   // the engine checks it does
    }

    // Every input drawn from its domain, as the regime asks.
    std::vector<double> ordinary(engine::uniform_stream& s, const regime& r) const
    {
        std::vector<double> inputs(l_.quantities.size());
        for (std::size_t i = 0; i < l_.quantities.size(); ++i) {
            const engine::domain& d = l_.quantities[i]->range;
            switch (d.what) {
            case engine::domain::kind::positive:
            case engine::domain::kind::nonnegative:
                inputs[i] = r.what == shape::spread ? decades(s, -6, 6) : decades(s, -2, 2);
                break;
            case engine::domain::kind::interval: {
                // Within 10^-12 of an end in the regimes that ask for it.
                const double width = d.upper - d.lower;
                if (r.what == shape::near_lower && r.slot == i)
                    inputs[i] = d.lower + width * decades(s, -12, -1);
                else if (r.what == shape::near_upper && r.slot == i)
                    inputs[i] = d.upper - width * decades(s, -12, -1);
                else
                    inputs[i] = d.lower + width * s.next();
                break;
            }
            case engine::domain::kind::real: inputs[i] = signed_magnitude(s, -2, 2); break;
            }
        }
        return inputs;
    }

    // The geometric regimes, on an ordinary draw.
    void reshape(engine::uniform_stream& s, std::vector<double>& x, shape what) const
    {
        if (what == shape::one_tiny)
            x[positive_slots_[static_cast<std::size_t>(s.next() * positive_slots_.size())]] *= decades(s, -12, -4);
        if (what == shape::equal_velocities) {
            // The second velocity a hair away from the first.
            const auto& a = l_.slots[velocity_parameters_[0]];
            const auto& b = l_.slots[velocity_parameters_[1]];
            for (std::size_t c = 0; c < a.size() && c < b.size(); ++c)
                x[b[c]] = x[a[c]] * (1 + signed_magnitude(s, -15, -6));
        }
        if (what != shape::grazing && what != shape::head_on)
            return;
        // The relative velocity u (of M to m, or of the body) and the direction a of approach.
        const auto& va = l_.slots[velocity_parameters_[0]];
        const std::size_t dim = va.size();
        std::vector<double> u(dim), a(dim);
        if (two_bodies_) {
            const auto& vb = l_.slots[velocity_parameters_[1]];
            const auto& ca = l_.slots[position_parameters_[0]];
            const auto& cb = l_.slots[position_parameters_[1]];
            for (std::size_t c = 0; c < dim; ++c) {
                u[c] = x[va[c]] - x[vb[c]];
                a[c] = x[ca[c]] - x[cb[c]];
            }
        } else {
            const std::vector<double> g = compile::run<double>(*approach_, x);
            for (std::size_t c = 0; c < dim; ++c) {
                u[c] = x[va[c]];
                a[c] = g[1 + c];
            }
        }
        double ua = 0, aa = 0;
        for (std::size_t c = 0; c < dim; ++c) {
            ua += u[c] * a[c];
            aa += a[c] * a[c];
        }
        const double keep = decades(s, -12, -3);
        for (std::size_t c = 0; c < dim; ++c) {
            const double along = ua / aa * a[c];
            // Nearly grazing: the part along the line of approach a tiny fraction of it;
            // nearly head-on: the part across it.
            x[va[c]] -= what == shape::grazing ? (1 - keep) * along : (1 - keep) * (u[c] - along);
        }
    }

    // Every sample of two bodies is a collision that happens: M approaches m (a pair drawn
    // separating has its velocities reversed). A body's approach is left to the guards.
    void approaching(std::vector<double>& x) const
    {
        if (!two_bodies_)
            return;
        const auto& va = l_.slots[velocity_parameters_[0]];
        const auto& vb = l_.slots[velocity_parameters_[1]];
        const auto& ca = l_.slots[position_parameters_[0]];
        const auto& cb = l_.slots[position_parameters_[1]];
        double dot = 0;
        for (std::size_t c = 0; c < va.size(); ++c)
            dot += (x[va[c]] - x[vb[c]]) * (x[ca[c]] - x[cb[c]]);
        if (dot > 0)
            for (std::size_t c = 0; c < va.size(); ++c) {
                x[va[c]] = -x[va[c]];
                x[vb[c]] = -x[vb[c]];
            }
    }

    // A regime of the kernel's file: its input given the value that makes its quantity
    // offset + slope*input take the value asked. False when that value is outside the
    // input's domain (the sample is drawn again).
    bool set_declared(engine::uniform_stream& s, std::vector<double>& x, const regime& r) const
    {
        const engine::sampling_regime& f = *r.file;
        if (f.slopes.size() > 1)
            return set_vector(s, x, r);
        const std::size_t slot = inputs_of_.at(&f).front();
        const std::vector<double> v = compile::run<double>(*r.values, x);
        double value = 0;
        if (f.what == engine::sampling_regime::kind::ratio) {
            // quantity = ±10^u denominator
            const double ratio = s.next() < 0.5 ? -1 : 1;
            value = (ratio * decades(s, std::log10(f.from), std::log10(f.to)) * v[2] - v[0]) / v[1];
        } else {
            // quantity = 0, then the input moved by a relative 10^-4 .. 1 of `within`
            const double to = std::log10(f.to);
            value = -v[0] / v[1] * (1 + signed_magnitude(s, to - 4, to));
        }
        const engine::domain& d = l_.quantities[slot]->range;
        if (!std::isfinite(value) || (d.what == engine::domain::kind::positive && !(value > 0)) ||
            (d.what == engine::domain::kind::nonnegative && !(value >= 0)))
            return false;
        x[slot] = value;
        return true;
    }

    // A quantity of several components, or an input of several (a spin vector): the inputs
    // set so that the quantity has the length ±10^u |denominator|, along a direction drawn
    // among those the inputs can give it, changed as little as they can be from their
    // draw (the part that does not change the quantity, such as a spin along the normal,
    // kept). The slopes' columns are made orthonormal (Gram-Schmidt, the inputs'
    // combinations carried along, a column that adds no direction giving one that changes
    // nothing); the inputs first cancel the quantity's offset, then add the length asked
    // along the direction.
    bool set_vector(engine::uniform_stream& s, std::vector<double>& x, const regime& r) const
    {
        const engine::sampling_regime& f = *r.file;
        const std::vector<std::size_t>& slots = inputs_of_.at(&f);
        const std::size_t m = f.offsets.size(), n = slots.size();
        const std::vector<double> v = compile::run<double>(*r.values, x);
        const auto dot = [](const std::vector<double>& a, const std::vector<double>& b) {
            double sum = 0;
            for (std::size_t i = 0; i < a.size(); ++i)
                sum += a[i] * b[i];
            return sum;
        };
        const auto take = [](std::vector<double>& a, double c, const std::vector<double>& b) {   // a -= c b
            for (std::size_t i = 0; i < a.size(); ++i)
                a[i] -= c * b[i];
        };
        std::vector<std::vector<double>> basis, inputs;   // basis[k] = slopes times inputs[k]
        std::vector<std::vector<double>> unseen;          // orthonormal: slopes times each = 0
        double largest = 0;
        for (std::size_t j = 0; j < n; ++j) {
            std::vector<double> column(m);
            for (std::size_t i = 0; i < m; ++i)
                column[i] = v[m + i * n + j];
            largest = std::max(largest, std::sqrt(dot(column, column)));
        }
        for (std::size_t j = 0; j < n; ++j) {
            std::vector<double> w(m), z(n, 0.0);
            for (std::size_t i = 0; i < m; ++i)
                w[i] = v[m + i * n + j];
            z[j] = 1;
            for (int pass = 0; pass < 2; ++pass)   // twice: orthogonal to the rounding too
                for (std::size_t k = 0; k < basis.size(); ++k) {
                    const double c = dot(basis[k], w);
                    take(w, c, basis[k]);
                    take(z, c, inputs[k]);
                }
            const double size = std::sqrt(dot(w, w));
            if (!(size > 1e-9 * largest)) {
                for (int pass = 0; pass < 2; ++pass)
                    for (const std::vector<double>& u : unseen)
                        take(z, dot(u, z), u);
                const double length = std::sqrt(dot(z, z));
                if (length > 0) {
                    for (double& e : z)
                        e /= length;
                    unseen.push_back(std::move(z));
                }
                continue;
            }
            for (double& e : w)
                e /= size;
            for (double& e : z)
                e /= size;
            basis.push_back(std::move(w));
            inputs.push_back(std::move(z));
        }
        if (basis.empty())
            return false;
        const std::vector<double> offset(v.begin(), v.begin() + static_cast<long>(m));
        std::vector<double> left = offset;   // what the inputs cannot cancel
        std::vector<double> set(n, 0.0);
        for (std::size_t k = 0; k < basis.size(); ++k) {
            const double c = dot(basis[k], offset);
            take(left, c, basis[k]);
            take(set, c, inputs[k]);
        }
        const double length = decades(s, std::log10(f.from), std::log10(f.to)) * std::abs(v[m + m * n]);
        if (std::sqrt(dot(left, left)) > 1e-3 * length)
            return false;   // a part of the quantity the inputs cannot change is larger than asked
        std::vector<double> direction(basis.size());
        double norm = 0;
        for (int tries = 0; !(norm > 0.1); ++tries) {   // uniform over the directions the inputs reach
            if (tries == 64)
                return false;
            for (double& e : direction)
                e = 2 * s.next() - 1;
            norm = std::sqrt(dot(direction, direction));
            norm = norm <= 1 ? norm : 0;
        }
        for (std::size_t k = 0; k < basis.size(); ++k)
            for (std::size_t i = 0; i < n; ++i)
                set[i] += length * direction[k] / norm * inputs[k][i];
        // The drawn inputs' part that changes nothing, in place of the one found.
        for (const std::vector<double>& u : unseen) {
            double drawn = 0, found = 0;
            for (std::size_t i = 0; i < n; ++i) {
                drawn += u[i] * x[slots[i]];
                found += u[i] * set[i];
            }
            for (std::size_t i = 0; i < n; ++i)
                set[i] += (drawn - found) * u[i];
        }
        // The quantity as set: the length asked, to 1e-3 (a column that added no direction
        // still moves it a hair), and the inputs in their domains.
        std::vector<double> quantity = offset;
        for (std::size_t i = 0; i < m; ++i)
            for (std::size_t j = 0; j < n; ++j)
                quantity[i] += v[m + i * n + j] * set[j];
        if (!(std::abs(std::sqrt(dot(quantity, quantity)) / length - 1) <= 1e-3))
            return false;
        for (std::size_t i = 0; i < n; ++i) {
            const engine::domain& d = l_.quantities[slots[i]]->range;
            if (!std::isfinite(set[i]) || (d.what == engine::domain::kind::positive && !(set[i] > 0)) ||
                (d.what == engine::domain::kind::nonnegative && !(set[i] >= 0)))
                return false;
        }
        for (std::size_t i = 0; i < n; ++i)
            x[slots[i]] = set[i];
        return true;
    }

    const engine::kernel& k_;
    const layout l_;
    std::vector<std::size_t> velocity_parameters_, position_parameters_, positive_slots_;
    bool two_velocities_ = false;
    bool two_bodies_ = false;
    std::shared_ptr<compile::program> approach_;
    std::vector<regime> regimes_;
    std::map<const engine::sampling_regime*, std::vector<std::size_t>> inputs_of_;
};

} // namespace

std::vector<sample> draw_samples(const engine::kernel& k, std::size_t count, std::uint64_t seed,
                                 const engine::term_order& order, const admission& admitted)
{
    return sampler(k, order).draw(count, seed, admitted);
}

std::vector<std::string> regime_names(const engine::kernel& k, const engine::term_order& order)
{
    return sampler(k, order).names();
}

} // namespace impact::verify
