// The example derivation files of the reference, docs/language.md (tests/examples/): each derived,
// every check proven, the key results against closed forms typed here; together they use
// every kind of step, check and kernel option. And the reference itself: docs/language.md
// documents every field the reader accepts, and no other.
//
// The examples are written for these tests, not from the paper (a ball, a spring, a
// pendulum, a seesaw, a puck, a photon, an incline, a swing, a scattered charge); the expected
// results are textbook mechanics.
#define BOOST_TEST_MODULE test_examples
#include <boost/test/unit_test.hpp>

#include "derivation_support.h"
#include "emit/errata.h"
#include "emit/verification.h"
#include "engine/library/library.h"
#include "pipeline/regenerate.h"
#include "verify/choice.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <filesystem>
#include <string>
#include <vector>

#include <unistd.h>

namespace {

using namespace impact;
using namespace impact::testing;

// Derived once for every test case: deriving the ten files takes a fraction of a second.
const engine::library& examples()
{
    static const engine::library lib =
        engine::derive_all(engine::read_directory(IMPACT_SOURCE_DIR "/tests/examples"));
    return lib;
}

const engine::derivation& example(const std::string& id)
{
    const auto found = examples().derived.find(id);
    BOOST_REQUIRE_MESSAGE(found != examples().derived.end(), "no example " + id);
    return found->second;
}

const engine::kernel& kernel_named(const engine::derivation& d, const std::string& name)
{
    for (const engine::kernel& k : d.kernels)
        if (k.name == name)
            return k;
    BOOST_FAIL("no kernel " + name + " in " + d.id());
    throw;
}

const engine::kernel_output& output_named(const engine::kernel& k, const std::string& member)
{
    for (const engine::kernel_output& o : k.outputs)
        if (o.member == member)
            return o;
    BOOST_FAIL("no output " + member + " in kernel " + k.name);
    throw;
}

// The solutions a step kept or rejected, for the step that solved for `unknown`.
const engine::step_result& step_solving(const engine::derivation& d, const std::string& unknown)
{
    const GiNaC::ex u = sym(d, unknown);
    for (const engine::step_result& s : d.steps)
        if (s.what == spec::step::kind::solve)
            for (const auto& [symbol, value] : s.values)
                if (symbol.is_equal(u))
                    return s;
    BOOST_FAIL("no step solves for " + unknown + " in " + d.id());
    throw;
}

std::string read_text(const std::string& path)
{
    std::ifstream in(path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

} // namespace

BOOST_AUTO_TEST_SUITE(test_examples)

BOOST_AUTO_TEST_CASE(every_example_is_derived_with_every_check_proven)
{
    const std::set<std::string> expected = {"compton", "incline", "pendulum", "pushed_block", "pushed_puck",
                                            "rutherford", "seesaw", "spring", "swing", "thrown_ball"};
    BOOST_TEST((std::set<std::string>(examples().order.begin(), examples().order.end()) == expected));
    for (const std::string& id : examples().order) {
        const engine::derivation& d = example(id);
        BOOST_TEST(!d.all_checks().empty(), id);
        // Proven, not sampled: every step's checks, every display form, every [[check]].
        for (const engine::check_result* c : d.all_checks())
            BOOST_TEST((c->outcome.what == engine::verdict::status::proven), id + ": " + c->name + " is "
                                                                                 + engine::to_string(c->outcome));
    }
}

BOOST_AUTO_TEST_CASE(the_examples_use_every_kind_of_step_check_and_kernel_option)
{
    std::set<spec::step::kind> steps;
    bool solve_rejects_by_condition = false, solve_rejects_by_domain = false;
    bool inequality = false, at = false, left_at = false, limit_to_point = false, limit_to_infinity = false,
         assuming = false, cases = false, continuity = false, derivative = false;
    bool claim = false, use = false, new_base = false, named_combination = false;
    bool array_input = false, renamed_scalar = false, velocities = false, relative = false, velocity = false,
         velocity_times = false, forms = false, parameter_guard = false, guard_below = false,
         guard_above = false, substitute = false, let = false, batch = false, bound_for_all = false,
         bound_for_one_type = false;
    for (const std::string& id : examples().order) {
        const engine::derivation& d = example(id);
        const spec::derivation& s = d.source;
        for (const engine::step_result& st : d.steps) {
            steps.insert(st.what);
            for (const engine::solution& sol : st.solutions) {
                solve_rejects_by_condition |= sol.outcome == engine::solution::fate::condition;
                solve_rejects_by_domain |= sol.outcome == engine::solution::fate::outside_domain;
            }
        }
        for (const spec::check& c : s.checks) {
            inequality |= c.claim.value.find('<') != std::string::npos || c.claim.value.find('>') != std::string::npos;
            at |= !c.at.empty();
            left_at |= !c.left_at.empty();
            limit_to_point |= c.limit && !c.limit->to_infinity;
            limit_to_infinity |= c.limit && c.limit->to_infinity;
            assuming |= !c.assuming.empty();
            continuity |= c.continuity.has_value();
            derivative |= c.claim.value.find("diff(") != std::string::npos;
        }
        for (const spec::step& st : s.steps)
            cases |= !st.cases.empty();
        claim |= !s.claims.empty();
        use |= !s.uses.empty();
        for (const spec::dimension& dim : s.dimensions)
            (dim.as ? named_combination : new_base) = true;
        for (const spec::kernel& k : s.kernels) {
            for (const spec::kernel_value& input : k.inputs) {
                array_input |= input.is_array;
                renamed_scalar |= !input.is_array && input.name.value != input.components.front().value;
            }
            velocities |= !k.velocities.empty();
            for (const spec::error_scale& e : k.error) {
                relative |= e.relative;
                velocity |= !e.relative && !e.factor;
                velocity_times |= !e.relative && e.factor.has_value();
            }
            forms |= !k.forms.empty();
            for (const spec::kernel_guard& g : k.guards) {
                parameter_guard |= !g.condition;
                guard_below |= g.condition && g.condition->value.find('<') != std::string::npos;
                guard_above |= g.condition && g.condition->value.find('>') != std::string::npos;
            }
            substitute |= !k.substitute.empty();
            let |= !k.let.empty();
            batch |= k.batch;
            for (const spec::error_bound& b : k.bounds)
                (b.type ? bound_for_one_type : bound_for_all) = true;
        }
    }
    BOOST_TEST(steps.size() == 4u);
    BOOST_TEST(solve_rejects_by_condition);
    BOOST_TEST(solve_rejects_by_domain);
    BOOST_TEST(inequality);
    BOOST_TEST(at);
    BOOST_TEST(left_at);
    BOOST_TEST(limit_to_point);
    BOOST_TEST(limit_to_infinity);
    BOOST_TEST(assuming);
    BOOST_TEST(cases);
    BOOST_TEST(continuity);
    BOOST_TEST(derivative);
    BOOST_TEST(claim);
    BOOST_TEST(use);
    BOOST_TEST(new_base);
    BOOST_TEST(named_combination);
    BOOST_TEST(array_input);
    BOOST_TEST(renamed_scalar);
    BOOST_TEST(velocities);
    BOOST_TEST(relative);
    BOOST_TEST(velocity);
    BOOST_TEST(velocity_times);
    BOOST_TEST(forms);
    BOOST_TEST(parameter_guard);
    BOOST_TEST(guard_below);
    BOOST_TEST(guard_above);
    BOOST_TEST(substitute);
    BOOST_TEST(let);
    BOOST_TEST(batch);
    BOOST_TEST(bound_for_all);
    BOOST_TEST(bound_for_one_type);
}

BOOST_AUTO_TEST_CASE(a_ball_thrown_up_at_w_lands_after_2w_over_g)
{
    const engine::derivation& d = example("thrown_ball");
    const GiNaC::ex w = sym(d, "w"), g = sym(d, "g"), T = sym(d, "T");
    BOOST_TEST(equal(value_of(d, "t_top"), w / g));
    BOOST_TEST(equal(value_of(d, "T"), 2 * w / g));
    BOOST_TEST(equal(value_of(d, "H"), w * w / (2 * g)));
    // The quadratic's other root, the launch, rejected by the step's condition.
    const engine::step_result& landing = step_solving(d, "T");
    BOOST_TEST_REQUIRE(landing.solutions.size() == 2u);
    const engine::solution& launch = landing.solutions[0].kept() ? landing.solutions[1] : landing.solutions[0];
    BOOST_TEST((launch.outcome == engine::solution::fate::condition));
    BOOST_TEST(launch.values.front().first.is_equal(T));
    BOOST_TEST(launch.values.front().second.is_zero());
    BOOST_TEST(launch.why == "T = 0 is the launch, not the landing");
}

BOOST_AUTO_TEST_CASE(the_fictional_textbook_is_right_once_and_wrong_once)
{
    const engine::derivation& d = example("thrown_ball");
    BOOST_TEST_REQUIRE(d.paper_checks.size() == 2u);
    // "A ball spends as long rising as it does falling": true.
    BOOST_TEST(d.paper_checks[0].subject == "book_time_up_is_half_the_flight");
    BOOST_TEST(d.paper_checks[0].agrees());
    // "Twice as fast, twice as high": the height grows with the square, a finding, not a
    // failed check (the derivation holds).
    BOOST_TEST(d.paper_checks[1].subject == "book_twice_as_fast_twice_as_high");
    BOOST_TEST(!d.paper_checks[1].agrees());
    BOOST_TEST(d.all_hold());
}

BOOST_AUTO_TEST_CASE(a_spring_oscillates_with_period_two_pi_root_m_over_k)
{
    const engine::derivation& d = example("spring");
    const GiNaC::ex m = sym(d, "m"), k = sym(d, "k"), A = sym(d, "A"), pi = sym(d, "pi");
    BOOST_TEST(equal(value_of(d, "T"), 2 * pi * GiNaC::sqrt(m / k)));
    BOOST_TEST(equal(value_of(d, "v_max"), A * GiNaC::sqrt(k / m)));
    BOOST_TEST(equal(value_of(d, "E"), k * A * A / 2));
    // v_max = -A sqrt(k/m) solves the equations too; v_max's domain (positive) rejects it.
    const engine::step_result& energy = step_solving(d, "v_max");
    BOOST_TEST_REQUIRE(energy.solutions.size() == 2u);
    const engine::solution& backwards = energy.solutions[0].kept() ? energy.solutions[1] : energy.solutions[0];
    BOOST_TEST((backwards.outcome == engine::solution::fate::outside_domain));
    BOOST_TEST(backwards.unknown.is_equal(sym(d, "v_max")));
    // The limits: to infinity (a stiff spring) and to a point (a light mass).
    BOOST_TEST(check_named(d, "a_stiff_spring_oscillates_fast").limit->to_infinity);
    BOOST_TEST(!check_named(d, "a_light_mass_oscillates_fast").limit->to_infinity);
}

BOOST_AUTO_TEST_CASE(a_pendulum_is_a_spring_of_stiffness_m_g_over_l)
{
    const engine::derivation& d = example("pendulum");
    const GiNaC::ex L = sym(d, "L"), g = sym(d, "g"), pi = sym(d, "pi");
    BOOST_TEST(equal(value_of(d, "T"), 2 * pi * GiNaC::sqrt(L / g)));
    BOOST_TEST(equal(value_of(d, "rate_max"), sym(d, "theta_0") * GiNaC::sqrt(g / L)));
    // The spring's period, imported and evaluated at k = m g / L.
    const engine::check_result& same = check_named(d, "a_spring_of_stiffness_m_g_over_L");
    BOOST_TEST(same.at.size() == 1u);
    BOOST_TEST(equal(same.lhs, 2 * pi * GiNaC::sqrt(L / g)));
    // The dimensions it adds: rate_max is an angle per time.
    BOOST_TEST(d.symbols.find("rate_max")->dim->to_string() == "angle/time");
}

BOOST_AUTO_TEST_CASE(on_a_balanced_seesaw_the_lighter_child_sits_further_out)
{
    const engine::derivation& d = example("seesaw");
    const GiNaC::ex q = sym(d, "q"), L = sym(d, "L");
    // m_1 d_1 = m_2 d_2 and d_1 + d_2 = L, with m_2 = q m_1.
    BOOST_TEST(equal(value_of(d, "d_1"), q * L / (1 + q)));
    BOOST_TEST(equal(value_of(d, "d_2"), L / (1 + q)));
    // The quotient assumes its divisor, the second torque, non-zero.
    const auto quotient = std::find_if(d.steps.begin(), d.steps.end(), [](const engine::step_result& s) {
        return s.what == spec::step::kind::quotient;
    });
    BOOST_TEST_REQUIRE((quotient != d.steps.end()));
    BOOST_TEST(quotient->assumptions.size() == 1u);
    BOOST_TEST(check_named(d, "the_lighter_child_sits_further_out").assuming.size() == 1u);
}

BOOST_AUTO_TEST_CASE(a_pushed_puck_gains_the_impulse_of_the_force)
{
    const engine::derivation& d = example("pushed_puck");
    const GiNaC::ex m = sym(d, "m"), t = sym(d, "t"), a_x = sym(d, "a_x"), a_y = sym(d, "a_y");
    const GiNaC::ex v_x = sym(d, "v_x"), v_y = sym(d, "v_y");
    BOOST_TEST(equal(value_of(d, "dp_x"), m * a_x * t));
    // The work-energy theorem: W = m t (a.v) + m t^2 |a|^2 / 2.
    BOOST_TEST(equal(value_of(d, "W"), m * t * (a_x * v_x + a_y * v_y) + m * t * t * (a_x * a_x + a_y * a_y) / 2));

    const engine::kernel& push = kernel_named(d, "push");
    // Its velocity in the kernel's inputs, a = F/m substituted: v + F t / m.
    const GiNaC::ex F_x = sym(d, "F_x");
    BOOST_TEST(equal(output_named(push, "v").values[0], v_x + F_x * t / m));
    BOOST_TEST(push.find_parameter("duration")->components.front().name == "t");
    BOOST_TEST(push.find_parameter("F")->is_array);
    BOOST_TEST(push.guards.size() == 4u);
    BOOST_TEST(push.lets.size() == 1u);
    BOOST_TEST((output_named(push, "v").error == engine::kernel_output::scale::velocity));
    BOOST_TEST(equal(output_named(push, "dp").scale_factor, m));
    BOOST_TEST((output_named(push, "E_push").error == engine::kernel_output::scale::relative));
    // [[kernel.bound]] with a type: 5 ulps in float, the default 4 in double and long double.
    BOOST_TEST(output_named(push, "E_push").bound_ulps[0] == 5.0);
    BOOST_TEST(output_named(push, "E_push").bound_ulps[1] == 4.0);
    BOOST_TEST(output_named(push, "E_push").bound_ulps[2] == 4.0);
    BOOST_TEST(kernel_named(d, "push_velocity").batch);
}

// Compton scattering: E' = E/(1 + (E/(m_e c^2))(1 - cos theta)), and the electron's T_e = E - E'.
// Its kernel calls sin: a small angle's 1 - cos(theta), which cos(theta) rounded to 1 makes 0,
// is computed as 2 sin^2(theta/2), within 4 ulps in every type and regime, small angles among them.
BOOST_AUTO_TEST_CASE(a_photon_scattered_by_a_small_angle_loses_what_its_kernel_computes_within_4_ulps, *boost::unit_test::label("measured"))
{
    const engine::derivation& d = example("compton");
    const GiNaC::ex E = sym(d, "E"), E_0 = sym(d, "E_0"), theta = sym(d, "theta");
    BOOST_TEST(equal(value_of(d, "Ep"), E / (1 + (E / E_0) * (1 - GiNaC::cos(theta)))));
    const engine::kernel& k = kernel_named(d, "compton");
    const verify::kernel_plan plan = verify::plan_kernel(k, engine::declaration_order(d.symbols));
    BOOST_REQUIRE_EQUAL(plan.components.size(), 2u);
    for (std::size_t i = 0; i < plan.components.size(); ++i) {
        const verify::component_plan& cp = plan.components[i];
        BOOST_TEST(cp.candidates[cp.chosen].label.find("no cancellation") != std::string::npos, cp.name);
        BOOST_TEST(plan.emitted[i].in_float.max_ulps <= 4.0, cp.name);
        BOOST_TEST(plan.emitted[i].in_double.max_ulps <= 4.0, cp.name);
        BOOST_TEST(plan.emitted[i].in_long_double.max_ulps <= 4.0, cp.name);
    }
    // Small angles are among the samples (theta within 3e-12 .. 0.3 of 0).
    BOOST_TEST(std::any_of(plan.samples.begin(), plan.samples.end(),
                           [](const verify::sample& s) { return s.regime == "theta near 0" && s.inputs[2] < 1e-9; }));

    // The kernel compiled and run: against the closed forms, typed here.
    namespace fs = std::filesystem;
    std::vector<std::string> missed;
    const pipeline::file_set files = pipeline::generate_kernels(examples(), &missed);
    BOOST_TEST(missed.empty());
    const fs::path dir = fs::temp_directory_path() / ("impact_test_compton_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    for (const auto& [path, text] : files) {
        fs::create_directories((dir / path).parent_path());
        std::ofstream(dir / path) << text;
    }
    std::ofstream(dir / "main.cpp")
        << "#include \"impact/compton.hpp\"\n#include <cmath>\n#include <cstdio>\n"
           "template <class Real>\nbool near(Real x, Real want) { return std::fabs(x - want) <= 4 * "
           "std::numeric_limits<Real>::epsilon() * std::fabs(want); }\n"
           "int main()\n{\n"
           // No turn: E' = E, T_e = 0.
           "    const auto straight = impact::compton<double>(2.0, 1.0, 0.0);\n"
           "    const bool a = straight.Ep == 2.0 && straight.T_e == 0.0;\n"
           // A right angle: 1/E' = 1/E + 1/E_0, E' = 3/4 for E = 3, E_0 = 1; T_e = 9/4.
           "    const auto right = impact::compton<double>(3.0, 1.0, 1.5707963267948966);\n"
           "    const bool b = near(right.Ep, 0.75) && near(right.T_e, 2.25);\n"
           // theta = 1e-8: T_e = E (E/E_0) theta^2/2 (1 + O(theta^2)) = 5e-17 for E = E_0 = 1,
           // where 1 - cos(theta) in double is 0.
           "    const auto small = impact::compton<double>(1.0, 1.0, 1e-8);\n"
           "    const bool c = near(small.T_e, 5e-17) && small.Ep == 1.0;\n"
           "    const auto small_f = impact::compton<float>(1.0f, 1.0f, 1e-4f);\n"
           "    const bool e = near(small_f.T_e, 5e-9f);\n"
           "    const auto small_l = impact::compton<long double>(1.0L, 1.0L, 1e-10L);\n"
           "    const bool f = near(small_l.T_e, 5e-21L);\n"
           "    std::printf(\"%d %d %d %d %d\\n\", a, b, c, e, f);\n"
           "    return a && b && c && e && f ? 0 : 1;\n}\n";
    const std::string command = std::string(IMPACT_CXX) + " -std=c++17 -O2 -I" + (dir / "kernels").string() + " " +
                                (dir / "main.cpp").string() + " -o " + (dir / "main").string() + " && " +
                                (dir / "main").string();
    BOOST_TEST(std::system(command.c_str()) == 0, command);
    fs::remove_all(dir);
}

// The kernels of the examples with angles (sin, cos and atan; 1 - cos(theta_0) as 2 sin^2(theta_0/2)):
// every output within 4 ulps in every type, an angle sampled near an end of its domain.
BOOST_AUTO_TEST_CASE(the_kernels_of_angles_are_within_4_ulps_in_every_type, *boost::unit_test::label("measured"))
{
    struct angled { std::string id, name, regime; };
    for (const angled& a : {angled{"incline", "incline_slide", "alpha near Pi/2"},
                            angled{"swing", "swing_bottom", "theta_0 near 0"},
                            angled{"rutherford", "rutherford", "E, kappa, b over 12 decades"}}) {
        const engine::derivation& d = example(a.id);
        const verify::kernel_plan plan =
            verify::plan_kernel(kernel_named(d, a.name), engine::declaration_order(d.symbols));
        BOOST_TEST_REQUIRE((!plan.components.empty() && plan.components.size() == plan.emitted.size()), a.name);
        for (std::size_t i = 0; i < plan.components.size(); ++i)
            for (const verify::accuracy& in : {plan.emitted[i].in_float, plan.emitted[i].in_double,
                                               plan.emitted[i].in_long_double})
                BOOST_TEST(in.max_ulps <= 4.0, a.name + ": " + plan.components[i].name);
        BOOST_TEST(std::any_of(plan.samples.begin(), plan.samples.end(),
                               [&](const verify::sample& s) { return s.regime == a.regime; }), a.regime);
    }
}

// Shot up at v_0 against g (sin(alpha) + mu cos(alpha)), a block slides v_0^2 over twice that.
BOOST_AUTO_TEST_CASE(a_block_shot_up_an_incline_slides_v0_squared_over_twice_its_deceleration)
{
    const engine::derivation& d = example("incline");
    const GiNaC::ex g = sym(d, "g"), mu = sym(d, "mu"), alpha = sym(d, "alpha"), v_0 = sym(d, "v_0");
    const GiNaC::ex a_up = g * (GiNaC::sin(alpha) + mu * GiNaC::cos(alpha));
    BOOST_TEST(equal(value_of(d, "d"), v_0 * v_0 / (2 * a_up)));
    BOOST_TEST(equal(value_of(d, "t_up"), v_0 / a_up));
    BOOST_TEST(equal(value_of(d, "alpha_s"), GiNaC::atan(mu)));
    // On a vertical wall, no friction: the height of a ball thrown up at v_0.
    BOOST_TEST(equal(value_of(d, "d").subs(alpha == GiNaC::Pi / 2), v_0 * v_0 / (2 * g)));
}

// Released at theta_0: m v^2/2 = m g L (cos(theta) - cos(theta_0)), T - m g cos(theta) = m v^2/L,
// so T = m g (3 cos(theta) - 2 cos(theta_0)): m g cos(theta_0) at the release; as hard as the
// weight where 3 cos(theta_w) = 1 + 2 cos(theta_0), -acos(...) outside (0, pi/2].
BOOST_AUTO_TEST_CASE(a_pendulum_s_string_holds_m_g_cos_theta_0_at_the_release)
{
    const engine::derivation& d = example("swing");
    const GiNaC::ex m = sym(d, "m"), g = sym(d, "g"), L = sym(d, "L"), theta = sym(d, "theta");
    const GiNaC::ex c_0 = GiNaC::cos(sym(d, "theta_0")), T = value_of(d, "T");
    BOOST_TEST(equal(T, m * g * (3 * GiNaC::cos(theta) - 2 * c_0)));
    BOOST_TEST(equal(T.subs(theta == sym(d, "theta_0")), m * g * c_0));
    BOOST_TEST(equal(GiNaC::pow(value_of(d, "v"), 2), 2 * g * L * (GiNaC::cos(theta) - c_0)));
    BOOST_TEST(equal(value_of(d, "theta_w"), GiNaC::acos(GiNaC::ex(1) / 3 + 2 * c_0 / 3)));
    const engine::step_result& as_weight = step_solving(d, "theta_w");
    BOOST_TEST_REQUIRE(as_weight.solutions.size() == 2u);
    const engine::solution& negative = as_weight.solutions[0].kept() ? as_weight.solutions[1] : as_weight.solutions[0];
    BOOST_TEST((negative.outcome == engine::solution::fate::outside_domain));
    BOOST_TEST(equal(output_named(kernel_named(d, "swing_bottom"), "T").values[0], m * g * (3 - 2 * c_0))); // theta = 0
}

// Rutherford: cot(theta/2) = 2 E b / kappa; closest where E = E b^2/r^2 + kappa/r.
BOOST_AUTO_TEST_CASE(a_charge_passing_a_nucleus_at_b_is_turned_by_2_atan_kappa_over_2_E_b)
{
    const engine::derivation& d = example("rutherford");
    const GiNaC::ex E = sym(d, "E"), kappa = sym(d, "kappa"), b = sym(d, "b");
    BOOST_TEST(equal(value_of(d, "theta"), 2 * GiNaC::atan(kappa / (2 * E * b))));
    BOOST_TEST(equal(value_of(d, "r_min"), (kappa + GiNaC::sqrt(kappa * kappa + 4 * E * E * b * b)) / (2 * E)));
    // At b = kappa/(2 E), half the head-on distance, by a right angle.
    const GiNaC::ex right = GiNaC::evalf(value_of(d, "theta").subs(b == kappa / (2 * E)) - GiNaC::Pi / 2);
    BOOST_TEST_REQUIRE(GiNaC::is_a<GiNaC::numeric>(right));
    BOOST_TEST(GiNaC::abs(GiNaC::ex_to<GiNaC::numeric>(right)).to_double() < 1e-15);
}

BOOST_AUTO_TEST_CASE(a_pushed_block_sticks_up_to_mu_m_g_then_slides)
{
    const engine::derivation& d = example("pushed_block");
    const GiNaC::ex F = sym(d, "F"), m = sym(d, "m"), g = sym(d, "g"), mu = sym(d, "mu");
    const engine::result* f = d.find_result("f");
    BOOST_REQUIRE(f);
    BOOST_REQUIRE_EQUAL(f->cases.size(), 2u);
    BOOST_TEST(equal(f->cases[0].value, F));
    BOOST_TEST(equal(f->cases[1].value, mu * m * g));
    // a >= 0 in each case: 0 while it sticks, F/m - mu*g > 0 by the condition once it slides.
    const engine::check_result& backwards = check_named(d, "the_block_never_accelerates_backwards");
    BOOST_REQUIRE_EQUAL(backwards.parts.size(), 2u);
    BOOST_TEST((backwards.parts[1].outcome.what == engine::verdict::status::proven));
    BOOST_TEST(check_named(d, "sticking_and_sliding_meet").parts.size() == 1u);
}

BOOST_AUTO_TEST_CASE(errata_of_files_that_transcribe_nothing_say_so)
{
    // The spring transcribes no printed line or claim: no table of 0 rows.
    const std::string errata = emit::errata_markdown({&example("spring")});
    BOOST_TEST(errata.find("# The text held to account\n\nNo derivation file in `examples/` transcribes a printed "
                           "line or claim of a text") != std::string::npos,
               errata);
    BOOST_TEST(errata.find("| Where |") == std::string::npos);
}

BOOST_AUTO_TEST_CASE(the_verification_of_a_folder_of_ones_own_speaks_of_its_kernels_not_of_collisions)
{
    // verification.md of the examples: its introduction names the folder's kernels and the
    // regimes of their inputs; none of them is a collision. The paper's keeps its words.
    const std::string own = emit::verification_markdown({}, "examples/", emit::of_the_paper(examples().in_order()));
    BOOST_TEST(own.find("# Kernel verification\n\nEvery output of every kernel generated from the derivation files "
                        "in `examples/`, run on inputs drawn from the regimes where its value is hard to compute, "
                        "each kernel's listed under its name: its positive inputs over 12 decades, each input of "
                        "an interval near each of its ends (1e-12 to 1e-1 of its width from it), and the regimes "
                        "its derivation file declares") != std::string::npos,
               own);
    BOOST_TEST(own.find("collision") == std::string::npos, own);
    BOOST_TEST(own.find("reduced mass") == std::string::npos, own);
    const std::string paper = emit::verification_markdown({}, "derivations/", true);
    BOOST_TEST(paper.find("Every output of every generated kernel, run on inputs drawn from the regimes where "
                          "collisions are hard to compute") != std::string::npos,
               paper);
}

BOOST_AUTO_TEST_CASE(generated_files_name_a_derivation_file_by_its_folders_own_name)
{
    BOOST_TEST(engine::folder_and_file_name("../../derivations/x.toml") == "derivations/x.toml");
    BOOST_TEST(engine::folder_and_file_name("/home/someone/mine/x.toml") == "mine/x.toml");
    BOOST_TEST(engine::folder_and_file_name("/x.toml") == "x.toml");
    const std::string here = std::filesystem::current_path().filename().string() + "/x.toml";
    BOOST_TEST(engine::folder_and_file_name("x.toml") == here);
    BOOST_TEST(engine::folder_and_file_name("./x.toml") == here);
}

BOOST_AUTO_TEST_CASE(the_example_kernels_meet_their_bounds_and_are_emitted, *boost::unit_test::label("measured"))
{
    std::vector<std::string> missed;
    const pipeline::file_set files = pipeline::generate_kernels(examples(), &missed);
    BOOST_TEST(missed.empty(), (missed.empty() ? std::string() : missed.front()));
    std::string all;
    for (const auto& [path, text] : files)
        all += text;
    for (const char* function : {"spring_motion(", "push(", "push_velocity(", "push_velocity_batch("})
        BOOST_TEST(all.find(function) != std::string::npos, function);
    // Each header names the file it comes from by its folder's own name (it named every
    // source derivations/<file>, wherever the file was).
    BOOST_TEST(all.find("// Generated by Impact from examples/spring.toml; do not edit.") != std::string::npos);
    BOOST_TEST(all.find("Generated by Impact from derivations/") == std::string::npos);
    // Their comments speak of their inputs and outputs, not of a collision none of them is.
    BOOST_TEST(all.find("allow no collision") == std::string::npos);
    BOOST_TEST(all.find("resolved no collision") == std::string::npos);
    BOOST_TEST(all.find("a collision's") == std::string::npos);
    BOOST_TEST(all.find("/// When the inputs are refused") != std::string::npos);
    // Every status a guard names, and out_of_range and underflow, which a kernel with a status
    // adds: the batch kernel's first (push_velocity's), the two of the range, then the others'.
    const std::size_t start = all.find("enum class status : std::int64_t { ");
    BOOST_REQUIRE(start != std::string::npos);
    const std::string statuses = all.substr(start, all.find(';', start) - start);
    const auto listed = [&](const std::string& s) {
        return statuses.find(" " + s + ",") != std::string::npos || statuses.find(" " + s + " }") != std::string::npos;
    };
    for (const char* s : {"ok", "invalid_input", "non_finite", "no_force", "pulled_back", "out_of_range", "underflow"})
        BOOST_TEST(listed(s), s);
    BOOST_TEST(std::count(statuses.begin(), statuses.end(), ',') == 6);
    BOOST_TEST(statuses.find("ok,") < statuses.find("out_of_range"));
    BOOST_TEST(statuses.find("out_of_range") < statuses.find("underflow"));
}

// Every key the reader accepts, by table, typed from reading it (src/spec/reader.cpp:
// parse_derivation, read_symbol, read_dimension, read_given, read_step, read_result,
// read_check_fields, read_claim, read_open_claim, read_not_compared, read_use;
// src/spec/kernel_reader.cpp: read_kernel, read_sampling_regime). A field added there fails this
// test until docs/language.md documents it.
const std::map<std::string, std::set<std::string>> fields_read = {
    {"top level", {"id", "title", "paper", "summary"}},
    {"[[use]]", {"derivation", "results"}},
    {"[[dimension]]", {"name", "as"}},
    {"[[symbol]]", {"name", "latex", "definition", "domain", "meaning", "dimension"}},
    {"[[given]]", {"name", "equation", "because", "paper", "printed", "quote"}},
    {"[[step]]", {"because", "solve", "for", "reject", "reject_because", "define", "as", "cases", "quotient",
                  "name", "rearrange", "into"}},
    {"[[result]]", {"name", "display", "paper", "printed", "quote"}},
    {"[[check]]", {"name", "claim", "continuity", "because", "at", "left_at", "limit", "assuming"}},
    {"[[claim]]", {"name", "claim", "because", "at", "left_at", "limit", "assuming", "paper", "quote", "mended", "holds", "label", "undecided"}},
    {"[[not_compared]]", {"paper", "because"}},
    {"[[reference]]", {"paper", "number", "entry"}},
    {"[[citation]]", {"paper", "quote", "cites", "names"}},
    {"[[kernel]]", {"name", "inputs", "outputs", "velocities", "error", "forms", "guards", "substitute", "let",
                    "batch", "fixed"}},
    {"[[kernel.bound]]", {"output", "type", "form", "ulps", "because"}},
    {"[[kernel.regime]]", {"name", "set", "ratio", "boundary", "from", "to", "within", "start"}},
};

// docs/language.md, the reference of derivation files: a `## ` heading per TOML table (its
// name in backticks, or "The top level"), then a table whose rows start with the field in backticks.
std::map<std::string, std::set<std::string>> fields_documented()
{
    const std::string reference = read_text(IMPACT_SOURCE_DIR "/docs/language.md");
    BOOST_REQUIRE(reference.rfind("# Derivation files\n", 0) == 0);
    std::istringstream section(reference);
    std::map<std::string, std::set<std::string>> documented;
    std::string table, line;
    auto in_backticks = [](const std::string& s) {
        const auto open = s.find('`');
        const auto close = open == std::string::npos ? open : s.find('`', open + 1);
        return close == std::string::npos ? std::string() : s.substr(open + 1, close - open - 1);
    };
    while (std::getline(section, line)) {
        if (line.rfind("## ", 0) == 0) {
            const std::string named = in_backticks(line);
            table = !named.empty() ? named : line.find("top level") != std::string::npos ? "top level" : "";
            if (!table.empty())
                documented[table];
        } else if (!table.empty() && line.rfind("| `", 0) == 0) {
            documented[table].insert(in_backticks(line));
        }
    }
    return documented;
}

BOOST_AUTO_TEST_CASE(the_language_reference_documents_every_field_the_reader_accepts_and_no_other)
{
    const auto documented = fields_documented();
    for (const auto& [table, fields] : fields_read) {
        const auto found = documented.find(table);
        BOOST_TEST_REQUIRE((found != documented.end()), "docs/language.md documents no table " + table);
        for (const std::string& field : fields)
            BOOST_TEST(found->second.count(field) == 1u, table + ": field '" + field + "' is not documented");
        for (const std::string& field : found->second)
            BOOST_TEST(fields.count(field) == 1u, table + ": docs/language.md documents '" + field + "', which the reader "
                                                  "does not accept");
    }
    for (const auto& [table, fields] : documented)
        BOOST_TEST(fields_read.count(table) == 1u, "docs/language.md documents a table " + table + " the reader does not read");
}

BOOST_AUTO_TEST_CASE(the_language_reference_links_every_example)
{
    const std::string reference = read_text(IMPACT_SOURCE_DIR "/docs/language.md");
    for (const std::string& id : examples().order)
        BOOST_TEST(reference.find("(../tests/examples/" + id + ".toml)") != std::string::npos, id);
}

BOOST_AUTO_TEST_SUITE_END()
