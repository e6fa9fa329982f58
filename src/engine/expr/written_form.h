// How an expression was written in its derivation file.
//
// Read once, by the engine, where the expression itself is read (an abbreviation's
// definition, a given equation, a step, a display form, a check's claim, the paper's
// printed form), and carried beside it for the printers, which never read the text.
//
// GiNaC keeps neither the order of terms and factors nor the way round a sum was
// written: it sorts operands by hash and may move a sign into a sum, storing
// -(1 - eps^2)*x as (-1 + eps^2)*x. A display form is chosen by a physicist for how it
// reads, so the LaTeX printer prints it the way it was written: a `written_form`
// records, for each sum and product of the text, its terms and factors in written
// order and which way round each sum was written. The printer consults it and falls
// back to `term_order` for whatever the text does not settle (GiNaC may have merged or
// cancelled parts of it), so printing stays deterministic either way.
#pragma once

#include <ginac/ginac.h>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace impact::engine {

class written_form {
public:
    /// Turns a piece of the text (a term, a factor, a sum) into GiNaC, e.g. with the
    /// derivation's symbol table; it may throw, and then the piece is not recorded.
    using parser = std::function<GiNaC::ex(const std::string&)>;

    /// Nothing written: every question is answered "not written".
    written_form() = default;

    /// Reads an expression, or a relation `lhs = rhs` (also <=, <, >=, >), as written.
    /// Text the reader does not follow gives an empty form, never an error.
    static written_form read(const std::string& text, const parser& parse);

    /// A factor of a written product: base^exponent, or a divisor (written after `/`).
    struct factor {
        GiNaC::ex base;
        GiNaC::ex exponent;
        bool divides = false;
    };

    /// A written product: its factors in written order. `leading_fraction` when it starts
    /// with a number divided by a number (`1/2*m*v^2`), which is then typeset ½ m v².
    struct product {
        std::vector<factor> factors;
        bool leading_fraction = false;
    };

    /// The written terms of a sum equal to `sum`, in written order; nullptr when no sum of
    /// the text equals it.
    const std::vector<GiNaC::ex>* terms(const GiNaC::ex& sum) const;

    /// Which way round the sum was written: true as it is, false as its negation (and
    /// not as it is); nothing when neither is written.
    std::optional<bool> as_written(const GiNaC::ex& sum) const;

    /// True when `sum` is written as the negation of a sum in parentheses: -(a - b).
    bool negated_group(const GiNaC::ex& sum) const;

    /// True when base^exponent is written as a power, e.g. m_eff^(-1) (not m_eff in a
    /// denominator).
    bool written_power(const GiNaC::ex& base, const GiNaC::ex& exponent) const;

    /// The written product sharing the most factors base^exponent with `factors` (at least
    /// one); a divisor d^k of the text matches d^-k.
    const product* best_product(const std::vector<std::pair<GiNaC::ex, GiNaC::ex>>& factors) const;

    /// True when the written factor is base^exponent (a divisor d^k as d^-k).
    static bool matches(const factor& written, const GiNaC::ex& base, const GiNaC::ex& exponent);

    bool empty() const { return sums_.empty() && products_.empty(); }

    /// The text itself as a tree, for a printer that shows a form exactly as transcribed
    /// (the paper's printed lines: m v + m ε v + m v - m ε v, which GiNaC would merge
    /// into 2 m v): sums with the sign of each term, products with their divisors in
    /// written order, powers, calls, parentheses, and the atoms (symbols, numbers) as the
    /// derivation reads them. A relation `lhs = rhs` is a node of its own.
    struct node {
        enum class kind { sum, product, negate, power, call, group, atom, relation };
        kind what = kind::atom;
        std::vector<bool> flags;       ///< sum: the term is subtracted; product: the factor divides
        std::vector<node> children;    ///< relation: its sides
        GiNaC::ex value;               ///< atom: the symbol or number
        std::string name;              ///< call: the function (sqrt, acos, ...); relation: =, <=, ...
    };

    /// The tree of the text; nothing when the text was not followed (or nothing was read).
    const std::optional<node>& tree() const { return tree_; }

    /// Whether an atom of the text holds `symbol`: a quantity the text uses, though GiNaC
    /// may have cancelled it from the value (x*D/D is x), whose conditions the text needs.
    bool mentions(const GiNaC::ex& symbol) const;

private:
    friend class written_reader;
    friend class derivation_codec;   // keeps a derivation between runs (engine/store/stored.h)
    struct sum {
        GiNaC::ex value;
        std::vector<GiNaC::ex> terms;
    };
    std::vector<sum> sums_;
    std::vector<GiNaC::ex> negated_groups_;
    std::vector<product> products_;
    std::vector<std::pair<GiNaC::ex, GiNaC::ex>> powers_;
    std::optional<node> tree_;
};

} // namespace impact::engine
