// The small parts a proof is made of, as stored text: domains (their bounds by their bits),
// dimensions, signs, findings, the reasons and steps of a sign proof, verdicts and the
// method of a limit.
#include "engine/store/stored_codec.h"

namespace impact::engine {

using namespace stored_detail;

// ---- small parts ----

json derivation_codec::put_domain(const domain& d)
{
    return {code(d.what),   bits(d.lower),  bits(d.upper),  d.lower_open,
            d.upper_open,   d.lower_text,   d.upper_text,   d.infinity_included};
}

domain derivation_codec::get_domain(const json& j)
{
    domain d;
    d.what = enum_of<domain::kind>(j.at(0), 3);
    d.lower = from_bits(j.at(1));
    d.upper = from_bits(j.at(2));
    d.lower_open = j.at(3).get<bool>();
    d.upper_open = j.at(4).get<bool>();
    d.lower_text = j.at(5).get<std::string>();
    d.upper_text = j.at(6).get<std::string>();
    d.infinity_included = j.at(7).get<bool>();
    return d;
}

json derivation_codec::put_dimension(const dimension& d)
{
    json out = json::array();
    for (const auto& [base, exponent] : d.exponents())
        out.push_back({base, integer_text(exponent.numer()), integer_text(exponent.denom())});
    return out;
}

dimension derivation_codec::get_dimension(const json& j)
{
    dimension d;
    for (const json& factor : j)
        d = d * dimension::base(factor.at(0).get<std::string>())
                    .power(integer_of(factor.at(1)) / integer_of(factor.at(2)));
    return d;
}

json derivation_codec::put_sign(const sign_set& s) { return {s.negative, s.zero, s.positive}; }

sign_set derivation_codec::get_sign(const json& j) { return {j.at(0).get<bool>(), j.at(1).get<bool>(), j.at(2).get<bool>()}; }

json derivation_codec::put_finding(const finding& f)
{
    json parts = json::array();
    for (const finding::part& p : f.parts)
        parts.push_back({code(p.what), p.words, put(p.value), put_optional(p.point), put_dimension(p.dim), p.term,
                         code(p.op)});
    return {parts, put_optional(f.corrected)};
}

void derivation_codec::get_finding(const json& j, finding& f)
{
    for (const json& p : j.at(0)) {
        finding::part part;
        part.what = enum_of<finding::part::kind>(p.at(0), 3);
        part.words = p.at(1).get<std::string>();
        part.value = get(p.at(2));
        part.point = get_optional(p.at(3));
        part.dim = get_dimension(p.at(4));
        part.term = p.at(5).get<bool>();
        part.op = enum_of<relation>(p.at(6), 4);
        f.parts.push_back(std::move(part));
    }
    f.corrected = get_optional(j.at(1));
}

json derivation_codec::put_reason(const sign_reason& r)
{
    return {r.words, put_finding(r.typeset), put_optional(r.declared), r.domain};
}

void derivation_codec::get_reason(const json& j, sign_reason& r)
{
    r.words = j.at(0).get<std::string>();
    get_finding(j.at(1), r.typeset);
    r.declared = get_optional(j.at(2));
    r.domain = j.at(3).get<std::string>();
}

json derivation_codec::put_sign_step(const sign_step& s) { return {put(s.factor), put_sign(s.sign), put_reason(s.why), s.words}; }

void derivation_codec::get_sign_step(const json& j, sign_step& s)
{
    s.factor = get(j.at(0));
    s.sign = get_sign(j.at(1));
    get_reason(j.at(2), s.why);
    s.words = j.at(3).get<std::string>();
}

json derivation_codec::put_condition(const condition& c) { return {put(c.expr), code(c.need), c.text, c.because}; }

void derivation_codec::get_condition(const json& j, condition& c)
{
    c.expr = get(j.at(0));
    c.need = enum_of<condition::kind>(j.at(1), 2);
    c.text = j.at(2).get<std::string>();
    c.because = j.at(3).get<std::string>();
}

json derivation_codec::put_verdict(const verdict& v)
{
    return {code(v.what),
            code(v.how),
            v.samples,
            put(v.residual),
            v.method,
            list(v.proof, &derivation_codec::put_sign_step),
            list(v.where, &derivation_codec::put_condition),
            list(v.defined, &derivation_codec::put_condition),
            put_finding(v.typeset)};
}

void derivation_codec::get_verdict(const json& j, verdict& v)
{
    v.what = enum_of<verdict::status>(j.at(0), 2);
    v.how = enum_of<verdict::basis>(j.at(1), 8);
    v.samples = j.at(2).get<std::size_t>();
    v.residual = get(j.at(3));
    v.method = j.at(4).get<std::string>();
    get_list(j.at(5), v.proof, &derivation_codec::get_sign_step);
    get_list(j.at(6), v.where, &derivation_codec::get_condition);
    get_list(j.at(7), v.defined, &derivation_codec::get_condition);
    get_finding(j.at(8), v.typeset);
}

json derivation_codec::put_limit_method(const limit_method& m)
{
    return {code(m.how),         put(m.symbol),    put(m.point),    put(m.denominator),
            put_sign(m.denominator_sign), put(m.coefficient), m.order, m.at_infinity,
            put(m.inverted),      put_optional(m.leading_in_inverse), m.words};
}

void derivation_codec::get_limit_method(const json& j, limit_method& m)
{
    m.how = enum_of<limit_method::kind>(j.at(0), 1);
    m.symbol = get(j.at(1));
    m.point = get(j.at(2));
    m.denominator = get(j.at(3));
    m.denominator_sign = get_sign(j.at(4));
    m.coefficient = get(j.at(5));
    m.order = j.at(6).get<int>();
    m.at_infinity = j.at(7).get<bool>();
    m.inverted = get(j.at(8));
    m.leading_in_inverse = get_optional(j.at(9));
    m.words = j.at(10).get<std::string>();
}

} // namespace impact::engine
