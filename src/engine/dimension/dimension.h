// Physical dimensions: a quantity's mass, length and time exponents (and those of any
// base a derivation adds, an angle say), and the dimension of an expression, inferred
// from its symbols'.
//
// A physicist's first check of a formula: terms of a sum, both sides of an equation and
// the arguments of atan2 share one dimension; exponents and the arguments of exp, log and
// the trigonometric functions are pure numbers; a square root halves the exponents. An
// expression that breaks a rule is refused with the two dimensions that disagree, named
// as a physicist would name them where the combination is a familiar one ("mass*length/time,
// a momentum").
#pragma once

#include "spec/error.h"

#include <ginac/ginac.h>

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace impact::engine {

/// A product of powers of base dimensions, e.g. mass^1 length^2 time^-2. The empty
/// product is a pure number.
class dimension {
public:
    dimension() = default;
    /// One base dimension to the first power: dimension::base("mass").
    static dimension base(const std::string& name);

    bool is_pure_number() const { return exponents_.empty(); }
    dimension operator*(const dimension& other) const;
    dimension operator/(const dimension& other) const;
    dimension power(const GiNaC::numeric& exponent) const;
    bool operator==(const dimension& other) const { return exponents_ == other.exponents_; }
    bool operator!=(const dimension& other) const { return !(*this == other); }

    /// Canonical text: bases with positive exponents first (mass, length, time, then
    /// others by name), then `/` and the rest: "mass*length^2/time^2", "1/time", "1".
    std::string to_string() const;
    /// The name a physicist gives the combination ("a momentum", "an energy"), if familiar.
    std::optional<std::string> familiar_name() const;
    /// to_string(), followed by the familiar name when there is one:
    /// "mass*length/time (a momentum)".
    std::string describe() const;
    /// The SI unit of the dimension, e.g. "kg m^2 s^-2" (bases other than mass, length
    /// and time by their own name).
    std::string si_unit() const;
    /// The SI unit as factors and exponents: {"kg", 1}, {"m", 2}, {"s", -2}.
    std::vector<std::pair<std::string, GiNaC::numeric>> si_factors() const;
    /// Each base and its exponent (none zero), by base name.
    const std::map<std::string, GiNaC::numeric, std::less<>>& exponents() const { return exponents_; }

private:
    std::map<std::string, GiNaC::numeric, std::less<>> exponents_;   ///< no zero exponents
};

/// Two parts of an expression that must share a dimension and do not: the terms of a sum
/// (`adds`) or the sides of an equation (`sets`), kept apart from the message so that a
/// finding can name them.
class dimension_clash : public error {
public:
    enum class kind { adds, sets };
    dimension_clash(source_location where, const std::string& what, kind k, GiNaC::ex first, dimension first_dim,
                    GiNaC::ex second, dimension second_dim)
        : error(std::move(where), what), how(k), first(std::move(first)), first_dim(std::move(first_dim)),
          second(std::move(second)), second_dim(std::move(second_dim))
    {
    }
    kind how;
    GiNaC::ex first;
    dimension first_dim;
    GiNaC::ex second;
    dimension second_dim;
};

/// Names of dimensions a derivation may use: mass, length and time, the familiar
/// combinations (velocity, acceleration, momentum, energy, force, angular_velocity,
/// moment_of_inertia, ...) and those the derivation adds.
class dimension_names {
public:
    dimension_names();
    /// A new base (`angle`) or a new name for a combination (`spin = 1/time`).
    void add(const std::string& name, const dimension& d, const source_location& where);
    void add_base(const std::string& name, const source_location& where);
    /// Parses "mass*length^2/time^2", "velocity", "1", "energy/mass". Throws
    /// `impact::error` at `where` when a name is unknown or the text is not a product of powers.
    dimension parse(const std::string& text, const source_location& where) const;
    bool knows(const std::string& name) const { return names_.count(name) != 0; }

private:
    std::map<std::string, dimension, std::less<>> names_;
};

/// The dimensions of a derivation's symbols, by GiNaC symbol.
using dimension_map = std::map<GiNaC::ex, dimension, GiNaC::ex_is_less>;

/// The dimension of `e`, from its symbols' dimensions. A symbol absent from `known` makes
/// the result unknown (nullopt), as does any part built on it; the parts that are known
/// are still checked. Throws `impact::error` at `where` naming the rule broken and the
/// dimensions, e.g. "adds mass*length/time (a momentum) to mass*length^2/time^2 (an energy)".
/// `text` writes the expressions a message names (by default GiNaC's own printing, whose
/// order of terms may change from run to run: the engine passes symbol_table::text).
using expression_text = std::function<std::string(const GiNaC::ex&)>;
std::optional<dimension> dimension_of(const GiNaC::ex& e, const dimension_map& known, const source_location& where,
                                      const expression_text& text = {});

/// Both sides of `relation` (an equation or inequality) share one dimension; returns it.
std::optional<dimension> dimension_of_relation(const GiNaC::ex& relation, const dimension_map& known,
                                               const source_location& where, const expression_text& text = {});

} // namespace impact::engine
