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

#include "engine/domain.h"
#include "pipeline/library.h"
#include "verify/accuracy.h"

#include <algorithm>
#include <iostream>
#include <string>

namespace {

using namespace impact;

const engine::derivation& eq8()
{
    static const pipeline::library lib =
        pipeline::derive_all(pipeline::read_directory(IMPACT_SOURCE_DIR "/derivations"), "inelastic_line");
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

template <class Real>
void check_collide_line(const char* type, double velocity_bound, double impulse_bound)
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
        const Real v_M = static_cast<Real>(engine::draw(velocity, stream));
        const Real v_m = static_cast<Real>(engine::draw(velocity, stream));
        const Real eps = static_cast<Real>(engine::draw(restitution, stream));
        const auto out = impact::collide_line(M, m, v_M, v_m, eps);

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
    std::cout << "collide_line<" << type << "> over " << samples << " samples, worst error in ulps of the velocity "
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
