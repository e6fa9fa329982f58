// Where a printed member of a line differs from another member of the same line (reconcile.h,
// locate_by_member): the factors of both, as written, matched in order, and the one run that
// differs named.
#include "engine/paper/reconcile.h"

#include "engine/prove/prove.h"

#include <optional>
#include <string>
#include <vector>

namespace impact::engine {
namespace {

// The value of a written node; nothing for a call it does not know.
std::optional<GiNaC::ex> value_of(const written_form::node& n)
{
    using kind = written_form::node::kind;
    std::vector<GiNaC::ex> parts;
    for (const written_form::node& child : n.children) {
        const auto v = value_of(child);
        if (!v)
            return std::nullopt;
        parts.push_back(*v);
    }
    switch (n.what) {
    case kind::atom: return n.value;
    case kind::group: return parts.at(0);
    case kind::negate: return -parts.at(0);
    case kind::power: return GiNaC::ex(GiNaC::power(parts.at(0), parts.at(1)));  // as in replace_at
    case kind::sum: {
        GiNaC::ex sum = 0;
        for (std::size_t i = 0; i < parts.size(); ++i)
            sum += i < n.flags.size() && n.flags[i] ? -parts[i] : parts[i];
        return sum;
    }
    case kind::product: {
        GiNaC::ex product = 1;
        for (std::size_t i = 0; i < parts.size(); ++i)
            product *= i < n.flags.size() && n.flags[i] ? 1 / parts[i] : parts[i];
        return product;
    }
    case kind::call:
        if (parts.size() == 1 && n.name == "sqrt")
            return GiNaC::sqrt(parts[0]);
        if (parts.size() == 1 && n.name == "abs")
            return GiNaC::abs(parts[0]);
        return std::nullopt;
    case kind::relation: return std::nullopt;
    }
    return std::nullopt;
}

struct written_factor {
    GiNaC::ex value;
    bool divides;
};

// The factors of a written product, products within parentheses opened, each with whether
// it divides.
bool flatten(const written_form::node& n, bool divides, std::vector<written_factor>& out)
{
    using kind = written_form::node::kind;
    if (n.what == kind::group)
        return flatten(n.children.at(0), divides, out);
    if (n.what == kind::product) {
        for (std::size_t i = 0; i < n.children.size(); ++i)
            if (!flatten(n.children[i], divides != (i < n.flags.size() && n.flags[i]), out))
                return false;
        return true;
    }
    const auto v = value_of(n);
    if (!v)
        return false;
    out.push_back({*v, divides});
    return true;
}

// Every way of cutting `n` factors into `k` runs, each run at least one factor: the ends
// of the runs.
void cuts(std::size_t n, std::size_t k, std::vector<std::size_t>& ends, std::vector<std::vector<std::size_t>>& out)
{
    const std::size_t from = ends.empty() ? 0 : ends.back();
    if (ends.size() + 1 == k) {
        if (from < n) {
            ends.push_back(n);
            out.push_back(ends);
            ends.pop_back();
        }
        return;
    }
    for (std::size_t end = from + 1; end + (k - ends.size() - 1) <= n; ++end) {
        ends.push_back(end);
        cuts(n, k, ends, out);
        ends.pop_back();
    }
}

const char* ordinal(std::size_t i)
{
    static const char* const names[] = {"first", "second", "third", "fourth", "fifth", "sixth"};
    return i < 6 ? names[i] : "next";
}

} // namespace

std::optional<finding> locate_by_member(const written_form::node& printed, const written_form::node& other,
                                        const GiNaC::ex& derived, const symbol_table& symbols,
                                        const resolver& resolve, proof_cache& run)
{
    try {
        std::vector<written_factor> p, q;
        if (!flatten(printed, false, p) || !flatten(other, false, q))
            return std::nullopt;
        // Numerator and denominator apart, each in written order.
        struct side {
            std::vector<GiNaC::ex> printed, other;
        } sides[2];
        for (const written_factor& f : p)
            sides[f.divides].printed.push_back(f.value);
        for (const written_factor& f : q)
            sides[f.divides].other.push_back(f.value);
        if (q.size() < 2 || sides[0].other.empty())
            return std::nullopt;
        auto equal = [&](const GiNaC::ex& a, const GiNaC::ex& b) {
            return prove_equal(resolve(a), resolve(b), symbols, run).what == verdict::status::proven;
        };
        // The one run of one side that differs, in the best cutting of each side.
        struct differing {
            bool divides;
            std::size_t index;   ///< which factor of the other member
            GiNaC::ex printed, other;
        };
        std::vector<differing> found;
        for (int d = 0; d < 2; ++d) {
            const side& s = sides[d];
            if (s.other.empty() && s.printed.empty())
                continue;
            if (s.other.empty() || s.printed.size() < s.other.size())
                return std::nullopt;
            std::vector<std::vector<std::size_t>> all;
            std::vector<std::size_t> ends;
            cuts(s.printed.size(), s.other.size(), ends, all);
            std::optional<std::vector<differing>> best;
            for (const std::vector<std::size_t>& cut : all) {
                std::vector<differing> here;
                for (std::size_t i = 0, begin = 0; i < cut.size(); begin = cut[i], ++i) {
                    GiNaC::ex run_value = 1;
                    for (std::size_t j = begin; j < cut[i]; ++j)
                        run_value *= s.printed[j];
                    if (!equal(run_value, s.other[i]))
                        here.push_back({d == 1, i, run_value, s.other[i]});
                    if (best && here.size() >= best->size())
                        break;
                }
                if (!best || here.size() < best->size())
                    best = here;
            }
            if (!best)
                return std::nullopt;
            found.insert(found.end(), best->begin(), best->end());
        }
        if (found.size() != 1)
            return std::nullopt;
        const differing& at = found.front();
        // The printed form with the other member's factor in place of the run reconciles?
        const GiNaC::ex printed_value = *value_of(printed);
        const GiNaC::ex edited = at.divides ? printed_value * at.printed / at.other
                                            : printed_value / at.printed * at.other;
        if (prove_equal(resolve(edited), derived, symbols, run).what != verdict::status::proven)
            return std::nullopt;
        finding f;
        f.say(std::string("the ") + ordinal(at.index) + " factor of the " +
              (at.divides ? "denominator" : "numerator") + ", ")
            .math(at.printed)
            .say(", where ")
            .math(at.other);
        if (!resolve(at.other).is_equal(at.other))
            return f.say(", that is ").math(resolve(at.other)).say(", belongs");
        return f.say(" belongs");
    } catch (const error&) {
        throw;
    } catch (const std::exception&) {
        return std::nullopt;
    }
}

} // namespace impact::engine
