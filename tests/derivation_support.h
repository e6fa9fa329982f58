// What tests of derivations written for the tests share: deriving a file or a text,
// a check's entry, the error a text raises, and finding a symbol, result or check by name.
#pragma once

#include <boost/test/unit_test.hpp>

#include "engine/derive/derive.h"
#include "spec/derivation.h"

#include <string>

namespace impact::testing {

inline engine::derivation derive_text(const std::string& text, const engine::derived_by_id& done = {})
{
    return engine::derive(spec::parse_derivation(text, "test.toml"), done);
}

/// A `[[check]]` entry of a derivation file: `name` claims `claim`.
inline std::string check(const std::string& name, const std::string& claim)
{
    return "[[check]]\nname = \"" + name + "\"\nclaim = \"" + claim + "\"\n";
}

/// A derivation file of the tests, e.g. derive_file("tests/solve/projectile_flight.toml").
inline engine::derivation derive_file(const std::string& relative)
{
    return engine::derive(spec::read_derivation(IMPACT_SOURCE_DIR "/" + relative), {});
}

/// The error deriving `text` raises; the test fails when it raises none.
inline impact::error error_for(const std::string& text)
{
    try {
        derive_text(text);
    } catch (const impact::error& e) {
        return e;
    }
    BOOST_FAIL("no error for:\n" + text);
    throw;
}

inline GiNaC::ex sym(const engine::derivation& d, const std::string& name)
{
    const engine::quantity* q = d.symbols.find(name);
    BOOST_REQUIRE_MESSAGE(q, "no symbol " + name + " in " + d.id());
    return q->symbol;
}

inline GiNaC::ex value_of(const engine::derivation& d, const std::string& name)
{
    const engine::result* r = d.find_result(name);
    BOOST_REQUIRE_MESSAGE(r, "no result " + name + " in " + d.id());
    return r->value;
}

/// Whether two expressions are equal as rational functions.
inline bool equal(const GiNaC::ex& a, const GiNaC::ex& b)
{
    return GiNaC::normal(GiNaC::expand(a - b)).is_zero();
}

inline const engine::check_result& check_named(const engine::derivation& d, const std::string& name)
{
    for (const engine::check_result* c : d.all_checks())
        if (c->name == name)
            return *c;
    BOOST_FAIL("no check " + name + " in " + d.id());
    throw;
}

} // namespace impact::testing
