// Derivations kept between runs (engine/store/stored.h): a derivation restored from its text is
// the one derived (what every emitter prints from it, and every kernel form, is the same),
// for derivation files that are not the paper's; the library takes a derivation from the
// store only when its file and those it uses are unchanged; a text that is not one Impact
// wrote is never trusted.
#define BOOST_TEST_MODULE test_stored
#include <boost/test/unit_test.hpp>

#include "emit/json.h"
#include "emit/latex.h"
#include "engine/library/library.h"
#include "engine/store/stored.h"
#include "pipeline/workers.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace impact;

namespace {

// A store in memory that counts what it is asked.
struct memory_store {
    std::map<std::string, std::string> texts;
    std::size_t found = 0;
    std::size_t kept = 0;

    engine::derivation_store handle()
    {
        return {[this](const std::string& key) -> std::optional<std::string> {
                    const auto it = texts.find(key);
                    if (it == texts.end())
                        return std::nullopt;
                    ++found;
                    return it->second;
                },
                [this](const std::string& key, const std::string& text) {
                    ++kept;
                    texts[key] = text;
                },
                {}};
    }
};

// The files of the tests' folders that are not the paper's, and the rough spheres in the
// plane with the derivation they use (cases, kernels, a fixed sphere's limits).
std::vector<spec::derivation> sources()
{
    std::vector<spec::derivation> all;
    for (const char* folder : {"tests/examples", "tests/cases"})
        for (const fs::path& file : engine::derivation_files(fs::path(IMPACT_SOURCE_DIR) / folder))
            all.push_back(spec::read_derivation(file.string()));
    for (const char* file : {"derivations/rough_sticking.toml", "derivations/rough_plane.toml"})
        all.push_back(spec::read_derivation(std::string(IMPACT_SOURCE_DIR "/") + file));
    return all;
}

// Every kernel form of a derivation as text, the fixed spheres' kernels' too.
void add_forms(const engine::kernel& k, const engine::symbol_table& symbols, std::vector<std::string>& out)
{
    out.push_back(k.name);
    for (const engine::kernel_output& o : k.outputs)
        for (const auto& forms : o.candidates)
            for (const engine::form& f : forms)
                out.push_back(o.member + " " + f.label + " " + symbols.text(f.value));
    for (const auto& [symbol, value] : k.lets)
        out.push_back(symbols.text(symbol) + " = " + symbols.text(value));
    for (const engine::kernel& fixed : k.limits)
        add_forms(fixed, symbols, out);
}

// What the emitters print from a library, and its kernels' forms.
std::vector<std::string> printed(const engine::library& lib)
{
    std::vector<std::string> out{emit::derivations_json(lib.in_order())};
    for (const engine::derivation* d : lib.in_order()) {
        out.push_back(emit::latex_fragment(*d));
        for (const engine::kernel& k : d->kernels)
            add_forms(k, d->symbols, out);
    }
    return out;
}

} // namespace

BOOST_AUTO_TEST_CASE(a_restored_derivation_prints_what_the_derived_one_prints)
{
    const std::vector<spec::derivation> files = sources();
    memory_store store;
    const engine::derivation_store handle = store.handle();
    const engine::library derived = engine::derive_all(files, "", {&handle});
    BOOST_TEST(store.found == 0u);
    BOOST_TEST(store.kept == files.size());
    const engine::library restored = engine::derive_all(files, "", {&handle});
    BOOST_TEST(store.found == files.size());
    BOOST_TEST(store.kept == files.size());
    const std::vector<std::string> before = printed(derived), after = printed(restored);
    BOOST_TEST_REQUIRE(before.size() == after.size());
    for (std::size_t i = 0; i < before.size(); ++i)
        BOOST_TEST(before[i] == after[i]);
    // The restored derivations hold symbols of their own, as a derivation does.
    const engine::derivation& a = derived.derived.at("rough_plane");
    const engine::derivation& b = restored.derived.at("rough_plane");
    BOOST_TEST(!a.symbols.find("mu")->symbol.is_equal(b.symbols.find("mu")->symbol));
    BOOST_TEST(b.all_hold());
    BOOST_TEST(b.checks.size() == a.checks.size());
}

// The progress line's count (pipeline/progress.h): told as each derivation is done, in one
// process or in two workers, cold or from the store; never going back, never past the
// number of files, ending at it.
BOOST_AUTO_TEST_CASE(progress_is_told_as_each_derivation_is_done_and_never_goes_back)
{
    const std::vector<spec::derivation> files = sources();
    memory_store store;
    for (const bool workers : {false, true})
        for (const bool warm : {false, true}) {
            BOOST_TEST_CONTEXT((workers ? "two workers" : "one process") << (warm ? ", warm" : ", cold"))
            {
                std::vector<std::pair<std::size_t, std::size_t>> told;
                if (!warm)
                    store = memory_store{};
                const engine::derivation_store kept = store.handle();
                const engine::deriving how{&kept, workers ? pipeline::worker_runner(2) : engine::task_runner{},
                                           [&](std::size_t done, std::size_t all) { told.emplace_back(done, all); }};
                engine::derive_all(files, "", how);
                BOOST_TEST(store.found == (warm ? files.size() : 0u));
                BOOST_TEST_REQUIRE(told.size() >= files.size());
                BOOST_TEST(told.back().first == files.size());
                for (std::size_t i = 0; i < told.size(); ++i) {
                    BOOST_TEST(told[i].second == files.size());
                    BOOST_TEST(told[i].first >= 1u);
                    if (i > 0)
                        BOOST_TEST(told[i].first >= told[i - 1].first, "call " << i);
                }
            }
        }
}

BOOST_AUTO_TEST_CASE(a_changed_file_is_derived_again_with_those_that_use_it_and_no_other)
{
    std::vector<spec::derivation> files = sources();
    memory_store store;
    const engine::derivation_store handle = store.handle();
    engine::derive_all(files, "", {&handle});
    const std::size_t all = files.size();
    // rough_plane uses rough_sticking: a new title in rough_sticking's file changes both (a
    // comment or spacing would change nothing).
    const auto retitle = [](spec::derivation& s) {
        s.contents.replace(s.contents.find("\ntitle = \""), 10, "\ntitle = \"Changed: ");
    };
    for (spec::derivation& s : files)
        if (s.id.value == "rough_sticking")
            retitle(s);
    store.found = store.kept = 0;
    engine::derive_all(files, "", {&handle});
    BOOST_TEST(store.found == all - 2);
    BOOST_TEST(store.kept == 2u);
    // rough_plane alone.
    for (spec::derivation& s : files)
        if (s.id.value == "rough_plane")
            retitle(s);
    store.found = store.kept = 0;
    engine::derive_all(files, "", {&handle});
    BOOST_TEST(store.found == all - 1);
    BOOST_TEST(store.kept == 1u);
}

BOOST_AUTO_TEST_CASE(comments_added_move_the_places_of_a_kept_derivation_and_derive_nothing)
{
    const std::string file = IMPACT_SOURCE_DIR "/tests/examples/spring.toml";
    const std::string text = spec::read_input_file(file);
    memory_store store;
    const engine::derivation_store handle = store.handle();
    engine::derive_all({spec::parse_derivation(text, file)}, "", {&handle});
    BOOST_TEST_REQUIRE(store.kept == 1u);
    // Two lines of comments at the top, one in the middle, a comment at the end: kept, with
    // every place where a derivation of the commented file has it.
    const std::size_t middle = text.find("\n[[result]]");
    BOOST_TEST_REQUIRE(middle != std::string::npos);
    std::string commented = "# A note.\n\n# Another.\n" + text.substr(0, middle) + "\n# Results:" +
                            text.substr(middle) + "\n# The end.\n";
    const engine::library kept = engine::derive_all({spec::parse_derivation(commented, file)}, "", {&handle});
    BOOST_TEST(store.found == 1u);
    BOOST_TEST(store.kept == 1u);
    const engine::derivation fresh = engine::derive(spec::parse_derivation(commented, file), {});
    const engine::derivation& back = kept.derived.at(fresh.id());
    BOOST_TEST_REQUIRE(back.checks.size() == fresh.checks.size());
    BOOST_TEST_REQUIRE(!fresh.checks.empty());
    for (std::size_t i = 0; i < fresh.checks.size(); ++i)
        BOOST_TEST(to_string(back.checks[i].where) == to_string(fresh.checks[i].where));
    BOOST_TEST_REQUIRE(back.results.size() == fresh.results.size());
    for (std::size_t i = 0; i < fresh.steps.size(); ++i)
        BOOST_TEST(to_string(back.steps[i].where) == to_string(fresh.steps[i].where));
    BOOST_TEST(fresh.checks.back().where.line > 3u);
    // A line whose spacing changed moves the columns after it: found, not taken, derived again.
    std::string spaced = text;
    spaced.replace(spaced.find("\nname = "), 8, "\nname  = ");
    engine::derive_all({spec::parse_derivation(spaced, file)}, "", {&handle});
    BOOST_TEST(store.kept == 2u);
}

BOOST_AUTO_TEST_CASE(a_text_impact_did_not_write_is_never_trusted)
{
    const spec::derivation source = spec::read_derivation(IMPACT_SOURCE_DIR "/tests/examples/spring.toml");
    const engine::derivation d = engine::derive(source, {});
    const std::optional<std::string> text = engine::stored_derivation(d);
    BOOST_TEST_REQUIRE(text.has_value());
    BOOST_TEST(engine::restored_derivation(*text, source).has_value());
    BOOST_TEST(!engine::restored_derivation("", source).has_value());
    BOOST_TEST(!engine::restored_derivation("impact derivation 0\n" + text->substr(text->find('\n') + 1), source));
    BOOST_TEST(!engine::restored_derivation(text->substr(0, text->size() / 2), source).has_value());
    BOOST_TEST(!engine::restored_derivation(text->substr(0, text->size() - 1), source).has_value());
    // The first expression written, a sum of an expression past the end of those written.
    const std::size_t body = text->find('\n') + 1;
    nlohmann::json wrong = nlohmann::json::parse(text->substr(body));
    wrong["nodes"][0] = {"+", 123456789};
    BOOST_TEST(!engine::restored_derivation(text->substr(0, body) + wrong.dump(), source).has_value());
    // ... or a sum of itself.
    wrong["nodes"][0] = {"+", 0, 0};
    BOOST_TEST(!engine::restored_derivation(text->substr(0, body) + wrong.dump(), source).has_value());
}

BOOST_AUTO_TEST_CASE(relations_come_back_with_their_sides_as_they_were)
{
    // GiNaC takes m == k for k == m, and m < k for k > m: each comes back as it was written.
    const spec::derivation source = spec::read_derivation(IMPACT_SOURCE_DIR "/tests/examples/spring.toml");
    engine::derivation d = engine::derive(source, {});
    const GiNaC::ex m = d.symbols.find("m")->symbol, k = d.symbols.find("k")->symbol;
    const std::vector<GiNaC::ex> relations{k == m, m == k, k > m, m < k, m <= k, k >= m};
    for (const GiNaC::ex& r : relations)
        d.givens.push_back({"r", r, "", "", {}, {}});
    const std::optional<std::string> text = engine::stored_derivation(d);
    BOOST_TEST_REQUIRE(text.has_value());
    const std::optional<engine::derivation> back = engine::restored_derivation(*text, source);
    BOOST_TEST_REQUIRE(back.has_value());
    const std::size_t first = back->givens.size() - relations.size();
    const std::vector<std::string> expected{"k == m", "m == k", "k > m", "m < k", "m <= k", "k >= m"};
    for (std::size_t i = 0; i < relations.size(); ++i) {
        const GiNaC::ex& r = back->givens[first + i].relation;
        const std::string op = r.info(GiNaC::info_flags::relation_equal)              ? "=="
                               : r.info(GiNaC::info_flags::relation_greater)            ? ">"
                               : r.info(GiNaC::info_flags::relation_less)               ? "<"
                               : r.info(GiNaC::info_flags::relation_less_or_equal)      ? "<="
                               : r.info(GiNaC::info_flags::relation_greater_or_equal)   ? ">="
                                                                                        : "?";
        BOOST_TEST(back->symbols.text(r.lhs()) + " " + op + " " + back->symbols.text(r.rhs()) == expected[i]);
    }
}

BOOST_AUTO_TEST_CASE(a_floating_point_number_is_not_kept)
{
    // A derivation holding 0.25 (a float, not 1/4) cannot be kept exactly: it is not kept.
    const spec::derivation source = spec::read_derivation(IMPACT_SOURCE_DIR "/tests/examples/spring.toml");
    engine::derivation d = engine::derive(source, {});
    BOOST_TEST_REQUIRE(!d.results.empty());
    d.results.front().display = d.results.front().display + GiNaC::numeric(0.25);
    BOOST_TEST(!engine::stored_derivation(d).has_value());
}
