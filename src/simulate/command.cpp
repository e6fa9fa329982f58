#include "simulate/command.h"

#include "simulate/simulate.h"

#include <fmt/format.h>

#include <cctype>
#include <cmath>
#include <filesystem>

namespace impact::simulate {
namespace {

// "x,y" → {x, y}
vec2 parse_pair(const std::string& text, const std::string& option)
{
    const auto comma = text.find(',');
    try {
        if (comma == std::string::npos)
            throw std::invalid_argument("no comma");
        std::size_t used = 0;
        const std::string x = text.substr(0, comma), y = text.substr(comma + 1);
        const double a = std::stod(x, &used);
        if (x.find_first_not_of(" \t", used) != std::string::npos)
            throw std::invalid_argument("trailing text");
        const double b = std::stod(y, &used);
        if (y.find_first_not_of(" \t", used) != std::string::npos)
            throw std::invalid_argument("trailing text");
        return {a, b};
    } catch (const std::exception&) {
        throw error({"--" + option, 0, 0}, fmt::format("'{}' must be two numbers x,y", text));
    }
}

// Fig. 2's shot: the cue ball m, off-centre by one radius, towards M at rest.
scenario default_scenario()
{
    scenario s;
    s.name = "billiard";
    s.M = {1.0, 0.5, {0.0, 0.0}, {0.0, 0.0}};
    s.m = {1.0, 0.5, {-3.0, 0.5}, {1.0, 0.0}};
    s.eps = 1;
    s.where = {"the command line", 0, 0};
    return s;
}

} // namespace

scenario scenario_from(const command_options& o)
{
    scenario s = o.file.empty() ? default_scenario() : read_scenario(o.file);
    if (o.name)
        s.name = *o.name;
    if (o.eps)
        s.eps = *o.eps;
    if (o.duration)
        s.duration = *o.duration;
    if (o.mass_M)
        s.M.mass = *o.mass_M;
    if (o.mass_m)
        s.m.mass = *o.mass_m;
    if (o.radius_M)
        s.M.radius = *o.radius_M;
    if (o.radius_m)
        s.m.radius = *o.radius_m;
    if (o.position_M)
        s.M.position = parse_pair(*o.position_M, "position-M");
    if (o.position_m)
        s.m.position = parse_pair(*o.position_m, "position-m");
    if (o.velocity_M)
        s.M.velocity = parse_pair(*o.velocity_M, "velocity-M");
    if (o.velocity_m)
        s.m.velocity = parse_pair(*o.velocity_m, "velocity-m");
    // A name becomes a file name.
    for (char c : s.name)
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-'))
            throw error(s.where, fmt::format("scenario name '{}' must be letters, digits, - and _", s.name));
    if (s.name.empty())
        throw error(s.where, "the scenario name is empty");
    validate(s);
    return s;
}

} // namespace impact::simulate
