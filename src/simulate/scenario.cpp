#include "simulate/scenario.h"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
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
    s.radius = in.required_number("radius");
    s.position = in.pair("position");
    s.velocity = in.pair("velocity");
    in.finish();
    return s;
}

bool finite(const vec2& v)
{
    return std::isfinite(v[0]) && std::isfinite(v[1]);
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
    s.duration = in.number("duration");
    if (const auto samples = in.number("samples"))
        s.samples = static_cast<int>(*samples);
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

void validate(const scenario& s)
{
    auto bad = [&](const std::string& what) { throw error(s.where, what); };
    for (const auto& [name, sp] : {std::pair<const char*, const sphere&>{"M", s.M}, {"m", s.m}}) {
        if (!(sp.mass > 0) || !std::isfinite(sp.mass))
            bad(fmt::format("the mass of {} must be a positive number", name));
        if (!(sp.radius > 0) || !std::isfinite(sp.radius))
            bad(fmt::format("the radius of {} must be a positive number", name));
        if (!finite(sp.position) || !finite(sp.velocity))
            bad(fmt::format("the position and velocity of {} must be finite numbers", name));
    }
    if (!(s.eps >= 0 && s.eps <= 1))
        bad(fmt::format("eps = {} is outside [0, 1]", s.eps));
    if (s.duration && !(*s.duration > 0 && std::isfinite(*s.duration)))
        bad("the duration must be a positive number");
    if (s.samples < 2 || s.samples > 100000)
        bad("samples must be between 2 and 100000");
    const double dx = s.M.position[0] - s.m.position[0], dy = s.M.position[1] - s.m.position[1];
    if (std::hypot(dx, dy) < s.M.radius + s.m.radius)
        bad("the spheres overlap at the start");
}

} // namespace impact::simulate
