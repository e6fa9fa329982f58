// The paper's claims held to account: each claim checked as a check is, a failed one said
// not to hold with what holds instead (its complement, the relation that holds, the regime
// where it holds), and printed values that are each other's swapped.
#include "engine/derive/deriver.h"

#include "engine/cases/cases.h"
#include "engine/derive/declarations.h"
#include "engine/expr/derivative.h"
#include "engine/expr/infix.h"
#include "engine/expr/dimensional.h"
#include "engine/kernel/kernel_build.h"
#include "engine/paper/reconcile.h"
#include "engine/solve/solve.h"

#include <fmt/format.h>

#include <cctype>
#include <algorithm>
#include <filesystem>
#include <stdexcept>
#include <iterator>
#include <set>

namespace impact::engine::detail {

// A claim of the paper's text, tested as a check. When it fails, the same claim is
// tried at the other notable points of its limit or special value (the ends of the
// domain, 0 and infinity): a claim made for the wrong regime is reported as such.
paper_comparison deriver::hold_to_account(const spec::claim& claim)
{
    paper_comparison p;
    p.what = paper_comparison::kind::claim;
    p.subject = claim.test.name.value;
    p.paper = claim.paper.value;
    p.printed_text = claim.quote.value;
    p.where = claim.test.claim.where;
    p.label = claim.label ? claim.label->value : "";
    check_result c = run_check(claim.test, true);
    p.printed = c.stated;
    p.derived = c.value ? *c.value : c.lhs;
    p.agreement = c.outcome;
    if (!claim.holds) {
        said_not_to_hold(p, claim.test, c);
        p.test = std::move(c);
        return p;
    }
    if (!p.agrees() && c.value && (claim.test.limit || !claim.test.at.empty()))
        p.findings = other_regimes(claim.test, c);
    else if (!p.agrees() && c.op == relation::equal) {
        p.findings = reconcile_expression(c.stated.rhs(), c.lhs, out_.symbols, resolver(), run_);
        if (auto found = complement_holds(c)) {
            // Either mends it: the edits of the printed side are said as the alternatives
            // (the second and later already are, to each other).
            if (!p.findings.empty())
                p.findings.front().parts.insert(p.findings.front().parts.begin(),
                                                {finding::part::kind::words, "or ", {}, {}, {}});
            p.findings.insert(p.findings.begin(), *found);
        }
    }
    if (p.agreement.what == verdict::status::failed && p.findings.empty() && c.parts.empty() && !c.limit)
        p.findings = what_holds_instead(claim.test, c);
    if (!p.agrees() && claim.mended)
        p.findings.insert(p.findings.begin(), mended_finding(claim));
    if (const auto found = printed_dimension_finding(out_.symbols, p.printed, p.printed))
        p.findings.insert(p.findings.begin(), *found);
    p.reconciliations = plain_texts(p.findings, out_.symbols);
    p.test = std::move(c);
    return p;
}

// The claim as the file mends the words (`mended`: "final" for "incident"), proven as the
// claim is (its special values, limit, assumptions): said first when it holds. A mended
// claim that does not hold is the file's mistake.
finding deriver::mended_finding(const spec::claim& claim)
{
    spec::check mended = claim.test;
    mended.claim = *claim.mended;
    mended.name.value += " (mended)";
    const check_result c = run_check(mended, true);
    if (c.outcome.what != verdict::status::proven)
        throw error(claim.mended->where,
                    fmt::format("claim '{}': the mended claim does not hold ({}): mend the words so that it does",
                                claim.test.name.value, to_string(c.outcome)));
    return finding().say("mended, it holds: ").states(c.stated.lhs(), c.op, c.stated.rhs());
}

// A claim the paper says does not hold (`holds = false`, Footnote 11's "the contrapositive
// does not hold"): it agrees when a point of the domains is found where it fails, decided
// exactly (a counterexample), disagrees when it is proven, and is undecided otherwise.
void deriver::said_not_to_hold(paper_comparison& p, const spec::check& spec_check, check_result& c)
{
    c.said_false = true;
    p.findings.clear();
    switch (c.outcome.what) {
    case verdict::status::proven:
        p.agreement = verdict{};
        p.agreement.residual = c.outcome.residual;
        p.agreement.method = "it holds, where the paper says it does not: " + c.outcome.method;
        p.findings = {c.outcome.how == verdict::basis::zero_difference
                          ? finding().say("it holds, where the paper says it does not: the difference of its "
                                          "sides simplifies to ").math(GiNaC::ex(0))
                      : c.outcome.how == verdict::basis::signs && !GiNaC::is_a<GiNaC::numeric>(c.outcome.residual)
                          ? finding().say("it holds, where the paper says it does not: the sign of each factor "
                                          "of ").math(c.outcome.residual).say(" follows from the domains")
                          : finding().say("it holds, where the paper says it does not")};
        break;
    case verdict::status::sampled: break;   // undecided, as sampled
    case verdict::status::failed:
        if (c.parts.empty())
            c.fails_at = find_counterexample(c.lhs, c.op, c.rhs, out_.symbols, assumptions_of(spec_check));
        p.agreement = verdict{};
        p.agreement.residual = c.outcome.residual;
        if (c.fails_at) {
            p.agreement.what = verdict::status::proven;
            p.agreement.how = verdict::basis::counterexample;
            p.agreement.method = "refuted at a point of the domains";
        } else {
            // Not refuted at a point: undecided, with nothing sampled that held.
            p.agreement.what = verdict::status::sampled;
            p.agreement.method = c.parts.empty() ? "no point of the domains was found where it fails"
                                                 : "split by cases: no point is searched for";
        }
        break;
    }
    p.reconciliations = plain_texts(p.findings, out_.symbols);
}

// A share said of its complement: the text calls tau the transferred share, where Eq. 12
// defines the share the cue ball keeps. A claim `x = rhs` about a quantity x that holds
// with 1 - x for x.
std::optional<finding> deriver::complement_holds(const check_result& failed)
{
    const GiNaC::ex left = failed.stated.lhs();
    if (!GiNaC::is_a<GiNaC::symbol>(left) || (failed.lhs - left).is_zero() || !failed.at.empty() ||
        !failed.left_at.empty() || failed.limit || GiNaC::is_a<GiNaC::numeric>(failed.lhs) ||
        GiNaC::is_a<GiNaC::numeric>(failed.rhs))
        return std::nullopt;   // a number and its complement say nothing of shares
    try {
        if (prove_equal(1 - failed.lhs, failed.rhs, out_.symbols, run_, when_unproven::give_up).what !=
            verdict::status::proven)
            return std::nullopt;
    } catch (const error&) {
        throw;
    } catch (const std::exception&) {
        return std::nullopt;   // arithmetic it cannot do says nothing of shares
    }
    return finding().say("it holds with ").math(1 - left).say(" for ").math(left);
}

// A failed claim without a finding: the relation reversed (a > b where a < b holds:
// "increasing" for decreasing values), else the derived value of the quantity on its
// left (an object ball's incident speed, 0); or, for an equation, a function of its
// left side that the right side is (the cosine of an angle printed as the angle).
std::vector<finding> deriver::what_holds_instead(const spec::check& original, const check_result& failed)
{
    // Said of the claim as written: not of one at special values or changed inputs.
    if (!failed.at.empty() || !failed.left_at.empty())
        return {};
    // A search that meets arithmetic it cannot do (tan at a pole) finds nothing; it never
    // stops the derivation.
    try {
        return what_holds_instead_search(original, failed);
    } catch (const error&) {
        throw;
    } catch (const std::exception&) {
        return {};
    }
}

std::vector<finding> deriver::what_holds_instead_search(const spec::check& original, const check_result& failed)
{
    const GiNaC::ex left = failed.stated.lhs();
    if (failed.op != relation::equal) {
        static const std::map<relation, relation> mirrored = {{relation::less, relation::greater},
                                                              {relation::less_equal, relation::greater_equal},
                                                              {relation::greater, relation::less},
                                                              {relation::greater_equal, relation::less_equal}};
        const relation reversed = mirrored.at(failed.op);
        if (prove_inequality_by_signs(failed.lhs, reversed, failed.rhs, out_.symbols, assumptions_of(original)))
            return {finding().say("the reverse holds: ").states(left, reversed, failed.stated.rhs())};
        // Neither way round: what a derived quantity on the left comes to.
        if (GiNaC::is_a<GiNaC::symbol>(left) && !(failed.lhs - left).is_zero())
            return {finding().say("derived, ").states(left, relation::equal, failed.lhs)};
        return {};
    }
    // Bars that do not belong: the change of a magnitude, |v'| - |v|, printed where the
    // change of the quantity itself is meant (Eq. 10's Delta|v_Delta|).
    if (failed.stated.has(GiNaC::abs(GiNaC::wild(0)))) {
        struct unbarred : GiNaC::map_function {
            std::vector<GiNaC::ex> inside;   // what the bars held, in the order met
            GiNaC::ex operator()(const GiNaC::ex& e) override
            {
                if (GiNaC::is_a<GiNaC::function>(e) && GiNaC::ex_to<GiNaC::function>(e).get_name() == "abs") {
                    inside.push_back(e.op(0));
                    return (*this)(e.op(0));
                }
                return e.map(*this);
            }
        } strip;
        const GiNaC::ex l = strip(failed.stated.lhs()), r = strip(failed.stated.rhs());
        if (prove_equal(resolve(l), resolve(r), out_.symbols, run_, when_unproven::give_up).what ==
            verdict::status::proven) {
            // In the order of the derivation's symbols (GiNaC's order of a sum's terms
            // follows its hashes), each once.
            const term_order order = declaration_order(out_.symbols);
            std::sort(strip.inside.begin(), strip.inside.end(),
                      [&](const GiNaC::ex& a, const GiNaC::ex& b) { return order.before(a, b); });
            strip.inside.erase(std::unique(strip.inside.begin(), strip.inside.end(),
                                           [](const GiNaC::ex& a, const GiNaC::ex& b) { return a.is_equal(b); }),
                               strip.inside.end());
            finding f;
            f.say("it holds without the absolute values around ");
            for (std::size_t i = 0; i < strip.inside.size(); ++i) {
                if (i > 0)
                    f.say(i + 1 == strip.inside.size() ? " and " : ", ");
                f.math(strip.inside[i]);
            }
            return {f};
        }
    }
    // An angle (derived as an arccosine, arcsine or arctangent) set equal to its cosine,
    // sine or tangent.
    if (!GiNaC::is_a<GiNaC::symbol>(left) || !GiNaC::is_a<GiNaC::function>(failed.lhs))
        return where_it_holds(original, failed);
    const std::string inverse = GiNaC::ex_to<GiNaC::function>(failed.lhs).get_name();
    const std::map<std::string, std::pair<GiNaC::ex (*)(const GiNaC::ex&), const char*>> of = {
        {"acos", {[](const GiNaC::ex& x) -> GiNaC::ex { return GiNaC::cos(x); }, "cosine"}},
        {"asin", {[](const GiNaC::ex& x) -> GiNaC::ex { return GiNaC::sin(x); }, "sine"}},
        {"atan", {[](const GiNaC::ex& x) -> GiNaC::ex { return GiNaC::tan(x); }, "tangent"}}};
    const auto function = of.find(inverse);
    if (function == of.end())
        return {};
    const auto [apply, name] = function->second;
    if (prove_equal(apply(failed.lhs), failed.rhs, out_.symbols, run_).what != verdict::status::proven)
        return {};
    return {finding()
                .say("it holds with ")
                .math(apply(left))
                .say(" for ")
                .math(left)
                .say(fmt::format(": the right side is the {} of ", name))
                .math(left)};
}

// An equation that holds only where a factor of the difference of its sides vanishes:
// the changes of velocity of Sec. II A are equal and opposite only for M = m (and
// where nothing collides, v_M = v_m). Each factor the domains do not prove non-zero
// must be linear in at most two symbols with numbers for coefficients (M - m, M + m,
// M - 2), said as an equation in the first declared; one that is not leaves nothing to
// say, since "only where" would be untrue.
std::vector<finding> deriver::where_it_holds(const spec::check& original, const check_result& failed)
{
    const GiNaC::ex difference = GiNaC::normal(out_.symbols.in_inputs(failed.lhs - failed.rhs));
    if (difference.is_zero() || has_radical(difference) || !difference.info(GiNaC::info_flags::rational_function))
        return {};
    const GiNaC::ex numerator = factor_polynomial(GiNaC::numer(difference), run_);
    const assumptions given = assumptions_of(original);
    std::vector<GiNaC::ex> factors;
    for (const GiNaC::ex& f : GiNaC::is_a<GiNaC::mul>(numerator) ? std::vector<GiNaC::ex>(numerator.begin(), numerator.end())
                                                                  : std::vector<GiNaC::ex>{numerator})
        factors.push_back(GiNaC::is_a<GiNaC::power>(f) ? f.op(0) : f);
    // The declared symbols in declaration order: the first one a factor names is set
    // on the left (M = m, as the file declares M first).
    // Each place with the declaration rank of its left side, to be said in that order
    // (GiNaC's order of factors follows its hashes, which a build may change).
    std::vector<std::pair<std::size_t, GiNaC::ex>> places;
    std::size_t other = 0;   // places that are not a symbol solved for
    const auto rank = [&](const GiNaC::ex& symbol) {
        const auto& all = out_.symbols.all();
        return static_cast<std::size_t>(std::find_if(all.begin(), all.end(), [&](const quantity& q) {
                                            return q.symbol.is_equal(symbol);
                                        }) - all.begin());
    };
    for (const GiNaC::ex& f : factors) {
        if (GiNaC::is_a<GiNaC::numeric>(f) || !prove_sign(f, given).sign.zero)
            continue;   // never zero under the domains
        std::vector<GiNaC::ex> in;
        for (const quantity& q : out_.symbols.all())
            if (f.has(q.symbol))
                in.push_back(q.symbol);
        if (in.empty())
            return {};
        // Linear in one or two symbols, with numbers for coefficients: the first symbol
        // solved for (M = m, v_M = v_m).
        const GiNaC::ex a = f.coeff(in.front(), 1);
        const bool linear = in.size() <= 2 && f.degree(in.front()) == 1 && GiNaC::is_a<GiNaC::numeric>(a) &&
                            (in.size() == 1 || (f.degree(in.back()) == 1 &&
                                                GiNaC::is_a<GiNaC::numeric>(f.coeff(in.back(), 1))));
        const GiNaC::ex rest = linear ? GiNaC::expand(f - a * in.front()) : GiNaC::ex(0);
        if (linear && (in.size() == 1 || (rest - rest.coeff(in.back(), 1) * in.back()).is_zero())) {
            places.emplace_back(rank(in.front()), in.front() == GiNaC::normal(-rest / a));
            continue;
        }
        // Any other factor, when short and of degree 1 in each of its symbols: two terms
        // set equal (r_x v_My = r_y v_Mx, the first with its sign), else the factor,
        // collected, set to 0.
        const GiNaC::ex e = GiNaC::expand(f);
        if (!GiNaC::is_a<GiNaC::add>(e) || e.nops() > 6 ||
            std::any_of(in.begin(), in.end(), [&](const GiNaC::ex& x) { return e.degree(x) != 1; }))
            return {};
        places.emplace_back(rank(in.front()), vanishes(e));
        ++other;
    }
    // One such factor alone restates the claim: nothing to say.
    if (places.empty() || (places.size() == 1 && other == 1))
        return {};
    const term_order order = declaration_order(out_.symbols);
    std::sort(places.begin(), places.end(), [&](const auto& x, const auto& y) {
        if (x.first != y.first)
            return x.first < y.first;
        if (!x.second.rhs().is_equal(y.second.rhs()))
            return order.before(x.second.rhs(), y.second.rhs());
        // Two set to 0: by their written form, the same in every build.
        return ginac_syntax(x.second.lhs(), out_.symbols.order()) < ginac_syntax(y.second.lhs(), out_.symbols.order());
    });
    finding said;
    said.say("it holds only where ");
    for (std::size_t i = 0; i < places.size(); ++i) {
        if (i > 0)
            said.say(i + 1 == places.size() ? " or " : ", ");
        said.math(places[i].second);
    }
    GiNaC::ex shown = 1;
    for (const GiNaC::ex& f : GiNaC::is_a<GiNaC::mul>(numerator) ? std::vector<GiNaC::ex>(numerator.begin(), numerator.end())
                                                                  : std::vector<GiNaC::ex>{numerator})
        shown *= GiNaC::is_a<GiNaC::power>(f) ? GiNaC::pow(collected(f.op(0)), f.op(1)) : collected(f);
    // The difference itself when it is short enough to read in a line of text.
    const GiNaC::ex whole = shown / GiNaC::denom(difference);
    std::size_t occurrences = 0;
    for (GiNaC::const_preorder_iterator it = whole.preorder_begin(); it != whole.preorder_end(); ++it)
        occurrences += GiNaC::is_a<GiNaC::symbol>(*it) ? 1 : 0;
    if (occurrences > 12)
        return {said};
    return {said.say(": the difference of its sides is ").math(whole)};
}

// `sum = 0` as said: its first term (by the declaration ranks of its symbols) with a
// positive sign; two terms set equal (r_x v_My = r_y v_Mx), more collected.
GiNaC::ex deriver::vanishes(const GiNaC::ex& sum) const
{
    const auto& all = out_.symbols.all();
    GiNaC::exmap ones;
    const auto key = [&](const GiNaC::ex& term) {
        std::vector<std::size_t> ranks;
        for (std::size_t i = 0; i < all.size(); ++i)
            if (term.has(all[i].symbol))
                ranks.push_back(i);
        return ranks;
    };
    for (const quantity& q : all)
        ones[q.symbol] = 1;
    std::vector<GiNaC::ex> terms(sum.begin(), sum.end());
    std::stable_sort(terms.begin(), terms.end(),
                     [&](const GiNaC::ex& a, const GiNaC::ex& b) { return key(a) < key(b); });
    const GiNaC::ex lead = terms.front().subs(ones, GiNaC::subs_options::no_pattern);
    const bool negative = GiNaC::is_a<GiNaC::numeric>(lead) && GiNaC::ex_to<GiNaC::numeric>(lead).is_negative();
    const GiNaC::ex e = negative ? GiNaC::expand(-sum) : sum;
    if (terms.size() == 2) {
        const GiNaC::ex first = negative ? -terms.front() : terms.front();
        return first == first - e;
    }
    return collected(e) == 0;
}

// A sum collected by the declared symbols, taken in declaration order, that each stand
// to the first power in two or more of its terms not yet covered, when together they
// cover every term: r_x (v_Mx - v_mx) + r_y (v_My - v_my). The sum as it was otherwise.
GiNaC::ex deriver::collected(const GiNaC::ex& sum) const
{
    const GiNaC::ex e = GiNaC::expand(sum);
    if (!GiNaC::is_a<GiNaC::add>(e) || e.nops() < 3)
        return sum;
    std::vector<bool> covered(e.nops(), false);
    GiNaC::lst by;
    for (const quantity& q : out_.symbols.all()) {
        std::vector<std::size_t> terms;
        for (std::size_t i = 0; i < e.nops(); ++i)
            if (!covered[i] && e.op(i).has(q.symbol) && e.op(i).degree(q.symbol) == 1)
                terms.push_back(i);
        if (terms.size() < 2)
            continue;
        by.append(q.symbol);
        for (const std::size_t i : terms)
            covered[i] = true;
    }
    if (std::find(covered.begin(), covered.end(), false) != covered.end())
        return sum;
    return GiNaC::collect(e, by);
}

std::vector<finding> deriver::other_regimes(const spec::check& original, const check_result& failed)
{
    std::vector<finding> found;
    const spec::text* symbol = nullptr;
    const spec::text* point = nullptr;
    if (original.limit) {
        symbol = &original.limit->symbol;
        point = &original.limit->written;
    } else if (original.at.size() == 1) {
        symbol = &original.at.front().name;
        point = &original.at.front().expression;
    }
    if (symbol) {
        const quantity& q = out_.symbols.at(*symbol);
        std::vector<std::string> candidates = {"0", "infinity"};
        if (q.range.what == domain::kind::interval)
            candidates = {q.range.lower_text.empty() ? fmt::format("{}", q.range.lower) : q.range.lower_text,
                          q.range.upper_text.empty() ? fmt::format("{}", q.range.upper) : q.range.upper_text};
        for (const std::string& other : candidates) {
            const bool infinity = other == "infinity";
            const bool same = original.limit ? original.limit->to_infinity == infinity &&
                                                   (infinity || original.limit->point.value == other)
                                             : other == original.at.front().expression.value;
            if (same)
                continue;
            spec::check moved = original;
            moved.at.clear();
            moved.limit = spec::limit_point{{symbol->value + " -> " + other, point->where},
                                      {symbol->value, point->where},
                                      {infinity ? "" : other, point->where},
                                      infinity};
            try {
                if (run_check(moved).outcome.what == verdict::status::proven)
                    found.push_back(finding()
                                        .say("it holds for ")
                                        .tends(q.symbol, infinity ? std::nullopt
                                                                  : std::optional<GiNaC::ex>(out_.symbols.parse(
                                                                        spec::text{other, point->where})))
                                        .say(" instead"));
            } catch (const error&) {
            }
        }
    }
    // A regime where it holds is the one change that mends it; the derived value only when
    // none is found.
    if (found.empty())
        found.push_back(
            finding().say("the derived value is ").math(*failed.value).say(", not ").math(failed.rhs));
    return found;
}

// Two claims of one quote, each a limit (or a value at one point) of the same quantity,
// as the file states it, at its own point of the same symbol, under the same assumptions,
// that both fail, each stating the value the other derives: one misprint, the values
// swapped (Sec. III C's "90°" and "0°"), told once for both in place of where each holds
// instead (a dimensional finding or the claim mended are kept before it).
void deriver::find_swapped_values(std::vector<paper_comparison>& claims) const
{
    struct regime {
        GiNaC::ex symbol;
        std::optional<GiNaC::ex> point;   // none: infinity
        bool limit = false;
    };
    const auto regime_of = [](const check_result& c) -> std::optional<regime> {
        if (c.limit && c.at.empty())
            return regime{c.limit->symbol, c.limit->to_infinity ? std::nullopt : std::optional(c.limit->point), true};
        if (!c.limit && c.at.size() == 1)
            return regime{c.at.front().first, c.at.front().second, false};
        return std::nullopt;
    };
    const auto same = [](const GiNaC::ex& a, const GiNaC::ex& b) { return (a - b).normal().is_zero(); };
    const auto same_assumptions = [](const check_result& a, const check_result& b) {
        return a.assuming.size() == b.assuming.size() &&
               std::equal(a.assuming.begin(), a.assuming.end(), b.assuming.begin(), [](const auto& x, const auto& y) {
                   return x.first.is_equal(y.first) && x.second == y.second;
               });
    };
    const auto candidate = [](const paper_comparison& p) {
        return p.agreement.what == verdict::status::failed && p.test && !p.test->said_false &&
               p.test->op == relation::equal && p.test->value && p.test->left_at.empty() && p.test->parts.empty();
    };
    const auto kept = [](const finding& f) {   // said before the change: not where it holds
        return std::any_of(f.parts.begin(), f.parts.end(),
                           [](const finding::part& part) { return part.what == finding::part::kind::dimension; }) ||
               (!f.parts.empty() && f.parts.front().words.rfind("mended", 0) == 0);
    };
    for (std::size_t i = 0; i < claims.size(); ++i)
        for (std::size_t j = i + 1; j < claims.size(); ++j) {
            paper_comparison& a = claims[i];
            paper_comparison& b = claims[j];
            if (a.paper != b.paper || a.printed_text != b.printed_text || !candidate(a) || !candidate(b) ||
                !same_assumptions(*a.test, *b.test))
                continue;
            const auto at_a = regime_of(*a.test);
            const auto at_b = regime_of(*b.test);
            if (!at_a || !at_b || at_a->limit != at_b->limit || !at_a->symbol.is_equal(at_b->symbol) ||
                !same(a.test->stated.lhs(), b.test->stated.lhs()) || same(a.test->rhs, b.test->rhs) ||
                !same(a.test->rhs, *b.test->value) || !same(b.test->rhs, *a.test->value))
                continue;
            const auto where = [](finding& f, const regime& r) -> finding& {
                return r.limit ? f.say(" for ").tends(r.symbol, r.point) : f.say(" at ").math(r.symbol == *r.point);
            };
            finding swapped = finding().say("the values are swapped: ").math(a.test->stated.lhs()).say(" is ");
            where(swapped.math(*a.test->value), *at_a).say(" and ");
            where(swapped.math(*b.test->value), *at_b);
            for (paper_comparison* p : {&a, &b}) {
                std::vector<finding> found;
                std::copy_if(p->findings.begin(), p->findings.end(), std::back_inserter(found), kept);
                found.push_back(swapped);
                p->findings = std::move(found);
                p->reconciliations = plain_texts(p->findings, out_.symbols);
            }
        }
}

} // namespace impact::engine::detail
