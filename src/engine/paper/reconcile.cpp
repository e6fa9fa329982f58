#include "engine/paper/reconcile.h"
#include "engine/paper/edits.h"

#include "engine/expr/order.h"
#include "engine/prove/prove.h"

#include <fmt/format.h>

#include <cln/rational.h>
#include <cln/real.h>

#include <algorithm>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <sstream>

namespace impact::engine {

using namespace reconcile_detail;

namespace {

GiNaC::numeric exact(double value)
{
    return GiNaC::numeric(cln::cl_N(cln::rational(cln::cl_DF(value))));
}

// Two points of the declared domains, to screen candidates before proving them.
std::vector<GiNaC::exmap> screening_points(const symbol_table& symbols)
{
    std::vector<GiNaC::exmap> points(2);
    uniform_stream stream(0x5eed5eedULL);
    for (GiNaC::exmap& point : points)
        for (const quantity& q : symbols.all())
            if (!q.definition)
                point[q.symbol] = exact(draw(q.range, stream));
    return points;
}

std::optional<GiNaC::numeric> value_at(const GiNaC::ex& e, const GiNaC::exmap& point)
{
    try {
        GiNaC::ex v = e.subs(point, GiNaC::subs_options::no_pattern);
        if (!GiNaC::is_a<GiNaC::numeric>(v))
            v = GiNaC::evalf(v);
        if (GiNaC::is_a<GiNaC::numeric>(v))
            return GiNaC::ex_to<GiNaC::numeric>(v);
    } catch (const std::exception&) {
    }
    return std::nullopt;
}

bool close(const GiNaC::numeric& a, const GiNaC::numeric& b)
{
    const double scale = std::max({1e-300, std::abs(a.to_double()), std::abs(b.to_double())});
    return GiNaC::abs(a - b).to_double() <= 1e-12 * scale;
}

std::set<std::string> names_in(const GiNaC::ex& e, const symbol_table& symbols)
{
    std::set<std::string> names;
    for (const quantity& q : symbols.all())
        if (e.has(q.symbol))
            names.insert(q.name);
    return names;
}

// The second edits of an edited form, `first` its first edit.
using extender = std::function<void(const candidate& first, const std::function<void(candidate)>& emit)>;

// At most this many forms of two edits are screened: beyond it the search stops at one
// edit (the printed form is long, and a finding of two edits would be a guess among many).
constexpr std::size_t two_edit_budget = 20000;

finding joined(finding a, const finding& b)
{
    a.say(", and ");
    a.parts.insert(a.parts.end(), b.parts.begin(), b.parts.end());
    return a;
}

template <class Screen, class Confirm>
std::vector<finding> search(std::vector<candidate> all, const symbol_table& symbols, Screen screen, Confirm confirm,
                            const extender& extend)
{
    // The smallest kind of change that works, every edit of that kind that does.
    std::stable_sort(all.begin(), all.end(),
                     [](const candidate& a, const candidate& b) { return a.priority < b.priority; });
    // Sorted and told apart by their text, so that the report is the same on every run.
    std::map<std::string, finding> found;
    // Two edits that make the same form are one change, told in the fewer words ("v'_1 and
    // v'_2 swapped", not also "write v'_1 for v'_2 in v'_2/(v'_1 + v'_2)").
    std::map<std::string, std::string> text_of_form;
    int best = 0;
    for (const candidate& c : all) {
        if (best && c.priority > best)
            break;
        if (screen(c.edited) && confirm(c.edited)) {
            finding change = c.change();
            change.corrected = c.edited;
            std::string text = plain_text(change, symbols);
            std::ostringstream form;
            form << c.edited;
            auto [at, inserted] = text_of_form.try_emplace(form.str(), text);
            if (!inserted) {
                const std::string& kept = at->second;
                if (text.size() > kept.size() || (text.size() == kept.size() && text >= kept))
                    continue;
                found.erase(kept);
                at->second = text;
            }
            found.emplace(std::move(text), std::move(change));
            best = c.priority;
        }
    }
    // No single edit: two, the first of a kind a misprint makes (a sign, a symbol, the
    // primes or squares missing; not a factor 2 or the reciprocal), the smallest pair of
    // kinds that works, every pair of that kind that does. Two pairs that make the same
    // form are one change (A then B is B then A), told in the fewer words: the one whose
    // second edit names a term of the printed form, not of the form the first edit made.
    if (found.empty()) {
        std::map<std::string, std::pair<std::string, finding>> by_form;
        std::vector<std::pair<const candidate*, candidate>> pairs;
        for (const candidate& first : all) {
            if (first.priority > 3 || pairs.size() > two_edit_budget)
                continue;
            extend(first, [&](candidate second) {
                if (second.priority <= 3)
                    pairs.emplace_back(&first, std::move(second));
            });
        }
        if (pairs.size() <= two_edit_budget) {
            std::stable_sort(pairs.begin(), pairs.end(), [](const auto& a, const auto& b) {
                return a.first->priority + a.second.priority < b.first->priority + b.second.priority;
            });
            for (const auto& [first, second] : pairs) {
                const int priority = first->priority + second.priority;
                if (best && priority > best)
                    break;
                if (screen(second.edited) && confirm(second.edited)) {
                    finding a = first->change(), b = second.change();
                    std::string ta = plain_text(a, symbols), tb = plain_text(b, symbols);
                    if (tb < ta) {
                        std::swap(a, b);
                        std::swap(ta, tb);
                    }
                    std::string text = ta + ", and " + tb;
                    std::ostringstream form;
                    form << second.edited;
                    finding both = joined(std::move(a), b);
                    both.corrected = second.edited;
                    auto [at, inserted] = by_form.try_emplace(form.str(), text, both);
                    if (!inserted && (text.size() < at->second.first.size() ||
                                      (text.size() == at->second.first.size() && text < at->second.first)))
                        at->second = {std::move(text), std::move(both)};
                    best = priority;
                }
            }
        }
        for (auto& [form, change] : by_form)
            found.emplace(std::move(change.first), std::move(change.second));
    }
    // Each change reconciles the two alone: after the first, each is said as an alternative
    // ("...; or ..."), never read as one more edit to make.
    std::vector<finding> out;
    for (auto& [text, change] : found) {
        if (!out.empty())
            change.parts.insert(change.parts.begin(), {finding::part::kind::words, "or ", {}, {}, {}});
        out.push_back(std::move(change));
    }
    return out;
}

} // namespace

static std::vector<finding> reconcile_expression_search(const GiNaC::ex& printed, const GiNaC::ex& derived,
                                              const symbol_table& symbols, const resolver& resolve,
                                              proof_cache& run)
{
    const auto points = screening_points(symbols);
    std::set<std::string> wanted = names_in(derived, symbols);
    for (const std::string& n : names_in(printed, symbols))
        wanted.insert(n);
    std::vector<candidate> all;
    single_edits(printed, "", wanted, symbols, [&](candidate c) { all.push_back(std::move(c)); });
    std::vector<std::optional<GiNaC::numeric>> target;
    for (const GiNaC::exmap& point : points)
        target.push_back(value_at(derived, point));
    auto screen = [&](const GiNaC::ex& edited) {
        for (std::size_t i = 0; i < points.size(); ++i) {
            const auto a = value_at(resolve(edited), points[i]);
            const auto& b = target[i];
            if (!a || !b || !close(*a, *b))
                return false;
        }
        return true;
    };
    auto confirm = [&](const GiNaC::ex& edited) {
        return prove_equal(resolve(edited), derived, symbols, run).what == verdict::status::proven;
    };
    auto extend = [&](const candidate& first, const std::function<void(candidate)>& emit) {
        single_edits(first.edited, "", wanted, symbols, emit);
    };
    return search(all, symbols, screen, confirm, extend);
}

static std::vector<finding> reconcile_equation_search(const GiNaC::ex& printed, const GiNaC::ex& derived,
                                            const symbol_table& symbols, const resolver& resolve,
                                            proof_cache& run)
{
    const auto points = screening_points(symbols);
    std::set<std::string> wanted = names_in(derived.lhs() - derived.rhs(), symbols);
    for (const std::string& n : names_in(printed.lhs() - printed.rhs(), symbols))
        wanted.insert(n);
    std::vector<candidate> all;
    single_edits(printed.lhs(), "on the left, ", wanted, symbols,
                 [&](candidate c) { all.push_back({c.priority, c.change, c.edited == printed.rhs()}); });
    single_edits(printed.rhs(), "on the right, ", wanted, symbols,
                 [&](candidate c) { all.push_back({c.priority, c.change, printed.lhs() == c.edited}); });
    const GiNaC::ex target = resolve(derived.lhs() - derived.rhs());
    auto screen = [&](const GiNaC::ex& edited) {
        std::optional<GiNaC::numeric> ratio;
        for (const GiNaC::exmap& point : points) {
            const auto a = value_at(resolve(edited.lhs() - edited.rhs()), point);
            const auto b = value_at(target, point);
            if (!a || !b || b->is_zero())
                return false;
            const GiNaC::numeric r = *a / *b;
            if (r.is_zero() || (ratio && !close(*ratio, r)))
                return false;
            ratio = r;
        }
        return true;
    };
    auto confirm = [&](const GiNaC::ex& edited) {
        return prove_equivalent(resolve(edited), resolve(derived), symbols, run).what == verdict::status::proven;
    };
    auto extend = [&](const candidate& first, const std::function<void(candidate)>& emit) {
        const GiNaC::ex lhs = first.edited.lhs(), rhs = first.edited.rhs();
        single_edits(lhs, "on the left, ", wanted, symbols,
                     [&](candidate c) { emit({c.priority, c.change, c.edited == rhs}); });
        single_edits(rhs, "on the right, ", wanted, symbols,
                     [&](candidate c) { emit({c.priority, c.change, lhs == c.edited}); });
    };
    return search(all, symbols, screen, confirm, extend);
}

std::vector<finding> reconcile_expression(const GiNaC::ex& printed, const GiNaC::ex& derived,
                                              const symbol_table& symbols, const resolver& resolve,
                                              proof_cache& run)
{
    // A search that meets arithmetic it cannot do (a printed form of 0 divided by) finds
    // nothing; it never stops the derivation.
    try {
        return reconcile_expression_search(printed, derived, symbols, resolve, run);
    } catch (const error&) {
        throw;
    } catch (const std::exception&) {
        return {};
    }
}

// The terms of a side: the operands of a sum, or the side itself.
static std::vector<GiNaC::ex> terms_of(const GiNaC::ex& side)
{
    return GiNaC::is_a<GiNaC::add>(side) ? std::vector<GiNaC::ex>(side.begin(), side.end())
                                         : std::vector<GiNaC::ex>{side};
}

// An equation no edit, or two, reconciles, compared term by term with the one it stands for:
// each side's printed terms that the derived side lacks, and the terms it lacks in their
// place (planar "Eq. 2": m'_{m,y} where m v'_{m,y} belongs; a whole y-component printed
// where the x-component belongs). Terms are matched by value, the derived quantities they
// name put in (a term written through m_eff is the term it stands for). The sides are
// matched the way that leaves fewer terms apart; nothing is said when each printed side is
// one term, which would only restate the two forms.
static std::vector<finding> terms_apart(const GiNaC::ex& printed, const GiNaC::ex& derived, const resolver& resolve)
{
    struct side_apart {
        std::vector<GiNaC::ex> printed_only, derived_only;
    };
    const auto apart = [&](const GiNaC::ex& p, const GiNaC::ex& d) {
        side_apart out;
        std::vector<GiNaC::ex> left = terms_of(d);
        for (const GiNaC::ex& t : terms_of(p)) {
            const auto same = std::find_if(left.begin(), left.end(), [&](const GiNaC::ex& u) {
                return u.is_equal(t) || GiNaC::normal(resolve(u) - resolve(t)).is_zero();
            });
            if (same == left.end())
                out.printed_only.push_back(t);
            else
                left.erase(same);
        }
        out.derived_only = left;
        return out;
    };
    const auto count = [](const side_apart& a, const side_apart& b) {
        return a.printed_only.size() + a.derived_only.size() + b.printed_only.size() + b.derived_only.size();
    };
    side_apart left = apart(printed.lhs(), derived.lhs()), right = apart(printed.rhs(), derived.rhs());
    const side_apart crossed_left = apart(printed.lhs(), derived.rhs()), crossed_right = apart(printed.rhs(), derived.lhs());
    const bool crossed = count(crossed_left, crossed_right) < count(left, right);
    if (crossed) {
        left = crossed_left;
        right = crossed_right;
    }
    const bool one_term_each = terms_of(printed.lhs()).size() == 1 && terms_of(printed.rhs()).size() == 1;
    if (count(left, right) == 0 || one_term_each)
        return {};
    const auto sum = [](const std::vector<GiNaC::ex>& terms) {
        GiNaC::ex out = 0;
        for (const GiNaC::ex& t : terms)
            out += t;
        return out;
    };
    finding f;
    bool first = true;
    for (const auto& [where, a] : {std::pair<const char*, const side_apart*>{"on the left, ", &left},
                                   std::pair<const char*, const side_apart*>{"on the right, ", &right}}) {
        if (a->printed_only.empty() && a->derived_only.empty())
            continue;
        f.say(std::string(first ? "" : "; ") + where);
        first = false;
        if (a->printed_only.empty())
            f.math(sum(a->derived_only)).say(" missing");
        else if (a->derived_only.empty())
            f.math(sum(a->printed_only)).say(" too many");
        else
            f.math(sum(a->printed_only)).say(" where ").math(sum(a->derived_only)).say(" belongs");
    }
    // The printed equation mended: the derived one, its sides the way the printed one has them.
    f.corrected = crossed ? (derived.rhs() == derived.lhs()) : derived;
    return {f};
}

std::vector<finding> reconcile_equation(const GiNaC::ex& printed, const GiNaC::ex& derived,
                                            const symbol_table& symbols, const resolver& resolve,
                                            proof_cache& run)
{
    // A search that meets arithmetic it cannot do (a printed form of 0 divided by) finds
    // nothing; it never stops the derivation.
    try {
        if (auto found = reconcile_equation_search(printed, derived, symbols, resolve, run); !found.empty())
            return found;
        return terms_apart(printed, derived, resolve);
    } catch (const error&) {
        throw;
    } catch (const std::exception&) {
        return {};
    }
}

} // namespace impact::engine
