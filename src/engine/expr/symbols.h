// The symbols of one derivation and the parsing of its expressions.
//
// Each declared name becomes one GiNaC symbol whose class follows its domain
// (`possymbol` for positive quantities, `realsymbol` otherwise) and whose TeX name is
// the LaTeX given in the file. Expressions are read with GiNaC's own parser in strict
// mode, so an undeclared name is an error at the place it was written.
#pragma once

#include "engine/dimension/dimension.h"
#include "engine/expr/domain.h"
#include "engine/expr/written_form.h"
#include "spec/derivation.h"

#include <ginac/ginac.h>

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace impact::engine {

class term_order;

/// A declared symbol with its domain; abbreviations carry their definition.
struct quantity {
    std::string name;
    GiNaC::ex symbol;
    domain range;
    std::string latex;
    std::string meaning;
    std::optional<GiNaC::ex> definition;
    written_form written;   ///< how the definition was written, for the printers
    source_location where;
    /// Its physical dimension: declared (`dimension = "velocity"`), or inferred from its
    /// definition or the step that derives it; none when neither says.
    std::optional<dimension> dim;
    bool dim_declared = false;
};

/// The relation a claim states between its sides.
enum class relation { equal, less_equal, less, greater_equal, greater };
std::string to_string(relation r);

/// `lhs op rhs` as parsed from a claim.
struct claim_sides {
    relation op = relation::equal;
    GiNaC::ex lhs;
    GiNaC::ex rhs;
};

class symbol_table {
public:
    /// Declares a symbol; a second declaration of the same name is an error.
    const quantity& declare(const spec::symbol& declaration);
    /// Declares a copy of a quantity from another derivation (for `[[use]]`).
    const quantity& adopt(const quantity& other);

    const quantity* find(const std::string& name) const;
    const quantity& at(const spec::text& name) const;   ///< error when undeclared
    const std::vector<quantity>& all() const { return quantities_; }

    /// Parses an expression; errors name the place of `text`.
    GiNaC::ex parse(const spec::text& text) const;
    /// Parses `lhs = rhs` into a GiNaC relational.
    GiNaC::ex parse_equation(const spec::text& text) const;

    /// An expression in GiNaC's syntax, its operands in declaration order: the same text
    /// on every run (GiNaC's own order changes from run to run).
    std::string text(const GiNaC::ex& e) const;

    /// Parses `lhs = rhs`, `lhs <= rhs`, `lhs < rhs`, `lhs >= rhs` or `lhs > rhs`.
    claim_sides parse_claim(const spec::text& text) const;

    /// Substitutions that expand every abbreviation into declared quantities.
    GiNaC::exmap abbreviations() const;
    /// `e` with every abbreviation replaced by its definition, and those its definition
    /// uses in turn, until only declared quantities are left (G_t = sqrt(G_t . G_t), each
    /// G_t,i in r, g and d, d in r).
    GiNaC::ex in_inputs(const GiNaC::ex& e) const;
    /// The dimensions the derivation's symbols may be given (mass, length, time, their
    /// familiar combinations and the derivation's own `[[dimension]]`s).
    dimension_names& dimension_words() { return dimension_words_; }
    const dimension_names& dimension_words() const { return dimension_words_; }
    /// The dimension of each symbol that has one, keyed by the GiNaC symbol.
    dimension_map dimensions() const;
    /// Gives a symbol the dimension inferred for it (from its definition or a step).
    void infer_dimension(const GiNaC::ex& symbol, const dimension& d);
    /// The domain of each symbol, keyed by the GiNaC symbol.
    const domain* domain_of(const GiNaC::ex& symbol) const;

    /// The symbols' declaration order (see `declaration_order`), made once for the
    /// declarations so far; its copies share what it has worked out.
    const term_order& order() const;

private:
    friend class derivation_codec;   // keeps a derivation between runs (engine/store/stored.h)
    std::vector<quantity> quantities_;
    dimension_names dimension_words_;
    GiNaC::symtab table_;
    // Texts already read: the same pieces are read again and again (a symbol, `M + m`),
    // most of all by the LaTeX printer's written forms. Only a text that reads is kept,
    // and declaring more symbols never changes what it reads as.
    mutable std::map<std::string, GiNaC::ex> parsed_;
    mutable std::shared_ptr<const term_order> order_;   // reset by each declaration
    mutable std::shared_ptr<GiNaC::parser> reader_;      // reset by each declaration
};

/// An expression in GiNaC's own syntax, as its parser reads it back.
std::string ginac_text(const GiNaC::ex& e);

/// A parse or arithmetic failure turned into an `impact::error` at `where`.
[[noreturn]] void rethrow_at(const source_location& where, const std::string& what);

} // namespace impact::engine
