#include "simulate/simulate.h"

// The generated kernels (build/generated/kernels, the same text as output/kernels/):
// the simulation runs the code the accuracy tests verify.
#include "impact/impact.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <tuple>

namespace impact::simulate {
namespace {

vec2 at_time(const sphere& s, double t)
{
    return {s.position[0] + s.velocity[0] * t, s.position[1] + s.velocity[1] * t};
}

vec2 moved(const vec2& from, const vec2& velocity, double t)
{
    return {from[0] + velocity[0] * t, from[1] + velocity[1] * t};
}

} // namespace

std::string fixed(double value, int digits)
{
    // A scene in units where its numbers are very large or very small keeps its
    // significant digits in scientific notation (which pgfplots reads too).
    if (std::fabs(value) >= 1e6)
        return fmt::format("{:.{}e}", value, digits);
    std::string text = fmt::format("{:.{}f}", value, digits);
    // -0.0000 and 0.0000 are the same number; write it one way.
    if (text.find_first_not_of("-0.") == std::string::npos && text[0] == '-')
        text.erase(0, 1);
    return text;
}

std::optional<double> time_of_contact(const scenario& s)
{
    // |d + w t|^2 = (R_M + R_m)^2 with d = C_M - C_m, w = v_M - v_m:
    // a t^2 + b t + c = 0, a = |w|^2, b = 2 d·w, c = |d|^2 - (R_M + R_m)^2 (c >= 0: apart).
    const double dx = s.M.position[0] - s.m.position[0], dy = s.M.position[1] - s.m.position[1];
    const double wx = s.M.velocity[0] - s.m.velocity[0], wy = s.M.velocity[1] - s.m.velocity[1];
    const double reach = s.M.radius + s.m.radius;
    const double a = wx * wx + wy * wy;
    const double b = 2 * (dx * wx + dy * wy);
    const double c = (dx * dx + dy * dy) - reach * reach;
    if (c <= 0)
        return 0.0;
    if (a == 0 || b >= 0)
        return std::nullopt;   // not approaching
    const double discriminant = b * b - 4 * a * c;
    if (discriminant < 0)
        return std::nullopt;   // they pass each other by
    // The smaller root, written without cancellation: q = (-b + sqrt(D))/2 > 0, t = c/q.
    const double q = (-b + std::sqrt(discriminant)) / 2;
    return c / q;
}

contact resolve(const scenario& s, const vec2& C_M, const vec2& C_m, const vec2& v_M, const vec2& v_m)
{
    contact hit;
    hit.C_M = C_M;
    hit.C_m = C_m;
    hit.v_M_before = v_M;
    hit.v_m_before = v_m;
    hit.w_M_before = hit.w_M_after = s.M.spin;
    hit.w_m_before = hit.w_m_after = s.m.spin;
    if (rough(s)) {
        // Walton's model in the lab frame: the generated kernel gives the velocities and
        // spins after, sticking or sliding.
        const double mu = s.mu ? *s.mu : std::numeric_limits<double>::infinity();
        const auto out = impact::collide_rough<double>(s.M.mass, s.m.mass, s.M.radius, s.m.radius, s.M.q, s.m.q, C_M,
                                                       C_m, v_M, v_m, s.M.spin, s.m.spin, s.eps, *s.beta, mu);
        if (out.status != impact::status::ok)
            throw std::logic_error("the generated kernel refused a collision of touching, approaching spheres");
        hit.v_M_after = out.v_M;
        hit.v_m_after = out.v_m;
        hit.w_M_after = out.w_M;
        hit.w_m_after = out.w_m;
    } else {
        // Eq. 9 in the lab frame: the generated kernel turns the velocities into the collision
        // frame, applies Eq. 8 along the line of action, keeps the perpendicular components
        // and turns them back. Smooth spheres exert no torque: the spins are kept.
        const auto out = impact::collide<double>(s.M.mass, s.m.mass, C_M, C_m, v_M, v_m, s.eps);
        if (out.status != impact::status::ok)
            throw std::logic_error("the generated kernel refused a collision of touching, approaching spheres");
        hit.v_M_after = out.v_M;
        hit.v_m_after = out.v_m;
    }
    // The impulses from the lighter sphere's changes, which lose fewer digits to rounding
    // (a heavy sphere's velocity and spin barely change). Along the line of action, from a
    // change of momentum (Eq. 6), v'_M = v_M - J/M, v'_m = v_m + J/m along r = C_M - C_m:
    const double rx = C_M[0] - C_m[0], ry = C_M[1] - C_m[1];
    const double r = std::hypot(rx, ry);
    const bool M_lighter = s.M.mass <= s.m.mass;
    hit.J = M_lighter ? s.M.mass * ((v_M[0] - hit.v_M_after[0]) * rx + (v_M[1] - hit.v_M_after[1]) * ry) / r
                      : s.m.mass * ((hit.v_m_after[0] - v_m[0]) * rx + (hit.v_m_after[1] - v_m[1]) * ry) / r;
    if (rough(s)) {
        // Across it, from the change of spin of the sphere with the least q mass R (whose spin
        // changes most): w' = w - (R/I) n x J_t with I = q mass R^2 for both spheres, and
        // n x J_t = J_t for J_t along z x n.
        const double inertia_M = s.M.q * s.M.mass * s.M.radius, inertia_m = s.m.q * s.m.mass * s.m.radius;
        hit.J_t = inertia_M <= inertia_m ? (hit.w_M_before - hit.w_M_after) * inertia_M
                                         : (hit.w_m_before - hit.w_m_after) * inertia_m;
        // Friction capped it when |J_t| is mu |J| (to rounding).
        hit.slid = s.mu && std::fabs(hit.J_t) >= *s.mu * std::fabs(hit.J) * (1 - 1e-9);
    }
    return hit;
}

trajectory run(const scenario& s)
{
    validate(s);
    trajectory path;
    const std::optional<double> touch = time_of_contact(s);
    path.duration = s.duration ? *s.duration : (touch && *touch > 0 ? 2 * *touch : 10.0);
    if (touch && *touch <= path.duration) {
        contact hit = resolve(s, at_time(s.M, *touch), at_time(s.m, *touch), s.M.velocity, s.m.velocity);
        hit.t = *touch;
        path.hit = hit;
    } else if (touch) {
        path.later_contact = touch;
    }

    // Each sphere turns at its spin until the contact, and at its new spin after it.
    auto positions = [&](double t) -> sample {
        if (!path.hit || t <= path.hit->t)
            return {t, at_time(s.M, t), at_time(s.m, t), s.M.spin * t, s.m.spin * t};
        const contact& c = *path.hit;
        const double after = t - c.t;
        return {t,
                moved(c.C_M, c.v_M_after, after),
                moved(c.C_m, c.v_m_after, after),
                c.w_M_before * c.t + c.w_M_after * after,
                c.w_m_before * c.t + c.w_m_after * after};
    };
    for (int i = 0; i < s.samples; ++i) {
        const double t = path.duration * i / (s.samples - 1);
        if (path.hit && path.samples.size() > 0 && path.samples.back().t < path.hit->t && t > path.hit->t)
            path.samples.push_back(positions(path.hit->t));
        path.samples.push_back(positions(t));
    }
    return path;
}

namespace {

// Decimals that keep a scene's smallest radius and mass to four significant digits or
// better: 4 for the paper's billiard balls (radius 0.5, mass 1), more for a scene in
// units where they are small.
int decimals(const scenario& s)
{
    const double smallest = std::min({s.M.radius, s.m.radius, s.M.mass, s.m.mass});
    return 4 + std::max(0, static_cast<int>(std::ceil(-std::log10(smallest))) - 1);
}

} // namespace

std::string table(const scenario& s, const trajectory& path)
{
    const int digits = decimals(s);
    auto fixed = [digits](double x) { return simulate::fixed(x, digits); };
    std::string out = fmt::format("# Trajectories of scenario '{}': centres of M and m; eps = {}.\n", s.name,
                                  fixed(s.eps));
    const bool turning = spinning(s);
    out += turning ? "t x_M y_M x_m y_m a_M a_m\n" : "t x_M y_M x_m y_m\n";
    for (const sample& p : path.samples) {
        out += fmt::format("{} {} {} {} {}", fixed(p.t), fixed(p.C_M[0]), fixed(p.C_M[1]), fixed(p.C_m[0]),
                           fixed(p.C_m[1]));
        out += turning ? fmt::format(" {} {}\n", fixed(p.a_M), fixed(p.a_m)) : "\n";
    }
    return out;
}

namespace {

std::string circle(const vec2& centre, double radius, const std::string& style, int digits)
{
    auto fixed = [digits](double x) { return simulate::fixed(x, digits); };
    return fmt::format("  \\addplot[{}, domain=0:360, samples=73, variable=\\t] ({{{} + {}*cos(\\t)}}, "
                       "{{{} + {}*sin(\\t)}});\n",
                       style, fixed(centre[0]), fixed(radius), fixed(centre[1]), fixed(radius));
}

} // namespace

std::string figure(const scenario& s, const trajectory& path, const std::string& data)
{
    std::string out = fmt::format("% Generated by Impact (impact simulate) for scenario '{}'; do not edit.\n"
                                  "% Needs \\usepackage{{pgfplots}}.\n",
                                  s.name);
    out += "\\begin{tikzpicture}\n\\begin{axis}[axis equal image, width=0.8\\linewidth, xlabel={$x$}, "
           "ylabel={$y$}, legend pos=outer north east, legend cell align=left]\n";
    out += fmt::format("  \\addplot[blue!70!black, thick, -stealth] table[x=x_M, y=y_M] {{{}}};\n", data);
    out += "  \\addlegendentry{$M$}\n";
    out += fmt::format("  \\addplot[red!70!black, thick, -stealth] table[x=x_m, y=y_m] {{{}}};\n", data);
    out += "  \\addlegendentry{$m$}\n";
    if (spinning(s)) {
        // A point fixed on each sphere's rim, every tenth sample: it turns with the sphere.
        for (const auto& [x, y, a, radius, colour] :
             {std::tuple<const char*, const char*, const char*, double, const char*>{"x_M", "y_M", "a_M", s.M.radius,
                                                                                     "blue!70!black"},
              {"x_m", "y_m", "a_m", s.m.radius, "red!70!black"}})
            out += fmt::format("  \\addplot[{}, only marks, mark=*, mark size=1pt, each nth point=10, forget plot] "
                               "table[x expr={{\\thisrow{{{}}} + {}*cos(deg(\\thisrow{{{}}}))}}, "
                               "y expr={{\\thisrow{{{}}} + {}*sin(deg(\\thisrow{{{}}}))}}] {{{}}};\n",
                               colour, x, fixed(radius, decimals(s)), a, y, fixed(radius, decimals(s)), a, data);
    }
    out += circle(s.M.position, s.M.radius, "blue!70!black, densely dotted, forget plot", decimals(s));
    out += circle(s.m.position, s.m.radius, "red!70!black, densely dotted, forget plot", decimals(s));
    if (path.hit) {
        out += circle(path.hit->C_M, s.M.radius, "blue!70!black, forget plot", decimals(s));
        out += circle(path.hit->C_m, s.m.radius, "red!70!black, forget plot", decimals(s));
    }
    out += "\\end{axis}\n\\end{tikzpicture}\n";
    return out;
}

std::string summary(const scenario& s, const trajectory& path)
{
    const int digits = decimals(s);
    auto fixed = [digits](double x) { return simulate::fixed(x, digits); };
    auto v = [&](const vec2& x) { return fmt::format("({}, {})", fixed(x[0]), fixed(x[1])); };
    std::string out = fmt::format("scenario {}: M = {}, m = {}, eps = {}", s.name, fixed(s.M.mass), fixed(s.m.mass),
                                  fixed(s.eps));
    if (rough(s))
        out += fmt::format(", rough: beta = {}, mu = {}", fixed(*s.beta),
                           s.mu && std::isfinite(*s.mu) ? fixed(*s.mu) : std::string("inf"));
    out += fmt::format(", simulated for t in [0, {}]\n", fixed(path.duration));
    if (!path.hit) {
        if (path.later_contact)
            out += fmt::format("the spheres do not touch before t = {} (they would at t = {})\n",
                               fixed(path.duration), fixed(*path.later_contact));
        else
            out += "the spheres never touch\n";
        return out;
    }
    const contact& c = *path.hit;
    out += fmt::format("contact at t = {}: C_M = {}, C_m = {}\n", fixed(c.t), v(c.C_M), v(c.C_m));
    out += fmt::format("  v_M {} -> {}\n  v_m {} -> {}\n", v(c.v_M_before), v(c.v_M_after), v(c.v_m_before),
                       v(c.v_m_after));
    if (spinning(s))
        out += fmt::format("  w_M {} -> {}\n  w_m {} -> {}\n", fixed(c.w_M_before), fixed(c.w_M_after),
                           fixed(c.w_m_before), fixed(c.w_m_after));
    out += fmt::format("  impulse along the line of action J = {}\n", fixed(c.J));
    if (rough(s))
        out += fmt::format("  impulse across it (on m, along z x n) J_t = {}, {}\n", fixed(c.J_t),
                           c.slid ? "the contact slid (|J_t| = mu |J|)" : "the contact stuck");
    return out;
}

} // namespace impact::simulate
