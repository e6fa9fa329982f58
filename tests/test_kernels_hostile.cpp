// The generated kernels under hostile input (issue 17): NaN, ±inf, denormals, zero, negative
// and huge masses, huge velocities, coincident and nearly coincident centres, eps a hair
// outside [0, 1]. Whatever the input, a kernel throws nothing (all are noexcept), divides
// nothing by zero, and either resolves the collision (status ok: finite velocities that
// conserve momentum) or says why not and returns the velocities unchanged, bit for bit
// (collide_line: J = 0; energy_loss and scatter_angle: a quiet NaN).
//
// Exact cases first, each with its status and outputs typed here from the physics (a head-on
// elastic hit of equal masses exchanges the velocities, a perfectly inelastic one moves on
// at the centre-of-mass velocity, a light sphere bounces off a heavy one at 2V - v), in
// float, double and long double. Then a seeded sweep: IMPACT_SWEEP_PAIRS pairs (20 000 by
// default) per type and kernel, each input drawn from a mix of ordinary and hostile values,
// checked against a classification of the inputs made here, independently of the kernels:
//
//   1. a mass not positive and finite            -> invalid_mass
//      (but one mass +infinity, the other positive and finite, is a fixed sphere:
//      collide_line and collide take the limit; see check_fixed_pair)
//   2. eps outside [0, 1] (or NaN)               -> invalid_restitution
//   3. a position or velocity not finite         -> non_finite
//   4. |C_M - C_m| = 0 in the type               -> coincident_centres     (2D, 3D)
//   5. (v_M - v_m).(C_M - C_m) >= 0              -> separating             (1D: v_M - v_m <= 0)
//   6. values that leave the type's range        -> out_of_range
//   7. a value of the arithmetic below the normal
//      range, or 0 from factors not 0            -> underflow
//   8. otherwise                                 -> ok
//
// in that order (the kernels document the first that applies). Steps 4 to 7 depend on
// rounding near their boundaries: there the classification admits both statuses (the
// sweep counts how often); elsewhere it admits one. Boundaries, from the kernels'
// documented contract: |r|^2 rounds to 0 in the type below about sqrt(denorm_min) and not
// above; the sign of the dot product is certain when it exceeds 16 ulps of the sum of the
// magnitudes of its terms and the smallest normal number; out_of_range is certain when the
// divisor is below min/epsilon / 4 or above 4 max, or a result above 4 max, and excluded
// when the divisor is within [4 min/epsilon, max/4] and every intermediate of the paper's
// closed form is below max/4. Magnitudes are worked out in long double, the inputs scaled
// by powers of 2 first so that nothing overflows there even for long double inputs.
// Underflow is excluded where every product of the documented forms is bounded away from
// the bottom of the range, and certain where one they must compute is below min/4 (see
// lowest_product and with_underflow).
//
// Every resolved collision must be accurate: in float and double, within 16 ulps of the
// closed form evaluated in long double (of the largest velocity, the impulse of the largest
// velocity and the lighter mass, the energy or epsilon of the larger kinetic energy), and
// every angle within 16 ulps of atan2 in long double. Before status::underflow, a collision
// whose intermediate product underflowed came out ok but imprecise.
#define BOOST_TEST_MODULE test_kernels_hostile
#include <boost/test/unit_test.hpp>

#include "impact/impact.hpp"

#include <algorithm>
#include <array>
#include <cfenv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#if defined(__SSE__) || defined(__x86_64__)
#include <xmmintrin.h>
#define IMPACT_TEST_MXCSR 1
#endif

// ---------------------------------------------------------------------------------
// Under the flags users have (test_kernels_hostile_fast_math, built with -Ofast, and _fp_contract).

namespace {

// What a caller compiled with the test's flags sees, -ffast-math included: not between
// IMPACT_PRECISE_BEGIN and IMPACT_PRECISE_END, so GCC inlines the kernels only if their
// options allow it. A NaN velocity must still be refused, the velocities returned as given.
template <std::size_t N>
impact::collide_result<double, N> collide_from_the_callers_flags(double v)
{
    std::array<double, N> C_M{}, C_m{}, v_M{}, v_m{};
    C_M[0] = 1;
    v_M[0] = -1;
    v_m[N - 1] = v;
    return impact::collide(1.0, 2.0, C_M, C_m, v_M, v_m, 0.5);
}

impact::status collide_batch_from_the_callers_flags(double v)
{
    impact::collide_batch_arrays<double, 2> a(3);
    for (std::size_t i = 0; i < 3; ++i) {
        a.M()[i] = 1;
        a.m()[i] = 2;
        a.C_M(0)[i] = 1;
        a.C_M(1)[i] = a.C_m(0)[i] = a.C_m(1)[i] = a.v_M(1)[i] = a.v_m(0)[i] = 0;
        a.v_M(0)[i] = -1;
        a.v_m(1)[i] = v;
        a.eps()[i] = 0.5;
    }
    impact::collide_batch(a.data());
    return a.status()[1];
}

} // namespace

BOOST_AUTO_TEST_CASE(a_caller_built_with_any_flags_gets_nan_and_infinities_refused)
{
    for (const double v : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
        const auto out2 = collide_from_the_callers_flags<2>(v);
        BOOST_TEST(static_cast<int>(out2.status) == static_cast<int>(impact::status::non_finite));
        BOOST_TEST(std::memcmp(&out2.v_m[1], &v, sizeof v) == 0);
        const auto out3 = collide_from_the_callers_flags<3>(v);
        BOOST_TEST(static_cast<int>(out3.status) == static_cast<int>(impact::status::non_finite));
        BOOST_TEST(std::memcmp(&out3.v_m[2], &v, sizeof v) == 0);
        BOOST_TEST(static_cast<int>(collide_batch_from_the_callers_flags(v)) == static_cast<int>(impact::status::non_finite));
    }
    const auto ok = collide_from_the_callers_flags<2>(0);
    BOOST_TEST(static_cast<int>(ok.status) == static_cast<int>(impact::status::ok));
}

// The test's own checks need what the kernels need: its arithmetic as written, and tests
// for NaN and infinities that no flag folds (std::isnan and std::isfinite are compiled in
// <cmath> with the test's flags, and under -ffinite-math-only may be folded to constants).
IMPACT_PRECISE_BEGIN

namespace {

template <class Real>
bool same_bits(Real a, Real b)
{
    // x87's long double: 10 bytes of value, the rest padding.
    constexpr std::size_t bytes = std::numeric_limits<Real>::digits == 64 ? 10 : sizeof(Real);
    return std::memcmp(&a, &b, bytes) == 0;
}
template <class Real>
bool is_finite(Real x)
{
    return impact::detail::finite(x);
}
template <class Real>
bool is_inf(Real x)
{
    return same_bits(x, std::numeric_limits<Real>::infinity()) || same_bits(x, -std::numeric_limits<Real>::infinity());
}
template <class Real>
bool is_nan(Real x)
{
    return !is_finite(x) && !is_inf(x);
}

} // namespace

namespace {

using impact::status;
using W = long double;  // the type the test works out magnitudes in

// ---------------------------------------------------------------------------------
// Comparing and describing values.

// Bit for bit, NaN-aware: the same bits for float and double; for long double, whose
// 80 bits sit in 16 bytes of which 6 are padding, the same value and sign, or both NaN.
template <class Real>
bool identical(Real a, Real b)
{
    if constexpr (sizeof(Real) <= sizeof(double))
        return std::memcmp(&a, &b, sizeof(Real)) == 0;
    else
        return (is_nan(a) && is_nan(b)) || (a == b && std::signbit(a) == std::signbit(b));
}

template <class Real, std::size_t N>
bool identical(const std::array<Real, N>& a, const std::array<Real, N>& b)
{
    for (std::size_t d = 0; d < N; ++d)
        if (!identical(a[d], b[d]))
            return false;
    return true;
}

const char* name(status s)
{
    switch (s) {
    case status::ok: return "ok";
    case status::invalid_mass: return "invalid_mass";
    case status::invalid_restitution: return "invalid_restitution";
    case status::non_finite: return "non_finite";
    case status::separating: return "separating";
    case status::coincident_centres: return "coincident_centres";
    case status::out_of_range: return "out_of_range";
    case status::underflow: return "underflow";
    // collide_rough's own (no kernel tested here returns them).
    case status::invalid_radius: return "invalid_radius";
    case status::invalid_inertia: return "invalid_inertia";
    case status::invalid_tangential_restitution: return "invalid_tangential_restitution";
    case status::invalid_friction: return "invalid_friction";
    // collide_wall's own.
    case status::invalid_normal: return "invalid_normal";
    case status::behind_the_wall: return "behind_the_wall";
    }
    return "(not a status)";
}

// A set of statuses, as the classification admits them.
using statuses = unsigned;
statuses only(status s)
{
    return 1u << static_cast<unsigned>(s);
}
bool admits(statuses set, status s)
{
    return (set & only(s)) != 0;
}
// The set admits more than one status: the inputs lie on a boundary of the classification.
bool borderline(statuses set)
{
    return (set & (set - 1)) != 0;
}

template <class Real>
std::string text(Real x)
{
    std::ostringstream out;
    out.precision(std::numeric_limits<Real>::max_digits10);
    out << x;
    return out.str();
}

template <class Real, std::size_t N>
std::string text(const std::array<Real, N>& a)
{
    std::string out = "{";
    for (std::size_t d = 0; d < N; ++d)
        out += (d ? ", " : "") + text(a[d]);
    return out + "}";
}

template <class Real>
const char* type_name()
{
    if constexpr (std::is_same_v<Real, float>)
        return "float";
    else if constexpr (std::is_same_v<Real, double>)
        return "double";
    else
        return "long double";
}

// Failures of the sweep, counted, the first few described: a sweep of millions of pairs
// would otherwise drown the log (and BOOST_TEST per pair would dominate its time).
struct failures {
    std::size_t count = 0;
    void operator()(bool holds, const std::string& what)
    {
        if (holds)
            return;
        if (++count <= 10)
            BOOST_TEST_MESSAGE("failed: " << what);
    }
};

// ---------------------------------------------------------------------------------
// Magnitudes, as powers of 2, of values worked out in long double.

W lg(W x)
{
    return x == 0 ? -std::numeric_limits<W>::infinity() : std::log2(std::fabs(x));
}

template <class Real>
struct range {
    using limits = std::numeric_limits<Real>;
    static W most() { return std::log2(static_cast<W>(limits::max())); }
    // The smallest divisor the kernels accept, as documented: min / epsilon of the type.
    static W least_divisor() { return static_cast<W>(limits::min_exponent - 1) - static_cast<W>(1 - limits::digits); }
    static W unit() { return static_cast<W>(limits::epsilon()) / 2; }  // the unit roundoff
};

// The power of 2 that brings x near 1 (0 for 0, infinities and NaN).
int scale_of(W x)
{
    return is_finite(x) && x != 0 ? std::ilogb(x) : 0;
}

// A number f 2^e with f in [0.5, 1) (or 0) and e unbounded: the collision's values worked
// out without overflow or underflow, whatever the type's range (long double's included).
struct big {
    W f = 0;
    long e = 0;
};

big normal(W f, long e)
{
    if (f == 0 || !is_finite(f))
        return {f, 0};
    int k = 0;
    const W g = std::frexp(f, &k);
    return {g, e + k};
}
big of(W x)
{
    return normal(x, 0);
}
big operator*(big a, big b)
{
    return normal(a.f * b.f, a.e + b.e);
}
big operator/(big a, big b)
{
    return normal(a.f / b.f, a.e - b.e);
}
big operator+(big a, big b)
{
    if (a.f == 0)
        return b;
    if (b.f == 0)
        return a;
    const long top = std::max(a.e, b.e);
    auto at_top = [&](big x) { return std::ldexp(x.f, static_cast<int>(std::max(x.e - top, -20000L))); };
    return normal(at_top(a) + at_top(b), top);
}
big operator-(big a)
{
    return {-a.f, a.e};
}
big magnitude(big a)
{
    return {std::fabs(a.f), a.e};
}
W lg(big a)
{
    return a.f == 0 ? -std::numeric_limits<W>::infinity() : std::log2(std::fabs(a.f)) + static_cast<W>(a.e);
}
W value(big a)  // in long double: infinite or 0 beyond its range
{
    return std::ldexp(a.f, static_cast<int>(std::clamp(a.e, -40000L, 40000L)));
}

// Whether x, worked out exactly (or nearly) in long double, is infinite once rounded to
// Real: at least max + half an ulp of max (round to nearest; max's last bit is odd, so the
// tie goes up too). For long double, long double's own overflow decides.
template <class Real>
bool beyond(W x)
{
    using limits = std::numeric_limits<Real>;
    if constexpr (sizeof(Real) >= sizeof(W))
        return !is_finite(x);
    else
        return !(std::fabs(x) < static_cast<W>(limits::max()) + std::ldexp(W(1), limits::max_exponent - limits::digits - 1));
}

// What the classification decides about the range of a collision's values: out_of_range
// certain, ok certain, or either. The divisor's lower bound has a margin of 4 (the kernels'
// divisor is within a few ulps of the exact one, or within a factor of 2 where |r|^2 is a
// denormal), and so have the intermediates; the divisor's upper bound and the results, the
// kernels' rounding (`slack`, in powers of 2).
template <class Real>
statuses range_statuses(W divisor_lg, const std::vector<W>& intermediates_lg, const std::vector<W>& results_lg,
                        W slack)
{
    const W most = range<Real>::most(), least = range<Real>::least_divisor();
    bool leaves = divisor_lg < least - 2 || divisor_lg > most + slack;
    bool inside = divisor_lg >= least + 2 && divisor_lg <= most - slack;
    for (W r : results_lg) {
        leaves = leaves || r > most + slack || is_nan(r);
        inside = inside && r <= most - slack;
    }
    for (W i : intermediates_lg)  // each a term of a sum of up to 3: below max/4, the sum fits
        inside = inside && i <= most - 2;
    if (leaves)
        return only(status::out_of_range);
    if (inside)
        return only(status::ok);
    return only(status::ok) | only(status::out_of_range);
}

// The kernels' rounding near the top of the range, as a power of 2: 64 ulps of the type,
// and of the logarithms worked out here.
template <class Real>
W slack()
{
    return 64 * (range<Real>::unit() + std::numeric_limits<W>::epsilon() * range<Real>::most());
}

// 7. Underflow, as the kernels document it: a value of the kernel's arithmetic (a product,
// quotient, fused multiply-add or function) below the smallest normal number, or fallen to 0
// from operands that are not 0. The test does not know the kernel's
// operations, only the documented forms: each value of them is a product of some of the
// collision's factors (masses, differences, eps, reciprocals of divisors, ...), so it is at
// least the product of those factors below 1. `monomials` lists the factors of each product
// of a form, as powers of 2 (-inf for a factor 0, left out: a product with a factor 0 is 0,
// as it should be); none can underflow when every such bound is at least min * 8.
W lowest_product(std::initializer_list<std::initializer_list<W>> monomials)
{
    W lowest = std::numeric_limits<W>::infinity();
    for (const auto& factors : monomials) {
        W bound = 0;
        for (W f : factors)
            bound += is_finite(f) ? std::min<W>(0, f) : 0;
        lowest = std::min(lowest, bound);
    }
    return lowest;
}

// The statuses admitted once underflow is considered: where ok is admitted, a lowest product
// that could fall below the normal range admits underflow too. (A subnormal input is not
// refused for itself: a sum of it is exact, and a product of it is tested.)
// `certain`: the least of products the forms compute as the last of a chain of products of
// factors not 0; below min/4, the kernel's value of it is below min, and underflow certain.
template <class Real>
statuses with_underflow(statuses admitted, W lowest, W certain = std::numeric_limits<W>::infinity())
{
    if (!admits(admitted, status::ok))
        return admitted;
    if (certain < std::numeric_limits<Real>::min_exponent - 3)
        return (admitted & ~only(status::ok)) | only(status::underflow);
    if (!(lowest >= std::numeric_limits<Real>::min_exponent + 2))
        admitted |= only(status::underflow);
    return admitted;
}

// ---------------------------------------------------------------------------------
// The draws: std::mt19937_64, whose output the standard fixes, and distributions written
// out here (the standard library's are implementation-defined), so that a seed gives the
// same pairs everywhere.

class draws {
public:
    explicit draws(std::uint64_t seed) : engine_(seed) {}
    W unit() { return static_cast<W>(engine_() >> 11) * 0x1p-53L; }  // [0, 1)
    std::size_t pick(std::size_t n) { return static_cast<std::size_t>(engine_() % n); }
    bool chance(W p) { return unit() < p; }

private:
    std::mt19937_64 engine_;
};

// Values of each kind, hostile or ordinary, in the type Real.
template <class Real>
struct hostile {
    using limits = std::numeric_limits<Real>;
    draws& d;
    W hostility;  // the chance that a value is drawn from the hostile mix

    Real pick_of(std::initializer_list<Real> values)
    {
        return *(values.begin() + static_cast<std::ptrdiff_t>(d.pick(values.size())));
    }
    // Values no kernel may trust: every edge of the type.
    Real edge()
    {
        const Real inf = limits::infinity(), tiny = limits::denorm_min(), least = limits::min(), most = limits::max();
        const Real huge = std::ldexp(Real(1), limits::max_exponent - 3);
        return pick_of({Real(0), -Real(0), tiny, -tiny, 4 * tiny, least, -least, most, -most, huge, -huge, inf, -inf,
                        limits::quiet_NaN(), std::sqrt(tiny), std::sqrt(most), -std::sqrt(most)});
    }
    Real mass()
    {
        if (d.chance(hostility))
            return d.chance(0.8) ? edge() : pick_of({Real(-1), Real(1) / 3, Real(1e30f), Real(1e-30f)});
        return static_cast<Real>(std::exp2(40 * d.unit() - 20));  // 2^-20 to 2^20
    }
    Real velocity()
    {
        if (d.chance(hostility))
            return edge();
        return static_cast<Real>(20 * d.unit() - 10);
    }
    Real position() { return velocity(); }
    // eps at and a hair beyond the ends of [0, 1], or anywhere in it.
    Real eps()
    {
        if (d.chance(hostility)) {
            const Real e = limits::epsilon();
            return pick_of({Real(0), -Real(0), Real(1), Real(1) + e, Real(1) - e / 2, -limits::denorm_min(),
                            static_cast<Real>(-1e-16), e, Real(2), limits::infinity(), -limits::infinity(),
                            limits::quiet_NaN(), limits::denorm_min()});
        }
        return static_cast<Real>(d.unit());
    }
    // The centre of m: often at or next to the centre of M.
    Real near(Real c)
    {
        if (!d.chance(2 * hostility))
            return position();
        const Real tiny = limits::denorm_min();
        const Real offset = pick_of({Real(0), tiny, -tiny, limits::min(), std::sqrt(tiny), 2 * std::sqrt(tiny),
                                     std::ldexp(Real(1), limits::min_exponent / 2 - 8),
                                     std::ldexp(Real(1), limits::min_exponent / 2 + 8), limits::epsilon()});
        return c + offset;
    }
};

// The share of hostile values in a pair: some pairs are ordinary throughout, so that
// resolved collisions are checked as often as refused ones.
W hostility(draws& d)
{
    const W levels[] = {0, 0.05L, 0.15L, 0.4L};
    return levels[d.pick(4)];
}

std::size_t sweep_pairs()
{
    if (const char* text = std::getenv("IMPACT_SWEEP_PAIRS"))
        return static_cast<std::size_t>(std::strtoull(text, nullptr, 10));
    return 20000;
}

// What a sweep saw: statuses given, pairs on a boundary of the classification, and
// resolved pairs whose outputs are far from the closed form.
struct tally {
    std::size_t pairs = 0, borderline = 0, imprecise = 0, measured = 0;
    std::array<std::size_t, 64> by_status{};  // more slots than statuses (checked where counted)
    std::size_t refused_without_underflow = 0;  // underflow where every value of the closed form is normal
    W worst_ulps = 0;

    void report(const std::string& what) const
    {
        std::cout << what << ": " << pairs << " pairs;";
        for (std::size_t s = 0; s < by_status.size(); ++s)
            if (by_status[s])
                std::cout << ' ' << name(static_cast<status>(s)) << ' ' << by_status[s];
        std::cout << "; on a boundary " << borderline;
        if (by_status[static_cast<std::size_t>(status::underflow)])
            std::cout << "; underflow where the closed form's values are all normal " << refused_without_underflow;
        if (measured)
            std::cout << "; resolved beyond 16 ulps of the closed form " << imprecise << " of " << measured
                      << " (worst " << worst_ulps << ")";
        std::cout << '\n';
    }
};

void require_admitted(failures& fail, status s, statuses expected, const std::string& where)
{
    fail(admits(expected, s), std::string("status ") + name(s) + " not admitted by the classification: " + where);
}

// The error of a resolved value against the closed form, in ulps of `scale`.
template <class Real>
W ulps_of(Real value, W exact, W scale)
{
    const W unit = static_cast<W>(std::numeric_limits<Real>::epsilon());
    if (scale == 0 || !is_finite(scale))
        return value == exact ? 0 : std::numeric_limits<W>::infinity();
    return std::fabs(static_cast<W>(value) - exact) / (scale * unit);
}

constexpr W imprecise_ulps = 16;

// ---------------------------------------------------------------------------------
// collide in N dimensions.

template <class Real, std::size_t N>
struct pair_nd {
    Real M, m, eps;
    std::array<Real, N> C_M, C_m, v_M, v_m;

    std::string describe() const
    {
        return "M " + text(M) + ", m " + text(m) + ", C_M " + text(C_M) + ", C_m " + text(C_m) + ", v_M " + text(v_M) +
               ", v_m " + text(v_m) + ", eps " + text(eps);
    }
};

template <class Real, std::size_t N>
pair_nd<Real, N> draw_pair(draws& d)
{
    hostile<Real> h{d, hostility(d)};
    pair_nd<Real, N> p{};
    p.M = h.mass();
    p.m = h.mass();
    for (std::size_t k = 0; k < N; ++k) {
        p.C_M[k] = h.position();
        p.C_m[k] = h.near(p.C_M[k]);
        p.v_M[k] = h.velocity();
        p.v_m[k] = h.velocity();
    }
    p.eps = h.eps();
    return p;
}

bool positive_and_finite(W x)
{
    return x > 0 && is_finite(x);
}

// A fixed sphere: one mass +infinity, the other positive and finite (collide_line and
// collide then take the limit of that mass growing without bound; energy_loss refuses it).
bool fixed_sphere(W M, W m)
{
    const W inf = std::numeric_limits<W>::infinity();
    return (M == inf && positive_and_finite(m)) || (m == inf && positive_and_finite(M));
}

// The closed form of the collision, v'_M = v_M - (1 + eps) m (dv.r) r / ((M + m)|r|^2),
// v'_m = v_m + (1 + eps) M (dv.r) r / ((M + m)|r|^2) (the impulse along the line of centres,
// Eq. 9 and its 3D form), worked out in long double with masses, lengths and velocities
// scaled by powers of 2; and the statuses the inputs admit.
template <class Real, std::size_t N>
struct collision_nd {
    statuses admitted = 0;
    std::array<W, N> v_M_after{}, v_m_after{};  // meaningful where ok is admitted
    W velocity_scale = 0;
    bool underflows = false;  // a value of the closed form below the normal range
};

template <class Real, std::size_t N>
collision_nd<Real, N> classify(const pair_nd<Real, N>& p)
{
    collision_nd<Real, N> c;
    if (!positive_and_finite(p.M) || !positive_and_finite(p.m)) {
        c.admitted = only(status::invalid_mass);
        return c;
    }
    if (!(p.eps >= 0 && p.eps <= 1)) {
        c.admitted = only(status::invalid_restitution);
        return c;
    }
    for (std::size_t k = 0; k < N; ++k)
        if (!is_finite(p.C_M[k]) || !is_finite(p.C_m[k]) || !is_finite(p.v_M[k]) || !is_finite(p.v_m[k])) {
            c.admitted = only(status::non_finite);
            return c;
        }

    std::array<W, N> r{}, dv{};
    bool infinite = false;  // a difference infinite in the type
    for (std::size_t k = 0; k < N; ++k) {
        r[k] = static_cast<W>(p.C_M[k]) - static_cast<W>(p.C_m[k]);
        dv[k] = static_cast<W>(p.v_M[k]) - static_cast<W>(p.v_m[k]);
        infinite = infinite || beyond<Real>(r[k]) || beyond<Real>(dv[k]);
    }
    // 4. |r|^2 is 0 in the type when every r_k^2 rounds to 0: r_k^2 <= denorm_min / 2 (the
    // tie goes to the even 0). Compared scaled by 2^2s, denorm_min then near 1, so that
    // long double holds both sides.
    const int s = (std::numeric_limits<Real>::digits - std::numeric_limits<Real>::min_exponent) / 2 + 1;
    const W half_tiny = std::ldexp(static_cast<W>(std::numeric_limits<Real>::denorm_min()), 2 * s) / 2;
    bool apart = false;
    for (std::size_t k = 0; k < N; ++k) {
        const W scaled = std::ldexp(std::fabs(r[k]), s);
        apart = apart || !(scaled * scaled <= half_tiny);
    }
    if (!apart) {
        c.admitted = only(status::coincident_centres);
        return c;
    }
    // A difference infinite in the type: the dot product is infinite or NaN, and the pair
    // separating or out of range.
    if (infinite) {
        c.admitted = only(status::separating) | only(status::out_of_range);
        return c;
    }

    big dot, dot_terms, r2;
    bool term_infinite = false;
    for (std::size_t k = 0; k < N; ++k) {
        const big term = of(dv[k]) * of(r[k]);
        dot = dot + term;
        dot_terms = dot_terms + magnitude(term);
        r2 = r2 + of(r[k]) * of(r[k]);
        term_infinite = term_infinite || beyond<Real>(value(term));  // (not by logarithms: too coarse there)
    }

    // 5. The pair approaches when dv.r < 0: certain away from 0, by more than the
    // rounding of the terms in the type and than the smallest normal number.
    const bool sign_certain = lg(dot) > lg(dot_terms) + std::log2(16 * range<Real>::unit()) &&
                              lg(dot) > std::numeric_limits<Real>::min_exponent + 6;
    if (sign_certain && dot.f > 0) {
        c.admitted = only(status::separating);
        return c;
    }
    if (term_infinite) {  // a term at the range's end: infinite in the type, or nearly
        c.admitted = only(status::separating) | only(status::out_of_range);
        return c;
    }
    if (beyond<Real>(value(dot_terms)))  // the terms' sum can overflow, whatever the order
        c.admitted |= only(status::separating) | only(status::out_of_range);
    if (!sign_certain) {
        c.admitted |= only(status::separating);
        if (dot_terms.f == 0) {  // exactly 0: no relative motion along r
            c.admitted = only(status::separating);
            return c;
        }
    }

    // 6. The range: k = (1 + eps) dv.r / ((M + m)|r|^2), then k m r_x and k M r_x.
    const big M = of(p.M), m = of(p.m), heavier = of(std::max<W>(p.M, p.m)), masses = M + m;
    const big k = of(1 + static_cast<W>(p.eps)) * dot / (masses * r2);
    const W divisor_lg = lg(masses * r2);
    std::vector<W> intermediates{lg(r2), lg(of(1 + static_cast<W>(p.eps)) * dot), lg(k), lg(k * heavier), lg(masses)};
    std::vector<W> results;
    for (std::size_t i = 0; i < N; ++i) {
        const big vM = of(p.v_M[i]) + -(k * m * of(r[i])), vm = of(p.v_m[i]) + k * M * of(r[i]);
        c.v_M_after[i] = value(vM);
        c.v_m_after[i] = value(vm);
        results.push_back(lg(vM));
        results.push_back(lg(vm));
        intermediates.push_back(lg(k * heavier * of(r[i])));
        c.velocity_scale = std::max({c.velocity_scale, std::fabs(c.v_M_after[i]), std::fabs(c.v_m_after[i])});
    }
    for (std::size_t i = 0; i < N; ++i)
        c.velocity_scale = std::max({c.velocity_scale, std::fabs(static_cast<W>(p.v_M[i])), std::fabs(static_cast<W>(p.v_m[i]))});
    // Where |r|^2 is a denormal, k may be a factor of 2 off in the type (the known limit).
    const bool r2_denormal = lg(r2) < std::numeric_limits<Real>::min_exponent - 1;
    for (W v : intermediates)
        c.underflows = c.underflows || v < std::numeric_limits<Real>::min_exponent + 1;
    for (std::size_t i = 0; i < N; ++i)
        for (W v : {static_cast<W>(p.v_M[i]), static_cast<W>(p.v_m[i]), static_cast<W>(p.C_M[i]), static_cast<W>(p.C_m[i]), dv[i], r[i]})
            c.underflows = c.underflows || (v != 0 && lg(v) < std::numeric_limits<Real>::min_exponent + 1);
    c.admitted |= range_statuses<Real>(divisor_lg, intermediates, results, r2_denormal ? 2 : slack<Real>());

    // 7. The documented form: v_M - k m r, v_m + k M r with k = (1 + eps) dv.r / ((M + m)|r|^2):
    // the products r_i r_i and dv_i r_i of the sums, (1 + eps) dv.r, (M + m)|r|^2, k, k m,
    // k M, k m r_i and k M r_i.
    const W k_lg = lg(dot) - lg(masses) - lg(r2), M_lg = lg(p.M), m_lg = lg(p.m);
    W lowest = lowest_product({{lg(dot)}, {lg(masses), lg(r2)}, {lg(dot), -lg(masses), -lg(r2)}, {k_lg, M_lg}, {k_lg, m_lg}});
    for (std::size_t i = 0; i < N; ++i) {
        lowest = std::min(lowest, lowest_product({{lg(r[i]), lg(r[i])}, {lg(dv[i]), lg(r[i])}, {k_lg, M_lg, lg(r[i])},
                                                  {k_lg, m_lg, lg(r[i])}}));
    }
    W certain = std::numeric_limits<W>::infinity();  // k m r_i and k M r_i, r_i not 0
    for (std::size_t i = 0; i < N; ++i)
        if (r[i] != 0)
            certain = std::min(certain, k_lg + std::min(M_lg, m_lg) + lg(r[i]));
    c.admitted = with_underflow<Real>(c.admitted, lowest, certain);
    return c;
}

// Momentum, M v'_M + m v'_m = M v_M + m v_m per axis (Eq. 1a), to 32 ulps of the sum S of
// the momenta's magnitudes. In 2D and 3D each impulse term (k m) r and (k M) r is rounded
// twice and each velocity once more (v - term): at most 5u S, whatever k's own error. In 1D
// each velocity is a quotient of sums of products (Eq. 8), at most 10u S over both. The
// sums here, in long double, add at most 4u S when Real is long double: 14u S at worst,
// doubled for second-order terms. A product that underflows adds an absolute error of
// denorm_min per rounding: up to 8 denorm_min in the momenta (1D, where masses multiply
// velocities inside the kernel); in 2D and 3D, k m and k M are multiplied by r after their
// rounding, up to 8 denorm_min (1 + |r|) in the velocities (`lever` = |r|). Worked out in
// big numbers, so that no product of the test's own overflows or underflows.
template <class Real>
bool conserves_momentum(Real M, Real m, Real v_M, Real v_m, Real v_M_after, Real v_m_after, W lever = 0)
{
    // In big numbers: no product overflows or underflows here, whatever the type.
    const big Mb = of(M), mb = of(m);
    const big before = Mb * of(v_M) + mb * of(v_m), after = Mb * of(v_M_after) + mb * of(v_m_after);
    const big magnitudes = magnitude(Mb * of(v_M)) + magnitude(mb * of(v_m)) + magnitude(Mb * of(v_M_after)) +
                           magnitude(mb * of(v_m_after));
    const W tiny = static_cast<W>(std::numeric_limits<Real>::denorm_min());
    const big allowed = of(32 * range<Real>::unit()) * magnitudes + of(8 * tiny) * (of(1) + (Mb + mb) * of(1 + lever));
    const big residual = after + -before;
    return residual.f == 0 || lg(residual) <= lg(allowed);
}

template <class Real, std::size_t N>
void check_resolved(failures& fail, tally& t, const pair_nd<Real, N>& p, const impact::collide_result<Real, N>& out,
                    const collision_nd<Real, N>& c)
{
    for (std::size_t k = 0; k < N; ++k) {
        fail(is_finite(out.v_M[k]) && is_finite(out.v_m[k]), "ok with a velocity not finite: " + p.describe());
        W lever = 0;
        for (std::size_t i = 0; i < N; ++i)
            lever = std::max(lever, std::fabs(static_cast<W>(p.C_M[i]) - static_cast<W>(p.C_m[i])));
        fail(conserves_momentum(p.M, p.m, p.v_M[k], p.v_m[k], out.v_M[k], out.v_m[k], lever),
             "momentum not conserved along axis " + std::to_string(k) + ": " + p.describe() + " -> " + text(out.v_M) +
                 ", " + text(out.v_m));
    }
    if constexpr (!std::is_same_v<Real, long double>) {  // long double has no wider reference here
        W worst = 0;
        for (std::size_t k = 0; k < N; ++k)
            worst = std::max({worst, ulps_of(out.v_M[k], c.v_M_after[k], c.velocity_scale),
                              ulps_of(out.v_m[k], c.v_m_after[k], c.velocity_scale)});
        ++t.measured;
        t.imprecise += worst > imprecise_ulps ? 1 : 0;
        t.worst_ulps = std::max(t.worst_ulps, worst);
        fail(worst <= imprecise_ulps, "ok but " + text(worst) + " ulps from the closed form: " + p.describe() + " -> " +
                                          text(out.v_M) + ", " + text(out.v_m));
    }
}

// `form`: nothing for the accurate form, impact::fast for the fast one (the same contract
// and the same classification; the fast form computes the closed form of the classification,
// v_M - k m r, plainly).
template <class Real, std::size_t N, class... Form>
impact::collide_result<Real, N> scalar_collide(const pair_nd<Real, N>& p, Form... form)
{
    return impact::collide(p.M, p.m, p.C_M, p.C_m, p.v_M, p.v_m, p.eps, form...);
}

// A fixed sphere (one mass +infinity): the statuses of the domains as for any pair, then
// any of the geometry's and the range's (its boundaries are not classified here); where
// resolved, the fixed sphere's velocity unchanged bit for bit and the other's within 16
// ulps of the limit's closed form, v - (1 + eps) ((v - V).r) r/|r|^2, V the fixed sphere's
// velocity, worked out in long double.
template <class Real, std::size_t N>
void check_fixed_pair(failures& fail, tally& t, const pair_nd<Real, N>& p, status got, const std::array<Real, N>& v_M,
                      const std::array<Real, N>& v_m)
{
    statuses admitted = only(status::coincident_centres) | only(status::separating) | only(status::ok) |
                        only(status::underflow) | only(status::out_of_range);
    bool finite = true;
    for (std::size_t k = 0; k < N; ++k)
        finite = finite && is_finite(p.C_M[k]) && is_finite(p.C_m[k]) && is_finite(p.v_M[k]) &&
                 is_finite(p.v_m[k]);
    if (!(p.eps >= 0 && p.eps <= 1))
        admitted = only(status::invalid_restitution);
    else if (!finite)
        admitted = only(status::non_finite);
    require_admitted(fail, got, admitted, "a fixed sphere: " + p.describe());
    if (got != status::ok)
        return;
    const bool M_fixed = is_inf(p.M);
    fail(M_fixed ? identical(v_M, p.v_M) : identical(v_m, p.v_m),
         "the fixed sphere's velocity changed: " + p.describe() + " -> " + text(v_M) + ", " + text(v_m));
    if constexpr (!std::is_same_v<Real, long double>) {
        W dot = 0, r2 = 0, scale = 0;
        for (std::size_t k = 0; k < N; ++k) {
            const W r = static_cast<W>(p.C_M[k]) - static_cast<W>(p.C_m[k]);
            dot += (static_cast<W>(p.v_M[k]) - static_cast<W>(p.v_m[k])) * r;
            r2 += r * r;
        }
        W worst = 0;
        for (std::size_t k = 0; k < N; ++k) {
            const W r = static_cast<W>(p.C_M[k]) - static_cast<W>(p.C_m[k]);
            const W push = (1 + static_cast<W>(p.eps)) * dot / r2 * r;
            const W exact = M_fixed ? static_cast<W>(p.v_m[k]) + push : static_cast<W>(p.v_M[k]) - push;
            const Real got_k = M_fixed ? v_m[k] : v_M[k];
            scale = std::max({scale, std::fabs(exact), std::fabs(static_cast<W>(p.v_M[k])),
                              std::fabs(static_cast<W>(p.v_m[k]))});
            worst = std::max(worst, std::fabs(static_cast<W>(got_k) - exact));
        }
        worst = worst / (scale * static_cast<W>(std::numeric_limits<Real>::epsilon()));
        ++t.measured;
        t.imprecise += worst > imprecise_ulps ? 1 : 0;
        t.worst_ulps = std::max(t.worst_ulps, worst);
        fail(worst <= imprecise_ulps, "a fixed sphere, ok but " + text(worst) + " ulps from the limit's closed form: " +
                                          p.describe() + " -> " + text(v_M) + ", " + text(v_m));
    }
}

// One pair through the scalar kernel, against the classification.
template <class Real, std::size_t N, class... Form>
void check_pair(failures& fail, tally& t, const pair_nd<Real, N>& p, Form... form)
{
    if (fixed_sphere(p.M, p.m)) {
        std::feclearexcept(FE_DIVBYZERO);
        const auto out = scalar_collide(p, form...);
        fail(std::fetestexcept(FE_DIVBYZERO) == 0, "divided by zero: " + p.describe());
        ++t.pairs;
        ++t.by_status.at(static_cast<std::size_t>(out.status));
        if (out.status != status::ok)
            fail(identical(out.v_M, p.v_M) && identical(out.v_m, p.v_m),
                 std::string("refused (") + name(out.status) + ") with velocities changed: " + p.describe());
        check_fixed_pair(fail, t, p, out.status, out.v_M, out.v_m);
        return;
    }
    const collision_nd<Real, N> c = classify(p);
    std::feclearexcept(FE_DIVBYZERO);
    const auto out = scalar_collide(p, form...);
    fail(std::fetestexcept(FE_DIVBYZERO) == 0, "divided by zero: " + p.describe());
    ++t.pairs;
    const auto s = static_cast<std::size_t>(out.status);
    fail(s < t.by_status.size(), "not a status: " + p.describe());
    if (s >= t.by_status.size())
        return;
    ++t.by_status[s];
    t.borderline += borderline(c.admitted) ? 1 : 0;
    require_admitted(fail, out.status, c.admitted, p.describe());
    t.refused_without_underflow += out.status == status::underflow && !c.underflows ? 1 : 0;
    if (out.status == status::ok)
        check_resolved(fail, t, p, out, c);
    else
        fail(identical(out.v_M, p.v_M) && identical(out.v_m, p.v_m),
             std::string("refused (") + name(out.status) + ") with velocities changed: " + p.describe());
}

// A chunk of pairs through collide_batch, with and without statuses: bit for bit the scalar
// kernel's velocities and statuses.
template <class Real, std::size_t N, class... Form>
void check_batch(failures& fail, const std::vector<pair_nd<Real, N>>& pairs, Form... form)
{
    const std::size_t n = pairs.size();
    std::vector<Real> M(n), m(n), eps(n);
    std::array<std::vector<Real>, N> C_M, C_m, v_M, v_m, v_M_plain, v_m_plain;
    for (std::size_t k = 0; k < N; ++k)
        for (auto* a : {&C_M[k], &C_m[k], &v_M[k], &v_m[k]})
            a->resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        M[i] = pairs[i].M;
        m[i] = pairs[i].m;
        eps[i] = pairs[i].eps;
        for (std::size_t k = 0; k < N; ++k) {
            C_M[k][i] = pairs[i].C_M[k];
            C_m[k][i] = pairs[i].C_m[k];
            v_M[k][i] = pairs[i].v_M[k];
            v_m[k][i] = pairs[i].v_m[k];
        }
    }
    v_M_plain = v_M;
    v_m_plain = v_m;
    std::vector<status> given(n, status::ok);
    auto data = [&](std::array<std::vector<Real>, N>& vM, std::array<std::vector<Real>, N>& vm, status* into) {
        impact::collide_batch_data<Real, N> b{};
        b.count = n;
        b.M = M.data();
        b.m = m.data();
        b.eps = eps.data();
        for (std::size_t k = 0; k < N; ++k) {
            b.C_M[k] = C_M[k].data();
            b.C_m[k] = C_m[k].data();
            b.v_M[k] = vM[k].data();
            b.v_m[k] = vm[k].data();
        }
        b.status = into;
        return b;
    };
    impact::collide_batch(data(v_M, v_m, given.data()), form...);
    impact::collide_batch(data(v_M_plain, v_m_plain, nullptr), form...);
    for (std::size_t i = 0; i < n; ++i) {
        const auto scalar = scalar_collide(pairs[i], form...);
        bool same = given[i] == scalar.status;
        for (std::size_t k = 0; k < N; ++k)
            same = same && identical(v_M[k][i], scalar.v_M[k]) && identical(v_m[k][i], scalar.v_m[k]) &&
                   identical(v_M_plain[k][i], scalar.v_M[k]) && identical(v_m_plain[k][i], scalar.v_m[k]);
        fail(same, std::string("batch differs from the scalar kernel (") + name(scalar.status) + " against " +
                       name(given[i]) + "): " + pairs[i].describe());
    }
}

template <class Real, std::size_t N, class... Form>
void sweep_collide(std::uint64_t seed, Form... form)
{
    draws d(seed);
    failures fail;
    tally t;
    const std::size_t total = sweep_pairs(), chunk = 4096;
    std::vector<pair_nd<Real, N>> pairs;
    for (std::size_t done = 0; done < total;) {
        pairs.clear();
        for (; pairs.size() < chunk && done < total; ++done)
            pairs.push_back(draw_pair<Real, N>(d));
        for (const auto& p : pairs)
            check_pair(fail, t, p, form...);
        check_batch(fail, pairs, form...);
    }
    t.report(std::string("collide<") + type_name<Real>() + ", " + std::to_string(N) + "D>" +
             (sizeof...(Form) ? ", impact::fast" : ""));
    BOOST_TEST(fail.count == 0u);
    BOOST_TEST(t.by_status[static_cast<std::size_t>(status::ok)] > t.pairs / 20);  // the sweep resolves collisions too
    BOOST_TEST(t.borderline < t.pairs / 20);  // and its classification decides most pairs alone
    BOOST_TEST(t.imprecise == 0u);  // every resolved collision within 16 ulps of the closed form
}

// ---------------------------------------------------------------------------------
// collide_line: along the line of action, m ahead of M (Eq. 8: the impulse J acts on M
// against the line and on m along it), so that the spheres approach when v_M > v_m.

template <class Real>
struct pair_1d {
    Real M, m, v_M, v_m, eps;
    std::string describe() const
    {
        return "M " + text(M) + ", m " + text(m) + ", v_M " + text(v_M) + ", v_m " + text(v_m) + ", eps " + text(eps);
    }
};

template <class Real>
pair_1d<Real> draw_pair_1d(draws& d)
{
    hostile<Real> h{d, hostility(d)};
    pair_1d<Real> p{};
    p.M = h.mass();
    p.m = h.mass();
    p.v_M = h.velocity();
    p.v_m = h.velocity();
    p.eps = h.eps();
    return p;
}

// The statuses shared by collide_line and energy_loss up to the range: the domains.
template <class Real>
statuses domain_statuses(const pair_1d<Real>& p)
{
    if (!positive_and_finite(p.M) || !positive_and_finite(p.m))
        return only(status::invalid_mass);
    if (!(p.eps >= 0 && p.eps <= 1))
        return only(status::invalid_restitution);
    if (!is_finite(p.v_M) || !is_finite(p.v_m))
        return only(status::non_finite);
    return 0;
}

// The closed forms of Eq. 8 and Eq. 11 in long double, scaled: velocities by 2^-b, masses
// by 2^-e.
struct line_closed_form {
    W v_M_after, v_m_after, J, dE;
    W velocity_scale;
    std::vector<W> line_intermediates, loss_intermediates;
    W divisor_lg, v_M_lg, v_m_lg, J_lg, dE_lg, dv;
    bool underflows;  // a value of the closed form below the normal range
    W line_lowest, loss_lowest;  // the lowest products of the documented forms (see lowest_product)
    W line_certain, loss_certain;  // the products the forms must compute (see with_underflow)
};

template <class Real>
line_closed_form closed_form(const pair_1d<Real>& p)
{
    line_closed_form f{};
    const W dv = static_cast<W>(p.v_M) - static_cast<W>(p.v_m);
    const W v_largest = std::max({std::fabs(dv), std::fabs(static_cast<W>(p.v_M)), std::fabs(static_cast<W>(p.v_m))});
    const int b = scale_of(v_largest), e = scale_of(std::max<W>(p.M, p.m));
    const W Ms = std::ldexp(static_cast<W>(p.M), -e), ms = std::ldexp(static_cast<W>(p.m), -e);
    const W vMs = std::ldexp(static_cast<W>(p.v_M), -b), vms = std::ldexp(static_cast<W>(p.v_m), -b);
    const W dvs = std::ldexp(dv, -b), eps = p.eps;
    const W vM = vMs - (1 + eps) * ms * dvs / (Ms + ms), vm = vms + (1 + eps) * Ms * dvs / (Ms + ms);  // Eq. 8
    const W J = (1 + eps) * Ms * ms * dvs / (Ms + ms);
    const W dE = -(1 - eps) * (1 + eps) * Ms * ms * dvs * dvs / (2 * (Ms + ms));  // Eq. 11
    f.dv = dv;
    f.v_M_after = std::ldexp(vM, b);
    f.v_m_after = std::ldexp(vm, b);
    f.J = std::ldexp(J, e + b);
    f.dE = std::ldexp(dE, e + 2 * b);
    f.velocity_scale = std::max({v_largest, std::fabs(f.v_M_after), std::fabs(f.v_m_after)});
    f.divisor_lg = lg(Ms + ms) + e;
    f.v_M_lg = lg(vM) + b;
    f.v_m_lg = lg(vm) + b;
    f.J_lg = lg(J) + e + b;
    f.dE_lg = lg(dE) + e + 2 * b;
    // Magnitudes from the values as given (scaled, a small mass can vanish in long double).
    const W M_lg = lg(p.M), m_lg = lg(p.m), mass_lg = std::max(M_lg, m_lg), dv_lg = lg(dv);
    // Eq. 8 written as the paper does: M v_M + m v_m + eps m (v_m - v_M) over M + m, and
    // J = (1 + eps) M m (v_M - v_m) / (M + m).
    f.line_intermediates = {M_lg + lg(p.v_M), m_lg + lg(p.v_m), mass_lg + lg(eps) + dv_lg, dv_lg,
                            M_lg + m_lg + lg(1 + eps), M_lg + m_lg + lg(1 + eps) + dv_lg};
    // Eq. 11: (1 - eps)(1 + eps) M m, times (v_M - v_m)^2, over 2 (M + m).
    f.loss_intermediates = {M_lg + m_lg + lg(1 + eps), M_lg + m_lg + lg((1 - eps) * (1 + eps)), dv_lg, 2 * dv_lg,
                            M_lg + m_lg + lg((1 - eps) * (1 + eps)) + 2 * dv_lg};
    // 7. The documented forms: v'_M = (M v_M + m v_m - eps m (v_M - v_m))/(M + m), v'_m alike,
    // J = (1 + eps) M m (v_M - v_m)/(M + m), dE = -(1 - eps)(1 + eps) M m (v_M - v_m)^2/(2 (M + m)).
    // A sum of the velocities' numerators may cancel: computed, it is 0 or at least the
    // rounding of its largest term, 2^-(2 digits + 8) of it; so are the velocities then.
    const W vM_lg = lg(p.v_M), vm_lg = lg(p.v_m), eps_lg = lg(eps), div_lg = lg(Ms + ms) + e;
    const W plus_lg = lg(1 + eps), minus_lg = lg(1 - eps), cancelled = -2 * std::numeric_limits<Real>::digits - 8;
    const W largest_term = std::max({M_lg + vM_lg, m_lg + vm_lg, mass_lg + eps_lg + dv_lg});
    // A sum whose exact value is above 8 ulps of its largest term is computed within a factor
    // of 2 of it; below, it may be as small as the floor.
    const auto sum_lg = [&](W exact_lg) {
        return exact_lg >= largest_term + 3 - std::numeric_limits<Real>::digits ? exact_lg - 1 : largest_term + cancelled;
    };
    const W partial_lg = sum_lg(lg(Ms * vMs + ms * vms) + e + b), partial_eps_lg = sum_lg(lg(Ms * vMs + eps * Ms * dvs) + e + b);
    const W numerator_M_lg = sum_lg(lg(vM) + b + div_lg), numerator_m_lg = sum_lg(lg(vm) + b + div_lg);
    f.line_lowest = lowest_product({{M_lg, vM_lg}, {m_lg, vm_lg}, {eps_lg, dv_lg}, {mass_lg, eps_lg, dv_lg},
                                    {M_lg, m_lg, eps_lg, dv_lg}, {M_lg, m_lg, plus_lg, dv_lg, -div_lg}, {partial_lg},
                                    {partial_eps_lg}, {numerator_M_lg}, {numerator_m_lg}, {numerator_M_lg, -div_lg},
                                    {numerator_m_lg, -div_lg}});
    f.loss_lowest = lowest_product({{M_lg, m_lg, plus_lg, minus_lg, dv_lg, dv_lg, -div_lg - 1}});
    // J's numerator (1 + eps) M m (v_M - v_m), and dE's, are chains of products of factors not 0.
    const W never = std::numeric_limits<W>::infinity();
    f.line_certain = dv != 0 ? M_lg + m_lg + plus_lg + dv_lg : never;
    f.loss_certain = eps < 1 && dv != 0 ? M_lg + m_lg + plus_lg + minus_lg + 2 * dv_lg : never;
    f.underflows = false;
    for (const auto* values : {&f.line_intermediates, &f.loss_intermediates})
        for (W v : *values)
            f.underflows = f.underflows || v < std::numeric_limits<Real>::min_exponent + 1;
    for (W v : {static_cast<W>(p.M), static_cast<W>(p.m), static_cast<W>(p.v_M), static_cast<W>(p.v_m), dv, f.J, f.dE})
        f.underflows = f.underflows || (v != 0 && lg(v) < std::numeric_limits<Real>::min_exponent + 1);
    return f;
}

template <class Real>
statuses classify_line(const pair_1d<Real>& p, const line_closed_form& f)
{
    if (const statuses s = domain_statuses(p))
        return s;
    // 5. v_M - v_m > 0 in the type exactly when v_M > v_m (the sign of a difference is exact).
    if (!(p.v_M > p.v_m))
        return only(status::separating);
    return with_underflow<Real>(
        range_statuses<Real>(f.divisor_lg, f.line_intermediates, {f.v_M_lg, f.v_m_lg, f.J_lg}, slack<Real>()),
        f.line_lowest, f.line_certain);
}

// A fixed sphere along the line (one mass +infinity): the statuses of the domains and the
// direction; where resolved, the fixed sphere's velocity unchanged bit for bit, the other's
// v_M + eps (v_M - v_m) (M fixed; v_m + eps (v_m - v_M) for m) and J = (1 + eps) mu (v_M - v_m),
// mu the finite mass, within 16 ulps, in long double.
template <class Real, class... Form>
void check_fixed_line_pair(failures& fail, tally& t, const pair_1d<Real>& p, Form... form)
{
    std::feclearexcept(FE_DIVBYZERO);
    const auto out = impact::collide_line(p.M, p.m, p.v_M, p.v_m, p.eps, form...);
    fail(std::fetestexcept(FE_DIVBYZERO) == 0, "divided by zero: " + p.describe());
    ++t.pairs;
    ++t.by_status.at(static_cast<std::size_t>(out.status));
    statuses admitted = only(status::ok) | only(status::underflow) | only(status::out_of_range);
    if (!(p.eps >= 0 && p.eps <= 1))
        admitted = only(status::invalid_restitution);
    else if (!is_finite(p.v_M) || !is_finite(p.v_m))
        admitted = only(status::non_finite);
    else if (!(p.v_M > p.v_m))
        admitted = only(status::separating);
    require_admitted(fail, out.status, admitted, "a fixed sphere: " + p.describe());
    if (out.status != status::ok) {
        fail(identical(out.v_M, p.v_M) && identical(out.v_m, p.v_m) && identical(out.J, Real(0)),
             std::string("refused (") + name(out.status) + ") with outputs changed: " + p.describe());
        return;
    }
    const bool M_fixed = is_inf(p.M);
    fail(M_fixed ? identical(out.v_M, p.v_M) : identical(out.v_m, p.v_m),
         "the fixed sphere's velocity changed: " + p.describe());
    fail(out.J >= 0, "an approaching pair pushed together (J < 0): " + p.describe());
    if constexpr (!std::is_same_v<Real, long double>) {
        const W vM = p.v_M, vm = p.v_m, eps = p.eps, finite = M_fixed ? p.m : p.M;
        const W other = M_fixed ? vM + eps * (vM - vm) : vm + eps * (vm - vM);
        const W J = (1 + eps) * finite * (vM - vm);
        const W scale = std::max({std::fabs(vM), std::fabs(vm), std::fabs(other)});
        const W worst = std::max(ulps_of(M_fixed ? out.v_m : out.v_M, other, scale), ulps_of(out.J, J, scale * finite));
        ++t.measured;
        t.imprecise += worst > imprecise_ulps ? 1 : 0;
        t.worst_ulps = std::max(t.worst_ulps, worst);
        fail(worst <= imprecise_ulps, "a fixed sphere, ok but " + text(worst) + " ulps from the limit's closed form: " +
                                          p.describe() + " -> " + text(out.v_M) + ", " + text(out.v_m) + ", J " +
                                          text(out.J));
    }
}

template <class Real, class... Form>
void check_line_pair(failures& fail, tally& t, const pair_1d<Real>& p, Form... form)
{
    if (fixed_sphere(p.M, p.m)) {
        check_fixed_line_pair(fail, t, p, form...);
        return;
    }
    const line_closed_form f = closed_form(p);
    const statuses admitted = classify_line(p, f);
    std::feclearexcept(FE_DIVBYZERO);
    const auto out = impact::collide_line(p.M, p.m, p.v_M, p.v_m, p.eps, form...);
    fail(std::fetestexcept(FE_DIVBYZERO) == 0, "divided by zero: " + p.describe());
    ++t.pairs;
    ++t.by_status.at(static_cast<std::size_t>(out.status));
    t.borderline += borderline(admitted) ? 1 : 0;
    require_admitted(fail, out.status, admitted, p.describe());
    t.refused_without_underflow += out.status == status::underflow && !f.underflows ? 1 : 0;
    if (out.status != status::ok) {
        fail(identical(out.v_M, p.v_M) && identical(out.v_m, p.v_m) && identical(out.J, Real(0)),
             std::string("refused (") + name(out.status) + ") with outputs changed: " + p.describe());
        return;
    }
    fail(is_finite(out.v_M) && is_finite(out.v_m) && is_finite(out.J), "ok, not finite: " + p.describe());
    fail(out.J >= 0, "an approaching pair pushed together (J < 0): " + p.describe());
    fail(conserves_momentum(p.M, p.m, p.v_M, p.v_m, out.v_M, out.v_m), "momentum not conserved: " + p.describe());
    if constexpr (!std::is_same_v<Real, long double>) {
        const W impulse_scale = f.velocity_scale * std::min<W>(p.M, p.m);
        const W worst = std::max({ulps_of(out.v_M, f.v_M_after, f.velocity_scale),
                                  ulps_of(out.v_m, f.v_m_after, f.velocity_scale), ulps_of(out.J, f.J, impulse_scale)});
        ++t.measured;
        t.imprecise += worst > imprecise_ulps ? 1 : 0;
        t.worst_ulps = std::max(t.worst_ulps, worst);
        fail(worst <= imprecise_ulps, "ok but " + text(worst) + " ulps from the closed form: " + p.describe() + " -> " +
                                          text(out.v_M) + ", " + text(out.v_m) + ", J " + text(out.J));
    }
}

template <class Real, class... Form>
void check_loss_pair(failures& fail, tally& t, const pair_1d<Real>& p, Form... form)
{
    const line_closed_form f = closed_form(p);
    statuses admitted = domain_statuses(p);
    if (!admitted)
        admitted = with_underflow<Real>(
            range_statuses<Real>(f.divisor_lg + 1, f.loss_intermediates, {f.dE_lg}, slack<Real>()), f.loss_lowest,
            f.loss_certain);
    std::feclearexcept(FE_DIVBYZERO);
    const Real dE = impact::energy_loss(p.M, p.m, p.v_M, p.v_m, p.eps, form...);
    fail(std::fetestexcept(FE_DIVBYZERO) == 0, "divided by zero: " + p.describe());
    ++t.pairs;
    t.borderline += borderline(admitted) ? 1 : 0;
    const bool refused = is_nan(dE);
    // NaN counted as underflow where the classification admits it, else as out_of_range.
    const status given = !refused ? status::ok : admits(admitted, status::underflow) ? status::underflow : status::out_of_range;
    ++t.by_status[static_cast<std::size_t>(given)];
    t.refused_without_underflow += given == status::underflow && !f.underflows ? 1 : 0;
    fail(refused ? admitted != only(status::ok) : admits(admitted, status::ok),
         std::string(refused ? "NaN where the inputs are valid and in range: " : "a value for refused inputs: ") +
             p.describe());
    if (refused)
        return;
    fail(is_finite(dE) && dE <= 0, "kinetic energy gained or not finite (Eq. 11: dE <= 0): " + p.describe());
    if constexpr (!std::is_same_v<Real, long double>) {
        const W energy_scale = std::max(static_cast<W>(p.M) * static_cast<W>(p.v_M) * static_cast<W>(p.v_M),
                                        static_cast<W>(p.m) * static_cast<W>(p.v_m) * static_cast<W>(p.v_m));
        const W error = ulps_of(dE, f.dE, std::max(std::fabs(f.dE), energy_scale * std::numeric_limits<Real>::epsilon()));
        ++t.measured;
        t.imprecise += error > imprecise_ulps ? 1 : 0;
        t.worst_ulps = std::max(t.worst_ulps, error);
        fail(error <= imprecise_ulps, "ok but " + text(error) + " ulps from the closed form: " + p.describe() + " -> " + text(dE));
    }
}

// A chunk of pairs through collide_line_batch, with and without statuses: bit for bit the
// scalar kernel's velocities, impulse and status (a fixed sphere, and a pair whose values may
// underflow, left by the loop to the scalar kernel).
template <class Real, class... Form>
void check_line_batch(failures& fail, const std::vector<pair_1d<Real>>& pairs, Form... form)
{
    const std::size_t n = pairs.size();
    std::vector<Real> M(n), m(n), eps(n), v_M(n), v_m(n), J(n, Real(7)), v_M_plain, v_m_plain, J_plain(n, Real(7));
    for (std::size_t i = 0; i < n; ++i) {
        M[i] = pairs[i].M;
        m[i] = pairs[i].m;
        eps[i] = pairs[i].eps;
        v_M[i] = pairs[i].v_M;
        v_m[i] = pairs[i].v_m;
    }
    v_M_plain = v_M;
    v_m_plain = v_m;
    std::vector<status> given(n, status::ok);
    // The members in order: count, the inputs, the impulse's own array, the statuses.
    const impact::collide_line_batch_data<Real> with{n,          M.data(), m.data(), v_M.data(), v_m.data(),
                                                     eps.data(), J.data(), given.data()};
    const impact::collide_line_batch_data<Real> without{n,          M.data(),       m.data(), v_M_plain.data(), v_m_plain.data(),
                                                        eps.data(), J_plain.data(), nullptr};
    impact::collide_line_batch(with, form...);
    impact::collide_line_batch(without, form...);
    for (std::size_t i = 0; i < n; ++i) {
        const pair_1d<Real>& p = pairs[i];
        const auto scalar = impact::collide_line(p.M, p.m, p.v_M, p.v_m, p.eps, form...);
        const bool same = given[i] == scalar.status && identical(v_M[i], scalar.v_M) && identical(v_m[i], scalar.v_m) &&
                          identical(J[i], scalar.J) && identical(v_M_plain[i], scalar.v_M) &&
                          identical(v_m_plain[i], scalar.v_m) && identical(J_plain[i], scalar.J);
        fail(same, std::string("collide_line_batch differs from the scalar kernel (") + name(scalar.status) + " against " +
                       name(given[i]) + "): " + p.describe());
    }
}

template <class Real, class... Form>
void sweep_line(std::uint64_t seed, Form... form)
{
    draws d(seed);
    failures fail_line, fail_loss;
    tally line, loss;
    std::vector<pair_1d<Real>> chunk;
    for (std::size_t i = sweep_pairs(); i-- > 0;) {
        const pair_1d<Real> p = draw_pair_1d<Real>(d);
        check_line_pair(fail_line, line, p, form...);
        check_loss_pair(fail_loss, loss, p, form...);
        chunk.push_back(p);
        if (chunk.size() == 4096 || i == 0) {
            check_line_batch(fail_line, chunk, form...);
            chunk.clear();
        }
    }
    const std::string fast = sizeof...(Form) ? ", impact::fast" : "";
    line.report(std::string("collide_line<") + type_name<Real>() + ">" + fast);
    loss.report(std::string("energy_loss<") + type_name<Real>() + ">" + fast + " (NaN counted as underflow or out_of_range)");
    BOOST_TEST(fail_line.count == 0u);
    BOOST_TEST(fail_loss.count == 0u);
    BOOST_TEST(line.by_status[static_cast<std::size_t>(status::ok)] > line.pairs / 20);
    BOOST_TEST(loss.by_status[static_cast<std::size_t>(status::ok)] > loss.pairs / 20);
    BOOST_TEST(line.borderline < line.pairs / 20);
    BOOST_TEST(line.imprecise == 0u);
    BOOST_TEST(loss.imprecise == 0u);
}

// scatter_angle: the angle between the outgoing velocities, in [0, pi/2] (Eq. 14: cos theta
// >= 0); a NaN outside its domain, both speeds positive and finite and eps in [0, 1].
template <class Real>
void sweep_scatter(std::uint64_t seed)
{
    draws d(seed);
    failures fail;
    std::size_t pairs = 0, refused = 0, underflows = 0, imprecise = 0, measured = 0;
    W worst = 0;
    const Real right_angle = static_cast<Real>(1.57079632679489661923132169163975144L);
    for (std::size_t i = sweep_pairs(); i-- > 0; ++pairs) {
        hostile<Real> h{d, hostility(d)};
        const Real v_par = h.velocity(), v_perp = h.velocity(), eps = h.eps();
        const bool valid = positive_and_finite(v_par) && positive_and_finite(v_perp) && eps >= 0 && eps <= 1;
        const Real theta = impact::scatter_angle(v_par, v_perp, eps);
        const std::string where = "v_par " + text(v_par) + ", v_perp " + text(v_perp) + ", eps " + text(eps);
        refused += is_nan(theta) ? 1 : 0;
        if (!valid) {
            fail(is_nan(theta), "a value outside the domain: " + where);
            continue;
        }
        // 7. The documented form atan2(2 v_perp, (1 - eps) v_par): its products, and the angle
        // itself, about 2 v_perp / ((1 - eps) v_par) where that is small.
        const W across = lg(v_perp) + 1, along = lg(v_par) + lg(1 - static_cast<W>(eps));
        const W lowest = lowest_product({{across}, {along}, {across - along}});
        // 6. 2 v_perp overflows (atan2 of an infinity would be finite, but not the angle).
        const statuses admitted =
            beyond<Real>(2 * static_cast<W>(v_perp))
                ? only(status::out_of_range)
                : with_underflow<Real>(only(status::ok), lowest);
        if (is_nan(theta)) {
            underflows += admits(admitted, status::underflow) ? 1 : 0;
            fail(admitted != only(status::ok), "NaN where the inputs are valid and in range: " + where);
            continue;
        }
        fail(admits(admitted, status::ok), "a value where the classification admits no ok: " + where);
        fail(theta >= 0 && theta <= std::nextafter(right_angle, Real(4)), "not in [0, pi/2]: " + where);
        if constexpr (!std::is_same_v<Real, long double>) {  // against atan2 in long double
            const W exact = std::atan2(2 * static_cast<W>(v_perp), (1 - static_cast<W>(eps)) * static_cast<W>(v_par));
            const W error = ulps_of(theta, exact, exact);
            ++measured;
            imprecise += error > imprecise_ulps ? 1 : 0;
            worst = std::max(worst, error);
            fail(error <= imprecise_ulps, "an angle " + text(error) + " ulps from atan2: " + where);
        }
    }
    std::cout << "scatter_angle<" << type_name<Real>() << ">: " << pairs << " inputs, " << refused << " NaN, of which "
              << underflows << " where underflow is admitted; beyond 16 ulps of atan2 " << imprecise << " of " << measured
              << " (worst " << worst << ")\n";
    BOOST_TEST(fail.count == 0u);
    BOOST_TEST(refused > 0u);
    BOOST_TEST(refused < pairs);
}

} // namespace

// ---------------------------------------------------------------------------------
// Exact cases.

namespace {

template <class Real>
struct edges {
    using limits = std::numeric_limits<Real>;
    static constexpr Real inf = limits::infinity();
    static constexpr Real nan = limits::quiet_NaN();
    static constexpr Real tiny = limits::denorm_min();  // 4.9e-324 in double
    static constexpr Real most = limits::max();         // 1.8e308 in double
    static Real huge() { return std::ldexp(Real(1), limits::max_exponent - 3); }  // 2^1021 in double: 4 of it fit
    static Real heaviest() { return std::ldexp(Real(1), limits::max_exponent - 1); }  // 2^1023 in double
    static Real above_one() { return Real(1) + limits::epsilon(); }            // 1 + 2^-52 in double
    static Real below_zero() { return -limits::epsilon() / 2; }                 // about -1.1e-16 in double
    // A mass whose square is below the normal range and whose square root is above it
    // (2^-600 in double: M m = 2^-1200 rounds to 0).
    static Real light() { return std::ldexp(Real(1), -(limits::max_exponent * 3) / 5 - 15); }
    // Two centres this far apart have |r|^2 = 0 in the type (2^-539 in double; 1e-310 too).
    static Real indistinct() { return std::ldexp(Real(1), (limits::min_exponent - limits::digits) / 2 - 2); }
};

template <class Real>
struct line_case {
    Real M, m, v_M, v_m, eps;
    status expected;
    Real v_M_after, v_m_after, J;  // for ok; otherwise the inputs and 0
    const char* why;
};

template <class Real>
std::vector<line_case<Real>> line_cases()
{
    using e = edges<Real>;
    const Real inf = e::inf, nan = e::nan, tiny = e::tiny, huge = e::huge();
    const Real light = std::ldexp(Real(1), -2);
    return {
        {2, 2, 3, -1, 1, status::ok, -1, 3, 8, "equal masses, elastic: velocities exchanged, J = M (v_M - v'_M)"},
        {1, 1, 1, -1, -Real(0), status::ok, 0, 0, 1, "eps = -0 is 0: perfectly inelastic, both at rest"},
        {1, 1, huge, 0, 1, status::ok, 0, huge, huge, "2^1021 (in double), equal masses, elastic: exchanged"},
        {1, 1, tiny, 0, 1, status::underflow, tiny, 0, 0, "a denormal velocity"},
        {1, 1, 1, 0, 1, status::ok, 0, 1, 1, "a velocity 0 is ordinary: equal masses, elastic, exchanged"},
        {e::light(), e::light(), 1, -1, 1, status::underflow, 1, -1, 0, "light masses: M m below the normal range"},
        {1, 1, 1, -1, tiny, status::underflow, 1, -1, 0, "a denormal eps"},
        {e::most, light, 1, -1, 0, status::ok, 1, 1, Real(1) / 2,
         "the largest mass carries a light one along at its own velocity; J = m (v'_m - v_m)"},
        {nan, 1, 1, -1, 1, status::invalid_mass, 1, -1, 0, "NaN mass"},
        {0, 1, 1, -1, 1, status::invalid_mass, 1, -1, 0, "zero mass"},
        {1, -Real(0), 1, -1, 1, status::invalid_mass, 1, -1, 0, "-0 mass"},
        {1, -1, 1, -1, 1, status::invalid_mass, 1, -1, 0, "negative mass"},
        {-inf, 1, 1, -1, 1, status::invalid_mass, 1, -1, 0, "a mass -infinity"},
        {inf, inf, 1, -1, 1, status::invalid_mass, 1, -1, 0, "both masses +infinity"},
        {inf, 1, 1, -1, 1, status::ok, 1, 3, 4,
         "a fixed sphere M (+infinity): m rebounds at v_M + eps (v_M - v_m), J = (1 + eps) m (v_M - v_m)"},
        {1, inf, 1, -1, Real(0.5), status::ok, -2, -1, 3,
         "a fixed sphere m (+infinity): M rebounds at v_m + eps (v_m - v_M), J = (1 + eps) M (v_M - v_m)"},
        {1, 1, 1, -1, e::below_zero(), status::invalid_restitution, 1, -1, 0, "eps just below 0"},
        {1, 1, 1, -1, e::above_one(), status::invalid_restitution, 1, -1, 0, "eps = 1 + epsilon"},
        {1, 1, 1, -1, nan, status::invalid_restitution, 1, -1, 0, "NaN eps"},
        {1, 1, nan, -1, 1, status::non_finite, nan, -1, 0, "NaN velocity"},
        {1, 1, 1, -inf, 1, status::non_finite, 1, -inf, 0, "infinite velocity"},
        {0, 1, nan, -1, nan, status::invalid_mass, nan, -1, 0, "the first guard that fails: the mass"},
        {1, 1, -1, 1, 1, status::separating, -1, 1, 0, "m ahead of M moves away faster"},
        {1, 1, 1, 1, 1, status::separating, 1, 1, 0, "no relative motion"},
        {1, 1, tiny, -tiny, 1, status::underflow, tiny, -tiny, 0, "denormal velocities"},
        {tiny, tiny, 1, -1, 1, status::out_of_range, 1, -1, 0, "denormal masses: M + m below min/epsilon"},
        {e::most, e::most, 1, -1, 1, status::out_of_range, 1, -1, 0, "M + m overflows"},
        {1, 1, e::most, -e::most, 1, status::out_of_range, e::most, -e::most, 0, "v_M - v_m overflows"},
    };
}

template <class Real>
void check_line_cases()
{
    for (const line_case<Real>& c : line_cases<Real>()) {
        BOOST_TEST_CONTEXT(type_name<Real>() << ": " << c.why)
        {
            std::feclearexcept(FE_DIVBYZERO);
            const auto out = impact::collide_line(c.M, c.m, c.v_M, c.v_m, c.eps);
            BOOST_TEST(std::fetestexcept(FE_DIVBYZERO) == 0);
            BOOST_TEST(name(out.status) == name(c.expected));
            BOOST_TEST(identical(out.v_M, c.v_M_after), text(out.v_M) << " against " << text(c.v_M_after));
            BOOST_TEST(identical(out.v_m, c.v_m_after), text(out.v_m) << " against " << text(c.v_m_after));
            BOOST_TEST(identical(out.J, c.J), text(out.J) << " against " << text(c.J));
        }
    }
}

template <class Real>
void check_loss_cases()
{
    using e = edges<Real>;
    const Real nan = e::nan;
    struct loss_case {
        Real M, m, v_M, v_m, eps, dE;
        const char* why;
    };
    const loss_case cases[] = {
        {1, 1, 1, -1, 0, -1, "perfectly inelastic: all the relative motion's energy, M m (2)^2 / (2 (M + m)) = 1"},
        {1, 1, 1, -1, -Real(0), -1, "eps = -0 is 0"},
        {2, 2, 3, -1, 1, 0, "elastic: nothing lost"},
        {1, 1, -1, 1, 0, -1, "the loss does not depend on which sphere is ahead"},
        {nan, 1, 1, -1, 0, nan, "NaN mass"},
        {-1, 1, 1, -1, 0, nan, "negative mass"},
        {0, 1, 1, -1, 0, nan, "zero mass"},
        {1, 1, 1, -1, e::above_one(), nan, "eps = 1 + epsilon"},
        {1, 1, 1, -1, e::below_zero(), nan, "eps just below 0"},
        {1, 1, e::inf, -1, 0, nan, "infinite velocity"},
        {e::tiny, e::tiny, 1, -1, 0, nan, "denormal masses: 2 (M + m) below min/epsilon"},
        {e::light(), e::light(), 1, -1, 0, nan, "light masses: M m below the normal range (underflow)"},
        {1, 1, e::tiny, 0, 0, nan, "a denormal velocity (underflow)"},
        {1, 1, 1, 0, 0, Real(-0.25), "a velocity 0 is ordinary: M m (1)^2 / (2 (M + m)) = 1/4"},
        {e::most, e::most, 1, -1, 0, nan, "M + m overflows"},
        {1, 1, e::most, -e::most, 0, nan, "v_M - v_m overflows"},
    };
    for (const loss_case& c : cases) {
        BOOST_TEST_CONTEXT(type_name<Real>() << ": " << c.why)
        {
            std::feclearexcept(FE_DIVBYZERO);
            const Real dE = impact::energy_loss(c.M, c.m, c.v_M, c.v_m, c.eps);
            BOOST_TEST(std::fetestexcept(FE_DIVBYZERO) == 0);
            BOOST_TEST((is_nan(c.dE) ? is_nan(dE) : dE == c.dE), text(dE) << " against " << text(c.dE));
        }
    }
}

template <class Real>
void check_scatter_cases()
{
    using e = edges<Real>;
    const Real right_angle = static_cast<Real>(1.57079632679489661923132169163975144L);
    struct scatter_case {
        Real v_par, v_perp, eps, theta;
        const char* why;
    };
    const scatter_case cases[] = {
        {1, Real(0.5), 1, right_angle, "elastic: a right angle"},
        {1, e::tiny, 0, e::nan, "a denormal v_perp (underflow)"},
        {1, e::most / 4, 0, right_angle, "a quarter of the largest v_perp: grazing, tan theta beyond the range"},
        {1, e::most, 0, e::nan, "the largest v_perp: 2 v_perp overflows (out_of_range)"},
        {e::tiny, 1, 0, e::nan, "a denormal v_par (underflow)"},
        {1, 1, 1, right_angle, "eps = 1: (1 - eps) v_par is 0, as it may be"},
        {1, 0, 0, e::nan, "v_perp = 0: outside the domain (positive)"},
        {-1, 1, 0, e::nan, "negative v_par"},
        {1, e::inf, 0, e::nan, "infinite v_perp"},
        {e::nan, 1, 0, e::nan, "NaN v_par"},
        {1, 1, e::above_one(), e::nan, "eps = 1 + epsilon"},
        {1, 1, e::below_zero(), e::nan, "eps just below 0"},
        {1, 1, e::nan, e::nan, "NaN eps"},
    };
    for (const scatter_case& c : cases) {
        BOOST_TEST_CONTEXT(type_name<Real>() << ": " << c.why)
        {
            const Real theta = impact::scatter_angle(c.v_par, c.v_perp, c.eps);
            if (is_nan(c.theta))
                BOOST_TEST(is_nan(theta), text(theta));
            else  // within an ulp: atan2 of the C library, correctly rounded or nearly
                BOOST_TEST(std::fabs(theta - c.theta) <= std::max(c.theta * std::numeric_limits<Real>::epsilon(), e::tiny),
                           text(theta) << " against " << text(c.theta));
        }
    }
}

// collide in the plane z = 0 (and in 2D): head-on along x, M at x = r to the right of m.
template <class Real, std::size_t N>
struct collide_case {
    Real M, m, eps, r, offset_y;  // C_M = (r, offset_y), C_m = 0
    Real v_Mx, v_mx;              // velocities along x
    status expected;
    Real v_Mx_after, v_mx_after;  // for ok
    const char* why;
};

template <class Real>
std::vector<collide_case<Real, 2>> collide_cases()
{
    using e = edges<Real>;
    const Real inf = e::inf, nan = e::nan, tiny = e::tiny, huge = e::huge();
    const int low = std::numeric_limits<Real>::min_exponent;
    // Centres 2^(low/2) apart, |r|^2 = 2^low: a normal number, but (M + m)|r|^2 is below
    // min/epsilon for masses of 1, and above it for masses of 2^digits.
    const Real close = std::ldexp(Real(1), low / 2), heavy = std::ldexp(Real(1), std::numeric_limits<Real>::digits);
    // Nearer still, |r|^2 is subnormal; masses of 2^(20 - low/2) keep (M + m)|r|^2 above min/epsilon.
    const Real nearer = std::ldexp(Real(1), low / 2 - 8), apart = std::ldexp(Real(1), 20 - low / 2);
    return {
        {1, 1, 1, 1, 0, -1, 1, status::ok, 1, -1, "equal masses, elastic, head-on: exchanged"},
        {1, 1, 0, 1, 0, -1, 1, status::ok, 0, 0, "perfectly inelastic: both at rest"},
        {e::heaviest(), 1, 1, 1, 0, -1, 1, status::ok, -1, -3, "a light sphere bounces off a heavy one at 2V - v"},
        {1, 1, 1, 1, 0, -huge, huge, status::ok, huge, -huge, "velocities of 2^1021 (in double) exchanged"},
        {1, 1, 1, 1, 0, -tiny, 0, status::underflow, -tiny, 0, "a denormal velocity"},
        {1, 1, 1, 1, 0, -1, 0, status::ok, 0, -1, "a velocity 0 is ordinary: exchanged"},
        {e::light(), e::light(), 1, 1, 0, -1, 1, status::ok, 1, -1, "light masses: k m is a ratio of masses, ordinary"},
        {apart, apart, 1, nearer, 0, -1, 1, status::underflow, -1, 1,
         "centres 2^(min_exponent/2 - 8) apart: |r|^2 below the normal range (the divisor in range)"},
        {heavy, heavy, 1, close, 0, -1, 1, status::ok, 1, -1, "centres 2^(min_exponent/2) apart, heavy masses"},
        {1, 1, 1, close, 0, -1, 1, status::out_of_range, -1, 1, "the same centres, masses of 1: divisor too small"},
        {1, 1, 1, 0, 0, -1, 1, status::coincident_centres, -1, 1, "coincident centres"},
        {1, 1, 1, e::indistinct(), 0, -1, 1, status::coincident_centres, -1, 1, "centres 2^-539 apart in double: |r|^2 = 0"},
        {1, 1, 1, tiny, 0, -1, 1, status::coincident_centres, -1, 1, "centres a denormal apart"},
        {1, 1, 1, 1, 0, -e::most, e::most, status::out_of_range, -e::most, e::most, "v_M - v_m overflows"},
        {e::most, e::most, 1, 1, 0, -1, 1, status::out_of_range, -1, 1, "M + m overflows"},
        {tiny, tiny, 1, 1, 0, -1, 1, status::out_of_range, -1, 1, "denormal masses"},
        {nan, 1, 1, 1, 0, -1, 1, status::invalid_mass, -1, 1, "NaN mass"},
        {1, 0, 1, 1, 0, -1, 1, status::invalid_mass, -1, 1, "zero mass"},
        {-1, 1, 1, 1, 0, -1, 1, status::invalid_mass, -1, 1, "negative mass"},
        {1, -inf, 1, 1, 0, -1, 1, status::invalid_mass, -1, 1, "a mass -infinity"},
        {inf, inf, 1, 1, 0, -1, 1, status::invalid_mass, -1, 1, "both masses +infinity"},
        {inf, 1, 1, 1, 0, -1, 1, status::ok, -1, -3, "a fixed sphere M (+infinity): m rebounds at 2 v_M - v_m"},
        {1, inf, Real(0.5), 1, 0, -1, 1, status::ok, 2, 1,
         "a fixed sphere m (+infinity): M rebounds at v_m + eps (v_m - v_M)"},
        {1, 1, e::below_zero(), 1, 0, -1, 1, status::invalid_restitution, -1, 1, "eps just below 0"},
        {1, 1, e::above_one(), 1, 0, -1, 1, status::invalid_restitution, -1, 1, "eps = 1 + epsilon"},
        {1, 1, nan, 1, 0, -1, 1, status::invalid_restitution, -1, 1, "NaN eps"},
        {1, 1, 1, nan, 0, -1, 1, status::non_finite, -1, 1, "NaN centre"},
        {1, 1, 1, 1, inf, -1, 1, status::non_finite, -1, 1, "infinite centre"},
        {1, 1, 1, 1, 0, nan, 1, status::non_finite, nan, 1, "NaN velocity"},
        {1, 1, 1, 1, 0, -1, -inf, status::non_finite, -1, -inf, "infinite velocity"},
        {1, 1, 1, 1, 0, 1, -1, status::separating, 1, -1, "moving apart"},
        {1, 1, 1, 1, 0, 1, 1, status::separating, 1, 1, "no relative motion"},
        {1, 1, 1, 1, e::most, -1, 1, status::out_of_range, -1, 1, "|r|^2 overflows"},
    };
}

template <class Real, std::size_t N>
void check_collide_cases()
{
    for (const collide_case<Real, 2>& c : collide_cases<Real>()) {
        BOOST_TEST_CONTEXT(type_name<Real>() << ", " << N << "D: " << c.why)
        {
            std::array<Real, N> C_M{}, C_m{}, v_M{}, v_m{}, v_M_after{}, v_m_after{};
            C_M[0] = c.r;
            C_M[1] = c.offset_y;
            v_M[0] = c.v_Mx;
            v_m[0] = c.v_mx;
            v_M_after[0] = c.v_Mx_after;
            v_m_after[0] = c.v_mx_after;
            if (N == 3)  // a component across the line of action, which the collision keeps
                v_M[N - 1] = v_M_after[N - 1] = v_m[N - 1] = v_m_after[N - 1] = Real(0.5);
            std::feclearexcept(FE_DIVBYZERO);
            const auto out = impact::collide(c.M, c.m, C_M, C_m, v_M, v_m, c.eps);
            BOOST_TEST(std::fetestexcept(FE_DIVBYZERO) == 0);
            BOOST_TEST(name(out.status) == name(c.expected));
            BOOST_TEST(identical(out.v_M, v_M_after), text(out.v_M) << " against " << text(v_M_after));
            BOOST_TEST(identical(out.v_m, v_m_after), text(out.v_m) << " against " << text(v_m_after));
        }
    }
}

} // namespace

BOOST_AUTO_TEST_CASE(collide_line_refuses_hostile_inputs_with_a_status_and_resolves_the_edges_it_can)
{
    check_line_cases<float>();
    check_line_cases<double>();
    check_line_cases<long double>();
}

BOOST_AUTO_TEST_CASE(energy_loss_is_nan_outside_its_domain_and_exact_at_its_edges)
{
    check_loss_cases<float>();
    check_loss_cases<double>();
    check_loss_cases<long double>();
}

BOOST_AUTO_TEST_CASE(scatter_angle_is_nan_outside_its_domain_and_right_at_its_edges)
{
    check_scatter_cases<float>();
    check_scatter_cases<double>();
    check_scatter_cases<long double>();
}

BOOST_AUTO_TEST_CASE(collide_refuses_hostile_inputs_with_a_status_and_resolves_the_edges_it_can)
{
    check_collide_cases<float, 2>();
    check_collide_cases<double, 2>();
    check_collide_cases<long double, 2>();
    check_collide_cases<float, 3>();
    check_collide_cases<double, 3>();
    check_collide_cases<long double, 3>();
}

// ---------------------------------------------------------------------------------
// The sweep: the seeds are fixed, the count is IMPACT_SWEEP_PAIRS (20 000 by default).

BOOST_AUTO_TEST_CASE(a_randomized_sweep_of_hostile_pairs_keeps_every_invariant_in_2d)
{
    sweep_collide<float, 2>(1701);
    sweep_collide<double, 2>(1702);
    sweep_collide<long double, 2>(1703);
}

BOOST_AUTO_TEST_CASE(a_randomized_sweep_of_hostile_pairs_keeps_every_invariant_in_3d)
{
    sweep_collide<float, 3>(1711);
    sweep_collide<double, 3>(1712);
    sweep_collide<long double, 3>(1713);
}

BOOST_AUTO_TEST_CASE(a_randomized_sweep_of_hostile_pairs_keeps_every_invariant_along_the_line)
{
    sweep_line<float>(1721);
    sweep_line<double>(1722);
    sweep_line<long double>(1723);
}

// The fast forms (impact::fast) keep the same contract: the same sweeps, the same
// classification, every resolved collision within the same 16 ulps of the closed form.
BOOST_AUTO_TEST_CASE(the_fast_forms_keep_every_invariant_of_the_sweep_in_2d_and_3d)
{
    sweep_collide<float, 2>(1731, impact::fast);
    sweep_collide<double, 2>(1732, impact::fast);
    sweep_collide<long double, 2>(1733, impact::fast);
    sweep_collide<float, 3>(1741, impact::fast);
    sweep_collide<double, 3>(1742, impact::fast);
    sweep_collide<long double, 3>(1743, impact::fast);
}

// A batch resolves a block of 8 ordinary pairs at once (the loop's sure blocks), and leaves a
// block with one pair that needs more to the loop and the scalar kernel: every lane of such a
// block, with every input in turn made hostile, is the scalar kernel's bit for bit. (A NaN
// lost in a tree of minima or maxima would pass for an ordinary value in one lane and not in
// another.)
template <class Real, std::size_t N>
pair_nd<Real, N> ordinary_pair(std::size_t i)
{
    pair_nd<Real, N> p{};
    const Real a = Real(1) + Real(i % 5) / Real(8), b = Real(i % 3) / Real(4);
    p.M = Real(1.5) * a;
    p.m = Real(0.75) + b;
    p.eps = Real(0.25) + b / Real(2);
    for (std::size_t k = 0; k < N; ++k) {
        p.C_M[k] = Real(k == 0 ? -1 : 0.25) * a;
        p.C_m[k] = Real(k == 0 ? 1 : -0.5) + b;
        p.v_M[k] = Real(k == 0 ? 2 : 0.5) * a;  // towards m
        p.v_m[k] = Real(k == 0 ? -1 : 0.125) - b;
    }
    return p;
}

template <class Real, std::size_t N>
Real& input_of(pair_nd<Real, N>& p, std::size_t f)
{
    if (f < 3)
        return f == 0 ? p.M : f == 1 ? p.m : p.eps;
    f -= 3;
    std::array<Real, N>* vectors[] = {&p.C_M, &p.C_m, &p.v_M, &p.v_m};
    return (*vectors[f / N])[f % N];
}

template <class Real, std::size_t N, class... Form>
void check_blocks_with_one_hostile_lane(failures& fail, Form... form)
{
    using limits = std::numeric_limits<Real>;
    const Real hostile[] = {limits::quiet_NaN(), limits::infinity(), -limits::infinity(), limits::denorm_min(),
                            limits::min(), limits::max(), Real(0), -Real(0), std::ldexp(Real(1), limits::min_exponent / 2),
                            -Real(1)};
    std::vector<pair_nd<Real, N>> pairs(24);
    for (std::size_t i = 0; i < pairs.size(); ++i)
        pairs[i] = ordinary_pair<Real, N>(i);
    check_batch(fail, pairs, form...);  // three sure blocks
    for (std::size_t lane : {8, 11, 15})
        for (std::size_t f = 0; f < 3 + 4 * N; ++f)
            for (Real h : hostile) {
                std::vector<pair_nd<Real, N>> changed = pairs;
                input_of(changed[lane], f) = h;
                check_batch(fail, changed, form...);
            }
    for (std::size_t lane : {8, 15}) {
        std::vector<pair_nd<Real, N>> separating = pairs, coincident = pairs;
        std::swap(separating[lane].v_M, separating[lane].v_m);
        coincident[lane].C_m = coincident[lane].C_M;
        check_batch(fail, separating, form...);
        check_batch(fail, coincident, form...);
    }
}

BOOST_AUTO_TEST_CASE(a_block_with_one_hostile_lane_is_the_scalar_kernels_in_every_lane)
{
    failures fail;
    check_blocks_with_one_hostile_lane<float, 2>(fail);
    check_blocks_with_one_hostile_lane<double, 2>(fail);
    check_blocks_with_one_hostile_lane<double, 3>(fail);
    check_blocks_with_one_hostile_lane<long double, 2>(fail);
    check_blocks_with_one_hostile_lane<float, 2>(fail, impact::fast);
    check_blocks_with_one_hostile_lane<double, 2>(fail, impact::fast);
    check_blocks_with_one_hostile_lane<double, 3>(fail, impact::fast);
    BOOST_TEST(fail.count == 0u);
}

// 8 ordinary pairs in 2D, a block of the batch loop.
std::array<pair_nd<double, 2>, 8> ordinary_block()
{
    std::array<pair_nd<double, 2>, 8> pairs;
    for (std::size_t i = 0; i < pairs.size(); ++i)
        pairs[i] = ordinary_pair<double, 2>(i);
    return pairs;
}

// The sure block of collide_batch in 2D on 8 pairs (the fast form's with impact::fast):
// whether it resolved them, and whether it left their velocities as they were; where it
// resolved them, every lane is the scalar kernel's, bit for bit, and ok. Compiled as the
// kernels' own block loops are (between IMPACT_PRECISE_BEGIN and _END): inlined into code
// compiled with the caller's flags, GCC compiles the sure block with them, -ffast-math's included.
IMPACT_PRECISE_BEGIN
template <class... Form>
std::pair<bool, bool> sure_block(const std::array<pair_nd<double, 2>, 8>& p, Form... form)
{
    std::array<double, 8> M, m, eps, C_Mx, C_My, C_mx, C_my;
    std::array<std::array<double, 8>, 4> v;
    for (std::size_t i = 0; i < 8; ++i) {
        M[i] = p[i].M, m[i] = p[i].m, eps[i] = p[i].eps;
        C_Mx[i] = p[i].C_M[0], C_My[i] = p[i].C_M[1], C_mx[i] = p[i].C_m[0], C_my[i] = p[i].C_m[1];
        v[0][i] = p[i].v_M[0], v[1][i] = p[i].v_M[1], v[2][i] = p[i].v_m[0], v[3][i] = p[i].v_m[1];
    }
    const auto before = v;
    std::array<status, 8> s{};
    bool resolved;
    if constexpr (sizeof...(Form) > 0)
        resolved = impact::detail::collide_batch_2d_fast_sure<double>(M.data(), m.data(), C_Mx.data(), C_My.data(), C_mx.data(), C_my.data(),
                                                                            v[0].data(), v[1].data(), v[2].data(), v[3].data(), eps.data(), s.data());
    else
        resolved = impact::detail::collide_batch_2d_sure<double>(M.data(), m.data(), C_Mx.data(), C_My.data(), C_mx.data(), C_my.data(),
                                                                       v[0].data(), v[1].data(), v[2].data(), v[3].data(), eps.data(), s.data());
    bool unchanged = true;
    for (std::size_t a = 0; a < 4; ++a)
        for (std::size_t i = 0; i < 8; ++i)
            unchanged = unchanged && identical(v[a][i], before[a][i]);
    for (std::size_t i = 0; resolved && i < 8; ++i) {
        const auto out = impact::collide(p[i].M, p[i].m, p[i].C_M, p[i].C_m, p[i].v_M, p[i].v_m, p[i].eps, form...);
        BOOST_TEST((out.status == status::ok && s[i] == status::ok));
        BOOST_TEST((identical(out.v_M[0], v[0][i]) && identical(out.v_M[1], v[1][i]) && identical(out.v_m[0], v[2][i]) &&
                    identical(out.v_m[1], v[3][i])));
    }
    return {resolved, unchanged};
}
IMPACT_PRECISE_END

BOOST_AUTO_TEST_CASE(a_block_of_ordinary_pairs_is_resolved_at_once_and_a_nan_anywhere_leaves_it)
{
    const std::array<pair_nd<double, 2>, 8> pairs = ordinary_block();
    const auto [resolved, unchanged] = sure_block(pairs);
    BOOST_TEST(resolved);
    BOOST_TEST(!unchanged);
    std::size_t left = 0;  // blocks left to the loop, as they were
    for (std::size_t lane = 0; lane < 8; ++lane)
        for (std::size_t f = 0; f < 11; ++f) {
            auto changed = pairs;
            input_of(changed[lane], f) = std::numeric_limits<double>::quiet_NaN();
            const auto [taken, kept] = sure_block(changed);
            left += !taken && kept ? 1 : 0;
        }
    BOOST_TEST(left == 88u);
}

// The sure block's range (collide_batch_2d_sure_k): 0, or a magnitude within [2^-k, 2^k], of
// each value it tests. At its lower end, 2^-k is in and the double just below it is not;
// above 2^k, nothing is (at 2^k itself, the block may leave a pair it could resolve: its sum
// of squares then exceeds 2^2k, where the block tests that). The accurate block tests every
// input: tried on v_Mx, which keeps the pair approaching at every one of these values.
BOOST_AUTO_TEST_CASE(the_sure_blocks_range_ends_where_the_loops_does)
{
    constexpr int k = impact::detail::collide_batch_2d_sure_k<double>;
    static_assert(k > 0 && k == impact::detail::collide_batch_2d_k<double>);
    const double lowest = std::ldexp(1.0, -k), highest = std::ldexp(1.0, k);
    const std::array<pair_nd<double, 2>, 8> pairs = ordinary_block();
    const auto resolved_with = [&](double v_Mx) {
        auto changed = pairs;
        changed[5].v_M[0] = v_Mx;
        const auto [taken, kept] = sure_block(changed);
        BOOST_TEST(taken != kept);  // resolved, or left as it was
        return taken;
    };
    BOOST_TEST(resolved_with(0.0));
    BOOST_TEST(resolved_with(-0.0));
    BOOST_TEST(resolved_with(lowest));
    BOOST_TEST(!resolved_with(std::nextafter(lowest, 0.0)));
    BOOST_TEST(!resolved_with(std::numeric_limits<double>::denorm_min()));
    BOOST_TEST(resolved_with(highest / 2));
    BOOST_TEST(!resolved_with(std::nextafter(highest, 2 * highest)));
    BOOST_TEST(!resolved_with(std::numeric_limits<double>::infinity()));
}

// A mass not above 0 and an eps below 0 leave both sure blocks (where they test the range by
// the bits, the masses' and eps's signs are tested by them: 0, -0 and negatives outside), an
// eps of 0 or 1 and a mass at the range's ends do not; -0 for eps, which the domain admits,
// is resolved by the block where it compares (and then as the scalar kernel resolves it) or
// left to the loop where it reads bits.
BOOST_AUTO_TEST_CASE(a_mass_not_above_0_or_an_eps_below_0_leaves_the_sure_blocks)
{
    const std::array<pair_nd<double, 2>, 8> pairs = ordinary_block();
    const auto resolved_with = [&](auto change, auto... form) {
        auto changed = pairs;
        change(changed[3]);
        const auto [taken, kept] = sure_block(changed, form...);
        BOOST_TEST(taken != kept);
        return taken;
    };
    const auto both = [&](auto change) {
        const bool accurate = resolved_with(change), fast = resolved_with(change, impact::fast);
        BOOST_TEST(accurate == fast);
        return accurate;
    };
    const double tiny = std::ldexp(1.0, -impact::detail::collide_batch_2d_sure_k<double>);
    for (const double mass : {0.0, -0.0, -1.0, -tiny, -std::numeric_limits<double>::infinity()}) {
        BOOST_TEST(!both([&](pair_nd<double, 2>& p) { p.M = mass; }));
        BOOST_TEST(!both([&](pair_nd<double, 2>& p) { p.m = mass; }));
    }
    for (const double eps : {-0.25, -tiny, -std::numeric_limits<double>::denorm_min()})
        BOOST_TEST(!both([&](pair_nd<double, 2>& p) { p.eps = eps; }));
    both([](pair_nd<double, 2>& p) { p.eps = -0.0; });
    BOOST_TEST(both([](pair_nd<double, 2>& p) { p.eps = 0.0; }));
    BOOST_TEST(both([](pair_nd<double, 2>& p) { p.eps = 1.0; }));
    BOOST_TEST(!both([](pair_nd<double, 2>& p) { p.eps = std::nextafter(1.0, 2.0); }));
    BOOST_TEST(both([&](pair_nd<double, 2>& p) { p.M = tiny; }));
    BOOST_TEST(!resolved_with([&](pair_nd<double, 2>& p) { p.M = std::nextafter(tiny, 0.0); }));
    BOOST_TEST(!resolved_with([&](pair_nd<double, 2>& p) { p.m = std::nextafter(tiny, 0.0); }));
    BOOST_TEST(both([&](pair_nd<double, 2>& p) { p.m = std::ldexp(1.0, impact::detail::collide_batch_2d_sure_k<double> - 1); }));
}

// The fast block tests the masses, eps, and the differences of centres and of velocities
// (range_cut: the arithmetic reads the centres and velocities through them, and the
// velocities again only to add the impulses to them, the results then tested as the loop
// tests them): a velocity below the range is resolved where its difference is in range, as
// the scalar kernel resolves it, and so are two velocities of 2^(k+1) or of the largest
// double whose difference is 0; a difference of centres at the range's lower end is in, the
// power of 2 below it out; a velocity whose difference passes 2^k, or infinite, or NaN,
// leaves the block.
BOOST_AUTO_TEST_CASE(the_fast_sure_block_tests_differences_of_inputs)
{
    constexpr int k = impact::detail::collide_batch_2d_fast_sure_k<double>;
    static_assert(k > impact::detail::collide_batch_2d_fast_k<double>);  // (2^-k: the analysis's own bound)
    const double lowest = std::ldexp(1.0, -k), highest = std::ldexp(1.0, k);
    const std::array<pair_nd<double, 2>, 8> pairs = ordinary_block();
    const auto resolved_with = [&](auto change) {
        auto changed = pairs;
        change(changed[5]);
        const auto [taken, kept] = sure_block(changed, impact::fast);
        BOOST_TEST(taken != kept);
        return taken;
    };
    BOOST_TEST(resolved_with([](pair_nd<double, 2>&) {}));
    BOOST_TEST(resolved_with([](pair_nd<double, 2>& p) { p.v_M[0] = std::numeric_limits<double>::denorm_min(); }));
    BOOST_TEST(resolved_with([](pair_nd<double, 2>& p) { p.v_m[1] = -std::numeric_limits<double>::min() / 4; }));
    // C_My - C_my exactly: the pair still approaches along x.
    BOOST_TEST(resolved_with([&](pair_nd<double, 2>& p) { p.C_M[1] = lowest, p.C_m[1] = 0; }));
    BOOST_TEST(!resolved_with([&](pair_nd<double, 2>& p) { p.C_M[1] = lowest / 2, p.C_m[1] = 0; }));
    BOOST_TEST(resolved_with([&](pair_nd<double, 2>& p) { p.C_M[1] = 0, p.C_m[1] = 0; }));
    BOOST_TEST(resolved_with([&](pair_nd<double, 2>& p) { p.M = lowest; }));
    BOOST_TEST(!resolved_with([&](pair_nd<double, 2>& p) { p.M = std::nextafter(lowest, 0.0); }));
    BOOST_TEST(!resolved_with([&](pair_nd<double, 2>& p) { p.v_M[0] = std::nextafter(highest, 2 * highest); }));
    BOOST_TEST(!resolved_with([](pair_nd<double, 2>& p) { p.v_M[1] = std::numeric_limits<double>::infinity(); }));
    BOOST_TEST(!resolved_with([](pair_nd<double, 2>& p) { p.v_m[0] = std::numeric_limits<double>::quiet_NaN(); }));
    BOOST_TEST(!resolved_with([](pair_nd<double, 2>& p) { p.C_m[0] = -std::numeric_limits<double>::infinity(); }));
    BOOST_TEST(resolved_with([&](pair_nd<double, 2>& p) { p.v_M[1] = 2 * highest, p.v_m[1] = 2 * highest; }));
    BOOST_TEST(resolved_with([](pair_nd<double, 2>& p) {
        p.v_M[1] = std::numeric_limits<double>::max(), p.v_m[1] = std::numeric_limits<double>::max();
    }));
}

BOOST_AUTO_TEST_CASE(the_fast_forms_keep_every_invariant_of_the_sweep_along_the_line)
{
    sweep_line<float>(1751, impact::fast);
    sweep_line<double>(1752, impact::fast);
    sweep_line<long double>(1753, impact::fast);
}

BOOST_AUTO_TEST_CASE(a_randomized_sweep_of_hostile_speeds_gives_an_angle_or_nan)
{
    sweep_scatter<float>(1731);
    sweep_scatter<double>(1732);
    sweep_scatter<long double>(1733);
}

// ---------------------------------------------------------------------------------
// Denormals flushed to zero: a program linked with -ffast-math (crtfastmath.o) starts with
// the processor's flush-to-zero and denormals-are-zero modes set on x86, and no pragma
// undoes that. The contract there: a denormal input counts as a zero of its sign (a denormal
// mass is not positive: invalid_mass), refused velocities still come back bit for bit as
// given, and a value of the arithmetic that would have been denormal is 0 and refused as
// underflow. The cases above are written for IEEE arithmetic: under a build that sets the
// modes (test_kernels_hostile_fast_math) they run with the modes cleared, and this
// case sets them itself in every build.

#ifdef IMPACT_TEST_MXCSR
namespace {

constexpr unsigned flush_modes = 0x8040;  // MXCSR: flush to zero (bit 15), denormals are zero (bit 6)

// Clears the modes for the cases written for IEEE arithmetic, saying when they were set.
struct ieee_arithmetic {
    ieee_arithmetic()
    {
        if (_mm_getcsr() & flush_modes) {
            std::cout << "denormals were flushed to zero at start (crtfastmath.o): cleared for the IEEE cases\n";
            _mm_setcsr(_mm_getcsr() & ~flush_modes);
        }
    }
};

struct flushed_denormals {
    unsigned saved = _mm_getcsr();
    flushed_denormals() { _mm_setcsr(saved | flush_modes); }
    ~flushed_denormals() { _mm_setcsr(saved); }
};

} // namespace

BOOST_TEST_GLOBAL_FIXTURE(ieee_arithmetic);

BOOST_AUTO_TEST_CASE(with_denormals_flushed_a_denormal_input_counts_as_zero)
{
    using limits = std::numeric_limits<double>;
    const double tiny = limits::denorm_min(), small = 4 * limits::min() / 3;  // small: normal, a denormal apart
    struct pair2 {
        double M, m;
        std::array<double, 2> C_M, C_m, v_M, v_m;
        double eps;
    };
    // An approaching pair with one denormal input each, and one whose product underflows.
    std::vector<pair2> pairs{
        {1, 2, {1, 0}, {0, 0}, {-1, tiny}, {0, -tiny}, 0.5},
        {tiny, 2, {1, 0}, {0, 0}, {-1, 0}, {0, 0}, 0.5},
        {1, 2, {1, tiny}, {0, 0}, {-1, 0}, {0, 0}, 0.5},
        {1, 2, {1, 0}, {0, 0}, {-1, 0}, {0, 0}, tiny},
        {1, 2, {small, 0}, {0, 0}, {-small, 0}, {0, 0}, 0.5},
        {1, 2, {tiny, 0}, {0, 0}, {-1, 0}, {0, 0}, 0.5},
    };
    // Each pair with its denormals made zeros of their sign, before the modes are set (with
    // denormals read as zero, a test of x != 0 would leave them as they are).
    const auto zeroed = [](double x) { return is_finite(x) && x != 0 && std::fabs(x) < limits::min() ? std::copysign(0.0, x) : x; };
    std::vector<pair2> as_zeros;
    for (const pair2& p : pairs) {
        pair2 z = p;
        z.M = zeroed(p.M);
        z.m = zeroed(p.m);
        z.eps = zeroed(p.eps);
        for (std::size_t k = 0; k < 2; ++k) {
            z.C_M[k] = zeroed(p.C_M[k]);
            z.C_m[k] = zeroed(p.C_m[k]);
            z.v_M[k] = zeroed(p.v_M[k]);
            z.v_m[k] = zeroed(p.v_m[k]);
        }
        as_zeros.push_back(z);
    }
    BOOST_TEST_REQUIRE(as_zeros[1].M == 0.0);  // the zeros were made while denormals were still read
    const flushed_denormals modes;
    for (std::size_t n = 0; n < pairs.size(); ++n) {
        const pair2& p = pairs[n];
        const pair2& z = as_zeros[n];
        const auto out = impact::collide(p.M, p.m, p.C_M, p.C_m, p.v_M, p.v_m, p.eps);
        const auto as_zero = impact::collide(z.M, z.m, z.C_M, z.C_m, z.v_M, z.v_m, z.eps);
        BOOST_TEST_MESSAGE("flushed: " << name(out.status));
        BOOST_TEST(name(out.status) == name(as_zero.status));
        if (n == 1)  // a denormal mass is a zero mass, not positive
            BOOST_TEST(name(out.status) == "invalid_mass");
        if (out.status == status::ok) {
            BOOST_TEST(identical(out.v_M, as_zero.v_M));
            BOOST_TEST(identical(out.v_m, as_zero.v_m));
        } else {
            BOOST_TEST(identical(out.v_M, p.v_M));
            BOOST_TEST(identical(out.v_m, p.v_m));
        }
        // The batch loop as the scalar kernel.
        impact::collide_batch_arrays<double, 2> a(1);
        a.M()[0] = p.M;
        a.m()[0] = p.m;
        a.eps()[0] = p.eps;
        for (std::size_t k = 0; k < 2; ++k) {
            a.C_M(k)[0] = p.C_M[k];
            a.C_m(k)[0] = p.C_m[k];
            a.v_M(k)[0] = p.v_M[k];
            a.v_m(k)[0] = p.v_m[k];
        }
        impact::collide_batch(a.data());
        BOOST_TEST(name(a.status()[0]) == name(out.status));
        for (std::size_t k = 0; k < 2; ++k) {
            BOOST_TEST(identical(a.v_M(k)[0], out.v_M[k]));
            BOOST_TEST(identical(a.v_m(k)[0], out.v_m[k]));
        }
    }
    // A value that would be denormal is 0: the pair is refused, as IEEE arithmetic refuses it
    // with underflow, or for the zero (|r|^2 = 0: coincident_centres; (v_M - v_m).r = 0:
    // separating), its velocities as given.
    using vec = std::array<double, 2>;
    for (const auto& [r, v] : {std::pair{1e-160, -1.0}, std::pair{1e-100, -1e-210}}) {
        const vec v_M{v, 0}, v_m{0, 0};
        const auto out = impact::collide(1.0, 2.0, vec{r, 0}, vec{0, 0}, v_M, v_m, 0.5);
        BOOST_TEST_MESSAGE("flushed: " << name(out.status));
        BOOST_TEST((out.status == status::underflow || out.status == status::coincident_centres ||
                    out.status == status::separating));
        BOOST_TEST(identical(out.v_M, v_M));
        BOOST_TEST(identical(out.v_m, v_m));
    }
}
#endif

IMPACT_PRECISE_END
