// The choice of each kernel's forms (verify/choice.h): the fast form (impact::fast) beside
// the accurate one. Its rule is checked as a property of the plans of two of the paper's
// kernels, each candidate's cost counted here from its own program: every output in a
// candidate within its fast bound, none within it cheaper; and the choice read back from
// its cache entry as it was made; and every sample one the kernel's guards admit.
#define BOOST_TEST_MODULE test_choice
#include <boost/test/unit_test.hpp>

#include "compile/program.h"
#include "engine/cases/cases.h"
#include "engine/library/library.h"
#include "verify/choice.h"
#include "verify/measure.h"

#include <cmath>
#include <map>
#include <memory>
#include <string>

namespace {

using namespace impact;

struct planned {
    engine::library lib;
    engine::term_order order;
    verify::kernel_plan plan;
};

// The plan of derivation `id`'s first kernel, measured.
const planned& plan_of(const std::string& id)
{
    static std::map<std::string, std::unique_ptr<planned>> plans;
    auto& p = plans[id];
    if (!p) {
        engine::library lib = engine::derive_all(engine::read_directory(IMPACT_SOURCE_DIR "/derivations"), id);
        engine::term_order order = engine::declaration_order(lib.derived.at(id).symbols);
        p.reset(new planned{std::move(lib), std::move(order), {}});
        p->plan = verify::plan_kernel(p->lib.derived.at(id).kernels.front(), p->order);
    }
    return *p;
}

void check_fast_choice(const std::string& id)
{
    const planned& p = plan_of(id);
    const engine::kernel& k = *p.plan.kernel;
    const auto all = verify::components(k);
    BOOST_REQUIRE_EQUAL(p.plan.components.size(), all.size());
    for (std::size_t i = 0; i < all.size(); ++i) {
        const verify::component_plan& cp = p.plan.components[i];
        const double bound = k.outputs[all[i].first].fast_bound_ulps[1];
        BOOST_TEST(bound == 16.0);  // no bound set in the file: the default
        const verify::candidate_result& fastest = cp.candidates.at(cp.fastest);
        BOOST_TEST(fastest.double_accuracy.max_ulps <= bound, cp.name);
        auto cost = [&](const verify::candidate_result& c) {
            return compile::cost_of(compile::compile_program(
                {c.value}, k.input_symbols(), p.order, {c.fma, c.compensated, c.compensated_lets}, k.lets));
        };
        for (const verify::candidate_result& c : cp.candidates)
            if (c.compensated_lets == fastest.compensated_lets && c.double_accuracy.max_ulps <= bound)
                BOOST_TEST(!compile::cheaper(cost(c), cost(fastest)), cp.name << ": " << c.label << " is cheaper than "
                                                                              << fastest.label);
        // Each type within the fast bound, as emitted.
        BOOST_TEST(p.plan.fast_emitted[i].in_float.max_ulps <= 16.0, cp.name);
        BOOST_TEST(p.plan.fast_emitted[i].in_double.max_ulps <= 16.0, cp.name);
        BOOST_TEST(p.plan.fast_emitted[i].in_long_double.max_ulps <= 16.0, cp.name);
    }
    // These kernels' accurate forms compensate; their fast forms do not, and cost less.
    for (const verify::component_plan& cp : p.plan.components) {
        BOOST_TEST(!cp.candidates[cp.fastest].compensated, cp.name);
        BOOST_TEST(!cp.candidates[cp.fastest].compensated_lets, cp.name);
    }
    const compile::cost fast = compile::cost_of(p.plan.fast_code), accurate = compile::cost_of(p.plan.code);
    BOOST_TEST(fast.operations < accurate.operations);
    BOOST_TEST(compile::cheaper(fast, accurate));
    BOOST_TEST(verify::missed_bounds({p.plan}).empty());
}

} // namespace

BOOST_AUTO_TEST_CASE(the_fast_form_of_collide_line_is_its_cheapest_within_16_ulps)
{
    check_fast_choice("inelastic_line");
}

BOOST_AUTO_TEST_CASE(the_fast_form_of_the_2d_collide_is_its_cheapest_within_16_ulps)
{
    check_fast_choice("inelastic_plane");
}

BOOST_AUTO_TEST_CASE(the_fast_form_is_read_back_from_the_cache_as_it_was_chosen)
{
    const planned& p = plan_of("inelastic_plane");
    const std::string text = verify::encode_choice(p.plan, p.order);
    const auto back = verify::decode_choice(text, *p.plan.kernel, p.order);
    BOOST_REQUIRE(back.has_value());
    BOOST_REQUIRE_EQUAL(back->components.size(), p.plan.components.size());
    for (std::size_t i = 0; i < p.plan.components.size(); ++i) {
        BOOST_TEST(back->components[i].fastest == p.plan.components[i].fastest);
        BOOST_TEST(back->fast_emitted[i].in_float.max_ulps == p.plan.fast_emitted[i].in_float.max_ulps);
        BOOST_TEST(back->fast_emitted[i].in_long_double.max_ulps == p.plan.fast_emitted[i].in_long_double.max_ulps);
    }
    BOOST_TEST(back->fast_code.code.size() == p.plan.fast_code.code.size());
    BOOST_TEST(back->fast_code.outputs == p.plan.fast_code.outputs);
    // A fastest candidate past the candidates: not a choice for this kernel.
    std::string damaged = text;
    const std::string chosen_line = "\n" + std::to_string(p.plan.components[0].chosen) + "\n" +
                                    std::to_string(p.plan.components[0].fastest) + "\n";
    const auto at = damaged.find(chosen_line);
    BOOST_REQUIRE(at != std::string::npos);
    damaged.replace(at, chosen_line.size(),
                    "\n" + std::to_string(p.plan.components[0].chosen) + "\n" +
                        std::to_string(p.plan.components[0].candidates.size()) + "\n");
    BOOST_TEST(!verify::decode_choice(damaged, *p.plan.kernel, p.order).has_value());
}

BOOST_AUTO_TEST_CASE(every_sample_is_one_the_kernel_computes)
{
    // A wall's kernel refuses a sphere behind the wall or moving away from it; its accuracy
    // is measured where it computes: every sample in front of the wall ((C - P).n > 0) and
    // approaching it (v.n < 0). Inputs: P, n, C, v, eps.
    const planned& p = plan_of("wall_plane");
    BOOST_REQUIRE_EQUAL(p.plan.samples.size(), 4200u);
    std::size_t admitted = 0;
    for (const verify::sample& s : p.plan.samples) {
        const double* x = s.inputs.data();
        const double in_front = (x[4] - x[0]) * x[2] + (x[5] - x[1]) * x[3];
        const double approach = x[6] * x[2] + x[7] * x[3];
        admitted += in_front > 0 && approach < 0;
    }
    BOOST_TEST(admitted == p.plan.samples.size());
}

BOOST_AUTO_TEST_CASE(a_compensated_divisor_that_needs_a_division_is_tested_after_it)
{
    // The 3D rough wall (derivations/rough_wall_space.toml): in its sliding case it divides by
    // the slip's length |G_t|, where G_t is built on the normal's length |n|. Compensated, the
    // correction of |n| (a division) is renormalised into G_t's leading part: that divisor
    // needs a division, and the kernel tests it once it is computed, after its first
    // divisions (compile::grouped_divisors), not computed again plainly (G_t . G_t
    // multiplied out, which cancels to nothing, even below 0, when the sphere spins fast about
    // the normal). Each candidate is measured (none passed over), the compensated ones are
    // chosen, better than every plain form and within the kernel's 4 ulps of the largest
    // velocity (the plain forms miss it: up to 90 ulps), and the program divides by each
    // group of divisors only once the group is computed.
    const verify::kernel_plan& plan = plan_of("rough_wall_space").plan;
    std::size_t compensated_chosen = 0;
    for (const verify::component_plan& cp : plan.components) {
        for (const verify::candidate_result& c : cp.candidates)
            BOOST_TEST(std::isfinite(c.double_accuracy.max_ulps), c.label);
        const verify::candidate_result& chosen = cp.candidates[cp.chosen];
        BOOST_TEST_MESSAGE(cp.name << ": " << chosen.label << ", " << chosen.double_accuracy.max_ulps << " ulps");
        BOOST_TEST(chosen.double_accuracy.max_ulps <= 4.0, cp.name);
        for (const verify::candidate_result& c : cp.candidates)
            if (!c.compensated && !c.compensated_lets)
                BOOST_TEST(chosen.double_accuracy.max_ulps < c.double_accuracy.max_ulps, cp.name << ": " << c.label);
        compensated_chosen += chosen.compensated || chosen.compensated_lets;
    }
    BOOST_TEST(compensated_chosen > 0u);
    BOOST_TEST(!compile::grouped_divisors(plan.code).late.empty());
    BOOST_TEST(!compile::divides_early(plan.code));
}

BOOST_AUTO_TEST_CASE(divisors_are_tested_in_two_groups_and_a_refusal_is_measured_as_one)
{
    // x/(y + 1/y): y is divided by first (an early divisor, computed without a division),
    // y + 1/y after (a late one: it needs the division by y).
    const GiNaC::symbol x("x"), y("y");
    const engine::term_order order({x, y});
    const compile::program p = compile::compile_program({x / (y + 1 / y)}, {x, y}, order, {});
    const compile::divisor_groups groups = compile::grouped_divisors(p);
    BOOST_TEST_REQUIRE(groups.early.size() == 1u);
    BOOST_TEST_REQUIRE(groups.late.size() == 1u);
    BOOST_TEST((p.code[groups.early.front()].op == compile::opcode::input));
    BOOST_TEST((p.code[groups.late.front()].op == compile::opcode::add));
    BOOST_TEST(!compile::divides_early(p));
    // 1/x, then 1/(y y): the division by x comes before y y, an early divisor, is computed;
    // ordered for registers, both divisors come first.
    const compile::program early = compile::compile_program({1 / x, 1 / (y * y)}, {x, y}, order, {});
    BOOST_TEST(compile::divides_early(early));
    BOOST_TEST(!compile::divides_early(compile::ordered_for_registers(early)));
    // Two late divisors, y + 1/y and x + 1/x: each division by one waits for both.
    const compile::program late =
        compile::ordered_for_registers(compile::compile_program({x / (y + 1 / y), y / (x + 1 / x)}, {x, y}, order, {}));
    BOOST_TEST(compile::grouped_divisors(late).late.size() == 2u);
    BOOST_TEST(!compile::divides_early(late));
    // A kernel refuses a collision where a divisor is below the least normal number over the
    // type's epsilon (about 9.9e-32 in float): measured, that sample is refused (an infinite
    // error), not the accurate quotient the program's arithmetic gives (1e-35 here).
    const std::vector<verify::sample> samples{{"ordinary", {1, 2}}, {"tiny", {1, 1e-35}}};
    verify::reference ref;
    ref.mantissa_bits = 24;
    ref.outputs = {{{0.4, 0}}, {{1e-35, 0}}};
    ref.scales = {{1}, {1}};
    const verify::accuracy in_float = verify::measure<float>(p, {0}, samples, ref, true).front();
    BOOST_TEST(in_float.refused == 1u);
    BOOST_TEST(std::isinf(in_float.max_ulps));
    BOOST_TEST(in_float.first_refused_regime == "tiny");
    // A kernel without guards has no status and tests nothing: it divides, and is measured so.
    BOOST_TEST(verify::measure<float>(p, {0}, samples, ref, false).front().refused == 0u);
    const verify::accuracy in_double = verify::measure<double>(p, {0}, samples, ref, true).front();
    BOOST_TEST(in_double.refused == 0u);
    BOOST_TEST(in_double.max_ulps < 1);
}

BOOST_AUTO_TEST_CASE(a_power_of_three_halves_is_a_square_root_and_a_product)
{
    // |n|^3 = (n.n)^(3/2): x sqrt(x), which compilers vectorise, not a call of pow (which GCC
    // does not vectorise, and which is not correctly rounded); plainly and compensated.
    const GiNaC::symbol x("x");
    const engine::term_order order({x});
    for (const bool compensated : {false, true}) {
        const compile::program p =
            compile::compile_program({GiNaC::pow(x, GiNaC::numeric(3, 2))}, {x}, order, {false, compensated});
        BOOST_TEST(compile::count(p, compile::opcode::call) == 0u, compensated);
        BOOST_TEST(compile::count(p, compile::opcode::sqrt) == 1u, compensated);
        // 2.25^(3/2) = 2.25 * 1.5 = 3.375, exactly.
        BOOST_TEST(compile::run<double>(p, {2.25}).front() == 3.375, compensated);
    }
}

BOOST_AUTO_TEST_CASE(the_condition_of_cases_is_compensated_with_its_branches)
{
    // a b - c d at a = b = 1 + 2^-30, c = 1, d = 1 + 2^-29 is 2^-60 > 0, exactly; in double
    // a b rounds to 1 + 2^-29 and the plain difference is 0, the other case. Near a
    // boundary between cases (a rough contact on the edge of sticking) the case taken is
    // the exact one only if the condition is compensated with the branches; |x| too.
    const GiNaC::symbol a("a"), b("b"), c("c"), d("d");
    const engine::term_order order({a, b, c, d});
    const GiNaC::ex gap = a * b - c * d;
    const std::vector<GiNaC::ex> cases = {engine::select_positive(gap, 1, -1),
                                          engine::select_positive(GiNaC::abs(gap) - GiNaC::pow(2, -61), 1, -1),
                                          engine::select_positive(GiNaC::abs(c * d - a * b) - GiNaC::pow(2, -61), 1, -1)};
    const std::vector<double> x = {1 + std::ldexp(1.0, -30), 1 + std::ldexp(1.0, -30), 1, 1 + std::ldexp(1.0, -29)};
    for (std::size_t i = 0; i < cases.size(); ++i) {
        const compile::program plain = compile::compile_program({cases[i]}, {a, b, c, d}, order);
        const compile::program compensated = compile::compile_program({cases[i]}, {a, b, c, d}, order, {false, true});
        BOOST_TEST(compile::run<double>(plain, x).front() == -1.0, i);
        BOOST_TEST(compile::run<double>(compensated, x).front() == 1.0, i);
    }
}
