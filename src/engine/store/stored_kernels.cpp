// The derivation's kernels as stored text: parameters, outputs (with their error bounds
// by their bits), guards, sampling regimes and the kernels of their limits.
#include "engine/store/stored_codec.h"

namespace impact::engine {

using namespace stored_detail;

// ---- kernels ----

// A kernel's input is a quantity of its own (a copy of the derivation's, or of a
// component it names), kept whole.
json derivation_codec::put_quantity(const quantity& q)
{
    return {q.name,           put(q.symbol),       put_domain(q.range),   q.latex,
            q.meaning,        put_optional(q.definition), put_written(q.written), put_where(q.where),
            q.dim ? put_dimension(*q.dim) : json(), q.dim_declared};
}

void derivation_codec::get_quantity(const json& j, quantity& q)
{
    q.name = j.at(0).get<std::string>();
    q.symbol = get(j.at(1));
    q.range = get_domain(j.at(2));
    q.latex = j.at(3).get<std::string>();
    q.meaning = j.at(4).get<std::string>();
    q.definition = get_optional(j.at(5));
    get_written(j.at(6), q.written);
    q.where = get_where(j.at(7));
    if (!j.at(8).is_null())
        q.dim = get_dimension(j.at(8));
    q.dim_declared = j.at(9).get<bool>();
}

json derivation_codec::put_parameter(const kernel_parameter& p)
{
    return {p.name, list(p.components, &derivation_codec::put_quantity), p.is_array};
}

void derivation_codec::get_parameter(const json& j, kernel_parameter& p)
{
    p.name = j.at(0).get<std::string>();
    get_list(j.at(1), p.components, &derivation_codec::get_quantity);
    p.is_array = j.at(2).get<bool>();
}

json derivation_codec::put_output(const kernel_output& o)
{
    json candidates = json::array();
    for (const std::vector<form>& forms : o.candidates) {
        json each = json::array();
        for (const form& f : forms)
            each.push_back({f.label, put(f.value)});
        candidates.push_back(each);
    }
    json bounds = json::array();
    for (std::size_t i = 0; i < o.bound_ulps.size(); ++i)
        bounds.push_back({bits(o.bound_ulps[i]), o.bound_because[i], bits(o.fast_bound_ulps[i]),
                          o.fast_bound_because[i]});
    return {o.member, o.is_array, put_exs(o.values), candidates, code(o.error), put(o.scale_factor), bounds};
}

void derivation_codec::get_output(const json& j, kernel_output& o)
{
    o.member = j.at(0).get<std::string>();
    o.is_array = j.at(1).get<bool>();
    o.values = get_exs(j.at(2));
    for (const json& each : j.at(3)) {
        o.candidates.emplace_back();
        for (const json& f : each)
            o.candidates.back().push_back({f.at(0).get<std::string>(), get(f.at(1))});
    }
    o.error = enum_of<kernel_output::scale>(j.at(4), 1);
    o.scale_factor = get(j.at(5));
    const json& bounds = j.at(6);
    if (bounds.size() != o.bound_ulps.size())
        throw not_readable("bounds of another number of types");
    for (std::size_t i = 0; i < o.bound_ulps.size(); ++i) {
        o.bound_ulps[i] = from_bits(bounds[i].at(0));
        o.bound_because[i] = bounds[i].at(1).get<std::string>();
        o.fast_bound_ulps[i] = from_bits(bounds[i].at(2));
        o.fast_bound_because[i] = bounds[i].at(3).get<std::string>();
    }
}

json derivation_codec::put_guard(const kernel_guard& g)
{
    return {g.status, g.parameters, put_optional(g.condition), code(g.op)};
}

void derivation_codec::get_guard(const json& j, kernel_guard& g)
{
    g.status = j.at(0).get<std::string>();
    g.parameters = j.at(1).get<std::vector<std::string>>();
    g.condition = get_optional(j.at(2));
    g.op = enum_of<relation>(j.at(3), 4);
}

json derivation_codec::put_regime(const sampling_regime& r)
{
    return {r.name,          put_where(r.where), code(r.what),       r.start,     put_exs(r.inputs),
            put_exs(r.offsets), put_exs(r.slopes), put(r.denominator), bits(r.from), bits(r.to)};
}

void derivation_codec::get_regime(const json& j, sampling_regime& r)
{
    r.name = j.at(0).get<std::string>();
    r.where = get_where(j.at(1));
    r.what = enum_of<sampling_regime::kind>(j.at(2), 1);
    r.start = j.at(3).get<std::string>();
    r.inputs = get_exs(j.at(4));
    r.offsets = get_exs(j.at(5));
    r.slopes = get_exs(j.at(6));
    r.denominator = get(j.at(7));
    r.from = from_bits(j.at(8));
    r.to = from_bits(j.at(9));
}

json derivation_codec::put_kernel(const kernel& k)
{
    return {k.name,
            put_where(k.where),
            list(k.parameters, &derivation_codec::put_parameter),
            list(k.outputs, &derivation_codec::put_output),
            list(k.guards, &derivation_codec::put_guard),
            put_exs(k.velocities),
            put_exs(k.speeds),
            put_pairs(k.lets),
            list(k.regimes, &derivation_codec::put_regime),
            k.batch,
            k.limit_of,
            k.fixed_mass,
            list(k.limits, &derivation_codec::put_kernel)};
}

void derivation_codec::get_kernel(const json& j, kernel& k)
{
    k.name = j.at(0).get<std::string>();
    k.where = get_where(j.at(1));
    get_list(j.at(2), k.parameters, &derivation_codec::get_parameter);
    get_list(j.at(3), k.outputs, &derivation_codec::get_output);
    get_list(j.at(4), k.guards, &derivation_codec::get_guard);
    k.velocities = get_exs(j.at(5));
    k.speeds = get_exs(j.at(6));
    k.lets = get_pairs(j.at(7));
    get_list(j.at(8), k.regimes, &derivation_codec::get_regime);
    k.batch = j.at(9).get<bool>();
    k.limit_of = j.at(10).get<std::string>();
    k.fixed_mass = j.at(11).get<std::string>();
    get_list(j.at(12), k.limits, &derivation_codec::get_kernel);
}

} // namespace impact::engine
