// Where a derivation's values, results and claims are defined in the reals
// (engine/prove/definedness.h): what each derived value needs, as the file writes it and as
// derived, in the inputs; and those needs proven from the domains or attached.
#include "engine/derive/deriver.h"

#include <algorithm>

namespace impact::engine::detail {

// Conditions written in derived quantities, put in the inputs.
std::vector<condition> deriver::in_inputs(const std::vector<condition>& needs) const
{
    return rewritten(needs, [this](const GiNaC::ex& e) { return resolve(e); }, out_.symbols);
}

// What the derived quantities that `uses` picks need, in their declared order: of two
// conditions that are one, written in two forms, add_conditions keeps the first, and GiNaC's
// order of the symbols (needs_ is a map by it) changes from run to run.
std::vector<const std::vector<condition>*>
deriver::needs_where(const std::function<bool(const GiNaC::ex&)>& uses) const
{
    std::vector<GiNaC::ex> symbols;
    for (const auto& [symbol, more] : needs_)
        if (uses(symbol))
            symbols.push_back(symbol);
    const term_order& order = out_.symbols.order();
    std::sort(symbols.begin(), symbols.end(), [&](const GiNaC::ex& a, const GiNaC::ex& b) { return order.before(a, b); });
    std::vector<const std::vector<condition>*> needs;
    for (const GiNaC::ex& symbol : symbols)
        needs.push_back(&needs_.at(symbol));
    return needs;
}

// What a value needs, `value` as parsed (in derived quantities) and `written` as the file
// writes it: the conditions of the text (exp(log(x)) needs x > 0, though GiNaC reads x),
// of the parsed value, of the value in the inputs (a solve's divisors), and those of
// every derived quantity it uses (a divisor that cancels once the quantity is put in, as
// T g with T = 2 w/g, is still a divisor of T), also one the text uses and GiNaC cancelled
// (x*T/T).
std::vector<condition> deriver::needs_of(const GiNaC::ex& value, const written_form* written) const
{
    std::vector<condition> needs;
    if (written)
        add_conditions(needs, in_inputs(definedness(*written, out_.symbols)));
    add_conditions(needs, in_inputs(definedness(value, out_.symbols)));
    add_conditions(needs, definedness(resolve(value), out_.symbols));
    // Put in again: a quantity a later step derives may stand in them (M = m).
    for (const std::vector<condition>* more :
         needs_where([&](const GiNaC::ex& symbol) { return value.has(symbol) || (written && written->mentions(symbol)); }))
        add_conditions(needs, in_inputs(*more));
    return needs;
}

// What a claim needs, `written` as the file writes it and `sides` as parsed: the conditions
// of its text, of its sides and of the derived quantities they use, the left side's also at
// the inputs `left_at` changes it to, all at the special values `at`; and those of `lhs` and
// `rhs`, the sides as proven.
std::vector<condition> deriver::needs_of_claim(const written_form& written, const claim_sides& sides,
                                               const GiNaC::exmap& left_at, const GiNaC::exmap& at,
                                               const GiNaC::ex& lhs, const GiNaC::ex& rhs) const
{
    std::vector<condition> as_written = in_inputs(definedness(written, out_.symbols));
    for (const GiNaC::ex& side : {sides.lhs, sides.rhs}) {
        add_conditions(as_written, in_inputs(definedness(side, out_.symbols)));
        for (const std::vector<condition>* more : needs_where([&](const GiNaC::ex& symbol) { return side.has(symbol); }))
            add_conditions(as_written, in_inputs(*more));
    }
    // A quantity the text uses, though GiNaC cancelled it (x*D/D is x), is needed too.
    for (const std::vector<condition>* more :
         needs_where([&](const GiNaC::ex& symbol) { return written.mentions(symbol); }))
        add_conditions(as_written, in_inputs(*more));
    std::vector<condition> needs = as_written;
    if (!left_at.empty())
        add_conditions(needs, rewritten(
                                  as_written,
                                  [&](const GiNaC::ex& e) { return e.subs(left_at, GiNaC::subs_options::no_pattern); },
                                  out_.symbols));
    if (!at.empty())
        needs = rewritten(needs, [&](const GiNaC::ex& e) { return e.subs(at); }, out_.symbols);
    add_conditions(needs, definedness(lhs, out_.symbols));
    add_conditions(needs, definedness(rhs, out_.symbols));
    return needs;
}

} // namespace impact::engine::detail
