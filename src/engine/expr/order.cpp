#include "engine/expr/order.h"

#include "engine/expr/infix.h"

#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <sstream>

namespace impact::engine {
namespace {

bool is_negative_number(const GiNaC::ex& e)
{
    return GiNaC::is_a<GiNaC::numeric>(e) && GiNaC::ex_to<GiNaC::numeric>(e).is_negative();
}

std::string number_text(const GiNaC::numeric& n)
{
    std::ostringstream out;
    out << n;
    return out.str();
}

} // namespace

term_order::term_order(std::vector<GiNaC::ex> symbols) : symbols_(std::move(symbols)) {}

GiNaC::ex term_order::negated_sum(const GiNaC::ex& sum)
{
    GiNaC::exvector negated;
    for (std::size_t i = 0; i < sum.nops(); ++i)
        negated.push_back(-sum.op(i));
    return GiNaC::add(negated);
}

std::string term_order::key(const power_term& p) const
{
    return p.exponent.is_equal(1) ? key(p.base) : key(p.base) + "^" + key(p.exponent);
}

bool term_order::before(const GiNaC::ex& a, const GiNaC::ex& b) const
{
    const std::string& ka = key(a);
    const std::string& kb = key(b);
    if (ka != kb)
        return ka < kb;
    return text(a) < text(b);
}

const std::string& term_order::key(const GiNaC::ex& e) const
{
    const auto known = memo_->keys.find(e);
    if (known != memo_->keys.end())
        return known->second;
    std::string k = compute_key(e);
    return memo_->keys.emplace(e, std::move(k)).first->second;
}

const std::string& term_order::text(const GiNaC::ex& e) const
{
    const auto known = memo_->texts.find(e);
    if (known != memo_->texts.end())
        return known->second;
    std::ostringstream out;
    print_expression(e, print_ginac_syntax(out, *this));
    return memo_->texts.emplace(e, out.str()).first->second;
}

std::string term_order::compute_key(const GiNaC::ex& e) const
{
    // Numbers sort first ('a'), then symbols by rank ('b'), then compound expressions
    // by the keys of their parts ('c'); a power follows its base. Keys are taken of
    // oriented factors, so that -(x - y) and (y - x) get the same key however GiNaC
    // happens to store them.
    if (GiNaC::is_a<GiNaC::numeric>(e))
        return "a" + number_text(GiNaC::abs(GiNaC::ex_to<GiNaC::numeric>(e)));
    if (GiNaC::is_a<GiNaC::symbol>(e)) {
        for (std::size_t i = 0; i < symbols_.size(); ++i)
            if (symbols_[i].is_equal(e))
                return fmt::format("b{:04d}", i);
        return "b9999" + GiNaC::ex_to<GiNaC::symbol>(e).get_name();
    }
    bool negated = false;
    if (GiNaC::is_a<GiNaC::power>(e))
        return key(oriented(e, negated));
    std::vector<std::string> parts;
    if (GiNaC::is_a<GiNaC::mul>(e)) {
        for (const power_term& factor : factors(e, negated)) {
            if (GiNaC::is_a<GiNaC::numeric>(factor.base) && factor.exponent.is_equal(1))
                continue;
            // The denominator sorts after the numerator: v_M - J/M, not -J/M + v_M.
            const bool divides = GiNaC::is_a<GiNaC::numeric>(factor.exponent) &&
                                 GiNaC::ex_to<GiNaC::numeric>(factor.exponent).is_negative();
            parts.push_back((divides ? "~" : "") + key(factor));
        }
        std::sort(parts.begin(), parts.end());
        return fmt::format("{}", fmt::join(parts, ""));
    }
    for (std::size_t i = 0; i < e.nops(); ++i) {
        const GiNaC::ex part = e.op(i);
        // In a sum, the sign of a term is part of its key: 1 - eps and 1 + eps differ.
        const char* sign = GiNaC::is_a<GiNaC::add>(e) ? (negative(part) ? "-" : "+") : "";
        parts.push_back(sign + key(part));
    }
    std::sort(parts.begin(), parts.end());
    const std::string name = GiNaC::is_a<GiNaC::function>(e) ? GiNaC::ex_to<GiNaC::function>(e).get_name() : "";
    return fmt::format("c{}({})", name, fmt::join(parts, ","));
}

std::vector<GiNaC::ex> term_order::terms(const GiNaC::ex& sum) const
{
    // A positive constant leads (1 - eps^2), a negative one trails (eps^2 - 1); the
    // rest in the order of `before` (each key looked up once).
    struct ranked {
        int rank;
        const std::string* key;
        GiNaC::ex term;
    };
    std::vector<ranked> items;
    for (const GiNaC::ex& term : sum)
        items.push_back({is_negative_number(term) ? 1 : 0, &key(term), term});
    std::sort(items.begin(), items.end(), [&](const ranked& a, const ranked& b) {
        if (a.rank != b.rank)
            return a.rank < b.rank;
        if (*a.key != *b.key)
            return *a.key < *b.key;
        return text(a.term) < text(b.term);
    });
    std::vector<GiNaC::ex> ordered;
    for (const ranked& item : items)
        ordered.push_back(item.term);
    return ordered;
}

bool term_order::leads_negative(const GiNaC::ex& sum) const
{
    // A sum with a constant keeps the constant positive (1 - eps, not -(eps - 1));
    // otherwise its first term decides. S and -S never both count as leading positive.
    std::optional<GiNaC::ex> lead;
    for (std::size_t i = 0; i < sum.nops(); ++i) {
        const GiNaC::ex term = sum.op(i);
        if (GiNaC::is_a<GiNaC::numeric>(term))
            return GiNaC::ex_to<GiNaC::numeric>(term).is_negative();
        if (!lead || before(term, *lead))
            lead = term;
    }
    return lead ? negative(*lead) : false;
}

term_order::power_term term_order::oriented(const GiNaC::ex& factor, bool& negated) const
{
    if (GiNaC::is_a<GiNaC::add>(factor) && leads_negative(factor)) {
        negated = !negated;
        return {negated_sum(factor), 1};
    }
    if (is_negative_number(factor)) {
        negated = !negated;
        return {-factor, 1};
    }
    if (!GiNaC::is_a<GiNaC::power>(factor))
        return {factor, 1};
    // (-x + y)^k = (x - y)^k for even k, -(x - y)^k for odd k.
    const GiNaC::ex base = factor.op(0), exponent = factor.op(1);
    if (GiNaC::is_a<GiNaC::add>(base) && exponent.info(GiNaC::info_flags::integer) && leads_negative(base)) {
        if (exponent.info(GiNaC::info_flags::odd))
            negated = !negated;
        return {negated_sum(base), exponent};
    }
    return {base, exponent};
}

bool term_order::negative(const GiNaC::ex& term) const
{
    if (GiNaC::is_a<GiNaC::numeric>(term))
        return GiNaC::ex_to<GiNaC::numeric>(term).is_negative();
    // The signs `factors` moves out, without ordering the factors.
    bool negated = false;
    if (GiNaC::is_a<GiNaC::mul>(term)) {
        for (std::size_t i = 0; i < term.nops(); ++i)
            oriented(term.op(i), negated);
    } else if (GiNaC::is_a<GiNaC::power>(term)) {
        oriented(term, negated);
    }
    return negated;
}

std::vector<term_order::power_term> term_order::factors(const GiNaC::ex& product, bool& negated) const
{
    negated = false;
    std::vector<power_term> items;
    for (std::size_t i = 0; i < product.nops(); ++i)
        items.push_back(oriented(product.op(i), negated));
    return sorted(std::move(items));
}

// Factors by key, ties broken by the full text of base^exponent.
std::vector<term_order::power_term> term_order::sorted(std::vector<power_term> items) const
{
    struct keyed {
        std::string key;
        power_term factor;
    };
    std::vector<keyed> all;
    for (power_term& item : items)
        all.push_back({key(item), std::move(item)});
    auto full_text = [this](const power_term& p) { return text(p.base) + "^" + text(p.exponent); };
    std::sort(all.begin(), all.end(), [&](const keyed& a, const keyed& b) {
        if (a.key != b.key)
            return a.key < b.key;
        return full_text(a.factor) < full_text(b.factor);
    });
    for (std::size_t i = 0; i < all.size(); ++i)
        items[i] = std::move(all[i].factor);
    return items;
}

term_order::fraction term_order::split(const GiNaC::ex& product) const
{
    fraction f;
    for (const power_term& factor : factors(product, f.negated)) {
        if (GiNaC::is_a<GiNaC::numeric>(factor.base) && factor.exponent.is_equal(1)) {
            const GiNaC::numeric n = GiNaC::ex_to<GiNaC::numeric>(factor.base);
            if (!n.is_rational())
                throw std::invalid_argument("cannot print an inexact coefficient exactly");
            if (n.numer() != 1)
                f.numerator.push_back({n.numer(), 1});
            if (n.denom() != 1)
                f.denominator.push_back({n.denom(), 1});
        } else if (GiNaC::is_a<GiNaC::numeric>(factor.exponent) &&
                   GiNaC::ex_to<GiNaC::numeric>(factor.exponent).is_negative()) {
            f.denominator.push_back({factor.base, -factor.exponent});
        } else {
            f.numerator.push_back(factor);
        }
    }
    return f;
}

term_order declaration_order(const symbol_table& symbols)
{
    return symbols.order();
}

} // namespace impact::engine
