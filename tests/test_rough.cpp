// Rough spheres (issue 21, the paper's "future research"), derived in the collision frame
// with every check proven: derivations/rough_sticking.toml solves the impulse, spin and
// restitution equations of a contact that sticks; derivations/rough_collision_frame.toml
// caps the tangential impulse by Coulomb friction, by cases (sticking and sliding), and
// proves momentum, angular momentum about the contact point, the energy change and its
// sign, the friction cone, the effective restitution and continuity at the cone's edge.
//
// The expected values are closed forms of Walton's model typed here: J_n = (1 + eps) m_r g_n,
// J_t = (1 + b) m_t g_t when sticking and mu J_n g_t/|g_t| when sliding, with
// m_r = M m/(M + m) and 1/m_t = 1/M + 1/m + 1/(q_M M) + 1/(q_m m).
#define BOOST_TEST_MODULE test_rough
#include <boost/test/unit_test.hpp>

#include "derivation_support.h"

#include "spec/derivation.h"

#include <string>

namespace {

using namespace impact;
using namespace impact::testing;

engine::derivation rough_sticking()
{
    return derive_file("derivations/rough_sticking.toml");
}

engine::derivation rough_collision_frame()
{
    engine::derived_by_id done;
    done.emplace("rough_sticking", rough_sticking());
    return engine::derive(spec::read_derivation(IMPACT_SOURCE_DIR "/derivations/rough_collision_frame.toml"), done);
}

bool proven(const engine::verdict& v)
{
    return v.what == engine::verdict::status::proven;
}

} // namespace

BOOST_AUTO_TEST_CASE(a_sticking_contact_solves_to_the_impulses_of_walton_s_model)
{
    const engine::derivation d = rough_sticking();
    const GiNaC::ex M = sym(d, "M"), m = sym(d, "m"), q_M = sym(d, "q_M"), q_m = sym(d, "q_m"),
                    eps = sym(d, "eps"), b = sym(d, "b"), R_M = sym(d, "R_M"), R_m = sym(d, "R_m");
    const GiNaC::ex g_n = sym(d, "v_Mn") - sym(d, "v_mn");
    const GiNaC::ex g_t = sym(d, "v_Mt") - sym(d, "v_mt") + R_M * sym(d, "w_M") + R_m * sym(d, "w_m");
    const GiNaC::ex m_r = M * m / (M + m);
    const GiNaC::ex m_t = 1 / (1 / M + 1 / m + 1 / (q_M * M) + 1 / (q_m * m));
    BOOST_TEST(equal(value_of(d, "J_n"), (1 + eps) * m_r * g_n));
    BOOST_TEST(equal(value_of(d, "J_t"), (1 + b) * m_t * g_t));
    BOOST_TEST(equal(value_of(d, "w_M_after"), sym(d, "w_M") - R_M * (1 + b) * m_t * g_t / (q_M * M * R_M * R_M)));
    for (const engine::check_result& c : d.checks)
        BOOST_TEST(proven(c.outcome), c.name << ": " << c.outcome.method);
    // E' <= E, through the closed form of the energy change proven just before it.
    const std::string& method = check_named(d, "energy_never_gained").outcome.method;
    BOOST_TEST(method.rfind("by the check 'energy_change' the difference of the sides is ", 0) == 0, method);
}

BOOST_AUTO_TEST_CASE(friction_caps_the_tangential_impulse_by_cases_with_every_check_proven)
{
    const engine::derivation d = rough_collision_frame();
    const GiNaC::ex M = sym(d, "M"), m = sym(d, "m"), q_M = sym(d, "q_M"), q_m = sym(d, "q_m"),
                    eps = sym(d, "eps"), b = sym(d, "b"), mu = sym(d, "mu"), g_n = sym(d, "g_n"),
                    g_t = sym(d, "g_t");
    const GiNaC::ex m_r = M * m / (M + m);
    const GiNaC::ex m_t = 1 / (1 / M + 1 / m + 1 / (q_M * M) + 1 / (q_m * m));
    const GiNaC::ex j_n = (1 + eps) * m_r * g_n;
    const engine::result* j_t = d.find_result("J_t");
    BOOST_REQUIRE(j_t);
    BOOST_REQUIRE_EQUAL(j_t->cases.size(), 2u);
    BOOST_TEST(equal(j_t->cases[0].value, (1 + b) * m_t * g_t));
    BOOST_TEST(equal(j_t->cases[1].value, mu * j_n * g_t / GiNaC::abs(g_t)));
    const engine::result* b_eff = d.find_result("b_eff");
    BOOST_REQUIRE(b_eff);
    BOOST_REQUIRE_EQUAL(b_eff->cases.size(), 2u);
    BOOST_TEST(equal(b_eff->cases[0].value, b));
    BOOST_TEST(equal(b_eff->cases[1].value, -1 + mu * (1 + eps) * (m_r / m_t) * g_n / GiNaC::abs(g_t)));
    for (const engine::check_result& c : d.checks)
        BOOST_TEST(proven(c.outcome), c.name << ": " << c.outcome.method);
    BOOST_TEST(d.all_hold());
    // The sliding case's energy: divided by the condition, as a textbook bounds it.
    const engine::check_result& energy = check_named(d, "energy_never_gained");
    BOOST_REQUIRE_EQUAL(energy.parts.size(), 2u);
    BOOST_TEST(energy.parts[1].outcome.method.find("divided by the condition's side") != std::string::npos,
               energy.parts[1].outcome.method);
    // Continuity solved for the friction coefficient, the shortest boundary value.
    const engine::check_result& meet = check_named(d, "sticking_and_sliding_meet");
    BOOST_REQUIRE_EQUAL(meet.parts.size(), 1u);
    BOOST_TEST(meet.parts[0].under.rfind("cases 1 and 2 at mu = ", 0) == 0, meet.parts[0].under);
}
