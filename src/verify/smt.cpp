#include "verify/smt.h"

#include "engine/expr/order.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <map>
#include <set>
#include <sstream>

namespace impact::verify {

using engine::condition;
using engine::relation;

namespace {

// A name SMT-LIB reads as one symbol: the quantity's own when it is a simple symbol,
// else quoted. Fresh variables hold a dot (inv.1, root.1), which no quantity's name does.
std::string smt_name(const std::string& name)
{
    bool simple = !name.empty() && !std::isdigit(static_cast<unsigned char>(name.front()));
    for (char c : name)
        simple = simple && (std::isalnum(static_cast<unsigned char>(c)) || c == '_');
    return simple ? name : "|" + name + "|";
}

const char* operator_of(relation op)
{
    switch (op) {
    case relation::equal: return "=";
    case relation::less_equal: return "<=";
    case relation::less: return "<";
    case relation::greater_equal: return ">=";
    case relation::greater: return ">";
    }
    return "=";
}

// Writes expressions as SMT-LIB terms, declaring what they use: the quantities, the
// abbreviations with their definitions, and a fresh variable for each reciprocal and
// each root (the same expression, the same variable: sqrt(x)*sqrt(x) = x needs it).
class smt_writer {
public:
    smt_writer(const engine::symbol_table& symbols, const std::set<std::string>& derived)
        : symbols_(symbols), derived_(derived), order_(engine::declaration_order(symbols))
    {
        for (std::size_t i = 0; i < symbols.all().size(); ++i) {
            index_[symbols.all()[i].symbol] = i;
            by_name_[symbols.all()[i].name] = i;
        }
    }

    // The first thing Z3's real arithmetic cannot say, if any.
    const std::string& failure() const { return failure_; }

    std::string term(const GiNaC::ex& e)
    {
        if (!failure_.empty())
            return "0";
        if (GiNaC::is_a<GiNaC::numeric>(e))
            return number(GiNaC::ex_to<GiNaC::numeric>(e));
        if (GiNaC::is_a<GiNaC::constant>(e)) {
            std::ostringstream name;
            name << e;
            return fail(name.str());
        }
        if (GiNaC::is_a<GiNaC::symbol>(e))
            return quantity(e);
        if (GiNaC::is_a<GiNaC::add>(e)) {
            std::vector<std::string> terms;
            for (const GiNaC::ex& t : order_.terms(e))
                terms.push_back(term(t));
            return fmt::format("(+ {})", fmt::join(terms, " "));
        }
        if (GiNaC::is_a<GiNaC::mul>(e)) {
            bool negated = false;
            std::vector<std::string> factors;
            for (const engine::term_order::power_term& f : order_.factors(e, negated))
                if (!f.base.is_equal(1))   // the 1 a product's sign leaves behind
                    factors.push_back(power(f.base, f.exponent));
            if (factors.empty())
                factors.push_back("1");
            const std::string product = factors.size() == 1 ? factors.front() : fmt::format("(* {})", fmt::join(factors, " "));
            return negated ? fmt::format("(- {})", product) : product;
        }
        if (GiNaC::is_a<GiNaC::power>(e)) {
            bool negated = false;
            const engine::term_order::power_term p = order_.oriented(e, negated);
            const std::string value = power(p.base, p.exponent);
            return negated ? fmt::format("(- {})", value) : value;
        }
        if (GiNaC::is_a<GiNaC::fderivative>(e))
            return fail("a derivative");
        if (GiNaC::is_a<GiNaC::function>(e)) {
            const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
            if (name == "abs") {
                // |a| by cases on the sign of a.
                const std::string a = term(e.op(0));
                return fmt::format("(ite (>= {0} 0) {0} (- {0}))", a);
            }
            if (name == "select_positive")   // a quantity defined by cases, as a kernel computes it
                return fmt::format("(ite (> {} 0) {} {})", term(e.op(0)), term(e.op(1)), term(e.op(2)));
            return fail(name);
        }
        return fail(GiNaC::ex_to<GiNaC::basic>(e).class_name());
    }

    std::string relation_term(const GiNaC::ex& lhs, relation op, const GiNaC::ex& rhs)
    {
        const std::string l = term(lhs);
        return fmt::format("({} {} {})", operator_of(op), l, term(rhs));
    }

    std::string condition_term(const condition& c)
    {
        const std::string e = term(c.expr);
        switch (c.need) {
        case condition::kind::nonzero: return fmt::format("(not (= {} 0))", e);
        case condition::kind::positive: return fmt::format("(> {} 0)", e);
        case condition::kind::nonnegative: return fmt::format("(>= {} 0)", e);
        }
        return "true";
    }

    // A narrowed domain of a quantity (a check's `assuming`).
    void narrow(const GiNaC::ex& symbol, const engine::domain& d)
    {
        const std::string name = term(symbol);
        for (std::string& a : domain_assertions(name, d))
            narrowed_.push_back(std::move(a));
    }

    // The declarations and assertions made so far, before the hypotheses and the claim.
    std::string preamble()
    {
        std::string out;
        std::vector<std::size_t> used(used_.begin(), used_.end());   // declaration order
        for (std::size_t i : used)
            out += fmt::format("(declare-fun {} () Real)\n", smt_name(symbols_.all()[i].name));
        for (const std::string& name : fresh_)
            out += fmt::format("(declare-fun {} () Real)\n", name);
        const auto section = [&out](const char* what, const std::vector<std::string>& assertions) {
            if (assertions.empty())
                return;
            out += fmt::format("; {}\n", what);
            for (const std::string& a : assertions)
                out += fmt::format("(assert {})\n", a);
        };
        std::vector<std::string> domains;
        for (std::size_t i : used)
            for (std::string& a : domain_assertions(smt_name(symbols_.all()[i].name), symbols_.all()[i].range))
                domains.push_back(std::move(a));
        section("the declared domains", domains);
        section("the domains the check narrows (assuming)", narrowed_);
        section("abbreviations: their definitions", definitions_);
        section("reciprocals and roots", fresh_facts_);
        section("where the sides are defined: divisors != 0, radicands >= 0", defined_);
        return out;
    }

private:
    std::string fail(const std::string& what)
    {
        if (failure_.empty())
            failure_ = "not expressible: " + what;
        return "0";
    }

    std::string number(const GiNaC::numeric& n)
    {
        if (!n.is_rational())
            return fail(n.is_real() ? "a floating-point number" : "a complex number");
        const GiNaC::numeric magnitude = GiNaC::abs(n);
        std::ostringstream num, den;
        num << magnitude.numer();
        den << magnitude.denom();
        const std::string value = magnitude.is_integer() ? num.str() : fmt::format("(/ {} {})", num.str(), den.str());
        return n.is_negative() ? fmt::format("(- {})", value) : value;
    }

    std::string quantity(const GiNaC::ex& s)
    {
        auto found = index_.find(s);
        if (found == index_.end()) {
            // A copy of a declared quantity, named as it (a root named in a continuity
            // proof: d for sqrt(r.r)); a derived one's copy stands for other inputs.
            const std::string& name = GiNaC::ex_to<GiNaC::symbol>(s).get_name();
            const auto named = by_name_.find(name);
            if (named == by_name_.end() || derived_.count(name))
                return fail("an undeclared symbol " + name);
            found = index_.find(symbols_.all()[named->second].symbol);
        }
        const engine::quantity& q = symbols_.all()[found->second];
        if (derived_.count(q.name))
            return fail("the derived quantity " + q.name + " left in the claim");
        const std::string name = smt_name(q.name);
        if (used_.insert(found->second).second && q.definition) {
            // An abbreviation is its definition (which may use others), in its own domain.
            const std::string value = term(*q.definition);
            definitions_.push_back(fmt::format("(= {} {})", name, value));
        }
        return name;
    }

    // base^exponent, exponent a rational number.
    std::string power(const GiNaC::ex& base, const GiNaC::ex& exponent)
    {
        if (!GiNaC::is_a<GiNaC::numeric>(exponent) || !GiNaC::ex_to<GiNaC::numeric>(exponent).is_rational())
            return fail("a power with a symbolic exponent");
        const GiNaC::numeric n = GiNaC::ex_to<GiNaC::numeric>(exponent);
        if (n.is_equal(1))
            return term(base);
        if (n.is_integer()) {
            const long k = n.to_long();
            if (k > 64 || k < -64)
                return fail("a power above 64");
            const std::string b = k > 0 ? term(base) : reciprocal(base, term(base));
            return repeated(b, k > 0 ? k : -k);
        }
        // base^(p/q) = r^|p|... with r = base^(1/q) would need base >= 0 twice; instead
        // r = base^(|p|/q): r >= 0, r^q = base^|p| where base >= 0.
        const long p = n.numer().to_long(), q = n.denom().to_long();
        const long a = p < 0 ? -p : p;
        const GiNaC::ex key = GiNaC::pow(base, GiNaC::numeric(a, q));
        std::string r;
        if (const auto known = roots_.find(key); known != roots_.end()) {
            r = known->second;
        } else {
            const std::string x = term(base);
            r = fresh("root");
            roots_[key] = r;
            fresh_facts_.push_back(fmt::format("(>= {} 0)", r));
            fresh_facts_.push_back(fmt::format("(=> (>= {0} 0) (= {1} {2}))", x, repeated(r, q), repeated(x, a)));
            defined_.push_back(fmt::format("(>= {} 0)", x));
        }
        return p < 0 ? reciprocal(key, r) : r;
    }

    // 1/B as a fresh q: B != 0 => q*B = 1, and B != 0 where the sides are defined.
    std::string reciprocal(const GiNaC::ex& key, const std::string& b)
    {
        if (const auto known = inverses_.find(key); known != inverses_.end())
            return known->second;
        const std::string q = fresh("inv");
        inverses_[key] = q;
        fresh_facts_.push_back(fmt::format("(=> (not (= {0} 0)) (= (* {1} {0}) 1))", b, q));
        defined_.push_back(fmt::format("(not (= {} 0))", b));
        return q;
    }

    std::string fresh(const char* kind)
    {
        std::string name = fmt::format("{}.{}", kind, fresh_.size() + 1);
        fresh_.push_back(name);
        return name;
    }

    static std::string repeated(const std::string& factor, long times)
    {
        if (times == 0)
            return "1";
        if (times == 1)
            return factor;
        std::vector<std::string> factors(static_cast<std::size_t>(times), factor);
        return fmt::format("(* {})", fmt::join(factors, " "));
    }

    // A bound of an interval as an SMT-LIB number: a rational the file writes (0, 1, 2/3,
    // 0.5); none for an infinite one.
    std::optional<std::string> bound(const std::string& text)
    {
        if (text.empty() || text.find("inf") != std::string::npos)
            return std::nullopt;
        GiNaC::ex value;
        try {
            GiNaC::parser reader;
            value = reader(text);
        } catch (const std::exception&) {
            fail("the bound " + text);
            return std::nullopt;
        }
        if (!GiNaC::is_a<GiNaC::numeric>(value)) {
            fail("the bound " + text);
            return std::nullopt;
        }
        return number(GiNaC::ex_to<GiNaC::numeric>(value));
    }

    std::vector<std::string> domain_assertions(const std::string& name, const engine::domain& d)
    {
        switch (d.what) {
        case engine::domain::kind::real: return {};
        case engine::domain::kind::positive: return {fmt::format("(> {} 0)", name)};
        case engine::domain::kind::nonnegative: return {fmt::format("(>= {} 0)", name)};
        case engine::domain::kind::interval: {
            std::vector<std::string> out;
            if (const std::optional<std::string> lo = bound(d.lower_text))
                out.push_back(fmt::format("({} {} {})", d.lower_open ? "<" : "<=", *lo, name));
            if (const std::optional<std::string> hi = bound(d.upper_text))
                out.push_back(fmt::format("({} {} {})", d.upper_open ? "<" : "<=", name, *hi));
            return out;
        }
        }
        return {};
    }

    const engine::symbol_table& symbols_;
    const std::set<std::string>& derived_;
    engine::term_order order_;
    std::map<GiNaC::ex, std::size_t, GiNaC::ex_is_less> index_;
    std::map<std::string, std::size_t> by_name_;
    std::set<std::size_t> used_;
    std::vector<std::string> fresh_;
    std::vector<std::string> fresh_facts_, definitions_, defined_, narrowed_;
    std::map<GiNaC::ex, std::string, GiNaC::ex_is_less> inverses_, roots_;
    std::string failure_;
};

} // namespace

smt_problem smt_problem_of(const smt_claim& claim, const engine::symbol_table& symbols)
{
    smt_writer w(symbols, claim.derived);
    // The assumptions: abbreviations declared with a domain, whether the claim uses them or not.
    for (const engine::quantity& q : symbols.all())
        if (q.definition && q.range.what != engine::domain::kind::real)
            w.term(q.symbol);
    for (const auto& [symbol, text] : claim.assuming) {
        try {
            w.narrow(symbol, engine::parse_domain(text, {}));
        } catch (const std::exception&) {
            return {"", "not expressible: the domain " + text};
        }
    }
    std::vector<std::string> hypotheses;
    for (const smt_relation& h : claim.hypotheses)
        hypotheses.push_back(w.relation_term(h.lhs, h.op, h.rhs));
    std::vector<std::string> where;
    for (const condition& c : claim.where)
        where.push_back(w.condition_term(c));
    // The negation: the claim fails, or a condition said proven does not hold.
    std::vector<std::string> broken;
    if (claim.any_of.empty()) {
        broken.push_back(fmt::format("(not {})", w.relation_term(claim.lhs, claim.op, claim.rhs)));
    } else {
        std::vector<std::string> any;
        for (const smt_relation& r : claim.any_of)
            any.push_back(w.relation_term(r.lhs, r.op, r.rhs));
        broken.push_back(fmt::format("(not (or {}))", fmt::join(any, " ")));
    }
    for (const condition& c : claim.goals)
        broken.push_back(fmt::format("(not {})", w.condition_term(c)));
    std::string text = w.preamble();
    if (!w.failure().empty())
        return {"", w.failure()};
    if (!hypotheses.empty()) {
        text += "; the case's condition\n";
        for (const std::string& h : hypotheses)
            text += fmt::format("(assert {})\n", h);
    }
    if (!where.empty()) {
        text += "; the conditions the claim is promised under (where)\n";
        for (const std::string& h : where)
            text += fmt::format("(assert {})\n", h);
    }
    text += claim.goals.empty() ? "; the claim, negated\n"
                                : "; the claim and the definedness conditions proven for it, one negated\n";
    text += broken.size() == 1 ? fmt::format("(assert {})\n", broken.front())
                               : fmt::format("(assert (or {}))\n", fmt::join(broken, " "));
    // Z3's nlsat procedure (complete for real arithmetic), by name: its default strategy for
    // such problems tries procedures for so many seconds each, so that its answer would hang
    // on the machine's speed; nlsat alone counts its steps against the resource limit.
    text += "(check-sat-using qfnra-nlsat)\n";
    return {text, ""};
}

} // namespace impact::verify
