#include "engine/prove/sturm.h"

#include <cln/integer.h>
#include <cln/rational.h>
#include <cln/real.h>

namespace impact::engine {
namespace {

// An end as a rational: itself when it is one; an end of π (Pi/2), at which a Sturm
// sequence cannot be evaluated exactly, as a rational within 10^-20 beyond it (below a
// lower end, above an upper one), so that the closure holds the domain and a sign shown on
// the closure holds on the domain.
GiNaC::numeric rational_end(const GiNaC::ex& end, bool lower)
{
    if (GiNaC::is_a<GiNaC::numeric>(end))
        return GiNaC::ex_to<GiNaC::numeric>(end);
    const long saved = GiNaC::Digits;
    GiNaC::Digits = 40;
    const GiNaC::numeric scaled = GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(end * GiNaC::pow(10, 20)));
    GiNaC::Digits = saved;
    const cln::cl_R x = cln::the<cln::cl_R>(scaled.to_cl_N());
    const cln::cl_I down = cln::floor1(x), up = cln::ceiling1(x);
    const cln::cl_I beyond = lower ? cln::minus1(down) : cln::plus1(up);
    return GiNaC::numeric(cln::cl_N(beyond)).div(GiNaC::numeric(10).power(20));
}

} // namespace

closed_interval closure_of(const domain& d)
{
    switch (d.what) {
    case domain::kind::real: return {};
    case domain::kind::positive: return {GiNaC::numeric(0), std::nullopt, false, false, GiNaC::ex(0), std::nullopt};
    case domain::kind::nonnegative: return {GiNaC::numeric(0), std::nullopt, true, false, GiNaC::ex(0), std::nullopt};
    case domain::kind::interval: break;
    }
    const GiNaC::ex low = d.exact_lower(), high = d.exact_upper();
    // A widened end is counted in: the sign there is the closure's, whatever the domain's.
    return {rational_end(low, true),
            rational_end(high, false),
            !d.lower_open || !GiNaC::is_a<GiNaC::numeric>(low),
            !d.upper_open || !GiNaC::is_a<GiNaC::numeric>(high),
            low,
            high};
}

int sign_of(const GiNaC::ex& value)
{
    const GiNaC::numeric n = GiNaC::ex_to<GiNaC::numeric>(value);
    return n.is_zero() ? 0 : n.is_positive() ? 1 : -1;
}

bool rational_polynomial_in(const GiNaC::ex& p, const GiNaC::ex& s)
{
    if (!p.is_polynomial(s))
        return false;
    for (int k = p.ldegree(s); k <= p.degree(s); ++k)
        if (!p.coeff(s, k).info(GiNaC::info_flags::rational))
            return false;
    return true;
}

std::vector<GiNaC::ex> sturm_sequence(const GiNaC::ex& q, const GiNaC::ex& s)
{
    std::vector<GiNaC::ex> sequence = {q, GiNaC::diff(q, GiNaC::ex_to<GiNaC::symbol>(s))};
    while (sequence.back().degree(s) > 0) {
        const GiNaC::ex r = GiNaC::expand(-GiNaC::rem(sequence[sequence.size() - 2], sequence.back(), s));
        if (r.is_zero())
            break;
        sequence.push_back(r);
    }
    return sequence;
}

int sign_changes(const std::vector<GiNaC::ex>& sequence, const GiNaC::ex& s, const std::optional<GiNaC::numeric>& x,
                 bool above)
{
    int count = 0, last = 0;
    for (const GiNaC::ex& p : sequence) {
        int sign = 0;
        if (x) {
            sign = sign_of(p.subs(s == *x));
        } else {
            sign = sign_of(p.lcoeff(s));
            if (!above && p.degree(s) % 2 == 1)
                sign = -sign;
        }
        if (sign == 0)
            continue;
        if (last != 0 && sign != last)
            ++count;
        last = sign;
    }
    return count;
}

} // namespace impact::engine
