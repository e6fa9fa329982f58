// The generated kernel `impact::collide_rough` in 2D (derivations/rough_plane.toml),
// checked against the physics of rough spheres typed here, not read from Impact:
// Walton's model (issue 21): g = v_M - v_m + (R_M w_M + R_m w_m) t at the contact, with
// n = (C_m - C_M)/|C_m - C_M| and t = z x n; J_n = (1 + eps) m_r g_n,
// J_t = min((1 + beta) m_t |g_t|, mu J_n) sign(g_t), 1/m_t = 1/M + 1/m + 1/(q_M M) + 1/(q_m m).
// Checked on the outputs: momentum, angular momentum about the contact point, the energy
// change -(1 - eps^2) m_r g_n^2/2 - J_t (g_t - J_t/(2 m_t)), the restitution laws, the
// smooth spheres of Eq. 9, and each refusal with its status; in double, and in float and long
// double against the model and its laws.
#define BOOST_TEST_MODULE test_rough_kernel
#include <boost/test/unit_test.hpp>

#include <impact/collide_rough_2d.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <cstring>
#include <vector>

namespace {

using vec = std::array<double, 2>;

struct collision {
    double M = 2, m = 3, R_M = 0.5, R_m = 0.25, q_M = 0.4, q_m = 2.0 / 3;
    vec C_M{0, 0}, C_m{0.75, 0};
    vec v_M{1, 0}, v_m{0, 0};
    double w_M = 0, w_m = 0, eps = 0.8, beta = 0.5, mu = 0.3;
};

// `form`: nothing for the accurate form, impact::fast for the fast one.
template <class... Form>
impact::collide_rough_result<double, 2> run(const collision& c, Form... form)
{
    return impact::collide_rough(c.M, c.m, c.R_M, c.R_m, c.q_M, c.q_m, c.C_M, c.C_m, c.v_M, c.v_m, c.w_M, c.w_m,
                                 c.eps, c.beta, c.mu, form...);
}

// The model, in long double, from the formulas.
struct model {
    long double n[2], t[2], g_n, g_t, J_n, J_t, m_r, m_t;
};

model expected(const collision& c)
{
    model e{};
    const long double rx = (long double)c.C_m[0] - c.C_M[0], ry = (long double)c.C_m[1] - c.C_M[1];
    const long double d = std::sqrt(rx * rx + ry * ry);
    e.n[0] = rx / d;
    e.n[1] = ry / d;
    e.t[0] = -e.n[1];
    e.t[1] = e.n[0];
    const long double ux = (long double)c.v_M[0] - c.v_m[0], uy = (long double)c.v_M[1] - c.v_m[1];
    e.g_n = ux * e.n[0] + uy * e.n[1];
    e.g_t = ux * e.t[0] + uy * e.t[1] + (long double)c.R_M * c.w_M + (long double)c.R_m * c.w_m;
    e.m_r = (long double)c.M * c.m / ((long double)c.M + c.m);
    e.m_t = 1 / (1 / (long double)c.M + 1 / (long double)c.m + 1 / ((long double)c.q_M * c.M) +
                 1 / ((long double)c.q_m * c.m));
    e.J_n = (1 + (long double)c.eps) * e.m_r * e.g_n;
    const long double stick = (1 + (long double)c.beta) * e.m_t * std::fabs(e.g_t);
    const long double cap = c.mu * e.J_n;
    const long double magnitude = std::isinf(c.mu) ? stick : std::min(stick, cap);
    e.J_t = e.g_t == 0 ? 0 : std::copysign(magnitude, e.g_t);
    return e;
}

double energy(const collision& c, const vec& v_M, const vec& v_m, double w_M, double w_m)
{
    const double I_M = c.q_M * c.M * c.R_M * c.R_M, I_m = c.q_m * c.m * c.R_m * c.R_m;
    return 0.5 * c.M * (v_M[0] * v_M[0] + v_M[1] * v_M[1]) + 0.5 * c.m * (v_m[0] * v_m[0] + v_m[1] * v_m[1]) +
           0.5 * I_M * w_M * w_M + 0.5 * I_m * w_m * w_m;
}

// A collision drawn at random: masses and radii in [least, most], q in [least_q, 2/3],
// centres, velocities and spins in [-1, 1], eps in [0, 1], beta in [-1, 1], mu in [0, 2].
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
    c.C_M = {unit(random), unit(random)};
    c.C_m = {unit(random), unit(random)};
    c.v_M = {unit(random), unit(random)};
    c.v_m = {unit(random), unit(random)};
    c.w_M = unit(random);
    c.w_m = unit(random);
    c.eps = fraction(random);
    c.beta = unit(random);
    c.mu = 2 * fraction(random);
    return c;
}

// Every output against the model: v_M' = v_M - J/M, v_m' = v_m + J/m,
// w' = w - J_t/(q mass R), within `ulps` of the collision's largest speed.
template <class... Form>
void check_against_model(const collision& c, double ulps, Form... form)
{
    const auto out = run(c, form...);
    BOOST_REQUIRE(out.status == impact::status::ok);
    const model e = expected(c);
    const double speed = std::max({std::fabs(c.v_M[0]), std::fabs(c.v_M[1]), std::fabs(c.v_m[0]),
                                   std::fabs(c.v_m[1]), std::fabs(c.R_M * c.w_M), std::fabs(c.R_m * c.w_m)});
    const double tolerance = ulps * speed * std::numeric_limits<double>::epsilon();
    for (int i = 0; i < 2; ++i) {
        const long double J = e.J_n * e.n[i] + e.J_t * e.t[i];
        BOOST_TEST(std::fabs(out.v_M[i] - (c.v_M[i] - J / c.M)) <= tolerance);
        BOOST_TEST(std::fabs(out.v_m[i] - (c.v_m[i] + J / c.m)) <= tolerance);
    }
    BOOST_TEST(std::fabs(out.w_M - (c.w_M - e.J_t / (c.q_M * c.M * c.R_M))) * c.R_M <= tolerance);
    BOOST_TEST(std::fabs(out.w_m - (c.w_m - e.J_t / (c.q_m * c.m * c.R_m))) * c.R_m <= tolerance);
}

} // namespace

BOOST_AUTO_TEST_CASE(head_on_without_spin_is_the_smooth_collision)
{
    // g_t = 0: no tangential impulse whatever beta and mu (mu = 0 too: the sliding
    // branch, which divides by |g_t|, is discarded, and nothing is refused).
    for (double mu : {0.0, 0.3, std::numeric_limits<double>::infinity()}) {
        collision c;
        c.mu = mu;
        const auto out = run(c);
        BOOST_TEST_INFO("mu = " << mu);
        BOOST_REQUIRE(out.status == impact::status::ok);
        // Eq. 8 along x: J = (1 + eps) M m (v_M - v_m)/(M + m) = 1.8 * 6/5 = 2.16.
        BOOST_TEST(out.v_M[0] == 1 - 2.16 / 2, boost::test_tools::tolerance(1e-15));
        BOOST_TEST(out.v_m[0] == 2.16 / 3, boost::test_tools::tolerance(1e-15));
        BOOST_TEST(out.v_M[1] == 0.0);
        BOOST_TEST(out.v_m[1] == 0.0);
        BOOST_TEST(out.w_M == 0.0);
        BOOST_TEST(out.w_m == 0.0);
    }
}

// One collision, sticking or sliding as mu and beta make it, against the model.
template <class... Form>
void check_sticking_and_sliding(double ulps, Form... form)
{
    collision c;
    c.v_M = {1, 0.5};
    c.w_M = 3;
    c.w_m = -1;
    for (double mu : {0.0, 0.05, 0.3, 2.0, std::numeric_limits<double>::infinity()})
        for (double beta : {-1.0, -0.3, 0.5, 1.0}) {
            c.mu = mu;
            c.beta = beta;
            BOOST_TEST_CONTEXT("mu = " << mu << ", beta = " << beta) check_against_model(c, ulps, form...);
        }
}

BOOST_AUTO_TEST_CASE(sticking_and_sliding_follow_the_model)
{
    check_sticking_and_sliding(8);
}

BOOST_AUTO_TEST_CASE(conservation_laws_and_the_energy_change)
{
    std::mt19937_64 random(21);
    for (int n = 0; n < 2000; ++n) {
        collision c = drawn(random, 0.1, 10, 0.05);
        if (n % 5 == 0)
            c.mu = std::numeric_limits<double>::infinity();
        const auto out = run(c);
        const model e = expected(c);
        if (e.g_n <= 0) {
            BOOST_TEST((out.status == impact::status::separating));
            continue;
        }
        BOOST_REQUIRE(out.status == impact::status::ok);
        check_against_model(c, 8);
        const double scale = 100 * std::numeric_limits<double>::epsilon();
        // Momentum.
        for (int i = 0; i < 2; ++i) {
            const double before = c.M * c.v_M[i] + c.m * c.v_m[i];
            const double after = c.M * out.v_M[i] + c.m * out.v_m[i];
            BOOST_TEST(std::fabs(after - before) <= scale * (c.M + c.m) * 10);
        }
        // Angular momentum about the contact point (lever arms R_M, R_m along n):
        // I w - R_M M v_M.t before and after for M, I w + R_m m v_m.t for m.
        auto angular = [&](const vec& v_M, const vec& v_m, double w_M, double w_m) {
            const double vMt = (double)(v_M[0] * e.t[0] + v_M[1] * e.t[1]);
            const double vmt = (double)(v_m[0] * e.t[0] + v_m[1] * e.t[1]);
            return c.q_M * c.M * c.R_M * c.R_M * w_M + c.q_m * c.m * c.R_m * c.R_m * w_m - c.R_M * c.M * vMt +
                   c.R_m * c.m * vmt;
        };
        const double L_scale = (c.M + c.m) * (c.R_M + c.R_m) * (10 + c.R_M + c.R_m);
        BOOST_TEST(std::fabs(angular(out.v_M, out.v_m, out.w_M, out.w_m) - angular(c.v_M, c.v_m, c.w_M, c.w_m)) <=
                   scale * L_scale);
        // The energy change, and never a gain.
        const double dE = energy(c, out.v_M, out.v_m, out.w_M, out.w_m) - energy(c, c.v_M, c.v_m, c.w_M, c.w_m);
        const long double formula =
            -(1 - (long double)c.eps * c.eps) * e.m_r * e.g_n * e.g_n / 2 - e.J_t * (e.g_t - e.J_t / (2 * e.m_t));
        const double E_scale = energy(c, c.v_M, c.v_m, c.w_M, c.w_m) + 1;
        BOOST_TEST(std::fabs(dE - (double)formula) <= scale * E_scale);
        BOOST_TEST(dE <= scale * E_scale);
        // Newton's restitution along n; tangentially, g_t' = -beta g_t while sticking, and
        // never reversed past it while sliding.
        const double gn_after = (out.v_M[0] - out.v_m[0]) * e.n[0] + (out.v_M[1] - out.v_m[1]) * e.n[1];
        const double gt_after = (out.v_M[0] - out.v_m[0]) * e.t[0] + (out.v_M[1] - out.v_m[1]) * e.t[1] +
                                c.R_M * out.w_M + c.R_m * out.w_m;
        const double g_scale = 10 + 10 * (c.R_M + c.R_m);
        BOOST_TEST(std::fabs(gn_after + c.eps * (double)e.g_n) <= scale * g_scale);
        BOOST_TEST((gt_after + c.beta * (double)e.g_t) * (double)e.g_t >= -scale * g_scale * g_scale);
        if (std::isinf(c.mu))
            BOOST_TEST(std::fabs(gt_after + c.beta * (double)e.g_t) <= scale * g_scale);
    }
}

// The kernel in float and in long double: the inputs rounded to the type (the model sees
// the rounded ones), the outputs against the model within 8 ulps of the type (twice the
// bound; in long double, the model's own rounding, as large, is given as much again), and
// momentum, the energy change and its sign within a hundred of the type's ulps.
template <class T>
void check_in_precision(double ulps)
{
    using tvec = std::array<T, 2>;
    const auto as = [](const vec& v) { return tvec{T(v[0]), T(v[1])}; };
    const long double unit = std::numeric_limits<T>::epsilon();
    std::mt19937_64 random(sizeof(T) * 1000 + 22);
    int checked = 0;
    for (int n = 0; n < 1000; ++n) {
        collision c = drawn(random, 0.1, 10, 0.05);
        if (n % 5 == 0)
            c.mu = std::numeric_limits<double>::infinity();
        for (double* x : {&c.M, &c.m, &c.R_M, &c.R_m, &c.q_M, &c.q_m, &c.w_M, &c.w_m, &c.eps, &c.beta, &c.mu,
                          &c.C_M[0], &c.C_M[1], &c.C_m[0], &c.C_m[1], &c.v_M[0], &c.v_M[1], &c.v_m[0], &c.v_m[1]})
            *x = static_cast<double>(static_cast<T>(*x));
        const auto out = impact::collide_rough<T>(T(c.M), T(c.m), T(c.R_M), T(c.R_m), T(c.q_M), T(c.q_m), as(c.C_M),
                                                  as(c.C_m), as(c.v_M), as(c.v_m), T(c.w_M), T(c.w_m), T(c.eps),
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
            const long double speed = std::max({std::fabs(c.v_M[0]), std::fabs(c.v_M[1]), std::fabs(c.v_m[0]),
                                                std::fabs(c.v_m[1]), std::fabs(c.R_M * c.w_M), std::fabs(c.R_m * c.w_m)});
            const long double tolerance = ulps * speed * unit;
            const long double v_M[2] = {out.v_M[0], out.v_M[1]}, v_m[2] = {out.v_m[0], out.v_m[1]};
            for (int i = 0; i < 2; ++i) {
                const long double J = e.J_n * e.n[i] + e.J_t * e.t[i];
                BOOST_TEST(std::fabs(v_M[i] - (c.v_M[i] - J / c.M)) <= tolerance);
                BOOST_TEST(std::fabs(v_m[i] - (c.v_m[i] + J / c.m)) <= tolerance);
            }
            BOOST_TEST(std::fabs(out.w_M - (c.w_M - e.J_t / ((long double)c.q_M * c.M * c.R_M))) * c.R_M <= tolerance);
            BOOST_TEST(std::fabs(out.w_m - (c.w_m - e.J_t / ((long double)c.q_m * c.m * c.R_m))) * c.R_m <= tolerance);
            const long double scale = 100 * unit;
            for (int i = 0; i < 2; ++i) {
                const long double before = (long double)c.M * c.v_M[i] + (long double)c.m * c.v_m[i];
                const long double after = c.M * v_M[i] + c.m * v_m[i];
                BOOST_TEST(std::fabs(after - before) <= scale * (c.M + c.m) * 10);
            }
            const auto energy_of = [&](const long double* a, const long double* b, long double p, long double q) {
                return (c.M * (a[0] * a[0] + a[1] * a[1]) + c.m * (b[0] * b[0] + b[1] * b[1]) +
                        (long double)c.q_M * c.M * c.R_M * c.R_M * p * p + (long double)c.q_m * c.m * c.R_m * c.R_m * q * q) /
                       2;
            };
            const long double before_M[2] = {c.v_M[0], c.v_M[1]}, before_m[2] = {c.v_m[0], c.v_m[1]};
            const long double E_before = energy_of(before_M, before_m, c.w_M, c.w_m);
            const long double dE = energy_of(v_M, v_m, out.w_M, out.w_m) - E_before;
            const long double formula =
                -(1 - (long double)c.eps * c.eps) * e.m_r * e.g_n * e.g_n / 2 - e.J_t * (e.g_t - e.J_t / (2 * e.m_t));
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
    // eps = beta = 1, mu = +inf: no energy lost, however the spheres spin.
    collision c;
    c.v_M = {1, -2};
    c.v_m = {-0.5, 0.25};
    c.w_M = 4;
    c.w_m = -7;
    c.eps = 1;
    c.beta = 1;
    c.mu = std::numeric_limits<double>::infinity();
    const auto out = run(c);
    BOOST_REQUIRE(out.status == impact::status::ok);
    const double before = energy(c, c.v_M, c.v_m, c.w_M, c.w_m);
    BOOST_TEST(energy(c, out.v_M, out.v_m, out.w_M, out.w_m) == before, boost::test_tools::tolerance(1e-14));
}

// The fast form (impact::fast) within twice its bound of 16 ulps (as the accurate form is
// held to twice its 4 here).
BOOST_AUTO_TEST_CASE(the_fast_form_follows_the_model_within_its_bound)
{
    check_sticking_and_sliding(32, impact::fast);
    std::mt19937_64 random(77);
    for (int i = 0; i < 2000; ++i) {
        const collision d = drawn(random, 0.01, 100, 0.01);
        if (run(d, impact::fast).status == impact::status::ok)
            BOOST_TEST_CONTEXT("drawn collision " << i) check_against_model(d, 32, impact::fast);
    }
}

template <class... Form>
void check_refusals(Form... form)
{
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    struct bad {
        void (*spoil)(collision&);
        impact::status status;
    };
    const bad cases[] = {
        {[](collision& c) { c.m = 0; }, impact::status::invalid_mass},
        {[](collision& c) { c.R_M = 0; }, impact::status::invalid_radius},
        {[](collision& c) { c.R_m = std::numeric_limits<double>::infinity(); }, impact::status::invalid_radius},
        {[](collision& c) { c.q_M = 0; }, impact::status::invalid_inertia},
        {[](collision& c) { c.q_m = 0.7; }, impact::status::invalid_inertia},
        {[](collision& c) { c.eps = 1.5; }, impact::status::invalid_restitution},
        {[](collision& c) { c.beta = -1.5; }, impact::status::invalid_tangential_restitution},
        {[](collision& c) { c.beta = std::numeric_limits<double>::quiet_NaN(); },
         impact::status::invalid_tangential_restitution},
        {[](collision& c) { c.mu = -0.1; }, impact::status::invalid_friction},
        {[](collision& c) { c.mu = std::numeric_limits<double>::quiet_NaN(); }, impact::status::invalid_friction},
        {[](collision& c) { c.w_M = std::numeric_limits<double>::quiet_NaN(); }, impact::status::non_finite},
        {[](collision& c) { c.w_m = std::numeric_limits<double>::infinity(); }, impact::status::non_finite},
        {[](collision& c) { c.C_m = c.C_M; }, impact::status::coincident_centres},
        {[](collision& c) { c.v_M = {-1, 0}; }, impact::status::separating},
    };
    (void)nan;
    (void)inf;
    for (const bad& b : cases) {
        collision c;
        c.w_M = 2;
        c.w_m = -3;
        b.spoil(c);
        const auto out = run(c, form...);
        BOOST_TEST((out.status == b.status), "status " << static_cast<int>(out.status));
        // Everything returned as given, bit for bit.
        BOOST_TEST(std::memcmp(&out.v_M, &c.v_M, sizeof c.v_M) == 0);
        BOOST_TEST(std::memcmp(&out.v_m, &c.v_m, sizeof c.v_m) == 0);
        BOOST_TEST(std::memcmp(&out.w_M, &c.w_M, sizeof c.w_M) == 0);
        BOOST_TEST(std::memcmp(&out.w_m, &c.w_m, sizeof c.w_m) == 0);
    }
}

BOOST_AUTO_TEST_CASE(bad_input_is_refused_with_its_status)
{
    check_refusals();
}

BOOST_AUTO_TEST_CASE(the_fast_form_refuses_bad_input_alike)
{
    check_refusals(impact::fast);
}

template <class... Form>
void check_batch(Form... form)
{
    // Ordinary, sticking, sliding, head-on (g_t = 0 with mu = 0), mu = +inf, and refused
    // pairs of every status, in one batch: each pair's velocities, spins and status are
    // the scalar kernel's, bit for bit.
    std::mt19937_64 random(2121);
    const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
    const std::size_t count = 1003;  // not a multiple of a block
    impact::collide_rough_batch_arrays<double, 2> batch(count);
    std::vector<collision> pairs(count);
    for (std::size_t i = 0; i < count; ++i) {
        collision& c = pairs[i];
        c = drawn(random, 0.01, 100, 0.01);
        c.mu /= 2;
        switch (i % 16) {
        case 1: c.mu = inf; break;
        case 2: c.mu = 0; c.C_M = {0, 0}; c.C_m = {1, 0}; c.v_M = {1, 0}; c.v_m = {0, 0}; c.w_M = c.w_m = 0; break;
        case 3: c.R_M = -1; break;
        case 4: c.q_m = 0.9; break;
        case 5: c.beta = nan; break;
        case 6: c.mu = -1; break;
        case 7: c.w_m = inf; break;
        case 8: c.C_m = c.C_M; break;
        case 9: c.M = 1e-300; c.m = 1e300; break;
        case 10: c.mu = 1e-300; break;
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
    std::size_t resolved = 0;
    for (std::size_t i = 0; i < count; ++i) {
        const auto out = run(pairs[i], form...);
        resolved += out.status == impact::status::ok ? 1 : 0;
        BOOST_TEST_CONTEXT("pair " << i)
        {
            BOOST_TEST((batch.status()[i] == out.status));
            for (std::size_t axis = 0; axis < 2; ++axis) {
                BOOST_TEST(std::memcmp(&batch.v_M(axis)[i], &out.v_M[axis], sizeof(double)) == 0);
                BOOST_TEST(std::memcmp(&batch.v_m(axis)[i], &out.v_m[axis], sizeof(double)) == 0);
            }
            BOOST_TEST(std::memcmp(&batch.w_M()[i], &out.w_M, sizeof(double)) == 0);
            BOOST_TEST(std::memcmp(&batch.w_m()[i], &out.w_m, sizeof(double)) == 0);
        }
    }
    BOOST_TEST(resolved > count / 4);
}

BOOST_AUTO_TEST_CASE(spheres_at_rest_are_resolved_by_the_batch_loop_itself)
{
    // A sphere at rest, a centre at the origin, a line of centres along an axis: inputs that
    // are 0, whose products and quotients are 0 as they should be. The vector loop resolves
    // every such pair itself (status ok); it leaves to the scalar kernel (status underflow)
    // only a pair whose arithmetic may have left the normal range. Every pair of the
    // benchmark's batch, whose spheres m stand still, once went to the scalar kernel after
    // the loop, so that the batch ran slower than a loop of scalar calls.
    const std::size_t count = 64;
    impact::collide_rough_batch_arrays<double, 2> batch(count);
    for (std::size_t i = 0; i < count; ++i) {
        const double angle = i % 4 == 0 ? 0 : 0.1 * static_cast<double>(i);
        batch.M()[i] = 1 + 0.25 * static_cast<double>(i % 5);
        batch.m()[i] = 2;
        batch.R_M()[i] = 0.5;
        batch.R_m()[i] = 0.75;
        batch.q_M()[i] = 0.4;
        batch.q_m()[i] = 2.0 / 3;
        batch.eps()[i] = 0.8;
        batch.beta()[i] = 0.5;
        batch.mu()[i] = i % 2 ? 0.05 : 5.0;   // sliding, sticking
        batch.w_M()[i] = i % 3 ? 1.5 : 0.0;
        batch.w_m()[i] = 0;
        batch.C_M(0)[i] = batch.C_M(1)[i] = 0;
        batch.C_m(0)[i] = std::cos(angle);
        batch.C_m(1)[i] = i % 4 == 0 ? 0 : std::sin(angle);
        batch.v_M(0)[i] = batch.C_m(0)[i] + 0.25;
        batch.v_M(1)[i] = batch.C_m(1)[i];
        batch.v_m(0)[i] = batch.v_m(1)[i] = 0;
    }
    impact::detail::collide_rough_batch_2d<double>(
        count, batch.M(), batch.m(), batch.R_M(), batch.R_m(), batch.q_M(), batch.q_m(), batch.C_M(0), batch.C_M(1),
        batch.C_m(0), batch.C_m(1), batch.v_M(0), batch.v_M(1), batch.v_m(0), batch.v_m(1), batch.w_M(), batch.w_m(),
        batch.eps(), batch.beta(), batch.mu(), batch.status());
    for (std::size_t i = 0; i < count; ++i)
        BOOST_TEST((batch.status()[i] == impact::status::ok), "pair " << i << " left to the scalar kernel");
}

BOOST_AUTO_TEST_CASE(the_batch_gives_the_scalar_results_bit_for_bit)
{
    check_batch();
}

BOOST_AUTO_TEST_CASE(the_fast_batch_gives_the_fast_scalar_results_bit_for_bit)
{
    check_batch(impact::fast);
}
