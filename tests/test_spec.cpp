// Reading derivation files: structure, and errors that point at file and line.
#define BOOST_TEST_MODULE test_spec
#include <boost/test/unit_test.hpp>

#include "spec/derivation.h"

#include <string>

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
    BOOST_TEST(d.kernels.at(0).outputs.at(0).expression.value == "y");
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
