#include "verify/measure.h"

#include "compile/functions.h"
#include "verify/accuracy.h"
#include "verify/cancellation.h"

#include <fmt/format.h>

#include <cmath>
#include <optional>
#include <stdexcept>

namespace impact::verify {
namespace {

constexpr int reference_digits = 60;

// std::`function`(a, b) to the reference's digits (compile/functions.h).
GiNaC::numeric exact_call(const std::string& function, const GiNaC::numeric& a, const GiNaC::numeric& b)
{
    const auto real = [](const GiNaC::numeric& x) { return cln::the<cln::cl_R>(x.to_cl_N()); };
    const std::optional<cln::cl_R> v = compile::exact_value(function, real(a), real(b), reference_digits);
    if (!v)
        throw std::invalid_argument(fmt::format("std::{}({}{}) has no finite real value, at inputs drawn from the "
                                                "inputs' domains; give the inputs domains where it has one",
                                                function, a.to_double(), function == "atan2" || function == "pow"
                                                                             ? fmt::format(", {}", b.to_double())
                                                                             : std::string()));
    return GiNaC::numeric(cln::cl_N(*v));
}

// The program run in CLN, in the precision of its inputs (60 digits in compute_reference).
std::vector<GiNaC::numeric> run_exact(const compile::program& p, const std::vector<GiNaC::numeric>& inputs)
{
    std::vector<GiNaC::numeric> v(p.code.size());
    for (std::size_t i = 0; i < p.code.size(); ++i) {
        const compile::instruction& in = p.code[i];
        switch (in.op) {
        case compile::opcode::input: v[i] = inputs[in.input]; break;
        case compile::opcode::constant:
            v[i] = in.pi ? GiNaC::ex_to<GiNaC::numeric>(GiNaC::Pi.evalf()) : in.value;
            break;
        case compile::opcode::add: v[i] = v[in.a] + v[in.b]; break;
        case compile::opcode::sub: v[i] = v[in.a] - v[in.b]; break;
        case compile::opcode::mul: v[i] = v[in.a] * v[in.b]; break;
        case compile::opcode::div: v[i] = v[in.a] / v[in.b]; break;
        case compile::opcode::neg: v[i] = -v[in.a]; break;
        case compile::opcode::fma: v[i] = v[in.a] * v[in.b] + v[in.c]; break;
        case compile::opcode::sqrt: v[i] = GiNaC::sqrt(v[in.a]); break;
        // The case whose condition holds at the point (to 60 digits; where it is 0, the
        // cases agree, and either gives the value).
        case compile::opcode::select: v[i] = v[in.a].is_positive() ? v[in.b] : v[in.c]; break;
        case compile::opcode::call:
            if (in.function == "abs") {
                v[i] = GiNaC::abs(v[in.a]);
                break;
            }
            v[i] = exact_call(in.function, v[in.a], in.b >= 0 ? v[in.b] : GiNaC::numeric(0));
            break;
        }
    }
    std::vector<GiNaC::numeric> out;
    for (int o : p.outputs)
        out.push_back(v[o]);
    return out;
}

// The exact value of a double rounded to a type with the given mantissa.
GiNaC::numeric rounded(double x, int mantissa_bits)
{
    if (mantissa_bits <= 24)
        return exact(static_cast<float>(x));
    return exact(x);  // double and long double hold a double exactly
}

// One ulp of `Real` at `scale`: 2^(floor(log2 scale) + 1 - digits).
template <class Real>
long double unit_in_last_place(double scale)
{
    return std::ldexp(1.0L, std::ilogb(scale) + 1 - std::numeric_limits<Real>::digits);
}

} // namespace

std::vector<std::pair<std::size_t, std::size_t>> components(const engine::kernel& k)
{
    std::vector<std::pair<std::size_t, std::size_t>> all;
    for (std::size_t o = 0; o < k.outputs.size(); ++o)
        for (std::size_t c = 0; c < k.outputs[o].values.size(); ++c)
            all.emplace_back(o, c);
    return all;
}

reference compute_reference(const engine::kernel& k, const std::vector<sample>& samples, int mantissa_bits)
{
    // One program for every exact output and every error-scale factor. Any of the
    // proven-equal forms gives the exact value when evaluated to 60 digits; the shortest
    // is the cheapest to evaluate.
    const std::vector<GiNaC::ex> inputs = k.input_symbols();
    const engine::term_order order(inputs);
    std::vector<GiNaC::ex> expressions;
    const auto all = components(k);
    for (const auto& [o, c] : all) {
        GiNaC::ex shortest = k.outputs[o].values[c];
        std::size_t length = compile::compile_program({shortest}, inputs, order, {}, k.lets).code.size();
        for (const engine::form& f : k.outputs[o].candidates[c]) {
            const std::size_t n = compile::compile_program({f.value}, inputs, order, {}, k.lets).code.size();
            if (n < length) {
                shortest = f.value;
                length = n;
            }
        }
        // Without the cancellations the functions' identities remove (1 − cos θ as 2 sin²(θ/2)):
        // 60 digits are then 60 digits of the value at every sample, a small angle's too.
        expressions.push_back(without_cancellation(shortest));
    }
    for (const engine::kernel_output& o : k.outputs)
        expressions.push_back(o.scale_factor);
    const std::size_t first_speed = expressions.size();
    for (const GiNaC::ex& v : k.speeds)
        expressions.push_back(v);
    const compile::program exact_program = compile::compile_program(expressions, inputs, order, {}, k.lets);

    std::vector<std::size_t> velocity_slots;
    for (std::size_t i = 0; i < inputs.size(); ++i)
        for (const GiNaC::ex& v : k.velocities)
            if (v.is_equal(inputs[i]))
                velocity_slots.push_back(i);

    const auto saved = GiNaC::Digits;
    GiNaC::Digits = reference_digits;
    reference ref;
    ref.mantissa_bits = mantissa_bits;
    for (const sample& s : samples) {
        std::vector<GiNaC::numeric> x;
        for (double value : s.inputs)
            // 60-digit floating point, not exact rationals, whose digits grow with every
            // product (their greatest common divisors took most of the time).
            x.push_back(GiNaC::ex_to<GiNaC::numeric>(GiNaC::ex(rounded(value, mantissa_bits)).evalf()));
        const std::vector<GiNaC::numeric> values = run_exact(exact_program, x);
        // The collision's velocity scale: the largest velocity among inputs and exact outputs.
        GiNaC::numeric speed = 0;
        for (std::size_t slot : velocity_slots)
            speed = std::max(speed, GiNaC::abs(x[slot]));
        for (std::size_t i = first_speed; i < values.size(); ++i)
            speed = std::max(speed, GiNaC::abs(values[i]));
        for (std::size_t i = 0; i < all.size(); ++i) {
            const engine::kernel_output& o = k.outputs[all[i].first];
            if (o.error == engine::kernel_output::scale::velocity && o.scale_factor.is_equal(1))
                speed = std::max(speed, GiNaC::abs(values[i]));
        }
        std::vector<GiNaC::numeric> scales;
        for (std::size_t i = 0; i < all.size(); ++i) {
            const engine::kernel_output& o = k.outputs[all[i].first];
            if (o.error == engine::kernel_output::scale::relative)
                scales.push_back(GiNaC::abs(values[i]));
            else
                scales.push_back(speed * GiNaC::abs(values[all.size() + all[i].first]));
        }
        std::vector<double_double> exact_values;
        std::vector<double> scale_values;
        for (std::size_t i = 0; i < all.size(); ++i) {
            const GiNaC::numeric& v = values[i];
            const double hi = v.to_double();
            exact_values.push_back({hi, std::isfinite(hi) ? (v - exact(hi)).to_double() : 0.0});
            scale_values.push_back(scales[i].to_double());
        }
        ref.outputs.push_back(std::move(exact_values));
        ref.scales.push_back(std::move(scale_values));
    }
    GiNaC::Digits = saved;
    return ref;
}

reference prefix(const reference& ref, std::size_t count)
{
    reference r;
    r.mantissa_bits = ref.mantissa_bits;
    r.outputs.assign(ref.outputs.begin(), ref.outputs.begin() + static_cast<long>(count));
    r.scales.assign(ref.scales.begin(), ref.scales.begin() + static_cast<long>(count));
    return r;
}

template <class Real>
std::vector<accuracy> measure(const compile::program& p, const std::vector<std::size_t>& which,
                              const std::vector<sample>& samples, const reference& ref, bool tests_divisors)
{
    std::vector<accuracy> result(which.size());
    std::vector<double> total(which.size(), 0);
    const std::vector<int> divisors = tests_divisors ? compile::divisors(p) : std::vector<int>{};
    for (std::size_t n = 0; n < samples.size(); ++n) {
        std::vector<Real> x;
        for (double value : samples[n].inputs)
            x.push_back(static_cast<Real>(value));
        const std::vector<Real> values = compile::run_values<Real>(p, x);
        // A collision the kernel would refuse as out of range (its velocities returned
        // unchanged) is no result at all: an infinite error, counted apart.
        const bool refused = compile::divisor_out_of_range(divisors, values);
        std::vector<Real> y;
        for (int o : p.outputs)
            y.push_back(values[static_cast<std::size_t>(o)]);
        for (std::size_t i = 0; i < which.size(); ++i) {
            const double_double& want = ref.outputs[n][which[i]];
            const double scale = ref.scales[n][which[i]];
            // |computed - exact|, the difference exact in long double while they are close.
            const long double gap =
                std::fabs((static_cast<long double>(y[i]) - want.hi) - static_cast<long double>(want.lo));
            double e = 0;
            if (refused)
                e = std::numeric_limits<double>::infinity();
            else if (!std::isfinite(static_cast<double>(y[i])))
                e = std::numeric_limits<double>::infinity();
            else if (gap == 0)
                e = 0;
            else if (scale == 0)
                e = std::numeric_limits<double>::infinity();
            else
                e = static_cast<double>(gap / unit_in_last_place<Real>(scale));
            total[i] += e;
            if (refused && result[i].refused++ == 0)
                result[i].first_refused_regime = samples[n].regime;
            if (e > result[i].max_ulps || result[i].samples == 0) {
                result[i].max_ulps = e;
                result[i].worst_regime = samples[n].regime;
            }
            ++result[i].samples;
        }
    }
    for (std::size_t i = 0; i < which.size(); ++i)
        result[i].mean_ulps = result[i].samples ? total[i] / static_cast<double>(result[i].samples) : 0;
    return result;
}

template std::vector<accuracy> measure<float>(const compile::program&, const std::vector<std::size_t>&,
                                              const std::vector<sample>&, const reference&, bool);
template std::vector<accuracy> measure<double>(const compile::program&, const std::vector<std::size_t>&,
                                               const std::vector<sample>&, const reference&, bool);
template std::vector<accuracy> measure<long double>(const compile::program&, const std::vector<std::size_t>&,
                                                    const std::vector<sample>&, const reference&, bool);

} // namespace impact::verify
