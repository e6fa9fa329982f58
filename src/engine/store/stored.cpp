#include "engine/store/stored.h"

#include "engine/expr/dimensional.h"

#include <cln/integer_io.h>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstring>
#include <locale>
#include <algorithm>
#include <map>
#include <set>
#include <sstream>
#include <string_view>
#include <stdexcept>

namespace impact::engine {

using json = nlohmann::json;

namespace {

// The first line of every stored derivation: another format is never read.
constexpr const char* format_line = "impact derivation 1\n";

// Something a derivation holds that cannot be kept exactly.
struct not_storable : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// A stored text that is not what this version wrote.
struct not_readable : std::runtime_error {
    using std::runtime_error::runtime_error;
};

std::string integer_text(const GiNaC::numeric& n)
{
    std::ostringstream out;
    out.imbue(std::locale::classic());
    out << n;
    return out.str();
}

GiNaC::numeric integer_of(const json& j)
{
    const std::string& digits = j.get_ref<const std::string&>();
    if (digits.empty() || digits.find_first_not_of("-0123456789") != std::string::npos)
        throw not_readable("not an integer");
    return GiNaC::numeric(cln::cl_I(digits.c_str()));
}

// The relations GiNaC makes, each by the code a stored text gives it.
struct relation_kind {
    const char* code;
    unsigned flag;
    GiNaC::relational::operators op;
};
constexpr relation_kind relation_kinds[] = {
    {"==", GiNaC::info_flags::relation_equal, GiNaC::relational::equal},
    {"!=", GiNaC::info_flags::relation_not_equal, GiNaC::relational::not_equal},
    {"<", GiNaC::info_flags::relation_less, GiNaC::relational::less},
    {"<=", GiNaC::info_flags::relation_less_or_equal, GiNaC::relational::less_or_equal},
    {">", GiNaC::info_flags::relation_greater, GiNaC::relational::greater},
    {">=", GiNaC::info_flags::relation_greater_or_equal, GiNaC::relational::greater_or_equal},
};

std::string relation_code(const GiNaC::ex& e)
{
    for (const relation_kind& k : relation_kinds)
        if (e.info(k.flag))
            return k.code;
    throw not_storable("a relation of unknown kind");
}

GiNaC::ex relation_of(const std::string& code, const GiNaC::ex& lhs, const GiNaC::ex& rhs)
{
    for (const relation_kind& k : relation_kinds)
        if (code == k.code)
            return GiNaC::relational(lhs, rhs, k.op);
    throw not_readable("a relation of unknown kind");
}

// The lines of a derivation file that hold more than spaces or a comment, each with its
// number (from 1), without the spaces that end it.
std::vector<std::pair<std::uint32_t, std::string_view>> content_lines(const std::string& text)
{
    std::vector<std::pair<std::uint32_t, std::string_view>> lines;
    std::uint32_t number = 0;
    for (std::size_t at = 0; at <= text.size();) {
        const std::size_t end = std::min(text.find('\n', at), text.size());
        std::string_view line(text.data() + at, end - at);
        ++number;
        while (!line.empty() && (line.back() == ' ' || line.back() == '\t' || line.back() == '\r'))
            line.remove_suffix(1);
        const std::size_t first = line.find_first_not_of(" \t");
        if (first != std::string_view::npos && line[first] != '#')
            lines.emplace_back(number, line);
        at = end + 1;
    }
    return lines;
}

// Where each line of `before` is in `now` (0: a line of spaces or a comment), when the two
// differ only by such lines; nothing otherwise (a line changed, or moved).
std::optional<std::vector<std::uint32_t>> line_map(const std::string& before, const std::string& now)
{
    const auto a = content_lines(before), b = content_lines(now);
    if (a.size() != b.size())
        return std::nullopt;
    std::vector<std::uint32_t> map(static_cast<std::size_t>(std::count(before.begin(), before.end(), '\n')) + 2, 0);
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (a[i].second != b[i].second)
            return std::nullopt;
        map[a[i].first] = b[i].first;
    }
    return map;
}

bool holds_float(const GiNaC::ex& e)
{
    if (GiNaC::is_a<GiNaC::numeric>(e))
        return !GiNaC::ex_to<GiNaC::numeric>(e).is_crational();
    for (std::size_t i = 0; i < e.nops(); ++i)
        if (holds_float(e.op(i)))
            return true;
    return false;
}

// A double by its bits: every value kept, infinities and NaN too.
json bits(double x)
{
    std::uint64_t b = 0;
    std::memcpy(&b, &x, sizeof b);
    return b;
}
double from_bits(const json& j)
{
    const auto b = j.get<std::uint64_t>();
    double x = 0;
    std::memcpy(&x, &b, sizeof x);
    return x;
}

template <typename Enum>
json code(Enum e)
{
    return static_cast<int>(e);
}

template <typename Enum>
Enum enum_of(const json& j, int last)
{
    const int v = j.get<int>();
    if (v < 0 || v > last)
        throw not_readable("an enumeration out of range");
    return static_cast<Enum>(v);
}

} // namespace

// Writes and reads a derivation. A friend of the classes whose state it keeps
// (symbol_table, written_form), so that it keeps exactly what they hold.
class derivation_codec {
public:
    // The derivation files' bytes now, by path: those of `source` and of `done`.
    derivation_codec(const spec::derivation& source, const derived_by_id& done)
    {
        contents_[source.file] = &source.contents;
        for (const auto& [id, d] : done)
            contents_.emplace(d.source.file, &d.source.contents);
    }

    // ---- writing ----

    json write(const derivation& d)
    {
        for (const quantity& q : d.symbols.all())
            table_.emplace(q.symbol, table_.size());
        json out;
        out["symbols"] = put_symbols(d.symbols);
        out["givens"] = list(d.givens, &derivation_codec::put_equation);
        out["steps"] = list(d.steps, &derivation_codec::put_step);
        out["results"] = list(d.results, &derivation_codec::put_result);
        out["checks"] = list(d.checks, &derivation_codec::put_check);
        out["paper_checks"] = list(d.paper_checks, &derivation_codec::put_comparison);
        out["kernels"] = list(d.kernels, &derivation_codec::put_kernel);
        out["nodes"] = std::move(nodes_);
        out["temporaries"] = std::move(temporaries_);
        // Each file a place names, with its bytes when it is a derivation file: a comment
        // added or removed moves the places after it, which reading puts right.
        json files = json::array();
        for (const std::string& file : files_) {
            const auto bytes = contents_.find(file);
            files.push_back({file, bytes == contents_.end() ? json() : json(*bytes->second)});
        }
        out["files"] = std::move(files);
        return out;
    }

    // ---- reading ----

    derivation read(const json& in, const spec::derivation& source)
    {
        derivation d;
        d.source = source;
        for (const json& f : in.at("files")) {
            const std::string& file = f.at(0).get_ref<const std::string&>();
            if (f.at(1).is_null())
                continue;
            const auto now = contents_.find(file);
            if (now == contents_.end())
                throw not_readable("a place in a file not read now");
            const std::string& before = f.at(1).get_ref<const std::string&>();
            if (before == *now->second)
                continue;
            std::optional<std::vector<std::uint32_t>> moved = line_map(before, *now->second);
            if (!moved)
                throw not_readable("a file changed in more than its comments");
            lines_moved_[file] = std::move(*moved);
        }
        get_symbols(in.at("symbols"), d.symbols, source);
        nodes_in_ = &in.at("nodes");
        temporaries_in_ = &in.at("temporaries");
        built_.assign(nodes_in_->size(), std::nullopt);
        temporary_symbols_.assign(temporaries_in_->size(), std::nullopt);
        get_symbol_values(in.at("symbols"), d.symbols);
        get_list(in.at("givens"), d.givens, &derivation_codec::get_equation);
        get_list(in.at("steps"), d.steps, &derivation_codec::get_step);
        get_list(in.at("results"), d.results, &derivation_codec::get_result);
        get_list(in.at("checks"), d.checks, &derivation_codec::get_check);
        get_list(in.at("paper_checks"), d.paper_checks, &derivation_codec::get_comparison);
        get_list(in.at("kernels"), d.kernels, &derivation_codec::get_kernel);
        return d;
    }

private:
    // ---- expressions ----

    // An expression as the index of its node; each distinct expression written once.
    json put(const GiNaC::ex& e)
    {
        // GiNaC compares a == b equal to b == a (and a < b to b > a): a relation is never
        // taken for one written before, so that its sides come back as they were.
        const bool relation = GiNaC::is_exactly_a<GiNaC::relational>(e);
        if (const auto known = relation ? ids_.end() : ids_.find(e); known != ids_.end()) {
            // GiNaC compares 0.5 and 1/2 equal: an expression equal to one written already
            // (and not the same object) is written by it only if it holds no float.
            if (!GiNaC::are_ex_trivially_equal(known->first, e) && holds_float(e))
                throw not_storable("a floating-point number");
            return known->second;
        }
        json node = json::array();
        if (GiNaC::is_a<GiNaC::symbol>(e)) {
            if (const auto mine = table_.find(e); mine != table_.end()) {
                node = {"s", mine->second};
            } else {
                const auto& s = GiNaC::ex_to<GiNaC::symbol>(e);
                const char* kind = GiNaC::is_exactly_a<GiNaC::possymbol>(e)    ? "possymbol"
                                   : GiNaC::is_exactly_a<GiNaC::realsymbol>(e) ? "realsymbol"
                                                                               : "symbol";
                if (!GiNaC::is_exactly_a<GiNaC::possymbol>(e) && !GiNaC::is_exactly_a<GiNaC::realsymbol>(e) &&
                    !GiNaC::is_exactly_a<GiNaC::symbol>(e))
                    throw not_storable("a symbol of another class");
                node = {"t", temporaries_.size()};
                temporaries_.push_back({kind, s.get_name(), s.get_TeX_name()});
            }
        } else if (GiNaC::is_a<GiNaC::numeric>(e)) {
            const GiNaC::numeric& n = GiNaC::ex_to<GiNaC::numeric>(e);
            if (n.is_rational()) {
                node = {"q", integer_text(n.numer()), integer_text(n.denom())};
            } else if (n.is_crational()) {
                node = {"c", put(n.real()), put(n.imag())};
            } else {
                throw not_storable("a floating-point number");
            }
        } else if (GiNaC::is_exactly_a<GiNaC::add>(e) || GiNaC::is_exactly_a<GiNaC::mul>(e) ||
                   GiNaC::is_exactly_a<GiNaC::lst>(e)) {
            node.push_back(GiNaC::is_exactly_a<GiNaC::add>(e) ? "+" : GiNaC::is_exactly_a<GiNaC::mul>(e) ? "*" : "l");
            for (std::size_t i = 0; i < e.nops(); ++i)
                node.push_back(put(e.op(i)));
        } else if (GiNaC::is_exactly_a<GiNaC::power>(e)) {
            node = {"^", put(e.op(0)), put(e.op(1))};
        } else if (GiNaC::is_exactly_a<GiNaC::function>(e)) {
            node = {"f", GiNaC::ex_to<GiNaC::function>(e).get_name()};
            for (std::size_t i = 0; i < e.nops(); ++i)
                node.push_back(put(e.op(i)));
        } else if (GiNaC::is_exactly_a<GiNaC::relational>(e)) {
            node = {"r", relation_code(e), put(e.op(0)), put(e.op(1))};
        } else if (GiNaC::is_exactly_a<GiNaC::constant>(e)) {
            if (e.is_equal(GiNaC::Pi))
                node = {"k", "Pi"};
            else if (e.is_equal(GiNaC::Euler))
                node = {"k", "Euler"};
            else if (e.is_equal(GiNaC::Catalan))
                node = {"k", "Catalan"};
            else
                throw not_storable("a constant of its own");
        } else {
            throw not_storable("a GiNaC object no derivation makes");
        }
        const std::size_t id = nodes_.size();
        nodes_.push_back(std::move(node));
        if (!relation)
            ids_.emplace(e, id);
        return id;
    }

    GiNaC::ex get(const json& j)
    {
        const std::size_t id = j.get<std::size_t>();
        if (id >= built_.size())
            throw not_readable("a node out of range");
        if (built_[id])
            return *built_[id];
        const json& node = (*nodes_in_)[id];
        const std::string& kind = node.at(0).get_ref<const std::string&>();
        // Every node is written after its operands: one naming itself or a later node is
        // not a text Impact wrote (and would never end).
        const auto operand = [&](std::size_t i) {
            if (node.at(i).get<std::size_t>() >= id)
                throw not_readable("an operand written after its expression");
            return get(node.at(i));
        };
        GiNaC::ex e;
        if (kind == "s") {
            const std::size_t i = node.at(1).get<std::size_t>();
            if (i >= symbols_in_.size())
                throw not_readable("a symbol out of range");
            e = symbols_in_[i];
        } else if (kind == "t") {
            e = temporary(node.at(1).get<std::size_t>());
        } else if (kind == "q") {
            e = integer_of(node.at(1)) / integer_of(node.at(2));
        } else if (kind == "c") {
            e = operand(1) + GiNaC::I * operand(2);
        } else if (kind == "+" || kind == "*" || kind == "l") {
            GiNaC::exvector operands;
            for (std::size_t i = 1; i < node.size(); ++i)
                operands.push_back(operand(i));
            if (kind == "+")
                e = GiNaC::add(operands);
            else if (kind == "*")
                e = GiNaC::mul(operands);
            else {
                GiNaC::lst l;
                for (const GiNaC::ex& x : operands)
                    l.append(x);
                e = l;
            }
        } else if (kind == "^") {
            e = GiNaC::pow(operand(1), operand(2));
        } else if (kind == "f") {
            GiNaC::exvector arguments;
            for (std::size_t i = 2; i < node.size(); ++i)
                arguments.push_back(operand(i));
            const unsigned serial = GiNaC::function::find_function(node.at(1).get<std::string>(),
                                                                    static_cast<unsigned>(arguments.size()));
            // Held: it was stored as evaluated (or held, as a select is), and stays so.
            e = GiNaC::function(serial, arguments).hold();
        } else if (kind == "r") {
            e = relation_of(node.at(1).get<std::string>(), operand(2), operand(3));
        } else if (kind == "k") {
            const std::string& name = node.at(1).get_ref<const std::string&>();
            e = name == "Pi" ? GiNaC::ex(GiNaC::Pi) : name == "Euler" ? GiNaC::ex(GiNaC::Euler) : GiNaC::ex(GiNaC::Catalan);
        } else {
            throw not_readable("a node of unknown kind");
        }
        built_[id] = e;
        return e;
    }

    GiNaC::ex temporary(std::size_t i)
    {
        if (i >= temporary_symbols_.size())
            throw not_readable("a symbol out of range");
        if (!temporary_symbols_[i]) {
            const json& t = (*temporaries_in_)[i];
            const std::string& kind = t.at(0).get_ref<const std::string&>();
            const std::string& name = t.at(1).get_ref<const std::string&>();
            const std::string& tex = t.at(2).get_ref<const std::string&>();
            if (kind == "possymbol")
                temporary_symbols_[i] = GiNaC::possymbol(name, tex);
            else if (kind == "realsymbol")
                temporary_symbols_[i] = GiNaC::realsymbol(name, tex);
            else
                temporary_symbols_[i] = GiNaC::symbol(name, tex);
        }
        return *temporary_symbols_[i];
    }

    json put_optional(const std::optional<GiNaC::ex>& e) { return e ? put(*e) : json(); }
    std::optional<GiNaC::ex> get_optional(const json& j) { return j.is_null() ? std::nullopt : std::optional(get(j)); }

    json put_pairs(const std::vector<std::pair<GiNaC::ex, GiNaC::ex>>& pairs)
    {
        json out = json::array();
        for (const auto& [a, b] : pairs)
            out.push_back({put(a), put(b)});
        return out;
    }
    std::vector<std::pair<GiNaC::ex, GiNaC::ex>> get_pairs(const json& j)
    {
        std::vector<std::pair<GiNaC::ex, GiNaC::ex>> out;
        for (const json& p : j)
            out.emplace_back(get(p.at(0)), get(p.at(1)));
        return out;
    }
    json put_exs(const std::vector<GiNaC::ex>& all)
    {
        json out = json::array();
        for (const GiNaC::ex& e : all)
            out.push_back(put(e));
        return out;
    }
    std::vector<GiNaC::ex> get_exs(const json& j)
    {
        std::vector<GiNaC::ex> out;
        for (const json& e : j)
            out.push_back(get(e));
        return out;
    }

    template <typename T>
    json list(const std::vector<T>& all, json (derivation_codec::*one)(const T&))
    {
        json out = json::array();
        for (const T& x : all)
            out.push_back((this->*one)(x));
        return out;
    }
    template <typename T>
    void get_list(const json& j, std::vector<T>& all, void (derivation_codec::*one)(const json&, T&))
    {
        all.clear();
        for (const json& x : j) {
            all.emplace_back();
            (this->*one)(x, all.back());
        }
    }

    // ---- small parts ----

    json put_where(const source_location& w)
    {
        files_.insert(w.file);
        return {w.file, w.line, w.column};
    }
    source_location get_where(const json& j)
    {
        source_location w{j.at(0).get<std::string>(), j.at(1).get<std::uint32_t>(), j.at(2).get<std::uint32_t>()};
        if (const auto moved = lines_moved_.find(w.file); moved != lines_moved_.end() && w.line != 0) {
            if (w.line >= moved->second.size() || moved->second[w.line] == 0)
                throw not_readable("a place on a line that is no longer there");
            w.line = moved->second[w.line];
        }
        return w;
    }

    static json put_domain(const domain& d)
    {
        return {code(d.what),   bits(d.lower),  bits(d.upper),  d.lower_open,
                d.upper_open,   d.lower_text,   d.upper_text,   d.infinity_included};
    }
    static domain get_domain(const json& j)
    {
        domain d;
        d.what = enum_of<domain::kind>(j.at(0), 3);
        d.lower = from_bits(j.at(1));
        d.upper = from_bits(j.at(2));
        d.lower_open = j.at(3).get<bool>();
        d.upper_open = j.at(4).get<bool>();
        d.lower_text = j.at(5).get<std::string>();
        d.upper_text = j.at(6).get<std::string>();
        d.infinity_included = j.at(7).get<bool>();
        return d;
    }

    static json put_dimension(const dimension& d)
    {
        json out = json::array();
        for (const auto& [base, exponent] : d.exponents())
            out.push_back({base, integer_text(exponent.numer()), integer_text(exponent.denom())});
        return out;
    }
    static dimension get_dimension(const json& j)
    {
        dimension d;
        for (const json& factor : j)
            d = d * dimension::base(factor.at(0).get<std::string>())
                        .power(integer_of(factor.at(1)) / integer_of(factor.at(2)));
        return d;
    }

    static json put_sign(const sign_set& s) { return {s.negative, s.zero, s.positive}; }
    static sign_set get_sign(const json& j) { return {j.at(0).get<bool>(), j.at(1).get<bool>(), j.at(2).get<bool>()}; }

    json put_finding(const finding& f)
    {
        json parts = json::array();
        for (const finding::part& p : f.parts)
            parts.push_back({code(p.what), p.words, put(p.value), put_optional(p.point), put_dimension(p.dim), p.term,
                             code(p.op)});
        return {parts, put_optional(f.corrected)};
    }
    void get_finding(const json& j, finding& f)
    {
        for (const json& p : j.at(0)) {
            finding::part part;
            part.what = enum_of<finding::part::kind>(p.at(0), 3);
            part.words = p.at(1).get<std::string>();
            part.value = get(p.at(2));
            part.point = get_optional(p.at(3));
            part.dim = get_dimension(p.at(4));
            part.term = p.at(5).get<bool>();
            part.op = enum_of<relation>(p.at(6), 4);
            f.parts.push_back(std::move(part));
        }
        f.corrected = get_optional(j.at(1));
    }

    json put_reason(const sign_reason& r)
    {
        return {r.words, put_finding(r.typeset), put_optional(r.declared), r.domain};
    }
    void get_reason(const json& j, sign_reason& r)
    {
        r.words = j.at(0).get<std::string>();
        get_finding(j.at(1), r.typeset);
        r.declared = get_optional(j.at(2));
        r.domain = j.at(3).get<std::string>();
    }

    json put_sign_step(const sign_step& s) { return {put(s.factor), put_sign(s.sign), put_reason(s.why), s.words}; }
    void get_sign_step(const json& j, sign_step& s)
    {
        s.factor = get(j.at(0));
        s.sign = get_sign(j.at(1));
        get_reason(j.at(2), s.why);
        s.words = j.at(3).get<std::string>();
    }

    json put_verdict(const verdict& v)
    {
        return {code(v.what), code(v.how), v.samples, put(v.residual), v.method,
                list(v.proof, &derivation_codec::put_sign_step)};
    }
    void get_verdict(const json& j, verdict& v)
    {
        v.what = enum_of<verdict::status>(j.at(0), 2);
        v.how = enum_of<verdict::basis>(j.at(1), 7);
        v.samples = j.at(2).get<std::size_t>();
        v.residual = get(j.at(3));
        v.method = j.at(4).get<std::string>();
        get_list(j.at(5), v.proof, &derivation_codec::get_sign_step);
    }

    json put_limit_method(const limit_method& m)
    {
        return {code(m.how),         put(m.symbol),    put(m.point),    put(m.denominator),
                put_sign(m.denominator_sign), put(m.coefficient), m.order, m.at_infinity,
                put(m.inverted),      put_optional(m.leading_in_inverse), m.words};
    }
    void get_limit_method(const json& j, limit_method& m)
    {
        m.how = enum_of<limit_method::kind>(j.at(0), 1);
        m.symbol = get(j.at(1));
        m.point = get(j.at(2));
        m.denominator = get(j.at(3));
        m.denominator_sign = get_sign(j.at(4));
        m.coefficient = get(j.at(5));
        m.order = j.at(6).get<int>();
        m.at_infinity = j.at(7).get<bool>();
        m.inverted = get(j.at(8));
        m.leading_in_inverse = get_optional(j.at(9));
        m.words = j.at(10).get<std::string>();
    }

    // ---- written forms ----

    json put_node(const written_form::node& n)
    {
        json children = json::array();
        for (const written_form::node& c : n.children)
            children.push_back(put_node(c));
        return {code(n.what), n.flags, children, put(n.value), n.name};
    }
    void get_node(const json& j, written_form::node& n)
    {
        n.what = enum_of<written_form::node::kind>(j.at(0), 7);
        n.flags = j.at(1).get<std::vector<bool>>();
        for (const json& c : j.at(2)) {
            n.children.emplace_back();
            get_node(c, n.children.back());
        }
        n.value = get(j.at(3));
        n.name = j.at(4).get<std::string>();
    }

    json put_product(const written_form::product& p)
    {
        json factors = json::array();
        for (const written_form::factor& f : p.factors)
            factors.push_back({put(f.base), put(f.exponent), f.divides});
        return {factors, p.leading_fraction};
    }
    void get_product(const json& j, written_form::product& p)
    {
        for (const json& f : j.at(0))
            p.factors.push_back({get(f.at(0)), get(f.at(1)), f.at(2).get<bool>()});
        p.leading_fraction = j.at(1).get<bool>();
    }

    json put_written(const written_form& w)
    {
        json sums = json::array();
        for (const written_form::sum& s : w.sums_)
            sums.push_back({put(s.value), put_exs(s.terms)});
        return {sums, put_exs(w.negated_groups_), list(w.products_, &derivation_codec::put_product),
                put_pairs(w.powers_), w.tree_ ? put_node(*w.tree_) : json()};
    }
    void get_written(const json& j, written_form& w)
    {
        for (const json& s : j.at(0))
            w.sums_.push_back({get(s.at(0)), get_exs(s.at(1))});
        w.negated_groups_ = get_exs(j.at(1));
        get_list(j.at(2), w.products_, &derivation_codec::get_product);
        w.powers_ = get_pairs(j.at(3));
        if (!j.at(4).is_null()) {
            written_form::node tree;
            get_node(j.at(4), tree);
            w.tree_ = std::move(tree);
        }
    }

    // ---- symbols ----

    json put_symbols(const symbol_table& table)
    {
        json out = json::array();
        for (const quantity& q : table.all())
            out.push_back({q.name, put_domain(q.range), q.latex, q.meaning, put_optional(q.definition),
                           put_written(q.written), put_where(q.where), q.dim ? put_dimension(*q.dim) : json(),
                           q.dim_declared});
        return out;
    }

    // The symbols first, made as the table makes them (a positive quantity a possymbol),
    // in the order it made them; their values once every symbol exists.
    void get_symbols(const json& j, symbol_table& table, const spec::derivation& source)
    {
        add_dimensions(table, source.dimensions);
        for (const json& s : j) {
            quantity q;
            q.name = s.at(0).get<std::string>();
            q.range = get_domain(s.at(1));
            q.latex = s.at(2).get<std::string>();
            q.meaning = s.at(3).get<std::string>();
            q.where = get_where(s.at(6));
            if (!s.at(7).is_null())
                q.dim = get_dimension(s.at(7));
            q.dim_declared = s.at(8).get<bool>();
            if (table.find(q.name))
                throw not_readable("a symbol named twice");
            symbols_in_.push_back(table.adopt(q).symbol);
        }
    }
    void get_symbol_values(const json& j, symbol_table& table)
    {
        std::size_t i = 0;
        for (const json& s : j) {
            quantity& q = table.quantities_.at(i++);
            q.definition = get_optional(s.at(4));
            get_written(s.at(5), q.written);
        }
    }

    // ---- the derivation's parts ----

    json put_equation(const equation& e)
    {
        return {e.name, put(e.relation), e.because, e.paper, put_where(e.where), put_written(e.written)};
    }
    void get_equation(const json& j, equation& e)
    {
        e.name = j.at(0).get<std::string>();
        e.relation = get(j.at(1));
        e.because = j.at(2).get<std::string>();
        e.paper = j.at(3).get<std::string>();
        e.where = get_where(j.at(4));
        get_written(j.at(5), e.written);
    }

    json put_case(const case_value& c)
    {
        return {code(c.op),          put(c.lhs),          put(c.rhs),        put(c.value),
                put(c.written_lhs),  put(c.written_rhs),  put(c.as_written), put_written(c.written),
                put_where(c.where)};
    }
    void get_case(const json& j, case_value& c)
    {
        c.op = enum_of<relation>(j.at(0), 4);
        c.lhs = get(j.at(1));
        c.rhs = get(j.at(2));
        c.value = get(j.at(3));
        c.written_lhs = get(j.at(4));
        c.written_rhs = get(j.at(5));
        c.as_written = get(j.at(6));
        get_written(j.at(7), c.written);
        c.where = get_where(j.at(8));
    }

    json put_part(const check_result::part& p)
    {
        json in_cases = json::array();
        for (const auto& [symbol, c] : p.in_cases)
            in_cases.push_back({put(symbol), put_case(c)});
        return {p.under,
                put_verdict(p.outcome),
                p.first,
                p.second,
                p.in_case ? put_case(*p.in_case) : json(),
                in_cases,
                p.boundary ? json{put(p.boundary->first), put(p.boundary->second)} : json()};
    }
    void get_part(const json& j, check_result::part& p)
    {
        p.under = j.at(0).get<std::string>();
        get_verdict(j.at(1), p.outcome);
        p.first = j.at(2).get<std::size_t>();
        p.second = j.at(3).get<std::size_t>();
        if (!j.at(4).is_null()) {
            p.in_case.emplace();
            get_case(j.at(4), *p.in_case);
        }
        for (const json& c : j.at(5)) {
            p.in_cases.emplace_back(get(c.at(0)), case_value{});
            get_case(c.at(1), p.in_cases.back().second);
        }
        if (!j.at(6).is_null())
            p.boundary.emplace(get(j.at(6).at(0)), get(j.at(6).at(1)));
    }

    json put_check(const check_result& c)
    {
        json assuming = json::array();
        for (const auto& [e, words] : c.assuming)
            assuming.push_back({put(e), words});
        return {c.name,
                c.statement,
                put(c.stated),
                put_pairs(c.at),
                put_pairs(c.left_at),
                code(c.op),
                c.limit ? json{put(c.limit->symbol), put(c.limit->point), c.limit->to_infinity} : json(),
                assuming,
                put_optional(c.value),
                c.limit_by ? put_limit_method(*c.limit_by) : json(),
                c.display_of,
                c.because,
                put(c.lhs),
                put(c.rhs),
                put_verdict(c.outcome),
                put_where(c.where),
                put_written(c.written),
                list(c.parts, &derivation_codec::put_part),
                c.cases_of,
                c.continuity,
                c.said_false,
                c.fails_at ? json{put_pairs(c.fails_at->point), put(c.fails_at->lhs), put(c.fails_at->rhs),
                                  c.fails_at->exact}
                           : json()};
    }
    void get_check(const json& j, check_result& c)
    {
        c.name = j.at(0).get<std::string>();
        c.statement = j.at(1).get<std::string>();
        c.stated = get(j.at(2));
        c.at = get_pairs(j.at(3));
        c.left_at = get_pairs(j.at(4));
        c.op = enum_of<relation>(j.at(5), 4);
        if (!j.at(6).is_null())
            c.limit = check_result::limit_point{get(j.at(6).at(0)), get(j.at(6).at(1)), j.at(6).at(2).get<bool>()};
        for (const json& a : j.at(7))
            c.assuming.emplace_back(get(a.at(0)), a.at(1).get<std::string>());
        c.value = get_optional(j.at(8));
        if (!j.at(9).is_null()) {
            c.limit_by.emplace();
            get_limit_method(j.at(9), *c.limit_by);
        }
        c.display_of = j.at(10).get<std::string>();
        c.because = j.at(11).get<std::string>();
        c.lhs = get(j.at(12));
        c.rhs = get(j.at(13));
        get_verdict(j.at(14), c.outcome);
        c.where = get_where(j.at(15));
        get_written(j.at(16), c.written);
        get_list(j.at(17), c.parts, &derivation_codec::get_part);
        c.cases_of = j.at(18).get<std::string>();
        c.continuity = j.at(19).get<bool>();
        c.said_false = j.at(20).get<bool>();
        if (!j.at(21).is_null())
            c.fails_at = counterexample{get_pairs(j.at(21).at(0)), get(j.at(21).at(1)), get(j.at(21).at(2)),
                                        j.at(21).at(3).get<bool>()};
    }

    json put_solution(const solution& s)
    {
        return {put_pairs(s.values), code(s.outcome), put(s.unknown), put_domain(s.range),
                put(s.condition),   s.why,           list(s.proof, &derivation_codec::put_sign_step)};
    }
    void get_solution(const json& j, solution& s)
    {
        s.values = get_pairs(j.at(0));
        s.outcome = enum_of<solution::fate>(j.at(1), 2);
        s.unknown = get(j.at(2));
        s.range = get_domain(j.at(3));
        s.condition = get(j.at(4));
        s.why = j.at(5).get<std::string>();
        get_list(j.at(6), s.proof, &derivation_codec::get_sign_step);
    }

    json put_step(const step_result& s)
    {
        return {code(s.what),
                s.description,
                s.because,
                put_pairs(s.values),
                s.yields ? put_equation(*s.yields) : json(),
                put_exs(s.assumptions),
                list(s.checks, &derivation_codec::put_check),
                put_where(s.where),
                put_optional(s.as_written),
                put_written(s.written),
                list(s.solutions, &derivation_codec::put_solution),
                list(s.cases, &derivation_codec::put_case),
                put(s.cases_of)};
    }
    void get_step(const json& j, step_result& s)
    {
        s.what = enum_of<spec::step::kind>(j.at(0), 3);
        s.description = j.at(1).get<std::string>();
        s.because = j.at(2).get<std::string>();
        s.values = get_pairs(j.at(3));
        if (!j.at(4).is_null()) {
            s.yields.emplace();
            get_equation(j.at(4), *s.yields);
        }
        s.assumptions = get_exs(j.at(5));
        get_list(j.at(6), s.checks, &derivation_codec::get_check);
        s.where = get_where(j.at(7));
        s.as_written = get_optional(j.at(8));
        get_written(j.at(9), s.written);
        get_list(j.at(10), s.solutions, &derivation_codec::get_solution);
        get_list(j.at(11), s.cases, &derivation_codec::get_case);
        s.cases_of = get(j.at(12));
    }

    json put_comparison(const paper_comparison& p)
    {
        return {code(p.what),
                p.subject,
                p.paper,
                p.printed_text,
                put(p.printed),
                put(p.derived),
                put_verdict(p.agreement),
                list(p.findings, &derivation_codec::put_finding),
                p.reconciliations,
                p.test ? put_check(*p.test) : json(),
                put_where(p.where),
                put_written(p.written),
                p.quote,
                p.label};
    }
    void get_comparison(const json& j, paper_comparison& p)
    {
        p.what = enum_of<paper_comparison::kind>(j.at(0), 2);
        p.subject = j.at(1).get<std::string>();
        p.paper = j.at(2).get<std::string>();
        p.printed_text = j.at(3).get<std::string>();
        p.printed = get(j.at(4));
        p.derived = get(j.at(5));
        get_verdict(j.at(6), p.agreement);
        get_list(j.at(7), p.findings, &derivation_codec::get_finding);
        p.reconciliations = j.at(8).get<std::vector<std::string>>();
        if (!j.at(9).is_null()) {
            p.test.emplace();
            get_check(j.at(9), *p.test);
        }
        p.where = get_where(j.at(10));
        get_written(j.at(11), p.written);
        p.quote = j.at(12).get<std::string>();
        p.label = j.at(13).get<std::string>();
    }

    json put_result(const result& r)
    {
        return {r.name,   put(r.symbol),          put(r.value), put(r.display),
                r.paper,  put_written(r.written), list(r.cases, &derivation_codec::put_case)};
    }
    void get_result(const json& j, result& r)
    {
        r.name = j.at(0).get<std::string>();
        r.symbol = get(j.at(1));
        r.value = get(j.at(2));
        r.display = get(j.at(3));
        r.paper = j.at(4).get<std::string>();
        get_written(j.at(5), r.written);
        get_list(j.at(6), r.cases, &derivation_codec::get_case);
    }

    // ---- kernels ----

    // A kernel's input is a quantity of its own (a copy of the derivation's, or of a
    // component it names), kept whole.
    json put_quantity(const quantity& q)
    {
        return {q.name,           put(q.symbol),       put_domain(q.range),   q.latex,
                q.meaning,        put_optional(q.definition), put_written(q.written), put_where(q.where),
                q.dim ? put_dimension(*q.dim) : json(), q.dim_declared};
    }
    void get_quantity(const json& j, quantity& q)
    {
        q.name = j.at(0).get<std::string>();
        q.symbol = get(j.at(1));
        q.range = get_domain(j.at(2));
        q.latex = j.at(3).get<std::string>();
        q.meaning = j.at(4).get<std::string>();
        q.definition = get_optional(j.at(5));
        get_written(j.at(6), q.written);
        q.where = get_where(j.at(7));
        if (!j.at(8).is_null())
            q.dim = get_dimension(j.at(8));
        q.dim_declared = j.at(9).get<bool>();
    }

    json put_parameter(const kernel_parameter& p)
    {
        return {p.name, list(p.components, &derivation_codec::put_quantity), p.is_array};
    }
    void get_parameter(const json& j, kernel_parameter& p)
    {
        p.name = j.at(0).get<std::string>();
        get_list(j.at(1), p.components, &derivation_codec::get_quantity);
        p.is_array = j.at(2).get<bool>();
    }

    json put_output(const kernel_output& o)
    {
        json candidates = json::array();
        for (const std::vector<form>& forms : o.candidates) {
            json each = json::array();
            for (const form& f : forms)
                each.push_back({f.label, put(f.value)});
            candidates.push_back(each);
        }
        json bounds = json::array();
        for (std::size_t i = 0; i < o.bound_ulps.size(); ++i)
            bounds.push_back({bits(o.bound_ulps[i]), o.bound_because[i], bits(o.fast_bound_ulps[i]),
                              o.fast_bound_because[i]});
        return {o.member, o.is_array, put_exs(o.values), candidates, code(o.error), put(o.scale_factor), bounds};
    }
    void get_output(const json& j, kernel_output& o)
    {
        o.member = j.at(0).get<std::string>();
        o.is_array = j.at(1).get<bool>();
        o.values = get_exs(j.at(2));
        for (const json& each : j.at(3)) {
            o.candidates.emplace_back();
            for (const json& f : each)
                o.candidates.back().push_back({f.at(0).get<std::string>(), get(f.at(1))});
        }
        o.error = enum_of<kernel_output::scale>(j.at(4), 1);
        o.scale_factor = get(j.at(5));
        const json& bounds = j.at(6);
        if (bounds.size() != o.bound_ulps.size())
            throw not_readable("bounds of another number of types");
        for (std::size_t i = 0; i < o.bound_ulps.size(); ++i) {
            o.bound_ulps[i] = from_bits(bounds[i].at(0));
            o.bound_because[i] = bounds[i].at(1).get<std::string>();
            o.fast_bound_ulps[i] = from_bits(bounds[i].at(2));
            o.fast_bound_because[i] = bounds[i].at(3).get<std::string>();
        }
    }

    json put_guard(const kernel_guard& g)
    {
        return {g.status, g.parameters, put_optional(g.condition), code(g.op)};
    }
    void get_guard(const json& j, kernel_guard& g)
    {
        g.status = j.at(0).get<std::string>();
        g.parameters = j.at(1).get<std::vector<std::string>>();
        g.condition = get_optional(j.at(2));
        g.op = enum_of<relation>(j.at(3), 4);
    }

    json put_regime(const sampling_regime& r)
    {
        return {r.name,          put_where(r.where), code(r.what),       r.start,     put_exs(r.inputs),
                put_exs(r.offsets), put_exs(r.slopes), put(r.denominator), bits(r.from), bits(r.to)};
    }
    void get_regime(const json& j, sampling_regime& r)
    {
        r.name = j.at(0).get<std::string>();
        r.where = get_where(j.at(1));
        r.what = enum_of<sampling_regime::kind>(j.at(2), 1);
        r.start = j.at(3).get<std::string>();
        r.inputs = get_exs(j.at(4));
        r.offsets = get_exs(j.at(5));
        r.slopes = get_exs(j.at(6));
        r.denominator = get(j.at(7));
        r.from = from_bits(j.at(8));
        r.to = from_bits(j.at(9));
    }

    json put_kernel(const kernel& k)
    {
        return {k.name,
                put_where(k.where),
                list(k.parameters, &derivation_codec::put_parameter),
                list(k.outputs, &derivation_codec::put_output),
                list(k.guards, &derivation_codec::put_guard),
                put_exs(k.velocities),
                put_exs(k.speeds),
                put_pairs(k.lets),
                list(k.regimes, &derivation_codec::put_regime),
                k.batch,
                k.limit_of,
                k.fixed_mass,
                list(k.limits, &derivation_codec::put_kernel)};
    }
    void get_kernel(const json& j, kernel& k)
    {
        k.name = j.at(0).get<std::string>();
        k.where = get_where(j.at(1));
        get_list(j.at(2), k.parameters, &derivation_codec::get_parameter);
        get_list(j.at(3), k.outputs, &derivation_codec::get_output);
        get_list(j.at(4), k.guards, &derivation_codec::get_guard);
        k.velocities = get_exs(j.at(5));
        k.speeds = get_exs(j.at(6));
        k.lets = get_pairs(j.at(7));
        get_list(j.at(8), k.regimes, &derivation_codec::get_regime);
        k.batch = j.at(9).get<bool>();
        k.limit_of = j.at(10).get<std::string>();
        k.fixed_mass = j.at(11).get<std::string>();
        get_list(j.at(12), k.limits, &derivation_codec::get_kernel);
    }

    std::map<std::string, const std::string*> contents_;
    std::set<std::string> files_;                                      // writing: the files places name
    std::map<std::string, std::vector<std::uint32_t>> lines_moved_;     // reading: old line -> line now
    // Writing: the symbols of the table by their place, the nodes so far, the others.
    std::map<GiNaC::ex, std::size_t, GiNaC::ex_is_less> table_;
    std::map<GiNaC::ex, std::size_t, GiNaC::ex_is_less> ids_;
    json nodes_ = json::array();
    json temporaries_ = json::array();
    // Reading.
    const json* nodes_in_ = nullptr;
    const json* temporaries_in_ = nullptr;
    std::vector<GiNaC::ex> symbols_in_;
    std::vector<std::optional<GiNaC::ex>> built_;
    std::vector<std::optional<GiNaC::ex>> temporary_symbols_;
};

std::optional<std::string> stored_derivation(const derivation& d, const derived_by_id& done)
{
    try {
        derivation_codec codec(d.source, done);
        return format_line + codec.write(d).dump();
    } catch (const not_storable&) {
        return std::nullopt;
    } catch (const json::exception&) {
        // A text that is not UTF-8 (a file name of other bytes): not kept.
        return std::nullopt;
    }
}

std::optional<derivation> restored_derivation(const std::string& text, const spec::derivation& source,
                                             const derived_by_id& done)
{
    const std::string header = format_line;
    if (text.compare(0, header.size(), header) != 0)
        return std::nullopt;
    try {
        const json in = json::parse(text.begin() + static_cast<std::ptrdiff_t>(header.size()), text.end());
        derivation_codec codec(source, done);
        return codec.read(in, source);
    } catch (const not_readable&) {
        return std::nullopt;
    } catch (const json::exception&) {
        return std::nullopt;
    } catch (const std::exception&) {
        // GiNaC's: a function no longer registered, a division by zero in a damaged text.
        return std::nullopt;
    }
}

} // namespace impact::engine
