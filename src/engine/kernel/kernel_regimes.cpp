// A kernel's `[[kernel.regime]]`s: the quantity an input is set to make take a value (a
// boundary approached, or a ratio), written in the kernel's inputs as offsets plus slopes
// times the input's components, its dimensions checked.
#include "engine/kernel/kernel_builder.h"

#include "engine/expr/dimensional.h"

#include <fmt/format.h>

#include <algorithm>
#include <string>
#include <vector>

namespace impact::engine {

// `[[kernel.regime]]`: the quantity that the input `set` makes take its value, written
// in the kernel's inputs as offsets + slopes times the input's components (the input
// must enter it so). A vector quantity is written "[A_x, A_y, A_z]"; its length is set.
sampling_regime kernel_builder::make_regime(const kernel& k, const spec::sampling_regime& r)
{
    sampling_regime regime;
    regime.name = r.name.value;
    regime.where = r.name.where;
    regime.start = r.start ? r.start->value : "";
    const kernel_parameter* p = find_parameter(k, r.set);
    if (std::any_of(p->components.begin(), p->components.end(),
                    [](const quantity& c) { return c.range.what == domain::kind::interval; }))
        throw error(r.set.where, fmt::format("regime '{}' sets '{}': give a scalar input of the real line or "
                                             "the positive numbers (an interval's ends have regimes of "
                                             "their own), or a vector",
                                             regime.name, r.set.value));
    if (p->is_array && r.boundary)
        throw error(r.set.where, fmt::format("regime '{}' sets the vector '{}': a boundary is approached by "
                                             "setting one scalar input; a vector input is set by a ratio "
                                             "(ratio = [\"[A_x, A_y, A_z]\", \"B\"])",
                                             regime.name, r.set.value));
    for (const quantity& c : p->components)
        regime.inputs.push_back(c.symbol);
    auto same_dimension = [&](const GiNaC::ex& a, const GiNaC::ex& b, const spec::text& where) {
        const auto da = check_expression(d_.symbols, a, where.where);
        const auto db = check_expression(d_.symbols, b, where.where);
        if (da && db && *da != *db)
            throw error(where.where, fmt::format("regime '{}': {} is {}, {} is {}", regime.name,
                                                 d_.symbols.text(a), da->describe(), d_.symbols.text(b),
                                                 db->describe()));
    };
    std::vector<GiNaC::ex> quantities;
    const spec::text& written = r.boundary ? *r.boundary : r.ratio.front();
    if (r.boundary) {
        const claim_sides sides = d_.symbols.parse_claim(*r.boundary);
        if (sides.op != relation::equal)
            throw error(r.boundary->where, "a regime's boundary reads 'lhs = rhs'");
        same_dimension(sides.lhs, sides.rhs, *r.boundary);
        regime.what = sampling_regime::kind::boundary;
        quantities.push_back(in_kernel(sides.lhs - sides.rhs));
        regime.to = r.within;
    } else {
        const GiNaC::ex b = d_.symbols.parse(r.ratio[1]);
        for (const spec::text& component : vector_components(r.ratio[0])) {
            const GiNaC::ex a = d_.symbols.parse(component);
            same_dimension(a, b, r.ratio[1]);
            quantities.push_back(in_kernel(a));
        }
        regime.denominator = in_kernel(b);
        require_inputs(k, regime.denominator, regime.name, r.ratio[1].where, "regime");
        for (const GiNaC::ex& input : regime.inputs)
            if (regime.denominator.has(input))
                throw error(r.ratio[1].where, fmt::format("regime '{}': '{}' depends on '{}', which the regime sets",
                                                          regime.name, r.ratio[1].value, r.set.value));
        regime.from = r.from;
        regime.to = r.to;
    }
    GiNaC::exmap at_zero;
    for (const GiNaC::ex& input : regime.inputs)
        at_zero[input] = 0;
    bool moves = false;
    for (const GiNaC::ex& quantity : quantities) {
        require_inputs(k, quantity, regime.name, written.where, "regime");
        for (const GiNaC::ex& input : regime.inputs) {
            const GiNaC::ex slope = quantity.diff(GiNaC::ex_to<GiNaC::symbol>(input));
            bool constant = true;
            for (const GiNaC::ex& other : regime.inputs)
                constant = constant && !slope.has(other);
            if (!constant)
                throw error(written.where, fmt::format("regime '{}': '{}' must enter '{}' as a multiple of it "
                                                       "plus what does not depend on it, so that one value of "
                                                       "it gives the quantity its value",
                                                       regime.name, r.set.value, written.value));
            moves = moves || !slope.is_zero();
            regime.slopes.push_back(slope);
        }
        regime.offsets.push_back(quantity.subs(at_zero, GiNaC::subs_options::no_pattern));
    }
    if (!moves)
        throw error(written.where, fmt::format("regime '{}': '{}' does not depend on '{}', which the regime sets",
                                               regime.name, written.value, r.set.value));
    return regime;
}

// The components of a regime's quantity: "[a, b, c]" (commas between brackets and
// parentheses left alone), or the one expression written.
std::vector<spec::text> kernel_builder::vector_components(const spec::text& written)
{
    const std::string& s = written.value;
    const std::size_t open = s.find_first_not_of(' ');
    const std::size_t close = s.find_last_not_of(' ');
    if (open == std::string::npos || s[open] != '[' || s[close] != ']')
        return {written};
    std::vector<spec::text> parts;
    int depth = 0;
    std::size_t start = open + 1;
    for (std::size_t i = open + 1; i <= close; ++i) {
        const char c = s[i];
        if (i == close && depth != 0)
            throw error(written.where, fmt::format("'{}' has unbalanced brackets", s));
        if (c == '(' || c == '[')
            ++depth;
        else if ((c == ')' || c == ']') && depth > 0)
            --depth;
        else if ((c == ',' && depth == 0) || i == close) {
            spec::text part = written;
            part.value = s.substr(start, i - start);
            if (part.value.find_first_not_of(' ') == std::string::npos)
                throw error(written.where, fmt::format("'{}' has an empty component", s));
            parts.push_back(std::move(part));
            start = i + 1;
        }
    }
    return parts;
}

} // namespace impact::engine
