// The domain of a symbol: where its values lie.
//
// Domains decide which GiNaC symbol class stands for a quantity (a positive mass is a
// `possymbol`, so that sqrt(M^2) = M), where numeric checks and verification sample,
// and which signs the engine may assume when it proves an inequality.
#pragma once

#include "spec/error.h"

#include <ginac/ginac.h>

#include <cstdint>
#include <string>

namespace impact::engine {

struct domain {
    enum class kind { real, positive, nonnegative, interval };
    kind what = kind::real;
    /// Interval bounds as numbers: a bound of π (`Pi/2`), which no double is, is rounded
    /// towards the inside of the interval, so that a value drawn between them is in the
    /// domain. exact_lower() and exact_upper() are the bounds themselves.
    double lower = 0;
    double upper = 0;
    bool lower_open = false;   ///< `(0, 1]` excludes 0
    bool upper_open = false;
    std::string lower_text{};  ///< the bounds as the file writes them (2/3, not 0.666...; Pi/2)
    std::string upper_text{};
    /// `[0, +inf]` or `(0, +inf]`: +infinity is a value too (a coefficient of friction that
    /// never lets a contact slide). The engine reasons on the finite values; a kernel accepts
    /// +infinity for it.
    bool infinity_included = false;

    /// True when every value of the domain is > 0 (or ≥ 0).
    bool is_positive() const;
    bool is_nonnegative() const;

    /// An interval's bounds exactly: the rational (2/3) or rational multiple of π (Pi/2,
    /// -3*Pi/4) the file writes, or the number `lower` (`upper`) when no text is given.
    GiNaC::ex exact_lower() const;
    GiNaC::ex exact_upper() const;

    /// True when `x` lies in the domain, or on its closure (an open end included:
    /// a special value or a limit may sit where the quantity itself never is).
    bool contains(double x) const;
    bool closure_contains(double x) const;
    /// The same of an exact real constant (3/7, Pi/4), compared with the exact bounds.
    bool contains(const GiNaC::ex& constant) const;
    bool closure_contains(const GiNaC::ex& constant) const;
    /// True when the domain reaches +infinity (a limit s -> infinity makes sense).
    bool unbounded_above() const { return what != kind::interval; }
    /// True when every value of this domain lies in `outer` (an assumption narrows a
    /// declared domain and must stay inside it).
    bool within(const domain& outer) const;

    /// The domain as written in a derivation file, e.g. `[0, 1]`.
    std::string to_string() const;
    /// The domain in LaTeX, e.g. `\in [0, 1]` or `> 0`.
    std::string to_latex() const;
};

/// A deterministic stream of uniform numbers in [0, 1) (splitmix64), the same on every
/// platform, so that sampled checks and verification runs are reproducible.
class uniform_stream {
public:
    explicit uniform_stream(std::uint64_t seed) : state_(seed) {}
    double next();

private:
    std::uint64_t state_;
};

/// A value drawn from a domain: intervals uniformly, positive quantities log-uniformly
/// over [1/20, 20], real ones uniformly over [-10, 10].
double draw(const domain& range, uniform_stream& stream);

/// Parses `real`, `positive`, `nonnegative`, an interval `[a, b]`, `(a, b]`, … whose
/// bounds are numbers (1, -1/2, 0.25) or rational multiples of π (Pi, -Pi/2, 3*Pi/4,
/// 0.5*Pi), or `[0, +inf]` and `(0, +inf]` (infinity included). Throws `impact::error` at
/// `where` when the text is not understood.
domain parse_domain(const std::string& text, const source_location& where);

/// The sign of a real constant (a rational, a rational multiple of π, their sums), exactly:
/// -1, 0 or 1.
int sign_of_constant(const GiNaC::ex& constant);

/// A bound as LaTeX: its text with π as \pi (`Pi/2` → `\pi/2`).
std::string latex_of_bound(const std::string& text);

} // namespace impact::engine
