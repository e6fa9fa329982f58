// Reads a [[kernel]] table of a derivation file into `spec::kernel` (for reader.cpp):
// its inputs and outputs, the scales of their errors, its guards, bounds and sampling
// regimes. As in reader.cpp, only the shape is checked; the expressions are the engine's.
#include "spec/kernel_reader.h"

#include <fmt/format.h>

#include <string>
#include <vector>

namespace impact::spec::detail {
namespace {

// `[a, b, c]` → a, b, c
std::vector<text> read_list(const text& list)
{
    std::string inner = list.value;
    const auto open = inner.find('['), close = inner.rfind(']');
    if (open == std::string::npos || close == std::string::npos || close < open)
        throw error(list.where, fmt::format("\"{}\" must be a list such as [x, y]", list.value));
    inner = inner.substr(open + 1, close - open - 1);
    std::vector<text> items;
    std::size_t start = 0;
    while (start <= inner.size()) {
        const auto comma = inner.find(',', start);
        const std::string item = trimmed(inner.substr(start, comma == std::string::npos ? std::string::npos
                                                                                         : comma - start));
        if (item.empty())
            throw error(list.where, fmt::format("empty entry in \"{}\"", list.value));
        items.push_back({item, list.where});
        if (comma == std::string::npos)
            break;
        start = comma + 1;
    }
    return items;
}

// `name = [a, b]` an array; `name = x` a scalar under another name; `name` itself.
kernel_value read_kernel_value(const binding& b)
{
    kernel_value v;
    v.name = b.name;
    if (b.expression.value.find('[') != std::string::npos) {
        v.is_array = true;
        v.components = read_list(b.expression);
    } else {
        v.components.push_back(b.expression);
    }
    return v;
}

kernel_guard read_guard(const binding& b)
{
    kernel_guard g;
    g.status = b.name;
    const std::string& text = b.expression.value;
    if (text.find('<') != std::string::npos || text.find('>') != std::string::npos)
        g.condition = b.expression;
    else
        g.parameters = read_list({"[" + text + "]", b.expression.where});
    return g;
}

error_scale read_error_scale(const binding& b)
{
    error_scale e;
    e.output = b.name;
    e.written = b.expression;
    const std::string& how = b.expression.value;
    if (how == "relative")
        return e;
    if (how.rfind("velocity", 0) != 0 || (how != "velocity" && trimmed(how.substr(8)).rfind('*', 0) != 0))
        throw error(b.expression.where,
                    fmt::format("error scale '{}' must be relative, velocity or velocity*<expression>", how));
    e.relative = false;
    const auto star = how.find('*');
    if (star != std::string::npos)
        e.factor = text{how.substr(star + 1), b.expression.where};
    return e;
}

// `[[kernel.regime]]`: a ratio of two quantities over decades, or a boundary approached.
sampling_regime read_sampling_regime(table_reader r)
{
    sampling_regime regime;
    regime.name = r.required_string("name");
    regime.set = r.required_string("set");
    regime.ratio = r.string_array("ratio", false);
    regime.boundary = r.optional_string("boundary");
    regime.start = r.optional_string("start");
    if (regime.start && regime.start->value != "nearly head-on" && regime.start->value != "nearly grazing")
        throw error(regime.start->where, fmt::format("regime '{}' starts from '{}': give \"nearly head-on\" or "
                                                     "\"nearly grazing\" (or no start: an ordinary draw)",
                                                     regime.name.value, regime.start->value));
    if (regime.ratio.empty() == !regime.boundary)
        throw error(r.where(), fmt::format("regime '{}' needs either ratio = [\"A\", \"B\"] or boundary = "
                                           "\"lhs = rhs\", not {}",
                                           regime.name.value, regime.boundary ? "both" : "neither"));
    // A field of the other kind of regime does not apply.
    const std::vector<std::string> others =
        regime.boundary ? std::vector<std::string>{"from", "to"} : std::vector<std::string>{"within"};
    for (const std::string& other : others)
        if (r.has(other))
            throw error(r.where_of(other), fmt::format("regime '{}' {}: '{}' does not apply (give {})", regime.name.value,
                                                       regime.boundary ? "approaches a boundary" : "spans a ratio",
                                                       other, regime.boundary ? "within" : "from and to"));
    if (!regime.ratio.empty()) {
        if (regime.ratio.size() != 2)
            throw error(r.where_of("ratio"), fmt::format("regime '{}': ratio = [\"A\", \"B\"] names two "
                                                         "quantities, A set to ±10^u B",
                                                         regime.name.value));
        regime.from = r.required_number("from");
        regime.to = r.required_number("to");
        if (!(regime.from > 0 && regime.from <= regime.to && regime.to < 1e300))
            throw error(r.where_of("from"), fmt::format("regime '{}': |A/B| from {} to {}: give 0 < from <= to",
                                                        regime.name.value, regime.from, regime.to));
    } else {
        regime.within = r.required_number("within");
        if (!(regime.within > 0 && regime.within < 1))
            throw error(r.where_of("within"), fmt::format("regime '{}': within {} of the boundary: give a "
                                                          "relative distance between 0 and 1",
                                                          regime.name.value, regime.within));
    }
    r.finish();
    return regime;
}

} // namespace

kernel read_kernel(table_reader& in)
{
    kernel k;
    k.name = in.required_string("name");
    // An input is a name, or an array `C_M = [C_Mx, C_My]`.
    for (const text& input : in.string_array("inputs", true))
        k.inputs.push_back(read_kernel_value(input.value.find('=') == std::string::npos
                                                 ? binding{input, input}
                                                 : in.split(input, "inputs")));
    for (const binding& output : in.binding_array("outputs", true))
        k.outputs.push_back(read_kernel_value(output));
    k.velocities = in.string_array("velocities", false);
    for (const binding& e : in.binding_array("error", false))
        k.error.push_back(read_error_scale(e));
    k.forms = in.binding_array("forms", false);
    for (const binding& g : in.binding_array("guards", false))
        k.guards.push_back(read_guard(g));
    k.substitute = in.binding_array("substitute", false);
    k.let = in.binding_array("let", false);
    k.batch = in.optional_bool("batch").value_or(false);
    k.fixed = in.string_array("fixed", false);
    for (const toml::table* table : in.table_array("bound")) {
        table_reader b = in.nested(*table, "[[kernel.bound]]");
        error_bound bound;
        bound.output = b.required_string("output");
        bound.type = b.optional_string("type");
        if (bound.type && bound.type->value != "float" && bound.type->value != "double" &&
            bound.type->value != "long double")
            throw error(bound.type->where, fmt::format("type '{}' must be float, double or long double",
                                                       bound.type->value));
        bound.form = b.optional_string("form");
        if (bound.form && bound.form->value != "accurate" && bound.form->value != "fast")
            throw error(bound.form->where, fmt::format("form '{}' must be accurate (the kernel as called without "
                                                       "a tag) or fast (called with impact::fast)",
                                                       bound.form->value));
        bound.ulps = b.required_number("ulps");
        bound.ulps_where = b.where_of("ulps");
        bound.because = b.required_string("because");
        b.finish();
        if (!(bound.ulps >= 0.5 && bound.ulps <= 1e15))
            throw error(bound.ulps_where, fmt::format("a bound of {} ulps: give one from 0.5 (correctly rounded) to "
                                                      "1e15 (no accuracy at all in double)",
                                                      bound.ulps));
        k.bounds.push_back(std::move(bound));
    }
    for (const toml::table* table : in.table_array("regime"))
        k.regimes.push_back(read_sampling_regime(in.nested(*table, "[[kernel.regime]]")));
    in.finish();
    return k;
}

} // namespace impact::spec::detail
