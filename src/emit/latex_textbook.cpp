// An intermediate result as a textbook shows it. GiNaC brings a value over one denominator
// with its numerator expanded (E'_K as a six-term sum); a reader follows the same value
// factored, or collected in one quantity with each coefficient factored:
// ((M v_M + m v_m)^2 + M m (v_M - v_m)^2 eps^2)/(2 (M + m)). Of these, the shortest to
// print is shown, and only when it is clearly shorter than the value as it is; the form
// shown is proven equal to the value here (a rational function normalised to zero), and
// the caller says which it is. A square root's argument is treated the same way.
#include "emit/latex.h"
#include "emit/latex_parts.h"
#include "engine/polynomial.h"

#include <algorithm>
#include <set>

namespace impact::emit::detail {
namespace {

void gather_symbols(const GiNaC::ex& e, std::vector<GiNaC::ex>& out)
{
    if (GiNaC::is_a<GiNaC::symbol>(e)) {
        if (std::none_of(out.begin(), out.end(), [&](const GiNaC::ex& s) { return s.is_equal(e); }))
            out.push_back(e);
        return;
    }
    for (std::size_t i = 0; i < e.nops(); ++i)
        gather_symbols(e.op(i), out);
}

bool is_polynomial_in(const GiNaC::ex& e, const std::vector<GiNaC::ex>& symbols)
{
    GiNaC::lst vars;
    for (const GiNaC::ex& s : symbols)
        vars.append(s);
    return e.is_polynomial(vars);
}

double width(const GiNaC::ex& e, const term_order& order)
{
    return latex_width(latex(e, order));
}

// A polynomial factored, each factor a flat sum whose first term in `order` is positive
// (GiNaC nests a factor, and gives it either sign, differently between runs; the sign is
// carried outside), so that a form, and its width, is the same on every run.
GiNaC::ex factored(const GiNaC::ex& p, const term_order& order)
{
    const GiNaC::ex f = engine::factor_reproducibly(p, GiNaC::factor_options::all);
    const GiNaC::ex factors = GiNaC::is_a<GiNaC::mul>(f) ? f : GiNaC::ex(GiNaC::lst{f});
    GiNaC::ex out = 1;
    bool flip = false;
    for (std::size_t i = 0; i < factors.nops(); ++i) {
        GiNaC::ex x = factors.op(i);
        const bool power = GiNaC::is_a<GiNaC::power>(x) && GiNaC::is_a<GiNaC::numeric>(x.op(1)) &&
                           GiNaC::ex_to<GiNaC::numeric>(x.op(1)).is_integer();
        // An irreducible factor as a flat sum: GiNaC nests it by its order of symbols.
        const GiNaC::ex base = GiNaC::expand(power ? x.op(0) : x);
        if (GiNaC::is_a<GiNaC::add>(base))
            x = power ? GiNaC::pow(base, x.op(1)) : base;
        if (GiNaC::is_a<GiNaC::add>(base)) {
            const std::vector<GiNaC::ex> terms = order.terms(base);
            if (!terms.empty() && order.negative(terms.front())) {
                x = power ? GiNaC::pow(-base, x.op(1)) : -base;
                // (-b)^n = (-1)^n b^n: an odd power carries the sign out.
                if (!power || GiNaC::ex_to<GiNaC::numeric>(x.op(1)).is_odd())
                    flip = !flip;
            }
        }
        out *= x;
    }
    return flip ? -out : out;
}

} // namespace

textbook_value textbook_form(const GiNaC::ex& e, const term_order& order)
{
    // A square root, or one over a square root: its argument as a textbook writes it.
    if (GiNaC::is_a<GiNaC::power>(e) &&
        (e.op(1).is_equal(GiNaC::numeric(1, 2)) || e.op(1).is_equal(GiNaC::numeric(-1, 2)))) {
        const textbook_value inner = textbook_form(e.op(0), order);
        if (inner.how.empty())
            return {e, ""};
        return {GiNaC::pow(inner.value, e.op(1)), "with the argument of the root " + inner.how};
    }
    // Square roots inside (|v'_1| over a sum, a quotient): each argument rewritten alone.
    // (A root under a fraction bar is a power -1/2: cos(theta) inside arccos.)
    if (!GiNaC::is_a<GiNaC::power>(e) && (e.has(GiNaC::pow(GiNaC::wild(0), GiNaC::numeric(1, 2))) ||
                                          e.has(GiNaC::pow(GiNaC::wild(0), GiNaC::numeric(-1, 2))))) {
        struct roots : GiNaC::map_function {
            const term_order& order;
            std::string how;
            explicit roots(const term_order& o) : order(o) {}
            GiNaC::ex operator()(const GiNaC::ex& x) override
            {
                if (GiNaC::is_a<GiNaC::power>(x) &&
                    (x.op(1).is_equal(GiNaC::numeric(1, 2)) || x.op(1).is_equal(GiNaC::numeric(-1, 2)))) {
                    const textbook_value inner = textbook_form(x.op(0), order);
                    if (inner.how.empty())
                        return x;
                    how = "with the argument of the root " + inner.how;
                    return GiNaC::pow(inner.value, x.op(1));
                }
                return x.map(*this);
            }
        } rewrite(order);
        const GiNaC::ex rewritten = e.map(rewrite);
        return {rewritten, rewrite.how};
    }
    try {
        const GiNaC::ex nd = GiNaC::numer_denom(GiNaC::normal(e));
        const GiNaC::ex numerator = nd.op(0).expand(), denominator = nd.op(1);
        std::vector<GiNaC::ex> symbols;
        gather_symbols(numerator, symbols);
        gather_symbols(denominator, symbols);
        if (!GiNaC::is_a<GiNaC::add>(numerator) || numerator.nops() < 3 || numerator.nops() > 40 ||
            !is_polynomial_in(numerator, symbols) || !is_polynomial_in(denominator, symbols))
            return {e, ""};
        // Candidates in a fixed order (their LaTeX), so that the choice is the same on every run.
        std::sort(symbols.begin(), symbols.end(), [&](const GiNaC::ex& a, const GiNaC::ex& b) {
            return latex(a, order) < latex(b, order);
        });
        const GiNaC::ex under = factored(denominator, order);
        textbook_value best{e, ""};
        double best_width = 0.85 * width(e, order);
        const GiNaC::ex whole = factored(numerator, order) / under;
        if (const double w = width(whole, order); w < best_width) {
            best = {whole, "factored"};
            best_width = w;
        }
        for (const GiNaC::ex& s : symbols) {
            const int degree = numerator.degree(s);
            if (degree < 1)
                continue;
            GiNaC::ex sum = 0;
            for (int k = degree; k >= 0; --k)
                sum += factored(numerator.coeff(s, k), order) * GiNaC::pow(s, k);
            const GiNaC::ex candidate = sum / under;
            if (const double w = width(candidate, order); w < best_width) {
                best = {candidate, "collected in $" + latex(s, order) + "$, each coefficient factored"};
                best_width = w;
            }
        }
        if (!best.how.empty() && !GiNaC::normal(best.value - e).is_zero())
            return {e, ""};
        return best;
    } catch (const std::exception&) {
        return {e, ""};
    }
}

} // namespace impact::emit::detail
