#include "engine/expr/derivative.h"

#include <sstream>
#include <stdexcept>

namespace impact::engine {
namespace {

// Printed as a file writes it: diff(f,x). The emitters typeset it (emit/latex.cpp).
void print_diff(const GiNaC::ex& f, const GiNaC::ex& x, const GiNaC::print_context& c)
{
    c.s << "diff(";
    f.print(c);
    c.s << ",";
    x.print(c);
    c.s << ")";
}

// Registered under the name the files use, so that GiNaC's parser reads diff(f, x) and a
// derivation kept between runs (engine/store/stored.h) reads it back. No eval function: held.
const unsigned derivative_serial =
    GiNaC::function::register_new(GiNaC::function_options("diff", 2).print_func<GiNaC::print_context>(print_diff));

struct taking : GiNaC::map_function {
    GiNaC::ex operator()(const GiNaC::ex& e) override
    {
        if (!has_derivative(e))
            return e;
        if (!is_derivative(e))
            return e.map(*this);
        const GiNaC::ex f = (*this)(e.op(0));
        if (!GiNaC::is_a<GiNaC::symbol>(e.op(1))) {
            std::ostringstream variable;
            variable << e.op(1);
            throw std::invalid_argument("diff(f, x) differentiates with respect to an input quantity, not " +
                                        variable.str());
        }
        return f.diff(GiNaC::ex_to<GiNaC::symbol>(e.op(1)));
    }
};

} // namespace

GiNaC::ex derivative(const GiNaC::ex& f, const GiNaC::ex& x)
{
    return GiNaC::function(derivative_serial, f, x).hold();
}

bool is_derivative(const GiNaC::ex& e)
{
    return GiNaC::is_exactly_a<GiNaC::function>(e) && GiNaC::ex_to<GiNaC::function>(e).get_serial() == derivative_serial;
}

bool has_derivative(const GiNaC::ex& e)
{
    if (is_derivative(e))
        return true;
    for (std::size_t i = 0; i < e.nops(); ++i)
        if (has_derivative(e.op(i)))
            return true;
    return false;
}

GiNaC::ex derivatives_taken(const GiNaC::ex& e)
{
    taking take;
    return take(e);
}

} // namespace impact::engine
