// Reading derivation files: structure, and errors that point at file and line.
#define BOOST_TEST_MODULE test_spec
#include <boost/test/unit_test.hpp>

#include "spec/derivation.h"
#include "spec/outline.h"

#include <filesystem>
#include <string>

#include <unistd.h>

using impact::spec::parse_derivation;

namespace {

const std::string minimal = R"(id = "tiny"
title = "A tiny derivation"
paper = "Eq. 0"

[[symbol]]
name = "x"
latex = "x"
domain = "positive"

[[symbol]]
name = "y"

[[given]]
name = "line"
equation = "y = 2*x"
because = "by definition"

[[step]]
solve = ["line"]
for = ["y"]

[[result]]
name = "y"
display = "2*x"

[[check]]
name = "doubles"
claim = "y = x + x"
at = { x = "3" }

[[kernel]]
name = "double_it"
inputs = ["x"]
outputs = ["twice = y"]
)";

// The error `parse_derivation` throws for `text`.
impact::error error_for(const std::string& text)
{
    try {
        parse_derivation(text, "bad.toml");
    } catch (const impact::error& e) {
        return e;
    }
    BOOST_FAIL("no error for:\n" + text);
    throw;
}

} // namespace

BOOST_AUTO_TEST_CASE(a_complete_file_is_read_into_its_parts)
{
    const auto d = parse_derivation(minimal, "tiny.toml");
    BOOST_TEST(d.id.value == "tiny");
    BOOST_TEST(d.paper->value == "Eq. 0");
    BOOST_TEST(d.symbols.size() == 2u);
    BOOST_TEST(d.symbols[0].domain.value == "positive");
    BOOST_TEST(d.symbols[1].domain.value == "real");   // the default
    BOOST_TEST(d.symbols[1].latex.value == "y");       // defaults to the name
    BOOST_TEST(d.givens.at(0).equation.value == "y = 2*x");
    BOOST_TEST(d.steps.at(0).unknowns.at(0).value == "y");
    BOOST_TEST(d.checks.at(0).at.at(0).name.value == "x");
    BOOST_TEST(d.checks.at(0).at.at(0).expression.value == "3");
    BOOST_TEST(d.kernels.at(0).outputs.at(0).name.value == "twice");
    BOOST_TEST(d.kernels.at(0).outputs.at(0).components.at(0).value == "y");
    BOOST_TEST(!d.kernels.at(0).outputs.at(0).is_array);
}

// Lists, limits, guards and error scales are read here, so that no later stage parses
// the file's text.
BOOST_AUTO_TEST_CASE(kernel_lists_guards_error_scales_and_limits_are_read_into_parts)
{
    const std::string text = std::string(minimal) +
                             "[[kernel]]\nname = \"k2\"\ninputs = [\"x\", \"C = [c1, c2 ]\", \"u = x\"]\n"
                             "outputs = [\"v = [y, 2*x]\"]\n"
                             "guards = [\"bad = x, C\", \"apart = x - 1 > 0\"]\n"
                             "error = [\"v = velocity*M/(M + m)\", \"w = relative\", \"z = velocity\"]\n"
                             "[[check]]\nname = \"l\"\nclaim = \"y = 0\"\nlimit = \"x ->  infinity\"\n"
                             "[[check]]\nname = \"l2\"\nclaim = \"y = 0\"\nlimit = \"x->1/2\"\n";
    const auto d = parse_derivation(text, "tiny.toml");
    const impact::spec::kernel& k = d.kernels.at(1);
    BOOST_TEST(k.inputs.at(0).components.at(0).value == "x");
    BOOST_TEST(k.inputs.at(1).is_array);
    BOOST_TEST(k.inputs.at(1).components.size() == 2u);
    BOOST_TEST(k.inputs.at(1).components.at(1).value == "c2");
    BOOST_TEST(k.inputs.at(2).name.value == "u");
    BOOST_TEST(k.inputs.at(2).components.at(0).value == "x");
    BOOST_TEST(k.outputs.at(0).components.at(1).value == "2*x");
    BOOST_TEST(k.guards.at(0).parameters.size() == 2u);
    BOOST_TEST(!k.guards.at(0).condition.has_value());
    BOOST_TEST(k.guards.at(1).condition->value == "x - 1 > 0");
    BOOST_TEST(!k.error.at(0).relative);
    BOOST_TEST(k.error.at(0).factor->value == "M/(M + m)");
    BOOST_TEST(k.error.at(1).relative);
    BOOST_TEST(!k.error.at(2).relative);
    BOOST_TEST(!k.error.at(2).factor.has_value());
    const auto& to_infinity = *d.checks.at(1).limit;
    BOOST_TEST(to_infinity.symbol.value == "x");
    BOOST_TEST(to_infinity.to_infinity);
    BOOST_TEST(d.checks.at(2).limit->point.value == "1/2");
    BOOST_TEST(!d.checks.at(2).limit->to_infinity);
}

BOOST_AUTO_TEST_CASE(a_limit_to_infinity_is_written_as_domains_write_it_too)
{
    // `h -> inf` read as a symbol inf, undeclared, though domains write +inf.
    for (const char* point : {"infinity", "oo", "inf", "+inf", "+infinity"}) {
        const std::string text = "id = \"t\"\ntitle = \"t\"\n[[symbol]]\nname = \"x\"\n[[result]]\nname = \"x\"\n"
                                 "[[check]]\nname = \"l\"\nclaim = \"x = 0\"\nlimit = \"x -> " + std::string(point) + "\"\n";
        const auto d = parse_derivation(text, "t.toml");
        BOOST_TEST(d.checks.at(0).limit->to_infinity, point);
        BOOST_TEST(d.checks.at(0).limit->point.value.empty(), point);
    }
}

BOOST_AUTO_TEST_CASE(a_limit_list_or_error_scale_that_is_not_understood_is_refused_at_its_place)
{
    auto refused = [](const std::string& extra, const std::string& message) {
        try {
            parse_derivation(std::string(minimal) + extra, "tiny.toml");
            BOOST_ERROR("accepted: " + extra);
        } catch (const impact::error& e) {
            BOOST_TEST(e.message() == message);
        }
    };
    refused("[[check]]\nname = \"l\"\nclaim = \"y = 0\"\nlimit = \"x = 1\"\n",
            "limit \"x = 1\" must read 'symbol -> point'");
    refused("[[kernel]]\nname = \"k2\"\ninputs = [\"C = [c1, ]\"]\noutputs = [\"v = y\"]\n",
            "empty entry in \"[c1, ]\"");
    refused("[[kernel]]\nname = \"k2\"\ninputs = [\"x\"]\noutputs = [\"v = y\"]\nerror = [\"v = speedy\"]\n",
            "error scale 'speedy' must be relative, velocity or velocity*<expression>");
    refused("[[kernel]]\nname = \"k2\"\ninputs = [\"x\"]\noutputs = [\"v = y\"]\nerror = [\"v = velocityx\"]\n",
            "error scale 'velocityx' must be relative, velocity or velocity*<expression>");
}

BOOST_AUTO_TEST_CASE(expressions_remember_the_line_they_were_written_on)
{
    const auto d = parse_derivation(minimal, "tiny.toml");
    BOOST_TEST(d.givens.at(0).equation.where.line == 15u);
    BOOST_TEST(d.givens.at(0).equation.where.file == "tiny.toml");
    BOOST_TEST(d.results.at(0).display->where.line == 24u);
}

BOOST_AUTO_TEST_CASE(invalid_toml_is_reported_with_its_line)
{
    const impact::error e = error_for("id = \"x\"\ntitle = \"t\"\n[[symbol]\nname = \"x\"\n");
    BOOST_TEST(e.where().file == "bad.toml");
    BOOST_TEST(e.where().line == 3u);
    BOOST_TEST(e.message().find("invalid TOML") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(a_missing_required_field_is_named)
{
    const impact::error e = error_for("id = \"x\"\ntitle = \"t\"\n[[given]]\nname = \"g\"\nequation = \"a = b\"\n");
    BOOST_TEST(e.message().find("'because'") != std::string::npos);
    BOOST_TEST(e.where().line == 3u);
}

BOOST_AUTO_TEST_CASE(a_misspelt_field_is_an_error_not_ignored)
{
    const impact::error e = error_for(minimal + "\n[[check]]\nname = \"c\"\nclaim = \"y = y\"\nbecuase = \"typo\"\n");
    BOOST_TEST(e.message().find("unknown field 'becuase'") != std::string::npos);
    BOOST_TEST(e.where().line == 39u);
}

BOOST_AUTO_TEST_CASE(a_field_of_the_wrong_type_is_named)
{
    const impact::error e = error_for("id = 3\ntitle = \"t\"\n");
    BOOST_TEST(e.message().find("'id'") != std::string::npos);
    BOOST_TEST(e.message().find("must be a string") != std::string::npos);
    BOOST_TEST(e.where().line == 1u);
}

BOOST_AUTO_TEST_CASE(a_step_must_say_what_it_does)
{
    const impact::error e = error_for("id = \"x\"\ntitle = \"t\"\n[[step]]\nbecause = \"nothing\"\n");
    BOOST_TEST(e.message().find("exactly one of 'solve'") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(empty_binary_and_oversized_files_are_refused)
{
    BOOST_TEST(error_for("  \n\n").message() == "file is empty");
    BOOST_TEST(error_for(std::string("id = \"x\"\0\x01", 10)).message().find("binary") != std::string::npos);
    BOOST_TEST(error_for(std::string(2 << 20, '#')).message().find("larger than the limit") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(a_derivation_without_results_is_refused)
{
    const impact::error e = error_for("id = \"x\"\ntitle = \"t\"\n");
    BOOST_TEST(e.message().find("no [[result]]") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(a_kernel_output_must_read_name_equals_expression)
{
    std::string text = minimal;
    text.replace(text.find("\"twice = y\""), 11, "\"twice\"");
    const impact::error e = error_for(text);
    BOOST_TEST(e.message().find("'name = expression'") != std::string::npos);
    BOOST_TEST(e.where().line == 34u);
}

BOOST_AUTO_TEST_CASE(references_and_their_citations_are_read_and_checked_against_each_other)
{
    const std::string refs = "\n[[reference]]\npaper = \"Note 1\"\nnumber = 1\nentry = \"A Writer. A Book. A Press, 1950.\"\n"
                             "[[citation]]\npaper = \"Sec. 1\"\nquote = \"as Writer shows1\"\ncites = 1\nnames = \"Writer\"\n";
    const auto d = parse_derivation(minimal + refs, "tiny.toml");
    BOOST_TEST_REQUIRE(d.references.size() == 1u);
    BOOST_TEST(d.references.at(0).number == 1);
    BOOST_TEST(d.references.at(0).paper.value == "Note 1");
    BOOST_TEST_REQUIRE(d.citations.size() == 1u);
    BOOST_TEST(d.citations.at(0).cites == 1);
    BOOST_TEST(d.citations.at(0).names->value == "Writer");
    // A citation of a number no entry has, an entry listed twice, a number that is no mark:
    // each an error at its table.
    impact::error e = error_for(minimal + refs + "[[citation]]\npaper = \"Sec. 2\"\nquote = \"q\"\ncites = 3\n");
    BOOST_TEST(e.message().find("cites reference 3, which no [[reference]] of this file lists") != std::string::npos,
               e.message());
    BOOST_TEST(e.where().line == 45u);
    e = error_for(minimal + refs + "[[reference]]\npaper = \"Note 2\"\nnumber = 1\nentry = \"B. C.\"\n");
    BOOST_TEST(e.message().find("reference 1 is listed twice (first at line 36)") != std::string::npos, e.message());
    BOOST_TEST(e.where().line == 45u);
    e = error_for(minimal + "\n[[reference]]\npaper = \"Note 1\"\nnumber = 1.5\nentry = \"x\"\n");
    BOOST_TEST(e.message().find("a whole number from 1") != std::string::npos, e.message());
}

BOOST_AUTO_TEST_CASE(an_undecided_claim_says_why_and_has_nothing_to_check)
{
    const std::string open = "\n[[claim]]\nname = \"empirical\"\npaper = \"Sec. III\"\n"
                             "quote = \"Restitution laws are empirical.\"\n"
                             "undecided = \"a statement about experiment\"\n"
                             "[[not_compared]]\npaper = \"Footnote 1\"\nbecause = \"a reference\"\n";
    const auto d = parse_derivation(minimal + open, "tiny.toml");
    BOOST_TEST(d.claims.empty());
    BOOST_TEST(d.open_claims.size() == 1u);
    BOOST_TEST(d.open_claims.at(0).paper.value == "Sec. III");
    BOOST_TEST(d.open_claims.at(0).undecided.value == "a statement about experiment");
    BOOST_TEST(d.uncompared.size() == 1u);
    BOOST_TEST(d.uncompared.at(0).because.value == "a reference");

    // Both a claim to check and `undecided`: which is it?
    impact::error e = error_for(minimal + "\n[[claim]]\nname = \"c\"\nclaim = \"y = 2*x\"\npaper = \"Eq. 1\"\n"
                                          "quote = \"y = 2x\"\nundecided = \"why\"\n");
    BOOST_TEST(e.message() == "claim 'c' is undecided: 'claim' does not apply (an undecided claim states why no "
                              "derivation settles it, and nothing to check)");
    BOOST_TEST(e.where().line == 38u);
    // A special value with nothing to check at it.
    e = error_for(minimal + "\n[[claim]]\nname = \"c\"\npaper = \"Eq. 1\"\nquote = \"y = 2x\"\n"
                            "undecided = \"why\"\nat = { x = \"1\" }\n");
    BOOST_TEST(e.message().find("'at' does not apply") != std::string::npos);
    // An empty reason.
    e = error_for(minimal + "\n[[claim]]\nname = \"c\"\npaper = \"Eq. 1\"\nquote = \"y = 2x\"\nundecided = \"  \"\n");
    BOOST_TEST(e.message() == "claim 'c': 'undecided' must say why no derivation settles it");
    // Its name is shared with the checks and claims, as theirs is.
    e = error_for(minimal + "\n[[claim]]\nname = \"doubles\"\npaper = \"Eq. 1\"\nquote = \"y = 2x\"\n"
                            "undecided = \"why\"\n");
    BOOST_TEST(e.message().find("check or claim 'doubles' is declared twice") != std::string::npos);
    // A line not compared says why.
    e = error_for(minimal + "\n[[not_compared]]\npaper = \"Footnote 1\"\n");
    BOOST_TEST(e.message().find("'because'") != std::string::npos);
    e = error_for(minimal + "\n[[not_compared]]\npaper = \"Footnote 1\"\nbecause = \"\"\n");
    BOOST_TEST(e.message() == "'Footnote 1' is not compared: 'because' must say why");
}

// The paper's order of places: a place per line, comments and blank lines skipped, spaces
// around a place (and a Windows line end) not part of it; each place keeps its line.
BOOST_AUTO_TEST_CASE(the_paper_s_order_of_places_is_read_a_place_per_line)
{
    const impact::spec::paper_outline o =
        impact::spec::parse_paper_outline("# the paper\n\nAbstract\r\n  Eq. 1a  \n# II B\nSec. II B, 1st paragraph\n", "order.txt");
    BOOST_TEST(o.places.size() == 3u);
    BOOST_TEST(o.places[0].value == "Abstract");
    BOOST_TEST(o.places[1].value == "Eq. 1a");
    BOOST_TEST(o.places[1].where.line == 4u);
    BOOST_TEST(o.places[1].where.column == 3u);
    BOOST_TEST(o.places[2].value == "Sec. II B, 1st paragraph");
    BOOST_TEST(*o.position("Sec. II B, 1st paragraph") == 2u);
    BOOST_TEST(!o.position("Eq. 1"));
    BOOST_TEST(*o.position("  Eq. 1a ") == 1u);
    // A byte order mark is not part of the first place.
    BOOST_TEST(impact::spec::parse_paper_outline("\xEF\xBB\xBF" "Abstract\n", "o.txt").places[0].value == "Abstract");
    // Nothing read from a folder without the file; a folder of that name is refused.
    BOOST_TEST(!impact::spec::read_paper_outline(IMPACT_SOURCE_DIR "/tests"));
    const std::filesystem::path folder =
        std::filesystem::temp_directory_path() / ("impact-test-spec-" + std::to_string(::getpid()));
    std::filesystem::create_directories(folder / impact::spec::paper_outline_name);
    try {
        impact::spec::read_paper_outline(folder);
        BOOST_ERROR("a folder named paper_order.txt was read");
    } catch (const impact::error& e) {
        BOOST_TEST(e.message() == "not a file: the paper's order of places is read from a text file of this name");
    }
    std::filesystem::remove_all(folder);
}
