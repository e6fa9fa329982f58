// Exact ranges of angles and the signs of the functions of them (internal to engine/prove):
// what the sign prover knows of sin, cos and tan on the part of their domain where an
// argument lies (theta in [0, Pi]: sin(theta) >= 0), and what the decision of identities
// needs to know of an argument (asin(sin(t)) = t for t in [-Pi/2, Pi/2]).
//
// A range is exact: its ends are GiNaC expressions (0, Pi/2, 1 - Pi/4), compared by the
// sign of their difference, which is a number decided exactly when rational, else by
// evaluation at 40 and at 60 digits, believed only when both agree and it lies far from 0.
#pragma once

#include "engine/prove/sign.h"

#include <ginac/ginac.h>

#include <optional>
#include <string>

namespace impact::engine {

/// The exact value of an end of an interval domain, as the file writes it (`Pi/2`, `2/3`):
/// domain::exact_lower() or exact_upper().
GiNaC::ex exact_end(const domain& d, bool upper);

/// Whether `e` holds no symbol: a number, possibly written with Pi or functions (2 - Pi).
bool without_symbols(const GiNaC::ex& e);

/// The sign (-1, 0 or 1) of an expression without symbols, or none when it cannot be
/// decided (a value too near 0 to tell at 60 digits, or not a real number).
std::optional<int> sign_of_number(const GiNaC::ex& c);

/// The values an expression takes, as an interval with exact ends; an infinite end is
/// marked and its value unused.
struct exact_interval {
    GiNaC::ex low = 0, high = 0;
    bool low_open = false, high_open = false;
    bool low_infinite = false, high_infinite = false;

    bool bounded() const { return !low_infinite && !high_infinite; }
    /// `[0, Pi]`, `(-inf, 1)`.
    std::string to_string(const assumptions& given) const;
};

/// `r` in a reason's typeset form: `[0, \pi/2)` with its ends typeset, or its words when an
/// end is infinite.
finding& interval_said(finding& f, const exact_interval& r, const assumptions& given);

/// The range of `e` under the domains of `given`: numbers and constants, symbols by their
/// domains, sums and constant multiples, and the monotone functions atan, asin, acos,
/// exp, log, sinh and tanh of a known range. None where it is not worked out.
std::optional<exact_interval> range_of(const GiNaC::ex& e, const assumptions& given);

/// Whether every value of `r` lies in [low, high] (each end open or not).
bool within(const exact_interval& r, const GiNaC::ex& low, bool low_open, const GiNaC::ex& high, bool high_open);

/// The signs sin(u + shift*Pi) takes for u in `r` (cos is shift 1/2): one sign between two
/// consecutive multiples of Pi, zero at an end that is one and included; any sign when
/// the range holds a multiple of Pi inside, or is unbounded.
sign_set sine_sign_on(const exact_interval& r, const GiNaC::numeric& shift);

} // namespace impact::engine
