// Fixed spheres (issue 21, "Fixed obstacles"): a mass of +infinity given to the generated
// kernels collide_line, collide (2D, 3D) and collide_rough (2D), which then compute the
// limit of their outputs as that mass grows without bound (`fixed = ["M", "m"]` in the
// derivation files). Checked here against closed forms typed from the physics, not read
// from Impact:
//   smooth, M fixed: v'_M = v_M; along n, v'_m.n = v_M.n - eps (v_m - v_M).n (Newton's law
//     of restitution, Eq. 5, against a body that does not move); across n, v_m unchanged;
//     along the line (Eq. 8), J = (1 + eps) m (v_M - v_m);
//   rough, M fixed (Walton's model with 1/M = 0): J_n = (1 + eps) m g_n,
//     1/m_t = 1/m + 1/(q_m m), J_t = min((1 + beta) m_t |g_t|, mu J_n) sign(g_t);
//     v'_M = v_M, w'_M = w_M, v'_m = v_m + (J_n n + J_t t)/m, w'_m = w_m - J_t/(q_m m R_m);
// and the same with the spheres' roles exchanged. A huge finite mass (1e300) gives the
// same results within a few ulps; two infinite masses, -infinity, NaN and 0 stay
// invalid_mass with the velocities returned bit for bit; the batch loops give the scalar
// results bit for bit (a fixed sphere is resolved by the scalar kernel, `settle`).
#define BOOST_TEST_MODULE test_fixed_kernels
#include <boost/test/unit_test.hpp>

#include <impact/collide_2d.hpp>
#include <impact/collide_3d.hpp>
#include <impact/collide_line.hpp>
#include <impact/collide_rough_2d.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

namespace {

const double inf = std::numeric_limits<double>::infinity();
const double nan = std::numeric_limits<double>::quiet_NaN();
const double eps_double = std::numeric_limits<double>::epsilon();

bool same_bits(double a, double b)
{
    return std::memcmp(&a, &b, sizeof a) == 0;
}

template <std::size_t N>
bool same_bits(const std::array<double, N>& a, const std::array<double, N>& b)
{
    return std::memcmp(a.data(), b.data(), sizeof(double) * N) == 0;
}

// |a - b| in ulps of `scale` (double).
double ulps(long double a, long double b, long double scale)
{
    return static_cast<double>(std::fabs(a - b) / (scale * eps_double));
}

// ------------------------------------------------------------------------------------
// collide_line (Eq. 8): M behind m on the line, approaching when v_M > v_m.

BOOST_AUTO_TEST_CASE(a_fixed_sphere_on_the_line_keeps_its_velocity_and_reverses_the_approach_times_eps)
{
    // M fixed at v_M = 1, m at -1, eps = 1/2: v'_m = 1 + (1/2)(1 - (-1)) = 2, J = (3/2) m 2.
    const auto fixed_M = impact::collide_line(inf, 2.0, 1.0, -1.0, 0.5);
    BOOST_TEST((fixed_M.status == impact::status::ok));
    BOOST_TEST(fixed_M.v_M == 1.0);
    BOOST_TEST(fixed_M.v_m == 2.0);
    BOOST_TEST(fixed_M.J == 6.0);
    // m fixed at v_m = -1, M at 1, eps = 1/4: v'_M = -1 + (1/4)(-1 - 1) = -3/2, J = (5/4) M 2.
    const auto fixed_m = impact::collide_line(4.0, inf, 1.0, -1.0, 0.25);
    BOOST_TEST((fixed_m.status == impact::status::ok));
    BOOST_TEST(fixed_m.v_M == -1.5);
    BOOST_TEST(fixed_m.v_m == -1.0);
    BOOST_TEST(fixed_m.J == 10.0);
}

BOOST_AUTO_TEST_CASE(random_fixed_spheres_on_the_line_match_the_closed_forms)
{
    std::mt19937_64 random(808);
    std::uniform_real_distribution<double> velocity(-10, 10), unit(0, 1), decade(-6, 6);
    double worst = 0;
    for (int i = 0; i < 2000; ++i) {
        double v_M = velocity(random), v_m = velocity(random);
        if (v_M <= v_m)
            std::swap(v_M, v_m);
        const double eps = unit(random), mass = std::pow(10.0, decade(random));
        const bool M_fixed = i % 2 == 0;
        const auto out = M_fixed ? impact::collide_line(inf, mass, v_M, v_m, eps) : impact::collide_line(mass, inf, v_M, v_m, eps);
        BOOST_TEST_REQUIRE((out.status == impact::status::ok));
        const long double VM = v_M, vm = v_m, e = eps, mu = mass;
        const long double other = M_fixed ? VM + e * (VM - vm) : vm + e * (vm - VM);
        const long double J = (1 + e) * mu * (VM - vm);
        const long double scale = std::max({std::fabs(VM), std::fabs(vm), std::fabs(other)});
        BOOST_TEST((M_fixed ? same_bits(out.v_M, v_M) : same_bits(out.v_m, v_m)));
        worst = std::max({worst, ulps(M_fixed ? out.v_m : out.v_M, other, scale), ulps(out.J, J, scale * mu)});
        // Newton's law of restitution (Eq. 5) on the outputs, within rounding.
        BOOST_TEST(std::fabs((out.v_M - out.v_m) + eps * (v_M - v_m)) <= 8 * eps_double * static_cast<double>(scale));
    }
    BOOST_TEST(worst <= 4.0, "worst " << worst << " ulps");
}

BOOST_AUTO_TEST_CASE(a_huge_finite_mass_on_the_line_agrees_with_the_fixed_sphere)
{
    std::mt19937_64 random(909);
    std::uniform_real_distribution<double> velocity(-10, 10), unit(0, 1), decade(-3, 3);
    for (int i = 0; i < 500; ++i) {
        double v_M = velocity(random), v_m = velocity(random);
        if (v_M <= v_m)
            std::swap(v_M, v_m);
        const double eps = unit(random), m = std::pow(10.0, decade(random));
        const auto huge = impact::collide_line(1e300, m, v_M, v_m, eps);
        const auto fixed = impact::collide_line(inf, m, v_M, v_m, eps);
        BOOST_TEST_REQUIRE((huge.status == impact::status::ok));
        BOOST_TEST_REQUIRE((fixed.status == impact::status::ok));
        const double scale = std::max({std::fabs(v_M), std::fabs(v_m), std::fabs(fixed.v_m)});
        BOOST_TEST(ulps(huge.v_M, fixed.v_M, scale) <= 4.0);
        BOOST_TEST(ulps(huge.v_m, fixed.v_m, scale) <= 4.0);
        BOOST_TEST(ulps(huge.J, fixed.J, scale * m) <= 4.0);
        const auto huge_m = impact::collide_line(m, 1e300, v_M, v_m, eps);
        const auto fixed_m = impact::collide_line(m, inf, v_M, v_m, eps);
        BOOST_TEST_REQUIRE((huge_m.status == impact::status::ok));
        BOOST_TEST(ulps(huge_m.v_M, fixed_m.v_M, scale + std::fabs(fixed_m.v_M)) <= 4.0);
        BOOST_TEST(ulps(huge_m.v_m, fixed_m.v_m, scale + std::fabs(fixed_m.v_M)) <= 4.0);
    }
}

BOOST_AUTO_TEST_CASE(masses_that_are_no_fixed_sphere_stay_refused_on_the_line)
{
    struct masses {
        double M, m;
    };
    for (const masses& bad : {masses{inf, inf}, masses{-inf, 1}, masses{1, -inf}, masses{nan, inf}, masses{inf, nan},
                              masses{inf, 0}, masses{0, inf}, masses{inf, -1}}) {
        BOOST_TEST_CONTEXT("M " << bad.M << ", m " << bad.m)
        {
            const auto out = impact::collide_line(bad.M, bad.m, 1.0, -1.0, 0.5);
            BOOST_TEST((out.status == impact::status::invalid_mass));
            BOOST_TEST(same_bits(out.v_M, 1.0));
            BOOST_TEST(same_bits(out.v_m, -1.0));
            BOOST_TEST(same_bits(out.J, 0.0));
        }
    }
    // The other guards apply to a fixed sphere as to any: separating, eps, velocities.
    BOOST_TEST((impact::collide_line(inf, 1.0, -1.0, 1.0, 0.5).status == impact::status::separating));
    BOOST_TEST((impact::collide_line(inf, 1.0, 1.0, -1.0, 1.5).status == impact::status::invalid_restitution));
    BOOST_TEST((impact::collide_line(1.0, inf, nan, -1.0, 0.5).status == impact::status::non_finite));
    const auto refused = impact::collide_line(inf, 1.0, -1.0, 1.0, 0.5);
    BOOST_TEST(same_bits(refused.v_M, -1.0));
    BOOST_TEST(same_bits(refused.v_m, 1.0));
}

// ------------------------------------------------------------------------------------
// collide in 2D and 3D (Eq. 9, Footnote 10): r = C_M - C_m, approaching when (v_M - v_m).r < 0.

template <std::size_t N>
struct smooth_pair {
    double M, m, eps;
    std::array<double, N> C_M, C_m, v_M, v_m;
};

// The fixed sphere's closed form: the other's velocity v - (1 + eps) ((v - V).n) n, V the
// fixed sphere's velocity, n along r; in long double.
template <std::size_t N>
std::array<long double, N> rebound(const smooth_pair<N>& p, bool M_fixed)
{
    long double rr = 0, dot = 0;
    for (std::size_t k = 0; k < N; ++k) {
        const long double r = static_cast<long double>(p.C_M[k]) - p.C_m[k];
        rr += r * r;
        dot += (static_cast<long double>(M_fixed ? p.v_m[k] : p.v_M[k]) - (M_fixed ? p.v_M[k] : p.v_m[k])) * r;
    }
    std::array<long double, N> after{};
    for (std::size_t k = 0; k < N; ++k) {
        const long double r = static_cast<long double>(p.C_M[k]) - p.C_m[k];
        after[k] = (M_fixed ? p.v_m[k] : p.v_M[k]) - (1 + static_cast<long double>(p.eps)) * dot / rr * r;
    }
    return after;
}

template <std::size_t N>
smooth_pair<N> draw_smooth(std::mt19937_64& random)
{
    std::uniform_real_distribution<double> unit(-1, 1), fraction(0, 1), decade(-6, 6);
    smooth_pair<N> p{};
    p.M = std::pow(10.0, decade(random));
    p.m = std::pow(10.0, decade(random));
    p.eps = fraction(random);
    double closing = 0;
    for (std::size_t k = 0; k < N; ++k) {
        p.C_M[k] = unit(random);
        p.C_m[k] = unit(random);
        p.v_M[k] = unit(random);
        p.v_m[k] = unit(random);
        closing += (p.v_M[k] - p.v_m[k]) * (p.C_M[k] - p.C_m[k]);
    }
    if (closing > 0)
        std::swap(p.v_M, p.v_m);  // approaching
    return p;
}

template <std::size_t N>
void check_smooth_fixed(std::uint64_t seed)
{
    std::mt19937_64 random(seed);
    double worst = 0;
    for (int i = 0; i < 2000; ++i) {
        smooth_pair<N> p = draw_smooth<N>(random);
        const bool M_fixed = i % 2 == 0;
        (M_fixed ? p.M : p.m) = inf;
        const auto out = impact::collide(p.M, p.m, p.C_M, p.C_m, p.v_M, p.v_m, p.eps);
        if (out.status == impact::status::separating)
            continue;  // (v_M - v_m).r == 0 after the swap: not approaching
        BOOST_TEST_REQUIRE((out.status == impact::status::ok));
        BOOST_TEST((M_fixed ? same_bits(out.v_M, p.v_M) : same_bits(out.v_m, p.v_m)));
        const std::array<long double, N> expected = rebound(p, M_fixed);
        const std::array<double, N>& got = M_fixed ? out.v_m : out.v_M;
        long double scale = 0;
        for (std::size_t k = 0; k < N; ++k)
            scale = std::max({scale, std::fabs(expected[k]), std::fabs(static_cast<long double>(p.v_M[k])),
                              std::fabs(static_cast<long double>(p.v_m[k]))});
        for (std::size_t k = 0; k < N; ++k)
            worst = std::max(worst, ulps(got[k], expected[k], scale));
        // Restitution along r and nothing across it, on the outputs: the relative velocity's
        // component along r is -eps times the one before, its part across r unchanged.
        long double rr = 0, before = 0, after = 0;
        for (std::size_t k = 0; k < N; ++k) {
            const long double r = static_cast<long double>(p.C_M[k]) - p.C_m[k];
            rr += r * r;
            before += (static_cast<long double>(p.v_M[k]) - p.v_m[k]) * r;
            after += (static_cast<long double>(out.v_M[k]) - out.v_m[k]) * r;
        }
        BOOST_TEST(std::fabs(after + p.eps * before) <= 16 * eps_double * scale * std::sqrt(rr) * N);
        for (std::size_t k = 0; k < N; ++k) {
            const long double r = static_cast<long double>(p.C_M[k]) - p.C_m[k];
            const long double across_before = (static_cast<long double>(p.v_M[k]) - p.v_m[k]) - before / rr * r;
            const long double across_after = (static_cast<long double>(out.v_M[k]) - out.v_m[k]) - after / rr * r;
            BOOST_TEST(std::fabs(across_after - across_before) <= 16 * eps_double * scale);
        }
    }
    BOOST_TEST(worst <= 4.0, N << "D: worst " << worst << " ulps");
}

BOOST_AUTO_TEST_CASE(random_fixed_spheres_in_2d_and_3d_match_the_closed_forms)
{
    check_smooth_fixed<2>(1001);
    check_smooth_fixed<3>(1002);
}

BOOST_AUTO_TEST_CASE(a_head_on_hit_on_a_fixed_sphere_in_the_plane_rebounds_at_eps_times_the_approach)
{
    // M fixed at the origin, m at (1, 0) moving at (-2, 3): along x reversed times eps = 1/2,
    // across (y) unchanged.
    const auto out = impact::collide(inf, 1.0, std::array<double, 2>{0, 0}, std::array<double, 2>{1, 0},
                                     std::array<double, 2>{0, 0}, std::array<double, 2>{-2, 3}, 0.5);
    BOOST_TEST((out.status == impact::status::ok));
    BOOST_TEST(out.v_M[0] == 0.0);
    BOOST_TEST(out.v_M[1] == 0.0);
    BOOST_TEST(out.v_m[0] == 1.0);
    BOOST_TEST(out.v_m[1] == 3.0);
}

template <std::size_t N>
void check_huge_against_fixed(std::uint64_t seed)
{
    std::mt19937_64 random(seed);
    for (int i = 0; i < 500; ++i) {
        smooth_pair<N> p = draw_smooth<N>(random);
        // m from 1 to 1e3: with M = 1e300 the impulse per mass, (1 + eps) (dv.r)/((M + m)|r|^2),
        // is about 1e-300 and m times it stays normal.
        p.m = std::pow(10.0, std::fmod(std::fabs(std::log10(p.m)), 3.0));
        const auto huge = impact::collide(1e300, p.m, p.C_M, p.C_m, p.v_M, p.v_m, p.eps);
        const auto fixed = impact::collide(inf, p.m, p.C_M, p.C_m, p.v_M, p.v_m, p.eps);
        if (fixed.status == impact::status::separating)
            continue;
        BOOST_TEST_REQUIRE((huge.status == impact::status::ok), "status " << static_cast<int>(huge.status));
        BOOST_TEST_REQUIRE((fixed.status == impact::status::ok));
        double scale = 0;
        for (std::size_t k = 0; k < N; ++k)
            scale = std::max({scale, std::fabs(p.v_M[k]), std::fabs(p.v_m[k]), std::fabs(fixed.v_m[k])});
        for (std::size_t k = 0; k < N; ++k) {
            BOOST_TEST(ulps(huge.v_M[k], fixed.v_M[k], scale) <= 4.0);
            BOOST_TEST(ulps(huge.v_m[k], fixed.v_m[k], scale) <= 4.0);
        }
    }
}

BOOST_AUTO_TEST_CASE(a_huge_finite_mass_in_2d_and_3d_agrees_with_the_fixed_sphere)
{
    check_huge_against_fixed<2>(2001);
    check_huge_against_fixed<3>(2002);
}

BOOST_AUTO_TEST_CASE(masses_that_are_no_fixed_sphere_stay_refused_in_the_plane)
{
    const std::array<double, 2> C_M{1, 0}, C_m{0, 0}, v_M{-1, 0.5}, v_m{1, -0.25};
    struct masses {
        double M, m;
    };
    for (const masses& bad : {masses{inf, inf}, masses{-inf, 1}, masses{nan, inf}, masses{inf, 0}, masses{1, -inf}}) {
        const auto out = impact::collide(bad.M, bad.m, C_M, C_m, v_M, v_m, 0.5);
        BOOST_TEST((out.status == impact::status::invalid_mass));
        BOOST_TEST(same_bits(out.v_M, v_M));
        BOOST_TEST(same_bits(out.v_m, v_m));
    }
    BOOST_TEST((impact::collide(inf, 1.0, C_M, C_M, v_M, v_m, 0.5).status == impact::status::coincident_centres));
    BOOST_TEST((impact::collide(inf, 1.0, C_M, C_m, v_m, v_M, 0.5).status == impact::status::separating));
}

template <std::size_t N>
void check_smooth_batch(std::uint64_t seed)
{
    // Finite pairs and fixed spheres (M or m), and refused ones, in one batch: bit for bit
    // the scalar kernel's velocities and statuses.
    std::mt19937_64 random(seed);
    const std::size_t count = 1003;
    impact::collide_batch_arrays<double, N> batch(count);
    std::vector<smooth_pair<N>> pairs(count);
    for (std::size_t i = 0; i < count; ++i) {
        smooth_pair<N>& p = pairs[i];
        p = draw_smooth<N>(random);
        switch (i % 7) {
        case 1: p.M = inf; break;
        case 2: p.m = inf; break;
        case 3: p.M = p.m = inf; break;
        case 4: p.M = -inf; break;
        default: break;
        }
        batch.M()[i] = p.M;
        batch.m()[i] = p.m;
        batch.eps()[i] = p.eps;
        for (std::size_t k = 0; k < N; ++k) {
            batch.C_M(k)[i] = p.C_M[k];
            batch.C_m(k)[i] = p.C_m[k];
            batch.v_M(k)[i] = p.v_M[k];
            batch.v_m(k)[i] = p.v_m[k];
        }
    }
    impact::collide_batch(batch.data());
    std::size_t fixed_resolved = 0;
    for (std::size_t i = 0; i < count; ++i) {
        const smooth_pair<N>& p = pairs[i];
        const auto out = impact::collide(p.M, p.m, p.C_M, p.C_m, p.v_M, p.v_m, p.eps);
        fixed_resolved += out.status == impact::status::ok && (std::isinf(p.M) || std::isinf(p.m)) ? 1 : 0;
        BOOST_TEST_CONTEXT(N << "D, pair " << i)
        {
            BOOST_TEST((batch.status()[i] == out.status));
            for (std::size_t k = 0; k < N; ++k) {
                BOOST_TEST(same_bits(batch.v_M(k)[i], out.v_M[k]));
                BOOST_TEST(same_bits(batch.v_m(k)[i], out.v_m[k]));
            }
        }
    }
    BOOST_TEST(fixed_resolved > count / 5);
}

BOOST_AUTO_TEST_CASE(the_batch_gives_the_scalar_results_for_fixed_spheres_bit_for_bit)
{
    check_smooth_batch<2>(3001);
    check_smooth_batch<3>(3002);
}

// ------------------------------------------------------------------------------------
// collide_rough (2D): n = (C_m - C_M)/|C_m - C_M|, t = z x n, approaching when g_n > 0.

using vec = std::array<double, 2>;

struct rough_pair {
    double M = 2, m = 3, R_M = 0.5, R_m = 0.25, q_M = 0.4, q_m = 2.0 / 3;
    vec C_M{0, 0}, C_m{0.75, 0};
    vec v_M{1, 0}, v_m{0, 0};
    double w_M = 0, w_m = 0, eps = 0.8, beta = 0.5, mu = 0.3;
};

// `form`: nothing for the accurate form, impact::fast for the fast one.
template <class... Form>
impact::collide_rough_result<double, 2> run(const rough_pair& c, Form... form)
{
    return impact::collide_rough(c.M, c.m, c.R_M, c.R_m, c.q_M, c.q_m, c.C_M, c.C_m, c.v_M, c.v_m, c.w_M, c.w_m,
                                 c.eps, c.beta, c.mu, form...);
}

// Walton's model against a fixed sphere, in long double: the moving sphere's velocity and
// spin after (mass mass, radius R, q), the impulse it takes J n + J_t t (M fixed: +; m
// fixed, the impulse on M is the opposite).
struct rough_after {
    long double v[2], w, J_n, J_t;
};

rough_after rough_fixed(const rough_pair& c, bool M_fixed)
{
    const long double rx = static_cast<long double>(c.C_m[0]) - c.C_M[0], ry = static_cast<long double>(c.C_m[1]) - c.C_M[1];
    const long double d = std::sqrt(rx * rx + ry * ry);
    const long double n[2] = {rx / d, ry / d}, t[2] = {-n[1], n[0]};
    const long double ux = static_cast<long double>(c.v_M[0]) - c.v_m[0], uy = static_cast<long double>(c.v_M[1]) - c.v_m[1];
    const long double g_n = ux * n[0] + uy * n[1];
    const long double g_t = ux * t[0] + uy * t[1] + static_cast<long double>(c.R_M) * c.w_M + static_cast<long double>(c.R_m) * c.w_m;
    const long double mass = M_fixed ? c.m : c.M, q = M_fixed ? c.q_m : c.q_M, R = M_fixed ? c.R_m : c.R_M;
    const long double m_t = 1 / (1 / mass + 1 / (q * mass));
    rough_after a{};
    a.J_n = (1 + static_cast<long double>(c.eps)) * mass * g_n;
    const long double stick = (1 + static_cast<long double>(c.beta)) * m_t * std::fabs(g_t);
    const long double magnitude = std::isinf(c.mu) ? stick : std::min(stick, c.mu * a.J_n);
    a.J_t = g_t == 0 ? 0 : std::copysign(magnitude, g_t);
    const long double sign = M_fixed ? 1 : -1;  // the impulse on m is +J, on M -J
    const vec& v = M_fixed ? c.v_m : c.v_M;
    for (int k = 0; k < 2; ++k)
        a.v[k] = v[k] + sign * (a.J_n * n[k] + a.J_t * t[k]) / mass;
    a.w = (M_fixed ? c.w_m : c.w_M) - a.J_t / (q * mass * R);
    return a;
}

rough_pair draw_rough(std::mt19937_64& random)
{
    std::uniform_real_distribution<double> unit(-1, 1), positive(0.01, 100), fraction(0, 1), q(0.01, 2.0 / 3);
    rough_pair c;
    c.M = positive(random);
    c.m = positive(random);
    c.R_M = positive(random) / 100;
    c.R_m = positive(random) / 100;
    c.q_M = q(random);
    c.q_m = q(random);
    c.C_M = {unit(random), unit(random)};
    c.C_m = {unit(random), unit(random)};
    c.v_M = {unit(random), unit(random)};
    c.v_m = {unit(random), unit(random)};
    c.w_M = unit(random) * 10;
    c.w_m = unit(random) * 10;
    c.eps = fraction(random);
    c.beta = unit(random);
    c.mu = 2 * fraction(random);
    const double closing = (c.v_M[0] - c.v_m[0]) * (c.C_m[0] - c.C_M[0]) + (c.v_M[1] - c.v_m[1]) * (c.C_m[1] - c.C_M[1]);
    if (closing < 0)
        std::swap(c.v_M, c.v_m);
    return c;
}

// Within `bound` ulps: 4 for the accurate form, 16 (its bound) for the fast one.
template <class... Form>
void check_rough_fixed(std::uint64_t seed, double bound, Form... form)
{
    std::mt19937_64 random(seed);
    double worst = 0;
    int sliding = 0, sticking = 0;
    for (int i = 0; i < 2000; ++i) {
        rough_pair c = draw_rough(random);
        if (i % 5 == 0)
            c.mu = inf;
        const bool M_fixed = i % 2 == 0;
        (M_fixed ? c.M : c.m) = inf;
        const auto out = run(c, form...);
        if (out.status == impact::status::separating)
            continue;
        BOOST_TEST_REQUIRE((out.status == impact::status::ok));
        // The fixed sphere keeps its velocity and its spin, bit for bit.
        BOOST_TEST((M_fixed ? same_bits(out.v_M, c.v_M) : same_bits(out.v_m, c.v_m)));
        BOOST_TEST((M_fixed ? same_bits(out.w_M, c.w_M) : same_bits(out.w_m, c.w_m)));
        const rough_after a = rough_fixed(c, M_fixed);
        const vec& v = M_fixed ? out.v_m : out.v_M;
        const double w = M_fixed ? out.w_m : out.w_M, R = M_fixed ? c.R_m : c.R_M;
        long double scale = 0;
        for (int k = 0; k < 2; ++k)
            scale = std::max({scale, std::fabs(static_cast<long double>(c.v_M[k])), std::fabs(static_cast<long double>(c.v_m[k])),
                              std::fabs(a.v[k])});
        scale = std::max({scale, std::fabs(static_cast<long double>(c.R_M) * c.w_M),
                          std::fabs(static_cast<long double>(c.R_m) * c.w_m), std::fabs(R * a.w)});
        for (int k = 0; k < 2; ++k)
            worst = std::max(worst, ulps(v[k], a.v[k], scale));
        worst = std::max(worst, ulps(w, a.w, scale / R));
        const bool slides = !std::isinf(c.mu) && std::fabs(a.J_t) == c.mu * a.J_n;
        (slides ? sliding : sticking) += 1;
    }
    BOOST_TEST(worst <= bound, "worst " << worst << " ulps");
    BOOST_TEST(sliding > 100);
    BOOST_TEST(sticking > 100);
}

BOOST_AUTO_TEST_CASE(random_rough_fixed_spheres_match_waltons_model_with_an_infinite_mass)
{
    check_rough_fixed(4001, 4);
}

BOOST_AUTO_TEST_CASE(the_fast_rough_form_matches_waltons_model_with_an_infinite_mass_within_its_bound)
{
    check_rough_fixed(4011, 16, impact::fast);
}

BOOST_AUTO_TEST_CASE(a_rough_sphere_hitting_a_fixed_one_head_on_rebounds_at_eps_times_the_approach)
{
    // m fixed at the origin, M at (-1, 0) moving at (2, 0) without spin: g_n = 2, g_t = 0,
    // J_n = (1 + eps) M g_n; v'_M = (2 - (1 + eps) 2, 0) = (-eps 2, 0), spins unchanged.
    rough_pair c;
    c.M = 3;
    c.m = inf;
    c.C_M = {-1, 0};
    c.C_m = {0, 0};
    c.v_M = {2, 0};
    c.v_m = {0, 0};
    c.eps = 0.5;
    const auto out = run(c);
    BOOST_TEST((out.status == impact::status::ok));
    BOOST_TEST(out.v_M[0] == -1.0);
    BOOST_TEST(out.v_M[1] == 0.0);
    BOOST_TEST(out.w_M == 0.0);
    BOOST_TEST(out.v_m[0] == 0.0);
    BOOST_TEST(out.w_m == 0.0);
}

BOOST_AUTO_TEST_CASE(a_huge_finite_rough_mass_agrees_with_the_fixed_sphere)
{
    std::mt19937_64 random(4002);
    for (int i = 0; i < 500; ++i) {
        rough_pair c = draw_rough(random);
        rough_pair fixed = c, huge = c;
        fixed.M = inf;
        huge.M = 1e300;
        const auto a = run(fixed), b = run(huge);
        if (a.status == impact::status::separating)
            continue;
        BOOST_TEST_REQUIRE((a.status == impact::status::ok));
        BOOST_TEST_REQUIRE((b.status == impact::status::ok));
        double scale = std::max({std::fabs(c.R_M * c.w_M), std::fabs(c.R_m * c.w_m), std::fabs(c.R_m * a.w_m)});
        for (int k = 0; k < 2; ++k)
            scale = std::max({scale, std::fabs(c.v_M[k]), std::fabs(c.v_m[k]), std::fabs(a.v_m[k])});
        for (int k = 0; k < 2; ++k) {
            BOOST_TEST(ulps(a.v_M[k], b.v_M[k], scale) <= 4.0);
            BOOST_TEST(ulps(a.v_m[k], b.v_m[k], scale) <= 4.0);
        }
        BOOST_TEST(ulps(a.w_M, b.w_M, scale / c.R_M) <= 4.0);
        BOOST_TEST(ulps(a.w_m, b.w_m, scale / c.R_m) <= 4.0);
    }
}

BOOST_AUTO_TEST_CASE(rough_masses_that_are_no_fixed_sphere_stay_refused)
{
    struct masses {
        double M, m;
    };
    for (const masses& bad : {masses{inf, inf}, masses{-inf, 1}, masses{nan, inf}, masses{inf, 0}, masses{2, -inf}}) {
        rough_pair c;
        c.M = bad.M;
        c.m = bad.m;
        c.w_M = 1;
        c.w_m = -2;
        const auto out = run(c);
        BOOST_TEST((out.status == impact::status::invalid_mass));
        BOOST_TEST(same_bits(out.v_M, c.v_M));
        BOOST_TEST(same_bits(out.v_m, c.v_m));
        BOOST_TEST(same_bits(out.w_M, c.w_M));
        BOOST_TEST(same_bits(out.w_m, c.w_m));
    }
    rough_pair c;
    c.M = inf;
    c.R_m = -1;
    BOOST_TEST((run(c).status == impact::status::invalid_radius));
    c = rough_pair{};
    c.m = inf;
    c.mu = nan;
    BOOST_TEST((run(c).status == impact::status::invalid_friction));
}

template <class... Form>
void check_rough_batch(std::uint64_t seed, Form... form)
{
    std::mt19937_64 random(seed);
    const std::size_t count = 1003;
    impact::collide_rough_batch_arrays<double, 2> batch(count);
    std::vector<rough_pair> pairs(count);
    for (std::size_t i = 0; i < count; ++i) {
        rough_pair& c = pairs[i];
        c = draw_rough(random);
        switch (i % 6) {
        case 1: c.M = inf; break;
        case 2: c.m = inf; break;
        case 3: c.M = c.m = inf; break;
        case 4: c.m = inf; c.mu = inf; break;
        default: break;
        }
        batch.M()[i] = c.M;
        batch.m()[i] = c.m;
        batch.R_M()[i] = c.R_M;
        batch.R_m()[i] = c.R_m;
        batch.q_M()[i] = c.q_M;
        batch.q_m()[i] = c.q_m;
        batch.eps()[i] = c.eps;
        batch.beta()[i] = c.beta;
        batch.mu()[i] = c.mu;
        batch.w_M()[i] = c.w_M;
        batch.w_m()[i] = c.w_m;
        for (std::size_t axis = 0; axis < 2; ++axis) {
            batch.C_M(axis)[i] = c.C_M[axis];
            batch.C_m(axis)[i] = c.C_m[axis];
            batch.v_M(axis)[i] = c.v_M[axis];
            batch.v_m(axis)[i] = c.v_m[axis];
        }
    }
    impact::collide_rough_batch(batch.data(), form...);
    std::size_t fixed_resolved = 0;
    for (std::size_t i = 0; i < count; ++i) {
        const rough_pair& c = pairs[i];
        const auto out = run(c, form...);
        fixed_resolved += out.status == impact::status::ok && (std::isinf(c.M) || std::isinf(c.m)) ? 1 : 0;
        BOOST_TEST_CONTEXT("pair " << i)
        {
            BOOST_TEST((batch.status()[i] == out.status));
            for (std::size_t axis = 0; axis < 2; ++axis) {
                BOOST_TEST(same_bits(batch.v_M(axis)[i], out.v_M[axis]));
                BOOST_TEST(same_bits(batch.v_m(axis)[i], out.v_m[axis]));
            }
            BOOST_TEST(same_bits(batch.w_M()[i], out.w_M));
            BOOST_TEST(same_bits(batch.w_m()[i], out.w_m));
        }
    }
    BOOST_TEST(fixed_resolved > count / 5);
}

BOOST_AUTO_TEST_CASE(the_rough_batch_gives_the_scalar_results_for_fixed_spheres_bit_for_bit)
{
    check_rough_batch(4003);
}

BOOST_AUTO_TEST_CASE(the_fast_rough_batch_gives_the_fast_scalar_results_for_fixed_spheres_bit_for_bit)
{
    check_rough_batch(4013, impact::fast);
}

} // namespace
