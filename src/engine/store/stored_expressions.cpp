// GiNaC's expressions as stored text: a graph of nodes, each distinct expression written
// once and every node after its operands; numbers as exact rationals (or complex ones), the
// derivation's symbols by their place in its table, any other symbol by its class and names.
#include "engine/store/stored_codec.h"

#include <cln/integer_io.h>

#include <cstring>
#include <locale>
#include <sstream>

namespace impact::engine {

namespace stored_detail {

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

} // namespace stored_detail

using namespace stored_detail;

namespace {

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

bool holds_float(const GiNaC::ex& e)
{
    if (GiNaC::is_a<GiNaC::numeric>(e))
        return !GiNaC::ex_to<GiNaC::numeric>(e).is_crational();
    for (std::size_t i = 0; i < e.nops(); ++i)
        if (holds_float(e.op(i)))
            return true;
    return false;
}

} // namespace

// An expression as the index of its node; each distinct expression written once.
json derivation_codec::put(const GiNaC::ex& e)
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

GiNaC::ex derivation_codec::get(const json& j)
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

GiNaC::ex derivation_codec::temporary(std::size_t i)
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

json derivation_codec::put_optional(const std::optional<GiNaC::ex>& e) { return e ? put(*e) : json(); }

std::optional<GiNaC::ex> derivation_codec::get_optional(const json& j) { return j.is_null() ? std::nullopt : std::optional(get(j)); }

json derivation_codec::put_pairs(const std::vector<std::pair<GiNaC::ex, GiNaC::ex>>& pairs)
{
    json out = json::array();
    for (const auto& [a, b] : pairs)
        out.push_back({put(a), put(b)});
    return out;
}

std::vector<std::pair<GiNaC::ex, GiNaC::ex>> derivation_codec::get_pairs(const json& j)
{
    std::vector<std::pair<GiNaC::ex, GiNaC::ex>> out;
    for (const json& p : j)
        out.emplace_back(get(p.at(0)), get(p.at(1)));
    return out;
}

json derivation_codec::put_exs(const std::vector<GiNaC::ex>& all)
{
    json out = json::array();
    for (const GiNaC::ex& e : all)
        out.push_back(put(e));
    return out;
}

std::vector<GiNaC::ex> derivation_codec::get_exs(const json& j)
{
    std::vector<GiNaC::ex> out;
    for (const json& e : j)
        out.push_back(get(e));
    return out;
}

} // namespace impact::engine
