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

/// Reads a scenario file. Throws `impact::error` (file:line:column) on bad input.
scenario read_scenario(const std::string& path);

/// Reads a scenario from TOML text; `file` names it in messages.
scenario parse_scenario(const std::string& text, const std::string& file);

/// Checks what the physics needs: positive masses and radii, eps in [0, 1], finite
/// numbers, spheres not overlapping at the start, a positive duration. Throws `impact::error`.
void validate(const scenario& s);

} // namespace impact::simulate
