// A collision scenario: two smooth spheres in a plane, and how long to watch them.
//
// Read from a small TOML file (`tests/scenarios/*.toml`) or built from command-line options.
// This is plain data; `simulate` moves the spheres.
//
//     name = "off_centre"
//     eps = 0.5             # Newton's coefficient of restitution, in [0, 1]
//     duration = 6          # optional: time simulated (default: twice the time to contact)
//     [M]
//     mass = 1.0
//     radius = 0.5
//     position = [0.0, 0.0]
//     velocity = [0.0, 0.0]
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
};

struct scenario {
    std::string name = "scenario";
    sphere M;                          ///< the paper's sphere M
    sphere m;                          ///< the paper's sphere m
    double eps = 1;                    ///< Newton's coefficient of restitution
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
};

/// Checks one number where it was given (`what` names it: "the mass of M", "--eps").
/// Throws `impact::error` at `where` saying the limit and what to do instead.
void check_number(double value, number_kind kind, const source_location& where, const std::string& what);

/// The number of samples, a whole number in [fewest_samples, most_samples].
int checked_samples(double value, const source_location& where);

/// Reads a scenario file. Throws `impact::error` (file:line:column) on bad input.
scenario read_scenario(const std::string& path);

/// Reads a scenario from TOML text; `file` names it in messages.
scenario parse_scenario(const std::string& text, const std::string& file);

/// Checks what the physics needs: every number as check_number says, spheres not
/// overlapping at the start, nor so far apart (or travelling so far) that double precision
/// cannot place their contact. Throws `impact::error`.
void validate(const scenario& s);

} // namespace impact::simulate
