// The sign of a function of known facts (sign_prover.h), and of a sum in which sines,
// cosines and the inverse functions stand as bounded quantities:
// - sin > 0 on (0, Pi), cos > 0 on (-Pi/2, Pi/2), each with its sign on the other half
//   periods, read off the exact range of the argument (angles.h); tan as sin/cos;
// - log(u) has the sign of u - 1 (increasing, log 1 = 0); asin, atan, sinh and tanh the sign
//   of their argument (odd, increasing); atan2(y, x) the sign of y (Pi where y = 0 > x);
// - a sum with sin and cos: the angles written over a basis (transcendental.h), each base
//   angle's sine s and cosine c a quantity in [-1, 1] (narrowed to one sign where the angle's
//   range gives it), reduced modulo s^2 + c^2 = 1; acos, asin, atan, atan2 and tanh quantities
//   in their ranges; then the sign of what is left, by the arguments for polynomials.
#include "engine/prove/sign_prover.h"

#include "engine/prove/angles.h"
#include "engine/prove/transcendental.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace impact::engine {
namespace {

std::string name_of(const GiNaC::ex& e)
{
    return GiNaC::ex_to<GiNaC::function>(e).get_name();
}

bool is_bounded_call(const GiNaC::ex& e)
{
    if (!GiNaC::is_a<GiNaC::function>(e))
        return false;
    const std::string name = name_of(e);
    return name == "acos" || name == "asin" || name == "atan" || name == "atan2" || name == "tanh";
}

// `e` has the sign `s`, typeset: "e > 0", or the words "of unknown sign" after it.
finding& sign_of(finding& f, const GiNaC::ex& e, const sign_set& s)
{
    if (!s.is_known() || (s.negative && s.positive))
        return f.math(e).say(" " + s.describe());
    const relation op = !s.negative && !s.zero   ? relation::greater
                        : !s.negative && s.positive ? relation::greater_equal
                        : !s.positive && !s.zero   ? relation::less
                        : !s.positive && s.negative ? relation::less_equal
                                                     : relation::equal;
    return f.states(e, op, 0);
}

// `e` in the domain `d`, typeset: "e in [0, 1]", "e > 0".
finding& said_in(finding& f, const GiNaC::ex& e, const domain& d, const assumptions& given)
{
    switch (d.what) {
    case domain::kind::positive: return f.states(e, relation::greater, 0);
    case domain::kind::nonnegative: return f.states(e, relation::greater_equal, 0);
    case domain::kind::real: return f.math(e).say(" real");
    case domain::kind::interval: break;
    }
    if (d.infinity_included)
        return f.math(e).say(" in " + d.to_string());
    exact_interval r;
    r.low = d.exact_lower();
    r.high = d.exact_upper();
    r.low_open = d.lower_open;
    r.high_open = d.upper_open;
    return interval_said(f.math(e).say(" in "), r, given);
}

bool has_sine_or_cosine(const GiNaC::ex& e)
{
    for (GiNaC::const_preorder_iterator it = e.preorder_begin(); it != e.preorder_end(); ++it)
        if (GiNaC::is_a<GiNaC::function>(*it) && (name_of(*it) == "sin" || name_of(*it) == "cos"))
            return true;
    return false;
}

bool has_bounded(const GiNaC::ex& e)
{
    for (GiNaC::const_preorder_iterator it = e.preorder_begin(); it != e.preorder_end(); ++it)
        if (is_bounded_call(*it) ||
            (GiNaC::is_a<GiNaC::function>(*it) && (name_of(*it) == "sin" || name_of(*it) == "cos")))
            return true;
    return false;
}

// An interval domain with exact ends written as texts (read back by exact_end, which reads
// a number as its double): none when an end is a rational no double holds exactly.
std::optional<domain> interval(const GiNaC::ex& low, const GiNaC::ex& high, bool low_open, bool high_open,
                               const assumptions& given)
{
    for (const GiNaC::ex& end : {low, high})
        if (GiNaC::is_a<GiNaC::numeric>(end)) {
            const GiNaC::numeric& n = GiNaC::ex_to<GiNaC::numeric>(end);
            if (!n.is_rational() || !GiNaC::numeric(n.to_double()).is_equal(n))
                return std::nullopt;
        }
    domain d;
    d.what = domain::kind::interval;
    d.lower = GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(low)).to_double();
    d.upper = GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(high)).to_double();
    d.lower_open = low_open;
    d.upper_open = high_open;
    d.lower_text = given.text(low);
    d.upper_text = given.text(high);
    return d;
}

// [-1, 1], or its half where the sign is known.
domain unit_range(const sign_set& s, const assumptions& given)
{
    if (!s.negative)
        return *interval(0, 1, !s.zero, false, given);
    if (!s.positive)
        return *interval(-1, 0, false, !s.zero, given);
    return *interval(-1, 1, false, false, given);
}

} // namespace

std::optional<std::pair<sign_set, sign_reason>> sign_prover::function_sign(const GiNaC::ex& e, int depth) const
{
    const std::string name = name_of(e);
    if (e.nops() == 2 && name == "atan2") {
        const sign_set y = sign(e.op(0), depth + 1).first, x = sign(e.op(1), depth + 1).first;
        sign_set r{y.negative, y.zero && x.positive, y.positive || (y.zero && x.negative)};
        if (!r.is_known())
            return std::nullopt;
        return std::make_pair(r, sign_reason(fmt::format("atan2 has the sign of {}, which is {}", text(e.op(0)),
                                                         y.describe())));
    }
    if (e.nops() != 1)
        return std::nullopt;
    const GiNaC::ex u = e.op(0);
    if (name == "sin" || name == "cos" || name == "tan") {
        const auto r = range_of(u, given_);
        if (!r)
            return std::nullopt;
        const sign_set s = sine_sign_on(*r, 0), c = sine_sign_on(*r, GiNaC::numeric(1, 2));
        const sign_set of = name == "sin" ? s : name == "cos" ? c : times(s, reciprocal(c));
        if (!of.is_known())
            return std::nullopt;
        sign_reason why(fmt::format("{} in {}, where {} is {}", text(u), r->to_string(given_), name, of.describe()));
        interval_said(why.typeset.math(u).say(" in "), *r, given_)
            .say(name == "sin" ? ", where the sine is " : name == "cos" ? ", where the cosine is " : ", where the tangent is ")
            .say(of.describe());
        return std::make_pair(of, why);
    }
    if (name == "log") {
        const sign_set s = sign(u - 1, depth + 1).first;
        if (!s.is_known())
            return std::nullopt;
        sign_reason why(fmt::format("log is increasing and log(1) = 0, and {} is {}", text(u - 1), s.describe()));
        sign_of(why.typeset.say("the logarithm is increasing and 0 at 1, and "), u - 1, s);
        return std::make_pair(s, why);
    }
    if (name == "asin" || name == "atan" || name == "sinh" || name == "tanh") {
        const sign_set s = sign(u, depth + 1).first;
        if (!s.is_known())
            return std::nullopt;
        sign_reason why(fmt::format("{} is increasing and 0 at 0, and {} is {}", name, text(u), s.describe()));
        const char* called = name == "asin" ? "arcsin" : name == "atan" ? "arctan" : name.c_str();
        sign_of(why.typeset.say(std::string(called) + " is increasing and 0 at 0, and "), u, s);
        return std::make_pair(s, why);
    }
    return std::nullopt;
}

std::optional<std::pair<sign_set, sign_reason>> sign_prover::constant_sign(const GiNaC::ex& e) const
{
    const std::optional<int> s = sign_of_number(e);
    if (!s)
        return std::nullopt;
    return std::make_pair(sign_set::exactly(*s), sign_reason("a number, evaluated at 40 and 60 digits"));
}

std::optional<std::pair<sign_set, sign_reason>> sign_prover::bounded_functions_sign(const GiNaC::ex& e, int depth,
                                                                                  bool trig_only) const
{
    if (depth > 4 || !has_bounded(e) || (trig_only && !has_sine_or_cosine(e)))
        return std::nullopt;
    assumptions within = given_;
    within.known = std::make_shared<worked_out>();
    std::vector<std::string> facts;
    finding typeset = finding().say("with ");
    GiNaC::exmap back;   // the quantities standing for sines, cosines and calls, as themselves
    GiNaC::ex value = e;
    if (const auto bases = through_base_angles(e, given_)) {
        const GiNaC::ex nd = GiNaC::normal(bases->value).numer_denom();
        value = reduced_modulo_circle(nd.op(0), bases->bases) / reduced_modulo_circle(nd.op(1), bases->bases);
        for (const base_angle& b : bases->bases) {
            if (!b.symbols)
                continue;
            const auto r = range_of(b.angle, given_);
            const exact_interval all{0, 0, true, true, true, true};
            within.domains[b.sine] = unit_range(sine_sign_on(r.value_or(all), 0), given_);
            within.domains[b.cosine] = unit_range(sine_sign_on(r.value_or(all), GiNaC::numeric(1, 2)), given_);
            facts.push_back(fmt::format("{} in {}, {} in {}, {}^2 + {}^2 = 1", text(b.sine),
                                        within.domains[b.sine].to_string(), text(b.cosine),
                                        within.domains[b.cosine].to_string(), text(b.sine), text(b.cosine)));
            back[b.sine] = GiNaC::sin(b.angle);
            back[b.cosine] = GiNaC::cos(b.angle);
            if (facts.size() > 1)
                typeset.say("; ");
            said_in(typeset, GiNaC::sin(b.angle), within.domains[b.sine], given_).say(", ");
            said_in(typeset, GiNaC::cos(b.angle), within.domains[b.cosine], given_).say(", ");
            typeset.states(GiNaC::pow(GiNaC::sin(b.angle), 2) + GiNaC::pow(GiNaC::cos(b.angle), 2), relation::equal, 1);
        }
    }
    // acos, asin, atan, atan2 and tanh as quantities in their ranges, in the order of their texts.
    std::vector<GiNaC::ex> calls;
    for (GiNaC::const_preorder_iterator it = value.preorder_begin(); it != value.preorder_end(); ++it)
        if (is_bounded_call(*it) && std::none_of(calls.begin(), calls.end(), [&](const GiNaC::ex& c) {
                return c.is_equal(*it);
            }))
            calls.push_back(*it);
    std::sort(calls.begin(), calls.end(), [this](const GiNaC::ex& a, const GiNaC::ex& b) { return text(a) < text(b); });
    GiNaC::exmap as_quantities;
    for (const GiNaC::ex& call : calls) {
        const auto r = range_of(call, given_);
        const auto range = r && r->bounded() ? interval(r->low, r->high, r->low_open, r->high_open, given_)
                                             : std::nullopt;
        if (!range)
            continue;
        const GiNaC::symbol quantity(text(call), text(call));
        within.domains[quantity] = *range;
        as_quantities[call] = quantity;
        facts.push_back(fmt::format("{} in {}", text(call), within.domains[quantity].to_string()));
        back[quantity] = call;
        if (facts.size() > 1)
            typeset.say("; ");
        said_in(typeset, call, within.domains[quantity], given_);
    }
    if (facts.empty())
        return std::nullopt;
    value = value.subs(as_quantities, GiNaC::subs_options::no_pattern);
    if (value.is_equal(e) || has_bounded(value))
        return std::nullopt;
    const sign_proof proof = prove_sign(value, within);
    if (!proof.sign.is_known())
        return std::nullopt;
    std::vector<std::string> steps;
    typeset.say(": ");
    for (const sign_step& step : proof.steps) {
        steps.push_back(step.words);
        if (steps.size() > 1)
            typeset.say(", ");
        sign_of(typeset, step.factor.subs(back, GiNaC::subs_options::no_pattern), step.sign).say(" (");
        if (!step.why.typeset.parts.empty())
            for (finding::part part : step.why.typeset.parts) {
                if (part.what == finding::part::kind::math)
                    part.value = part.value.subs(back, GiNaC::subs_options::no_pattern);
                typeset.parts.push_back(std::move(part));
            }
        else if (const auto known = step.why.declared ? within.domains.find(*step.why.declared) : within.domains.end();
                 known != within.domains.end())
            said_in(typeset, step.why.declared->subs(back, GiNaC::subs_options::no_pattern), known->second, given_);
        else
            typeset.say(step.why.declared ? "declared " + step.why.domain : step.why.words);
        typeset.say(")");
    }
    sign_reason why(fmt::format("with {}: {}", fmt::join(facts, "; "), fmt::join(steps, ", ")));
    why.typeset = std::move(typeset);
    return std::make_pair(proof.sign, why);
}

} // namespace impact::engine
