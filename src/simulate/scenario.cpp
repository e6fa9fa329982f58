#include "simulate/scenario.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>

#define TOML_EXCEPTIONS 1
#include <toml++/toml.h>

namespace impact::simulate {
namespace {

source_location location_of(const std::string& file, const toml::source_region& region)
{
    return {file, static_cast<std::uint32_t>(region.begin.line), static_cast<std::uint32_t>(region.begin.column)};
}

// Reads the keys of one table, refusing keys it does not know (a misspelt key would
// otherwise be silently ignored).
class table_reader {
public:
    table_reader(const toml::table& table, std::string file, std::string context)
        : table_(table), file_(std::move(file)), context_(std::move(context))
    {
    }

    source_location where(std::string_view key) const
    {
        if (const toml::node* node = table_.get(key))
            return location_of(file_, node->source());
        return location_of(file_, table_.source());
    }

    std::optional<double> number(std::string_view key)
    {
        const toml::node* node = get(key);
        if (!node)
            return std::nullopt;
        if (const auto v = node->value<double>())
            return *v;
        throw error(location_of(file_, node->source()), fmt::format("'{}' in {} must be a number", key, context_));
    }

    double required_number(std::string_view key)
    {
        if (const auto v = number(key))
            return *v;
        throw error(location_of(file_, table_.source()),
                    fmt::format("{} is missing the required field '{}'", context_, key));
    }

    vec2 pair(std::string_view key)
    {
        const toml::node* node = get(key);
        if (!node)
            throw error(location_of(file_, table_.source()),
                        fmt::format("{} is missing the required field '{}'", context_, key));
        const toml::array* array = node->as_array();
        if (!array || array->size() != 2 || !(*array)[0].value<double>() || !(*array)[1].value<double>())
            throw error(location_of(file_, node->source()),
                        fmt::format("'{}' in {} must be two numbers, [x, y]", key, context_));
        return {*(*array)[0].value<double>(), *(*array)[1].value<double>()};
    }

    std::optional<std::string> string(std::string_view key)
    {
        const toml::node* node = get(key);
        if (!node)
            return std::nullopt;
        if (const auto v = node->value<std::string>())
            return *v;
        throw error(location_of(file_, node->source()), fmt::format("'{}' in {} must be a string", key, context_));
    }

    const toml::table& table(std::string_view key)
    {
        const toml::node* node = get(key);
        if (!node || !node->is_table())
            throw error(location_of(file_, table_.source()),
                        fmt::format("{} needs a table [{}] describing the sphere", context_, key));
        return *node->as_table();
    }

    void finish() const
    {
        for (const auto& [key, node] : table_)
            if (!read_.count(std::string(key.str())))
                throw error(location_of(file_, node.source()),
                            fmt::format("unknown key '{}' in {}", key.str(), context_));
    }

private:
    const toml::node* get(std::string_view key)
    {
        read_.insert(std::string(key));
        return table_.get(key);
    }

    const toml::table& table_;
    std::string file_;
    std::string context_;
    std::set<std::string> read_;
};

sphere read_sphere(const toml::table& table, const std::string& file, const std::string& name)
{
    table_reader in(table, file, "[" + name + "]");
    sphere s;
    s.mass = in.required_number("mass");
    check_number(s.mass, number_kind::positive, in.where("mass"), "the mass of " + name);
    s.radius = in.required_number("radius");
    check_number(s.radius, number_kind::positive, in.where("radius"), "the radius of " + name);
    s.position = in.pair("position");
    s.velocity = in.pair("velocity");
    for (int i = 0; i < 2; ++i) {
        check_number(s.position[i], number_kind::coordinate, in.where("position"), "the position of " + name);
        check_number(s.velocity[i], number_kind::coordinate, in.where("velocity"), "the velocity of " + name);
    }
    if (const auto spin = in.number("spin")) {
        s.spin = *spin;
        check_number(s.spin, number_kind::coordinate, in.where("spin"), "the spin of " + name);
    }
    if (const auto q = in.number("q")) {
        s.q = *q;
        check_number(s.q, number_kind::inertia, in.where("q"), "q of " + name);
    }
    in.finish();
    return s;
}

double length(const vec2& v)
{
    return std::hypot(v[0], v[1]);
}

} // namespace

scenario parse_scenario(const std::string& text, const std::string& file)
{
    toml::table table;
    try {
        table = toml::parse(text, file);
    } catch (const toml::parse_error& e) {
        throw error(location_of(file, e.source()), fmt::format("invalid TOML: {}", e.description()));
    }
    table_reader in(table, file, "the scenario");
    scenario s;
    s.where = {file, 1, 1};
    if (const auto name = in.string("name"))
        s.name = *name;
    s.eps = in.required_number("eps");
    check_number(s.eps, number_kind::restitution, in.where("eps"), "eps");
    s.duration = in.number("duration");
    if (s.duration)
        check_number(*s.duration, number_kind::positive, in.where("duration"), "the duration");
    if (const auto samples = in.number("samples"))
        s.samples = checked_samples(*samples, in.where("samples"));
    s.beta = in.number("beta");
    if (s.beta)
        check_number(*s.beta, number_kind::tangential, in.where("beta"), "beta");
    s.mu = in.number("mu");
    if (s.mu) {
        check_number(*s.mu, number_kind::friction, in.where("mu"), "mu");
        if (!s.beta)
            throw error(in.where("mu"), mu_needs_beta("beta"));
    }
    s.M = read_sphere(in.table("M"), file, "M");
    s.m = read_sphere(in.table("m"), file, "m");
    in.finish();
    validate(s);
    return s;
}

scenario read_scenario(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw error({path, 0, 0}, "cannot read the scenario file");
    std::ostringstream text;
    text << in.rdbuf();
    return parse_scenario(text.str(), path);
}

std::string mu_needs_beta(const std::string& beta)
{
    return fmt::format("mu is the friction of rough spheres: give {} too, the tangential restitution in [-1, 1] "
                       "(-1: smooth, 1: perfectly rough)",
                       beta);
}

void check_number(double value, number_kind kind, const source_location& where, const std::string& what)
{
    auto refuse = [&](const std::string& why) { throw error(where, fmt::format("{} is {}, {}", what, value, why)); };
    if (kind == number_kind::friction && value == std::numeric_limits<double>::infinity())
        return;   // a contact that never slides
    if (!std::isfinite(value))
        refuse(kind == number_kind::friction ? "not a number in [0, inf]" : "not a finite number");
    switch (kind) {
    case number_kind::tangential:
        if (!(value >= -1 && value <= 1))
            refuse("outside [-1, 1] (-1 is smooth, 1 perfectly rough)");
        return;
    case number_kind::inertia:
        if (!(value > 0 && value <= 2.0 / 3))
            refuse("outside (0, 2/3] (2/5 is a solid sphere, 2/3 a hollow one)");
        return;
    case number_kind::friction:
        if (!(value >= 0))
            refuse("negative (0 is frictionless, inf a contact that never slides)");
        if (value == 0)
            return;
        break;
    case number_kind::restitution:
        if (!(value >= 0 && value <= 1))
            refuse("outside [0, 1] (0 is perfectly inelastic, 1 perfectly elastic)");
        return;
    case number_kind::positive:
        if (!(value > 0))
            refuse("not positive");
        break;
    case number_kind::coordinate:
        if (value == 0)
            return;
        break;
    }
    if (std::fabs(value) > limits::largest || std::fabs(value) < limits::smallest)
        refuse(fmt::format("beyond what the simulation computes with: a number other than 0 must lie between "
                           "{:g} and {:g} in magnitude, so that its squares and products stay in double precision; "
                           "choose units in which it does",
                           limits::smallest, limits::largest));
}

int checked_samples(double value, const source_location& where)
{
    if (!(value >= limits::fewest_samples && value <= limits::most_samples) || value != std::floor(value))
        throw error(where, fmt::format("samples = {} must be a whole number from {} to {} (a trajectory of more "
                                       "points: pdflatex reads every point of its figure into memory, and takes about 20 s for 10000)",
                                       value, limits::fewest_samples, limits::most_samples));
    return static_cast<int>(value);
}

void validate(const scenario& s)
{
    auto bad = [&](const std::string& what) { throw error(s.where, what); };
    for (const auto& [name, sp] : {std::pair<const char*, const sphere&>{"M", s.M}, {"m", s.m}}) {
        check_number(sp.mass, number_kind::positive, s.where, fmt::format("the mass of {}", name));
        check_number(sp.radius, number_kind::positive, s.where, fmt::format("the radius of {}", name));
        for (int i = 0; i < 2; ++i) {
            check_number(sp.position[i], number_kind::coordinate, s.where, fmt::format("the position of {}", name));
            check_number(sp.velocity[i], number_kind::coordinate, s.where, fmt::format("the velocity of {}", name));
        }
        check_number(sp.spin, number_kind::coordinate, s.where, fmt::format("the spin of {}", name));
        check_number(sp.q, number_kind::inertia, s.where, fmt::format("q of {}", name));
    }
    check_number(s.eps, number_kind::restitution, s.where, "eps");
    if (s.beta)
        check_number(*s.beta, number_kind::tangential, s.where, "beta");
    if (s.mu) {
        check_number(*s.mu, number_kind::friction, s.where, "mu");
        if (!s.beta)
            bad(mu_needs_beta("beta"));
    }
    if (s.duration)
        check_number(*s.duration, number_kind::positive, s.where, "the duration");
    checked_samples(s.samples, s.where);
    const vec2 apart{s.M.position[0] - s.m.position[0], s.M.position[1] - s.m.position[1]};
    if (length(apart) < s.M.radius + s.m.radius)
        bad("the spheres overlap at the start");
    // Double precision resolves a position to about 1e-16 of its size: the contact is
    // placed within 1e-6 of a radius only while the scene spans at most 1e10 radii.
    const double radius = std::min(s.M.radius, s.m.radius);
    if (length(apart) / radius > limits::span_in_radii)
        bad(fmt::format("the spheres start {:g} radii apart (of the smaller sphere), more than the {:g} within "
                        "which double precision places their contact; bring them closer or make them larger",
                        length(apart) / radius, limits::span_in_radii));
    if (s.duration)
        for (const auto& [name, sp] : {std::pair<const char*, const sphere&>{"M", s.M}, {"m", s.m}})
            if (length(sp.velocity) * *s.duration / radius > limits::span_in_radii)
                bad(fmt::format("{} travels {:g} radii (of the smaller sphere) in the duration {:g}, more than the "
                                "{:g} within which double precision places the spheres; shorten the duration",
                                name, length(sp.velocity) * *s.duration / radius, *s.duration,
                                limits::span_in_radii));
}

} // namespace impact::simulate
