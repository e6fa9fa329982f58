// Simulation and figures through the generated kernels, checked against physics laws
// and closed forms typed here: contact times, exchanged velocities, right angles,
// conserved momentum, the energy lost (Eq. 11), and Eq. 14 as an arctangent; rough spheres
// by Walton's model (sticking, sliding, angular momentum about the contact point, energy).
#define BOOST_TEST_MODULE test_simulate
#include <boost/test/unit_test.hpp>

#include "support.h"

#include "simulate/command.h"
#include "report/figures.h"
#include "simulate/simulate.h"

#include <sys/wait.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

using namespace impact;
using namespace impact::simulate;
namespace fs = std::filesystem;

namespace {

using impact::testing::run_impact;
using impact::testing::run_result;

constexpr double pi = 3.14159265358979323846;

scenario head_on(double eps, double mass_M = 1, double mass_m = 1)
{
    scenario s;
    s.name = "head_on";
    s.eps = eps;
    s.M = {mass_M, 0.5, {0, 0}, {0, 0}};
    s.m = {mass_m, 0.5, {-3, 0}, {1, 0}};
    return s;
}

double dot(const vec2& a, const vec2& b)
{
    return a[0] * b[0] + a[1] * b[1];
}

struct scratch {
    fs::path root = fs::temp_directory_path() / ("impact-simulate-" + std::to_string(::getpid()));
    scratch() { fs::create_directories(root); }
    ~scratch() { fs::remove_all(root); }
    std::string write(const std::string& name, const std::string& text) const
    {
        std::ofstream(root / name) << text;
        return (root / name).string();
    }
};

// The numbers of one row of a figure table whose first column is `x`.
std::vector<double> row_at(const std::string& table, const std::string& x)
{
    std::istringstream lines(table);
    std::string line;
    while (std::getline(lines, line)) {
        if (line.rfind(x + " ", 0) != 0)
            continue;
        std::istringstream fields(line);
        std::vector<double> values;
        double v;
        while (fields >> v)
            values.push_back(v);
        return values;
    }
    return {};
}

} // namespace

BOOST_AUTO_TEST_SUITE(physics)

BOOST_AUTO_TEST_CASE(head_on_spheres_touch_when_the_gap_closes)
{
    // Centres 3 apart, radii 0.5 each, closing at speed 1: contact at t = 2.
    const auto t = time_of_contact(head_on(1));
    BOOST_TEST_REQUIRE(t.has_value());
    BOOST_TEST(*t == 2.0, boost::test_tools::tolerance(1e-14));
}

BOOST_AUTO_TEST_CASE(equal_masses_elastic_head_on_exchange_velocities)
{
    const trajectory path = run(head_on(1));
    BOOST_TEST_REQUIRE(path.hit.has_value());
    BOOST_TEST(path.hit->v_M_after[0] == 1.0, boost::test_tools::tolerance(1e-14));
    BOOST_TEST(std::abs(path.hit->v_m_after[0]) < 1e-14);
    BOOST_TEST(std::abs(path.hit->v_M_after[1]) < 1e-14);
}

BOOST_AUTO_TEST_CASE(perfectly_inelastic_head_on_spheres_move_on_together)
{
    const trajectory path = run(head_on(0));
    BOOST_TEST_REQUIRE(path.hit.has_value());
    BOOST_TEST(path.hit->v_M_after[0] == 0.5, boost::test_tools::tolerance(1e-14));
    BOOST_TEST(path.hit->v_m_after[0] == 0.5, boost::test_tools::tolerance(1e-14));
}

BOOST_AUTO_TEST_CASE(an_elastic_off_centre_billiard_shot_scatters_at_a_right_angle)
{
    scenario s = head_on(1);
    s.m.position = {-3, 0.5};   // off-centre by one radius
    const trajectory path = run(s);
    BOOST_TEST_REQUIRE(path.hit.has_value());
    const contact& c = *path.hit;
    BOOST_TEST(std::abs(dot(c.v_M_after, c.v_m_after)) < 1e-14);
    // The object ball leaves along the line of centres at contact.
    const vec2 line{c.C_M[0] - c.C_m[0], c.C_M[1] - c.C_m[1]};
    BOOST_TEST(std::abs(line[0] * c.v_M_after[1] - line[1] * c.v_M_after[0]) < 1e-14);
    // The cue ball keeps its velocity across the line: (1, 0) · (1/2, √3/2) = 1/2 along that direction.
    BOOST_TEST(std::hypot(c.v_m_after[0], c.v_m_after[1]) == 0.5, boost::test_tools::tolerance(1e-13));
}

BOOST_AUTO_TEST_CASE(momentum_is_conserved_and_energy_lost_as_eq11_says)
{
    scenario s = head_on(0.4, 3.0, 1.25);
    s.m.position = {-4, 0.3};
    s.M.velocity = {-0.2, 0.1};
    s.m.velocity = {1.1, -0.05};
    const trajectory path = run(s);
    BOOST_TEST_REQUIRE(path.hit.has_value());
    const contact& c = *path.hit;
    for (int k = 0; k < 2; ++k)
        BOOST_TEST(s.M.mass * c.v_M_after[k] + s.m.mass * c.v_m_after[k] ==
                       s.M.mass * c.v_M_before[k] + s.m.mass * c.v_m_before[k],
                   boost::test_tools::tolerance(1e-13));
    // Eq. 11: ΔE = -(1 - ε²)/2 · M m/(M + m) · (relative velocity along the line)².
    const vec2 line{c.C_M[0] - c.C_m[0], c.C_M[1] - c.C_m[1]};
    const double n = std::hypot(line[0], line[1]);
    const double relative = ((c.v_M_before[0] - c.v_m_before[0]) * line[0] +
                             (c.v_M_before[1] - c.v_m_before[1]) * line[1]) / n;
    const double expected = -(1 - 0.4 * 0.4) / 2 * (3.0 * 1.25 / 4.25) * relative * relative;
    auto energy = [&](const vec2& vM, const vec2& vm) { return 0.5 * s.M.mass * dot(vM, vM) + 0.5 * s.m.mass * dot(vm, vm); };
    BOOST_TEST(energy(c.v_M_after, c.v_m_after) - energy(c.v_M_before, c.v_m_before) == expected,
               boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(spheres_that_pass_each_other_never_touch)
{
    scenario s = head_on(1);
    s.m.position = {-3, 1.5};   // the paths are 1.5 apart, the radii add up to 1
    const trajectory path = run(s);
    BOOST_TEST(!path.hit.has_value());
    BOOST_TEST(!path.later_contact.has_value());
    BOOST_TEST(summary(s, path).find("the spheres never touch") != std::string::npos);
    // Moving apart: never either.
    s = head_on(1);
    s.m.velocity = {-1, 0};
    BOOST_TEST(!time_of_contact(s).has_value());
}

BOOST_AUTO_TEST_CASE(a_contact_after_the_simulated_time_is_reported_as_such)
{
    scenario s = head_on(1);
    s.duration = 1.0;
    const trajectory path = run(s);
    BOOST_TEST(!path.hit.has_value());
    BOOST_TEST_REQUIRE(path.later_contact.has_value());
    BOOST_TEST(summary(s, path).find("do not touch before t = 1.0000 (they would at t = 2.0000)") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(the_trajectory_table_has_the_contact_as_a_row)
{
    scenario s = head_on(1);
    s.duration = 2.5;
    s.samples = 2;   // t = 0 and 2.5: the contact at t = 2 is added between them
    const std::string text = table(s, run(s));
    BOOST_TEST(text.find("t x_M y_M x_m y_m\n") != std::string::npos);
    BOOST_TEST(text.find("\n2.0000 0.0000 0.0000 -1.0000 0.0000\n") != std::string::npos, text);
    BOOST_TEST(text.find("\n2.5000 0.5000 0.0000 -1.0000 0.0000\n") != std::string::npos, text);
}

// m (spinning at 7 about z, counter-clockwise) hits M at rest head-on: n = (-1, 0) from M's
// centre to m's, g = v_M - v_m + R_m w_m z x n = (-1, -3.5), g_n = 1, g_t = (0, -3.5);
// m_r = 1/2, J_n = (1 + eps) m_r g_n = 1 (eps = 1), 1/m_t = 1 + 1 + 2.5 + 2.5 = 7.
scenario spinning_head_on(double beta, std::optional<double> mu)
{
    scenario s = head_on(1);
    s.m.spin = 7;
    s.beta = beta;
    s.mu = mu;
    return s;
}

BOOST_AUTO_TEST_CASE(rough_spheres_stick_as_waltons_model_says)
{
    // Sticking, beta = 1: J_t = (1 + beta) m_t g_t = (0, -1) on m; v_m' = v_m + J_n n + J_t,
    // v_M' = -(J_n n + J_t); w' = w - (R/(q mass R^2)) n x J_t with n x J_t = 1.
    const trajectory path = run(spinning_head_on(1, std::nullopt));
    BOOST_TEST_REQUIRE(path.hit.has_value());
    const contact& c = *path.hit;
    const double tol = 1e-14;
    BOOST_TEST(std::abs(c.v_m_after[0]) < tol);
    BOOST_TEST(c.v_m_after[1] == -1.0, boost::test_tools::tolerance(tol));
    BOOST_TEST(c.v_M_after[0] == 1.0, boost::test_tools::tolerance(tol));
    BOOST_TEST(c.v_M_after[1] == 1.0, boost::test_tools::tolerance(tol));
    BOOST_TEST(c.w_m_after == 2.0, boost::test_tools::tolerance(tol));
    BOOST_TEST(c.w_M_after == -5.0, boost::test_tools::tolerance(tol));
    BOOST_TEST(c.J_t == 1.0, boost::test_tools::tolerance(tol));
    BOOST_TEST(!c.slid);
    // beta = 1: the contact points' tangential velocity reversed, g'_t = -g_t: its y-component
    // g'_y = v'_My - v'_my - R (w'_M + w'_m) (z x n = (0, -1)) is 3.5, where g_y was -3.5.
    BOOST_TEST(c.v_M_after[1] - c.v_m_after[1] - 0.5 * (c.w_M_after + c.w_m_after) == 3.5,
               boost::test_tools::tolerance(1e-13));
    const std::string text = summary(spinning_head_on(1, std::nullopt), path);
    BOOST_TEST(text.find("rough: beta = 1.0000, mu = inf") != std::string::npos, text);
    BOOST_TEST(text.find("w_m 7.0000 -> 2.0000") != std::string::npos, text);
    BOOST_TEST(text.find("J_t = 1.0000, the contact stuck") != std::string::npos, text);
}

BOOST_AUTO_TEST_CASE(rough_spheres_slide_when_friction_caps_the_impulse)
{
    // mu J_n = 0.1 < |(1 + beta) m_t g_t| = 1: sliding, J_t = mu J_n g_t/|g_t| = (0, -0.1).
    const trajectory path = run(spinning_head_on(1, 0.1));
    BOOST_TEST_REQUIRE(path.hit.has_value());
    const contact& c = *path.hit;
    const double tol = 1e-14;
    BOOST_TEST(c.v_m_after[1] == -0.1, boost::test_tools::tolerance(tol));
    BOOST_TEST(c.v_M_after[0] == 1.0, boost::test_tools::tolerance(tol));
    BOOST_TEST(c.v_M_after[1] == 0.1, boost::test_tools::tolerance(tol));
    BOOST_TEST(c.w_m_after == 6.5, boost::test_tools::tolerance(tol));
    BOOST_TEST(c.w_M_after == -0.5, boost::test_tools::tolerance(tol));
    BOOST_TEST(c.slid);
    BOOST_TEST(summary(spinning_head_on(1, 0.1), path).find("the contact slid") != std::string::npos);
    // beta = -1 is the paper's smooth collision: spins kept, velocities as collide gives.
    const trajectory smooth = run(spinning_head_on(-1, 0.3));
    BOOST_TEST_REQUIRE(smooth.hit.has_value());
    BOOST_TEST(smooth.hit->w_m_after == 7.0, boost::test_tools::tolerance(tol));
    BOOST_TEST(std::abs(smooth.hit->w_M_after) < tol);
    BOOST_TEST(smooth.hit->v_M_after[0] == 1.0, boost::test_tools::tolerance(tol));
    BOOST_TEST(std::abs(smooth.hit->v_M_after[1]) < tol);
}

BOOST_AUTO_TEST_CASE(a_heavy_spinning_sphere_is_reported_sliding)
{
    // M 1e8 times heavier, spinning at 10: its spin changes by about 1e-8, too little to
    // read the tangential impulse from; the light sphere's change tells it. g_t = 5 - 0 = 5,
    // the sticking impulse (1 + beta) m_t g_t is about 2.9, mu J_n about 0.2: it slides.
    scenario s = head_on(1, 1e8, 1);
    s.M.spin = 10;
    s.beta = 1;
    s.mu = 0.1;
    const trajectory path = run(s);
    BOOST_TEST_REQUIRE(path.hit.has_value());
    BOOST_TEST(path.hit->slid);
    BOOST_TEST(std::abs(path.hit->J_t) == 0.1 * std::abs(path.hit->J), boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(a_rough_collision_keeps_momentum_and_angular_momentum_and_loses_energy)
{
    for (const std::optional<double> mu : {std::optional<double>{}, std::optional<double>{0.05}}) {
        scenario s = head_on(0.7, 2.5, 1.0);
        s.M.radius = 0.8;
        s.m.radius = 0.3;
        s.M.q = 2.0 / 3;
        s.m.position = {-4, 0.6};
        s.M.velocity = {-0.1, 0.2};
        s.m.velocity = {1.3, -0.1};
        s.M.spin = -2;
        s.m.spin = 5;
        s.beta = 0.4;
        s.mu = mu;
        const trajectory path = run(s);
        BOOST_TEST_REQUIRE(path.hit.has_value());
        const contact& c = *path.hit;
        BOOST_TEST(c.slid == mu.has_value());
        const double tol = 1e-12;
        for (int k = 0; k < 2; ++k)
            BOOST_TEST(s.M.mass * c.v_M_after[k] + s.m.mass * c.v_m_after[k] ==
                           s.M.mass * c.v_M_before[k] + s.m.mass * c.v_m_before[k],
                       boost::test_tools::tolerance(tol));
        // About the contact point P = C_M + R_M n: each impulse acts at P, so the angular
        // momentum (C - P) x mass v + q mass R^2 w is kept.
        const vec2 d{c.C_m[0] - c.C_M[0], c.C_m[1] - c.C_M[1]};
        const double length = std::hypot(d[0], d[1]);
        const vec2 n{d[0] / length, d[1] / length};
        const vec2 P{c.C_M[0] + s.M.radius * n[0], c.C_M[1] + s.M.radius * n[1]};
        auto cross = [](const vec2& a, const vec2& b) { return a[0] * b[1] - a[1] * b[0]; };
        auto angular = [&](const vec2& vM, const vec2& vm, double wM, double wm) {
            const vec2 rM{c.C_M[0] - P[0], c.C_M[1] - P[1]}, rm{c.C_m[0] - P[0], c.C_m[1] - P[1]};
            return s.M.mass * cross(rM, vM) + s.m.mass * cross(rm, vm) +
                   s.M.q * s.M.mass * s.M.radius * s.M.radius * wM + s.m.q * s.m.mass * s.m.radius * s.m.radius * wm;
        };
        BOOST_TEST(angular(c.v_M_after, c.v_m_after, c.w_M_after, c.w_m_after) ==
                       angular(c.v_M_before, c.v_m_before, c.w_M_before, c.w_m_before),
                   boost::test_tools::tolerance(tol));
        // The energy, translational and rotational: sticking, dE = -(1 - eps^2) m_r g_n^2/2
        // - (1 - beta^2) m_t |g_t|^2/2; sliding, the same normal part less |J_t| (|g_t| - |J_t|/(2 m_t)).
        auto energy = [&](const vec2& vM, const vec2& vm, double wM, double wm) {
            return 0.5 * s.M.mass * dot(vM, vM) + 0.5 * s.m.mass * dot(vm, vm) +
                   0.5 * s.M.q * s.M.mass * s.M.radius * s.M.radius * wM * wM +
                   0.5 * s.m.q * s.m.mass * s.m.radius * s.m.radius * wm * wm;
        };
        const double dE = energy(c.v_M_after, c.v_m_after, c.w_M_after, c.w_m_after) -
                          energy(c.v_M_before, c.v_m_before, c.w_M_before, c.w_m_before);
        const vec2 t{-n[1], n[0]};   // z x n
        const double W = s.M.radius * c.w_M_before + s.m.radius * c.w_m_before;
        const vec2 g{c.v_M_before[0] - c.v_m_before[0] + W * t[0], c.v_M_before[1] - c.v_m_before[1] + W * t[1]};
        const double g_n = dot(g, n), g_t = dot(g, t);
        const double m_r = s.M.mass * s.m.mass / (s.M.mass + s.m.mass);
        const double m_t = 1 / (1 / s.M.mass + 1 / s.m.mass + 1 / (s.M.q * s.M.mass) + 1 / (s.m.q * s.m.mass));
        const double normal = -(1 - 0.7 * 0.7) * m_r * g_n * g_n / 2;
        if (!mu) {
            BOOST_TEST(dE == normal - (1 - 0.4 * 0.4) * m_t * g_t * g_t / 2, boost::test_tools::tolerance(tol));
        } else {
            // |J_t| = mu J_n.
            const double J_t = *mu * (1 + 0.7) * m_r * g_n;
            BOOST_TEST(std::abs(c.J_t) == J_t, boost::test_tools::tolerance(tol));
            BOOST_TEST(dE == normal - J_t * (std::abs(g_t) - J_t / (2 * m_t)), boost::test_tools::tolerance(tol));
        }
        BOOST_TEST(dE < 0);
    }
}

BOOST_AUTO_TEST_CASE(spins_turn_the_marks_of_the_table)
{
    // Before the contact at t = 2 m turns at 7, after it at 2 (sticking above): at t = 3
    // it has turned 14 + 2 = 16 radians, M -5.
    const scenario s = spinning_head_on(1, std::nullopt);
    const std::string text = table(s, run(s));
    BOOST_TEST(text.find("t x_M y_M x_m y_m a_M a_m\n") != std::string::npos, text);
    const std::vector<double> at_3 = row_at(text, "3.0000");
    BOOST_TEST_REQUIRE(at_3.size() == 7u);
    BOOST_TEST(at_3[5] == -5.0, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(at_3[6] == 16.0, boost::test_tools::tolerance(1e-12));
    // Smooth spheres spin on unchanged; spheres that do not spin keep the five columns.
    scenario smooth = head_on(1);
    smooth.M.spin = 1.5;
    const std::vector<double> kept = row_at(table(smooth, run(smooth)), "3.0000");
    BOOST_TEST_REQUIRE(kept.size() == 7u);
    BOOST_TEST(kept[5] == 4.5, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(table(head_on(1), run(head_on(1))).find("a_M") == std::string::npos);
    // The figure marks a point of each rim from the angle columns.
    const std::string tex = figure(s, run(s), "spin.dat");
    BOOST_TEST(tex.find("x expr={\\thisrow{x_m} + 0.5000*cos(deg(\\thisrow{a_m}))}") != std::string::npos, tex);
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(scenarios)

BOOST_AUTO_TEST_CASE(a_scenario_file_is_read)
{
    const scenario s = parse_scenario("name = \"x\"\neps = 0.5\nduration = 4\n"
                                      "[M]\nmass = 2\nradius = 0.25\nposition = [1, 2]\nvelocity = [0, -1]\n"
                                      "[m]\nmass = 1.5\nradius = 0.5\nposition = [-2, 2]\nvelocity = [1, 0]\n",
                                      "x.toml");
    BOOST_TEST(s.name == "x");
    BOOST_TEST(s.eps == 0.5);
    BOOST_TEST(*s.duration == 4.0);
    BOOST_TEST(s.M.mass == 2.0);
    BOOST_TEST(s.M.position[1] == 2.0);
    BOOST_TEST(s.m.velocity[0] == 1.0);
}

BOOST_AUTO_TEST_CASE(bad_scenarios_are_refused_with_their_place)
{
    const std::string spheres = "[M]\nmass = 1\nradius = 0.5\nposition = [0, 0]\nvelocity = [0, 0]\n"
                                "[m]\nmass = 1\nradius = 0.5\nposition = [-3, 0]\nvelocity = [1, 0]\n";
    auto refused = [](const std::string& text, const std::string& what) {
        try {
            parse_scenario(text, "bad.toml");
        } catch (const impact::error& e) {
            BOOST_TEST(std::string(e.what()).find(what) != std::string::npos, e.what());
            return;
        }
        BOOST_ERROR("accepted: " + text);
    };
    // The scenario with its first `from` written `to`.
    auto replaced = [](std::string text, const std::string& from, const std::string& to) {
        return text.replace(text.find(from), from.size(), to);
    };
    refused("eps = 1.5\n" + spheres, "bad.toml:1:7: error: eps is 1.5, outside [0, 1]");
    refused("eps = nan\n" + spheres, "bad.toml:1:7: error: eps is nan, not a finite number");
    refused("eps = 1\nduration = -inf\n" + spheres, "bad.toml:2:12: error: the duration is -inf, not a finite number");
    refused("eps = 1\nduration = 1e300\n" + spheres,
            "bad.toml:2:12: error: the duration is 1e+300, beyond what the simulation computes with: a number "
            "other than 0 must lie between 1e-100 and 1e+100 in magnitude");
    refused("eps = 1\nsamples = 1e9\n" + spheres,
            "bad.toml:2:11: error: samples = 1000000000 must be a whole number from 2 to 10000");
    refused("eps = 1\nsamples = 2.5\n" + spheres, "samples = 2.5 must be a whole number");
    refused("eps = 1\n" + replaced(spheres, "mass = 1", "mass = 1e-300"), "bad.toml:3:8: error: the mass of M is 1e-300, beyond what the simulation");
    refused("eps = 1\n" + replaced(spheres, "[-3, 0]", "[-3e10, 0]"), "bad.toml:1:1: error: the spheres start 6e+10 radii apart (of the smaller sphere), "
                                "more than the 1e+10 within which double precision places their contact");
    refused("eps = 1\nduration = 1e11\n" + spheres,
            "bad.toml:1:1: error: m travels 2e+11 radii (of the smaller sphere) in the duration 1e+11");
    refused("eps = 1\nspeed = 3\n" + spheres, "bad.toml:2:");
    refused("eps = 1\n" + spheres.substr(0, spheres.find("[m]")), "needs a table [m]");
    refused("eps = \"one\"\n" + spheres, "'eps' in the scenario must be a number");
    refused("eps = 1\nbeta = 1.5\n" + spheres, "bad.toml:2:8: error: beta is 1.5, outside [-1, 1]");
    refused("eps = 1\nbeta = 0\nmu = -0.5\n" + spheres, "bad.toml:3:6: error: mu is -0.5, negative");
    refused("eps = 1\nbeta = 0\nmu = nan\n" + spheres, "bad.toml:3:6: error: mu is nan, not a number in [0, inf]");
    refused("eps = 1\nmu = 0.5\n" + spheres, "bad.toml:2:6: error: mu is the friction of rough spheres: give beta too");
    refused("eps = 1\n" + replaced(spheres, "velocity = [0, 0]", "velocity = [0, 0]\nq = 0.7"), "bad.toml:7:5: error: q of M is 0.7, outside (0, 2/3]");
    refused("eps = 1\n" + replaced(spheres, "velocity = [1, 0]", "velocity = [1, 0]\nspin = inf"), "error: the spin of m is inf, not a finite number");
    const scenario read = parse_scenario(
        "eps = 1\nbeta = 0.5\nmu = inf\n" + replaced(spheres, "velocity = [1, 0]", "velocity = [1, 0]\nspin = -2"),
        "good.toml");
    BOOST_TEST(*read.beta == 0.5);
    BOOST_TEST(std::isinf(*read.mu));
    BOOST_TEST(read.m.spin == -2.0);
    BOOST_TEST(read.M.q == 0.4);
    refused("eps = 1\n" + replaced(spheres, "[-3, 0]", "[-0.5, 0]"), "the spheres overlap at the start");
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(figures)

BOOST_AUTO_TEST_CASE(fig3_follows_eq14_as_an_arctangent)
{
    const auto files = report::figure_files();
    const std::string& by_perp = files.at("figures/scatter_angle_vs_v_perp.dat");
    // Columns eps = 0, 1/3, 2/3, 0.9, 1; θ = atan(2 v⊥ / ((1 - ε) v∥)), v∥ = 1.
    const std::vector<double> row = row_at(by_perp, "0.500");
    BOOST_TEST_REQUIRE(row.size() == 6u);
    const double eps[] = {0, 1.0 / 3, 2.0 / 3, 0.9};
    for (int j = 0; j < 4; ++j)
        BOOST_TEST(row[j + 1] == std::atan(2 * 0.5 / (1 - eps[j])) * 180 / pi, boost::test_tools::tolerance(1e-5));
    BOOST_TEST(row[5] == 90.0);   // elastic: a right angle
    const std::string& by_eps = files.at("figures/scatter_angle_vs_eps.dat");
    const std::vector<double> at_zero = row_at(by_eps, "0.00");
    BOOST_TEST_REQUIRE(at_zero.size() == 6u);
    BOOST_TEST(at_zero[1] == std::atan(0.2) * 180 / pi, boost::test_tools::tolerance(1e-5));
}

BOOST_AUTO_TEST_CASE(fig2_draws_three_billiard_shots_to_scale)
{
    const auto files = report::figure_files();
    for (const char* name : {"figures/billiard_eps_1.dat", "figures/billiard_eps_2_3.dat",
                             "figures/billiard_eps_1_3.dat", "figures/billiard.tex", "figures/billiard_plot.tex"})
        BOOST_TEST(files.count(name) == 1u, name);
    // The figure includes its picture compiled; the picture is drawn by pgfplots.
    BOOST_TEST(files.at("figures/billiard.tex").find("\\includegraphics{figures/billiard_plot}") != std::string::npos);
    BOOST_TEST(files.at("figures/billiard.tex").find("\\label{fig:billiard}") != std::string::npos);
    const std::string& tex = files.at("figures/billiard_plot.tex");
    BOOST_TEST(tex.find("axis equal image") != std::string::npos);
    BOOST_TEST(tex.find("title={$\\epsilon = 2/3$}") != std::string::npos);
    // The elastic shot: after contact the object ball leaves along the line of centres,
    // at 30 degrees below the x axis (an off-centre hit by one radius).
    const std::vector<double> last = row_at(files.at("figures/billiard_eps_1.dat"), "5.0000");
    BOOST_TEST_REQUIRE(last.size() == 5u);
    BOOST_TEST(std::atan2(last[2], last[1]) * 180 / pi == -30.0, boost::test_tools::tolerance(1e-3));
}

// The rough-sphere figure against Walton's model typed here: two equal solid spheres
// (q = 2/5, so 1/m_t = 1 + 1 + 5/2 + 5/2 = 7 for unit masses, m_r = 1/2), eps = 0.9,
// beta = 0.4. Sticking: beta_eff = beta; sliding: -1 + mu (1 + eps) (m_r/m_t)/tan psi,
// where (1 + beta) m_t tan psi > mu (1 + eps) m_r.
BOOST_AUTO_TEST_CASE(the_rough_figure_follows_waltons_model)
{
    const auto files = report::figure_files();
    const std::string& data = files.at("figures/rough_beta_eff.dat");
    const double mu[] = {0.05, 0.1, 0.2, 0.5};
    const double m_r = 0.5, m_t = 1.0 / 7, eps = 0.9, beta = 0.4;
    for (const char* psi_text : {"5.0", "20.0", "30.0", "45.0", "60.0", "80.0", "89.0"}) {
        const std::vector<double> row = row_at(data, psi_text);
        BOOST_TEST_REQUIRE(row.size() == 6u, psi_text);
        const double tan_psi = std::tan(row[0] * pi / 180);
        for (int j = 0; j < 4; ++j) {
            const bool slides = (1 + beta) * m_t * tan_psi > mu[j] * (1 + eps) * m_r;
            const double expected = slides ? -1 + mu[j] * (1 + eps) * (m_r / m_t) / tan_psi : beta;
            // The table keeps four decimals: within half a unit of the last.
            BOOST_TEST(std::fabs(row[j + 1] - expected) <= 0.5e-4 + 1e-12, psi_text << ", mu = " << mu[j]);
        }
        BOOST_TEST(std::fabs(row[5] - beta) <= 0.5e-4 + 1e-12);   // mu = +inf: always sticks
    }
    const std::string& figure = files.at("figures/rough_beta_eff.tex");
    BOOST_TEST(figure.find("\\includegraphics{figures/rough_beta_eff_plot}") != std::string::npos);
    BOOST_TEST(figure.find("\\label{fig:rough-beta-eff}") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(figures_are_the_same_bytes_every_time)
{
    BOOST_TEST((report::figure_files() == report::figure_files()));
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(command)

BOOST_AUTO_TEST_CASE(simulate_writes_a_table_and_a_figure)
{
    const scratch s;
    const std::string file = s.write("shot.toml", "name = \"shot\"\neps = 0.5\n"
                                                  "[M]\nmass = 1\nradius = 0.5\nposition = [0, 0]\nvelocity = [0, 0]\n"
                                                  "[m]\nmass = 1\nradius = 0.5\nposition = [-3, 0]\nvelocity = [1, 0]\n");
    const run_result r = run_impact("simulate " + file + " --output " + (s.root / "out").string());
    BOOST_TEST(r.status == 0, r.output);
    BOOST_TEST(r.output.find("contact at t = 2.0000") != std::string::npos, r.output);
    BOOST_TEST(r.output.find("v_m (1.0000, 0.0000) -> (0.2500, 0.0000)") != std::string::npos, r.output);
    BOOST_TEST(fs::exists(s.root / "out" / "shot.dat"));
    std::ifstream in(s.root / "out" / "shot.tex");
    std::ostringstream tex;
    tex << in.rdbuf();
    BOOST_TEST(tex.str().find("table[x=x_M, y=y_M] {shot.dat}") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(the_example_scenarios_run)
{
    // The scenarios docs/simulate.md shows: read, checked and run as users will.
    int count = 0;
    for (const auto& entry : fs::directory_iterator(fs::path(IMPACT_SOURCE_DIR) / "tests" / "scenarios")) {
        const scenario s = read_scenario(entry.path().string());
        const trajectory path = run(s);
        BOOST_TEST(path.hit.has_value(), entry.path());
        ++count;
    }
    BOOST_TEST(count >= 2);
    // The rough one slides: its tangential impulse is mu times the normal one.
    const scenario rough = read_scenario(IMPACT_SOURCE_DIR "/tests/scenarios/rough_spin.toml");
    const trajectory path = run(rough);
    BOOST_TEST_REQUIRE(path.hit.has_value());
    BOOST_TEST(path.hit->slid);
    BOOST_TEST(std::abs(path.hit->J_t) == 0.3 * std::abs(path.hit->J), boost::test_tools::tolerance(1e-13));
}

BOOST_AUTO_TEST_CASE(simulate_says_when_the_spheres_never_touch)
{
    const scratch s;
    const run_result r = run_impact("simulate --position-m=-3,2 --output " + (s.root / "out").string());
    BOOST_TEST(r.status == 0, r.output);
    BOOST_TEST(r.output.find("the spheres never touch") != std::string::npos, r.output);
}

BOOST_AUTO_TEST_CASE(simulate_refuses_bad_options)
{
    // Each option's mistake: exit 2, one line naming the option, nothing written.
    const scratch s;
    const std::string out = (s.root / "out").string();
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"--eps 2", "--eps: error: eps is 2, outside [0, 1]"},
        {"--eps -1e-16", "--eps: error: eps is -1e-16, outside [0, 1]"},
        {"--velocity-m 1", "--velocity-m: error: '1' must be two numbers x,y"},
        {"--velocity-m 1e300,0", "--velocity-m: error: the velocity of m is 1e+300, beyond what the simulation"},
        {"--position-M 0,nan", "--position-M: error: the position of M is nan, not a finite number"},
        {"--duration 1e300", "--duration: error: the duration is 1e+300, beyond what the simulation computes with"},
        {"--duration 0", "--duration: error: the duration is 0, not positive"},
        {"--duration inf", "--duration: error: the duration is inf, not a finite number"},
        {"--mass-M -1", "--mass-M: error: the mass of M is -1, not positive"},
        {"--mass-m 1e-300", "--mass-m: error: the mass of m is 1e-300, beyond what the simulation computes with"},
        {"--radius-M 0", "--radius-M: error: the radius of M is 0, not positive"},
        {"--radius-m 1e101", "--radius-m: error: the radius of m is 1e+101, beyond"},
        {"--duration 1e12", "the command line: error: m travels 2e+12 radii (of the smaller sphere)"},
        {"--name ../x", "the command line: error: scenario name '../x' must be letters, digits, - and _"},
        {"--beta 2", "--beta: error: beta is 2, outside [-1, 1]"},
        {"--beta 0 --mu -1", "--mu: error: mu is -1, negative"},
        {"--mu 0.5", "--mu: error: mu is the friction of rough spheres: give --beta too"},
        {"--q-M 0", "--q-M: error: q of M is 0, outside (0, 2/3]"},
        {"--spin-m nan", "--spin-m: error: the spin of m is nan, not a finite number"},
        // Mistakes the option parser finds are one line too, with exit status 2.
        {"--eps abc", "impact: error: Could not convert: --eps = abc (impact --help lists the commands"},
        {"--eps", "impact: error: --eps: 1 required FLOAT missing"},
        {"--bogus 3", "impact: error: The following argument was not expected: --bogus"},
    };
    for (const auto& [options, message] : cases) {
        const run_result r = run_impact("simulate --output " + out + " " + options);
        BOOST_TEST(r.status == 2, options << ": " << r.output);
        BOOST_TEST(r.output.rfind(message, 0) == 0, options << ": " << r.output);
        BOOST_TEST(r.output.find('\n') == r.output.size() - 1, options << ": not one line: " << r.output);
        BOOST_TEST(!fs::exists(out), options << ": wrote " << out);
    }
}

BOOST_AUTO_TEST_SUITE_END()
