// The generated kernel `impact::collide_wall` in 2D and 3D (derivations/wall_plane.toml,
// wall_space.toml): a smooth sphere against a fixed wall through P with normal n (of any
// length, out of the wall towards the sphere). Checked against the physics typed here, not
// read from Impact: v' = v - (1 + eps) (v.n) n/|n|^2 when the sphere approaches (v.n < 0),
// so that v'.n = -eps v.n (Newton's law of restitution, Eq. 5, against a body at rest), the
// velocity along the wall unchanged, the speed never gained; the sphere-sphere kernel
// `collide` with the other sphere fixed (mass +infinity, at rest, the line of centres along
// n) agrees; every refusal with its status and the velocity returned bit for bit; the batch
// loop gives the scalar results bit for bit. And `impact::collide_wall_rough` (derivations/
// rough_wall_plane.toml), a rough sphere that spins, against Walton's model typed here: the
// contact sticks, reversing the wall's tangential velocity relative to it, R w - v.t, scaled
// by beta, unless friction caps the tangential impulse at mu times the normal one; the
// angular momentum about the contact point kept; the rough sphere-sphere kernel with the
// other sphere fixed agrees. In space (derivations/rough_wall_space.toml) the spin is a vector:
// the same model with g = -v + R w x u, against the model typed here, the floor's closed
// forms, the plane's kernel for a hit in the plane, every refusal, and a spin about the normal,
// which changes nothing the contact sees.
#define BOOST_TEST_MODULE test_wall_kernel
#include <boost/test/unit_test.hpp>

#include <impact/collide_2d.hpp>
#include <impact/collide_3d.hpp>
#include <impact/collide_wall_2d.hpp>
#include <impact/collide_wall_3d.hpp>
#include <impact/collide_rough_2d.hpp>
#include <impact/collide_wall_rough_2d.hpp>
#include <impact/collide_wall_rough_3d.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <type_traits>
#include <vector>

namespace {

const double inf = std::numeric_limits<double>::infinity();
const double nan = std::numeric_limits<double>::quiet_NaN();

template <std::size_t N>
using vec = std::array<double, N>;

template <std::size_t N>
bool same_bits(const vec<N>& a, const vec<N>& b)
{
    return std::memcmp(a.data(), b.data(), sizeof(double) * N) == 0;
}

template <std::size_t N>
struct wall_hit {
    vec<N> P, n, C, v;
    double eps;
};

template <std::size_t N>
long double dot(const vec<N>& a, const vec<N>& b)
{
    long double s = 0;
    for (std::size_t k = 0; k < N; ++k)
        s += static_cast<long double>(a[k]) * b[k];
    return s;
}

// A sphere in front of a wall, moving towards it: P, n, v, eps at random, C = P + (a bit) n
// plus a displacement along the wall.
template <std::size_t N>
wall_hit<N> draw(std::mt19937_64& random)
{
    std::uniform_real_distribution<double> unit(-1, 1), fraction(0, 1), decade(-3, 3);
    wall_hit<N> h{};
    for (std::size_t k = 0; k < N; ++k) {
        h.P[k] = unit(random);
        h.n[k] = unit(random) * std::pow(10.0, decade(random) / 3);
        h.v[k] = unit(random);
    }
    // C = P + ahead n + d, d along the wall (its part along n taken out).
    const double ahead = fraction(random) + 0.01;
    vec<N> d{};
    for (double& x : d)
        x = unit(random);
    const long double along = dot(d, h.n) / dot(h.n, h.n);
    for (std::size_t k = 0; k < N; ++k)
        h.C[k] = h.P[k] + ahead * h.n[k] + static_cast<double>(d[k] - along * h.n[k]);
    if (dot(h.v, h.n) > 0)
        for (double& x : h.v)
            x = -x;
    h.eps = fraction(random);
    return h;
}

// `form`: nothing for the accurate form (4 ulps), impact::fast for the fast one (its bound, 16).
template <std::size_t N, class... Form>
void check_against_the_physics(std::uint64_t seed, double bound, Form... form)
{
    std::mt19937_64 random(seed);
    double worst = 0;
    int resolved = 0;
    for (int i = 0; i < 4000; ++i) {
        const wall_hit<N> h = draw<N>(random);
        const auto out = impact::collide_wall(h.P, h.n, h.C, h.v, h.eps, form...);
        if (out.status == impact::status::separating || out.status == impact::status::behind_the_wall)
            continue;  // v.n or (C - P).n rounded to 0
        BOOST_TEST_REQUIRE((out.status == impact::status::ok));
        ++resolved;
        const long double n2 = dot(h.n, h.n), vn = dot(h.v, h.n);
        long double scale = 0;
        std::array<long double, N> expected{};
        for (std::size_t k = 0; k < N; ++k) {
            expected[k] = h.v[k] - (1 + static_cast<long double>(h.eps)) * vn * h.n[k] / n2;
            scale = std::max({scale, std::fabs(expected[k]), std::fabs(static_cast<long double>(h.v[k]))});
        }
        for (std::size_t k = 0; k < N; ++k)
            worst = std::max(worst, static_cast<double>(std::fabs(out.v[k] - expected[k]) /
                                                        (scale * std::numeric_limits<double>::epsilon())));
        // Restitution along n, nothing along the wall, no speed gained (within rounding).
        const long double after_n = dot(out.v, h.n) / std::sqrt(n2);
        const double tolerance = 16 * std::numeric_limits<double>::epsilon() * static_cast<double>(scale);
        BOOST_TEST(std::fabs(after_n + h.eps * vn / std::sqrt(n2)) <= tolerance);
        for (std::size_t k = 0; k < N; ++k) {
            const long double along_before = h.v[k] - vn * h.n[k] / n2;
            const long double along_after = out.v[k] - dot(out.v, h.n) * h.n[k] / n2;
            BOOST_TEST(std::fabs(along_after - along_before) <= tolerance);
        }
        BOOST_TEST(dot(out.v, out.v) <= dot(h.v, h.v) * (1 + 16 * std::numeric_limits<double>::epsilon()));
    }
    BOOST_TEST(resolved > 3900);
    BOOST_TEST(worst <= bound, N << "D: worst " << worst << " ulps");
}

BOOST_AUTO_TEST_CASE(random_wall_hits_match_the_reflection_scaled_by_eps)
{
    check_against_the_physics<2>(5001, 4);
    check_against_the_physics<3>(5002, 4);
}

BOOST_AUTO_TEST_CASE(the_fast_form_matches_the_reflection_within_its_bound)
{
    check_against_the_physics<2>(5011, 16, impact::fast);
    check_against_the_physics<3>(5012, 16, impact::fast);
}

BOOST_AUTO_TEST_CASE(a_ball_dropped_on_the_floor_bounces_at_eps_times_its_speed)
{
    // The floor y = 0, normal (0, 2) (not a unit vector), a ball at height 1 falling at
    // (3, -4): it leaves at (3, 4 eps), eps = 1/2.
    const auto out = impact::collide_wall(vec<2>{5, 0}, vec<2>{0, 2}, vec<2>{0, 1}, vec<2>{3, -4}, 0.5);
    BOOST_TEST((out.status == impact::status::ok));
    BOOST_TEST(out.v[0] == 3.0);
    BOOST_TEST(out.v[1] == 2.0);
    // In 3D, a wall x = 1 facing -x, the sphere at x = 0 moving at (1, 2, 3), elastic.
    const auto out3 = impact::collide_wall(vec<3>{1, 7, -7}, vec<3>{-1, 0, 0}, vec<3>{0, 0, 0}, vec<3>{1, 2, 3}, 1.0);
    BOOST_TEST((out3.status == impact::status::ok));
    BOOST_TEST(out3.v[0] == -1.0);
    BOOST_TEST(out3.v[1] == 2.0);
    BOOST_TEST(out3.v[2] == 3.0);
}

// The wall is the sphere-sphere collision with the other sphere fixed: M = +infinity at rest,
// centred behind the wall along -n (r = C_M - C_m = -n); within a few ulps of the largest
// velocity (each kernel rounds its own way).
template <std::size_t N>
void check_against_a_fixed_sphere(std::uint64_t seed)
{
    std::mt19937_64 random(seed);
    for (int i = 0; i < 1000; ++i) {
        const wall_hit<N> h = draw<N>(random);
        const auto wall = impact::collide_wall(h.P, h.n, h.C, h.v, h.eps);
        if (wall.status != impact::status::ok)
            continue;
        // The sphere at the origin (only C_M - C_m matters), M at -n: exactly r = -n.
        vec<N> C_M{}, C_m{}, at_rest{};
        for (std::size_t k = 0; k < N; ++k)
            C_M[k] = -h.n[k];
        const auto sphere = impact::collide(inf, 1.0, C_M, C_m, at_rest, h.v, h.eps);
        BOOST_TEST_REQUIRE((sphere.status == impact::status::ok));
        BOOST_TEST(same_bits(sphere.v_M, at_rest));
        double scale = 0;
        for (std::size_t k = 0; k < N; ++k)
            scale = std::max({scale, std::fabs(h.v[k]), std::fabs(wall.v[k])});
        for (std::size_t k = 0; k < N; ++k)
            BOOST_TEST(std::fabs(sphere.v_m[k] - wall.v[k]) <= 8 * std::numeric_limits<double>::epsilon() * scale);
    }
}

BOOST_AUTO_TEST_CASE(the_wall_is_a_fixed_sphere_at_rest)
{
    check_against_a_fixed_sphere<2>(6001);
    check_against_a_fixed_sphere<3>(6002);
}

BOOST_AUTO_TEST_CASE(each_refusal_has_its_status_and_returns_the_velocity_bit_for_bit)
{
    using impact::status;
    struct refused {
        vec<2> P, n, C, v;
        double eps;
        status expected;
    };
    const vec<2> P{0, 0}, n{0, 1}, C{0, 1}, v{1, -1};
    for (const refused& r : {refused{P, n, C, v, 1.5, status::invalid_restitution},
                             refused{P, n, C, v, nan, status::invalid_restitution},
                             refused{P, n, C, {inf, -1}, 0.5, status::non_finite},
                             refused{P, {nan, 1}, C, v, 0.5, status::non_finite},
                             refused{{0, inf}, n, C, v, 0.5, status::non_finite},
                             refused{P, {0, 0}, C, v, 0.5, status::invalid_normal},
                             refused{P, n, {0, -1}, v, 0.5, status::behind_the_wall},
                             refused{P, n, {3, 0}, v, 0.5, status::behind_the_wall},  // centre on the wall
                             refused{P, n, C, {1, 1}, 0.5, status::separating},
                             refused{P, n, C, {1, 0}, 0.5, status::separating}}) {  // along the wall
        const auto out = impact::collide_wall(r.P, r.n, r.C, r.v, r.eps);
        BOOST_TEST((out.status == r.expected), "status " << static_cast<int>(out.status));
        BOOST_TEST(same_bits(out.v, r.v));
        const auto fast = impact::collide_wall(r.P, r.n, r.C, r.v, r.eps, impact::fast);  // the same guards
        BOOST_TEST((fast.status == r.expected), "fast form's status " << static_cast<int>(fast.status));
        BOOST_TEST(same_bits(fast.v, r.v));
    }
    // The first guard that fails: eps before the velocity, the normal before the side.
    BOOST_TEST((impact::collide_wall(P, {0, 0}, vec<2>{0, -1}, v, 2.0).status == status::invalid_restitution));
    BOOST_TEST((impact::collide_wall(P, {0, 0}, vec<2>{0, -1}, v, 0.5).status == status::invalid_normal));
}

template <std::size_t N, class... Form>
void check_batch(std::uint64_t seed, Form... form)
{
    std::mt19937_64 random(seed);
    const std::size_t count = 1003;
    std::vector<wall_hit<N>> hits(count);
    std::array<std::vector<double>, N> P, n, C, v;
    for (std::size_t k = 0; k < N; ++k)
        for (auto* a : {&P[k], &n[k], &C[k], &v[k]})
            a->resize(count);
    std::vector<double> eps(count);
    std::vector<impact::status> statuses(count);
    for (std::size_t i = 0; i < count; ++i) {
        wall_hit<N>& h = hits[i];
        h = draw<N>(random);
        switch (i % 9) {
        case 1: h.eps = 2; break;
        case 2: h.n = vec<N>{}; break;
        case 3: h.v[0] = nan; break;
        case 4: for (double& x : h.v) x = -x; break;
        case 5: h.n[0] *= 1e-200; h.n[N - 1] *= 1e-200; break;
        default: break;
        }
        for (std::size_t k = 0; k < N; ++k) {
            P[k][i] = h.P[k];
            n[k][i] = h.n[k];
            C[k][i] = h.C[k];
            v[k][i] = h.v[k];
        }
        eps[i] = h.eps;
    }
    impact::collide_wall_batch_data<double, N> data{};
    data.count = count;
    for (std::size_t k = 0; k < N; ++k) {
        data.P[k] = P[k].data();
        data.n[k] = n[k].data();
        data.C[k] = C[k].data();
        data.v[k] = v[k].data();
    }
    data.eps = eps.data();
    data.status = statuses.data();
    impact::collide_wall_batch(data, form...);
    std::size_t resolved = 0;
    for (std::size_t i = 0; i < count; ++i) {
        const wall_hit<N>& h = hits[i];
        const auto out = impact::collide_wall(h.P, h.n, h.C, h.v, h.eps, form...);
        resolved += out.status == impact::status::ok ? 1 : 0;
        BOOST_TEST_CONTEXT(N << "D, hit " << i)
        {
            BOOST_TEST((statuses[i] == out.status));
            for (std::size_t k = 0; k < N; ++k)
                BOOST_TEST(std::memcmp(&v[k][i], &out.v[k], sizeof(double)) == 0);
        }
    }
    BOOST_TEST(resolved > count / 3);
}

BOOST_AUTO_TEST_CASE(the_batch_gives_the_scalar_results_bit_for_bit)
{
    check_batch<2>(7001);
    check_batch<3>(7002);
}

BOOST_AUTO_TEST_CASE(the_fast_batch_gives_the_fast_scalar_results_bit_for_bit)
{
    check_batch<2>(7011, impact::fast);
    check_batch<3>(7012, impact::fast);
}

// A rough sphere (radius R, q, spin w) hits a wall: Walton's model in the frame of the unit
// normal u = n/|n| and t = z x u, in long double. The wall's velocity relative to the contact
// point: g_n = -v.u (> 0 approaching), g_t = R w - v.t; per unit mass, the normal impulse
// (1 + eps) g_n, the tangential one (1 + beta) q/(1 + q) g_t when it lies inside the friction
// cone, mu (1 + eps) g_n sign(g_t) otherwise; v' = v + j_n u + j_t t, w' = w - j_t/(q R).
struct rough_wall_hit {
    vec<2> P, n, C, v;
    double R, q, w, eps, beta, mu;
};

struct rough_after {
    std::array<long double, 2> v;
    long double w;
    bool sliding;
};

rough_after walton(const rough_wall_hit& h)
{
    const long double length = std::sqrt(dot(h.n, h.n));
    const long double ux = h.n[0] / length, uy = h.n[1] / length, tx = -uy, ty = ux;
    const long double g_n = -(h.v[0] * ux + h.v[1] * uy);
    const long double g_t = h.R * static_cast<long double>(h.w) - (h.v[0] * tx + h.v[1] * ty);
    const long double j_n = (1 + static_cast<long double>(h.eps)) * g_n;
    const long double stick = (1 + static_cast<long double>(h.beta)) * h.q / (1 + static_cast<long double>(h.q)) * g_t;
    const bool sliding = std::fabs(stick) > h.mu * j_n;
    const long double j_t = sliding ? h.mu * j_n * (g_t > 0 ? 1 : -1) : stick;
    return {{h.v[0] + j_n * ux + j_t * tx, h.v[1] + j_n * uy + j_t * ty}, h.w - j_t / (h.q * h.R), sliding};
}

rough_wall_hit draw_rough(std::mt19937_64& random)
{
    const wall_hit<2> h = draw<2>(random);
    std::uniform_real_distribution<double> unit(-1, 1), fraction(0, 1), decade(-2, 2);
    rough_wall_hit r{h.P, h.n, h.C, h.v, std::pow(10.0, decade(random) / 2), 0.05 + 0.6 * fraction(random),
                     unit(random) * std::pow(10.0, decade(random)), h.eps, unit(random),
                     fraction(random) < 0.25 ? inf : std::pow(10.0, decade(random))};
    return r;
}

BOOST_AUTO_TEST_CASE(a_rough_wall_follows_waltons_model)
{
    std::mt19937_64 random(8001);
    double worst = 0;
    int resolved = 0, slid = 0;
    for (int i = 0; i < 4000; ++i) {
        const rough_wall_hit h = draw_rough(random);
        const auto out = impact::collide_wall_rough(h.R, h.q, h.P, h.n, h.C, h.v, h.w, h.eps, h.beta, h.mu);
        if (out.status == impact::status::separating || out.status == impact::status::behind_the_wall)
            continue;
        BOOST_TEST_REQUIRE((out.status == impact::status::ok));
        ++resolved;
        const rough_after want = walton(h);
        slid += want.sliding;
        // Errors in ulps of the largest velocity (R w counted as one; w' scaled by R).
        long double scale = std::max({std::fabs(static_cast<long double>(h.v[0])), std::fabs(static_cast<long double>(h.v[1])),
                                      std::fabs(h.R * static_cast<long double>(h.w)), std::fabs(want.v[0]),
                                      std::fabs(want.v[1]), std::fabs(h.R * want.w)});
        const long double ulp = scale * std::numeric_limits<double>::epsilon();
        worst = std::max({worst, static_cast<double>(std::fabs(out.v[0] - want.v[0]) / ulp),
                          static_cast<double>(std::fabs(out.v[1] - want.v[1]) / ulp),
                          static_cast<double>(h.R * std::fabs(out.w - want.w) / ulp)});
        // The angular momentum about the contact point, q m R^2 w + m R (u x v), kept (m = 1).
        const long double length = std::sqrt(dot(h.n, h.n));
        auto about_contact = [&](long double vx, long double vy, long double w) {
            return h.q * h.R * h.R * w + h.R * (h.n[0] * vy - h.n[1] * vx) / length;
        };
        BOOST_TEST(std::fabs(about_contact(out.v[0], out.v[1], out.w) - about_contact(h.v[0], h.v[1], h.w)) <=
                   64 * h.R * ulp);
    }
    BOOST_TEST(resolved > 3900);
    BOOST_TEST(slid > 400);
    BOOST_TEST(resolved - slid > 400);
    BOOST_TEST(worst <= 4, "worst " << worst << " ulps");
}

BOOST_AUTO_TEST_CASE(a_spinning_ball_on_the_floor_sticks_or_slides)
{
    // The floor y = 0 with normal (0, 2); a solid ball (q = 2/5, R = 1/2) falling at (0, -1),
    // spinning at w = 7: g_n = 1, g_t = R w - v.t = 3.5 with t = (-1, 0). Elastic and perfectly
    // rough (eps = beta = 1), never sliding: j_t = 2 (2/7) 3.5 = 2, so v' = (0, 1) + 2 t = (-2, 1),
    // w' = 7 - 2/(0.4 * 0.5) = -3.
    const auto stuck = impact::collide_wall_rough(0.5, 0.4, vec<2>{0, 0}, vec<2>{0, 2}, vec<2>{0, 0.5},
                                                  vec<2>{0, -1}, 7.0, 1.0, 1.0, inf);
    BOOST_TEST((stuck.status == impact::status::ok));
    BOOST_TEST(stuck.v[0] == -2.0, boost::test_tools::tolerance(1e-15));
    BOOST_TEST(stuck.v[1] == 1.0, boost::test_tools::tolerance(1e-15));
    BOOST_TEST(stuck.w == -3.0, boost::test_tools::tolerance(1e-15));
    // mu = 1/4: mu (1 + eps) g_n = 1/2 < 2, the ball slides: j_t = 1/2, v' = (-1/2, 1), w' = 7 - 2.5 = 4.5.
    const auto slid = impact::collide_wall_rough(0.5, 0.4, vec<2>{0, 0}, vec<2>{0, 2}, vec<2>{0, 0.5},
                                                 vec<2>{0, -1}, 7.0, 1.0, 1.0, 0.25);
    BOOST_TEST(slid.v[0] == -0.5, boost::test_tools::tolerance(1e-15));
    BOOST_TEST(slid.v[1] == 1.0, boost::test_tools::tolerance(1e-15));
    BOOST_TEST(slid.w == 4.5, boost::test_tools::tolerance(1e-15));
    // A smooth contact (beta = -1, mu = 0) is collide_wall's reflection, the spin kept.
    const auto smooth = impact::collide_wall_rough(0.5, 0.4, vec<2>{5, 0}, vec<2>{0, 2}, vec<2>{0, 1},
                                                   vec<2>{3, -4}, 7.0, 0.5, -1.0, 0.0);
    BOOST_TEST(smooth.v[0] == 3.0);
    BOOST_TEST(smooth.v[1] == 2.0);
    BOOST_TEST(smooth.w == 7.0);
}

BOOST_AUTO_TEST_CASE(the_rough_wall_is_a_fixed_rough_sphere_at_rest)
{
    // collide_rough with M = +infinity at rest and not spinning, its centre at -n from the
    // sphere's: the line of centres along n (the other sphere's radius and q do not matter).
    std::mt19937_64 random(8002);
    int compared = 0;
    for (int i = 0; i < 1000; ++i) {
        const rough_wall_hit h = draw_rough(random);
        const auto wall = impact::collide_wall_rough(h.R, h.q, h.P, h.n, h.C, h.v, h.w, h.eps, h.beta, h.mu);
        if (wall.status != impact::status::ok)
            continue;
        const vec<2> C_M{-h.n[0], -h.n[1]}, C_m{0, 0}, at_rest{0, 0};
        const auto sphere = impact::collide_rough(inf, 1.0, 0.3, h.R, 0.4, h.q, C_M, C_m, at_rest, h.v, 0.0, h.w,
                                                  h.eps, h.beta, h.mu);
        BOOST_TEST_REQUIRE((sphere.status == impact::status::ok));
        BOOST_TEST(same_bits(sphere.v_M, at_rest));
        BOOST_TEST(sphere.w_M == 0.0);
        const double scale = std::max({std::fabs(h.v[0]), std::fabs(h.v[1]), std::fabs(h.R * h.w),
                                       std::fabs(wall.v[0]), std::fabs(wall.v[1]), std::fabs(h.R * wall.w)});
        const double tolerance = 8 * std::numeric_limits<double>::epsilon() * scale;
        BOOST_TEST(std::fabs(sphere.v_m[0] - wall.v[0]) <= tolerance);
        BOOST_TEST(std::fabs(sphere.v_m[1] - wall.v[1]) <= tolerance);
        BOOST_TEST(h.R * std::fabs(sphere.w_m - wall.w) <= tolerance);
        ++compared;
    }
    BOOST_TEST(compared > 900);
}

BOOST_AUTO_TEST_CASE(each_rough_refusal_has_its_status_and_returns_the_velocity_and_spin_bit_for_bit)
{
    using impact::status;
    struct refused {
        double R, q, eps, beta, mu, w;
        vec<2> n, C, v;
        status expected;
    };
    const vec<2> n{0, 1}, C{0, 1}, v{1, -1};
    for (const refused& r : {refused{0, 0.4, 0.5, 0, 1, 2, n, C, v, status::invalid_radius},
                             refused{inf, 0.4, 0.5, 0, 1, 2, n, C, v, status::invalid_radius},
                             refused{1, 0.7, 0.5, 0, 1, 2, n, C, v, status::invalid_inertia},
                             refused{1, 0, 0.5, 0, 1, 2, n, C, v, status::invalid_inertia},
                             refused{1, 0.4, 1.5, 0, 1, 2, n, C, v, status::invalid_restitution},
                             refused{1, 0.4, 0.5, 1.5, 1, 2, n, C, v, status::invalid_tangential_restitution},
                             refused{1, 0.4, 0.5, 0, -1, 2, n, C, v, status::invalid_friction},
                             refused{1, 0.4, 0.5, 0, nan, 2, n, C, v, status::invalid_friction},
                             refused{1, 0.4, 0.5, 0, 1, nan, n, C, v, status::non_finite},
                             refused{1, 0.4, 0.5, 0, 1, 2, {0, 0}, C, v, status::invalid_normal},
                             refused{1, 0.4, 0.5, 0, 1, 2, n, {0, -1}, v, status::behind_the_wall},
                             refused{1, 0.4, 0.5, 0, 1, 2, n, C, {1, 1}, status::separating}}) {
        for (const bool fast : {false, true}) {
            const auto out = fast ? impact::collide_wall_rough(r.R, r.q, vec<2>{0, 0}, r.n, r.C, r.v, r.w, r.eps,
                                                               r.beta, r.mu, impact::fast)
                                  : impact::collide_wall_rough(r.R, r.q, vec<2>{0, 0}, r.n, r.C, r.v, r.w, r.eps,
                                                               r.beta, r.mu);
            BOOST_TEST((out.status == r.expected), "status " << static_cast<int>(out.status) << (fast ? " (fast)" : ""));
            BOOST_TEST(same_bits(out.v, r.v));
            BOOST_TEST(std::memcmp(&out.w, &r.w, sizeof(double)) == 0);
        }
    }
}



// A rough sphere hits a wall in space: Walton's model with vector spins, in long double.
// u = n/|n|; the wall's velocity relative to the sphere's contact point (at -R u from its
// centre): g = -v + R w x u, g_n = g.u (> 0 approaching), g_t = g - g_n u; per unit mass the
// normal impulse (1 + eps) g_n along u, the tangential one (1 + beta) q/(1 + q) g_t inside
// the friction cone, mu (1 + eps) g_n g_t/|g_t| outside it; v' = v + j_n u + j_t,
// w' = w - u x j_t/(q R) (the impulse's moment at -R u over q m R^2).
struct rough_wall_hit_3d {
    vec<3> P, n, C, v, w;
    double R, q, eps, beta, mu;
};

struct rough_after_3d {
    std::array<long double, 3> v, w;
    bool sliding;
    long double g_n, slip, j_t;        ///< g.u, |g_t| and |j_t| before
    std::array<long double, 3> u, g_t;
};

std::array<long double, 3> cross(const std::array<long double, 3>& a, const std::array<long double, 3>& b)
{
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

long double dot(const std::array<long double, 3>& a, const std::array<long double, 3>& b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

rough_after_3d walton_3d(const rough_wall_hit_3d& h)
{
    const long double length = std::sqrt(dot(h.n, h.n));
    std::array<long double, 3> u, w, g, g_t;
    for (std::size_t k = 0; k < 3; ++k)
        u[k] = h.n[k] / length, w[k] = h.w[k];
    const std::array<long double, 3> w_x_u = cross(w, u);
    for (std::size_t k = 0; k < 3; ++k)
        g[k] = -static_cast<long double>(h.v[k]) + h.R * w_x_u[k];
    const long double g_n = g[0] * u[0] + g[1] * u[1] + g[2] * u[2];
    for (std::size_t k = 0; k < 3; ++k)
        g_t[k] = g[k] - g_n * u[k];
    const long double slip = std::sqrt(g_t[0] * g_t[0] + g_t[1] * g_t[1] + g_t[2] * g_t[2]);
    const long double j_n = (1 + static_cast<long double>(h.eps)) * g_n;
    const long double stick = (1 + static_cast<long double>(h.beta)) * h.q / (1 + static_cast<long double>(h.q));
    const bool sliding = stick * slip > h.mu * j_n;
    std::array<long double, 3> j_t;
    for (std::size_t k = 0; k < 3; ++k)
        j_t[k] = sliding ? h.mu * j_n * g_t[k] / slip : stick * g_t[k];
    const std::array<long double, 3> moment = cross(u, j_t);
    rough_after_3d after{};
    for (std::size_t k = 0; k < 3; ++k) {
        after.v[k] = h.v[k] + j_n * u[k] + j_t[k];
        after.w[k] = h.w[k] - moment[k] / (h.q * h.R);
    }
    after.sliding = sliding;
    after.g_n = g_n;
    after.slip = slip;
    after.j_t = sliding ? h.mu * j_n : stick * slip;
    after.u = u;
    after.g_t = g_t;
    return after;
}

rough_wall_hit_3d draw_rough_3d(std::mt19937_64& random)
{
    const wall_hit<3> h = draw<3>(random);
    std::uniform_real_distribution<double> unit(-1, 1), fraction(0, 1), decade(-2, 2);
    rough_wall_hit_3d r{h.P, h.n, h.C, h.v, {}, std::pow(10.0, decade(random) / 2), 0.05 + 0.6 * fraction(random),
                        h.eps, unit(random), 0};
    const double spin = std::pow(10.0, decade(random));
    for (double& x : r.w)
        x = unit(random) * spin;
    r.mu = fraction(random) < 0.25 ? inf : std::pow(10.0, decade(random));
    return r;
}

BOOST_AUTO_TEST_CASE(a_rough_wall_in_space_follows_waltons_model)
{
    std::mt19937_64 random(8101);
    double worst = 0;
    int resolved = 0, slid = 0;
    for (int i = 0; i < 4000; ++i) {
        const rough_wall_hit_3d h = draw_rough_3d(random);
        const auto out = impact::collide_wall_rough(h.R, h.q, h.P, h.n, h.C, h.v, h.w, h.eps, h.beta, h.mu);
        if (out.status == impact::status::separating || out.status == impact::status::behind_the_wall)
            continue;
        BOOST_TEST_REQUIRE((out.status == impact::status::ok));
        ++resolved;
        const rough_after_3d want = walton_3d(h);
        slid += want.sliding;
        // Errors in ulps of the largest velocity (R w counted as one; w' scaled by R).
        long double scale = 0;
        for (std::size_t k = 0; k < 3; ++k)
            scale = std::max({scale, std::fabs(static_cast<long double>(h.v[k])), std::fabs(h.R * static_cast<long double>(h.w[k])),
                              std::fabs(want.v[k]), std::fabs(h.R * want.w[k])});
        const long double ulp = scale * std::numeric_limits<double>::epsilon();
        for (std::size_t k = 0; k < 3; ++k)
            worst = std::max({worst, static_cast<double>(std::fabs(out.v[k] - want.v[k]) / ulp),
                              static_cast<double>(h.R * std::fabs(out.w[k] - want.w[k]) / ulp)});
        // The angular momentum about the contact point, q m R^2 w + R u x m v, kept (m = 1).
        const long double length = std::sqrt(dot(h.n, h.n));
        const std::array<long double, 3> u{h.n[0] / length, h.n[1] / length, h.n[2] / length};
        auto about_contact = [&](const std::array<long double, 3>& v, const std::array<long double, 3>& w) {
            const std::array<long double, 3> u_x_v = cross(u, v);
            std::array<long double, 3> L;
            for (std::size_t k = 0; k < 3; ++k)
                L[k] = h.q * h.R * h.R * w[k] + h.R * u_x_v[k];
            return L;
        };
        const auto before = about_contact({h.v[0], h.v[1], h.v[2]}, {h.w[0], h.w[1], h.w[2]});
        const auto after = about_contact({out.v[0], out.v[1], out.v[2]}, {out.w[0], out.w[1], out.w[2]});
        for (std::size_t k = 0; k < 3; ++k)
            BOOST_TEST(std::fabs(after[k] - before[k]) <= 64 * h.R * ulp);
        // The energy change per unit mass, v^2/2 + q R^2 w^2/2, is
        // -(1 - eps^2) g_n^2/2 - |j_t| (|g_t| - |j_t|/(2 m_t)) with m_t = q/(1 + q), never a
        // gain; the slip after, g_t' = g_t - |j_t| (1 + q)/q g_t/|g_t|, is never reversed past
        // -beta g_t (as derivations/rough_wall_space.toml proves, here on the compiled kernel).
        auto energy = [&](const std::array<long double, 3>& v, const std::array<long double, 3>& w) {
            return (dot(v, v) + h.q * h.R * h.R * dot(w, w)) / 2;
        };
        const std::array<long double, 3> v0{h.v[0], h.v[1], h.v[2]}, w0{h.w[0], h.w[1], h.w[2]};
        const std::array<long double, 3> v1{out.v[0], out.v[1], out.v[2]}, w1{out.w[0], out.w[1], out.w[2]};
        const long double dE = energy(v1, w1) - energy(v0, w0);
        const long double m_t = h.q / (1 + static_cast<long double>(h.q));
        const long double formula = -(1 - static_cast<long double>(h.eps) * h.eps) * want.g_n * want.g_n / 2 -
                                    want.j_t * (want.slip - want.j_t / (2 * m_t));
        const long double E_ulp = 64 * scale * ulp;
        BOOST_TEST(std::fabs(dE - formula) <= E_ulp, "hit " << i << ": " << dE << " against " << formula);
        BOOST_TEST(dE <= E_ulp, "hit " << i);
        const std::array<long double, 3> w1_x_u = cross(w1, want.u);
        std::array<long double, 3> g1;
        for (std::size_t k = 0; k < 3; ++k)
            g1[k] = -v1[k] + h.R * w1_x_u[k];
        const long double g1_n = dot(g1, want.u);
        long double past = 0;  // (g_t' + beta g_t).g_t: 0 sticking, >= 0 sliding
        for (std::size_t k = 0; k < 3; ++k)
            past += (g1[k] - g1_n * want.u[k] + h.beta * want.g_t[k]) * want.g_t[k];
        BOOST_TEST(past >= -64 * ulp * (want.slip + scale), "hit " << i);
    }
    BOOST_TEST(resolved > 3900);
    BOOST_TEST(slid > 400);
    BOOST_TEST(resolved - slid > 400);
    BOOST_TEST(worst <= 4, "worst " << worst << " ulps");
}

// A spin about the normal moves the contact point along nothing: w x u keeps only w's part
// across u, so the slip, the impulse and the velocity after are those without it, and the
// spin after is the one without it plus that part, unchanged. Exact inputs: n = (1, 2, 2),
// the spin across it a(2, -1, 0) + b(2, 2, -3) in eighths, and k n about it with k a power
// of 2 up to 2^17 (2^17 times what the contact sees), so that w = w_t + k n is the same
// number in float. Before the sliding impulse divided by |G_t| from G_t . G_t multiplied
// out, float refused 300 of these 4000 hits as out of range and erred by 9e7 ulps.
template <class Real>
void a_spin_about_the_normal_changes_nothing_else()
{
    using V = std::array<Real, 3>;
    std::mt19937_64 random(8103);
    std::uniform_int_distribution<int> eighths(-16, 16), power(6, 17);
    std::uniform_real_distribution<double> unit(-1, 1), fraction(0, 1);
    const V P{0, 0, 0}, n{1, 2, 2}, C{1, 2, 2};
    const Real R = Real(0.5), q = Real(0.4);
    const Real epsilon = std::numeric_limits<Real>::epsilon();
    double worst_v = 0, worst_w = 0;
    for (int i = 0; i < 4000; ++i) {
        V v{Real(unit(random)), Real(unit(random)), Real(unit(random))};
        if (v[0] + 2 * v[1] + 2 * v[2] >= 0)
            for (Real& x : v)
                x = -x;
        const Real a = Real(eighths(random)) / 8, b = Real(eighths(random)) / 8;
        const V w_t{2 * a + 2 * b, -a + 2 * b, -3 * b};
        const Real k = std::ldexp(Real(1), power(random)) * (fraction(random) < 0.5 ? 1 : -1);
        const V w{w_t[0] + k, w_t[1] + 2 * k, w_t[2] + 2 * k};
        const Real eps = Real(fraction(random)), beta = Real(unit(random)), mu = Real(std::pow(10.0, 2 * unit(random)));
        const auto without = impact::collide_wall_rough(R, q, P, n, C, v, w_t, eps, beta, mu);
        const auto spun = impact::collide_wall_rough(R, q, P, n, C, v, w, eps, beta, mu);
        BOOST_TEST_REQUIRE((without.status == impact::status::ok));
        BOOST_TEST_REQUIRE((spun.status == impact::status::ok), "refused hit " << i);
        // The velocity after in ulps of the velocities the contact sees; the spin's change
        // in ulps of the spin (it is added to w, 2^17 times larger).
        Real scale = 0, spin = 0;
        for (std::size_t c = 0; c < 3; ++c) {
            scale = std::max(scale, std::max(std::fabs(v[c]), std::max(R * std::fabs(w_t[c]), std::fabs(without.v[c]))));
            spin = std::max(spin, std::fabs(w[c]));
        }
        for (std::size_t c = 0; c < 3; ++c) {
            worst_v = std::max(worst_v, static_cast<double>(std::fabs(spun.v[c] - without.v[c]) / (scale * epsilon)));
            const Real change = (spun.w[c] - w[c]) - (without.w[c] - w_t[c]);
            worst_w = std::max(worst_w, static_cast<double>(std::fabs(change) / (spin * epsilon)));
        }
    }
    BOOST_TEST(worst_v <= 4, "velocity after: " << worst_v << " ulps");
    BOOST_TEST(worst_w <= 4, "spin's change: " << worst_w << " ulps");
}

BOOST_AUTO_TEST_CASE(a_spin_about_the_normal_changes_neither_the_impulse_nor_the_velocity_after)
{
    a_spin_about_the_normal_changes_nothing_else<float>();
    a_spin_about_the_normal_changes_nothing_else<double>();
    a_spin_about_the_normal_changes_nothing_else<long double>();
}

BOOST_AUTO_TEST_CASE(a_spinning_ball_on_the_floor_in_space_sticks_or_slides)
{
    // The floor z = 0 with normal (0, 0, 2); a solid ball (q = 2/5, R = 1/2) falling at
    // (0, 0, -1), spinning at w = (0, 7, 0): w x u = (7, 0, 0), g = (3.5, 0, 1), g_n = 1,
    // g_t = (3.5, 0, 0). Elastic and perfectly rough (eps = beta = 1), never sliding:
    // j_t = 2 (2/7) (3.5, 0, 0) = (2, 0, 0), v' = (0, 0, -1) + 2 (0, 0, 1) + (2, 0, 0) = (2, 0, 1),
    // w' = w - u x j_t/(q R) = (0, 7, 0) - (0, 2, 0)/0.2 = (0, -3, 0).
    const vec<3> floor{0, 0, 0}, up{0, 0, 2}, centre{0, 0, 0.5}, falling{0, 0, -1}, spin{0, 7, 0};
    const auto stuck = impact::collide_wall_rough(0.5, 0.4, floor, up, centre, falling, spin, 1.0, 1.0, inf);
    BOOST_TEST((stuck.status == impact::status::ok));
    const vec<3> stuck_v{2, 0, 1}, stuck_w{0, -3, 0};
    for (std::size_t k = 0; k < 3; ++k) {
        BOOST_TEST(stuck.v[k] == stuck_v[k], boost::test_tools::tolerance(1e-15));
        BOOST_TEST(stuck.w[k] == stuck_w[k], boost::test_tools::tolerance(1e-15));
    }
    // mu = 1/4: mu (1 + eps) g_n = 1/2 < 2, the ball slides: j_t = (1/2, 0, 0),
    // v' = (1/2, 0, 1), w' = (0, 7 - 2.5, 0) = (0, 4.5, 0).
    const auto slid = impact::collide_wall_rough(0.5, 0.4, floor, up, centre, falling, spin, 1.0, 1.0, 0.25);
    const vec<3> slid_v{0.5, 0, 1}, slid_w{0, 4.5, 0};
    for (std::size_t k = 0; k < 3; ++k) {
        BOOST_TEST(slid.v[k] == slid_v[k], boost::test_tools::tolerance(1e-15));
        BOOST_TEST(slid.w[k] == slid_w[k], boost::test_tools::tolerance(1e-15));
    }
    // A smooth contact (beta = -1, mu = 0) is collide_wall's reflection, the spin kept.
    const vec<3> v{3, 1, -4}, w{1, 7, -2};
    const auto smooth = impact::collide_wall_rough(0.5, 0.4, vec<3>{5, 0, 0}, up, vec<3>{0, 2, 1}, v, w, 0.5, -1.0, 0.0);
    BOOST_TEST(smooth.v[0] == 3.0);
    BOOST_TEST(smooth.v[1] == 1.0);
    BOOST_TEST(smooth.v[2] == 2.0);
    BOOST_TEST(same_bits(smooth.w, w));
}

BOOST_AUTO_TEST_CASE(a_rough_hit_in_the_plane_is_the_planes)
{
    // Everything in the x-y plane and the spin about z: the 3D kernel gives the 2D kernel's
    // velocity (z component 0) and spin (about z), derived separately (rough_wall_plane).
    std::mt19937_64 random(8102);
    int compared = 0;
    for (int i = 0; i < 1000; ++i) {
        const rough_wall_hit h = draw_rough(random);
        const auto plane = impact::collide_wall_rough(h.R, h.q, h.P, h.n, h.C, h.v, h.w, h.eps, h.beta, h.mu);
        if (plane.status != impact::status::ok)
            continue;
        const auto space = impact::collide_wall_rough(h.R, h.q, vec<3>{h.P[0], h.P[1], 0}, vec<3>{h.n[0], h.n[1], 0},
                                                      vec<3>{h.C[0], h.C[1], 0}, vec<3>{h.v[0], h.v[1], 0},
                                                      vec<3>{0, 0, h.w}, h.eps, h.beta, h.mu);
        BOOST_TEST_REQUIRE((space.status == impact::status::ok));
        const double scale = std::max({std::fabs(h.v[0]), std::fabs(h.v[1]), std::fabs(h.R * h.w), std::fabs(plane.v[0]),
                                       std::fabs(plane.v[1]), std::fabs(h.R * plane.w)});
        const double tolerance = 8 * std::numeric_limits<double>::epsilon() * scale;
        BOOST_TEST(std::fabs(space.v[0] - plane.v[0]) <= tolerance);
        BOOST_TEST(std::fabs(space.v[1] - plane.v[1]) <= tolerance);
        BOOST_TEST(std::fabs(space.v[2]) <= tolerance);
        BOOST_TEST(h.R * std::fabs(space.w[2] - plane.w) <= tolerance);
        BOOST_TEST(h.R * std::fabs(space.w[0]) <= tolerance);
        BOOST_TEST(h.R * std::fabs(space.w[1]) <= tolerance);
        ++compared;
    }
    BOOST_TEST(compared > 900);
}

BOOST_AUTO_TEST_CASE(each_rough_refusal_in_space_has_its_status_and_returns_velocity_and_spin_bit_for_bit)
{
    using impact::status;
    struct refused {
        double R, q, eps, beta, mu;
        vec<3> w, n, C, v;
        status expected;
    };
    const vec<3> w{2, -1, 3}, n{0, 0, 1}, C{0, 0, 1}, v{1, 0.5, -1};
    for (const refused& r : {refused{0, 0.4, 0.5, 0, 1, w, n, C, v, status::invalid_radius},
                             refused{inf, 0.4, 0.5, 0, 1, w, n, C, v, status::invalid_radius},
                             refused{1, 0.7, 0.5, 0, 1, w, n, C, v, status::invalid_inertia},
                             refused{1, 0, 0.5, 0, 1, w, n, C, v, status::invalid_inertia},
                             refused{1, 0.4, 1.5, 0, 1, w, n, C, v, status::invalid_restitution},
                             refused{1, 0.4, 0.5, 1.5, 1, w, n, C, v, status::invalid_tangential_restitution},
                             refused{1, 0.4, 0.5, 0, -1, w, n, C, v, status::invalid_friction},
                             refused{1, 0.4, 0.5, 0, nan, w, n, C, v, status::invalid_friction},
                             refused{1, 0.4, 0.5, 0, 1, {2, nan, 3}, n, C, v, status::non_finite},
                             refused{1, 0.4, 0.5, 0, 1, w, {0, 0, 0}, C, v, status::invalid_normal},
                             refused{1, 0.4, 0.5, 0, 1, w, n, {0, 0, -1}, v, status::behind_the_wall},
                             refused{1, 0.4, 0.5, 0, 1, w, n, C, {1, 0.5, 1}, status::separating}}) {
        for (const bool fast : {false, true}) {
            const auto out = fast ? impact::collide_wall_rough(r.R, r.q, vec<3>{0, 0, 0}, r.n, r.C, r.v, r.w, r.eps,
                                                               r.beta, r.mu, impact::fast)
                                  : impact::collide_wall_rough(r.R, r.q, vec<3>{0, 0, 0}, r.n, r.C, r.v, r.w, r.eps,
                                                               r.beta, r.mu);
            BOOST_TEST((out.status == r.expected), "status " << static_cast<int>(out.status) << (fast ? " (fast)" : ""));
            BOOST_TEST(same_bits(out.v, r.v));
            BOOST_TEST(same_bits(out.w, r.w));
        }
    }
}

// A spin's component k: the 2D spin is one number, the 3D spin a vector.
template <class Spin>
auto& spin(Spin& w, std::size_t k)
{
    if constexpr (std::is_scalar_v<Spin>)   // a number, or a pointer to the batch's array
        return w;
    else
        return w[k];
}

// The batch, in the plane or in space: every hit, refused ones among them, gives the scalar
// kernel's velocity, spin and status bit for bit.
template <class Hit, class... Form>
void check_rough_batch(std::uint64_t seed, Hit (*draw_hit)(std::mt19937_64&), Form... form)
{
    constexpr std::size_t N = std::tuple_size_v<decltype(Hit::P)>;
    constexpr std::size_t spins = N == 2 ? 1 : 3;
    std::mt19937_64 random(seed);
    const std::size_t count = 1003;
    std::vector<Hit> hits(count);
    std::array<std::vector<double>, N> P, n, C, v;
    std::array<std::vector<double>, spins> w;
    for (std::size_t k = 0; k < N; ++k)
        for (auto* a : {&P[k], &n[k], &C[k], &v[k]})
            a->resize(count);
    for (std::vector<double>& a : w)
        a.resize(count);
    std::vector<double> R(count), q(count), eps(count), beta(count), mu(count);
    std::vector<impact::status> statuses(count);
    for (std::size_t i = 0; i < count; ++i) {
        Hit& h = hits[i];
        h = draw_hit(random);
        switch (i % 9) {
        case 1: h.beta = 2; break;
        case 2: h.n = vec<N>{}; break;
        case 3: spin(h.w, spins == 1 ? 0 : 1) = nan; break;
        case 4: for (double& x : h.v) x = -x; break;
        case 5: h.q = 1; break;
        default: break;
        }
        for (std::size_t k = 0; k < N; ++k) {
            P[k][i] = h.P[k];
            n[k][i] = h.n[k];
            C[k][i] = h.C[k];
            v[k][i] = h.v[k];
        }
        for (std::size_t k = 0; k < spins; ++k)
            w[k][i] = spin(h.w, k);
        R[i] = h.R, q[i] = h.q, eps[i] = h.eps, beta[i] = h.beta, mu[i] = h.mu;
    }
    impact::collide_wall_rough_batch_data<double, N> data{};
    data.count = count;
    for (std::size_t k = 0; k < N; ++k) {
        data.P[k] = P[k].data();
        data.n[k] = n[k].data();
        data.C[k] = C[k].data();
        data.v[k] = v[k].data();
    }
    for (std::size_t k = 0; k < spins; ++k)
        spin(data.w, k) = w[k].data();
    data.R = R.data(), data.q = q.data(), data.eps = eps.data(), data.beta = beta.data(), data.mu = mu.data();
    data.status = statuses.data();
    impact::collide_wall_rough_batch(data, form...);
    std::size_t resolved = 0;
    for (std::size_t i = 0; i < count; ++i) {
        const Hit& h = hits[i];
        auto out = impact::collide_wall_rough(h.R, h.q, h.P, h.n, h.C, h.v, h.w, h.eps, h.beta, h.mu, form...);
        resolved += out.status == impact::status::ok ? 1 : 0;
        BOOST_TEST_CONTEXT("hit " << i)
        {
            BOOST_TEST((statuses[i] == out.status));
            for (std::size_t k = 0; k < N; ++k)
                BOOST_TEST(std::memcmp(&v[k][i], &out.v[k], sizeof(double)) == 0);
            for (std::size_t k = 0; k < spins; ++k)
                BOOST_TEST(std::memcmp(&w[k][i], &spin(out.w, k), sizeof(double)) == 0);
        }
    }
    BOOST_TEST(resolved > count / 3);
}

BOOST_AUTO_TEST_CASE(the_rough_batch_gives_the_scalar_results_bit_for_bit)
{
    check_rough_batch(9001, draw_rough);
    check_rough_batch(9011, draw_rough, impact::fast);
}

BOOST_AUTO_TEST_CASE(the_rough_batch_in_space_gives_the_scalar_results_bit_for_bit)
{
    check_rough_batch(9101, draw_rough_3d);
    check_rough_batch(9111, draw_rough_3d, impact::fast);
}

} // namespace
