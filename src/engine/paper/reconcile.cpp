#include "engine/paper/reconcile.h"

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
namespace {

// A node of an expression, with the way down to it and the term of a sum it sits in.
struct site {
    std::vector<std::size_t> path;
    GiNaC::ex node;
    GiNaC::ex term;          ///< the enclosing term of a sum (or the whole expression)
    bool is_term = false;    ///< the node itself is a term of a sum
};

void collect_sites(const GiNaC::ex& e, std::vector<std::size_t>& path, const GiNaC::ex& term, bool is_term,
                   std::vector<site>& out)
{
    out.push_back({path, e, term, is_term});
    if (GiNaC::is_a<GiNaC::numeric>(e) || GiNaC::is_a<GiNaC::symbol>(e))
        return;
    for (std::size_t i = 0; i < e.nops(); ++i) {
        path.push_back(i);
        const bool child_is_term = GiNaC::is_a<GiNaC::add>(e);
        collect_sites(e.op(i), path, child_is_term ? e.op(i) : term, child_is_term, out);
        path.pop_back();
    }
}

// `e` with the node at `path` replaced, rebuilt from its operands.
GiNaC::ex replace_at(const GiNaC::ex& e, const std::vector<std::size_t>& path, std::size_t depth,
                     const GiNaC::ex& replacement)
{
    if (depth == path.size())
        return replacement;
    const std::size_t i = path[depth];
    const GiNaC::ex child = replace_at(e.op(i), path, depth + 1, replacement);
    if (GiNaC::is_a<GiNaC::add>(e) || GiNaC::is_a<GiNaC::mul>(e)) {
        GiNaC::exvector operands(e.begin(), e.end());
        operands[i] = child;
        return GiNaC::is_a<GiNaC::add>(e) ? GiNaC::ex(GiNaC::add(operands)) : GiNaC::ex(GiNaC::mul(operands));
    }
    if (GiNaC::is_a<GiNaC::power>(e)) {
        // Built here, not by GiNaC::pow: a power that cannot be evaluated (0 to a negative
        // exponent, as an edit may make) throws pole_error, and the object GiNaC::pow
        // allocates for it would never be freed (LeakSanitizer found it).
        const GiNaC::power rebuilt = i == 0 ? GiNaC::power(child, e.op(1)) : GiNaC::power(e.op(0), child);
        return GiNaC::ex(rebuilt);
    }
    if (GiNaC::is_a<GiNaC::relational>(e))
        return i == 0 ? (child == e.rhs()) : (e.lhs() == child);
    GiNaC::ex copy = e;
    copy.let_op(i) = child;
    return copy;
}

struct candidate {
    int priority;            ///< smaller is a smaller change
    std::function<finding()> change;  ///< described only if it reconciles (printing costs)
    GiNaC::ex edited;
};

// `symbol` primed: the declared `<name>_after`, if any.
const quantity* primed(const quantity& q, const symbol_table& symbols)
{
    return symbols.find(q.name + "_after");
}

const quantity* declared(const GiNaC::ex& symbol, const symbol_table& symbols)
{
    for (const quantity& q : symbols.all())
        if (q.symbol.is_equal(symbol))
            return &q;
    return nullptr;
}

// Every single edit of `e`; `side` prefixes the descriptions ("on the left, ").
void single_edits(const GiNaC::ex& e, const std::string& side, const std::set<std::string>& wanted,
                  const symbol_table& symbols, const std::function<void(candidate)>& emit)
{
    std::vector<site> sites;
    std::vector<std::size_t> path;
    collect_sites(e, path, e, false, sites);

    emit({1, [=] { return finding::words(side + "the sign of the whole expression"); }, -e});
    emit({4, [=] { return finding::words(side + "a factor 2 too many"); }, e / 2});
    emit({4, [=] { return finding::words(side + "a factor 2 missing"); }, e * 2});
    emit({4, [=] { return finding::words(side + "the reciprocal of the printed form"); }, 1 / e});
    const auto order = std::make_shared<term_order>(declaration_order(symbols));
    // A term named by its magnitude: GiNaC may store it as -1/m or as 1/m in -(...).
    // (Descriptions are written later, for the edits that reconcile: captured by value.)
    auto magnitude = [order](const GiNaC::ex& term) { return order->negative(term) ? -term : term; };
    // Where in a quotient a term stands, said with it: a term the paper prints more than
    // once (Eq. 12's m ε v, once above the bar and twice below) is then named without doubt.
    const auto divides = [](const GiNaC::ex& f) {
        return GiNaC::is_a<GiNaC::power>(f) && GiNaC::is_a<GiNaC::numeric>(f.op(1)) &&
               GiNaC::ex_to<GiNaC::numeric>(f.op(1)).is_negative();
    };
    // The innermost quotient on the way down to the term decides (Eq. 9's lab-frame
    // components, (r_x/|r|) (...)/(M + m) - ..., have their term above the bar of (...)/(M + m)).
    const auto in_quotient = [=](const std::vector<std::size_t>& path) -> std::string {
        std::string where;
        GiNaC::ex at = e;
        for (std::size_t i : path) {
            if (GiNaC::is_a<GiNaC::mul>(at) && std::any_of(at.begin(), at.end(), divides))
                where = divides(at.op(i)) ? " in the denominator" : " in the numerator";
            at = at.op(i);
        }
        return where;
    };
    std::set<std::string> present;
    for (const site& s : sites) {
        if (s.is_term && !s.path.empty()) {
            emit({2,
                  [=] {
                      return finding().say(side + "the sign of the term ").term(magnitude(s.node)).say(in_quotient(s.path));
                  },
                  replace_at(e, s.path, 0, -s.node)});
        }
        if (!GiNaC::is_a<GiNaC::symbol>(s.node))
            continue;
        const quantity* from = declared(s.node, symbols);
        if (!from)
            continue;
        present.insert(from->name);
        emit({3, [=] { return finding().say(side + "a spurious ").math(from->symbol).say(" in ").term(magnitude(s.term)); },
              replace_at(e, s.path, 0, 1)});
        for (const quantity& to : symbols.all()) {
            if (to.name == from->name || !wanted.count(to.name))
                continue;
            const quantity* prime = primed(*from, symbols);
            const bool adds_prime = prime && prime->name == to.name;
            emit({adds_prime ? 2 : 3,
                  [=] {
                      return finding()
                          .say(side + (adds_prime ? "a missing prime: " : "write "))
                          .math(to.symbol)
                          .say(" for ")
                          .math(from->symbol)
                          .say(" in ")
                          .term(magnitude(s.term));
                  },
                  replace_at(e, s.path, 0, to.symbol)});
        }
    }
    // Two symbols swapped throughout.
    for (auto a = present.begin(); a != present.end(); ++a) {
        for (auto b = std::next(a); b != present.end(); ++b) {
            const GiNaC::ex sa = symbols.find(*a)->symbol, sb = symbols.find(*b)->symbol;
            emit({3, [=] { return finding().say(side).math(sa).say(" and ").math(sb).say(" swapped"); },
                  e.subs(GiNaC::lst{sa, sb}, GiNaC::lst{sb, sa}, GiNaC::subs_options::no_pattern)});
        }
    }
    // The symbols of one dimension squared throughout (½ m v for ½ m v², in every term):
    // the squares missing.
    std::map<std::string, std::vector<std::string>> by_dimension;
    for (const quantity& q : symbols.all())   // in the order of their declaration
        if (present.count(q.name) && q.dim && !q.dim->is_pure_number())
            by_dimension[q.dim->to_string()].push_back(q.name);
    for (const auto& [dim, names] : by_dimension) {
        GiNaC::exmap square;
        std::vector<GiNaC::ex> squared;
        for (const std::string& name : names) {
            square[symbols.find(name)->symbol] = GiNaC::pow(symbols.find(name)->symbol, 2);
            squared.push_back(symbols.find(name)->symbol);
        }
        emit({3,
              [=] {
                  finding f;
                  f.say(side + "the squares of ");
                  for (std::size_t i = 0; i < squared.size(); ++i) {
                      if (i > 0)
                          f.say(i + 1 == squared.size() ? " and " : ", ");
                      f.math(squared[i]);
                  }
                  return f.say(" missing");
              },
              e.subs(square, GiNaC::subs_options::no_pattern)});
    }
    // Every symbol of the expression that has a primed version, primed.
    GiNaC::exmap prime_all;
    for (const std::string& name : present)
        if (const quantity* prime = primed(*symbols.find(name), symbols))
            prime_all[symbols.find(name)->symbol] = prime->symbol;
    if (!prime_all.empty())
        emit({1, [=] { return finding::words(side + "the primes missing"); },
              e.subs(prime_all, GiNaC::subs_options::no_pattern)});
}

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
