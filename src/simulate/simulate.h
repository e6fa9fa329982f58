// Two spheres moved until they touch, the collision resolved by the generated kernel, and
// their trajectories written as a table and a pgfplots figure.
//
// Between collisions the spheres move in straight lines (and spin at constant rates), so
// the time of contact is a root of |r_mM + Δv t| = R_M + R_m (r_mM = C_M - C_m,
// Δv = v_M - v_m), found in closed form; two freely moving spheres touch at most once. At
// contact the generated lab-frame kernel gives the velocities after the collision: for
// smooth spheres `impact::collide` (Eq. 9: the line of action's components change as
// Eq. 8 says, the perpendicular ones are kept, and so are the spins); for rough ones
// `impact::collide_rough` (Walton's model: the contact points stick, their tangential
// velocity reversed with restitution beta, unless Coulomb friction mu J_n caps the
// tangential impulse and they slide), which changes the spins too.
#pragma once

#include "simulate/scenario.h"

#include <optional>
#include <string>
#include <vector>

namespace impact::simulate {

/// The positions of both centres at one time.
struct sample {
    double t = 0;
    vec2 C_M{}, C_m{};
    double a_M = 0, a_m = 0;   ///< the angle each sphere has turned since t = 0 (radians)
};

/// The collision, as resolved.
struct contact {
    double t = 0;
    vec2 C_M{}, C_m{};                   ///< the centres at contact
    vec2 v_M_before{}, v_m_before{};
    vec2 v_M_after{}, v_m_after{};
    double w_M_before = 0, w_m_before = 0;   ///< the spins
    double w_M_after = 0, w_m_after = 0;
    double J = 0;                        ///< the impulse along the line of action (Eq. 8)
    /// Rough spheres: the impulse on m across the line of action, along z x n (n from M's
    /// centre to m's), and whether friction capped it (the contact slid).
    double J_t = 0;
    bool slid = false;
};

struct trajectory {
    double duration = 0;
    std::vector<sample> samples;         ///< in time order; the contact is one of them
    std::optional<contact> hit;          ///< nothing when the spheres never touch
    /// When they do not touch: whether they would, later than the simulated time.
    std::optional<double> later_contact;
};

/// The earliest time t >= 0 at which the spheres touch moving freely, if any.
std::optional<double> time_of_contact(const scenario& s);

/// The velocities (and spins) after the spheres collide at centres C_M, C_m (touching and
/// approaching), from the generated kernel `impact::collide` or, rough, `impact::collide_rough`.
contact resolve(const scenario& s, const vec2& C_M, const vec2& C_m, const vec2& v_M, const vec2& v_m);

/// Moves the spheres for the scenario's duration (by default twice the time to contact,
/// or 10 time units when they never touch).
trajectory run(const scenario& s);

/// The trajectories as a whitespace-separated table (t, x_M, y_M, x_m, y_m, and when a
/// sphere spins, a_M, a_m: the angles turned), fixed format, for pgfplots.
std::string table(const scenario& s, const trajectory& path);

/// A pgfplots figure of both paths to scale, the spheres drawn where they start (faint)
/// and at contact; when a sphere spins, a mark on each sphere's rim every tenth sample
/// (a point fixed on the sphere, at angle 0 at t = 0) shows it turning. `data` names the
/// table file as the figure's \input will see it.
std::string figure(const scenario& s, const trajectory& path, const std::string& data);

/// A few lines for the terminal: the contact (or that there is none) and the velocities.
std::string summary(const scenario& s, const trajectory& path);

/// A number as figure files write it: fixed, `digits` decimals, no negative zero.
std::string fixed(double value, int digits = 4);

} // namespace impact::simulate
