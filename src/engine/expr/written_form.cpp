#include "engine/expr/written_form.h"

#include <cctype>
#include <memory>
#include <stdexcept>

namespace impact::engine {
namespace {

// The text split into tokens, each with the place it starts and ends.
struct token {
    enum class kind { number, name, op, relation, end };
    kind what = kind::end;
    std::string text;
    std::size_t begin = 0;
    std::size_t end = 0;
};

std::vector<token> tokenize(const std::string& s)
{
    std::vector<token> out;
    std::size_t i = 0;
    while (i < s.size()) {
        const unsigned char c = static_cast<unsigned char>(s[i]);
        if (std::isspace(c)) {
            ++i;
            continue;
        }
        token t;
        t.begin = i;
        if (std::isdigit(c) || (c == '.' && i + 1 < s.size() && std::isdigit(static_cast<unsigned char>(s[i + 1])))) {
            t.what = token::kind::number;
            while (i < s.size() && (std::isdigit(static_cast<unsigned char>(s[i])) || s[i] == '.'))
                ++i;
        } else if (std::isalpha(c) || c == '_') {
            t.what = token::kind::name;
            while (i < s.size() && (std::isalnum(static_cast<unsigned char>(s[i])) || s[i] == '_'))
                ++i;
        } else if (c == '<' || c == '>' || c == '=' || c == '!') {
            t.what = token::kind::relation;
            ++i;
            if (i < s.size() && s[i] == '=')
                ++i;
        } else if (std::string("+-*/^(),").find(static_cast<char>(c)) != std::string::npos) {
            t.what = token::kind::op;
            ++i;
        } else {
            throw std::invalid_argument("unexpected character");
        }
        t.end = i;
        t.text = s.substr(t.begin, t.end - t.begin);
        out.push_back(t);
    }
    token end;
    end.begin = end.end = s.size();
    out.push_back(end);
    return out;
}

// The tree of the text as written: parentheses, signs and operand order kept.
struct node {
    enum class kind { sum, product, negate, power, call, group, atom };
    kind what = kind::atom;
    std::size_t begin = 0;
    std::size_t end = 0;
    std::vector<bool> flags;   // sum: the term is subtracted; product: the factor divides
    std::vector<node> children;
};

// Recursive descent with GiNaC's precedences: + - < * / < unary - < ^ (right associative).
class tree_parser {
public:
    explicit tree_parser(const std::string& text) : tokens_(tokenize(text)) {}

    std::vector<node> sides()
    {
        std::vector<node> out{sum()};
        while (peek().what == token::kind::relation) {
            ++at_;
            out.push_back(sum());
        }
        if (peek().what != token::kind::end)
            throw std::invalid_argument("trailing text");
        return out;
    }

private:
    const token& peek() const { return tokens_[at_]; }
    bool is_op(const char* op) const { return peek().what == token::kind::op && peek().text == op; }
    std::size_t last_end() const { return tokens_[at_ - 1].end; }

    node sum()
    {
        node n;
        n.what = node::kind::sum;
        n.begin = peek().begin;
        bool negative = false;
        if (is_op("+") || is_op("-")) {
            negative = is_op("-");
            ++at_;
        }
        n.flags.push_back(negative);
        n.children.push_back(product());
        while (is_op("+") || is_op("-")) {
            n.flags.push_back(is_op("-"));
            ++at_;
            n.children.push_back(product());
        }
        n.end = last_end();
        if (n.children.size() == 1 && !n.flags[0])
            return n.children[0];
        return n;
    }

    node product()
    {
        node n;
        n.what = node::kind::product;
        n.begin = peek().begin;
        n.flags.push_back(false);
        n.children.push_back(unary());
        while (is_op("*") || is_op("/")) {
            n.flags.push_back(is_op("/"));
            ++at_;
            n.children.push_back(unary());
        }
        n.end = last_end();
        if (n.children.size() == 1)
            return n.children[0];
        return n;
    }

    node unary()
    {
        if (is_op("-")) {
            node n;
            n.what = node::kind::negate;
            n.begin = peek().begin;
            ++at_;
            n.children.push_back(unary());
            n.end = last_end();
            return n;
        }
        if (is_op("+")) {
            ++at_;
            return unary();
        }
        return power();
    }

    node power()
    {
        node base = primary();
        if (!is_op("^"))
            return base;
        ++at_;
        node n;
        n.what = node::kind::power;
        n.begin = base.begin;
        n.children.push_back(std::move(base));
        n.children.push_back(unary());
        n.end = last_end();
        return n;
    }

    node primary()
    {
        node n;
        n.begin = peek().begin;
        if (peek().what == token::kind::number) {
            ++at_;
        } else if (peek().what == token::kind::name) {
            ++at_;
            if (is_op("(")) {
                n.what = node::kind::call;
                ++at_;
                if (!is_op(")")) {
                    n.children.push_back(sum());
                    while (is_op(",")) {
                        ++at_;
                        n.children.push_back(sum());
                    }
                }
                expect(")");
            }
        } else if (is_op("(")) {
            n.what = node::kind::group;
            ++at_;
            n.children.push_back(sum());
            expect(")");
        } else {
            throw std::invalid_argument("expected an operand");
        }
        n.end = last_end();
        return n;
    }

    void expect(const char* op)
    {
        if (!is_op(op))
            throw std::invalid_argument("unbalanced parentheses");
        ++at_;
    }

    std::vector<token> tokens_;
    std::size_t at_ = 0;
};

const node& unwrapped(const node& n)
{
    return n.what == node::kind::group ? unwrapped(n.children[0]) : n;
}

// The relation of `lhs op rhs` as written: =, <=, <, >= or >.
std::string relation_between(const std::string& text)
{
    for (const token& t : tokenize(text))
        if (t.what == token::kind::relation)
            return t.text;
    return "=";
}

} // namespace

// Walks the tree of a text and records its sums, products and powers as GiNaC sees them.
class written_reader {
public:
    written_reader(const std::string& text, const written_form::parser& parse, written_form& out)
        : text_(text), parse_(parse), out_(out)
    {
    }

    // The tree of the text as the printers see it: atoms read by the derivation's parser.
    written_form::node tree(const node& n) const
    {
        written_form::node out;
        out.flags = n.flags;
        switch (n.what) {
        case node::kind::sum: out.what = written_form::node::kind::sum; break;
        case node::kind::product: out.what = written_form::node::kind::product; break;
        case node::kind::negate: out.what = written_form::node::kind::negate; break;
        case node::kind::power: out.what = written_form::node::kind::power; break;
        case node::kind::group: out.what = written_form::node::kind::group; break;
        case node::kind::call: {
            out.what = written_form::node::kind::call;
            const std::string head = text_.substr(n.begin, n.end - n.begin);
            std::string name = head.substr(0, head.find('('));
            while (!name.empty() && std::isspace(static_cast<unsigned char>(name.back())))
                name.pop_back();
            out.name = name;
            break;
        }
        case node::kind::atom: {
            out.what = written_form::node::kind::atom;
            const auto v = value(n);
            if (!v)
                throw std::invalid_argument("an atom the derivation does not read");
            out.value = *v;
            return out;
        }
        }
        for (const node& child : n.children)
            out.children.push_back(tree(child));
        return out;
    }

    void record(const node& n)
    {
        switch (n.what) {
        case node::kind::sum: record_sum(n); break;
        case node::kind::product: record_product(n); break;
        case node::kind::negate:
            if (unwrapped(n.children[0]).what == node::kind::sum && n.children[0].what == node::kind::group)
                if (auto inner = value(unwrapped(n.children[0])))
                    out_.negated_groups_.push_back(*inner);
            record(n.children[0]);
            break;
        case node::kind::power:
            if (auto p = value(n); p && GiNaC::is_a<GiNaC::power>(*p)) {
                const written_form::factor f = as_factor(n, *p, false);
                out_.powers_.emplace_back(f.base, f.exponent);
            }
            for (const node& child : n.children)
                record(child);
            break;
        case node::kind::call:
        case node::kind::group:
            for (const node& child : n.children)
                record(child);
            break;
        case node::kind::atom: break;
        }
    }

private:
    std::optional<GiNaC::ex> value_of(const node& n) const { return value(n); }

    std::optional<GiNaC::ex> value(const node& n) const
    {
        try {
            return parse_(text_.substr(n.begin, n.end - n.begin));
        } catch (const std::exception&) {
            return std::nullopt;
        }
    }

    // base^exponent as written: GiNaC may store (1 - eps)^2 as (-1 + eps)^2, so the base
    // of a written power is read from its own text.
    written_form::factor as_factor(const node& n, const GiNaC::ex& value, bool divides) const
    {
        if (!GiNaC::is_a<GiNaC::power>(value))
            return {value, 1, divides};
        const node& inner = unwrapped(n);
        if (inner.what == node::kind::power)
            if (const auto base = value_of(inner.children[0]))
                if (base->is_equal(value.op(0)) || (-*base - value.op(0)).expand().is_zero())
                    return {*base, value.op(1), divides};
        return {value.op(0), value.op(1), divides};
    }

    void record_sum(const node& n)
    {
        written_form::sum s;
        bool complete = true;
        for (std::size_t i = 0; i < n.children.size(); ++i) {
            const auto term = value(n.children[i]);
            if (!term) {
                complete = false;
                continue;
            }
            s.terms.push_back(n.flags[i] ? -*term : *term);
            // -(a - b) as a term: the sum in parentheses is written negated.
            const node& inner = unwrapped(n.children[i]);
            if (n.flags[i] && n.children[i].what == node::kind::group && inner.what == node::kind::sum)
                if (auto v = value(inner))
                    out_.negated_groups_.push_back(*v);
        }
        const auto whole = value(n);
        if (complete && whole && s.terms.size() >= 2) {
            s.value = *whole;
            out_.sums_.push_back(std::move(s));
        }
        for (const node& child : n.children)
            record(child);
    }

    // a*(b*c)/(d*e) is one product of GiNaC's: its factors are a, b, c and the divisors d, e.
    struct flat_factor {
        bool divides;
        const node* item;
        bool grouped;   // inside parentheses of the chain: the 2 of 1/(2*m)
    };

    void flatten(const node& n, bool divides, bool grouped, std::vector<flat_factor>& out) const
    {
        const node& inner = unwrapped(n);
        if (inner.what == node::kind::product) {
            const bool deeper = grouped || n.what == node::kind::group;
            for (std::size_t i = 0; i < inner.children.size(); ++i)
                flatten(inner.children[i], divides != inner.flags[i], deeper, out);
            return;
        }
        out.push_back({divides, &n, grouped});
    }

    void record_product(const node& n)
    {
        std::vector<flat_factor> items;
        flatten(n, false, false, items);
        written_form::product p;
        bool complete = true;
        for (const auto& [divides, item, grouped] : items) {
            const auto v = value(*item);
            if (!v || unwrapped(*item).what == node::kind::negate) {
                complete = false;
                continue;
            }
            p.factors.push_back(as_factor(*item, *v, divides));
        }
        // 1/2*m*v^2 starts with a fraction; 1/(2*m) does not.
        p.leading_fraction = complete && p.factors.size() >= 2 && GiNaC::is_a<GiNaC::numeric>(p.factors[0].base) &&
                             !p.factors[0].divides && GiNaC::is_a<GiNaC::numeric>(p.factors[1].base) &&
                             p.factors[1].divides && !items[1].grouped;
        if (complete && !p.factors.empty())
            out_.products_.push_back(std::move(p));
        for (const flat_factor& f : items)
            record(*f.item);
    }

    const std::string& text_;
    const written_form::parser& parse_;
    written_form& out_;
};

written_form written_form::read(const std::string& text, const parser& parse)
{
    written_form form;
    try {
        tree_parser reader(text);
        written_reader recorder(text, parse, form);
        const auto sides = reader.sides();
        for (const auto& side : sides)
            recorder.record(side);
        try {
            if (sides.size() == 1) {
                form.tree_ = recorder.tree(sides[0]);
            } else {
                written_form::node relation;
                relation.what = written_form::node::kind::relation;
                relation.name = relation_between(text);
                for (const auto& side : sides)
                    relation.children.push_back(recorder.tree(side));
                form.tree_ = std::move(relation);
            }
        } catch (const std::exception&) {
            form.tree_.reset();
        }
    } catch (const std::exception&) {
        return written_form();
    }
    return form;
}

const std::vector<GiNaC::ex>* written_form::terms(const GiNaC::ex& sum) const
{
    for (const written_form::sum& s : sums_)
        if (s.value.is_equal(sum))
            return &s.terms;
    return nullptr;
}

std::optional<bool> written_form::as_written(const GiNaC::ex& sum) const
{
    if (terms(sum))
        return true;
    GiNaC::exvector negated;
    for (std::size_t i = 0; i < sum.nops(); ++i)
        negated.push_back(-sum.op(i));
    if (terms(GiNaC::add(negated)))
        return false;
    for (const GiNaC::ex& group : negated_groups_)
        if (group.is_equal(GiNaC::add(negated)))
            return false;
    return std::nullopt;
}

bool written_form::negated_group(const GiNaC::ex& sum) const
{
    GiNaC::exvector negated;
    for (std::size_t i = 0; i < sum.nops(); ++i)
        negated.push_back(-sum.op(i));
    const GiNaC::ex other = GiNaC::add(negated);
    for (const GiNaC::ex& group : negated_groups_)
        if (group.is_equal(other))
            return true;
    return false;
}

bool written_form::written_power(const GiNaC::ex& base, const GiNaC::ex& exponent) const
{
    for (const auto& [b, e] : powers_)
        if (b.is_equal(base) && e.is_equal(exponent))
            return true;
    return false;
}

bool written_form::matches(const factor& written, const GiNaC::ex& base, const GiNaC::ex& exponent)
{
    if (!written.base.is_equal(base))
        return false;
    return written.divides ? written.exponent.is_equal(-exponent) : written.exponent.is_equal(exponent);
}

const written_form::product* written_form::best_product(const std::vector<std::pair<GiNaC::ex, GiNaC::ex>>& factors) const
{
    const product* best = nullptr;
    std::size_t best_score = 0;
    for (const product& p : products_) {
        std::size_t score = 0;
        for (const auto& [base, exponent] : factors)
            for (const factor& w : p.factors)
                if (matches(w, base, exponent)) {
                    ++score;
                    break;
                }
        if (score > best_score) {
            best = &p;
            best_score = score;
        }
    }
    return best;
}

namespace {

bool mentions(const written_form::node& n, const GiNaC::ex& symbol)
{
    if (n.what == written_form::node::kind::atom && n.value.has(symbol))
        return true;
    for (const written_form::node& child : n.children)
        if (mentions(child, symbol))
            return true;
    return false;
}

} // namespace

bool written_form::mentions(const GiNaC::ex& symbol) const
{
    return tree_ && engine::mentions(*tree_, symbol);
}

} // namespace impact::engine
