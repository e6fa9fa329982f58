// The generated kernel `impact::collide_rough` in 3D (derivations/rough_space.toml),
// checked against the physics of rough spheres typed here, not read from Impact:
// Walton's model in space (issue 21): n = (C_m - C_M)/|C_m - C_M|,
// g = v_M - v_m + (R_M w_M + R_m w_m) x n, g_n = g.n, g_t = g - g_n n;
// J_n = (1 + eps) m_r g_n, J_t = min((1 + beta) m_t |g_t|, mu J_n) g_t/|g_t|,
// 1/m_r = 1/M + 1/m, 1/m_t = 1/M + 1/m + 1/(q_M M) + 1/(q_m m); J = J_n n + J_t on m;
// v_M' = v_M - J/M, v_m' = v_m + J/m, w' = w - n x J_t/(q mass R).
// Checked on the outputs: the model on random hits, sticking and sliding; momentum; angular
// momentum about the contact point (lever arms R_M, R_m along n); the energy change
// -(1 - eps^2) m_r g_n^2/2 - |J_t| (|g_t| - |J_t|/(2 m_t)), never a gain; Newton's restitution
// along n and the slip never reversed past -beta g_t; eps = beta = 1, mu = +inf keeping the
// energy; beta = -1 giving the smooth kernel of fn10 with spins unchanged; a hit in the x-y
// plane giving the 2D kernel's results; a fixed sphere (a mass of +infinity); every refusal;
// the batch loop bit for bit; in float and long double, the model, momentum and the energy.
#define BOOST_TEST_MODULE test_rough_kernel_3d
#include <boost/test/unit_test.hpp>

#include <impact/collide_3d.hpp>
#include <impact/collide_rough_2d.hpp>
#include <impact/collide_rough_3d.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

namespace {

using vec = std::array<double, 3>;
using lvec = std::array<long double, 3>;
const double inf = std::numeric_limits<double>::infinity();

struct collision {
    double M = 2, m = 3, R_M = 0.5, R_m = 0.25, q_M = 0.4, q_m = 2.0 / 3;
    vec C_M{0, 0, 0}, C_m{0.75, 0, 0};
    vec v_M{1, 0, 0}, v_m{0, 0, 0};
    vec w_M{0, 0, 0}, w_m{0, 0, 0};
    double eps = 0.8, beta = 0.5, mu = 0.3;
};

template <class... Form>
impact::collide_rough_result<double, 3> run(const collision& c, Form... form)
{
    return impact::collide_rough(c.M, c.m, c.R_M, c.R_m, c.q_M, c.q_m, c.C_M, c.C_m, c.v_M, c.v_m, c.w_M, c.w_m,
                                 c.eps, c.beta, c.mu, form...);
}

lvec cross(const lvec& a, const lvec& b)
{
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

long double dot(const lvec& a, const lvec& b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

lvec wide(const vec& a)
{
    return {a[0], a[1], a[2]};
}

// The model, in long double, from the formulas; a mass of +infinity gives its limit
// (1/M = 0).
struct model {
    lvec n, g_t, J, J_t;
    long double g_n, g_t_size, J_n, J_t_size, m_r, m_t;
    lvec v_M, v_m, w_M, w_m;
};

model expected(const collision& c)
{
    model e{};
    const lvec r = {(long double)c.C_m[0] - c.C_M[0], (long double)c.C_m[1] - c.C_M[1],
                    (long double)c.C_m[2] - c.C_M[2]};
    const long double d = std::sqrt(dot(r, r));
    for (int i = 0; i < 3; ++i)
        e.n[i] = r[i] / d;
    lvec spin;
    for (int i = 0; i < 3; ++i)
        spin[i] = (long double)c.R_M * c.w_M[i] + (long double)c.R_m * c.w_m[i];
    const lvec turn = cross(spin, e.n);
    lvec g;
    for (int i = 0; i < 3; ++i)
        g[i] = (long double)c.v_M[i] - c.v_m[i] + turn[i];
    e.g_n = dot(g, e.n);
    for (int i = 0; i < 3; ++i)
        e.g_t[i] = g[i] - e.g_n * e.n[i];
    e.g_t_size = std::sqrt(dot(e.g_t, e.g_t));
    const long double M = c.M, m = c.m;
    e.m_r = 1 / (1 / M + 1 / m);
    e.m_t = 1 / (1 / M + 1 / m + 1 / (c.q_M * M) + 1 / (c.q_m * m));
    e.J_n = (1 + (long double)c.eps) * e.m_r * e.g_n;
    const long double stick = (1 + (long double)c.beta) * e.m_t * e.g_t_size;
    e.J_t_size = std::isinf(c.mu) ? stick : std::min(stick, c.mu * e.J_n);
    for (int i = 0; i < 3; ++i) {
        e.J_t[i] = e.g_t_size == 0 ? 0 : e.J_t_size * e.g_t[i] / e.g_t_size;
        e.J[i] = e.J_n * e.n[i] + e.J_t[i];
    }
    const lvec n_x_J_t = cross(e.n, e.J_t);
    for (int i = 0; i < 3; ++i) {
        e.v_M[i] = c.v_M[i] - e.J[i] / M;
        e.v_m[i] = c.v_m[i] + e.J[i] / m;
        e.w_M[i] = c.w_M[i] - n_x_J_t[i] / (c.q_M * M * c.R_M);
        e.w_m[i] = c.w_m[i] - n_x_J_t[i] / (c.q_m * m * c.R_m);
    }
    return e;
}

// The largest velocity among the inputs (spins counted as R w): the outputs' error scale.
double largest_speed(const collision& c)
{
    double s = 0;
    for (int i = 0; i < 3; ++i)
        s = std::max({s, std::fabs(c.v_M[i]), std::fabs(c.v_m[i]), std::fabs(c.R_M * c.w_M[i]),
                      std::fabs(c.R_m * c.w_m[i])});
    return s;
}

template <class... Form>
void check_against_model(const collision& c, double ulps, Form... form)
{
    const auto out = run(c, form...);
    BOOST_REQUIRE(out.status == impact::status::ok);
    const model e = expected(c);
    const double tolerance = ulps * largest_speed(c) * std::numeric_limits<double>::epsilon();
    for (int i = 0; i < 3; ++i) {
        BOOST_TEST(std::fabs(out.v_M[i] - e.v_M[i]) <= tolerance);
        BOOST_TEST(std::fabs(out.v_m[i] - e.v_m[i]) <= tolerance);
        BOOST_TEST(std::fabs(out.w_M[i] - e.w_M[i]) * c.R_M <= tolerance);
        BOOST_TEST(std::fabs(out.w_m[i] - e.w_m[i]) * c.R_m <= tolerance);
    }
}

double energy(const collision& c, const vec& v_M, const vec& v_m, const vec& w_M, const vec& w_m)
{
    const double I_M = c.q_M * c.M * c.R_M * c.R_M, I_m = c.q_m * c.m * c.R_m * c.R_m;
    double e = 0;
    for (int i = 0; i < 3; ++i)
        e += 0.5 * c.M * v_M[i] * v_M[i] + 0.5 * c.m * v_m[i] * v_m[i] + 0.5 * I_M * w_M[i] * w_M[i] +
             0.5 * I_m * w_m[i] * w_m[i];
    return e;
}

// Masses and radii in [least, most], q in [least_q, 2/3], centres, velocities and spins in
// [-1, 1]^3, eps in [0, 1], beta in [-1, 1], mu in [0, 2].
collision drawn(std::mt19937_64& random, double least, double most, double least_q)
{
    std::uniform_real_distribution<double> unit(-1, 1), positive(least, most), fraction(0, 1);
    collision c;
    c.M = positive(random);
    c.m = positive(random);
    c.R_M = positive(random);
    c.R_m = positive(random);
    c.q_M = least_q + fraction(random) * (2.0 / 3 - least_q);
    c.q_m = least_q + fraction(random) * (2.0 / 3 - least_q);
    for (vec* v : {&c.C_M, &c.C_m, &c.v_M, &c.v_m, &c.w_M, &c.w_m})
        *v = {unit(random), unit(random), unit(random)};
    c.eps = fraction(random);
    c.beta = unit(random);
    c.mu = 2 * fraction(random);
    return c;
}

} // namespace

BOOST_AUTO_TEST_CASE(a_ball_spinning_into_another_sticks_or_slides_as_walton_s_model_says)
{
    // M at the origin hits m on the x axis, spinning about z: g = (1, 0, 0) + 0.5 (0, 0, 4) x (1, 0, 0)
    // = (1, 2, 0), g_n = 1, g_t = (0, 2, 0). m_r = 6/5, 1/m_t = 1/2 + 1/3 + 5/4 + 1/2 = 31/12.
    // Sticking (mu = +inf): J_t = 1.5 (12/31) 2 = 36/31 along y; J_n = 1.8 (6/5) = 2.16.
    collision c;
    c.w_M = {0, 0, 4};
    c.mu = inf;
    const auto stuck = run(c);
    BOOST_REQUIRE(stuck.status == impact::status::ok);
    const auto tol = boost::test_tools::tolerance(1e-14);
    BOOST_TEST(stuck.v_M[0] == 1 - 2.16 / 2, tol);
    BOOST_TEST(stuck.v_M[1] == -(36.0 / 31) / 2, tol);
    BOOST_TEST(stuck.v_m[0] == 2.16 / 3, tol);
    BOOST_TEST(stuck.v_m[1] == (36.0 / 31) / 3, tol);
    // w' = w - n x J_t/(q mass R), n x J_t = (0, 0, 36/31).
    BOOST_TEST(stuck.w_M[2] == 4 - (36.0 / 31) / (0.4 * 2 * 0.5), tol);
    BOOST_TEST(stuck.w_m[2] == -(36.0 / 31) / ((2.0 / 3) * 3 * 0.25), tol);
    BOOST_TEST(stuck.v_M[2] == 0.0);
    BOOST_TEST(stuck.w_M[0] == 0.0);
    // Sliding (mu = 0.3): |J_t| = 0.3 * 2.16 = 0.648 < 36/31.
    c.mu = 0.3;
    const auto slid = run(c);
    BOOST_REQUIRE(slid.status == impact::status::ok);
    BOOST_TEST(slid.v_M[1] == -0.648 / 2, tol);
    BOOST_TEST(slid.v_m[1] == 0.648 / 3, tol);
    BOOST_TEST(slid.w_M[2] == 4 - 0.648 / (0.4 * 2 * 0.5), tol);
}

BOOST_AUTO_TEST_CASE(random_hits_follow_the_model_and_its_laws)
{
    std::mt19937_64 random(2103);
    int sticking = 0, sliding = 0;
    for (int n = 0; n < 4000; ++n) {
        collision c = drawn(random, 0.1, 10, 0.05);
        if (n % 5 == 0)
            c.mu = inf;
        const auto out = run(c);
        const model e = expected(c);
        if (e.g_n <= 0) {
            BOOST_TEST((out.status == impact::status::separating));
            continue;
        }
        BOOST_REQUIRE(out.status == impact::status::ok);
        const bool sticks = std::isinf(c.mu) || (1 + c.beta) * e.m_t * e.g_t_size <= c.mu * e.J_n;
        (sticks ? sticking : sliding) += 1;
        BOOST_TEST_CONTEXT("hit " << n)
        {
            check_against_model(c, 8);
            const double scale = 100 * std::numeric_limits<double>::epsilon();
            // Momentum.
            for (int i = 0; i < 3; ++i) {
                const double before = c.M * c.v_M[i] + c.m * c.v_m[i];
                const double after = c.M * out.v_M[i] + c.m * out.v_m[i];
                BOOST_TEST(std::fabs(after - before) <= scale * (c.M + c.m) * 10);
            }
            // Angular momentum about the contact point: I w + mass (C - P) x v, with
            // C_M - P = -R_M n and C_m - P = R_m n.
            auto angular = [&](const vec& v_M, const vec& v_m, const vec& w_M, const vec& w_m) {
                lvec arm_M, arm_m;
                for (int i = 0; i < 3; ++i) {
                    arm_M[i] = -c.R_M * e.n[i];
                    arm_m[i] = c.R_m * e.n[i];
                }
                const lvec L_M = cross(arm_M, wide(v_M)), L_m = cross(arm_m, wide(v_m));
                lvec L;
                for (int i = 0; i < 3; ++i)
                    L[i] = c.q_M * c.M * c.R_M * c.R_M * w_M[i] + c.q_m * c.m * c.R_m * c.R_m * w_m[i] +
                           c.M * L_M[i] + c.m * L_m[i];
                return L;
            };
            const lvec L_before = angular(c.v_M, c.v_m, c.w_M, c.w_m);
            const lvec L_after = angular(out.v_M, out.v_m, out.w_M, out.w_m);
            const double L_scale = (c.M + c.m) * (c.R_M + c.R_m) * (10 + c.R_M + c.R_m);
            for (int i = 0; i < 3; ++i)
                BOOST_TEST(std::fabs((double)(L_after[i] - L_before[i])) <= scale * L_scale);
            // The energy change, and never a gain.
            const double dE = energy(c, out.v_M, out.v_m, out.w_M, out.w_m) - energy(c, c.v_M, c.v_m, c.w_M, c.w_m);
            const long double formula = -(1 - (long double)c.eps * c.eps) * e.m_r * e.g_n * e.g_n / 2 -
                                        e.J_t_size * (e.g_t_size - e.J_t_size / (2 * e.m_t));
            const double E_scale = energy(c, c.v_M, c.v_m, c.w_M, c.w_m) + 1;
            BOOST_TEST(std::fabs(dE - (double)formula) <= scale * E_scale);
            BOOST_TEST(dE <= scale * E_scale);
            // Newton's restitution along n; across n, g_t' = -beta g_t while sticking, and
            // never reversed past it while sliding (g_t' = -beta_eff g_t with beta_eff <= beta).
            lvec spin_after;
            for (int i = 0; i < 3; ++i)
                spin_after[i] = (long double)c.R_M * out.w_M[i] + (long double)c.R_m * out.w_m[i];
            const lvec turn = cross(spin_after, e.n);
            lvec g_after;
            for (int i = 0; i < 3; ++i)
                g_after[i] = (long double)out.v_M[i] - out.v_m[i] + turn[i];
            const long double gn_after = dot(g_after, e.n);
            const double g_scale = 10 + 10 * (c.R_M + c.R_m);
            BOOST_TEST(std::fabs((double)(gn_after + c.eps * e.g_n)) <= scale * g_scale);
            lvec gt_after;
            for (int i = 0; i < 3; ++i)
                gt_after[i] = g_after[i] - gn_after * e.n[i];
            lvec past;  // g_t' + beta g_t: 0 while sticking, along g_t while sliding
            for (int i = 0; i < 3; ++i)
                past[i] = gt_after[i] + c.beta * e.g_t[i];
            if (sticks)
                BOOST_TEST(std::sqrt((double)dot(past, past)) <= scale * g_scale);
            else
                BOOST_TEST((double)dot(past, e.g_t) >= -scale * g_scale * g_scale);
        }
    }
    BOOST_TEST(sticking > 200);
    BOOST_TEST(sliding > 200);
}

// The kernel in float and in long double: the inputs rounded to the type (the model sees
// the rounded ones), the outputs against the model within 8 ulps of the type (twice the
// bound; in long double, the model's own rounding, as large, is given as much again), and
// momentum, the energy change and its sign within a hundred of the type's ulps.
template <class T>
void check_in_precision(double ulps)
{
    using tvec = std::array<T, 3>;
    const auto narrow = [](vec& v) {
        for (double& x : v)
            x = static_cast<double>(static_cast<T>(x));
    };
    const auto as = [](const vec& v) { return tvec{T(v[0]), T(v[1]), T(v[2])}; };
    const auto wide_t = [](const tvec& v) { return lvec{v[0], v[1], v[2]}; };
    const long double unit = std::numeric_limits<T>::epsilon();
    std::mt19937_64 random(sizeof(T) * 1000 + 21);
    int checked = 0;
    for (int n = 0; n < 1000; ++n) {
        collision c = drawn(random, 0.1, 10, 0.05);
        if (n % 5 == 0)
            c.mu = inf;
        for (double* x : {&c.M, &c.m, &c.R_M, &c.R_m, &c.q_M, &c.q_m, &c.eps, &c.beta, &c.mu})
            *x = static_cast<double>(static_cast<T>(*x));
        for (vec* v : {&c.C_M, &c.C_m, &c.v_M, &c.v_m, &c.w_M, &c.w_m})
            narrow(*v);
        const auto out = impact::collide_rough<T>(T(c.M), T(c.m), T(c.R_M), T(c.R_m), T(c.q_M), T(c.q_m), as(c.C_M),
                                                  as(c.C_m), as(c.v_M), as(c.v_m), as(c.w_M), as(c.w_m), T(c.eps),
                                                  T(c.beta), T(c.mu));
        const model e = expected(c);
        if (e.g_n <= 0) {
            BOOST_TEST((out.status == impact::status::separating));
            continue;
        }
        BOOST_REQUIRE(out.status == impact::status::ok);
        ++checked;
        BOOST_TEST_CONTEXT("hit " << n)
        {
            const lvec v_M = wide_t(out.v_M), v_m = wide_t(out.v_m), w_M = wide_t(out.w_M), w_m = wide_t(out.w_m);
            const long double tolerance = ulps * largest_speed(c) * unit;
            for (int i = 0; i < 3; ++i) {
                BOOST_TEST(std::fabs(v_M[i] - e.v_M[i]) <= tolerance);
                BOOST_TEST(std::fabs(v_m[i] - e.v_m[i]) <= tolerance);
                BOOST_TEST(std::fabs(w_M[i] - e.w_M[i]) * c.R_M <= tolerance);
                BOOST_TEST(std::fabs(w_m[i] - e.w_m[i]) * c.R_m <= tolerance);
            }
            const long double scale = 100 * unit;
            for (int i = 0; i < 3; ++i) {
                const long double before = (long double)c.M * c.v_M[i] + (long double)c.m * c.v_m[i];
                const long double after = c.M * v_M[i] + c.m * v_m[i];
                BOOST_TEST(std::fabs(after - before) <= scale * (c.M + c.m) * 10);
            }
            const auto energy_of = [&](const lvec& a, const lvec& b, const lvec& p, const lvec& q) {
                return (c.M * dot(a, a) + c.m * dot(b, b) + (long double)c.q_M * c.M * c.R_M * c.R_M * dot(p, p) +
                        (long double)c.q_m * c.m * c.R_m * c.R_m * dot(q, q)) /
                       2;
            };
            const long double E_before = energy_of(wide(c.v_M), wide(c.v_m), wide(c.w_M), wide(c.w_m));
            const long double dE = energy_of(v_M, v_m, w_M, w_m) - E_before;
            const long double formula = -(1 - (long double)c.eps * c.eps) * e.m_r * e.g_n * e.g_n / 2 -
                                        e.J_t_size * (e.g_t_size - e.J_t_size / (2 * e.m_t));
            BOOST_TEST(std::fabs(dE - formula) <= scale * (E_before + 1));
            BOOST_TEST(dE <= scale * (E_before + 1));
        }
    }
    BOOST_TEST(checked > 300);
}

BOOST_AUTO_TEST_CASE(in_float_the_kernel_follows_the_model_and_its_laws)
{
    check_in_precision<float>(8);
}

BOOST_AUTO_TEST_CASE(in_long_double_the_kernel_follows_the_model_and_its_laws)
{
    check_in_precision<long double>(16);
}

BOOST_AUTO_TEST_CASE(perfectly_rough_elastic_spheres_keep_their_energy)
{
    collision c;
    c.v_M = {1, -2, 0.5};
    c.v_m = {-0.5, 0.25, -1};
    c.w_M = {4, -1, 2};
    c.w_m = {-7, 3, 0.5};
    c.eps = 1;
    c.beta = 1;
    c.mu = inf;
    const auto out = run(c);
    BOOST_REQUIRE(out.status == impact::status::ok);
    const double before = energy(c, c.v_M, c.v_m, c.w_M, c.w_m);
    BOOST_TEST(energy(c, out.v_M, out.v_m, out.w_M, out.w_m) == before, boost::test_tools::tolerance(1e-14));
}

BOOST_AUTO_TEST_CASE(smooth_spheres_are_the_smooth_kernel_with_spins_unchanged)
{
    // beta = -1: no tangential impulse, whatever mu and the spins: Eq. 9 in space (fn10).
    std::mt19937_64 random(99);
    for (int n = 0; n < 500; ++n) {
        collision c = drawn(random, 0.1, 10, 0.05);
        c.beta = -1;
        const auto rough = run(c);
        const auto smooth = impact::collide(c.M, c.m, c.C_M, c.C_m, c.v_M, c.v_m, c.eps);
        BOOST_TEST((rough.status == smooth.status));
        if (rough.status != impact::status::ok)
            continue;
        const double tolerance = 8 * largest_speed(c) * std::numeric_limits<double>::epsilon();
        for (int i = 0; i < 3; ++i) {
            BOOST_TEST(std::fabs(rough.v_M[i] - smooth.v_M[i]) <= tolerance);
            BOOST_TEST(std::fabs(rough.v_m[i] - smooth.v_m[i]) <= tolerance);
            BOOST_TEST(rough.w_M[i] == c.w_M[i]);
            BOOST_TEST(rough.w_m[i] == c.w_m[i]);
        }
    }
}

BOOST_AUTO_TEST_CASE(a_hit_in_the_x_y_plane_is_the_plane_s_kernel)
{
    // Centres and velocities in the plane z = 0, spins about z: the 2D kernel (rough_plane),
    // whose spin is the z component.
    std::mt19937_64 random(7);
    int compared = 0;
    for (int n = 0; n < 500; ++n) {
        collision c = drawn(random, 0.1, 10, 0.05);
        for (vec* v : {&c.C_M, &c.C_m, &c.v_M, &c.v_m})
            (*v)[2] = 0;
        c.w_M[0] = c.w_M[1] = c.w_m[0] = c.w_m[1] = 0;
        const auto space = run(c);
        const auto plane = impact::collide_rough(c.M, c.m, c.R_M, c.R_m, c.q_M, c.q_m, std::array<double, 2>{c.C_M[0], c.C_M[1]},
                                                 std::array<double, 2>{c.C_m[0], c.C_m[1]},
                                                 std::array<double, 2>{c.v_M[0], c.v_M[1]},
                                                 std::array<double, 2>{c.v_m[0], c.v_m[1]}, c.w_M[2], c.w_m[2], c.eps,
                                                 c.beta, c.mu);
        BOOST_TEST((space.status == plane.status));
        if (space.status != impact::status::ok)
            continue;
        ++compared;
        const double tolerance = 8 * largest_speed(c) * std::numeric_limits<double>::epsilon();
        for (int i = 0; i < 2; ++i) {
            BOOST_TEST(std::fabs(space.v_M[i] - plane.v_M[i]) <= tolerance);
            BOOST_TEST(std::fabs(space.v_m[i] - plane.v_m[i]) <= tolerance);
        }
        BOOST_TEST(space.v_M[2] == 0.0);
        BOOST_TEST(space.v_m[2] == 0.0);
        BOOST_TEST(std::fabs(space.w_M[2] - plane.w_M) * c.R_M <= tolerance);
        BOOST_TEST(std::fabs(space.w_m[2] - plane.w_m) * c.R_m <= tolerance);
        for (int i = 0; i < 2; ++i) {
            BOOST_TEST(space.w_M[i] == 0.0);
            BOOST_TEST(space.w_m[i] == 0.0);
        }
    }
    BOOST_TEST(compared > 100);
}

BOOST_AUTO_TEST_CASE(a_fixed_sphere_keeps_its_velocity_and_spin_and_the_other_follows_the_limit)
{
    // M = +infinity (then m = +infinity): the model with 1/M = 0, m_r = m, 1/m_t = 1/m + 1/(q_m m).
    std::mt19937_64 random(4);
    int resolved = 0;
    for (int n = 0; n < 1000; ++n) {
        collision c = drawn(random, 0.1, 10, 0.05);
        const bool fixed_M = n % 2 == 0;
        (fixed_M ? c.M : c.m) = inf;
        const auto out = run(c);
        if (expected(c).g_n <= 0) {
            BOOST_TEST((out.status == impact::status::separating));
            continue;
        }
        BOOST_REQUIRE(out.status == impact::status::ok);
        ++resolved;
        BOOST_TEST_CONTEXT("hit " << n << (fixed_M ? ", M" : ", m") << " fixed")
        {
            check_against_model(c, 8);
            const vec& v = fixed_M ? c.v_M : c.v_m;
            const vec& w = fixed_M ? c.w_M : c.w_m;
            BOOST_TEST(std::memcmp(&(fixed_M ? out.v_M : out.v_m), &v, sizeof v) == 0);
            BOOST_TEST(std::memcmp(&(fixed_M ? out.w_M : out.w_m), &w, sizeof w) == 0);
        }
    }
    BOOST_TEST(resolved > 300);
    // Both fixed: refused.
    collision both;
    both.M = both.m = inf;
    BOOST_TEST((run(both).status == impact::status::invalid_mass));
}

BOOST_AUTO_TEST_CASE(bad_input_is_refused_with_its_status_and_returned_as_given)
{
    struct bad {
        void (*spoil)(collision&);
        impact::status status;
    };
    const bad cases[] = {
        {[](collision& c) { c.m = 0; }, impact::status::invalid_mass},
        {[](collision& c) { c.M = -1; }, impact::status::invalid_mass},
        {[](collision& c) { c.R_M = 0; }, impact::status::invalid_radius},
        {[](collision& c) { c.R_m = inf; }, impact::status::invalid_radius},
        {[](collision& c) { c.q_M = 0; }, impact::status::invalid_inertia},
        {[](collision& c) { c.q_m = 0.7; }, impact::status::invalid_inertia},
        {[](collision& c) { c.eps = 1.5; }, impact::status::invalid_restitution},
        {[](collision& c) { c.beta = -1.5; }, impact::status::invalid_tangential_restitution},
        {[](collision& c) { c.beta = std::numeric_limits<double>::quiet_NaN(); },
         impact::status::invalid_tangential_restitution},
        {[](collision& c) { c.mu = -0.1; }, impact::status::invalid_friction},
        {[](collision& c) { c.mu = std::numeric_limits<double>::quiet_NaN(); }, impact::status::invalid_friction},
        {[](collision& c) { c.w_M[2] = std::numeric_limits<double>::quiet_NaN(); }, impact::status::non_finite},
        {[](collision& c) { c.v_m[1] = inf; }, impact::status::non_finite},
        {[](collision& c) { c.C_M[2] = inf; }, impact::status::non_finite},
        {[](collision& c) { c.C_m = c.C_M; }, impact::status::coincident_centres},
        {[](collision& c) { c.v_M = {-1, 0.5, 0.5}; }, impact::status::separating},
    };
    for (const bad& b : cases)
        for (bool fast : {false, true}) {
            collision c;
            c.w_M = {2, 1, -1};
            c.w_m = {-3, 0.5, 1};
            b.spoil(c);
            const auto out = fast ? run(c, impact::fast) : run(c);
            BOOST_TEST((out.status == b.status), "status " << static_cast<int>(out.status) << (fast ? " (fast)" : ""));
            BOOST_TEST(std::memcmp(&out.v_M, &c.v_M, sizeof c.v_M) == 0);
            BOOST_TEST(std::memcmp(&out.v_m, &c.v_m, sizeof c.v_m) == 0);
            BOOST_TEST(std::memcmp(&out.w_M, &c.w_M, sizeof c.w_M) == 0);
            BOOST_TEST(std::memcmp(&out.w_m, &c.w_m, sizeof c.w_m) == 0);
        }
}

BOOST_AUTO_TEST_CASE(the_fast_form_follows_the_model_within_its_bound)
{
    // Twice its bound of 16 ulps, as the accurate form is held to twice its 4 above.
    std::mt19937_64 random(77);
    for (int i = 0; i < 2000; ++i) {
        const collision d = drawn(random, 0.01, 100, 0.01);
        if (run(d, impact::fast).status == impact::status::ok)
            BOOST_TEST_CONTEXT("drawn collision " << i) check_against_model(d, 32, impact::fast);
    }
}

namespace {

template <class... Form>
void check_batch(Form... form)
{
    // Ordinary, sticking, sliding, head-on without spin (g_t = 0, mu = 0), mu = +inf, a fixed
    // sphere and refused pairs, in one batch: each pair's velocities, spins and status are the
    // scalar kernel's, bit for bit.
    std::mt19937_64 random(2121);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const std::size_t count = 1003;  // not a multiple of a block
    impact::collide_rough_batch_arrays<double, 3> batch(count);
    std::vector<collision> pairs(count);
    for (std::size_t i = 0; i < count; ++i) {
        collision& c = pairs[i];
        c = drawn(random, 0.01, 100, 0.01);
        c.mu /= 2;
        switch (i % 16) {
        case 1: c.mu = inf; break;
        case 2:
            c.mu = 0;
            c.C_M = {0, 0, 0};
            c.C_m = {1, 0, 0};
            c.v_M = {1, 0, 0};
            c.v_m = {0, 0, 0};
            c.w_M = c.w_m = {0, 0, 0};
            break;
        case 3: c.R_M = -1; break;
        case 4: c.q_m = 0.9; break;
        case 5: c.beta = nan; break;
        case 6: c.mu = -1; break;
        case 7: c.w_m[1] = inf; break;
        case 8: c.C_m = c.C_M; break;
        case 9: c.M = 1e-300; c.m = 1e300; break;
        case 10: c.mu = 1e-300; break;
        case 11: c.M = inf; break;
        case 12: c.m = inf; break;
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
        for (std::size_t axis = 0; axis < 3; ++axis) {
            batch.C_M(axis)[i] = c.C_M[axis];
            batch.C_m(axis)[i] = c.C_m[axis];
            batch.v_M(axis)[i] = c.v_M[axis];
            batch.v_m(axis)[i] = c.v_m[axis];
            batch.w_M(axis)[i] = c.w_M[axis];
            batch.w_m(axis)[i] = c.w_m[axis];
        }
    }
    impact::collide_rough_batch(batch.data(), form...);
    std::size_t resolved = 0;
    for (std::size_t i = 0; i < count; ++i) {
        const auto out = run(pairs[i], form...);
        resolved += out.status == impact::status::ok ? 1 : 0;
        BOOST_TEST_CONTEXT("pair " << i)
        {
            BOOST_TEST((batch.status()[i] == out.status));
            for (std::size_t axis = 0; axis < 3; ++axis) {
                BOOST_TEST(std::memcmp(&batch.v_M(axis)[i], &out.v_M[axis], sizeof(double)) == 0);
                BOOST_TEST(std::memcmp(&batch.v_m(axis)[i], &out.v_m[axis], sizeof(double)) == 0);
                BOOST_TEST(std::memcmp(&batch.w_M(axis)[i], &out.w_M[axis], sizeof(double)) == 0);
                BOOST_TEST(std::memcmp(&batch.w_m(axis)[i], &out.w_m[axis], sizeof(double)) == 0);
            }
        }
    }
    BOOST_TEST(resolved > count / 4);
}

} // namespace

BOOST_AUTO_TEST_CASE(the_batch_gives_the_scalar_results_bit_for_bit)
{
    check_batch();
}

BOOST_AUTO_TEST_CASE(the_fast_batch_gives_the_fast_scalar_results_bit_for_bit)
{
    check_batch(impact::fast);
}
