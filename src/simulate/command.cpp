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
    // Each number is checked as given, so that the message names its option.
    auto take = [](const std::optional<double>& given, double& into, number_kind kind, const char* option,
                   const char* what) {
        if (!given)
            return;
        check_number(*given, kind, {option, 0, 0}, what);
        into = *given;
    };
    auto take_pair = [](const std::optional<std::string>& given, vec2& into, const char* option, const char* what) {
        if (!given)
            return;
        into = parse_pair(*given, option);
        for (double x : into)
            check_number(x, number_kind::coordinate, {fmt::format("--{}", option), 0, 0}, what);
    };
    if (o.name)
        s.name = *o.name;
    take(o.eps, s.eps, number_kind::restitution, "--eps", "eps");
    if (o.duration) {
        check_number(*o.duration, number_kind::positive, {"--duration", 0, 0}, "the duration");
        s.duration = *o.duration;
    }
    take(o.mass_M, s.M.mass, number_kind::positive, "--mass-M", "the mass of M");
    take(o.mass_m, s.m.mass, number_kind::positive, "--mass-m", "the mass of m");
    take(o.radius_M, s.M.radius, number_kind::positive, "--radius-M", "the radius of M");
    take(o.radius_m, s.m.radius, number_kind::positive, "--radius-m", "the radius of m");
    take_pair(o.position_M, s.M.position, "position-M", "the position of M");
    take_pair(o.position_m, s.m.position, "position-m", "the position of m");
    take_pair(o.velocity_M, s.M.velocity, "velocity-M", "the velocity of M");
    take_pair(o.velocity_m, s.m.velocity, "velocity-m", "the velocity of m");
    take(o.spin_M, s.M.spin, number_kind::coordinate, "--spin-M", "the spin of M");
    take(o.spin_m, s.m.spin, number_kind::coordinate, "--spin-m", "the spin of m");
    take(o.q_M, s.M.q, number_kind::inertia, "--q-M", "q of M");
    take(o.q_m, s.m.q, number_kind::inertia, "--q-m", "q of m");
    if (o.beta) {
        check_number(*o.beta, number_kind::tangential, {"--beta", 0, 0}, "beta");
        s.beta = o.beta;
    }
    if (o.mu) {
        check_number(*o.mu, number_kind::friction, {"--mu", 0, 0}, "mu");
        if (!s.beta)
            throw error({"--mu", 0, 0}, mu_needs_beta("--beta"));
        s.mu = o.mu;
    }
    // A name becomes a file name.
    for (char c : s.name)
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-'))
            throw error(s.where, fmt::format("scenario name '{}' must be letters, digits, - and _", s.name));
    if (s.name.empty())
        throw error(s.where, "the scenario name is empty");
    if (s.name.size() > 64)
        throw error(s.where, fmt::format("scenario name '{}...' is longer than 64 characters", s.name.substr(0, 16)));
    validate(s);
    return s;
}

} // namespace impact::simulate
