// A finding about one of the paper's printed forms (the smallest change that reconciles
// it with what is derived, a dimensional inconsistency, the regime where a claim holds
// instead), kept as words and the mathematics they mention, so that each emitter
// typesets it in its own way: plain text for the terminal and JSON, LaTeX for the report.
// No later stage reads the words back.
#pragma once

#include "engine/dimension/dimension.h"
#include "engine/expr/symbols.h"

#include <ginac/ginac.h>

#include <optional>
#include <string>
#include <vector>

namespace impact::engine {

struct finding {
    struct part {
        enum class kind {
            words,      ///< plain prose
            math,       ///< an expression (or an equation) of the derivation's symbols
            tends,      ///< `value` tends to `point` (or to infinity when `point` is empty)
            dimension,  ///< a physical dimension, named as a physicist names it
        };
        kind what = kind::words;
        std::string words;
        GiNaC::ex value;
        std::optional<GiNaC::ex> point;
        engine::dimension dim;
        /// math: a term of a sum, named whatever its sign ("the sign of the term ..."), so
        /// that a printer may show it as the paper writes it, +x or -x.
        bool term = false;
        /// math: when `value` is lhs == rhs, the relation it stands for (an inequality
        /// keeps its sides in `value` and its relation here).
        relation op = relation::equal;
    };
    std::vector<part> parts;
    /// A smallest change: the printed form with the change made, in the printed form's own
    /// variables, proven equal to the derived value (an equation: equivalent to the derived one).
    std::optional<GiNaC::ex> corrected;

    finding& say(std::string text)
    {
        parts.push_back({part::kind::words, std::move(text), {}, {}, {}});
        return *this;
    }
    finding& math(const GiNaC::ex& e)
    {
        parts.push_back({part::kind::math, {}, e, {}, {}});
        return *this;
    }
    /// `lhs op rhs`: an equation, or an inequality.
    finding& states(const GiNaC::ex& lhs, relation op, const GiNaC::ex& rhs)
    {
        math(lhs == rhs);
        parts.back().op = op;
        return *this;
    }
    /// A term of a sum, named whatever its sign.
    finding& term(const GiNaC::ex& e)
    {
        math(e);
        parts.back().term = true;
        return *this;
    }
    finding& tends(const GiNaC::ex& symbol, std::optional<GiNaC::ex> point)
    {
        parts.push_back({part::kind::tends, {}, symbol, std::move(point), {}});
        return *this;
    }
    finding& of_dimension(const engine::dimension& d)
    {
        parts.push_back({part::kind::dimension, {}, {}, {}, d});
        return *this;
    }
    /// A finding that is one piece of prose.
    static finding words(std::string text) { return finding().say(std::move(text)); }
};

/// The finding as plain text, expressions in the file's syntax: "the sign of the term
/// M*eps*(v_M-v_m)", "a momentum (mass*length/time) where an energy ... belongs".
std::string plain_text(const finding& f, const symbol_table& symbols);

/// Each finding as plain text.
std::vector<std::string> plain_texts(const std::vector<finding>& found, const symbol_table& symbols);

} // namespace impact::engine
