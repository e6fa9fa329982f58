// Where kernels' accuracy is measured (verify/sampling.h): each regime's samples are where
// its name says, checked from the inputs with the physics typed here (the contact points'
// velocities, the friction cone), not with the engine's expressions: the rough spheres'
// tangential slip over sixteen decades, the sticking boundary within 1e-12, nearly central
// hits with large spin, β and q near their ends; a wall's grazing and head-on hits along
// its normal; and the names each kernel's regimes are listed under in verification.md.
#define BOOST_TEST_MODULE test_sampling
#include <boost/test/unit_test.hpp>

#include "engine/library/library.h"
#include "verify/sampling.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <string>

#include <unistd.h>

namespace {

using namespace impact;

struct drawn {
    engine::library lib;
    engine::term_order order;
    const engine::kernel* kernel = nullptr;
    std::vector<verify::sample> samples;

    // The samples of one regime.
    std::vector<const verify::sample*> in(const std::string& regime) const
    {
        std::vector<const verify::sample*> out;
        for (const verify::sample& s : samples)
            if (s.regime == regime)
                out.push_back(&s);
        return out;
    }
};

// 4200 samples of derivation `id`'s first kernel, as verification draws them (without the
// guards' admission: the regimes' shapes are what is checked).
const drawn& samples_of(const std::string& id)
{
    static std::map<std::string, std::unique_ptr<drawn>> all;
    auto& d = all[id];
    if (!d) {
        engine::library lib = engine::derive_all(engine::read_directory(IMPACT_SOURCE_DIR "/derivations"), id);
        engine::term_order order = engine::declaration_order(lib.derived.at(id).symbols);
        d.reset(new drawn{std::move(lib), std::move(order), nullptr, {}});
        d->kernel = &d->lib.derived.at(id).kernels.front();
        d->samples = verify::draw_samples(*d->kernel, 4200, 12345, d->order);
    }
    return *d;
}

// The samples of derivation `id`'s first kernel with `regimes` appended to its file (the
// kernel is the file's last table), derived from a folder of its own.
drawn samples_with(const std::string& id, const std::string& file, const std::string& regimes)
{
    namespace fs = std::filesystem;
    const fs::path folder = fs::temp_directory_path() / ("impact-test-sampling-" + std::to_string(::getpid()));
    fs::remove_all(folder);
    fs::create_directories(folder);
    {
        std::ifstream in(std::string(IMPACT_SOURCE_DIR "/derivations/") + file);
        std::ofstream out(folder / file);
        out << in.rdbuf() << "\n" << regimes;
    }
    engine::library lib = engine::derive_all(engine::read_directory(folder), id);
    fs::remove_all(folder);
    engine::term_order order = engine::declaration_order(lib.derived.at(id).symbols);
    drawn d{std::move(lib), std::move(order), nullptr, {}};
    d.kernel = &d.lib.derived.at(id).kernels.front();
    d.samples = verify::draw_samples(*d.kernel, 4200, 12345, d.order);
    return d;
}

// The 2D rough kernel's inputs, in its order: M, m, R_M, R_m, q_M, q_m, C_M, C_m, v_M, v_m,
// w_M, w_m, eps, beta, mu.
struct rough_pair {
    long double M, m, R_M, R_m, q_M, q_m, C_Mx, C_My, C_mx, C_my, v_Mx, v_My, v_mx, v_my, w_M, w_m, eps, beta, mu;

    explicit rough_pair(const std::vector<double>& x)
        : M(x[0]), m(x[1]), R_M(x[2]), R_m(x[3]), q_M(x[4]), q_m(x[5]), C_Mx(x[6]), C_My(x[7]), C_mx(x[8]),
          C_my(x[9]), v_Mx(x[10]), v_My(x[11]), v_mx(x[12]), v_my(x[13]), w_M(x[14]), w_m(x[15]), eps(x[16]),
          beta(x[17]), mu(x[18])
    {
    }
    long double d() const { return std::hypot(C_mx - C_Mx, C_my - C_My); }
    long double n_x() const { return (C_mx - C_Mx) / d(); }
    long double n_y() const { return (C_my - C_My) / d(); }
    // g = v_M - v_m + (R_M w_M + R_m w_m) z x n; g_n = g.n, g_t = g.t with t = z x n.
    long double g_n() const { return (v_Mx - v_mx) * n_x() + (v_My - v_my) * n_y(); }
    long double g_t() const { return -(v_Mx - v_mx) * n_y() + (v_My - v_my) * n_x() + R_M * w_M + R_m * w_m; }
    // The centres' relative velocity across the line of centres.
    long double across() const { return -(v_Mx - v_mx) * n_y() + (v_My - v_my) * n_x(); }
    long double m_t() const { return 1 / (1 / M + 1 / m + 1 / (q_M * M) + 1 / (q_m * m)); }
    long double J_n() const { return (1 + eps) * M * m / (M + m) * g_n(); }
};

} // namespace

BOOST_AUTO_TEST_CASE(the_rough_kernel_s_regimes_are_listed_in_turn)
{
    const drawn& d = samples_of("rough_plane");
    const std::vector<std::string> expected = {
        "ordinary", "M, m, R_M, R_m, mu over 12 decades", "q_M near 0", "q_M near 2/3", "q_m near 0", "q_m near 2/3",
        "eps near 0", "eps near 1", "beta near -1", "beta near 1", "nearly grazing", "nearly head-on",
        "nearly equal velocities", "|g_t|/g_n from 1e-8 to 1e8", "nearly central, large spin",
        "at the sticking boundary"};
    BOOST_TEST(verify::regime_names(*d.kernel, d.order) == expected, boost::test_tools::per_element());
    BOOST_REQUIRE_EQUAL(d.samples.size(), 4200u);
    for (std::size_t i = 0; i < d.samples.size(); ++i)
        BOOST_TEST(d.samples[i].regime == expected[i % expected.size()]);
}

BOOST_AUTO_TEST_CASE(the_slip_spans_sixteen_decades_of_the_normal_speed)
{
    const drawn& d = samples_of("rough_plane");
    long double smallest = 1e300L, largest = 0;
    const auto in = d.in("|g_t|/g_n from 1e-8 to 1e8");
    BOOST_REQUIRE(in.size() > 200u);
    for (const verify::sample* s : in) {
        const rough_pair p(s->inputs);
        BOOST_TEST(p.g_n() > 0);   // approaching
        const long double ratio = std::fabs(p.g_t() / p.g_n());
        BOOST_TEST(ratio >= 1e-8L * (1 - 1e-4L));
        BOOST_TEST(ratio <= 1e8L * (1 + 1e-4L));
        smallest = std::min(smallest, ratio);
        largest = std::max(largest, ratio);
    }
    BOOST_TEST(smallest < 1e-6L);
    BOOST_TEST(largest > 1e6L);
}

BOOST_AUTO_TEST_CASE(a_vector_input_sets_a_vector_quantity_s_length)
{
    // The 3D rough wall: its spin vector w sets the contact point's slip g_t, a vector in
    // the wall's plane, to 1e-8 .. 1e8 of the normal speed g_n, along a direction drawn
    // at random; the quantity is written as its components, G_t = d^2 g_t (d = |N|).
    const drawn d = samples_with("rough_wall_space", "rough_wall_space.toml",
                                 "[[kernel.regime]]\nname = \"slip\"\nset = \"w\"\n"
                                 "ratio = [\"[G_tx, G_ty, G_tz]\", \"s_n*n_norm\"]\nfrom = 1e-8\nto = 1e8\n");
    // Inputs R, q, P, n, C, v, w, eps, beta, mu. The contact point, -R n from the centre
    // (n = N/|N|, out of the wall), moves at g = v + w x (-R n); g_n = -g.n (> 0 when
    // approaching), g_t = g + g_n n.
    struct parts {
        long double g_n, g_t[3];
    };
    auto slip = [](const verify::sample& s) {
        const std::vector<double>& x = s.inputs;
        const long double R = x[0], N[3] = {x[5], x[6], x[7]}, v[3] = {x[11], x[12], x[13]},
                          w[3] = {x[14], x[15], x[16]};
        const long double d = std::sqrt(N[0] * N[0] + N[1] * N[1] + N[2] * N[2]);
        const long double n[3] = {N[0] / d, N[1] / d, N[2] / d};
        const long double g[3] = {v[0] - R * (w[1] * n[2] - w[2] * n[1]), v[1] - R * (w[2] * n[0] - w[0] * n[2]),
                                  v[2] - R * (w[0] * n[1] - w[1] * n[0])};
        parts p;
        p.g_n = -(g[0] * n[0] + g[1] * n[1] + g[2] * n[2]);
        for (int i = 0; i < 3; ++i)
            p.g_t[i] = g[i] + p.g_n * n[i];
        return p;
    };
    const auto in = d.in("slip");
    BOOST_REQUIRE(in.size() > 200u);
    long double smallest = 1e300L, largest = 0;
    int z_positive = 0;
    for (const verify::sample* s : in) {
        const parts p = slip(*s);   // approaching or not (drawn without the guards' admission)
        const long double ratio = std::hypot(p.g_t[0], p.g_t[1], p.g_t[2]) / std::fabs(p.g_n);
        BOOST_TEST(ratio >= 1e-8L * (1 - 1e-3L));
        BOOST_TEST(ratio <= 1e8L * (1 + 1e-3L));
        smallest = std::min(smallest, ratio);
        largest = std::max(largest, ratio);
        z_positive += p.g_t[2] > 0;
    }
    BOOST_TEST(smallest < 1e-6L);
    BOOST_TEST(largest > 1e6L);
    // The direction is drawn, not fixed: either sign of a component, about as often.
    BOOST_TEST(z_positive > static_cast<int>(in.size()) / 4);
    BOOST_TEST(z_positive < 3 * static_cast<int>(in.size()) / 4);
    // The spin is changed as little as it can be: its part along n, which leaves g_t as it
    // is, stays as drawn (a spin across n alone, the smallest that gives g_t, would have
    // none).
    int along_n = 0;
    for (const verify::sample* s : in) {
        const std::vector<double>& x = s->inputs;
        const long double N[3] = {x[5], x[6], x[7]}, w[3] = {x[14], x[15], x[16]};
        const long double along = (w[0] * N[0] + w[1] * N[1] + w[2] * N[2]) / std::hypot(N[0], N[1], N[2]);
        along_n += std::fabs(along) > 1e-3L * std::hypot(w[0], w[1], w[2]);
    }
    BOOST_TEST(along_n > static_cast<int>(in.size()) / 2);
    BOOST_TEST(verify::regime_names(*d.kernel, d.order).back() == "slip");
}

BOOST_AUTO_TEST_CASE(a_nearly_central_hit_with_large_spin)
{
    const drawn& d = samples_of("rough_plane");
    const auto in = d.in("nearly central, large spin");
    BOOST_REQUIRE(in.size() > 200u);
    // The centres' relative velocity across the line of centres was scaled by 1e-12 to 1e-3
    // (on most samples then within 1e-3 of the part along it; in an ordinary draw, seldom).
    std::size_t central = 0;
    for (const verify::sample* s : in) {
        const rough_pair p(s->inputs);
        central += std::fabs(p.across()) <= 1e-3L * std::fabs(p.g_n());
        const long double ratio = std::fabs(p.g_t() / p.g_n());
        BOOST_TEST(ratio >= 1e2L * (1 - 1e-6L));
        BOOST_TEST(ratio <= 1e8L * (1 + 1e-6L));
        // The slip is the spins': the rims turn at nearly g_t.
        BOOST_TEST(std::fabs(p.R_M * p.w_M + p.R_m * p.w_m) >= 0.99L * std::fabs(p.g_t()));
    }
    BOOST_TEST(central >= in.size() * 9 / 10);
    std::size_t ordinary_central = 0;
    for (const verify::sample* s : d.in("ordinary")) {
        const rough_pair p(s->inputs);
        ordinary_central += std::fabs(p.across()) <= 1e-3L * std::fabs(p.g_n());
    }
    BOOST_TEST(ordinary_central < in.size() / 10);
}

BOOST_AUTO_TEST_CASE(the_sticking_boundary_within_a_relative_1e_12)
{
    // Walton's model sticks while (1 + beta) m_t |g_t| <= mu J_n: mu J_n within a relative
    // 1e-12 of the impulse that makes the contact stick, on either side.
    const drawn& d = samples_of("rough_plane");
    const auto in = d.in("at the sticking boundary");
    BOOST_REQUIRE(in.size() > 200u);
    std::size_t sticking = 0, sliding = 0;
    for (const verify::sample* s : in) {
        const rough_pair p(s->inputs);
        const long double stick = (1 + p.beta) * p.m_t() * std::fabs(p.g_t());
        const long double gap = p.mu * p.J_n() / stick - 1;
        BOOST_TEST(std::fabs(gap) <= 1.01e-12L, "mu J_n / J_stick - 1 = " << static_cast<double>(gap));
        sticking += gap > 0;
        sliding += gap < 0;
    }
    BOOST_TEST(sticking > 50u);
    BOOST_TEST(sliding > 50u);
}

BOOST_AUTO_TEST_CASE(an_interval_input_near_each_end_one_at_a_time)
{
    const drawn& d = samples_of("rough_plane");
    long double closest = 1;
    for (const verify::sample* s : d.in("beta near -1")) {
        const rough_pair p(s->inputs);
        BOOST_TEST(p.beta + 1 > 0);
        BOOST_TEST(p.beta + 1 <= 0.2L);   // within a tenth of the width, 2
        closest = std::min(closest, p.beta + 1);
    }
    BOOST_TEST(closest < 1e-9L);
    for (const verify::sample* s : d.in("beta near 1"))
        BOOST_TEST(1 - rough_pair(s->inputs).beta <= 0.2L);
    for (const verify::sample* s : d.in("q_M near 0")) {
        const rough_pair p(s->inputs);
        BOOST_TEST(p.q_M > 0);
        BOOST_TEST(p.q_M <= 2.0L / 30);
    }
    // In eps's regime, beta is drawn over all of [-1, 1].
    long double lowest = 1, highest = -1;
    for (const verify::sample* s : d.in("eps near 1")) {
        const rough_pair p(s->inputs);
        BOOST_TEST(1 - p.eps <= 0.1L);
        lowest = std::min(lowest, p.beta);
        highest = std::max(highest, p.beta);
    }
    BOOST_TEST(lowest < -0.8L);
    BOOST_TEST(highest > 0.8L);
}

BOOST_AUTO_TEST_CASE(a_wall_s_grazing_and_head_on_hits_are_along_its_normal)
{
    // The smooth wall in the plane: inputs P, n, C, v, eps. Its line of approach is the
    // normal N (the guard v.N < 0), not two centres.
    const drawn& d = samples_of("wall_plane");
    const std::vector<std::string> expected = {"ordinary", "eps near 0", "eps near 1", "nearly grazing",
                                               "nearly head-on"};
    BOOST_TEST(verify::regime_names(*d.kernel, d.order) == expected, boost::test_tools::per_element());
    auto parts = [](const verify::sample& s) {
        const long double N_x = s.inputs[2], N_y = s.inputs[3], v_x = s.inputs[6], v_y = s.inputs[7];
        const long double n = std::hypot(N_x, N_y);
        return std::pair<long double, long double>{(v_x * N_x + v_y * N_y) / n, (-v_x * N_y + v_y * N_x) / n};
    };
    const auto grazing = d.in("nearly grazing");
    const auto head_on = d.in("nearly head-on");
    BOOST_REQUIRE(grazing.size() > 500u);
    BOOST_REQUIRE(head_on.size() > 500u);
    // One part scaled by 1e-12 to 1e-3, the other kept: on most samples the one within 1e-3
    // of the other (in an ordinary draw, seldom).
    auto share = [&](const std::vector<const verify::sample*>& in, bool grazing_hit) {
        std::size_t n = 0;
        for (const verify::sample* s : in) {
            const auto [along, across] = parts(*s);
            n += grazing_hit ? std::fabs(along) <= 1e-3L * std::fabs(across)
                             : std::fabs(across) <= 1e-3L * std::fabs(along);
        }
        return static_cast<double>(n) / static_cast<double>(in.size());
    };
    BOOST_TEST(share(grazing, true) >= 0.9);
    BOOST_TEST(share(head_on, false) >= 0.9);
    BOOST_TEST(share(d.in("ordinary"), true) < 0.05);
    BOOST_TEST(share(d.in("ordinary"), false) < 0.05);
}

BOOST_AUTO_TEST_CASE(kernels_without_a_line_of_approach_get_no_grazing_regime)
{
    // collide_line: every hit is head-on. scatter_angle: no bodies, a velocity's parts.
    const drawn& line = samples_of("inelastic_line");
    BOOST_TEST(verify::regime_names(*line.kernel, line.order) ==
                   (std::vector<std::string>{"ordinary", "M, m over 12 decades", "eps near 0", "eps near 1",
                                             "nearly equal velocities"}),
               boost::test_tools::per_element());
    const drawn& scatter = samples_of("scatter_angle");
    BOOST_TEST(verify::regime_names(*scatter.kernel, scatter.order) ==
                   (std::vector<std::string>{"ordinary", "v_par, v_perp over 12 decades", "eps near 0", "eps near 1",
                                             "one of v_par, v_perp 1e-12 to 1e-4 of its draw"}),
               boost::test_tools::per_element());
    // Each drawn over 1e-2 .. 1e2, one then scaled by 1e-12 .. 1e-4: on most samples under
    // 1e-4 of the other (in an ordinary draw, never: two draws are at most 1e4 apart).
    auto share_tiny = [&](const std::string& regime) {
        std::size_t n = 0;
        const auto in = scatter.in(regime);
        for (const verify::sample* s : in)
            n += std::min(s->inputs[0], s->inputs[1]) < 1e-4 * std::max(s->inputs[0], s->inputs[1]);
        return static_cast<double>(n) / static_cast<double>(in.size());
    };
    BOOST_TEST(share_tiny("one of v_par, v_perp 1e-12 to 1e-4 of its draw") >= 0.8);
    BOOST_TEST(share_tiny("ordinary") == 0.0);
}

BOOST_AUTO_TEST_CASE(a_fixed_sphere_s_kernel_keeps_the_file_s_regimes_in_the_limit)
{
    // collide_rough with M = +infinity: inputs m, R_M, R_m, q_M, q_m, C_M, C_m, v_M, v_m, w_M,
    // w_m, eps, beta, mu. As M grows, m_r -> m and 1/m_t -> 1/m + 1/(q_m m): the sticking
    // boundary is (1 + beta) q_m m |g_t| / (1 + q_m) = mu (1 + eps) m g_n.
    const drawn& d = samples_of("rough_plane");
    const engine::kernel& fixed = d.kernel->limits.front();
    BOOST_REQUIRE_EQUAL(fixed.fixed_mass, "M");
    const std::vector<verify::sample> samples = verify::draw_samples(fixed, 4200, 777, d.order);
    std::size_t boundary = 0, ratio = 0;
    for (const verify::sample& s : samples) {
        std::vector<double> x = s.inputs;
        x.insert(x.begin(), 1.0);   // M's slot, unused below
        const rough_pair p(x);
        if (s.regime == "at the sticking boundary") {
            const long double stick = (1 + p.beta) * p.q_m * p.m / (1 + p.q_m) * std::fabs(p.g_t());
            const long double gap = p.mu * (1 + p.eps) * p.m * p.g_n() / stick - 1;
            BOOST_TEST(std::fabs(gap) <= 1.01e-12L, "mu J_n / J_stick - 1 = " << static_cast<double>(gap));
            ++boundary;
        }
        if (s.regime == "|g_t|/g_n from 1e-8 to 1e8") {
            const long double r = std::fabs(p.g_t() / p.g_n());
            BOOST_TEST(r >= 1e-8L * (1 - 1e-4L));
            BOOST_TEST(r <= 1e8L * (1 + 1e-4L));
            ++ratio;
        }
    }
    BOOST_TEST(boundary > 200u);
    BOOST_TEST(ratio > 200u);
}
