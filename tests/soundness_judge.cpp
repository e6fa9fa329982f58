// The judge: soundness_judge.h says what it promises. Each value is carried with a bound on
// its rounding error (0 for an exact rational), so that a divisor, radicand or logarithm's
// argument within that bound of 0 leaves the point undecided (skipped) instead of refuting
// or confirming anything.
#include "soundness_judge.h"

#include <algorithm>
#include <cctype>
#include <set>
#include <sstream>
#include <stdexcept>

namespace impact::soundness {

namespace {

using GiNaC::numeric;

// How tightly a term binds as written: sums 1, products and quotients 2, a negation 3,
// powers 4, names, numbers and calls 5. An operand is put in parentheses unless it binds
// as tightly as its place needs, so that the text reads back as the same tree.
int binding(const term& t)
{
    switch (t.what) {
    case term::op::number:
        if (t.value.is_negative())
            return 3;
        return t.value.is_integer() ? 5 : 2;
    case term::op::add:
    case term::op::sub: return 1;
    case term::op::mul:
    case term::op::div: return 2;
    case term::op::neg: return 3;
    case term::op::pow: return 4;
    default: return 5;
    }
}

std::string operand(const term& t, int needs)
{
    return binding(t) >= needs ? text(t) : "(" + text(t) + ")";
}

const char* function_name(term::op f)
{
    switch (f) {
    case term::op::sqrt: return "sqrt";
    case term::op::abs: return "abs";
    case term::op::exp: return "exp";
    case term::op::log: return "log";
    case term::op::sin: return "sin";
    case term::op::cos: return "cos";
    case term::op::conjugate: return "conjugate";
    default: return nullptr;
    }
}

// ---- the parser ------------------------------------------------------------------------

class parser {
public:
    explicit parser(const std::string& s) : s_(s) {}

    relation_claim claim()
    {
        relation_claim c;
        c.lhs = sum();
        skip();
        static const std::pair<const char*, relation> relations[] = {
            {"!=", relation::not_equal}, {"<=", relation::less_equal}, {">=", relation::greater_equal},
            {"==", relation::equal},     {"<", relation::less},        {">", relation::greater},
            {"=", relation::equal}};
        bool found = false;
        for (const auto& [word, r] : relations) {
            if (s_.compare(at_, std::string(word).size(), word) == 0) {
                at_ += std::string(word).size();
                c.rel = r;
                found = true;
                break;
            }
        }
        if (!found)
            fail("a relation");
        c.rhs = sum();
        end();
        return c;
    }

    term whole()
    {
        term t = sum();
        end();
        return t;
    }

private:
    [[noreturn]] void fail(const std::string& wanted) const
    {
        throw std::runtime_error("soundness judge: " + wanted + " wanted at " + std::to_string(at_) + " of '" + s_ +
                                 "'");
    }
    void skip()
    {
        while (at_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[at_])))
            ++at_;
    }
    bool eat(char c)
    {
        skip();
        if (at_ < s_.size() && s_[at_] == c) {
            ++at_;
            return true;
        }
        return false;
    }
    void end()
    {
        skip();
        if (at_ != s_.size())
            fail("the end");
    }
    term sum()
    {
        term t = product();
        for (;;) {
            if (eat('+'))
                t = t + product();
            else if (peek_minus())
                t = t - product();
            else
                return t;
        }
    }
    bool peek_minus()
    {
        skip();
        if (at_ < s_.size() && s_[at_] == '-') {
            ++at_;
            return true;
        }
        return false;
    }
    term product()
    {
        term t = unary();
        for (;;) {
            if (eat('*'))
                t = t * unary();
            else if (eat('/'))
                t = t / unary();
            else
                return t;
        }
    }
    term unary()
    {
        if (eat('-'))
            return -unary();
        if (eat('+'))
            return unary();
        return power();
    }
    term power()
    {
        term base = atom();
        if (eat('^'))
            return pow(base, unary());  // right-associative: a^b^c = a^(b^c); a^-1
        return base;
    }
    term atom()
    {
        skip();
        if (eat('(')) {
            term t = sum();
            if (!eat(')'))
                fail("')'");
            return t;
        }
        if (at_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[at_]))) {
            std::size_t from = at_;
            while (at_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[at_])))
                ++at_;
            return term::number(numeric(s_.substr(from, at_ - from).c_str()));
        }
        if (at_ < s_.size() && (std::isalpha(static_cast<unsigned char>(s_[at_])) || s_[at_] == '_')) {
            std::size_t from = at_;
            while (at_ < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[at_])) || s_[at_] == '_'))
                ++at_;
            const std::string name = s_.substr(from, at_ - from);
            static const std::pair<const char*, term::op> functions[] = {
                {"sqrt", term::op::sqrt}, {"abs", term::op::abs}, {"exp", term::op::exp},
                {"log", term::op::log},   {"sin", term::op::sin}, {"cos", term::op::cos},
                {"conjugate", term::op::conjugate}};
            for (const auto& [word, f] : functions) {
                if (name == word) {
                    if (!eat('('))
                        fail("'(' after " + name);
                    term argument = sum();
                    if (!eat(')'))
                        fail("')'");
                    return call(f, argument);
                }
            }
            if (name == "Pi" || name == "I")
                fail("a name other than " + name);
            return term::symbol(name);
        }
        fail("a number, a name or '('");
    }

    const std::string& s_;
    std::size_t at_ = 0;
};

// ---- evaluation with a bound on rounding -----------------------------------------------

// A value: defined with its error bound, undefined (a side is not a real number there), or
// undecided at this precision (an argument within its rounding of a boundary).
struct value {
    enum class state { defined, undefined, undecided } what = state::defined;
    numeric v;
    numeric err;        // bound on |computed - exact|; 0 when exact
    std::string why;    // undefined or undecided: what

    bool exact() const { return err.is_zero() && v.is_rational(); }
};

value undefined(const std::string& why)
{
    value r;
    r.what = value::state::undefined;
    r.why = why;
    return r;
}

value undecided(const std::string& why)
{
    value r;
    r.what = value::state::undecided;
    r.why = why;
    return r;
}

struct evaluation {
    const std::map<std::string, numeric>& point;
    const std::map<std::string, term>& defined;
    int digits;
    numeric unit;   // relative size of a rounding: 10^-(digits - 3)
    int depth = 0;

    numeric ulp(const numeric& v) const { return v.is_rational() ? numeric(0) : GiNaC::abs(v) * unit; }

    // A float result v of a monotone function f at x ± e: its error bound.
    template <typename F>
    numeric spread(const F& f, const numeric& x, const numeric& e, const numeric& v) const
    {
        if (e.is_zero())
            return ulp(v);
        return std::max(GiNaC::abs(f(x + e) - v), GiNaC::abs(f(x - e) - v)) + ulp(v) + GiNaC::abs(v) * unit;
    }

    // The sign of a value, when its error bound decides it: -1, 0, 1, or none.
    static std::optional<int> sign(const value& x)
    {
        if (x.exact())
            return x.v.is_zero() ? 0 : (x.v.is_positive() ? 1 : -1);
        if (GiNaC::abs(x.v) > x.err)
            return x.v.is_positive() ? 1 : -1;
        return std::nullopt;
    }

    value finish(numeric v, numeric err) const
    {
        if (!v.is_real())
            return undefined("a value that is not real");
        value r;
        r.v = v;
        r.err = err;
        return r;
    }

    value operator()(const term& t)
    {
        switch (t.what) {
        case term::op::number: return finish(t.value, 0);
        case term::op::symbol: {
            if (auto at = point.find(t.name); at != point.end())
                return finish(at->second, 0);
            if (auto def = defined.find(t.name); def != defined.end()) {
                if (++depth > 20)
                    throw std::runtime_error("soundness judge: " + t.name + " defined in terms of itself");
                value v = (*this)(def->second);
                --depth;
                if (v.what != value::state::defined)
                    v.why = t.name + " = " + text(def->second) + ": " + v.why;
                return v;
            }
            throw std::runtime_error("soundness judge: no value for " + t.name);
        }
        default: break;
        }
        std::vector<value> a;
        for (const term& arg : t.args) {
            a.push_back((*this)(arg));
            if (a.back().what != value::state::defined)
                return a.back();
        }
        switch (t.what) {
        case term::op::add: {
            numeric v = a[0].v + a[1].v;
            return finish(v, a[0].err + a[1].err + ulp(v));
        }
        case term::op::sub: {
            numeric v = a[0].v - a[1].v;
            return finish(v, a[0].err + a[1].err + ulp(v));
        }
        case term::op::neg: return finish(-a[0].v, a[0].err);
        case term::op::mul: {
            numeric v = a[0].v * a[1].v;
            return finish(v, GiNaC::abs(a[0].v) * a[1].err + GiNaC::abs(a[1].v) * a[0].err + a[0].err * a[1].err +
                                 ulp(v));
        }
        case term::op::div: {
            const std::optional<int> s = sign(a[1]);
            if (!s)
                return undecided("a divisor within its rounding of 0: " + text(t.args[1]));
            if (*s == 0)
                return undefined("the divisor " + text(t.args[1]) + " is 0");
            numeric v = a[0].v / a[1].v;
            const numeric b = GiNaC::abs(a[1].v);
            return finish(v, (GiNaC::abs(a[0].v) * a[1].err + b * a[0].err) / (b * (b - a[1].err)) + ulp(v));
        }
        case term::op::abs: return finish(GiNaC::abs(a[0].v), a[0].err);
        case term::op::conjugate: return a[0];   // real: its own conjugate
        case term::op::pow: return power(t, a[0], a[1]);
        case term::op::sqrt: return power(t, a[0], finish(numeric(1, 2), 0));
        case term::op::exp: {
            if (GiNaC::abs(a[0].v) > 100000)
                return undecided("exp of a value beyond 10^5");
            const auto f = [](const numeric& x) { return GiNaC::exp(x); };
            numeric v = a[0].v.is_zero() ? numeric(1) : f(a[0].v);
            return finish(v, spread(f, a[0].v, a[0].err, v));
        }
        case term::op::log: {
            const std::optional<int> s = sign(a[0]);
            if (!s)
                return undecided("the argument of log within its rounding of 0: " + text(t.args[0]));
            if (*s <= 0)
                return undefined("the argument of log " + text(t.args[0]) + " is not > 0");
            if (a[0].exact() && a[0].v == 1)
                return finish(0, 0);
            const auto f = [](const numeric& x) { return GiNaC::log(x); };
            numeric v = f(a[0].v);
            return finish(v, spread(f, a[0].v, a[0].err, v));
        }
        case term::op::sin:
        case term::op::cos: {
            const bool is_sin = t.what == term::op::sin;
            if (a[0].v.is_zero() && a[0].exact())
                return finish(is_sin ? 0 : 1, 0);
            numeric v = is_sin ? GiNaC::sin(a[0].v) : GiNaC::cos(a[0].v);
            return finish(v, a[0].err + ulp(v) + unit);
        }
        default: throw std::runtime_error("soundness judge: an operation it does not evaluate");
        }
    }

    // base^exponent: an integer power of any base (not 0 under a negative one); a fractional
    // power, GiNaC's principal root, real only for a base >= 0 (> 0 under a negative one).
    value power(const term& t, const value& base, const value& exponent)
    {
        if (!exponent.exact())
            return undecided("an exponent that is not a rational number: " + text(t));
        const numeric e = exponent.v;
        const std::optional<int> s = sign(base);
        if (e.is_integer()) {
            if (e.is_zero())
                return finish(1, 0);
            if (e.is_negative() && !s)
                return undecided("a base within its rounding of 0 under a negative power: " + text(t));
            if (e.is_negative() && *s == 0)
                return undefined("0 to a negative power: " + text(t));
            if (GiNaC::abs(e) > 400)
                return undecided("a power beyond 400");
            numeric v = base.v.power(e);
            if (base.err.is_zero())
                return finish(v, ulp(v));
            // |b|^n is monotone in |b|: bound it at |b| +- err.
            const numeric b = GiNaC::abs(base.v);
            const numeric hi = (b + base.err).power(GiNaC::abs(e));
            const numeric lo = b > base.err ? (b - base.err).power(GiNaC::abs(e)) : numeric(0);
            numeric err;
            if (e.is_positive())
                err = std::max(hi - GiNaC::abs(v), GiNaC::abs(v) - lo);
            else  // |v| = 1/|b|^n, b clearly away from 0
                err = std::max(GiNaC::abs(v) - 1 / hi, 1 / lo - GiNaC::abs(v));
            return finish(v, err + ulp(v));
        }
        if (!s)
            return undecided("the base of a fractional power within its rounding of 0: " + text(t));
        if (*s < 0)
            return undefined("a fractional power of a negative base: " + text(t));
        if (*s == 0) {
            if (e.is_negative())
                return undefined("0 to a negative power: " + text(t));
            return finish(0, 0);
        }
        const auto f = [&](const numeric& x) { return x.is_positive() ? x.power(e) : numeric(0); };
        numeric v = base.v.power(e);
        if (base.err.is_zero())
            return finish(v, ulp(v));
        if (base.v - base.err <= 0 && e.is_negative())
            return undecided("a base within its rounding of 0 under a negative power: " + text(t));
        return finish(v, spread(f, base.v, base.err, v));
    }
};

// Digits set for a scope, and set back.
struct digits_scope {
    explicit digits_scope(long d) : saved(GiNaC::Digits) { GiNaC::Digits = d; }
    ~digits_scope() { GiNaC::Digits = saved; }
    long saved;
};

// Whether a relation holds between two defined values at this precision. Two values within
// their error bounds of each other (16 times over), or within 10^-(digits - 10) relative to
// their size, are taken as equal: the bounds carry the rounding of what cancelled (z e^100 -
// (w + e^100) is -w, though e^100 is 10^43: a tolerance relative to the sides' size, 10^-40
// of 10^43, would call -31/13 and 0 equal).
std::optional<bool> holds(relation rel, const value& l, const value& r, int digits)
{
    int s;
    if (l.exact() && r.exact()) {
        const numeric d = l.v - r.v;
        s = d.is_zero() ? 0 : (d.is_positive() ? 1 : -1);
    } else {
        const numeric d = l.v - r.v;
        const numeric size = std::max(GiNaC::abs(l.v), GiNaC::abs(r.v));
        const numeric tolerance =
            std::max(16 * (l.err + r.err), size * numeric(1) / numeric(10).power(digits - 10));
        s = GiNaC::abs(d) <= tolerance ? 0 : (d.is_positive() ? 1 : -1);
    }
    switch (rel) {
    case relation::equal: return s == 0;
    case relation::not_equal: return s != 0;
    case relation::less: return s < 0;
    case relation::less_equal: return s <= 0;
    case relation::greater: return s > 0;
    case relation::greater_equal: return s >= 0;
    }
    return std::nullopt;
}

// What a relation comes to at a point, at one precision.
struct at_point {
    enum class state { holds, fails, undefined, undecided } what = state::undecided;
    std::string why;
};

at_point evaluate(const relation_claim& c, const std::map<std::string, numeric>& point,
                  const std::map<std::string, term>& defined, int digits)
{
    const digits_scope scope(digits);
    evaluation eval{point, defined, digits, numeric(1) / numeric(10).power(digits - 3)};
    value l, r;
    try {
        l = eval(c.lhs);
        r = eval(c.rhs);
    } catch (const std::runtime_error& e) {
        // CLN's underflow (exp(-10^5)), or a name without a value: not decided here.
        if (std::string(e.what()).rfind("soundness judge", 0) == 0)
            throw;
        return {at_point::state::undecided, e.what()};
    }
    for (const value* v : {&l, &r}) {
        if (v->what == value::state::undecided)
            return {at_point::state::undecided, v->why};
    }
    for (const value* v : {&l, &r}) {
        if (v->what == value::state::undefined)
            return {at_point::state::undefined, std::string(v == &l ? "the left side" : "the right side") +
                                                    " is undefined or not real: " + v->why};
    }
    const std::optional<bool> h = holds(c.rel, l, r, digits);
    if (!h)
        return {at_point::state::undecided, "rounding"};
    std::ostringstream values;
    values << "left " << GiNaC::ex(l.v) << ", right " << GiNaC::ex(r.v);
    return {*h ? at_point::state::holds : at_point::state::fails, values.str()};
}

std::string point_text(const std::map<std::string, numeric>& point)
{
    std::ostringstream out;
    bool first = true;
    for (const auto& [name, v] : point) {
        out << (first ? "" : ", ") << name << " = " << GiNaC::ex(v);
        first = false;
    }
    return out.str();
}

// A value drawn from a domain: a simple one (0, +-1, 2, 1/2, the ends), a value another
// symbol already has (x = y makes x - y a divisor of 0), a rational, or a large or small one.
numeric draw_value(const domain& d, const std::vector<numeric>& taken, std::mt19937_64& rng)
{
    const auto below = [&](std::uint64_t n) { return static_cast<std::int64_t>(rng() % n); };
    for (int attempt = 0; attempt < 40; ++attempt) {
        numeric x;
        const std::int64_t kind = below(100);
        if (kind < 20 && !taken.empty()) {
            x = taken[below(taken.size())];
            if (below(3) == 0)
                x = -x;
        } else if (kind < 55) {
            std::vector<numeric> simple = {0, 1, -1, 2, -2, numeric(1, 2), numeric(-1, 2), 3, -3, numeric(1, 3), 10, -10};
            if (d.low)
                simple.push_back(*d.low);
            if (d.high)
                simple.push_back(*d.high);
            if (d.low && d.high)
                simple.push_back((*d.low + *d.high) / 2);
            x = simple[below(simple.size())];
        } else if (kind < 90) {
            if (d.low && d.high) {
                const std::int64_t n = 1 + below(60);
                x = *d.low + (*d.high - *d.low) * numeric(below(n + 1)) / numeric(n);
            } else {
                x = numeric(1 + below(100)) / numeric(1 + below(20));
                if (below(2) == 0)
                    x = -x;
                if (d.low && !d.high)
                    x = *d.low + GiNaC::abs(x);
                if (d.high && !d.low)
                    x = *d.high - GiNaC::abs(x);
            }
        } else {
            x = numeric(10).power(numeric(3 + below(7)));
            if (below(2) == 0)
                x = 1 / x;
            if (below(2) == 0)
                x = -x;
        }
        if (d.contains(x))
            return x;
    }
    // An inner point: the middle of an interval, else a point beside its end.
    if (d.low && d.high)
        return (*d.low + *d.high) / 2;
    if (d.low)
        return *d.low + 1;
    if (d.high)
        return *d.high - 1;
    return 1;
}

std::map<std::string, numeric> draw_point(const problem& p, std::mt19937_64& rng)
{
    std::map<std::string, numeric> point;
    std::vector<numeric> taken;
    for (const auto& [name, d] : p.inputs) {
        numeric x = draw_value(d, taken, rng);
        point[name] = x;
        taken.push_back(x);
    }
    return point;
}

} // namespace

term term::number(const GiNaC::numeric& v)
{
    term t;
    t.what = op::number;
    t.value = v;
    return t;
}

term term::symbol(const std::string& name)
{
    term t;
    t.what = op::symbol;
    t.name = name;
    return t;
}

term term::of(op what, std::vector<term> args)
{
    term t;
    t.what = what;
    t.args = std::move(args);
    return t;
}

term operator+(const term& a, const term& b) { return term::of(term::op::add, {a, b}); }
term operator-(const term& a, const term& b) { return term::of(term::op::sub, {a, b}); }
term operator*(const term& a, const term& b) { return term::of(term::op::mul, {a, b}); }
term operator/(const term& a, const term& b) { return term::of(term::op::div, {a, b}); }
term operator-(const term& a) { return term::of(term::op::neg, {a}); }
term pow(const term& base, const term& exponent) { return term::of(term::op::pow, {base, exponent}); }
term pow(const term& base, int numerator, int denominator)
{
    return pow(base, term::number(numeric(numerator, denominator)));
}
term call(term::op function, const term& argument) { return term::of(function, {argument}); }

std::string text(const term& t)
{
    switch (t.what) {
    case term::op::number: {
        std::ostringstream out;
        out << GiNaC::ex(t.value);
        return out.str();
    }
    case term::op::symbol: return t.name;
    case term::op::add: return text(t.args[0]) + " + " + operand(t.args[1], 2);
    case term::op::sub: return text(t.args[0]) + " - " + operand(t.args[1], 2);
    case term::op::mul: return operand(t.args[0], 2) + "*" + operand(t.args[1], 4);
    case term::op::div: return operand(t.args[0], 2) + "/" + operand(t.args[1], 4);
    case term::op::pow: return operand(t.args[0], 5) + "^" + operand(t.args[1], 5);
    case term::op::neg: return "-" + operand(t.args[0], 5);
    default: return std::string(function_name(t.what)) + "(" + text(t.args[0]) + ")";
    }
}

std::string text(relation r)
{
    switch (r) {
    case relation::equal: return "=";
    case relation::not_equal: return "!=";
    case relation::less: return "<";
    case relation::less_equal: return "<=";
    case relation::greater: return ">";
    case relation::greater_equal: return ">=";
    }
    return "?";
}

std::string text(const relation_claim& c) { return text(c.lhs) + " " + text(c.rel) + " " + text(c.rhs); }

relation_claim parse_relation(const std::string& s) { return parser(s).claim(); }
term parse_term(const std::string& s) { return parser(s).whole(); }

bool domain::contains(const GiNaC::numeric& x) const
{
    if (low && (low_open ? x <= *low : x < *low))
        return false;
    if (high && (high_open ? x >= *high : x > *high))
        return false;
    return true;
}

domain parse_domain(const std::string& s)
{
    domain d;
    if (s.empty() || s == "real")
        return d;
    if (s == "positive" || s == "nonnegative") {
        d.low = numeric(0);
        d.low_open = s == "positive";
        return d;
    }
    const std::size_t comma = s.find(',');
    if (s.size() < 5 || comma == std::string::npos || (s.front() != '[' && s.front() != '(') ||
        (s.back() != ']' && s.back() != ')'))
        throw std::runtime_error("soundness judge: a domain it does not read: " + s);
    const auto end = [](std::string e) -> std::optional<numeric> {
        e.erase(std::remove(e.begin(), e.end(), ' '), e.end());
        if (e == "+inf" || e == "-inf" || e == "inf")
            return std::nullopt;
        const std::size_t slash = e.find('/');
        if (slash == std::string::npos)
            return numeric(e.c_str());
        return numeric(e.substr(0, slash).c_str()) / numeric(e.substr(slash + 1).c_str());
    };
    d.low = end(s.substr(1, comma - 1));
    d.high = end(s.substr(comma + 1, s.size() - comma - 2));
    d.low_open = s.front() == '(';
    d.high_open = s.back() == ')';
    return d;
}

problem read_problem(const spec::derivation& file)
{
    problem p;
    std::set<std::string> derived;
    for (const spec::step& s : file.steps) {
        if (s.what != spec::step::kind::define || !s.cases.empty())
            throw std::runtime_error("soundness judge: a step other than `define` by an expression");
        p.defined[s.name.value] = parse_term(s.expression.value);
        derived.insert(s.name.value);
    }
    for (const spec::symbol& s : file.symbols) {
        if (s.definition)
            p.defined[s.name.value] = parse_term(s.definition->value);
        else if (!derived.count(s.name.value))
            p.inputs.emplace_back(s.name.value, parse_domain(s.domain.value));
    }
    for (const spec::check& c : file.checks) {
        if (!c.at.empty() || !c.left_at.empty() || c.limit || !c.assuming.empty() || c.continuity)
            throw std::runtime_error("soundness judge: a check with `at`, `limit`, `assuming` or continuity");
        p.claims[c.name.value] = parse_relation(c.claim.value);
    }
    return p;
}

judgement judge(const problem& p, const relation_claim& claim, const engine::verdict& outcome, std::mt19937_64& rng,
                const judge_options& options)
{
    judgement j;
    if (outcome.what == engine::verdict::status::failed)
        return j;
    std::vector<relation_claim> where;
    for (const engine::condition& c : outcome.where)
        where.push_back(parse_relation(c.text));
    for (std::size_t draw = 0; draw < options.draws && j.points < options.wanted; ++draw) {
        const std::map<std::string, numeric> point = draw_point(p, rng);
        const auto inside = [&](int digits) {
            for (const relation_claim& c : where)
                if (evaluate(c, point, p.defined, digits).what != at_point::state::holds)
                    return false;
            return true;
        };
        if (!inside(60))
            continue;
        const at_point a = evaluate(claim, point, p.defined, 60);
        if (a.what == at_point::state::undecided)
            continue;
        ++j.points;
        if (a.what == at_point::state::holds)
            continue;
        // Believed only when 120 digits say the same.
        const at_point again = evaluate(claim, point, p.defined, 120);
        if (again.what != a.what || !inside(120))
            continue;
        ++j.refutable;
        if (j.sound) {
            j.sound = false;
            j.why = "at " + point_text(point) + ": " +
                    (a.what == at_point::state::fails ? "the claim is false (" + again.why + ")" : again.why);
        }
    }
    return j;
}

truth sample_truth(const problem& p, const relation_claim& claim, std::mt19937_64& rng, std::size_t draws)
{
    truth t;
    for (std::size_t draw = 0; draw < draws; ++draw) {
        const at_point a = evaluate(claim, draw_point(p, rng), p.defined, 60);
        if (a.what == at_point::state::holds || a.what == at_point::state::fails)
            ++t.defined;
        if (a.what == at_point::state::fails)
            ++t.false_at;
    }
    return t;
}

} // namespace impact::soundness
