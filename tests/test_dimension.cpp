// Dimensions: their algebra and names, and the rules by which an expression's dimension
// follows from its symbols' (engine/dimension/dimension.h). Expected texts are typed here.
#define BOOST_TEST_MODULE test_dimension
#include <boost/test/unit_test.hpp>

#include "engine/derive/derive.h"
#include "engine/expr/dimensional.h"
#include "engine/dimension/dimension.h"
#include "spec/derivation.h"

#include <fstream>
#include <iterator>
#include <map>
#include <string>

using namespace impact;
using engine::dimension;

namespace impact::engine {
std::ostream& operator<<(std::ostream& out, const dimension& d)
{
    return out << d.to_string();
}
} // namespace impact::engine

namespace {

const engine::dimension_names names;

dimension d(const std::string& text)
{
    return names.parse(text, {"test", 1, 1});
}

// The symbols of Eq. 8 and Eq. 11 with their dimensions.
struct collision {
    GiNaC::possymbol M{"M"}, m{"m"}, R{"R"}, t{"t"};
    GiNaC::realsymbol v_M{"v_M"}, v_m{"v_m"}, eps{"eps"}, x{"x"}, unknown{"unknown"};
    engine::dimension_map known{{M, d("mass")},     {m, d("mass")},  {R, d("length")}, {t, d("time")},
                                {v_M, d("velocity")}, {v_m, d("velocity")}, {eps, d("1")}, {x, d("length")}};

    std::string of(const GiNaC::ex& e) const
    {
        const auto found = engine::dimension_of(e, known, {"bad.toml", 7, 3});
        return found ? found->to_string() : "unknown";
    }

    std::string refusal(const GiNaC::ex& e) const
    {
        try {
            engine::dimension_of(e, known, {"bad.toml", 7, 3});
        } catch (const error& e) {
            return e.what();
        }
        return "accepted";
    }
};

} // namespace

BOOST_AUTO_TEST_SUITE(algebra)

BOOST_AUTO_TEST_CASE(named_dimensions_are_products_of_mass_length_and_time)
{
    BOOST_TEST(d("energy").to_string() == "mass*length^2/time^2");
    BOOST_TEST(d("momentum").to_string() == "mass*length/time");
    BOOST_TEST(d("velocity") == d("length/time"));
    BOOST_TEST(d("energy/velocity") == d("momentum"));
    BOOST_TEST(d("angular_velocity").to_string() == "1/time");
    BOOST_TEST(d("moment_of_inertia").to_string() == "mass*length^2");
    BOOST_TEST(d("1").to_string() == "1");
    BOOST_TEST(d("length/length").is_pure_number());
    BOOST_TEST(d("length^(1/2)").to_string() == "length^(1/2)");
    BOOST_TEST(d("time^-2*length").to_string() == "length/time^2");
}

BOOST_AUTO_TEST_CASE(familiar_combinations_are_named_as_a_physicist_would)
{
    BOOST_TEST(d("mass*length/time").describe() == "mass*length/time (a momentum)");
    BOOST_TEST(d("mass*length^2/time^2").describe() == "mass*length^2/time^2 (an energy)");
    BOOST_TEST(d("mass*time").describe() == "mass*time");
    BOOST_TEST(d("mass").describe() == "mass");
    BOOST_TEST(d("1").describe() == "a pure number");
    BOOST_TEST(d("energy").si_unit() == "kg m^2 s^-2");
    BOOST_TEST(d("1").si_unit() == "1");
}

BOOST_AUTO_TEST_CASE(a_derivation_may_add_a_base_and_names)
{
    engine::dimension_names own;
    own.add_base("angle", {});
    own.add("spin", own.parse("angle/time", {}), {});
    BOOST_TEST(own.parse("spin*time", {}).to_string() == "angle");
    BOOST_CHECK_THROW(own.add_base("mass", {"f", 2, 1}), error);
}

BOOST_AUTO_TEST_CASE(a_text_that_is_not_a_product_of_powers_is_refused_at_its_place)
{
    try {
        names.parse("mass*lenght", {"bad.toml", 4, 13});
        BOOST_ERROR("accepted");
    } catch (const error& e) {
        BOOST_TEST(std::string(e.what()) ==
                   "bad.toml:4:13: error: dimension \"mass*lenght\" names 'lenght', which is not a dimension; write "
                   "a product of powers of mass, length, time and named dimensions, such as mass*length^2/time^2, "
                   "or 1 for a pure number");
    }
    BOOST_CHECK_THROW(names.parse("mass+length", {}), error);
    BOOST_CHECK_THROW(names.parse("mass^x", {}), error);
    BOOST_CHECK_THROW(names.parse("", {}), error);
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(inference)

BOOST_AUTO_TEST_CASE(products_powers_and_sums_of_one_dimension)
{
    const collision c;
    // Eq. 8: v'_M = v_M - (1 + eps) m (v_M - v_m)/(M + m), a velocity.
    BOOST_TEST(c.of(c.v_M - (1 + c.eps) * c.m * (c.v_M - c.v_m) / (c.M + c.m)) == "length/time");
    // Eq. 11: the energy lost, (1 - eps^2) M m (v_M - v_m)^2 / (2 (M + m)).
    BOOST_TEST(c.of((1 - GiNaC::pow(c.eps, 2)) * c.M * c.m * GiNaC::pow(c.v_M - c.v_m, 2) / (2 * (c.M + c.m))) ==
               "mass*length^2/time^2");
    BOOST_TEST(c.of(GiNaC::sqrt(c.v_M * c.v_M + c.v_m * c.v_m)) == "length/time");
    BOOST_TEST(c.of(GiNaC::sqrt(c.R)) == "length^(1/2)");
    BOOST_TEST(c.of(GiNaC::atan2(c.v_M, c.v_m)) == "1");
    BOOST_TEST(c.of(GiNaC::cos(c.eps) + GiNaC::exp(c.v_M * c.t / c.R)) == "1");
    BOOST_TEST(c.of(GiNaC::abs(c.v_M)) == "length/time");
    BOOST_TEST(c.of(c.v_M == c.v_m) == "length/time");
    BOOST_TEST(c.of(c.v_M * c.M == 0) == "mass*length/time");
}

BOOST_AUTO_TEST_CASE(a_symbol_without_a_dimension_leaves_what_holds_it_unknown)
{
    const collision c;
    BOOST_TEST(c.of(c.unknown * c.M) == "unknown");
    BOOST_TEST(c.of(c.unknown + c.M) == "unknown");
    // The known parts are still checked.
    BOOST_TEST(c.refusal(c.unknown + c.M + c.v_M) != "accepted");
}

BOOST_AUTO_TEST_CASE(appendix_a_line_1_adds_a_momentum_where_an_energy_belongs)
{
    // The paper prints E'_K = 1/2 m v'_m + 1/2 m v'_M: the squares (and M) missing.
    const collision c;
    const GiNaC::ex printed = c.m * c.v_m / 2 + c.m * c.v_M / 2;
    const GiNaC::ex energy = c.M * c.v_M * c.v_M / 2 + c.m * c.v_m * c.v_m / 2;
    // (GiNaC's order of terms is its own: only the dimensions' words are compared.)
    const std::string message = c.refusal(energy == printed);
    BOOST_TEST(message.rfind("bad.toml:7:3: error: sets ", 0) == 0, message);
    BOOST_TEST(message.find(", mass*length^2/time^2 (an energy), against ") != std::string::npos, message);
    BOOST_TEST(message.find(", mass*length/time (a momentum): both sides share one dimension") != std::string::npos,
               message);
}

BOOST_AUTO_TEST_CASE(each_rule_broken_is_named_with_the_dimensions)
{
    const collision c;
    BOOST_TEST(c.refusal(c.M * c.v_M + c.M * c.v_M * c.v_M).find("mass*length/time (a momentum)") !=
               std::string::npos);
    BOOST_TEST(c.refusal(c.M * c.v_M + c.M * c.v_M * c.v_M).find("mass*length^2/time^2 (an energy)") !=
               std::string::npos);
    BOOST_TEST(c.refusal(1 + c.M).find("the terms of a sum share one dimension") != std::string::npos);
    // x is real: GiNaC keeps atan2(v_M, x) as it is (a positive x would turn it into an atan).
    BOOST_TEST(c.refusal(GiNaC::atan2(c.v_M, c.x)) ==
               "bad.toml:7:3: error: takes atan2 of v_M, length/time (a velocity), and x, length: its two arguments "
               "share one dimension");
    BOOST_TEST(c.refusal(GiNaC::exp(c.t)) == "bad.toml:7:3: error: takes exp of t, time: its argument is a pure number");
    BOOST_TEST(c.refusal(GiNaC::sin(c.M / c.m) + c.M).find("adds") != std::string::npos);
    BOOST_TEST(c.refusal(GiNaC::pow(c.eps, c.t)).find("an exponent is a pure number") != std::string::npos);
    BOOST_TEST(c.refusal(GiNaC::pow(c.M, c.eps)).find("takes only a numeric exponent") != std::string::npos);
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(derivation_files)

// A projectile, not the paper's: every kind of expression the rules cover, dimensions
// declared, named by the file ([[dimension]]) and inferred from definitions and steps.
const char* const projectile = R"toml(id = "projectile"
title = "a projectile's flight"
[[dimension]]
name = "angle"
[[dimension]]
name = "spin"
as = "angle/time"
[[symbol]]
name = "g"
domain = "positive"
dimension = "acceleration"
[[symbol]]
name = "w"
domain = "positive"
dimension = "velocity"
[[symbol]]
name = "alpha"
domain = "[0, 1]"
dimension = "1"
[[symbol]]
name = "k"
domain = "positive"
dimension = "1/time"
[[symbol]]
name = "omega"
dimension = "spin"
[[symbol]]
name = "T"
[[symbol]]
name = "R"
dimension = "length"
[[symbol]]
name = "h"
dimension = "length"
definition = "w^2*sin(alpha)^2/(2*g)"
[[symbol]]
name = "heading"
definition = "atan2(w*sin(alpha), w*cos(alpha))"
[[symbol]]
name = "decay"
definition = "exp(-k*T) + log(k*T)"
[[symbol]]
name = "landing_speed"
definition = "sqrt(w^2 + 2*g*h)"
[[symbol]]
name = "turned"
definition = "omega*T"
[[given]]
name = "flight"
equation = "T = 2*w*sin(alpha)/g"
because = "the height is back to zero"
[[given]]
name = "range"
equation = "R = w*cos(alpha)*T"
because = "uniform motion across"
[[step]]
solve = ["flight", "range"]
for = ["T", "R"]
[[result]]
name = "R"
[[check]]
name = "double_angle"
claim = "R = 2*w^2*sin(alpha)*cos(alpha)/g"
)toml";

BOOST_AUTO_TEST_CASE(a_consistent_derivation_of_every_kind_of_expression_derives)
{
    const engine::derivation d = engine::derive(spec::parse_derivation(projectile, "projectile.toml"), {});
    const std::map<std::string, std::string> expected = {
        {"g", "length/time^2"}, {"w", "length/time"},   {"alpha", "1"},    {"k", "1/time"},
        {"omega", "angle/time"}, {"T", "time"},          {"R", "length"},   {"h", "length"},
        {"heading", "1"},        {"decay", "1"},         {"landing_speed", "length/time"},
        {"turned", "angle"},
    };
    for (const engine::quantity& q : d.symbols.all()) {
        BOOST_TEST_REQUIRE(q.dim.has_value(), q.name);
        BOOST_TEST(q.dim->to_string() == expected.at(q.name), q.name);
    }
    BOOST_TEST(d.all_hold());
    BOOST_TEST(engine::symbols_without_dimension(d.symbols).empty());
}

BOOST_AUTO_TEST_CASE(a_file_without_dimensions_still_derives_and_says_what_has_none)
{
    std::string text = projectile;
    for (std::size_t at; (at = text.find("dimension = ")) != std::string::npos;)
        text.erase(at, text.find('\n', at) - at + 1);
    text.erase(text.find("[[dimension]]"), text.find("[[symbol]]") - text.find("[[dimension]]"));
    const engine::derivation d = engine::derive(spec::parse_derivation(text, "projectile.toml"), {});
    BOOST_TEST(d.all_hold());
    // g, w, alpha, k, omega, T, R and every abbreviation of them: nothing to infer from.
    BOOST_TEST(engine::symbols_without_dimension(d.symbols).size() == 12u);
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(kernels)

// The committed headers are what a regeneration writes (test_cli); their parameter
// comments name the SI unit each input is expected in.
BOOST_AUTO_TEST_CASE(kernel_parameters_name_their_units)
{
    std::ifstream in(IMPACT_SOURCE_DIR "/output/kernels/impact/collide_line.hpp");
    const std::string header((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    for (const char* line : {"///   M: mass of sphere M (positive, in kg)\n",
                             "///   eps: Newton's coefficient of restitution ([0, 1], a pure number)\n"})
        BOOST_TEST(header.find(line) != std::string::npos, line);
    BOOST_TEST(header.find("(real, in m s^-1)") != std::string::npos);
}

BOOST_AUTO_TEST_SUITE_END()
