// The checks of a derivation's LaTeX fragment, with how each was established (a sign, a
// limit, cases), and a claim as checked, which the paper's part (latex_paper.cpp) and the
// errata table (latex_errata.cpp) show too.
#include "emit/errata.h"
#include "emit/latex.h"
#include "emit/latex_parts.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cctype>
#include <map>

namespace impact::emit {

const char* detail::latex_relation(engine::relation op)
{
    switch (op) {
    case engine::relation::equal: return "=";
    case engine::relation::less_equal: return "\\leq";
    case engine::relation::less: return "<";
    case engine::relation::greater_equal: return "\\geq";
    case engine::relation::greater: return ">";
    }
    return "=";
}

using detail::latex_relation;

namespace {

// True when a \frac has another \frac inside its arguments (too tall to set inline).
bool nested_fraction(const std::string& math)
{
    for (std::size_t at = math.find("\\frac"); at != std::string::npos; at = math.find("\\frac", at + 1)) {
        // The extent of the two argument groups.
        std::size_t i = at + 5;
        for (int group = 0; group < 2 && i < math.size(); ++group) {
            int depth = 0;
            const std::size_t begin = i;
            for (; i < math.size(); ++i) {
                depth += math[i] == '{' ? 1 : math[i] == '}' ? -1 : 0;
                if (depth == 0)
                    break;
            }
            if (math.substr(begin + 1, i - begin).find("\\frac") != std::string::npos)
                return true;
            ++i;
        }
    }
    return false;
}

// Whether a word of a check's name is the name of a Greek letter (elastic_tau), which
// LaTeX sets as that letter.
bool greek_letter(const std::string& w)
{
    static const char* const letters[] = {"alpha", "beta",  "gamma",   "delta", "epsilon", "zeta", "eta",   "theta",
                                          "iota",  "kappa", "lambda",  "mu",    "nu",      "xi",   "rho",   "sigma",
                                          "tau",   "upsilon", "phi",   "chi",   "psi",     "omega"};
    return std::find(std::begin(letters), std::end(letters), w) != std::end(letters);
}

// A check's name as a heading a physicist reads (LaTeX): its words, a single letter or a
// Greek letter's name as the quantity it names (n_is_a_unit_vector: "$n$ is a unit vector",
// elastic_tau: "Elastic $\tau$"), eq11 as "Eq. 11",
// and the sphere and component a name ends in as a qualifier: momentum_conserved_x is
// "Momentum conserved ($x$ component)", exchange_symmetry_M_y "Exchange symmetry ($M$,
// $y$ component)".
std::string heading(const std::string& name)
{
    std::vector<std::string> words;
    for (std::size_t begin = 0; begin <= name.size();) {
        const std::size_t end = std::min(name.find('_', begin), name.size());
        if (end > begin)
            words.push_back(name.substr(begin, end - begin));
        begin = end + 1;
    }
    std::vector<std::string> qualifiers;
    if (words.size() > 1 && (words.back() == "x" || words.back() == "y" || words.back() == "z")) {
        qualifiers.push_back("$" + words.back() + "$ component");
        words.pop_back();
    }
    if (words.size() > 1 && (words.back() == "M" || words.back() == "m" || words.back() == "J")) {
        qualifiers.insert(qualifiers.begin(), "$" + words.back() + "$");
        words.pop_back();
    }
    std::string out;
    for (const std::string& w : words) {
        std::string typeset = latex_text(w);
        const bool number_follows = w.size() > 2 && w.compare(0, 2, "eq") == 0 &&
                                    std::all_of(w.begin() + 2, w.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
        if (number_follows)
            typeset = "Eq.~" + w.substr(2);
        else if (w.size() == 1 && std::isalpha(static_cast<unsigned char>(w[0])) && w != "a")
            typeset = "$" + w + "$";
        else if (greek_letter(w))
            typeset = "$\\" + w + "$";
        else if (w == "galilean")
            typeset = "Galilean";
        out += (out.empty() ? "" : " ") + typeset;
    }
    if (!out.empty() && std::islower(static_cast<unsigned char>(out[0])))
        out[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(out[0])));
    if (!qualifiers.empty())
        out += " (" + qualifiers.front() + (qualifiers.size() > 1 ? ", " + qualifiers.back() : "") + ")";
    return out;
}

std::string sentence_end(const std::string& text)
{
    if (text.empty())
        return text;
    const char last = text.back();
    return (last == '.' || last == '?' || last == '!') ? text : text + ".";
}

// A sign as a relation to zero in LaTeX, or nothing when it is not one.
const char* relation_to_zero(const engine::sign_set& sign)
{
    static const std::pair<const char*, const char*> relations[] = {
        {">= 0", "\\geq"}, {"<= 0", "\\leq"}, {"> 0", ">"}, {"< 0", "<"}};
    for (const auto& [described, tex] : relations)
        if (sign.describe() == described)
            return tex;
    return nullptr;
}

} // namespace

namespace detail {

// Math set inline when it is short and flat, displayed (and broken) otherwise.
bool wants_display(const std::string& math)
{
    return latex_width(math) > 230 || nested_fraction(math);
}

// How a check was established, in words and math: the sign of each factor for an
// inequality, the method of a limit, the sample size when not proven.
std::string fragment_writer::how(const engine::check_result& c) const
{
    std::string out;
    if (c.limit_by)
        out += " The limit is established " + limit_text(*c.limit_by) + ".";
    if (!c.outcome.proof.empty()) {
        std::vector<std::string> signs;
        for (const engine::sign_step& step : c.outcome.proof)
            signs.push_back(sign_text(step));
        out += " From the signs of its factors: " + listing(signs) + ".";
    }
    if (const std::string unsettled = unsettled_text(c.outcome); !unsettled.empty())
        out += " " + unsettled;
    return out;
}

// What a check not proven shows: its sample size, or its residual; nothing when proven.
std::string fragment_writer::unsettled_text(const engine::verdict& v) const
{
    if (v.what == engine::verdict::status::sampled)
        return fmt::format("GiNaC cannot decide it; it holds at {} sampled points of the domains (40 digits).", v.samples);
    if (v.what == engine::verdict::status::failed)
        return "Residual: $" + math(v.residual) + "$.";
    return "";
}

// A check proven case by case, or a continuity check boundary by boundary: each part.
std::string fragment_writer::cases_text(const engine::check_result& c) const
{
    if (c.parts.empty())
        return "";
    std::vector<std::string> parts;
    const engine::quantity* q = d_.symbols.find(c.cases_of);
    // The case as proven when it is short; else as the file writes it (its value in the
    // declared quantities is displayed where the quantity is defined).
    const auto case_value_text = [this](const GiNaC::ex& symbol, const engine::case_value& one) {
        std::string value = math(one.value);
        if (latex_width(value) > 0.4 * content_width)
            value = math(one.as_written, &one.written);
        return fmt::format("${} = {}$", math(symbol), value);
    };
    // A case as long as a line is referred to by its number: it is displayed where its
    // quantity is defined, and a check repeating it would only repeat it (at special
    // values, where the case's value changes, it is short again).
    const auto too_long = [](const std::string& text) { return latex_width(text) > 0.8 * content_width; };
    for (const engine::check_result::part& p : c.parts) {
        if (p.in_case && (!p.in_cases.empty() || q)) {
            std::vector<std::string> values;
            if (!p.in_cases.empty())
                for (const auto& [symbol, one] : p.in_cases)
                    values.push_back(case_value_text(symbol, one));
            else
                values.push_back(case_value_text(q->symbol, *p.in_case));
            const std::string text = fmt::format("{} where ${}$", fmt::join(values, ", "), case_condition(*p.in_case));
            if (too_long(text))
                parts.push_back(fmt::format("case {} of ${}$: {}", p.first,
                                            q ? math(q->symbol) : math(p.in_cases.front().first),
                                            status_text(p.outcome, order_)));
            else
                parts.push_back(fmt::format("case {} ({}): {}", p.first, text, status_text(p.outcome, order_)));
        } else if (p.boundary) {
            const std::string value = math(p.boundary->second);
            if (latex_width(value) > 0.4 * content_width)
                parts.push_back(fmt::format("cases {} and {} where their conditions meet, solved for ${}$: {}",
                                            p.first, p.second, math(p.boundary->first), status_text(p.outcome, order_)));
            else
                parts.push_back(fmt::format("cases {} and {} at ${} = {}$: {}", p.first, p.second,
                                            math(p.boundary->first), value, status_text(p.outcome, order_)));
        } else {
            parts.push_back(fmt::format("{}: {}", latex_text(p.under), status_text(p.outcome, order_)));
        }
    }
    // Every case proven, and the list longer than a line (the rough spheres' sticking and
    // sliding, each with its condition): said once, the cases being displayed where their
    // quantity is defined.
    const bool all_proven = std::all_of(c.parts.begin(), c.parts.end(), [](const engine::check_result::part& p) {
        return p.in_case && p.outcome.what == engine::verdict::status::proven;
    });
    std::vector<std::string> names;
    if (q)
        names.push_back("$" + math(q->symbol) + "$");
    else if (!c.parts.empty())
        for (const auto& [symbol, one] : c.parts.front().in_cases)
            names.push_back("$" + math(symbol) + "$");
    if (!c.continuity && all_proven && !names.empty() && c.parts.size() > 1 &&
        latex_width(listing(parts)) > content_width) {
        return fmt::format(" Case by case, in each of the {} cases of {} (as defined above): \\textbf{{proven}}.",
                           c.parts.size(), listing(names));
    }
    return fmt::format(" {}: {}.", c.continuity ? "Where the cases meet" : "Case by case", listing(parts));
}

std::string fragment_writer::proof(const engine::check_result& c) const
{
    using basis = engine::verdict::basis;
    const engine::verdict& v = c.outcome;
    std::string out = "Claim: " + sentence_end(claim_latex(d_, c)) + "\n\n";
    if (c.limit_by)
        out += "The limit is established " + limit_text(*c.limit_by) + ".\n\n";
    if (const std::string by_cases = cases_text(c); !by_cases.empty())
        out += by_cases.substr(1) + "\n\n";
    if (v.how == basis::zero_difference)
        out += "The difference of its sides normalises to zero.\n\n";
    else if (v.how == basis::signs && !v.residual.is_zero())
        out += fmt::format("The difference of its sides is ${}$, and the sign of each of its factors follows from "
                           "the domains.\n\n",
                           math(textbook(v.residual).value));
    else if ((v.how == basis::identity || v.how == basis::decided || (v.how == basis::none && c.parts.empty())) &&
             !v.typeset.parts.empty())
        out += sentence_end(capitalised(finding_latex(v.typeset, order_))) + "\n\n";
    else if (!v.method.empty() && c.parts.empty() && !c.limit_by)
        out += "How: " + sentence_end(latex_text(v.method)) + "\n\n";
    if (!v.proof.empty()) {
        out += "From the signs of its factors:\n\\begin{itemize}\n";
        for (const engine::sign_step& step : v.proof)
            out += "\\item " + sign_text(step) + "\n";
        out += "\\end{itemize}\n";
    }
    // Each condition with what needs it: "$M + m \neq 0$ (a divisor)".
    const auto with_reasons = [&](const std::vector<engine::condition>& conditions) {
        std::vector<std::string> each;
        for (const engine::condition& k : conditions)
            each.push_back("$" + condition_latex(k, order_) + "$" + (k.because.empty() ? "" : " (" + latex_text(k.because) + ")"));
        return listing(each);
    };
    if (!v.where.empty())
        out += "It holds where " + with_reasons(v.where) + ", which the domains do not prove.\n\n";
    if (!v.defined.empty())
        out += "Defined wherever it is used, proven from the domains: " + with_reasons(v.defined) + ".\n\n";
    if (const std::string unsettled = unsettled_text(v); !unsettled.empty())
        out += unsettled + "\n\n";
    return out;
}

// "$x - 1 \leq 0$ (linear in x ...)", "$M > 0$ (declared positive)"
std::string fragment_writer::sign_text(const engine::sign_step& step) const
{
    const char* relation = relation_to_zero(step.sign);
    if (!relation)
        return latex_text(step.words);
    const std::string why = step.why.declared       ? "declared " + latex_text(step.why.domain)
                            : step.why.typeset.parts.empty() ? latex_text(step.why.words)
                                                             : finding_latex(step.why.typeset, order_);
    // The factor as a textbook writes it (factored, or collected, a root's argument too),
    // not as the proof expanded it.
    return fmt::format("${} {} 0$ ({})", math(textbook(step.factor).value), relation, why);
}

std::string fragment_writer::limit_text(const engine::limit_method& how) const
{
    using kind = engine::limit_method::kind;
    if (how.at_infinity && how.leading_in_inverse)
        return fmt::format("by substituting ${} = 1/t$ and letting $t \\to 0^+$: the leading term is ${}$",
                           math(how.inverted), math(textbook(*how.leading_in_inverse).value));
    // How the limit at the point was taken (at t = 0 for s = 1/t), typeset: the proof's
    // words are program text (`x - 0`, `*`, `^`).
    std::string at_point;
    if (how.how == kind::substitution) {
        static const std::map<std::string, std::string> tex = {
            {">= 0", "\\geq 0"}, {"> 0", "> 0"}, {"< 0", "< 0"}, {"<= 0", "\\leq 0"}, {"!= 0", "\\neq 0"}};
        const auto sign = tex.find(how.denominator_sign.describe());
        at_point = fmt::format("by substitution (continuous there: its denominator ${}$ is ${}$)",
                               math(how.denominator), sign != tex.end() ? sign->second : "\\neq 0");
    } else {
        // The leading term c (s - a)^n of the series in s - a (in s when a is 0).
        const bool bare = GiNaC::is_a<GiNaC::symbol>(how.point) ||
                          (GiNaC::is_a<GiNaC::numeric>(how.point) && how.point.info(GiNaC::info_flags::nonnegative));
        const std::string variable =
            how.point.is_zero() ? math(how.symbol)
                                : fmt::format("{} - {}", math(how.symbol),
                                              bare ? math(how.point) : parenthesised(math(how.point)));
        const std::string power = how.point.is_zero() ? variable : "(" + variable + ")";
        std::string term = math(how.coefficient);
        if (how.order != 0) {
            const std::string raised = how.order == 1 ? power : fmt::format("{}^{{{}}}", power, how.order);
            term = how.coefficient.is_equal(1)    ? raised
                   : how.coefficient.is_equal(-1) ? "-" + raised
                   : GiNaC::is_a<GiNaC::add>(how.coefficient) ? parenthesised(term) + " " + raised
                                                              : term + " " + raised;
        }
        at_point = fmt::format("by the leading term of its series in ${}$, ${}$", variable, term);
    }
    if (how.at_infinity)
        return fmt::format("by substituting ${} = 1/t$ and letting $t \\to 0^+$: {}", math(how.inverted), at_point);
    return at_point;
}

std::string fragment_writer::display(const std::string& lhs, const char* relation, const GiNaC::ex& rhs,
                                     const written_form* w) const
{
    return "\n\\begin{align*}\n" + rows(lhs, rhs, w, "", relation) + "\n\\end{align*}\n";
}

std::string fragment_writer::claim_lhs(const engine::check_result& c, const written_form* w) const
{
    std::string lhs = math(c.stated.lhs(), w);
    if (c.limit) {
        const std::string point = c.limit->to_infinity ? "\\infty" : math(c.limit->point);
        lhs = fmt::format("\\lim_{{{} \\to {}}} {}", math(c.limit->symbol), point, lhs);
    }
    return lhs;
}

// A check's label, `impact:<id>:check:<name>`, its name's characters other than letters, digits
// and _ as _: the web report's anchor for it and its proof (report/html.h).
std::string fragment_writer::check_label(const engine::check_result& c) const
{
    return fmt::format("\\label{{{}:check:{}}}", latex_label(d_), check_label_name(c.name));
}

std::string fragment_writer::checks() const
{
    if (d_.checks.empty())
        return "";
    std::string out = "\n\\paragraph{Checks.}\n\\begin{itemize}\n";
    // A check that states a result's display form, nothing more (no special values, limit
    // or cases), is that result's display-form check: said once, with its reason.
    auto restated = [&](const engine::check_result& c) -> const engine::result* {
        if (!c.display_of.empty() || c.op != engine::relation::equal || !c.at.empty() || !c.left_at.empty() || c.limit ||
            !c.assuming.empty() || !c.parts.empty() || c.continuity || !c.stated.info(GiNaC::info_flags::relation))
            return nullptr;
        for (const engine::result& r : d_.results)
            if (r.cases.empty() && c.stated.lhs().is_equal(r.symbol) && c.stated.rhs().is_equal(r.display))
                for (const engine::check_result& shown : d_.checks)
                    if (shown.display_of == r.name && shown.outcome.what == c.outcome.what)
                        return &r;
        return nullptr;
    };
    // What the check before said of its changed inputs and of its cases: a run of symmetry
    // checks (Galilean invariance component by component) says them once.
    std::string previous_left, previous_cases;
    for (const engine::check_result& c : d_.checks) {
        if (restated(c))
            continue;
        // A display form is the result typeset above: say so, do not print it again.
        if (!c.display_of.empty()) {
            const std::string& name = c.display_of;
            const engine::quantity* q = d_.symbols.find(name);
            const engine::result* r = d_.find_result(name);
            // A result shown once for several lines of the paper: its display form is one
            // check, said once, for all of them.
            if (r && &shown_as(*r) != r) {
                const engine::check_result* first = nullptr;
                for (const engine::check_result& other : d_.checks)
                    if (other.display_of == shown_as(*r).name)
                        first = &other;
                if (first && first->outcome.what == c.outcome.what)
                    continue;
            }
            // Only a numbered result, shown under its own tag, has a number to refer to.
            const std::optional<std::string> ref = r ? result_ref(*r) : std::nullopt;
            const std::string where = ref ? ", " + *ref + "," : "";
            out += fmt::format("\\item{} {} --- the display form of ${}${} equals the derived result", check_label(c),
                               status_text(c.outcome, order_), q ? math(q->symbol) : latex_text(name), where);
            std::string also;
            for (const engine::check_result& same : d_.checks)
                if (const engine::result* of = restated(same); of && of->name == name)
                    also += fmt::format(". {} states the same{}", heading(same.name),
                                        same.because.empty() ? "" : ": " + latex_prose(same.because));
            out += also + (also.empty() || also.back() != '.' ? ".\n" : "\n");
            continue;
        }
        if (c.continuity) {
            const engine::quantity* q = d_.symbols.find(c.cases_of);
            out += fmt::format("\\item{} {} --- {}: ${}$ is continuous where its cases meet.", check_label(c),
                               status_text(c.outcome, order_), heading(c.name), q ? math(q->symbol) : latex_text(c.cases_of));
            if (!c.because.empty())
                out += " " + sentence_end(capitalised(latex_prose(c.because)));
            out += cases_text(c) + "\n";
            continue;
        }
        const written_form& w = c.written;
        out += fmt::format("\\item{} {} --- {}: ", check_label(c), status_text(c.outcome, order_), heading(c.name));
        // The claim as the file writes it, nothing merged (cos θ (−sin θ) + sin θ cos θ = 0,
        // not 0 = 0); a limit, and a claim too wide for the line, as GiNaC reads it.
        const std::string inline_math = w.tree() && !c.limit && !wants_display(claim_math(c, order_, &w))
                                            ? latex_as_written(*w.tree(), order_)
                                            : claim_math(c, order_, &w);
        const bool shown = wants_display(inline_math);
        const std::string lhs = claim_lhs(c, &w);
        if (shown && !c.limit && latex_width(lhs) > content_width - 40)
            // A left side too wide for a line of its own (an energy summed over both
            // spheres): broken like the right side, which follows on lines of its own.
            out += "\n\\begin{align*}\n" + rows("", c.stated.lhs(), &w, "", "") + " \\\\\n" +
                   rows("", c.stated.rhs(), &w, "", latex_relation(c.op)) + "\n\\end{align*}\n";
        else
            out += shown ? display(lhs, latex_relation(c.op), c.stated.rhs(), &w) : "$" + inline_math + "$";
        std::vector<std::string> conditions;
        std::vector<std::string> at;
        for (const auto& [symbol, value] : c.at)
            at.push_back(fmt::format("${} = {}$", math(symbol), math(value)));
        if (!at.empty())
            conditions.push_back("at " + listing(at));
        std::vector<std::string> assuming;
        for (const auto& [symbol, range] : c.assuming)
            assuming.push_back(fmt::format("${} \\in {}$", math(symbol), range));
        if (!assuming.empty())
            conditions.push_back("for " + listing(assuming));
        std::vector<std::string> left;
        for (const auto& [symbol, value] : c.left_at)
            left.push_back(fmt::format("${} \\to {}$", math(symbol), math(value)));
        if (!left.empty())
            conditions.push_back(listing(left) == previous_left ? "the left side taken at the same changed inputs"
                                                                : "the left side taken at " + listing(left));
        previous_left = listing(left);
        // A reason that opens with the check's special values says them: not twice ("At
        // $\epsilon = 0$. At $\epsilon = 0$ all the kinetic energy ... is lost").
        if (conditions.size() == 1 && !c.because.empty() &&
            capitalised(latex_prose(c.because)).rfind(capitalised(conditions.front()) + " ", 0) == 0)
            conditions.clear();
        // After a displayed claim the text starts a new sentence.
        if (!conditions.empty())
            out += shown ? capitalised(listing(conditions)) + "."
                         : (c.left_at.empty() || !c.at.empty() ? " " : ", ") + listing(conditions) + ".";
        else if (!shown)
            out += ".";
        if (!c.because.empty())
            out += (shown && conditions.empty() ? "" : " ") + sentence_end(capitalised(latex_prose(c.because)));
        const std::string by_cases = cases_text(c);
        out += how(c) + (!by_cases.empty() && by_cases == previous_cases ? " Case by case, as the check above." : by_cases) +
               "\n";
        previous_cases = by_cases;
    }
    return out + "\\end{itemize}\n";
}

} // namespace detail

std::string check_label_name(const std::string& check)
{
    std::string name;
    for (char ch : check)
        name += std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
    return name;
}

std::string claim_math(const engine::check_result& c, const term_order& order, const written_form* written)
{
    std::string lhs = latex(c.stated.lhs(), order, written);
    if (c.limit) {
        const std::string point = c.limit->to_infinity ? "\\infty" : latex(c.limit->point, order);
        lhs = fmt::format("\\lim_{{{} \\to {}}} {}", latex(c.limit->symbol, order), point, lhs);
    }
    return fmt::format("{} {} {}", lhs, latex_relation(c.op), latex(c.stated.rhs(), order, written));
}

std::string claim_latex(const engine::derivation& d, const engine::check_result& c)
{
    const term_order order = engine::declaration_order(d.symbols);
    if (c.continuity) {
        const engine::quantity* q = d.symbols.find(c.cases_of);
        return fmt::format("${}$ is continuous where its cases meet", q ? latex(q->symbol, order) : latex_text(c.cases_of));
    }
    if (GiNaC::is_a<GiNaC::relational>(c.stated))
        return checked_claim_latex(c, order);
    // "the cases of J_t cover every value", its quantity typeset.
    static const std::string before = "the cases of ", after = " cover every value";
    const std::string& words = c.statement;
    const engine::quantity* q = words.size() > before.size() + after.size() && words.rfind(before, 0) == 0 &&
                                        words.compare(words.size() - after.size(), after.size(), after) == 0
                                    ? d.symbols.find(words.substr(before.size(), words.size() - before.size() - after.size()))
                                    : nullptr;
    return q ? fmt::format("the cases of ${}$ cover every value", latex(q->symbol, order)) : latex_text(words);
}

std::vector<std::string> checks_proofs_latex(const engine::derivation& d)
{
    const detail::fragment_writer writer(d);
    std::vector<std::string> proofs;
    for (const engine::check_result* c : d.all_checks())
        proofs.push_back(writer.proof(*c));
    return proofs;
}

std::string checked_claim_latex(const engine::check_result& c, const term_order& order)
{
    // As the file writes it, nothing merged ((-a_M n_x)(-J n_y) - ... = 0, not 0 = 0); a
    // limit as GiNaC reads it.
    const auto& tree = c.written.tree();
    std::string out = "$" + (tree && !c.limit ? latex_as_written(*tree, order) : claim_math(c, order, &c.written)) + "$";
    std::vector<std::string> conditions, at, assuming, left;
    for (const auto& [symbol, value] : c.at)
        at.push_back(fmt::format("${} = {}$", latex(symbol, order), latex(value, order)));
    if (!at.empty())
        conditions.push_back("at " + detail::listing(at));
    for (const auto& [symbol, range] : c.assuming)
        assuming.push_back(fmt::format("${} \\in {}$", latex(symbol, order), range));
    if (!assuming.empty())
        conditions.push_back("for " + detail::listing(assuming));
    for (const auto& [symbol, value] : c.left_at)
        left.push_back(fmt::format("${} \\to {}$", latex(symbol, order), latex(value, order)));
    if (!left.empty())
        conditions.push_back("the left side taken at " + detail::listing(left));
    if (!conditions.empty())
        out += ", " + detail::listing(conditions);
    if (!c.said_false)
        return out;
    out += ", which the paper says does not hold";
    if (c.fails_at) {
        // The counterexample: the point, and the sides there.
        std::vector<std::string> point;
        for (const auto& [symbol, value] : c.fails_at->point)
            point.push_back(fmt::format("${} = {}$", latex(symbol, order), latex(value, order)));
        out += fmt::format("; at {} the left side is ${}$ and the right ${}$", detail::listing(point),
                           latex(c.fails_at->lhs, order), latex(c.fails_at->rhs, order));
    }
    return out;
}

} // namespace impact::emit
