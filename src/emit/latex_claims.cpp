// The checks of a derivation's LaTeX fragment, with how each was established, and the
// paper's printed forms held to account, in the fragment and as rows of the errata table.
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

// Math set inline when it is short and flat, displayed (and broken) otherwise.
bool wants_display(const std::string& math)
{
    return latex_width(math) > 230 || nested_fraction(math);
}

} // namespace

namespace detail {

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
    if (c.outcome.what == engine::verdict::status::sampled)
        out += fmt::format(" GiNaC cannot decide it; it holds at {} sampled points of the domains (40 digits).",
                           c.outcome.samples);
    if (c.outcome.what == engine::verdict::status::failed)
        out += " Residual: $" + math(c.outcome.residual) + "$.";
    return out;
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
                                            status_text(p.outcome)));
            else
                parts.push_back(fmt::format("case {} ({}): {}", p.first, text, status_text(p.outcome)));
        } else if (p.boundary) {
            const std::string value = math(p.boundary->second);
            if (latex_width(value) > 0.4 * content_width)
                parts.push_back(fmt::format("cases {} and {} where their conditions meet, solved for ${}$: {}",
                                            p.first, p.second, math(p.boundary->first), status_text(p.outcome)));
            else
                parts.push_back(fmt::format("cases {} and {} at ${} = {}$: {}", p.first, p.second,
                                            math(p.boundary->first), value, status_text(p.outcome)));
        } else {
            parts.push_back(fmt::format("{}: {}", latex_text(p.under), status_text(p.outcome)));
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
            out += fmt::format("\\item {} --- the display form of ${}${} equals the derived result", status_text(c.outcome),
                               q ? math(q->symbol) : latex_text(name), where);
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
            out += fmt::format("\\item {} --- {}: ${}$ is continuous where its cases meet.", status_text(c.outcome),
                               heading(c.name), q ? math(q->symbol) : latex_text(c.cases_of));
            if (!c.because.empty())
                out += " " + sentence_end(capitalised(latex_prose(c.because)));
            out += cases_text(c) + "\n";
            continue;
        }
        const written_form& w = c.written;
        out += fmt::format("\\item {} --- {}: ", status_text(c.outcome), heading(c.name));
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

// A printed or derived form: inline when short, else displayed and broken.
bool fragment_writer::displayed(const GiNaC::ex& e, const written_form* w) const
{
    return wants_display(e.info(GiNaC::info_flags::relation) ? relation_math(e, w) : math(e, w));
}

std::string fragment_writer::form(const GiNaC::ex& e, const written_form* w) const
{
    if (!displayed(e, w))
        return "$" + (e.info(GiNaC::info_flags::relation) ? relation_math(e, w) : math(e, w)) + "$";
    if (e.info(GiNaC::info_flags::relation))
        return display(math(e.lhs(), w), "=", e.rhs(), w);
    return display("", "", e, w);
}

// A claim as checked, too wide for a line: displayed (its two sides on lines of their own
// when its left side is wide), its special values, domains or changed inputs after it.
std::string fragment_writer::checked_display(const engine::check_result& t) const
{
    const std::string shown = checked_claim_latex(t, order_);
    const std::string lhs = claim_lhs(t, &t.written);
    std::string out = latex_width(lhs) > content_width - 40
                          ? "\n\\begin{align*}\n" + rows("", t.stated.lhs(), &t.written, "", "") + " \\\\\n" +
                                rows("", t.stated.rhs(), &t.written, "", latex_relation(t.op)) + "\n\\end{align*}\n"
                          : display(lhs, latex_relation(t.op), t.stated.rhs(), &t.written);
    const std::string conditions = shown.substr(shown.find('$', 1) + 1);
    if (conditions.size() > 2)
        out += capitalised(conditions.substr(2)) + ".\n";
    return out;
}

// Each of the paper's items: what it prints or says, the verdict, and for a
// disagreement what is derived and the smallest change that reconciles the two.
// Text after a displayed formula starts a new sentence.
std::string fragment_writer::paper() const
{
    const std::vector<engine::text_comparison> words = engine::text_comparisons(d_.source);
    if (d_.paper_checks.empty() && words.empty())
        return "";
    // In the report, whose errata table has a row for each (\impacterratatable, its
    // section's label), a sentence that says where, with the count: each finding printed
    // once. A fragment pasted alone lists them.
    std::size_t agree = 0, disagrees = 0, undecided = 0;
    std::vector<std::string> disagree;   // their places, each once
    for (const engine::text_comparison& t : words) {
        const std::string v = engine::to_string(t.verdict);
        agree += v == "agrees";
        disagrees += v == "disagrees";
        undecided += v == "undecided";
        if (v == "disagrees" && std::find(disagree.begin(), disagree.end(), paper_text(t.paper)) == disagree.end())
            disagree.push_back(paper_text(t.paper));
    }
    for (const std::vector<std::size_t>& row : emit::errata_rows(d_)) {
        const std::string v = row_verdict(d_, row);
        agree += v == "agrees";
        disagrees += v == "disagrees";
        undecided += v == "undecided";
        const std::string place = paper_text(d_.paper_checks[row.front()].paper);
        if (v == "disagrees" && std::find(disagree.begin(), disagree.end(), place) == disagree.end())
            disagree.push_back(place);
    }
    std::vector<std::string> counts;
    if (agree > 0)
        counts.push_back(fmt::format("{} {}", agree, agree == 1 ? "agrees" : "agree"));
    if (!disagree.empty())
        counts.push_back(fmt::format("{} {} ({})", disagrees, disagrees == 1 ? "disagrees" : "disagree",
                                     fmt::join(disagree, "; ")));
    if (undecided > 0)
        counts.push_back(fmt::format("{} undecided", undecided));
    std::string out = "\n\\paragraph{The paper, held to account.}\n\\ifdefined\\impacterratatable\n" +
                      fmt::format("The paper's printed lines and claims that this derivation compares are rows of the "
                                  "table in Section~\\ref{{\\impacterratatable}}, with their findings: {}.\n",
                                  fmt::join(counts, ", ")) +
                      "\\else\n\\begin{itemize}\n";
    // One item per finding: a misprint that one finding explains in several components of
    // one equation (Eq. 9's v'_m) is shown once, the other components named.
    // The claims checked of one quote are one item when all are proven (what was proven of
    // each said beside it), and an item each otherwise, so that each failure is said: the
    // quote in the first, each saying what it checked.
    struct item {
        std::vector<std::size_t> row;
        bool checked_apart = false;   // one of several checks of one quote that do not all hold
        bool same_quote = false;      // ... and not the first: the quote is not repeated
    };
    std::vector<item> items;
    for (const std::vector<std::size_t>& row : emit::errata_rows(d_)) {
        if (d_.paper_checks[row.front()].what == engine::paper_comparison::kind::claim && row.size() > 1 &&
            row_verdict(d_, row) != "agrees")
            for (std::size_t k : row)
                items.push_back({{k}, true, k != row.front()});
        else
            items.push_back({row});
    }
    for (const item& it : items) {
        const std::vector<std::size_t>& row = it.row;
        const engine::paper_comparison p = in_the_papers_units(d_.paper_checks[row.front()]);
        const std::string what = subject(p);
        out += fmt::format("\\item {}, {}: ", paper_text(p.paper), what);
        bool after_display = false;
        if (p.what == engine::paper_comparison::kind::claim) {
            out += it.same_quote ? std::string("the same words") : fmt::format("``{}''", latex_prose(p.printed_text));
            if (it.checked_apart && p.test)
                out += ", checked as " + checked_claim_latex(*p.test, order_);
        } else {
            const std::string printed = as_printed(p);
            after_display = wants_display(printed);
            out += "printed " + read_as(p) + (after_display ? shown_as_printed(p) : "$" + printed + "$");
        }
        const std::string verdict = comparison_verdict(p);
        if (p.agrees()) {
            // A claim: what was proven, so that two claims of one sentence read apart; one
            // too wide for the line displayed after the item's words (the errata table,
            // which has no room for it, refers here).
            std::vector<std::string> proven;
            std::string displays;
            for (std::size_t k : row)
                if (const engine::paper_comparison c = in_the_papers_units(d_.paper_checks[k]);
                    c.what == engine::paper_comparison::kind::claim && c.test) {
                    const std::string shown = checked_claim_latex(*c.test, order_);
                    if (latex_width(shown) < 260 && shown.find("\\frac{\\frac") == std::string::npos) {
                        proven.push_back(shown);
                        continue;
                    }
                    displays += checked_display(*c.test);
                }
            // A claim the paper says does not hold agrees by being refuted, not proven.
            const bool refuted = std::all_of(row.begin(), row.end(), [&](std::size_t k) {
                const engine::paper_comparison& c = d_.paper_checks[k];
                return c.test && c.test->said_false;
            });
            const std::string how = refuted ? "refuted, as the paper says" : "proven";
            const std::string checked =
                proven.empty() ? "" : " (" + how + ": " + fmt::format("{}", fmt::join(proven, "; ")) + ")";
            const std::string also =
                displays.empty() ? "" : (proven.empty() ? "; " + how + ":" : "; and " + how + ":") + displays;
            out += after_display ? "It agrees" + checked + (also.empty() ? ".\n" : also)
                                 : " --- agrees" + checked + (also.empty() ? ".\n" : also);
            continue;
        }
        out += fmt::format(after_display ? (verdict == "disagrees" ? "It \\textbf{{{}}}" : "It is \\textbf{{{}}}")
                                         : " --- \\textbf{{{}}}",
                           verdict);
        if (verdict == "undecided") {
            out += ": neither proven nor refuted (" + latex_prose(p.agreement.method) + ").\n";
            continue;
        }
        if (p.what != engine::paper_comparison::kind::claim || p.agreement.what == engine::verdict::status::failed) {
            const auto [derived, written] = derived_form(p);
            // After a long quote the line has little room left: a derived form of any
            // width is displayed.
            const bool wide = p.what == engine::paper_comparison::kind::claim &&
                              latex_width(derived.info(GiNaC::info_flags::relation) ? relation_math(derived, written)
                                                                                   : math(derived, written)) > 150;
            after_display = wide || displayed(derived, written);
            out += ": derived " + (wide ? shown(derived, written) : form(derived, written));
        } else {
            after_display = false;
        }
        // A dimensional inconsistency is said as such, then the change that mends it.
        const std::string dimensions = findings(p, finding_kind::dimensions);
        const std::string changes = findings(p, finding_kind::changes);
        std::string tail;
        if (!dimensions.empty())
            tail += after_display ? capitalised(dimensions) : "; it is " + dimensions;
        // Findings that say what holds instead ("the reverse holds: ...", "it holds for ... instead")
        // are no edit: "smallest change" names only an edit of the printed form.
        const bool edit = p.what != engine::paper_comparison::kind::claim ||
                          std::any_of(p.findings.begin(), p.findings.end(),
                                      [](const engine::finding& f) { return f.corrected.has_value(); });
        if (!changes.empty())
            tail += after_display && tail.empty() ? (edit ? "Smallest change: " + changes : capitalised(changes))
                                                  : (edit ? "; smallest change: " + changes : "; " + changes);
        else if (p.what == engine::paper_comparison::kind::claim && p.test)
            tail += after_display && tail.empty() ? capitalised(unreconciled(p, 250)) : "; " + unreconciled(p, 250);
        if (row.size() > 1) {
            std::vector<std::string> others;
            for (std::size_t k = 1; k < row.size(); ++k)
                others.push_back(subject(d_.paper_checks[row[k]]));
            tail += (tail.empty() && after_display ? "" : ". ") +
                    fmt::format("The same misprint, with the same smallest change, is in {}", listing(others));
        }
        out += tail + (tail.empty() && after_display ? "\n" : ".\n");
    }
    // The words compared: claims no derivation settles (undecided, and why), references.
    for (const engine::text_comparison& t : words) {
        const std::string verdict = engine::to_string(t.verdict);
        out += fmt::format("\\item {}, {}: ``{}'' --- {}: {}.\n", paper_text(t.paper),
                           t.what == engine::text_comparison::kind::reference ? "reference entry" : "claim",
                           latex_prose(t.printed), verdict == "agrees" ? verdict : "\\textbf{" + verdict + "}",
                           latex_prose(t.finding));
    }
    return out + "\\end{itemize}\n\\fi\n";
}

} // namespace detail

engine::paper_comparison in_the_papers_units(const engine::paper_comparison& p)
{
    const std::string& words = p.printed_text;
    if (p.what != engine::paper_comparison::kind::claim ||
        (words.find("^\\circ") == std::string::npos && words.find("\u00b0") == std::string::npos))
        return p;
    // q π as the symbol "180 |q|°", its sign outside: printed, never computed with. Only a
    // whole side or a whole term of a sum (θ = π/2, θ - π/2), never a π inside a product
    // (π r² is an area).
    struct to_degrees : GiNaC::map_function {
        GiNaC::ex operator()(const GiNaC::ex& e) override
        {
            if (GiNaC::is_a<GiNaC::relational>(e) || GiNaC::is_a<GiNaC::add>(e))
                return e.map(*this);   // each side, each term
            const GiNaC::ex q = e / GiNaC::Pi;
            if (!e.has(GiNaC::Pi) || !GiNaC::is_a<GiNaC::numeric>(q) || !q.info(GiNaC::info_flags::rational))
                return e;
            const GiNaC::numeric degrees = GiNaC::abs(GiNaC::ex_to<GiNaC::numeric>(q)) * 180;
            const std::string number = degrees.is_integer()
                                           ? fmt::format("{}", degrees.to_long())
                                           : fmt::format("\\tfrac{{{}}}{{{}}}", degrees.numer().to_long(),
                                                         degrees.denom().to_long());
            const GiNaC::ex angle = GiNaC::symbol(fmt::format("degrees_{}", number), number + "^\\circ");
            return GiNaC::ex_to<GiNaC::numeric>(q).is_negative() ? -angle : angle;
        }
    } degrees;
    // A claim about an angle (its left side derived as an arccosine, arcsine or arctangent):
    // its value 0 is 0° too ("the derived value is 0°, not 90°"); never the 0 of a cosine.
    const bool angle = p.test && GiNaC::is_a<GiNaC::function>(p.test->lhs) && [&] {
        const std::string name = GiNaC::ex_to<GiNaC::function>(p.test->lhs).get_name();
        return name == "acos" || name == "asin" || name == "atan";
    }();
    const GiNaC::symbol zero_degrees("degrees_0", "0^\\circ");
    const auto value = [&](const GiNaC::ex& e) -> GiNaC::ex { return angle && e.is_zero() ? zero_degrees : degrees(e); };
    engine::paper_comparison shown = p;
    shown.printed = degrees(p.printed);
    shown.derived = value(p.derived);
    for (engine::finding& f : shown.findings)
        for (engine::finding::part& part : f.parts) {
            part.value = value(part.value);
            if (part.point)
                part.point = degrees(*part.point);
        }
    if (shown.test) {
        engine::check_result& c = *shown.test;
        const GiNaC::ex stated = degrees(c.stated.lhs()) == value(c.stated.rhs());
        // The claim as its file writes it names π: set from the expression instead.
        if (!stated.is_equal(c.stated))
            c.written = written_form();
        c.stated = stated;
        c.lhs = degrees(c.lhs);
        c.rhs = value(c.rhs);
        if (c.value)
            c.value = value(*c.value);
        for (auto& [symbol, value] : c.at)
            value = degrees(value);
    }
    return shown;
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
