#include "emit/order.h"

#include <fmt/format.h>

#include <algorithm>
#include <sstream>

namespace impact::emit {
namespace {

bool is_negative_number(const GiNaC::ex& e)
{
    return GiNaC::is_a<GiNaC::numeric>(e) && GiNaC::ex_to<GiNaC::numeric>(e).is_negative();
}

// The numeric coefficient of a term of a sum (1 when there is none).
GiNaC::numeric coefficient_of(const GiNaC::ex& term)
{
    if (GiNaC::is_a<GiNaC::numeric>(term))
        return GiNaC::ex_to<GiNaC::numeric>(term);
    if (GiNaC::is_a<GiNaC::mul>(term)) {
        GiNaC::numeric c = 1;
        for (std::size_t i = 0; i < term.nops(); ++i)
            if (GiNaC::is_a<GiNaC::numeric>(term.op(i)))
                c *= GiNaC::ex_to<GiNaC::numeric>(term.op(i));
        return c;
    }
    return 1;
}

std::string number_text(const GiNaC::numeric& n)
{
    std::ostringstream out;
    out << n;
    return out.str();
}

// -sum, negating each term so that products inside it are not multiplied out.
GiNaC::ex negate_terms(const GiNaC::ex& sum)
{
    GiNaC::exvector negated;
    for (std::size_t i = 0; i < sum.nops(); ++i)
        negated.push_back(-sum.op(i));
    return GiNaC::add(negated);
}

} // namespace

term_order::term_order(std::vector<GiNaC::ex> symbols) : symbols_(std::move(symbols)) {}

std::string term_order::key(const GiNaC::ex& e) const
{
    // Numbers sort first ('a'), then symbols by rank ('b'), then compound expressions
    // by the keys of their parts ('c'); a power follows its base.
    if (GiNaC::is_a<GiNaC::numeric>(e))
        return "a" + number_text(GiNaC::abs(GiNaC::ex_to<GiNaC::numeric>(e)));
    if (GiNaC::is_a<GiNaC::symbol>(e)) {
        for (std::size_t i = 0; i < symbols_.size(); ++i)
            if (symbols_[i].is_equal(e))
                return fmt::format("b{:04d}", i);
        return "b9999" + GiNaC::ex_to<GiNaC::symbol>(e).get_name();
    }
    if (GiNaC::is_a<GiNaC::power>(e))
        return key(e.op(0)) + "^" + key(e.op(1));
    std::vector<std::string> parts;
    for (std::size_t i = 0; i < e.nops(); ++i) {
        const GiNaC::ex& part = e.op(i);
        if (GiNaC::is_a<GiNaC::mul>(e) && GiNaC::is_a<GiNaC::numeric>(part))
            continue;
        // In a product, the denominator sorts after the numerator: v_M - J/M, not -J/M + v_M.
        const bool divides = GiNaC::is_a<GiNaC::mul>(e) && GiNaC::is_a<GiNaC::power>(part) &&
                             GiNaC::is_a<GiNaC::numeric>(part.op(1)) &&
                             GiNaC::ex_to<GiNaC::numeric>(part.op(1)).is_negative();
        parts.push_back((divides ? "~" : "") + key(part));
    }
    std::sort(parts.begin(), parts.end());
    std::string name = GiNaC::is_a<GiNaC::function>(e) ? GiNaC::ex_to<GiNaC::function>(e).get_name() : "";
    if (GiNaC::is_a<GiNaC::mul>(e))
        return fmt::format("{}", fmt::join(parts, ""));
    return fmt::format("c{}({})", name, fmt::join(parts, ","));
}

std::vector<GiNaC::ex> term_order::terms(const GiNaC::ex& sum) const
{
    // A positive constant leads (1 - eps^2), a negative one trails (eps^2 - 1).
    std::vector<std::pair<std::string, GiNaC::ex>> keyed;
    for (std::size_t i = 0; i < sum.nops(); ++i) {
        const GiNaC::ex& term = sum.op(i);
        keyed.emplace_back(is_negative_number(term) ? "~" : key(term), term);
    }
    std::stable_sort(keyed.begin(), keyed.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<GiNaC::ex> ordered;
    for (auto& [k, term] : keyed)
        ordered.push_back(term);
    return ordered;
}

bool term_order::leads_negative(const GiNaC::ex& sum) const
{
    const auto ordered = terms(sum);
    return !ordered.empty() && coefficient_of(ordered.front()).is_negative();
}

bool term_order::negative(const GiNaC::ex& term) const
{
    if (GiNaC::is_a<GiNaC::numeric>(term))
        return GiNaC::ex_to<GiNaC::numeric>(term).is_negative();
    if (GiNaC::is_a<GiNaC::mul>(term)) {
        bool negated = false;
        factors(term, negated);
        return negated;
    }
    return false;
}

std::vector<GiNaC::ex> term_order::factors(const GiNaC::ex& product, bool& negated) const
{
    negated = false;
    std::vector<GiNaC::ex> items;
    for (std::size_t i = 0; i < product.nops(); ++i) {
        GiNaC::ex factor = product.op(i);
        // A sum to an odd integer power whose first term is negative: (-x + y)^k = -(x - y)^k.
        const bool is_sum = GiNaC::is_a<GiNaC::add>(factor);
        const bool is_odd_power_of_sum = GiNaC::is_a<GiNaC::power>(factor) && GiNaC::is_a<GiNaC::add>(factor.op(0)) &&
                                         factor.op(1).info(GiNaC::info_flags::odd);
        if (is_sum && leads_negative(factor)) {
            factor = negate_terms(factor);
            negated = !negated;
        } else if (is_odd_power_of_sum && leads_negative(factor.op(0))) {
            factor = GiNaC::pow(negate_terms(factor.op(0)), factor.op(1));
            negated = !negated;
        }
        if (is_negative_number(factor)) {
            factor = -factor;
            negated = !negated;
        }
        items.push_back(factor);
    }
    std::stable_sort(items.begin(), items.end(),
                     [this](const GiNaC::ex& a, const GiNaC::ex& b) { return key(a) < key(b); });
    return items;
}

term_order::fraction term_order::split(const GiNaC::ex& product) const
{
    fraction f;
    for (const GiNaC::ex& factor : factors(product, f.negated)) {
        if (GiNaC::is_a<GiNaC::numeric>(factor)) {
            const GiNaC::numeric n = GiNaC::ex_to<GiNaC::numeric>(factor);
            if (!n.is_rational())
                throw std::invalid_argument("cannot print an inexact coefficient exactly");
            if (n.numer() != 1)
                f.numerator.push_back(n.numer());
            if (n.denom() != 1)
                f.denominator.push_back(n.denom());
        } else if (GiNaC::is_a<GiNaC::power>(factor) && GiNaC::is_a<GiNaC::numeric>(factor.op(1)) &&
                   GiNaC::ex_to<GiNaC::numeric>(factor.op(1)).is_negative()) {
            f.denominator.push_back(GiNaC::pow(factor.op(0), -factor.op(1)));
        } else {
            f.numerator.push_back(factor);
        }
    }
    return f;
}

term_order declaration_order(const engine::derivation& d)
{
    std::vector<GiNaC::ex> symbols;
    for (const engine::quantity& q : d.symbols.all())
        symbols.push_back(q.symbol);
    return term_order(std::move(symbols));
}

} // namespace impact::emit
