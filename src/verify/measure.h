// The accuracy of a compiled kernel, measured against CLN.
//
// For a floating-point type, each sample's inputs are first rounded to that type; the
// exact outputs at those inputs are computed from the derived results with CLN to 60
// significant digits (about 199 bits, in which the inputs and products of two or three are exact:
// far more than the 64 bits of a long double's ulp, even after a cancellation of 30 digits);
// the compiled program is run in the type; the difference is counted in ulps of the
// output's scale: its own exact value (relative), or the largest velocity of the
// collision, among the inputs and the exact outputs, times a factor (for J, the reduced
// mass).
#pragma once

#include "compile/program.h"
#include "engine/derivation/derivation.h"
#include "verify/sampling.h"

#include <ginac/ginac.h>

#include <limits>
#include <string>
#include <vector>

namespace impact::verify {

/// A value to about 106 bits: hi + lo, each a double (enough to measure errors in
/// float, double and long double without going back to CLN for every comparison).
struct double_double {
    double hi = 0;
    double lo = 0;
};

/// The exact outputs of a kernel at the samples' inputs, rounded to one type.
struct reference {
    std::vector<std::vector<double_double>> outputs;   ///< per sample: each output component
    std::vector<std::vector<double>> scales;           ///< per sample: the error scale of each component
    int mantissa_bits = 53;
};

/// One entry per output component of `k`, in order: (output index, component index).
std::vector<std::pair<std::size_t, std::size_t>> components(const engine::kernel& k);

/// The first `count` samples' part of a reference.
reference prefix(const reference& ref, std::size_t count);

/// The reference for samples rounded to a type with `mantissa_bits` (24, 53, 64).
reference compute_reference(const engine::kernel& k, const std::vector<sample>& samples, int mantissa_bits);

struct accuracy {
    std::size_t samples = 0;
    double mean_ulps = 0;
    double max_ulps = 0;
    std::string worst_regime;
    std::size_t refused = 0;  ///< samples the kernel refuses as out of range (a divisor out of the type's range)
    std::string first_refused_regime;  ///< the regime of the first of them
};

/// Runs `p` (whose outputs are the kernel's components listed in `which`) in `Real` on
/// every sample and measures each of its outputs against `ref`. Where `tests_divisors`
/// (the kernel has guards, and so a status), a sample whose divisors the emitted kernel
/// would find out of range is refused: an infinite error, counted in `refused`.
template <class Real>
std::vector<accuracy> measure(const compile::program& p, const std::vector<std::size_t>& which,
                              const std::vector<sample>& samples, const reference& ref, bool tests_divisors);

} // namespace impact::verify
