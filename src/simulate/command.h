// `impact simulate`: a scenario from a file and/or options (src/cli/main.cpp runs it and writes it out).
#pragma once

#include "simulate/scenario.h"

#include <optional>
#include <string>

namespace impact::simulate {

/// What the command line gives; options override the scenario file's values, and
/// without a file the defaults are Fig. 2's billiard shot (eps = 1).
struct command_options {
    std::string file;                        ///< a scenario file, optional
    std::string output = "simulations";      ///< folder for <name>.dat and <name>.tex
    bool force = false;                      ///< write into a folder Impact does not own
    std::optional<std::string> name;
    std::optional<double> eps, duration;
    std::optional<double> mass_M, mass_m, radius_M, radius_m;
    std::optional<std::string> position_M, position_m, velocity_M, velocity_m;  ///< "x,y"
    std::optional<double> spin_M, spin_m, q_M, q_m;   ///< spins, moments of inertia over mass radius^2
    std::optional<double> beta, mu;                    ///< rough spheres: beta given
};

/// The scenario the options describe. Throws `impact::error` on bad input.
scenario scenario_from(const command_options& o);

} // namespace impact::simulate
