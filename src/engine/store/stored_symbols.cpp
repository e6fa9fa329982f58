// The symbol table and the written forms (how a quantity or an equation was written in
// its file) as stored text.
#include "engine/store/stored_codec.h"

#include "engine/expr/dimensional.h"

namespace impact::engine {

using namespace stored_detail;

// ---- written forms ----

json derivation_codec::put_node(const written_form::node& n)
{
    json children = json::array();
    for (const written_form::node& c : n.children)
        children.push_back(put_node(c));
    return {code(n.what), n.flags, children, put(n.value), n.name};
}

void derivation_codec::get_node(const json& j, written_form::node& n)
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

json derivation_codec::put_product(const written_form::product& p)
{
    json factors = json::array();
    for (const written_form::factor& f : p.factors)
        factors.push_back({put(f.base), put(f.exponent), f.divides});
    return {factors, p.leading_fraction};
}

void derivation_codec::get_product(const json& j, written_form::product& p)
{
    for (const json& f : j.at(0))
        p.factors.push_back({get(f.at(0)), get(f.at(1)), f.at(2).get<bool>()});
    p.leading_fraction = j.at(1).get<bool>();
}

json derivation_codec::put_written(const written_form& w)
{
    json sums = json::array();
    for (const written_form::sum& s : w.sums_)
        sums.push_back({put(s.value), put_exs(s.terms)});
    return {sums, put_exs(w.negated_groups_), list(w.products_, &derivation_codec::put_product),
            put_pairs(w.powers_), w.tree_ ? put_node(*w.tree_) : json()};
}

void derivation_codec::get_written(const json& j, written_form& w)
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

json derivation_codec::put_symbols(const symbol_table& table)
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
void derivation_codec::get_symbols(const json& j, symbol_table& table, const spec::derivation& source)
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

void derivation_codec::get_symbol_values(const json& j, symbol_table& table)
{
    std::size_t i = 0;
    for (const json& s : j) {
        quantity& q = table.quantities_.at(i++);
        q.definition = get_optional(s.at(4));
        get_written(s.at(5), q.written);
    }
}

} // namespace impact::engine
