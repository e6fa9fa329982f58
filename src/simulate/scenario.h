// A collision scenario: two spheres in a plane, smooth (the paper's) or rough (they grip
// each other, spin and slide: Walton's model), and how long to watch them.
//
// Read from a small TOML file (`tests/scenarios/*.toml`) or built from command-line options.
// This is plain data; `simulate` moves the spheres.
//
//     name = "off_centre"
//     eps = 0.5             # Newton's coefficient of restitution, in [0, 1]
//     duration = 6          # optional: time simulated (default: twice the time to contact)
//     beta = 0.5            # optional: rough spheres, the tangential restitution in [-1, 1]
//     mu = 0.2              # optional with beta: Coulomb's friction coefficient (default inf)
//     [M]
//     mass = 1.0
//     radius = 0.5
//     position = [0.0, 0.0]
//     velocity = [0.0, 0.0]
//     spin = 3.0            # optional: angular velocity, counter-clockwise (default 0)
//     q = 0.4               # optional: moment of inertia over mass radius^2 (default 2/5)
//     [m]
//     ...
#pragma once

#include "spec/error.h"

#include <array>
#include <optional>
#include <string>

namespace impact::simulate {

using vec2 = std::array<double, 2>;

struct sphere {
    double mass = 1;
    double radius = 0.5;
    vec2 position{0, 0};
    vec2 velocity{0, 0};
    double spin = 0;       ///< angular velocity about the axis out of the plane (counter-clockwise > 0)
    double q = 0.4;        ///< moment of inertia in units of mass radius^2 (2/5: a solid sphere)
};

struct scenario {
    std::string name = "scenario";
    sphere M;                          ///< the paper's sphere M
    sphere m;                          ///< the paper's sphere m
    double eps = 1;                    ///< Newton's coefficient of restitution
    /// Rough spheres when given: the tangential restitution (-1: smooth, 1: perfectly rough).
    std::optional<double> beta;
    /// Coulomb's coefficient of friction of rough spheres (+infinity: the contact never slides).
    std::optional<double> mu;
    std::optional<double> duration;    ///< time simulated; by default twice the time to contact
    int samples = 101;                 ///< points of each trajectory (the contact is added)
    source_location where;             ///< the file it was read from, for messages
};

/// What a scenario's numbers may be. The simulation is in double precision and in any
/// consistent units; these bounds keep every square and product of two numbers finite
/// and normal, and the contact resolved to a small part of a radius.
namespace limits {
constexpr double largest = 1e100;      ///< the magnitude of any number
constexpr double smallest = 1e-100;    ///< the magnitude of a number that is not zero
/// How far apart the spheres may start, and how far one may travel, in units of the
/// smaller radius: double precision then places the contact within 1e-6 of a radius.
constexpr double span_in_radii = 1e10;
constexpr int fewest_samples = 2;
/// Points per trajectory: the table is a line per point, and pgfplots reads it into
/// pdflatex's memory, which a figure of more points than this exhausts.
constexpr int most_samples = 10000;
} // namespace limits

/// What a number of a scenario stands for, and so the values it may take.
enum class number_kind {
    positive,      ///< a mass, a radius, a duration
    coordinate,    ///< a position or velocity component: any sign, or zero
    restitution,   ///< Newton's coefficient of restitution, in [0, 1]
    tangential,    ///< the tangential restitution beta, in [-1, 1]
    friction,      ///< Coulomb's coefficient mu, in [0, +infinity]
    inertia,       ///< q, a moment of inertia over mass radius^2, in (0, 2/3]
};

/// Checks one number where it was given (`what` names it: "the mass of M", "--eps").
/// Throws `impact::error` at `where` saying the limit and what to do instead.
void check_number(double value, number_kind kind, const source_location& where, const std::string& what);

/// The message for a friction `mu` given without `beta` (named as given: "beta", "--beta").
std::string mu_needs_beta(const std::string& beta);

/// The number of samples, a whole number in [fewest_samples, most_samples].
int checked_samples(double value, const source_location& where);

/// Whether the spheres are rough (`beta` given): then `collide_rough` resolves the contact.
inline bool rough(const scenario& s)
{
    return s.beta.has_value();
}

/// Whether a sphere spins, before or (rough) after the contact: then the trajectories
/// carry the angle each sphere has turned.
inline bool spinning(const scenario& s)
{
    return rough(s) || s.M.spin != 0 || s.m.spin != 0;
}

/// Reads a scenario file. Throws `impact::error` (file:line:column) on bad input.
scenario read_scenario(const std::string& path);

/// Reads a scenario from TOML text; `file` names it in messages.
scenario parse_scenario(const std::string& text, const std::string& file);

/// Checks what the physics needs: every number as check_number says, spheres not
/// overlapping at the start, nor so far apart (or travelling so far) that double precision
/// cannot place their contact. Throws `impact::error`.
void validate(const scenario& s);

} // namespace impact::simulate
