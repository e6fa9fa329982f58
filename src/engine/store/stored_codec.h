// The codec that writes a derivation as text and reads it back (stored.h), shared by the
// files that each keep one kind of its parts: stored.cpp the derivation as a whole and its
// places (file, line, column; moved when comments above them changed), stored_expressions.cpp
// GiNaC's expressions as a graph of nodes, each written once, stored_proofs.cpp the small
// parts a proof is made of (domains, dimensions, signs, verdicts), stored_symbols.cpp the
// symbol table and written forms, stored_parts.cpp the derivation's givens, steps, checks,
// paper comparisons and results, stored_kernels.cpp its kernels. Each part is written by a
// put_ method and read back by the get_ method beside it, in the same order.
#pragma once

#include "engine/derivation/derivation.h"
#include "spec/derivation.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace impact::engine {

using json = nlohmann::json;

namespace stored_detail {

// Something a derivation holds that cannot be kept exactly.
struct not_storable : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// A stored text that is not what this version wrote.
struct not_readable : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Numbers kept exactly (stored_expressions.cpp): an integer as its decimal digits, a
// double by its bits.
std::string integer_text(const GiNaC::numeric& n);
GiNaC::numeric integer_of(const json& j);
json bits(double x);
double from_bits(const json& j);

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

} // namespace stored_detail

// Writes and reads a derivation. A friend of the classes whose state it keeps
// (symbol_table, written_form), so that it keeps exactly what they hold.
class derivation_codec {
public:
    derivation_codec(const spec::derivation& source, const derived_by_id& done);

    // ---- writing ---- (stored.cpp)

    json write(const derivation& d);

    // ---- reading ---- (stored.cpp)

    derivation read(const json& in, const spec::derivation& source);

private:
    // ---- expressions ---- (stored_expressions.cpp)

    json put(const GiNaC::ex& e);
    GiNaC::ex get(const json& j);
    GiNaC::ex temporary(std::size_t i);

    json put_optional(const std::optional<GiNaC::ex>& e);
    std::optional<GiNaC::ex> get_optional(const json& j);

    json put_pairs(const std::vector<std::pair<GiNaC::ex, GiNaC::ex>>& pairs);
    std::vector<std::pair<GiNaC::ex, GiNaC::ex>> get_pairs(const json& j);
    json put_exs(const std::vector<GiNaC::ex>& all);
    std::vector<GiNaC::ex> get_exs(const json& j);

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

    // ---- small parts ---- (places: stored.cpp; the rest: stored_proofs.cpp)

    json put_where(const source_location& w);
    source_location get_where(const json& j);

    static json put_domain(const domain& d);
    static domain get_domain(const json& j);

    static json put_dimension(const dimension& d);
    static dimension get_dimension(const json& j);

    static json put_sign(const sign_set& s);
    static sign_set get_sign(const json& j);

    json put_finding(const finding& f);
    void get_finding(const json& j, finding& f);

    json put_reason(const sign_reason& r);
    void get_reason(const json& j, sign_reason& r);

    json put_sign_step(const sign_step& s);
    void get_sign_step(const json& j, sign_step& s);

    json put_condition(const condition& c);
    void get_condition(const json& j, condition& c);

    json put_verdict(const verdict& v);
    void get_verdict(const json& j, verdict& v);

    json put_limit_method(const limit_method& m);
    void get_limit_method(const json& j, limit_method& m);

    // ---- written forms ---- (stored_symbols.cpp)

    json put_node(const written_form::node& n);
    void get_node(const json& j, written_form::node& n);

    json put_product(const written_form::product& p);
    void get_product(const json& j, written_form::product& p);

    json put_written(const written_form& w);
    void get_written(const json& j, written_form& w);

    // ---- symbols ---- (stored_symbols.cpp)

    json put_symbols(const symbol_table& table);
    void get_symbols(const json& j, symbol_table& table, const spec::derivation& source);
    void get_symbol_values(const json& j, symbol_table& table);

    // ---- the derivation's parts ---- (stored_parts.cpp)

    json put_equation(const equation& e);
    void get_equation(const json& j, equation& e);

    json put_case(const case_value& c);
    void get_case(const json& j, case_value& c);

    json put_part(const check_result::part& p);
    void get_part(const json& j, check_result::part& p);

    json put_check(const check_result& c);
    void get_check(const json& j, check_result& c);

    json put_solution(const solution& s);
    void get_solution(const json& j, solution& s);

    json put_step(const step_result& s);
    void get_step(const json& j, step_result& s);

    json put_comparison(const paper_comparison& p);
    void get_comparison(const json& j, paper_comparison& p);

    json put_result(const result& r);
    void get_result(const json& j, result& r);

    // ---- kernels ---- (stored_kernels.cpp)

    json put_quantity(const quantity& q);
    void get_quantity(const json& j, quantity& q);

    json put_parameter(const kernel_parameter& p);
    void get_parameter(const json& j, kernel_parameter& p);

    json put_output(const kernel_output& o);
    void get_output(const json& j, kernel_output& o);

    json put_guard(const kernel_guard& g);
    void get_guard(const json& j, kernel_guard& g);

    json put_regime(const sampling_regime& r);
    void get_regime(const json& j, sampling_regime& r);

    json put_kernel(const kernel& k);
    void get_kernel(const json& j, kernel& k);

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

} // namespace impact::engine
