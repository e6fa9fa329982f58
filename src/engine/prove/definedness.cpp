// Where an expression is defined in the reals (definedness.h): conditions read off a GiNaC
// expression and off a text as written, proven from the domains or attached.
#include "engine/prove/definedness.h"

#include <fmt/format.h>

#include <algorithm>
#include <optional>

namespace impact::engine {
namespace {

const char* relation_text(condition::kind need)
{
    switch (need) {
    case condition::kind::nonzero: return "!=";
    case condition::kind::positive: return ">";
    case condition::kind::nonnegative: return ">=";
    }
    return "!=";
}

bool negative_term(const GiNaC::ex& t)
{
    if (GiNaC::is_a<GiNaC::numeric>(t))
        return GiNaC::ex_to<GiNaC::numeric>(t).is_negative();
    if (GiNaC::is_a<GiNaC::mul>(t)) {
        const GiNaC::ex last = t.op(t.nops() - 1);
        return GiNaC::is_a<GiNaC::numeric>(last) && GiNaC::ex_to<GiNaC::numeric>(last).is_negative();
    }
    return false;
}

// Whether a condition with no symbols holds (evaluated at 40 digits); none when it cannot
// be evaluated.
std::optional<bool> holds_as_number(const GiNaC::ex& e, condition::kind need)
{
    struct digits_kept {
        decltype(GiNaC::Digits) saved = GiNaC::Digits;
        ~digits_kept() { GiNaC::Digits = saved; }
    } kept;
    try {
        GiNaC::Digits = 40;
        const GiNaC::ex v = GiNaC::evalf(e);
        if (!GiNaC::is_a<GiNaC::numeric>(v) || !GiNaC::ex_to<GiNaC::numeric>(v).is_real())
            return false;
        const GiNaC::numeric& x = GiNaC::ex_to<GiNaC::numeric>(v);
        switch (need) {
        case condition::kind::nonzero: return !x.is_zero();
        case condition::kind::positive: return x.is_positive();
        case condition::kind::nonnegative: return !x.is_negative();
        }
    } catch (const std::exception&) {
    }
    return std::nullopt;
}

bool has_symbols(const GiNaC::ex& e)
{
    for (GiNaC::const_preorder_iterator it = e.preorder_begin(); it != e.preorder_end(); ++it)
        if (GiNaC::is_a<GiNaC::symbol>(*it))
            return true;
    return false;
}

// Collects conditions, each a divisor split into its factors (b^2 != 0 is b != 0).
class collector {
public:
    explicit collector(const symbol_table& symbols) : symbols_(symbols) {}

    void need(const GiNaC::ex& e, condition::kind kind, const char* because)
    {
        if (kind == condition::kind::nonzero) {
            nonzero(e, because);
            return;
        }
        add(e, kind, because);
    }

    // The conditions of a power base^exponent.
    void power(const GiNaC::ex& base, const GiNaC::ex& exponent)
    {
        if (GiNaC::is_a<GiNaC::numeric>(exponent)) {
            const GiNaC::numeric& k = GiNaC::ex_to<GiNaC::numeric>(exponent);
            if (!k.is_real())
                return;
            if (k.is_integer()) {
                if (k.is_negative())
                    need(base, condition::kind::nonzero, "a divisor");
                return;
            }
            const bool root = k.is_rational() && k.denom() == 2;
            need(base, k.is_negative() ? condition::kind::positive : condition::kind::nonnegative,
                 root ? "a radicand" : "the base of a fractional power");
            return;
        }
        need(base, condition::kind::positive, "the base of a power with a symbolic exponent");
    }

    // The conditions of a function's call.
    void call(const std::string& name, const GiNaC::exvector& args)
    {
        if (args.size() == 1) {
            const GiNaC::ex& u = args[0];
            if (name == "log")
                need(u, condition::kind::positive, "the argument of log");
            else if (name == "acos" || name == "asin")
                need(1 - GiNaC::pow(u, 2), condition::kind::nonnegative,
                     name == "acos" ? "the argument of acos, in [-1, 1]" : "the argument of asin, in [-1, 1]");
            else if (name == "acosh")
                need(u - 1, condition::kind::nonnegative, "the argument of acosh, >= 1");
            else if (name == "atanh")
                need(1 - GiNaC::pow(u, 2), condition::kind::positive, "the argument of atanh, in (-1, 1)");
            else if (name == "tan")
                need(GiNaC::cos(u), condition::kind::nonzero, "a divisor (tan = sin/cos)");
            else if (name == "sqrt")
                power(u, GiNaC::numeric(1, 2));
        } else if (args.size() == 2) {
            if (name == "atan2")
                need(GiNaC::pow(args[0], 2) + GiNaC::pow(args[1], 2), condition::kind::nonzero,
                     "atan2's arguments, not both 0");
            else if (name == "pow")
                power(args[0], args[1]);
        }
    }

    // In the order of their texts: GiNaC's order of a product's factors, or a sum's terms,
    // changes from run to run, and the conditions must not.
    std::vector<condition> take()
    {
        std::stable_sort(found_.begin(), found_.end(),
                         [](const condition& a, const condition& b) { return a.text < b.text; });
        return std::move(found_);
    }

private:
    void nonzero(const GiNaC::ex& e, const char* because)
    {
        if (GiNaC::is_a<GiNaC::mul>(e)) {
            for (std::size_t i = 0; i < e.nops(); ++i)
                nonzero(e.op(i), because);
            return;
        }
        if (GiNaC::is_a<GiNaC::power>(e) && GiNaC::is_a<GiNaC::numeric>(e.op(1)) &&
            GiNaC::ex_to<GiNaC::numeric>(e.op(1)).is_positive()) {
            nonzero(e.op(0), because);
            return;
        }
        add(e, condition::kind::nonzero, because);
    }

    void add(const GiNaC::ex& e, condition::kind kind, const char* because)
    {
        if (!has_symbols(e)) {
            const std::optional<bool> holds = holds_as_number(e, kind);
            if (holds.value_or(false))
                return;
        }
        // A divisor written with a leading minus is the same divisor.
        GiNaC::ex expr = e;
        if (kind == condition::kind::nonzero && symbols_.text(expr).rfind('-', 0) == 0)
            expr = -expr;
        condition c{expr, kind, condition_text(expr, kind, symbols_), because};
        add_conditions(found_, {c});
    }

    const symbol_table& symbols_;
    std::vector<condition> found_;
};

void walk(const GiNaC::ex& e, collector& out)
{
    if (GiNaC::is_a<GiNaC::power>(e)) {
        out.power(e.op(0), e.op(1));
    } else if (GiNaC::is_a<GiNaC::function>(e)) {
        GiNaC::exvector args(e.begin(), e.end());
        out.call(GiNaC::ex_to<GiNaC::function>(e).get_name(), args);
    }
    for (std::size_t i = 0; i < e.nops(); ++i)
        walk(e.op(i), out);
}

// The value of a written node, its conditions collected on the way; none where the text
// holds something this walk does not follow (an unknown function).
std::optional<GiNaC::ex> walk(const written_form::node& n, collector& out)
{
    using kind = written_form::node::kind;
    std::vector<GiNaC::ex> values;
    for (const written_form::node& child : n.children) {
        std::optional<GiNaC::ex> v = walk(child, out);
        if (!v)
            return std::nullopt;
        values.push_back(*v);
    }
    switch (n.what) {
    case kind::atom: return n.value;
    case kind::group: return values.at(0);
    case kind::negate: return -values.at(0);
    case kind::relation: return GiNaC::ex(0);
    case kind::sum: {
        GiNaC::ex sum = 0;
        for (std::size_t i = 0; i < values.size(); ++i)
            sum += n.flags.at(i) ? -values[i] : values[i];
        return sum;
    }
    case kind::product: {
        GiNaC::ex product = 1;
        for (std::size_t i = 0; i < values.size(); ++i) {
            if (n.flags.at(i)) {
                out.need(values[i], condition::kind::nonzero, "a divisor");
                product /= values[i];
            } else {
                product *= values[i];
            }
        }
        return product;
    }
    case kind::power:
        out.power(values.at(0), values.at(1));
        return GiNaC::pow(values.at(0), values.at(1));
    case kind::call: {
        out.call(n.name, values);
        if (n.name == "sqrt" && values.size() == 1)
            return GiNaC::sqrt(values[0]);
        if (n.name == "pow" && values.size() == 2)
            return GiNaC::pow(values[0], values[1]);
        try {
            GiNaC::exvector args(values.begin(), values.end());
            return GiNaC::ex(GiNaC::function(GiNaC::function::find_function(n.name, values.size()), args));
        } catch (const std::exception&) {
            return std::nullopt;
        }
    }
    }
    return std::nullopt;
}

// Whether `e` has at most `limit` nodes: small enough to compare by expanding.
bool small(const GiNaC::ex& e, std::size_t limit = 64)
{
    std::size_t n = 0;
    for (GiNaC::const_preorder_iterator it = e.preorder_begin(); it != e.preorder_end(); ++it)
        if (++n > limit)
            return false;
    return true;
}

// The same condition (e and -e are one divisor); large expressions are compared as they
// stand, small ones expanded.
bool same_condition(const condition& a, const condition& b)
{
    if (a.need != b.need)
        return false;
    if (a.expr.is_equal(b.expr) || (a.need == condition::kind::nonzero && a.expr.is_equal(-b.expr)))
        return true;
    if (!small(a.expr) || !small(b.expr))
        return false;
    try {
        if (GiNaC::expand(a.expr - b.expr).is_zero())
            return true;
        return a.need == condition::kind::nonzero && GiNaC::expand(a.expr + b.expr).is_zero();
    } catch (const std::exception&) {
        return false;
    }
}

// Whether `e` is, up to a positive factor, the radicand of an abbreviation declared
// positive (d = sqrt(r_x^2 + r_y^2 + r_z^2), d > 0: so r_x^2 + r_y^2 + r_z^2 > 0).
bool radicand_of_a_positive_root(const GiNaC::ex& e, const assumptions& given)
{
    for (const assumptions::assumed_sign& a : given.assumed) {
        if (!a.range.is_positive() || !GiNaC::is_a<GiNaC::power>(a.definition) ||
            !a.definition.op(1).is_equal(GiNaC::numeric(1, 2)))
            continue;
        const GiNaC::ex ratio = GiNaC::normal(GiNaC::expand(e) / a.definition.op(0));
        if (GiNaC::is_a<GiNaC::numeric>(ratio) && GiNaC::ex_to<GiNaC::numeric>(ratio).is_positive())
            return true;
    }
    return false;
}

bool proven(const condition& c, const assumptions& given)
{
    try {
        if (radicand_of_a_positive_root(c.expr, given))
            return true;
        const sign_set s = prove_sign(c.expr, given).sign;
        switch (c.need) {
        case condition::kind::nonzero: return !s.zero;
        case condition::kind::positive: return s.is_positive();
        case condition::kind::nonnegative: return s.is_nonnegative();
        }
    } catch (const std::exception&) {
    }
    return false;
}

// Whether the domains prove the condition false everywhere.
bool refuted(const condition& c, const assumptions& given)
{
    if (c.need == condition::kind::nonzero)
        return false;
    try {
        const sign_set s = prove_sign(c.expr, given).sign;
        return c.need == condition::kind::positive ? !s.positive : !s.positive && !s.zero;
    } catch (const std::exception&) {
        return false;
    }
}

// `range` with the values the condition on its symbol excludes taken out, or none when it
// cannot say (x != 0 for a real x).
std::optional<domain> narrowed(domain range, condition::kind need)
{
    const bool strict = need != condition::kind::nonnegative;
    switch (range.what) {
    case domain::kind::real:
        if (need == condition::kind::nonzero)
            return std::nullopt;
        range.what = strict ? domain::kind::positive : domain::kind::nonnegative;
        return range;
    case domain::kind::nonnegative:
        if (strict)
            range.what = domain::kind::positive;
        return range;
    case domain::kind::positive: return range;
    case domain::kind::interval:
        if (need == condition::kind::nonzero) {
            if (range.lower == 0 && !range.lower_open)
                range.lower_open = true;
            else if (range.upper == 0 && !range.upper_open)
                range.upper_open = true;
            else
                return std::nullopt;
            return range;
        }
        if (range.lower < 0 || (range.lower == 0 && strict && !range.lower_open)) {
            range.lower = 0;
            range.lower_text = "0";
            range.lower_open = strict;
        }
        return range;
    }
    return std::nullopt;
}

} // namespace

std::pair<GiNaC::ex, GiNaC::ex> condition_sides(const GiNaC::ex& expr)
{
    GiNaC::ex left = 0, right = 0;
    const std::size_t terms = GiNaC::is_a<GiNaC::add>(expr) ? expr.nops() : 1;
    for (std::size_t i = 0; i < terms; ++i) {
        const GiNaC::ex term = GiNaC::is_a<GiNaC::add>(expr) ? expr.op(i) : expr;
        if (negative_term(term))
            right -= term;
        else
            left += term;
    }
    return {left, right};
}

std::string condition_text(const GiNaC::ex& expr, condition::kind need, const symbol_table& symbols)
{
    const auto [left, right] = condition_sides(expr);
    return fmt::format("{} {} {}", symbols.text(left), relation_text(need), symbols.text(right));
}

std::vector<condition> definedness(const GiNaC::ex& e, const symbol_table& symbols)
{
    collector out(symbols);
    walk(e, out);
    return out.take();
}

std::vector<condition> definedness(const written_form& written, const symbol_table& symbols)
{
    collector out(symbols);
    if (written.tree()) {
        try {
            walk(*written.tree(), out);
        } catch (const std::exception&) {
            // a part GiNaC cannot build (1/0): the parse itself reports it
        }
    }
    return out.take();
}

void add_conditions(std::vector<condition>& into, const std::vector<condition>& more)
{
    // Of two that are one condition written in two forms (a radicand rotated and as
    // declared), the shorter text is kept, then the first in the order of texts: which comes
    // first follows GiNaC's order of terms, which changes from run to run.
    const auto plainer = [](const condition& a, const condition& b) {
        return a.text.size() != b.text.size() ? a.text.size() < b.text.size() : a.text < b.text;
    };
    for (const condition& c : more) {
        const auto same = std::find_if(into.begin(), into.end(), [&](const condition& d) { return same_condition(c, d); });
        if (same == into.end())
            into.push_back(c);
        else if (plainer(c, *same))
            *same = c;
    }
}

std::vector<condition> rewritten(const std::vector<condition>& needs,
                                 const std::function<GiNaC::ex(const GiNaC::ex&)>& into, const symbol_table& symbols)
{
    collector out(symbols);
    for (const condition& c : needs) {
        GiNaC::ex e = c.expr;
        try {
            e = into(c.expr);
        } catch (const std::exception&) {
            e = 0;   // undefined at the values put in
        }
        out.need(e, c.need, c.because.c_str());
    }
    return out.take();
}

settled_conditions settle(const std::vector<condition>& needs, const assumptions& given)
{
    // Conditions on one symbol first: they narrow its domain for the others.
    // Conditions on one symbol first: they narrow its domain for the others; then the
    // strict ones, which imply the others (r^2 > 0 gives r^2 != 0 and r^2 >= 0).
    const auto rank = [](const condition& c) {
        const int strength = c.need == condition::kind::positive ? 0 : c.need == condition::kind::nonnegative ? 1 : 2;
        return (GiNaC::is_a<GiNaC::symbol>(c.expr) ? 0 : 3) + strength;
    };
    std::vector<condition> ordered = needs;
    // Within a rank in the order of their texts: what is gathered from several quantities
    // comes in GiNaC's order of them, which changes from run to run.
    std::stable_sort(ordered.begin(), ordered.end(), [&](const condition& a, const condition& b) {
        return rank(a) != rank(b) ? rank(a) < rank(b) : a.text < b.text;
    });
    settled_conditions out;
    assumptions under = given;
    const auto implied = [&](const condition& c) {
        for (const condition& a : out.attached)
            if (a.expr.is_equal(c.expr) || (c.need == condition::kind::nonzero && a.expr.is_equal(-c.expr)))
                if (a.need == condition::kind::positive || a.need == c.need)
                    return true;
        return false;
    };
    for (condition c : ordered) {
        // A divisor the domains prove >= 0 (a sum of squares) is not 0 where it is > 0: said so,
        // as its root's radicand is.
        if (c.need == condition::kind::nonzero && !proven(c, under)) {
            condition stronger = c;
            stronger.need = condition::kind::positive;
            if (proven({c.expr, condition::kind::nonnegative, "", ""}, under)) {
                const std::size_t at = stronger.text.find(" != ");
                if (at != std::string::npos)
                    stronger.text.replace(at, 4, " > ");
                c = stronger;
            }
        }
        if (implied(c))
            continue;   // said already, by a stronger condition on the same expression
        if (proven(c, under)) {
            out.proven.push_back(c);
            continue;
        }
        if (refuted(c, under))
            out.never.push_back(c);
        out.attached.push_back(c);
        under = where(under, {c});
    }
    return out;
}

assumptions where(const assumptions& given, const std::vector<condition>& attached)
{
    if (attached.empty())
        return given;
    assumptions under = given;
    under.known = std::make_shared<worked_out>();
    for (const condition& c : attached) {
        under.where.push_back(c);
        if (GiNaC::is_a<GiNaC::symbol>(c.expr)) {
            const auto d = under.domains.find(c.expr);
            if (d != under.domains.end())
                if (std::optional<domain> range = narrowed(d->second, c.need))
                    d->second = *range;
            continue;
        }
        if (c.need == condition::kind::nonzero)
            continue;
        domain range;
        range.what = c.need == condition::kind::positive ? domain::kind::positive : domain::kind::nonnegative;
        under.assumed.push_back({GiNaC::symbol("where_" + std::to_string(under.assumed.size())),
                                 GiNaC::expand(c.expr), range});
    }
    return under;
}

bool hold_at(const std::vector<condition>& conditions, const GiNaC::exmap& point)
{
    for (const condition& c : conditions) {
        GiNaC::ex at;
        try {
            at = c.expr.subs(point, GiNaC::subs_options::no_pattern);
        } catch (const std::exception&) {
            return false;
        }
        if (!holds_as_number(at, c.need).value_or(false))
            return false;
    }
    return true;
}

std::string to_string(const std::vector<condition>& conditions)
{
    std::vector<std::string> texts;
    for (const condition& c : conditions)
        texts.push_back(c.text);
    return fmt::format("{}", fmt::join(texts, ", "));
}

} // namespace impact::engine
