// The single edits of a printed form (edits.h): the places in it, each rebuilt with one
// node replaced, and every edit of each kind offered as a candidate.
#include "engine/paper/edits.h"

#include "engine/expr/order.h"

#include <algorithm>
#include <map>
#include <memory>
#include <vector>

namespace impact::engine::reconcile_detail {

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

} // namespace

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

} // namespace impact::engine::reconcile_detail
