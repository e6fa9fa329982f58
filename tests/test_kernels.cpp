// The generated kernels, compiled, against the symbolic results evaluated by CLN.
//
// Inputs are drawn (seeded) over the declared domains; each kernel output is compared
// with the derived result at the same inputs, taken exactly, at 50 digits. Errors are
// counted in ulps of the collision's velocity scale: the largest velocity magnitude
// among the inputs and the exact outputs (for J, that scale times the reduced mass).
// Bounds: 4 ulps for velocities; 8 for J, whose magnitude reaches 4 times that scale
// ((1 + eps) (v_M - v_m)), so that its own rounding alone costs 2 ulps of the scale.
#define BOOST_TEST_MODULE test_kernels
#include <boost/test/unit_test.hpp>

#include "impact/impact.hpp"

#include "engine/expr/domain.h"
#include "engine/library/library.h"
#include "verify/accuracy.h"

#include <algorithm>
#include <cfenv>
#include <cstdint>
#include <cstring>
#include <iostream>
#include <limits>
#include <string>
#include <utility>
#include <vector>

// Built with -ffast-math too (test_kernels_fast_math, built with -Ofast, and _fp_contract): the test's own
// arithmetic, which measures the kernels', as written. The kernels keep theirs by themselves.
IMPACT_PRECISE_BEGIN

namespace {

using namespace impact;

const engine::derivation& eq8()
{
    static const engine::library lib =
        engine::derive_all(engine::read_directory(IMPACT_SOURCE_DIR "/derivations"), "inelastic_line");
    return lib.derived.at("inelastic_line");
}

GiNaC::ex sym(const std::string& name)
{
    return eq8().symbols.find(name)->symbol;
}

struct worst {
    double ulps = 0;
    std::string where;
    void update(double e, const std::string& at)
    {
        if (e > ulps) {
            ulps = e;
            where = at;
        }
    }
};

template <class Real, class... Form>
void check_collide_line(const char* type, double velocity_bound, double impulse_bound, Form... form)
{
    constexpr int samples = 4000;
    engine::uniform_stream stream(20261121);
    const engine::domain positive{engine::domain::kind::positive};
    const engine::domain velocity{engine::domain::kind::real};
    const engine::domain restitution{engine::domain::kind::interval, 0, 1};
    const engine::derivation& d = eq8();
    const GiNaC::ex exact_vM = d.find_result("v_M_after")->value;
    const GiNaC::ex exact_vm = d.find_result("v_m_after")->value;
    const GiNaC::ex exact_J = d.find_result("J")->value;

    worst vM, vm, J;
    for (int i = 0; i < samples; ++i) {
        // Masses up to 10^±6 apart; the inputs rounded to Real first, so that the kernel
        // and the reference see the same numbers.
        const Real M = static_cast<Real>(std::pow(engine::draw(positive, stream), 4.6));
        const Real m = static_cast<Real>(std::pow(engine::draw(positive, stream), 4.6));
        // The faster sphere named M: m is ahead of M on the line, so the pair approaches
        // when v_M > v_m; collide_line leaves a separating pair as it is.
        const Real v_1 = static_cast<Real>(engine::draw(velocity, stream));
        const Real v_2 = static_cast<Real>(engine::draw(velocity, stream));
        const Real v_M = std::max(v_1, v_2), v_m = std::min(v_1, v_2);
        const Real eps = static_cast<Real>(engine::draw(restitution, stream));
        const auto out = impact::collide_line(M, m, v_M, v_m, eps, form...);
        BOOST_REQUIRE((out.status == impact::status::ok || v_M == v_m));

        const GiNaC::exmap point = {{sym("M"), verify::exact(M)},     {sym("m"), verify::exact(m)},
                                    {sym("v_M"), verify::exact(v_M)}, {sym("v_m"), verify::exact(v_m)},
                                    {sym("eps"), verify::exact(eps)}};
        const GiNaC::numeric want_vM = verify::evaluate(exact_vM, point);
        const GiNaC::numeric want_vm = verify::evaluate(exact_vm, point);
        const GiNaC::numeric want_J = verify::evaluate(exact_J, point);
        const GiNaC::numeric scale = std::max({GiNaC::abs(verify::exact(v_M)), GiNaC::abs(verify::exact(v_m)),
                                               GiNaC::abs(want_vM), GiNaC::abs(want_vm)});
        const GiNaC::numeric reduced_mass = verify::exact(M) * verify::exact(m) / (verify::exact(M) + verify::exact(m));
        const std::string at = "sample " + std::to_string(i);
        vM.update(verify::ulps(out.v_M, want_vM, scale), at);
        vm.update(verify::ulps(out.v_m, want_vm, scale), at);
        J.update(verify::ulps(out.J, want_J, scale * reduced_mass), at);
    }
    std::cout << "collide_line<" << type << (sizeof...(Form) ? ", impact::fast" : "") << "> over " << samples << " samples, worst error in ulps of the velocity "
              << "scale: v_M " << vM.ulps << " (" << vM.where << "), v_m " << vm.ulps << " (" << vm.where
              << "), J/mu " << J.ulps << " (" << J.where << ")\n";
    BOOST_TEST(vM.ulps <= velocity_bound);
    BOOST_TEST(vm.ulps <= velocity_bound);
    BOOST_TEST(J.ulps <= impulse_bound);
}

} // namespace

BOOST_AUTO_TEST_CASE(collide_line_double_is_within_a_few_ulps_of_cln)
{
    check_collide_line<double>("double", 4, 8);
}

BOOST_AUTO_TEST_CASE(collide_line_float_is_within_a_few_ulps_of_cln)
{
    check_collide_line<float>("float", 4, 8);
}

BOOST_AUTO_TEST_CASE(collide_line_long_double_is_within_a_few_ulps_of_cln)
{
    check_collide_line<long double>("long double", 4, 8);
}

// The fast form within its declared bound, 16 ulps of each output's scale (the test's J
// bound twice its velocities', as above).
BOOST_AUTO_TEST_CASE(the_fast_collide_line_is_within_its_bound_in_every_type)
{
    check_collide_line<float>("float", 16, 32, impact::fast);
    check_collide_line<double>("double", 16, 32, impact::fast);
    check_collide_line<long double>("long double", 16, 32, impact::fast);
}

BOOST_AUTO_TEST_CASE(equal_masses_elastic_collision_swaps_velocities)
{
    // A physics law, not the derivation: equal masses exchange velocities when elastic.
    const auto out = impact::collide_line(2.0, 2.0, 3.0, -1.0, 1.0);
    BOOST_TEST(out.v_M == -1.0);
    BOOST_TEST(out.v_m == 3.0);
    BOOST_TEST(out.J == 8.0);  // M (v_M - v'_M) = 2 * (3 - -1)
}

BOOST_AUTO_TEST_CASE(perfectly_inelastic_collision_moves_on_at_the_centre_of_mass_velocity)
{
    const auto out = impact::collide_line(3.0f, 1.0f, 1.0f, -3.0f, 0.0f);
    BOOST_TEST(out.v_M == 0.0f);  // (3 * 1 + 1 * -3) / 4
    BOOST_TEST(out.v_m == 0.0f);
}

// ---------------------------------------------------------------------------------
// The lab-frame kernels and the scalar kernels of the public API, against closed forms
// typed here (the impulse along the line of centres), and their physical properties.

namespace {

using GiNaC::numeric;

numeric ex_of(double x)
{
    return verify::exact(x);
}

// A seeded stream of collisions in D dimensions that approach each other, drawn over
// wide ranges (masses 1e-6..1e6, velocities and positions 1e-2..1e2 in magnitude).
template <std::size_t D>
struct collision {
    double M, m, eps;
    std::array<double, D> C_M, C_m, v_M, v_m;
};

template <std::size_t D>
collision<D> draw_collision(engine::uniform_stream& s)
{
    auto decades = [&](double lo, double hi) { return std::pow(10.0, lo + (hi - lo) * s.next()); };
    auto signed_value = [&] { return (s.next() < 0.5 ? -1 : 1) * decades(-2, 2); };
    collision<D> c;
    c.M = decades(-6, 6);
    c.m = decades(-6, 6);
    c.eps = s.next();
    double closing = 0;
    for (std::size_t i = 0; i < D; ++i) {
        c.C_M[i] = signed_value();
        c.C_m[i] = signed_value();
        c.v_M[i] = signed_value();
        c.v_m[i] = signed_value();
        closing += (c.v_M[i] - c.v_m[i]) * (c.C_M[i] - c.C_m[i]);
    }
    if (closing > 0)
        for (std::size_t i = 0; i < D; ++i) {
            c.v_M[i] = -c.v_M[i];
            c.v_m[i] = -c.v_m[i];
        }
    return c;
}

// v'_M = v_M - (1 + eps) m/(M + m) ((v_M - v_m).r / r.r) r, and v'_m with +M: the
// impulse along the line of centres r = C_M - C_m, exactly.
template <std::size_t D>
std::pair<std::array<numeric, D>, std::array<numeric, D>> exact_collision(const collision<D>& c)
{
    numeric dot = 0, rr = 0;
    std::array<numeric, D> r;
    for (std::size_t i = 0; i < D; ++i) {
        r[i] = ex_of(c.C_M[i]) - ex_of(c.C_m[i]);
        dot += (ex_of(c.v_M[i]) - ex_of(c.v_m[i])) * r[i];
        rr += r[i] * r[i];
    }
    const numeric k = (1 + ex_of(c.eps)) * dot / ((ex_of(c.M) + ex_of(c.m)) * rr);
    std::array<numeric, D> a, b;
    for (std::size_t i = 0; i < D; ++i) {
        a[i] = ex_of(c.v_M[i]) - k * ex_of(c.m) * r[i];
        b[i] = ex_of(c.v_m[i]) + k * ex_of(c.M) * r[i];
    }
    return {a, b};
}

// `form`: nothing for the accurate form (bound 4 ulps), impact::fast for the fast one (its
// declared bound, 16).
template <std::size_t D, class... Form>
void check_collide_accuracy(double bound, Form... form)
{
    engine::uniform_stream s(D * 7919);
    double worst = 0;
    for (int n = 0; n < 3000; ++n) {
        const collision<D> c = draw_collision<D>(s);
        const auto out = impact::collide(c.M, c.m, c.C_M, c.C_m, c.v_M, c.v_m, c.eps, form...);
        BOOST_REQUIRE(out.status == impact::status::ok);
        const auto [a, b] = exact_collision(c);
        numeric scale = 0;
        for (std::size_t i = 0; i < D; ++i)
            scale = std::max({scale, GiNaC::abs(ex_of(c.v_M[i])), GiNaC::abs(ex_of(c.v_m[i])), GiNaC::abs(a[i]),
                              GiNaC::abs(b[i])});
        for (std::size_t i = 0; i < D; ++i) {
            worst = std::max(worst, verify::ulps(out.v_M[i], a[i], scale));
            worst = std::max(worst, verify::ulps(out.v_m[i], b[i], scale));
        }
    }
    std::cout << "collide<double" << (sizeof...(Form) ? ", impact::fast" : "") << "> in " << D
              << "D over 3000 collisions: worst error " << worst << " ulps of the largest velocity\n";
    BOOST_TEST(worst <= bound);
}

template <std::size_t D, class... Form>
void check_momentum_and_symmetry(Form... form)
{
    engine::uniform_stream s(D * 104729);
    double worst_momentum = 0, worst_swap = 0;
    for (int n = 0; n < 3000; ++n) {
        const collision<D> c = draw_collision<D>(s);
        const auto out = impact::collide(c.M, c.m, c.C_M, c.C_m, c.v_M, c.v_m, c.eps, form...);
        // The same collision with the spheres named the other way round.
        const auto swapped = impact::collide(c.m, c.M, c.C_m, c.C_M, c.v_m, c.v_M, c.eps, form...);
        BOOST_REQUIRE(swapped.status == impact::status::ok);
        double speed = 0;
        for (std::size_t i = 0; i < D; ++i)
            speed = std::max({speed, std::abs(c.v_M[i]), std::abs(c.v_m[i]), std::abs(out.v_M[i]), std::abs(out.v_m[i])});
        for (std::size_t i = 0; i < D; ++i) {
            // Momentum before and after, exactly: the difference in ulps of (M + m) times the speed.
            const numeric before = ex_of(c.M) * ex_of(c.v_M[i]) + ex_of(c.m) * ex_of(c.v_m[i]);
            const numeric after = ex_of(c.M) * ex_of(out.v_M[i]) + ex_of(c.m) * ex_of(out.v_m[i]);
            const numeric momentum_scale = (ex_of(c.M) + ex_of(c.m)) * ex_of(speed);
            worst_momentum = std::max(worst_momentum, verify::ulps(after, before, momentum_scale, 53));
            worst_swap = std::max(worst_swap, verify::ulps(swapped.v_m[i], ex_of(out.v_M[i]), ex_of(speed), 53));
            worst_swap = std::max(worst_swap, verify::ulps(swapped.v_M[i], ex_of(out.v_m[i]), ex_of(speed), 53));
        }
    }
    std::cout << "collide<double" << (sizeof...(Form) ? ", impact::fast" : "") << "> in " << D
              << "D: momentum conserved to " << worst_momentum
              << " ulps of (M + m) times the largest velocity; swapping the spheres agrees to " << worst_swap
              << " ulps\n";
    BOOST_TEST(worst_momentum <= 8.0);
    BOOST_TEST(worst_swap <= 8.0);
}

} // namespace

BOOST_AUTO_TEST_CASE(collide_in_2d_is_within_4_ulps_of_the_exact_impulse_along_the_line_of_centres)
{
    check_collide_accuracy<2>(4);
}

BOOST_AUTO_TEST_CASE(collide_in_3d_is_within_4_ulps_of_the_exact_impulse_along_the_line_of_centres)
{
    check_collide_accuracy<3>(4);
}

BOOST_AUTO_TEST_CASE(the_fast_collide_is_within_its_bound_of_16_ulps_of_the_exact_impulse)
{
    check_collide_accuracy<2>(16, impact::fast);
    check_collide_accuracy<3>(16, impact::fast);
}

BOOST_AUTO_TEST_CASE(the_fast_collide_conserves_momentum_and_does_not_care_which_sphere_is_named_first)
{
    check_momentum_and_symmetry<2>(impact::fast);
    check_momentum_and_symmetry<3>(impact::fast);
}

// Nearly grazing contacts: the relative velocity almost perpendicular to the line of
// centres, so that (v_M - v_m).r cancels down to the rounding of the inputs (about 2^-53
// of |v||r|). With v_M = 0, v'_M = -k m r is the impulse itself, and it must be right to
// a few ulps of its own size, not only of the largest velocity: the compensated dot
// product must carry the cancellation (a double-double sum not renormalised after it
// cancels loses several bits here).
BOOST_AUTO_TEST_CASE(collide_keeps_the_impulse_of_a_nearly_grazing_contact_to_a_few_ulps_of_itself)
{
    engine::uniform_stream s(4243);
    double worst = 0;
    int counted = 0;
    for (int n = 0; n < 20000; ++n) {
        const double x = 0.5 + s.next(), y = 0.5 + s.next(), speed = 1 + 9 * s.next();
        collision<2> c{1 + s.next(), 1 + s.next(), s.next(), {x, y}, {0, 0}, {0, 0}, {speed * y, -speed * x}};
        // (v_M - v_m).r is what the rounding of v_m left: approaching when it is negative.
        const numeric dot = -(ex_of(c.v_m[0]) * ex_of(x) + ex_of(c.v_m[1]) * ex_of(y));
        if (dot.is_zero())
            continue;
        if (dot.is_positive())
            c.v_m = {-c.v_m[0], -c.v_m[1]};
        const auto out = impact::collide(c.M, c.m, c.C_M, c.C_m, c.v_M, c.v_m, c.eps);
        if (out.status == impact::status::separating)
            continue;  // the guard's own, rounded, (v_M - v_m).r had the other sign
        BOOST_REQUIRE(out.status == impact::status::ok);
        const auto exact = exact_collision(c).first;
        for (std::size_t i = 0; i < 2; ++i)
            worst = std::max(worst, verify::ulps(out.v_M[i], exact[i], GiNaC::abs(exact[i])));
        ++counted;
    }
    std::cout << "collide<double>, " << counted << " nearly grazing contacts: the impulse within " << worst
              << " ulps of itself\n";
    BOOST_TEST(counted > 5000);
    BOOST_TEST(worst <= 4.0);
}

namespace {

// The velocities after a collision depend on the masses only through their ratio and on
// the centres only through the direction of the line joining them: scaling every mass by
// 2^a and every position by 2^b, both exact in floating point, must give the same
// velocities bit for bit, however large or small the scales, while every value the
// kernel computes stays in the range of doubles.
template <std::size_t D>
void check_scale_invariance()
{
    engine::uniform_stream s(D * 31337);
    const std::pair<int, int> scales[] = {{300, 100}, {-300, -100}, {500, -200}, {-500, 200}, {-900, 30}};
    int compared = 0;
    for (int n = 0; n < 500; ++n) {
        const collision<D> c = draw_collision<D>(s);
        const auto out = impact::collide(c.M, c.m, c.C_M, c.C_m, c.v_M, c.v_m, c.eps);
        BOOST_REQUIRE(out.status == impact::status::ok);
        for (const auto& [a, b] : scales) {
            std::array<double, D> C_M, C_m;
            for (std::size_t i = 0; i < D; ++i) {
                C_M[i] = std::ldexp(c.C_M[i], b);
                C_m[i] = std::ldexp(c.C_m[i], b);
            }
            const auto scaled = impact::collide(std::ldexp(c.M, a), std::ldexp(c.m, a), C_M, C_m, c.v_M, c.v_m, c.eps);
            BOOST_REQUIRE(scaled.status == impact::status::ok);
            for (std::size_t i = 0; i < D; ++i) {
                BOOST_TEST(std::memcmp(&scaled.v_M[i], &out.v_M[i], sizeof(double)) == 0);
                BOOST_TEST(std::memcmp(&scaled.v_m[i], &out.v_m[i], sizeof(double)) == 0);
            }
            ++compared;
        }
    }
    BOOST_TEST(compared == 2500);
}

} // namespace

BOOST_AUTO_TEST_CASE(collide_gives_the_same_velocities_at_every_scale_of_mass_and_length)
{
    check_scale_invariance<2>();
    check_scale_invariance<3>();
}

BOOST_AUTO_TEST_CASE(collide_conserves_momentum_and_does_not_care_which_sphere_is_named_first_2d)
{
    check_momentum_and_symmetry<2>();
}

BOOST_AUTO_TEST_CASE(collide_conserves_momentum_and_does_not_care_which_sphere_is_named_first_3d)
{
    check_momentum_and_symmetry<3>();
}

BOOST_AUTO_TEST_CASE(energy_loss_is_the_energy_the_output_velocities_lost)
{
    engine::uniform_stream s(31337);
    double worst = 0, worst_exact = 0;
    for (int n = 0; n < 3000; ++n) {
        const double M = std::pow(10.0, -3 + 6 * s.next()), m = std::pow(10.0, -3 + 6 * s.next());
        // The faster sphere named M, so that collide_line below resolves the collision.
        const double v_1 = 20 * s.next() - 10, v_2 = 20 * s.next() - 10, eps = s.next();
        const double v_M = std::max(v_1, v_2), v_m = std::min(v_1, v_2);
        const double dE = impact::energy_loss(M, m, v_M, v_m, eps);
        BOOST_REQUIRE(dE <= 0);
        // Against the closed form -(1 - eps^2) M m (v_M - v_m)^2 / (2 (M + m)), exactly.
        const numeric d = ex_of(v_M) - ex_of(v_m);
        const numeric exact = -(1 - ex_of(eps) * ex_of(eps)) * ex_of(M) * ex_of(m) * d * d / (2 * (ex_of(M) + ex_of(m)));
        worst_exact = std::max(worst_exact, verify::ulps(dE, exact, exact));
        // Against E' - E of collide_line's outputs, in ulps of the kinetic energy E.
        const auto out = impact::collide_line(M, m, v_M, v_m, eps);
        auto energy = [&](double a, double b) {
            return (ex_of(M) * ex_of(a) * ex_of(a) + ex_of(m) * ex_of(b) * ex_of(b)) / 2;
        };
        const numeric E = energy(v_M, v_m);
        worst = std::max(worst, verify::ulps(ex_of(dE), energy(out.v_M, out.v_m) - E, E, 53));
    }
    std::cout << "energy_loss<double>: " << worst_exact << " ulps of the exact loss at worst; agrees with E' - E "
              << "of collide_line's outputs to " << worst << " ulps of E\n";
    BOOST_TEST(worst_exact <= 4.0);
    BOOST_TEST(worst <= 16.0);
}

BOOST_AUTO_TEST_CASE(scatter_angle_is_within_4_ulps_of_the_arccosine_of_eq14)
{
    engine::uniform_stream s(2718);
    double worst = 0;
    const auto saved = GiNaC::Digits;
    GiNaC::Digits = 60;
    for (int n = 0; n < 2000; ++n) {
        // Head-on (v_perp tiny) to grazing (v_perp large), eps anywhere in [0, 1).
        const double v_par = std::pow(10.0, -2 + 4 * s.next()), v_perp = std::pow(10.0, -14 + 16 * s.next());
        const double eps = s.next() * 0.999;
        const double theta = impact::scatter_angle(v_par, v_perp, eps);
        const numeric a = (1 - ex_of(eps)) * ex_of(v_par);
        const numeric cos_theta = a / GiNaC::sqrt(a * a + 4 * ex_of(v_perp) * ex_of(v_perp));
        const numeric exact = GiNaC::acos(cos_theta);
        worst = std::max(worst, verify::ulps(theta, exact, exact));
    }
    GiNaC::Digits = saved;
    std::cout << "scatter_angle<double>: worst error " << worst << " ulps of theta\n";
    BOOST_TEST(worst <= 4.0);
    BOOST_TEST(impact::scatter_angle(1.0, 0.5, 1.0) == std::acos(0.0));  // elastic: a right angle
}

BOOST_AUTO_TEST_CASE(the_batch_kernel_gives_the_scalar_results_bit_for_bit)
{
    constexpr std::size_t n = 512;
    engine::uniform_stream s(99);
    std::vector<double> M(n), m(n), eps(n);
    std::array<std::vector<double>, 3> C_M, C_m, v_M, v_m, v_M0, v_m0;
    for (auto* a : {&C_M, &C_m, &v_M, &v_m})
        for (auto& component : *a)
            component.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const collision<3> c = draw_collision<3>(s);
        M[i] = c.M;
        m[i] = i % 7 == 0 ? -1.0 : c.m;          // some invalid masses
        eps[i] = c.eps;
        for (std::size_t d = 0; d < 3; ++d) {
            C_M[d][i] = c.C_M[d];
            C_m[d][i] = c.C_m[d];
            v_M[d][i] = i % 5 == 0 ? -c.v_M[d] : c.v_M[d];  // some separating pairs
            v_m[d][i] = i % 5 == 0 ? -c.v_m[d] : c.v_m[d];
        }
    }
    v_M0 = v_M;
    v_m0 = v_m;
    // Counts around the batch's blocks of 8 pairs and its reading 64 pairs ahead; the pairs
    // past the count are left alone.
    for (const std::size_t count : {std::size_t{0}, std::size_t{1}, std::size_t{7}, std::size_t{8}, std::size_t{9},
                                    std::size_t{64}, std::size_t{65}, std::size_t{73}, n}) {
        v_M = v_M0;
        v_m = v_m0;
        std::vector<impact::status> status(n, impact::status::separating);
        impact::collide_batch_data<double, 3> data{count,
                                                   M.data(),
                                                   m.data(),
                                                   {C_M[0].data(), C_M[1].data(), C_M[2].data()},
                                                   {C_m[0].data(), C_m[1].data(), C_m[2].data()},
                                                   {v_M[0].data(), v_M[1].data(), v_M[2].data()},
                                                   {v_m[0].data(), v_m[1].data(), v_m[2].data()},
                                                   eps.data(),
                                                   status.data()};
        impact::collide_batch(data);
        std::size_t resolved = 0;
        for (std::size_t i = 0; i < n; ++i) {
            auto r = impact::collide(M[i], m[i], {C_M[0][i], C_M[1][i], C_M[2][i]}, {C_m[0][i], C_m[1][i], C_m[2][i]},
                                     {v_M0[0][i], v_M0[1][i], v_M0[2][i]}, {v_m0[0][i], v_m0[1][i], v_m0[2][i]},
                                     eps[i]);
            if (i >= count)  // not in the batch: untouched
                r = {{v_M0[0][i], v_M0[1][i], v_M0[2][i]}, {v_m0[0][i], v_m0[1][i], v_m0[2][i]}, impact::status::separating};
            BOOST_TEST((r.status == status[i]), "pair " << i << " of a batch of " << count);
            resolved += r.status == impact::status::ok ? 1 : 0;
            for (std::size_t d = 0; d < 3; ++d) {
                BOOST_TEST(std::memcmp(&r.v_M[d], &v_M[d][i], sizeof(double)) == 0);
                BOOST_TEST(std::memcmp(&r.v_m[d], &v_m[d][i], sizeof(double)) == 0);
            }
        }
        if (count == n)
            BOOST_TEST(resolved > n / 2);  // most pairs collide: the comparison covers the arithmetic
    }
}

// Inputs that allow no collision, each with the status the kernels must give, and a
// collision that is resolved (status ok), in 2D.
struct bad_pair {
    double M, m, eps;
    std::array<double, 2> C_M, C_m, v_M, v_m;
    impact::status expected;
};

std::vector<bad_pair> bad_pairs()
{
    using impact::status;
    const std::array<double, 2> C_M{1, 0}, C_m{0, 0}, v_M{-1, 0.5}, v_m{1, -0.25};
    const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
    return {
        {2, 1, 0.5, C_m, C_m, v_M, v_m, status::coincident_centres},       // no line of action
        {0, 1, 0.5, C_M, C_m, v_M, v_m, status::invalid_mass},
        {2, -1, 0.5, C_M, C_m, v_M, v_m, status::invalid_mass},
        {nan, 1, 0.5, C_M, C_m, v_M, v_m, status::invalid_mass},
        {2, -inf, 0.5, C_M, C_m, v_M, v_m, status::invalid_mass},
        {2, 1, 1.5, C_M, C_m, v_M, v_m, status::invalid_restitution},
        {2, 1, -0.1, C_M, C_m, v_M, v_m, status::invalid_restitution},
        {2, 1, nan, C_M, C_m, v_M, v_m, status::invalid_restitution},
        {inf, inf, 0.5, C_M, C_m, v_M, v_m, status::invalid_mass},     // two fixed spheres
        {2, 1, 0.5, C_M, C_m, {inf, 0}, v_m, status::non_finite},
        {2, 1, 0.5, {nan, 0}, C_m, v_M, v_m, status::non_finite},
        {2, 1, 0.5, C_M, {0, nan}, v_M, v_m, status::non_finite},
        {2, 1, 0.5, C_M, C_m, v_M, {1, -inf}, status::non_finite},
        {2, 1, 0.5, C_M, C_m, {1, 0.5}, v_m, status::separating},           // M moves away from m
        {2, 1, 0.5, C_M, C_m, {1, 0}, {1, 0}, status::separating},          // no relative motion
        {0, 1, 2, C_m, C_m, {inf, 0}, v_m, status::invalid_mass},           // the first guard that fails
    };
}

// Finite inputs whose collision leaves the range of the floating-point type Real: the
// kernels must refuse them (status out_of_range, velocities unchanged) rather than return
// infinities or NaNs as a resolved collision, or divide by zero. Every value is exact in
// Real (and so in double).
template <class Real>
std::vector<bad_pair> out_of_range_pairs()
{
    using impact::status;
    using limits = std::numeric_limits<Real>;
    const double max = limits::max(), e = limits::min_exponent;
    const std::array<double, 2> C_m{0, 0}, v_M{-1, 0.5}, v_m{1, -0.25};
    // Masses and a distance so small that (M + m)|r|^2 underflows (to a subnormal in
    // double, to 0 in float).
    const double tiny_mass = std::ldexp(1.0, static_cast<int>(e / 2) - 20);
    const double tiny_distance = std::ldexp(1.0, static_cast<int>(e / 4) - 10);
    return {
        {2, 1, 0.5, {static_cast<double>(4 * std::sqrt(limits::max())), 0}, C_m, v_M, v_m, status::out_of_range},  // |r|^2 overflows
        {2, 1, 0.5, {0.75 * max, 0}, {-0.75 * max, 0}, v_M, v_m, status::out_of_range},  // C_M - C_m overflows
        {tiny_mass, tiny_mass, 0.5, {tiny_distance, 0}, C_m, v_M, v_m, status::out_of_range},
        // Head-on, eps = 1, a light sphere hit by one 2^20 times heavier: it would leave
        // at about 1.25 times the largest Real.
        {1, 1 << 20, 1, {1, 0}, C_m, {-max / 4, 0}, {max / 2, 0}, status::out_of_range},
    };
}

BOOST_AUTO_TEST_CASE(inputs_that_allow_no_collision_leave_the_velocities_unchanged_with_a_status)
{
    using impact::status;
    std::vector<bad_pair> cases = bad_pairs();
    for (const bad_pair& b : out_of_range_pairs<double>())
        cases.push_back(b);
    for (const bad_pair& b : cases) {
        std::feclearexcept(FE_ALL_EXCEPT);
        const auto out = impact::collide(b.M, b.m, b.C_M, b.C_m, b.v_M, b.v_m, b.eps);
        BOOST_TEST(std::fetestexcept(FE_DIVBYZERO) == 0);  // nothing divides by zero, even silently
        BOOST_TEST((out.status == b.expected));
        for (std::size_t d = 0; d < 2; ++d) {
            BOOST_TEST(std::memcmp(&out.v_M[d], &b.v_M[d], sizeof(double)) == 0);
            BOOST_TEST(std::memcmp(&out.v_m[d], &b.v_m[d], sizeof(double)) == 0);
        }
    }
    // And a head-on hit of equal masses with eps = 1 exchanges the velocities.
    const auto out = impact::collide(1.0, 1.0, std::array<double, 2>{1, 0}, std::array<double, 2>{0, 0},
                                     std::array<double, 2>{-1, 0}, std::array<double, 2>{1, 0}, 1.0);
    BOOST_TEST((out.status == status::ok));
    BOOST_TEST(out.v_M[0] == 1.0);
    BOOST_TEST(out.v_m[0] == -1.0);
}

namespace {

// The out-of-range pairs in the plane z = 0 of space, or in 2D, in the type Real.
template <class Real, std::size_t D>
void check_out_of_range(const bad_pair& b)
{
    std::array<Real, D> C_M{}, C_m{}, v_M{}, v_m{};
    for (std::size_t d = 0; d < 2; ++d) {
        C_M[d] = static_cast<Real>(b.C_M[d]);
        C_m[d] = static_cast<Real>(b.C_m[d]);
        v_M[d] = static_cast<Real>(b.v_M[d]);
        v_m[d] = static_cast<Real>(b.v_m[d]);
    }
    std::feclearexcept(FE_ALL_EXCEPT);
    const auto out = impact::collide(static_cast<Real>(b.M), static_cast<Real>(b.m), C_M, C_m, v_M, v_m,
                                     static_cast<Real>(b.eps));
    BOOST_TEST(std::fetestexcept(FE_DIVBYZERO) == 0);
    BOOST_TEST((out.status == impact::status::out_of_range));
    BOOST_TEST(std::memcmp(out.v_M.data(), v_M.data(), sizeof v_M) == 0);
    BOOST_TEST(std::memcmp(out.v_m.data(), v_m.data(), sizeof v_m) == 0);
}

} // namespace

BOOST_AUTO_TEST_CASE(collisions_that_leave_the_floating_point_range_are_refused_with_a_status)
{
    for (const bad_pair& b : out_of_range_pairs<double>()) {
        check_out_of_range<double, 2>(b);
        check_out_of_range<double, 3>(b);
    }
    for (const bad_pair& b : out_of_range_pairs<float>()) {
        check_out_of_range<float, 2>(b);
        check_out_of_range<float, 3>(b);
    }
}

// The batch loop decides every status without branches and computes every pair: each bad
// pair, between resolved ones so that one vector of the loop holds several statuses, must
// get the scalar kernel's status and keep its velocities, with nothing divided by zero.
template <class Real>
void check_batch_statuses(bool with_status, const std::vector<bad_pair>& cases)
{
    using impact::status;
    std::vector<bad_pair> pairs;
    for (const bad_pair& b : cases) {
        pairs.push_back(b);
        pairs.push_back({3, 2, 0.75, {0.5, 1}, {0, -0.5}, {-1, -2}, {0.25, 1}, status::ok});
    }
    const std::size_t n = pairs.size();
    std::vector<Real> M(n), m(n), eps(n);
    std::array<std::vector<Real>, 2> C_M, C_m, v_M, v_m;
    for (auto* a : {&C_M, &C_m, &v_M, &v_m})
        for (auto& component : *a)
            component.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        M[i] = static_cast<Real>(pairs[i].M);
        m[i] = static_cast<Real>(pairs[i].m);
        eps[i] = static_cast<Real>(pairs[i].eps);
        for (std::size_t d = 0; d < 2; ++d) {
            C_M[d][i] = static_cast<Real>(pairs[i].C_M[d]);
            C_m[d][i] = static_cast<Real>(pairs[i].C_m[d]);
            v_M[d][i] = static_cast<Real>(pairs[i].v_M[d]);
            v_m[d][i] = static_cast<Real>(pairs[i].v_m[d]);
        }
    }
    const auto v_M0 = v_M, v_m0 = v_m;
    std::vector<status> statuses(n, status::ok);
    impact::collide_batch_data<Real, 2> data{n,           M.data(),     m.data(),
                                             {C_M[0].data(), C_M[1].data()}, {C_m[0].data(), C_m[1].data()},
                                             {v_M[0].data(), v_M[1].data()}, {v_m[0].data(), v_m[1].data()},
                                             eps.data(),  with_status ? statuses.data() : nullptr};
    std::feclearexcept(FE_ALL_EXCEPT);
    impact::collide_batch(data);
    BOOST_TEST(std::fetestexcept(FE_DIVBYZERO) == 0);  // a pair not resolved divides by 1
    for (std::size_t i = 0; i < n; ++i) {
        using pair = std::array<Real, 2>;
        const auto r = impact::collide(M[i], m[i], pair{C_M[0][i], C_M[1][i]}, pair{C_m[0][i], C_m[1][i]},
                                       pair{v_M0[0][i], v_M0[1][i]}, pair{v_m0[0][i], v_m0[1][i]}, eps[i]);
        BOOST_TEST((r.status == pairs[i].expected));
        if (with_status)
            BOOST_TEST((statuses[i] == pairs[i].expected));
        for (std::size_t d = 0; d < 2; ++d) {
            BOOST_TEST(std::memcmp(&r.v_M[d], &v_M[d][i], sizeof(Real)) == 0);
            BOOST_TEST(std::memcmp(&r.v_m[d], &v_m[d][i], sizeof(Real)) == 0);
            if (pairs[i].expected != status::ok) {
                BOOST_TEST(std::memcmp(&v_M0[d][i], &v_M[d][i], sizeof(Real)) == 0);
                BOOST_TEST(std::memcmp(&v_m0[d][i], &v_m[d][i], sizeof(Real)) == 0);
            }
        }
    }
}

BOOST_AUTO_TEST_CASE(the_batch_kernel_gives_each_pair_the_scalar_status_and_divides_nothing_by_zero)
{
    std::vector<bad_pair> in_double = bad_pairs(), in_float = bad_pairs();
    for (const bad_pair& b : out_of_range_pairs<double>())
        in_double.push_back(b);
    for (const bad_pair& b : out_of_range_pairs<float>())
        in_float.push_back(b);
    check_batch_statuses<double>(true, in_double);
    check_batch_statuses<double>(false, in_double);
    check_batch_statuses<float>(true, in_float);
}

// The arrays of a batch in one allocation, as collide_batch_arrays lays them out: every
// array where the documentation puts it, 64 + 256 k bytes past a page boundary (modulo
// 4 KiB) for the k-th (M, m, C_M, C_m, v_M, v_m by axis, eps, status), none overlapping.
template <class Real, std::size_t N>
void check_batch_arrays_layout(std::size_t count)
{
    impact::collide_batch_arrays<Real, N> arrays(count);
    BOOST_TEST(arrays.count() == count);
    std::vector<std::pair<const unsigned char*, std::size_t>> in_order;  // start, bytes
    auto add = [&](const auto* array) { in_order.emplace_back(reinterpret_cast<const unsigned char*>(array), count * sizeof(*array)); };
    add(arrays.M());
    add(arrays.m());
    for (std::size_t axis = 0; axis < N; ++axis)
        add(arrays.C_M(axis));
    for (std::size_t axis = 0; axis < N; ++axis)
        add(arrays.C_m(axis));
    for (std::size_t axis = 0; axis < N; ++axis)
        add(arrays.v_M(axis));
    for (std::size_t axis = 0; axis < N; ++axis)
        add(arrays.v_m(axis));
    add(arrays.eps());
    add(arrays.status());
    BOOST_TEST(in_order.size() == 4 * N + 4);
    for (std::size_t k = 0; k < in_order.size(); ++k) {
        const auto address = reinterpret_cast<std::uintptr_t>(in_order[k].first);
        BOOST_TEST(address % 64 == 0u);
        BOOST_TEST(address % 4096 == (64 + 256 * k) % 4096, "array " << k << " of " << count << " pairs");
        if (k > 0)
            BOOST_TEST(in_order[k - 1].first + in_order[k - 1].second <= in_order[k].first);
    }

    // Every value written stays as written (no array overlaps another), and data() names
    // the same arrays.
    for (std::size_t i = 0; i < count; ++i) {
        arrays.M()[i] = static_cast<Real>(i);
        arrays.v_m(N - 1)[i] = -static_cast<Real>(i);
        arrays.eps()[i] = Real(0.5);
        arrays.status()[i] = impact::status::separating;
    }
    const impact::collide_batch_data<Real, N> data = arrays.data();
    BOOST_TEST(data.count == count);
    BOOST_TEST(data.M == arrays.M());
    BOOST_TEST(data.C_m[0] == arrays.C_m(0));
    BOOST_TEST(data.v_m[N - 1] == arrays.v_m(N - 1));
    BOOST_TEST(data.eps == arrays.eps());
    BOOST_TEST(data.status == arrays.status());
    for (std::size_t i = 0; i < count; ++i) {
        BOOST_TEST(data.M[i] == static_cast<Real>(i));
        BOOST_TEST(data.v_m[N - 1][i] == -static_cast<Real>(i));
        BOOST_TEST(data.eps[i] == Real(0.5));
        BOOST_TEST((data.status[i] == impact::status::separating));
    }
}

BOOST_AUTO_TEST_CASE(batch_arrays_start_where_the_documentation_says_and_overlap_nothing)
{
    // Counts around one page of doubles (512) and of floats (1024), and none.
    for (std::size_t count : {0, 1, 511, 512, 513, 1024, 5000}) {
        check_batch_arrays_layout<double, 2>(count);
        check_batch_arrays_layout<double, 3>(count);
        check_batch_arrays_layout<float, 3>(count);
        check_batch_arrays_layout<long double, 2>(count);
    }
}

BOOST_AUTO_TEST_CASE(a_batch_in_its_own_arrays_gives_the_scalar_results_bit_for_bit)
{
    constexpr std::size_t n = 100;
    engine::uniform_stream s(7);
    impact::collide_batch_arrays<double, 3> batch(n);
    std::vector<collision<3>> drawn;
    for (std::size_t i = 0; i < n; ++i) {
        drawn.push_back(draw_collision<3>(s));
        const collision<3>& c = drawn.back();
        batch.M()[i] = c.M;
        batch.m()[i] = c.m;
        batch.eps()[i] = c.eps;
        for (std::size_t d = 0; d < 3; ++d) {
            batch.C_M(d)[i] = c.C_M[d];
            batch.C_m(d)[i] = c.C_m[d];
            batch.v_M(d)[i] = c.v_M[d];
            batch.v_m(d)[i] = c.v_m[d];
        }
    }
    impact::collide_batch(batch.data());
    std::size_t resolved = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const collision<3>& c = drawn[i];
        const auto r = impact::collide(c.M, c.m, c.C_M, c.C_m, c.v_M, c.v_m, c.eps);
        BOOST_TEST((batch.status()[i] == r.status));
        resolved += r.status == impact::status::ok ? 1 : 0;
        for (std::size_t d = 0; d < 3; ++d) {
            BOOST_TEST(std::memcmp(&r.v_M[d], &batch.v_M(d)[i], sizeof(double)) == 0);
            BOOST_TEST(std::memcmp(&r.v_m[d], &batch.v_m(d)[i], sizeof(double)) == 0);
        }
    }
    BOOST_TEST(resolved > 0u);
}

BOOST_AUTO_TEST_CASE(batch_arrays_move_and_refuse_a_count_no_allocation_can_hold)
{
    impact::collide_batch_arrays<double, 2> first(10);
    first.M()[9] = 4.5;
    const double* where = first.M();
    impact::collide_batch_arrays<double, 2> second(std::move(first));
    BOOST_TEST(second.count() == 10u);
    BOOST_TEST(second.M() == where);
    BOOST_TEST(second.M()[9] == 4.5);
    BOOST_TEST(first.count() == 0u);  // NOLINT: the object moved from holds no arrays
    BOOST_TEST(first.M() == nullptr);
    BOOST_TEST(first.data().v_M[1] == nullptr);
    impact::collide_batch_arrays<double, 2> third(3);
    third = std::move(second);
    BOOST_TEST(third.count() == 10u);
    BOOST_TEST(third.M()[9] == 4.5);

    // One pair more than the address space holds, at 16 doubles a pair (3D: M, m, eps, 12
    // coordinates and a status) or 12 (2D); 15 floats and a status of 8 bytes.
    const std::size_t bytes = std::numeric_limits<std::size_t>::max();
    BOOST_CHECK_THROW((impact::collide_batch_arrays<double, 3>(bytes / (16 * 8) + 1)), std::bad_array_new_length);
    BOOST_CHECK_THROW((impact::collide_batch_arrays<double, 2>(bytes / (12 * 8) + 1)), std::bad_array_new_length);
    BOOST_CHECK_THROW((impact::collide_batch_arrays<float, 3>(bytes / (15 * 4 + 8) + 1)), std::bad_array_new_length);
    BOOST_CHECK_THROW((impact::collide_batch_arrays<double, 3>(std::numeric_limits<std::size_t>::max())),
                      std::bad_array_new_length);
}

BOOST_AUTO_TEST_CASE(arrays_crowd_one_page_offset_when_more_than_half_start_within_256_bytes)
{
    // Starts given as addresses: page p, offset o within it.
    auto at = [](std::uintptr_t page, std::uintptr_t offset) { return reinterpret_cast<const void*>(page * 4096 + offset); };
    std::array<const void*, 9> starts{};
    for (std::size_t k = 0; k < 9; ++k)
        starts[k] = at(100 + 7 * k, 16);  // one by one, each past an allocator's 16-byte header
    BOOST_TEST(impact::detail::crowded(starts));
    for (std::size_t k = 0; k < 9; ++k)
        starts[k] = at(100 + 7 * k, 64 + 256 * k);  // staggered
    BOOST_TEST(!impact::detail::crowded(starts));
    for (std::size_t k = 0; k < 4; ++k)
        starts[k] = at(100 + 7 * k, 4000 + 20 * k);  // 4 of 9 within 256 bytes, across a page's end
    BOOST_TEST(!impact::detail::crowded(starts));
    starts[4] = at(3, 4090 + 150);  // a fifth: more than half
    BOOST_TEST(impact::detail::crowded(starts));
    starts[4] = at(3, 4000 + 256);  // 256 bytes past the first: not within
    BOOST_TEST(!impact::detail::crowded(starts));
}

BOOST_AUTO_TEST_CASE(a_batch_whose_arrays_share_a_page_offset_gives_the_scalar_results_bit_for_bit)
{
    // Every array at the same offset within its pages (the loop reads them as they are: with its
    // sure block, skewed reading lost, and kernels without one read them skewed). Counts
    // around its blocks of 8 pairs, its reading 64 pairs ahead and its leads of up to 18
    // blocks (144 pairs).
    constexpr std::size_t most = 1000, stride = 1024;  // pairs at most; array k starts 8 KiB after array k - 1
    engine::uniform_stream s(2026);
    std::vector<collision<3>> drawn;
    for (std::size_t i = 0; i < most; ++i)
        drawn.push_back(draw_collision<3>(s));
    for (std::size_t count : {0, 1, 7, 8, 9, 16, 17, 63, 64, 65, 72, 143, 144, 145, 151, 152, 153, 160, 300, 1000}) {
        std::vector<double> storage(15 * stride);
        auto array = [&](std::size_t k) { return storage.data() + k * stride; };
        std::vector<impact::status> status(count + 1, impact::status::separating);
        for (std::size_t i = 0; i < count; ++i) {
            const collision<3>& c = drawn[i];
            array(0)[i] = c.M;
            array(1)[i] = i % 11 == 3 ? 0.0 : c.m;  // some invalid masses
            array(14)[i] = c.eps;
            for (std::size_t d = 0; d < 3; ++d) {
                array(2 + d)[i] = c.C_M[d];
                array(5 + d)[i] = c.C_m[d];
                array(8 + d)[i] = c.v_M[d];
                array(11 + d)[i] = c.v_m[d];
            }
        }
        impact::collide_batch_data<double, 3> data{count, array(0), array(1), {array(2), array(3), array(4)},
                                                   {array(5), array(6), array(7)}, {array(8), array(9), array(10)},
                                                   {array(11), array(12), array(13)}, array(14), status.data()};
        BOOST_TEST(impact::detail::crowded(std::array<const void*, 9>{data.M, data.m, data.C_M[0], data.C_M[1], data.C_M[2],
                                                                       data.C_m[0], data.C_m[1], data.C_m[2], data.eps}));
        impact::collide_batch(data);
        for (std::size_t i = 0; i < count; ++i) {
            const collision<3>& c = drawn[i];
            const auto r = impact::collide(c.M, i % 11 == 3 ? 0.0 : c.m, c.C_M, c.C_m, c.v_M, c.v_m, c.eps);
            BOOST_TEST((status[i] == r.status), "pair " << i << " of " << count);
            for (std::size_t d = 0; d < 3; ++d) {
                BOOST_TEST(std::memcmp(&r.v_M[d], &data.v_M[d][i], sizeof(double)) == 0);
                BOOST_TEST(std::memcmp(&r.v_m[d], &data.v_m[d][i], sizeof(double)) == 0);
            }
        }
        BOOST_TEST((status[count] == impact::status::separating));  // past the count: untouched
    }
}

IMPACT_PRECISE_END
