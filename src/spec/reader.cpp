// Reads a derivation file (TOML, through toml++) into `spec::derivation`.
//
// Only the shape of the file is checked here: required fields, types, unknown keys.
// Whether expressions parse and symbols are declared is the engine's business,
// which reports it at the place recorded in each `spec::text`. A [[kernel]] table is read
// in kernel_reader.cpp.
#include "spec/derivation.h"
#include "spec/latex_name.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <system_error>

#include "spec/kernel_reader.h"
#include "spec/table_reader.h"

namespace impact::spec {
namespace {

using detail::location_of;
using detail::trimmed;
using detail::table_reader;
using detail::read_kernel;

// A derivation is a page of text; anything much larger is a mistake.
constexpr std::size_t max_file_bytes = 1 << 20;
// Ids become file names.
constexpr std::size_t max_id_length = 64;


// TOML is text: a NUL or another control character (tab and line breaks aside) means
// the file is something else, reported at the first such byte.
void refuse_binary(const std::string& contents, const std::string& file)
{
    const auto control = std::find_if(contents.begin(), contents.end(), [](char c) {
        const auto byte = static_cast<unsigned char>(c);
        return (byte < 0x20 && c != '\t' && c != '\n' && c != '\r') || byte == 0x7f;
    });
    if (control == contents.end())
        return;
    const auto offset = static_cast<std::size_t>(control - contents.begin());
    const auto line_start = offset == 0 ? std::string::npos : contents.rfind('\n', offset - 1);
    const auto line = 1 + std::count(contents.begin(), control, '\n');
    const auto column = line_start == std::string::npos ? offset + 1 : offset - line_start;
    throw error({file, static_cast<std::uint32_t>(line), static_cast<std::uint32_t>(column)},
                fmt::format("file is binary (byte 0x{:02x}), not a TOML derivation",
                            static_cast<unsigned char>(*control)));
}

// An id names output files (latex/<id>.tex, kernels/impact/<id>.hpp): a path such as
// "../x" must not write outside the output folder.
void check_id(const text& id)
{
    const auto word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
    if (id.value.empty() || !std::isalpha(static_cast<unsigned char>(id.value[0])) ||
        !std::all_of(id.value.begin(), id.value.end(), word))
        throw error(id.where, fmt::format("id '{}' must be a name of letters, digits and _, starting with a letter",
                                          id.value));
    if (id.value.size() > max_id_length)
        throw error(id.where, fmt::format("id '{}...' is longer than {} characters", id.value.substr(0, 16),
                                          max_id_length));
}

symbol read_symbol(table_reader& in)
{
    symbol s;
    s.name = in.required_string("name");
    s.latex = in.string_or("latex", latex_of_name(s.name.value));
    s.definition = in.optional_string("definition");
    s.domain = in.string_or("domain", "real");
    s.meaning = in.string_or("meaning", "");
    s.dimension = in.optional_string("dimension");
    in.finish();
    return s;
}

dimension read_dimension(table_reader& in)
{
    dimension d;
    d.name = in.required_string("name");
    d.as = in.optional_string("as");
    in.finish();
    return d;
}

given read_given(table_reader& in)
{
    given g;
    g.name = in.required_string("name");
    g.equation = in.required_string("equation");
    g.because = in.required_string("because");
    g.paper = in.optional_string("paper");
    g.printed = in.optional_string("printed");
    g.quote = in.optional_string("quote");
    if (g.quote && !g.printed)
        throw error(g.quote->where, "'quote' is the paper's text of a 'printed' form: give 'printed' too");
    in.finish();
    return g;
}

// `cases = [{ when = "lhs <= rhs", as = "value" }, ...]`: two cases at least, each an
// inequality and a value; whether the conditions are inequalities of the derivation's
// quantities is the engine's business.
std::vector<case_of> read_cases(table_reader& in, const text& name)
{
    const source_location where = in.where_of("cases");
    std::vector<case_of> cases;
    for (const toml::table* table : in.table_array("cases")) {
        table_reader c = in.nested(*table, fmt::format("a case of '{}'", name.value));
        case_of one;
        one.where = c.where();
        one.when = c.required_string("when");
        one.as = c.required_string("as");
        c.finish();
        const std::string& w = one.when.value;
        if (w.find('<') == std::string::npos && w.find('>') == std::string::npos)
            throw error(one.when.where, fmt::format("condition \"{}\" must be an inequality 'lhs op rhs' with op one "
                                                    "of <, <=, >, >=", w));
        cases.push_back(std::move(one));
    }
    if (cases.size() < 2)
        throw error(where, fmt::format("'cases' of '{}' must list two cases or more, each "
                                       "{{ when = \"lhs <= rhs\", as = \"value\" }}", name.value));
    return cases;
}

step read_step(table_reader& in)
{
    step s;
    s.where = in.where();
    s.because = in.string_or("because", "");
    const int kinds = int(in.has("solve")) + int(in.has("define")) + int(in.has("quotient")) +
                      int(in.has("rearrange"));
    if (kinds != 1)
        throw error(s.where, "a step must have exactly one of 'solve', 'define', 'quotient' or 'rearrange'");
    if (in.has("solve")) {
        s.what = step::kind::solve;
        s.equations = in.string_array("solve", true);
        s.unknowns = in.string_array("for", true);
        s.reject = in.string_array("reject", false);
        if (auto because = in.optional_string("reject_because"))
            s.reject_because = *because;
        if (!s.reject.empty() && s.reject_because.value.empty())
            throw error(s.where, "'reject' needs 'reject_because': why the solutions it rejects are not wanted");
        if (s.reject.empty() && !s.reject_because.value.empty())
            throw error(s.reject_because.where, "'reject_because' without 'reject': no solution is rejected");
    } else if (in.has("define")) {
        s.what = step::kind::define;
        s.name = in.required_string("define");
        if (in.has("as") && in.has("cases"))
            throw error(in.where_of("cases"), fmt::format("step '{}' has both 'as' and 'cases': give one value or "
                                                          "its cases", s.name.value));
        if (in.has("cases"))
            s.cases = read_cases(in, s.name);
        else
            s.expression = in.required_string("as");
    } else if (in.has("quotient")) {
        s.what = step::kind::quotient;
        s.equations = in.string_array("quotient", true);
        s.name = in.required_string("name");
        if (s.equations.size() != 2)
            throw error(s.where, "'quotient' takes two equations: the numerator and the denominator");
    } else {
        s.what = step::kind::rearrange;
        s.source = in.required_string("rearrange");
        s.expression = in.required_string("into");
        s.name = in.required_string("name");
    }
    in.finish();
    return s;
}

result read_result(table_reader& in)
{
    result r;
    r.name = in.required_string("name");
    r.display = in.optional_string("display");
    r.paper = in.optional_string("paper");
    r.printed = in.optional_string("printed");
    r.quote = in.optional_string("quote");
    if (r.quote && !r.printed)
        throw error(r.quote->where, "'quote' is the paper's text of a 'printed' form: give 'printed' too");
    in.finish();
    return r;
}

// `v_perp -> 0`, `v_perp -> infinity` (or `oo`, `inf`, `+inf`, `+infinity`, as domains write it).
limit_point read_limit(const text& written)
{
    const auto arrow = written.value.find("->");
    if (arrow == std::string::npos)
        throw error(written.where, fmt::format("limit \"{}\" must read 'symbol -> point'", written.value));
    limit_point l;
    l.written = written;
    l.symbol = {trimmed(written.value.substr(0, arrow)), written.where};
    l.point = {trimmed(written.value.substr(arrow + 2)), written.where};
    for (const char* spelt : {"infinity", "oo", "inf", "+inf", "+infinity", "+oo"})
        l.to_infinity = l.to_infinity || l.point.value == spelt;
    if (l.to_infinity)
        l.point.value.clear();
    return l;
}

// The fields a check and a claim share; a check may be `continuity` in place of `claim`.
check read_check_fields(table_reader& in, bool continuity_allowed = false)
{
    check c;
    c.name = in.required_string("name");
    if (continuity_allowed && in.has("continuity")) {
        c.continuity = in.optional_string("continuity");
        if (in.has("claim"))
            throw error(in.where_of("claim"), fmt::format("check '{}' has both 'claim' and 'continuity': a continuity "
                                                          "check states its claim itself", c.name.value));
        for (const char* other : {"at", "left_at", "limit", "assuming"})
            if (in.has(other))
                throw error(in.where_of(other), fmt::format("'{}' does not apply to a continuity check", other));
        c.claim = {"", c.continuity->where};
    } else {
        c.claim = in.required_string("claim");
    }
    c.because = in.string_or("because", "");
    c.at = in.binding_table("at");
    c.left_at = in.binding_table("left_at");
    if (const auto written = in.optional_string("limit"))
        c.limit = read_limit(*written);
    c.assuming = in.binding_table("assuming");
    return c;
}

check read_check(table_reader& in)
{
    check c = read_check_fields(in, true);
    in.finish();
    return c;
}

claim read_claim(table_reader& in)
{
    claim c;
    c.test = read_check_fields(in);
    c.holds = in.optional_bool("holds").value_or(true);
    c.mended = in.optional_string("mended");
    c.label = in.optional_string("label");
    if (c.mended && !c.holds)
        throw error(c.mended->where, fmt::format("claim '{}': 'mended' mends a claim that does not hold; a claim "
                                                 "said not to hold ('holds = false') has nothing to mend",
                                                 c.test.name.value));
    if (!c.holds && c.test.limit)
        throw error(in.where_of("holds"), fmt::format("claim '{}': 'holds = false' does not apply beside 'limit' (a "
                                                      "limit is refuted by no single point)",
                                                      c.test.name.value));
    c.paper = in.required_string("paper");
    c.quote = in.required_string("quote");
    in.finish();
    return c;
}

// A claim no derivation settles: its words, its place and why, and nothing to check.
open_claim read_open_claim(table_reader& in)
{
    open_claim c;
    c.name = in.required_string("name");
    c.undecided = in.required_string("undecided");
    for (const char* other : {"claim", "at", "left_at", "limit", "assuming", "because"})
        if (in.has(other))
            throw error(in.where_of(other),
                        fmt::format("claim '{}' is undecided: '{}' does not apply (an undecided claim states why "
                                    "no derivation settles it, and nothing to check)",
                                    c.name.value, other));
    if (trimmed(c.undecided.value).empty())
        throw error(c.undecided.where, fmt::format("claim '{}': 'undecided' must say why no derivation settles it",
                                                   c.name.value));
    c.paper = in.required_string("paper");
    c.quote = in.required_string("quote");
    in.finish();
    return c;
}

not_compared read_not_compared(table_reader& in)
{
    not_compared n;
    n.paper = in.required_string("paper");
    n.because = in.required_string("because");
    in.finish();
    if (trimmed(n.because.value).empty())
        throw error(n.because.where, fmt::format("'{}' is not compared: 'because' must say why", n.paper.value));
    return n;
}

// A reference's number: a whole number from 1, as the paper's marks are.
int reference_number(table_reader& in, const char* key, const char* context)
{
    const double n = in.required_number(key);
    if (!(n >= 1 && n <= 10000 && n == static_cast<double>(static_cast<int>(n))))
        throw error(in.where_of(key), fmt::format("'{}' in {} must be a reference's number, a whole number from 1",
                                                  key, context));
    return static_cast<int>(n);
}

reference read_reference(table_reader& in)
{
    reference r;
    r.where = in.where();
    r.paper = in.required_string("paper");
    r.number = reference_number(in, "number", "[[reference]]");
    r.entry = in.required_string("entry");
    in.finish();
    if (trimmed(r.entry.value).empty())
        throw error(r.entry.where, fmt::format("reference {}: 'entry' is the entry as the paper prints it", r.number));
    return r;
}

citation read_citation(table_reader& in)
{
    citation c;
    c.where = in.where();
    c.paper = in.required_string("paper");
    c.quote = in.required_string("quote");
    c.cites = reference_number(in, "cites", "[[citation]]");
    c.names = in.optional_string("names");
    in.finish();
    if (c.names && trimmed(c.names->value).empty())
        throw error(c.names->where, "'names' is the author the words name beside the mark; leave it out if none");
    return c;
}

// Each reference listed once, and each citation of a listed one.
void check_references(const derivation& d)
{
    std::map<int, const reference*> listed;
    for (const reference& r : d.references)
        if (!listed.emplace(r.number, &r).second)
            throw error(r.where, fmt::format("reference {} is listed twice (first at line {})", r.number,
                                             listed.at(r.number)->where.line));
    for (const citation& c : d.citations)
        if (!listed.count(c.cites))
            throw error(c.where, fmt::format("the citation at '{}' cites reference {}, which no [[reference]] of "
                                             "this file lists",
                                             c.paper.value, c.cites));
}

use read_use(table_reader& in)
{
    use u;
    u.derivation = in.required_string("derivation");
    u.results = in.binding_array("results", true);
    in.finish();
    return u;
}

// A name identifies its entry in the output (a line of verification.md, a kernel's
// function): two entries of one kind with one name would be confused, or not compile.
void refuse_twice(const std::vector<const text*>& names, std::string_view what)
{
    for (std::size_t i = 0; i < names.size(); ++i)
        for (std::size_t j = 0; j < i; ++j)
            if (names[i]->value == names[j]->value)
                throw error(names[i]->where, fmt::format("{} '{}' is declared twice (first at line {})", what,
                                                         names[i]->value, names[j]->where.line));
}

void check_names(const derivation& d)
{
    std::vector<const text*> results, checks, kernels;
    for (const result& r : d.results)
        results.push_back(&r.name);
    // Checks and claims share verification.md, where the name tells them apart.
    for (const check& c : d.checks)
        checks.push_back(&c.name);
    for (const claim& c : d.claims)
        checks.push_back(&c.test.name);
    for (const open_claim& c : d.open_claims)
        checks.push_back(&c.name);
    for (const kernel& k : d.kernels)
        kernels.push_back(&k.name);
    refuse_twice(results, "result");
    refuse_twice(checks, "check or claim");
    refuse_twice(kernels, "kernel");
}

// Reads every entry of an array of tables with `read`.
template <class T, class Read>
std::vector<T> read_all(table_reader& top, const std::string& file, std::string_view key, Read read)
{
    std::vector<T> items;
    for (const toml::table* table : top.table_array(key)) {
        table_reader in(*table, file, fmt::format("[[{}]]", key));
        items.push_back(read(in));
    }
    return items;
}

} // namespace

std::optional<std::string> meaningful_content(const std::string& contents)
{
    try {
        std::ostringstream out;
        out << toml::parse(contents);
        return out.str();
    } catch (const toml::parse_error&) {
        return std::nullopt;
    }
}

derivation parse_derivation(const std::string& contents, const std::string& file)
{
    if (contents.size() > max_file_bytes)
        throw error({file, 0, 0}, fmt::format("file is {} bytes, larger than the limit of {} bytes",
                                              contents.size(), max_file_bytes));
    if (contents.find_first_not_of(" \t\r\n") == std::string::npos)
        throw error({file, 0, 0}, "file is empty");
    refuse_binary(contents, file);

    toml::table table;
    try {
        table = toml::parse(contents, file);
    } catch (const toml::parse_error& e) {
        throw error(location_of(file, e.source()), fmt::format("invalid TOML: {}", e.description()));
    }

    table_reader top(table, file, "the derivation");
    derivation d;
    d.file = file;
    d.contents = contents;
    d.id = top.required_string("id");
    check_id(d.id);
    d.title = top.required_string("title");
    d.paper = top.optional_string("paper");
    d.summary = top.string_or("summary", "");
    d.uses = read_all<use>(top, file, "use", read_use);
    d.dimensions = read_all<dimension>(top, file, "dimension", read_dimension);
    d.symbols = read_all<symbol>(top, file, "symbol", read_symbol);
    d.givens = read_all<given>(top, file, "given", read_given);
    d.steps = read_all<step>(top, file, "step", read_step);
    d.results = read_all<result>(top, file, "result", read_result);
    d.checks = read_all<check>(top, file, "check", read_check);
    // A claim with `undecided` has nothing to check: it is kept apart from those checked.
    for (const toml::table* table : top.table_array("claim")) {
        table_reader in(*table, file, "[[claim]]");
        if (in.has("undecided"))
            d.open_claims.push_back(read_open_claim(in));
        else
            d.claims.push_back(read_claim(in));
    }
    d.uncompared = read_all<not_compared>(top, file, "not_compared", read_not_compared);
    d.references = read_all<reference>(top, file, "reference", read_reference);
    d.citations = read_all<citation>(top, file, "citation", read_citation);
    d.kernels = read_all<kernel>(top, file, "kernel", read_kernel);
    top.finish();
    check_names(d);
    check_references(d);

    if (d.results.empty())
        throw error(top.where(), "the derivation declares no [[result]]");
    return d;
}

std::string read_input_file(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw error({path, 0, 0}, "cannot open the file: " + std::error_code(errno, std::generic_category()).message());
    in.seekg(0, std::ios::end);
    const auto size = static_cast<std::size_t>(in.tellg());
    if (size > max_file_bytes)
        throw error({path, 0, 0}, fmt::format("file is {} bytes, larger than the limit of {} bytes",
                                              size, max_file_bytes));
    in.seekg(0);
    std::ostringstream contents;
    contents << in.rdbuf();
    return contents.str();
}

derivation read_derivation(const std::string& path)
{
    return parse_derivation(read_input_file(path), path);
}

} // namespace impact::spec
