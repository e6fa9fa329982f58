// An intermediate result as a textbook shows it. GiNaC brings a value over one denominator
// with its numerator expanded (E'_K as a six-term sum); a reader follows the same value
// factored, or collected in one quantity with each coefficient factored:
// ((M v_M + m v_m)^2 + M m (v_M - v_m)^2 eps^2)/(2 (M + m)). Of these, the shortest to
// print is shown, and only when it is clearly shorter than the value as it is; the form
// shown is proven equal to the value here (a rational function normalised to zero), and
// the caller says which it is. A square root's argument is treated the same way.
#include "emit/latex.h"
#include "emit/latex_parts.h"
#include "engine/algebra/polynomial.h"
#include "engine/algebra/factor_split.h"

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
// (Found by Gauss's lemma where it decides, engine/algebra/factor_split.h: the same
// factors as GiNaC's factor() finds, at a fraction of its time.)
GiNaC::ex factored(const GiNaC::ex& p, const term_order& order)
{
    const GiNaC::ex f = engine::factor_split(p, GiNaC::factor_options::all);
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

// Roots and absolute values (sqrt(N_x^2 + N_y^2), |g_t|) as symbols of their own, so that
// the value around them is a rational function to factor or collect; `atoms` maps each
// symbol back. A root is a symbol for sqrt(b), raised to the root's integer multiple
// (b^(-1/2) is 1/sqrt(b)); the symbols are numbered by the atoms' text, the same every run.
GiNaC::ex with_atoms(const GiNaC::ex& e, const term_order& order, GiNaC::exmap& atoms)
{
    std::vector<GiNaC::ex> found;
    struct collect : GiNaC::map_function {
        std::vector<GiNaC::ex>& found;
        explicit collect(std::vector<GiNaC::ex>& f) : found(f) {}
        GiNaC::ex operator()(const GiNaC::ex& x) override
        {
            GiNaC::ex atom;
            if (GiNaC::is_a<GiNaC::power>(x) && GiNaC::is_a<GiNaC::numeric>(x.op(1)) &&
                !GiNaC::ex_to<GiNaC::numeric>(x.op(1)).is_integer())
                atom = GiNaC::pow(x.op(0), GiNaC::numeric(1, 2));
            else if (GiNaC::is_a<GiNaC::function>(x))
                atom = x;
            else
                return x.map(*this);
            if (std::none_of(found.begin(), found.end(), [&](const GiNaC::ex& a) { return a.is_equal(atom); }))
                found.push_back(atom);
            return x;
        }
    } gather(found);
    e.map(gather);
    std::sort(found.begin(), found.end(),
              [&](const GiNaC::ex& a, const GiNaC::ex& b) { return order.text(a) < order.text(b); });
    GiNaC::exmap to_symbol;
    for (std::size_t i = 0; i < found.size(); ++i) {
        const GiNaC::symbol s("textbook_atom_" + std::to_string(i), "A_{" + std::to_string(i) + "}");
        atoms[s] = found[i];
        to_symbol[found[i]] = s;
    }
    struct replace : GiNaC::map_function {
        const GiNaC::exmap& to_symbol;
        explicit replace(const GiNaC::exmap& t) : to_symbol(t) {}
        GiNaC::ex operator()(const GiNaC::ex& x) override
        {
            if (GiNaC::is_a<GiNaC::power>(x) && GiNaC::is_a<GiNaC::numeric>(x.op(1)) &&
                !GiNaC::ex_to<GiNaC::numeric>(x.op(1)).is_integer()) {
                const GiNaC::numeric twice = GiNaC::ex_to<GiNaC::numeric>(x.op(1)) * 2;
                const auto s = to_symbol.find(GiNaC::pow(x.op(0), GiNaC::numeric(1, 2)));
                if (twice.is_integer() && s != to_symbol.end())
                    return GiNaC::pow(s->second, twice);
                return x;
            }
            if (GiNaC::is_a<GiNaC::function>(x)) {
                const auto s = to_symbol.find(x);
                return s == to_symbol.end() ? x : s->second;
            }
            return x.map(*this);
        }
    } swap(to_symbol);
    return e.map(swap);
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
    // Square roots and absolute values inside (|v'_1| over a sum, a quotient, a friction
    // ratio over |g_t|): each argument rewritten alone. (A root under a fraction bar is a
    // power -1/2: cos(theta) inside arccos.)
    textbook_value root_args{e, ""};
    if (!GiNaC::is_a<GiNaC::power>(e) && (e.has(GiNaC::pow(GiNaC::wild(0), GiNaC::numeric(1, 2))) ||
                                          e.has(GiNaC::pow(GiNaC::wild(0), GiNaC::numeric(-1, 2))) ||
                                          e.has(GiNaC::abs(GiNaC::wild(0))))) {
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
                if (GiNaC::is_a<GiNaC::function>(x) && GiNaC::ex_to<GiNaC::function>(x).get_name() == "abs") {
                    const textbook_value inner = textbook_form(x.op(0), order);
                    if (inner.how.empty())
                        return x.map(*this);
                    how = "with the argument of the absolute value " + inner.how;
                    return GiNaC::abs(inner.value);
                }
                return x.map(*this);
            }
        } rewrite(order);
        root_args = {e.map(rewrite), rewrite.how};
    }
    try {
        GiNaC::exmap atoms;
        const GiNaC::ex rational = with_atoms(root_args.value, order, atoms);
        const GiNaC::ex nd = GiNaC::numer_denom(GiNaC::normal(rational));
        const GiNaC::ex numerator = nd.op(0).expand(), denominator = nd.op(1);
        std::vector<GiNaC::ex> symbols;
        gather_symbols(numerator, symbols);
        gather_symbols(denominator, symbols);
        if (!GiNaC::is_a<GiNaC::add>(numerator) || numerator.nops() < 3 || numerator.nops() > 40 ||
            !is_polynomial_in(numerator, symbols) || !is_polynomial_in(denominator, symbols))
            return root_args;
        // Candidates in a fixed order (their LaTeX), so that the choice is the same on every run.
        std::sort(symbols.begin(), symbols.end(), [&](const GiNaC::ex& a, const GiNaC::ex& b) {
            return latex(a, order) < latex(b, order);
        });
        const GiNaC::ex under = factored(denominator, order);
        textbook_value best = root_args;
        // Widths with each root or absolute value as one letter: what is saved is in the
        // sum around them, not in an atom the candidates all print alike.
        // A rewriting is worth showing when it is 15% narrower, or, on a long line (over
        // 133 pt), when it saves 20 pt (four letters).
        const double as_given = width(rational, order);
        double best_width = std::max(0.85 * as_given, as_given - 20);
        const GiNaC::ex whole = factored(numerator, order) / under;
        if (const double w = width(whole, order); w < best_width) {
            best = {whole.subs(atoms), "factored"};
            best_width = w;
        }
        for (const GiNaC::ex& s : symbols) {
            if (atoms.count(s))
                continue;
            const int degree = numerator.degree(s);
            if (degree < 1)
                continue;
            GiNaC::ex sum = 0;
            for (int k = degree; k >= 0; --k)
                sum += factored(numerator.coeff(s, k), order) * GiNaC::pow(s, k);
            const GiNaC::ex candidate = sum / under;
            if (const double w = width(candidate, order); w < best_width) {
                best = {candidate.subs(atoms), "collected in $" + latex(s, order) + "$, each coefficient factored"};
                best_width = w;
            }
        }
        // Linear in several quantities, each term having exactly one of them (g'_y: each
        // term one velocity, spin or impulse): collected in all of them at once. The most
        // particular quantities first (those in fewest terms), each one kept that shares
        // no term with those kept before.
        {
            const std::vector<GiNaC::ex> terms(numerator.begin(), numerator.end());
            std::vector<std::pair<std::size_t, GiNaC::ex>> linear;
            for (const GiNaC::ex& s : symbols) {
                if (atoms.count(s))
                    continue;
                std::size_t in = 0;
                bool at_most_once = true;
                for (const GiNaC::ex& t : terms) {
                    const int d = t.degree(s);
                    at_most_once = at_most_once && d <= 1;
                    in += d == 1;
                }
                if (at_most_once && in > 0)
                    linear.emplace_back(in, s);
            }
            std::stable_sort(linear.begin(), linear.end(),
                             [](const auto& a, const auto& b) { return a.first < b.first; });
            std::vector<GiNaC::ex> kept;
            std::vector<int> covered(terms.size(), 0);
            for (const auto& [in, s] : linear) {
                bool shares = false;
                for (std::size_t i = 0; i < terms.size(); ++i)
                    shares = shares || (covered[i] && terms[i].degree(s) == 1);
                if (shares)
                    continue;
                kept.push_back(s);
                for (std::size_t i = 0; i < terms.size(); ++i)
                    covered[i] += terms[i].degree(s) == 1;
            }
            if (kept.size() > 1 && std::all_of(covered.begin(), covered.end(), [](int c) { return c == 1; })) {
                // Quantities with the same coefficient, or its negative, share it:
                // (v_{M,x} - v_{m,x}) once rather than v_{M,x} and v_{m,x} each with it.
                std::vector<std::pair<GiNaC::ex, GiNaC::ex>> groups;   // coefficient, sum of ±quantities
                std::vector<std::string> names;
                for (const GiNaC::ex& s : kept) {
                    const GiNaC::ex c = numerator.coeff(s, 1).expand();
                    auto g = std::find_if(groups.begin(), groups.end(), [&](const auto& x) {
                        return (x.first - c).expand().is_zero() || (x.first + c).expand().is_zero();
                    });
                    if (g == groups.end())
                        groups.emplace_back(c, s);
                    else
                        g->second += (g->first - c).expand().is_zero() ? s : -s;
                    names.push_back("$" + latex(s, order) + "$");
                }
                GiNaC::ex sum = 0;
                for (const auto& [c, quantities] : groups)
                    sum += factored(c, order) * quantities;
                const GiNaC::ex candidate = sum / under;
                if (const double w = width(candidate, order); w < best_width) {
                    best = {candidate.subs(atoms), "collected in " + listing(names) + ", each coefficient factored"};
                    best_width = w;
                }
            }
        }
        // Proven equal: the numerator of the difference expanded to zero (radicals and
        // absolute values as variables of their own), else normalised to zero.
        if (!best.how.empty() && engine::expand_numerator(best.value - root_args.value) != engine::expansion::zero &&
            !GiNaC::normal(best.value - root_args.value).is_zero())
            return root_args;
        return best;
    } catch (const std::exception&) {
        return root_args;
    }
}

} // namespace impact::emit::detail
