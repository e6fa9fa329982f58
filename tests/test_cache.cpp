// The cache of `impact regenerate` (src/cache/): SHA-256 against the standard's examples,
// entries checked before use (a damaged or truncated one is computed again), the folder
// refused when it holds what is not Impact's, eviction of the oldest entries only; and end
// to end, a warm regeneration, one from damaged entries and two at once sharing a cache
// write the bytes a regeneration without a cache writes; its size given by --cache-size or
// IMPACT_CACHE_SIZE, and a size that is none refused.
#define BOOST_TEST_MODULE test_cache
#include <boost/test/unit_test.hpp>

#include "cache/sha256.h"
#include "cache/store.h"
#include "spec/error.h"

#include "support.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

namespace fs = std::filesystem;
using namespace impact;
using impact::testing::run_command;
using impact::testing::run_result;
using impact::testing::snapshot;

namespace {

// A fresh folder under the system's temporary folder, removed at the end.
struct scratch : impact::testing::temporary_folder {
    scratch() : temporary_folder("impact-test-cache") {}
};

std::string read(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
}

void write(const fs::path& path, const std::string& bytes)
{
    std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

// The paper's smooth spheres (support.h), copied once: 12 derivations with every kind of entry
// the cache keeps (14 s of a cold regeneration's wall time against 43 s for the folder without
// rough_space.toml, 7 Dec 2026); nothing the cache does depends on the rough spheres.
const fs::path& derivations()
{
    static const impact::testing::temporary_folder folder("impact-test-cache-derivations");
    static const bool copied = [] {
        impact::testing::copy_derivations(folder.root, impact::testing::smooth_spheres);
        return true;
    }();
    (void)copied;
    return folder.root;
}

// `impact regenerate` of those derivations into `output`, with the default cache under
// `xdg` (never the user's ~/.cache) and any further `arguments`.
run_result regenerate(const fs::path& xdg, const fs::path& output, const std::string& arguments)
{
    return run_command("XDG_CACHE_HOME='" + xdg.string() + "' " + IMPACT_BINARY + " regenerate --timings --derivations '" +
                       derivations().string() + "' --output '" + output.string() + "' " + arguments);
}

bool said(const std::string& output, const std::string& pattern)
{
    return std::regex_search(output, std::regex(pattern));
}

// What a regeneration without any cache writes, made once.
const std::map<std::string, std::string>& cold_output()
{
    static const std::map<std::string, std::string> files = [] {
        const scratch s;
        const run_result r = regenerate(s.root / "xdg", s.root / "output", "--no-cache");
        BOOST_TEST_REQUIRE(r.status == 0, r.output);
        BOOST_TEST(r.output.find("cache: none") != std::string::npos, r.output);
        // --no-cache reads and writes no cache, not even the default one.
        BOOST_TEST(!fs::exists(s.root / "xdg"));
        return snapshot(s.root / "output");
    }();
    return files;
}

// A cache one regeneration of the project's derivations filled, made once, in the default
// folder ($XDG_CACHE_HOME/impact): tests that start from a warm cache copy it rather than
// regenerate (each cold regeneration takes about 14 s here, far longer under the sanitizers).
fs::path copy_of_a_filled_cache(const fs::path& to)
{
    static const scratch s;
    static const fs::path filled = [] {
        const run_result r = regenerate(s.root / "xdg", s.root / "output", "");
        BOOST_TEST_REQUIRE(r.status == 0, r.output);
        BOOST_TEST(fs::exists(s.root / "xdg" / "impact" / "CACHEDIR.TAG"));
        BOOST_TEST(said(r.output, "kernel choice: 0 reused, [1-9][0-9]* computed"), r.output);
        BOOST_TEST((snapshot(s.root / "output") == cold_output()));
        return s.root / "xdg" / "impact";
    }();
    fs::copy(filled, to, fs::copy_options::recursive);
    return to;
}

// The entries a regeneration left in `cache`.
std::vector<fs::path> entries_in(const fs::path& cache)
{
    std::vector<fs::path> found;
    for (const auto& e : fs::directory_iterator(cache))
        if (e.path().extension() == ".entry")
            found.push_back(e.path());
    std::sort(found.begin(), found.end());
    return found;
}

} // namespace

BOOST_AUTO_TEST_SUITE(test_cache)

BOOST_AUTO_TEST_CASE(sha256_gives_the_digests_of_the_standards_examples)
{
    // FIPS 180-4's examples (one block, two blocks) and the empty message.
    BOOST_TEST(cache::sha256_hex("abc") == "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
    BOOST_TEST(cache::sha256_hex("") == "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
    const std::string two_blocks = "abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq";
    BOOST_TEST(cache::sha256_hex(two_blocks) == "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
    // Given in pieces of any size, the same digest.
    cache::sha256 pieces;
    for (std::size_t at = 0; at < two_blocks.size(); at += 7)
        pieces.add(std::string_view(two_blocks).substr(at, 7));
    BOOST_TEST(pieces.hex() == cache::sha256_hex(two_blocks));
    // A million 'a's, the standard's long example.
    BOOST_TEST(cache::sha256_hex(std::string(1000000, 'a')) ==
               "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

BOOST_AUTO_TEST_CASE(the_programs_fingerprint_is_the_build_id_the_linker_wrote)
{
    // binutils' readelf reads the note from the file; Impact reads it from memory.
    const fs::path self = fs::read_symlink("/proc/self/exe");
    const run_result notes = run_command("readelf -n '" + self.string() + "'");
    BOOST_TEST_REQUIRE(notes.status == 0, notes.output);
    std::smatch id;
    if (!std::regex_search(notes.output, id, std::regex("Build ID: ([0-9a-f]+)"))) {
        // Linked without a build ID: the fingerprint is the hash of the executable.
        std::ifstream in(self, std::ios::binary);
        std::ostringstream bytes;
        bytes << in.rdbuf();
        BOOST_TEST(cache::program_fingerprint() == cache::sha256_hex(bytes.str()));
        return;
    }
    BOOST_TEST(cache::program_fingerprint() == "build " + id[1].str());
}

BOOST_AUTO_TEST_CASE(a_stored_result_comes_back_for_its_key_only)
{
    const scratch s;
    cache::store store(s.root / "cache");
    BOOST_TEST(!store.get("PDF", "sources 1").has_value());
    store.put("PDF", "sources 1", std::string("%PDF-\0binary\n", 13));
    BOOST_TEST(store.get("PDF", "sources 1").value() == std::string("%PDF-\0binary\n", 13));
    BOOST_TEST(!store.get("PDF", "sources 2").has_value());
    BOOST_TEST(!store.get("kernel choice", "sources 1").has_value());   // another kind, another entry
    const auto counts = store.statistics();
    BOOST_TEST(counts.at("PDF").hits == 1u);
    BOOST_TEST(counts.at("PDF").misses == 2u);
    BOOST_TEST(counts.at("PDF").rejected == 0u);
    BOOST_TEST(fs::exists(s.root / "cache" / "CACHEDIR.TAG"));
    BOOST_TEST(read(s.root / "cache" / "CACHEDIR.TAG").rfind("Signature: 8a477f597d28d172789f06886806bc55\n", 0) == 0u);
}

BOOST_AUTO_TEST_CASE(a_corrupted_entry_is_rejected_and_computed_again)
{
    const scratch s;
    cache::store store(s.root / "cache");
    store.put("PDF", "key", "the result of a long computation");
    const fs::path entry = store.entry_path("PDF", "key");
    std::string bytes = read(entry);
    bytes[bytes.size() - 5] ^= 0x01;   // one bit of the result flipped, its length unchanged
    write(entry, bytes);
    BOOST_TEST(!store.get("PDF", "key").has_value());
    BOOST_TEST(store.statistics().at("PDF").rejected == 1u);
    store.put("PDF", "key", "the result of a long computation");
    BOOST_TEST(store.get("PDF", "key").value() == "the result of a long computation");
}

BOOST_AUTO_TEST_CASE(a_truncated_entry_is_rejected_and_computed_again)
{
    const scratch s;
    cache::store store(s.root / "cache");
    store.put("kernel choice", "key", std::string(10000, 'x'));
    const fs::path entry = store.entry_path("kernel choice", "key");
    for (std::size_t keep : {std::size_t(0), std::size_t(10), read(entry).size() - 1}) {
        write(entry, read(entry).substr(0, keep));
        BOOST_TEST(!store.get("kernel choice", "key").has_value(), "truncated to " << keep << " bytes");
        store.put("kernel choice", "key", std::string(10000, 'x'));
    }
    BOOST_TEST(store.statistics().at("kernel choice").rejected == 3u);
    BOOST_TEST(store.get("kernel choice", "key").value() == std::string(10000, 'x'));
}

BOOST_AUTO_TEST_CASE(an_entry_renamed_to_another_key_is_rejected)
{
    const scratch s;
    cache::store store(s.root / "cache");
    store.put("PDF", "first", "one");
    fs::copy_file(store.entry_path("PDF", "first"), store.entry_path("PDF", "second"));
    BOOST_TEST(!store.get("PDF", "second").has_value());
}

BOOST_AUTO_TEST_CASE(a_folder_holding_a_users_file_is_refused_and_the_file_kept)
{
    const scratch s;
    fs::create_directories(s.root / "cache");
    write(s.root / "cache" / "notes.txt", "mine\n");
    try {
        cache::store store(s.root / "cache");
        BOOST_FAIL("a folder holding notes.txt was taken for a cache");
    } catch (const impact::error& e) {
        const std::string what = e.what();
        BOOST_TEST(what.rfind((s.root / "cache").string() + ": error: ", 0) == 0u, what);
        BOOST_TEST(what.find("notes.txt") != std::string::npos, what);
    }
    BOOST_TEST(read(s.root / "cache" / "notes.txt") == "mine\n");
    BOOST_TEST(!fs::exists(s.root / "cache" / "CACHEDIR.TAG"));
    // Files named like entries, in a folder Impact did not tag, are not taken for its own.
    fs::remove(s.root / "cache" / "notes.txt");
    write(s.root / "cache" / (std::string(64, 'a') + ".entry"), "someone else's\n");
    BOOST_CHECK_THROW(cache::store(s.root / "cache"), impact::error);
    BOOST_TEST(read(s.root / "cache" / (std::string(64, 'a') + ".entry")) == "someone else's\n");
}

// Two regenerations opening one new folder at once: the first is writing its tag (a
// temporary file, renamed into place) when the second looks. That folder is Impact's.
BOOST_AUTO_TEST_CASE(a_new_folder_whose_tag_another_regeneration_is_writing_is_taken)
{
    const scratch s;
    fs::create_directories(s.root / "cache");
    write(s.root / "cache" / "CACHEDIR.TAG.tmp-4242-0", "");
    cache::store store(s.root / "cache");
    BOOST_TEST(fs::exists(s.root / "cache" / "CACHEDIR.TAG"));
    // A temporary entry is another matter: entries come after the tag.
    const scratch t;
    fs::create_directories(t.root / "cache");
    write(t.root / "cache" / (std::string(64, 'b') + ".entry.tmp-4242-1"), "");
    BOOST_CHECK_THROW(cache::store(t.root / "cache"), impact::error);
}

BOOST_AUTO_TEST_CASE(a_file_given_as_the_cache_folder_is_refused)
{
    const scratch s;
    write(s.root / "file", "not a folder\n");
    BOOST_CHECK_THROW(cache::store(s.root / "file"), impact::error);
    BOOST_TEST(read(s.root / "file") == "not a folder\n");
}

BOOST_AUTO_TEST_CASE(trimming_removes_the_entries_used_longest_ago_and_nothing_else)
{
    const scratch s;
    // Room for two entries of about 1100 bytes, not three.
    cache::store store(s.root / "cache", 2500);
    const auto now = fs::file_time_type::clock::now();
    const char* keys[] = {"oldest", "middle", "newest"};
    for (int i = 0; i < 3; ++i) {
        store.put("PDF", keys[i], std::string(1000, 'x'));
        fs::last_write_time(store.entry_path("PDF", keys[i]), now - std::chrono::minutes(30 - 10 * i));
    }
    // A temporary file a killed run left two hours ago, and one being written now.
    const fs::path stale = s.root / "cache" / (std::string(64, 'b') + ".entry.tmp-1-0");
    const fs::path fresh = s.root / "cache" / (std::string(64, 'c') + ".entry.tmp-2-0");
    write(stale, "partial");
    write(fresh, "partial");
    fs::last_write_time(stale, now - std::chrono::hours(2));
    store.trim();
    BOOST_TEST(!fs::exists(store.entry_path("PDF", "oldest")));
    BOOST_TEST(fs::exists(store.entry_path("PDF", "middle")));
    BOOST_TEST(fs::exists(store.entry_path("PDF", "newest")));
    BOOST_TEST(!fs::exists(stale));
    BOOST_TEST(fs::exists(fresh));
    BOOST_TEST(fs::exists(s.root / "cache" / "CACHEDIR.TAG"));
    // A hit makes an entry the newest: "middle" outlives "newest" at the next trim.
    BOOST_TEST(store.get("PDF", "middle").has_value());
    store.put("PDF", "latest", std::string(1000, 'x'));
    store.trim();
    BOOST_TEST(fs::exists(store.entry_path("PDF", "middle")));
    BOOST_TEST(!fs::exists(store.entry_path("PDF", "newest")));
}

BOOST_AUTO_TEST_CASE(a_cache_size_is_bytes_or_a_number_with_a_binary_unit)
{
    BOOST_TEST(cache::parse_size("1048576").value() == 1048576u);
    BOOST_TEST(cache::parse_size("512M").value() == 512ull * 1024 * 1024);
    BOOST_TEST(cache::parse_size("2G").value() == 2ull * 1024 * 1024 * 1024);
    BOOST_TEST(cache::parse_size("2g").value() == 2ull * 1024 * 1024 * 1024);
    BOOST_TEST(cache::parse_size("100KiB").value() == 102400u);
    BOOST_TEST(cache::parse_size("3MB").value() == 3ull * 1024 * 1024);
    BOOST_TEST(cache::parse_size("1T").value() == 1ull << 40);
    BOOST_TEST(cache::parse_size("0").value() == 0u);
    for (const char* bad : {"", "M", "-1", "1.5G", "12Q", "2 G", " 2G", "2GG", "abc", "99999999999999999999",
                            "16777216T"})
        BOOST_TEST(!cache::parse_size(bad).has_value(), "'" << bad << "' taken for a size");
}

BOOST_AUTO_TEST_CASE(a_warm_regeneration_writes_what_one_without_a_cache_writes)
{
    const scratch s;
    // A cache the default folder ($XDG_CACHE_HOME/impact) filled: copy_of_a_filled_cache
    // checks that regeneration's output against one without a cache.
    const fs::path cache = copy_of_a_filled_cache(s.root / "cache");
    const run_result warm = regenerate(s.root / "elsewhere", s.root / "warm", "--cache '" + cache.string() + "'");
    BOOST_TEST_REQUIRE(warm.status == 0, warm.output);
    // Nothing changed: the whole output reused, nothing derived.
    BOOST_TEST(said(warm.output, "output: 1 reused, 0 computed"), warm.output);
    BOOST_TEST(!said(warm.output, "kernel choice"), warm.output);
    BOOST_TEST(!fs::exists(s.root / "elsewhere"));
    BOOST_TEST((snapshot(s.root / "warm") == cold_output()));
}

BOOST_AUTO_TEST_CASE(a_comment_changes_nothing_and_a_changed_title_recomputes_only_the_report)
{
    const scratch s;
    const fs::path derivations = s.root / "derivations", cache = s.root / "cache";
    fs::copy(::derivations(), derivations);
    const auto run = [&](const std::string& output, const std::string& arguments) {
        return run_command(std::string(IMPACT_BINARY) + " regenerate --timings --derivations '" + derivations.string() +
                           "' --output '" + (s.root / output).string() + "' " + arguments);
    };
    const std::string at = "--cache '" + cache.string() + "'";
    BOOST_TEST_REQUIRE(run("cold", at).status == 0);
    const fs::path file = derivations / "eq08_inelastic_line.toml";
    write(file, "# A comment a user added.\n" + read(file) + "\n# And another one.\n");
    const run_result commented = run("commented", at);
    BOOST_TEST_REQUIRE(commented.status == 0, commented.output);
    BOOST_TEST(said(commented.output, "output: 1 reused, 0 computed"), commented.output);
    BOOST_TEST((snapshot(s.root / "commented") == snapshot(s.root / "cold")));
    // The paper's order of places: a comment in it changes nothing either; a place moved
    // reorders the errata, so the output is made again (its kernels' choice reused).
    const fs::path order = derivations / "paper_order.txt";
    write(order, read(order) + "# A comment a user added.\n");
    const run_result order_commented = run("order_commented", at);
    BOOST_TEST(said(order_commented.output, "output: 1 reused, 0 computed"), order_commented.output);
    write(order, "Sec. IV, 3rd paragraph, 1st sentence\n" +
                     std::regex_replace(read(order), std::regex("\nSec\\. IV, 3rd paragraph, 1st sentence\n"), "\n"));
    const run_result reordered = run("reordered", at);
    BOOST_TEST_REQUIRE(reordered.status == 0, reordered.output);
    BOOST_TEST(said(reordered.output, "output: 0 reused, 1 computed"), reordered.output);
    // The derivations are kept by their files without comments: eq08's comments derive
    // nothing (its places, moved by the comment above them, are put right as it is read).
    BOOST_TEST(said(reordered.output, "derivation: 12 reused, 0 computed"), reordered.output);
    BOOST_TEST(said(reordered.output, "kernel choice: [1-9][0-9]* reused, 0 computed"), reordered.output);
    // Nor is Z3 run again: every proof's answer is kept by its problem's text.
    BOOST_TEST(said(reordered.output, "z3 answer: [1-9][0-9]* reused, 0 computed"), reordered.output);
    const std::string errata = read(s.root / "reordered" / "errata.md");
    BOOST_TEST(errata.find("| Sec. IV, 3rd paragraph, 1st sentence |") < errata.find("| Abstract, 5th sentence |"));
    // A new title of the inelastic plane's (eq09): derived again, with the one derivation that
    // uses it (wall_plane), the 10 others kept; the kernels' choice and the figures reused,
    // the report compiled again; what is written is what a regeneration without a cache writes.
    const fs::path plane = derivations / "eq09_inelastic_plane.toml";
    std::string text = read(plane);
    const std::size_t title = text.find("\ntitle = \"");
    BOOST_TEST_REQUIRE(title != std::string::npos);
    text.insert(title + 10, "Once more: ");
    write(plane, text);
    const run_result retitled = run("retitled", at);
    BOOST_TEST_REQUIRE(retitled.status == 0, retitled.output);
    BOOST_TEST(said(retitled.output, "output: 0 reused, 1 computed"), retitled.output);
    BOOST_TEST(said(retitled.output, "derivation: 10 reused, 2 computed"), retitled.output);
    BOOST_TEST(said(retitled.output, "kernel choice: [1-9][0-9]* reused, 0 computed"), retitled.output);
    BOOST_TEST(said(retitled.output, "PDF: 2 reused, 1 computed"), retitled.output);
    BOOST_TEST_REQUIRE(run("uncached", "--no-cache").status == 0);
    BOOST_TEST((snapshot(s.root / "retitled") == snapshot(s.root / "uncached")));
    BOOST_TEST((snapshot(s.root / "retitled") != snapshot(s.root / "cold")));
    // A derivation nothing uses: it alone is derived again.
    const fs::path leaf = derivations / "wall_space.toml";
    text = read(leaf);
    const std::size_t leaf_title = text.find("\ntitle = \"");
    BOOST_TEST_REQUIRE(leaf_title != std::string::npos);
    text.insert(leaf_title + 10, "Once more: ");
    write(leaf, text);
    const run_result leaf_retitled = run("leaf_retitled", at);
    BOOST_TEST_REQUIRE(leaf_retitled.status == 0, leaf_retitled.output);
    BOOST_TEST(said(leaf_retitled.output, "derivation: 11 reused, 1 computed"), leaf_retitled.output);
    // Two keys of a table swapped: the same derivation, kept under the same key, but its
    // places cannot be followed to the lines they moved to. It is found, not used, and said
    // so, and derived again (here beside the leaf, retitled once more).
    const fs::path swapped = derivations / "wall_plane.toml";
    text = read(swapped);
    const std::string name_then_latex = "name = \"m\"\nlatex = \"m\"\n";
    const std::size_t pair = text.find(name_then_latex);
    BOOST_TEST_REQUIRE(pair != std::string::npos);
    text.replace(pair, name_then_latex.size(), "latex = \"m\"\nname = \"m\"\n");
    write(swapped, text);
    text = read(leaf);
    text.insert(leaf_title + 10, "Twice: ");
    write(leaf, text);
    const run_result swapped_keys = run("swapped_keys", at);
    BOOST_TEST_REQUIRE(swapped_keys.status == 0, swapped_keys.output);
    BOOST_TEST(said(swapped_keys.output, "derivation: 10 reused, 2 computed \\(0 damaged, 1 found but not usable"),
               swapped_keys.output);
}

BOOST_AUTO_TEST_CASE(damaged_and_truncated_entries_are_computed_again_and_the_output_is_the_same)
{
    const scratch s;
    const fs::path cache = copy_of_a_filled_cache(s.root / "cache");
    const std::vector<fs::path> entries = entries_in(cache);
    BOOST_TEST_REQUIRE(entries.size() >= 4u);
    // Every other entry cut in half, the others with one byte changed near their end.
    for (std::size_t i = 0; i < entries.size(); ++i) {
        std::string bytes = read(entries[i]);
        if (i % 2 == 0)
            bytes.resize(bytes.size() / 2);
        else
            bytes[bytes.size() - 2] ^= 0x20;
        write(entries[i], bytes);
    }
    const run_result r = regenerate(s.root, s.root / "second", "--cache '" + cache.string() + "'");
    BOOST_TEST_REQUIRE(r.status == 0, r.output);
    BOOST_TEST(said(r.output, "PDF: 0 reused, 3 computed \\(3 damaged"), r.output);
    BOOST_TEST(said(r.output, "kernel choice: 0 reused, ([1-9][0-9]*) computed \\(\\1 damaged"), r.output);
    BOOST_TEST(said(r.output, "derivation: 0 reused, 12 computed \\(12 damaged"), r.output);
    BOOST_TEST((snapshot(s.root / "second") == cold_output()));
    // The entries were written again: the next run reuses everything.
    const run_result again = regenerate(s.root, s.root / "third", "--cache '" + cache.string() + "'");
    BOOST_TEST(said(again.output, "output: 1 reused, 0 computed"), again.output);
    BOOST_TEST((snapshot(s.root / "third") == cold_output()));
}

// Two regenerations of the paper's smooth spheres at once: each writes what one alone without a
// cache writes.
BOOST_AUTO_TEST_CASE(two_regenerations_at_once_sharing_one_cache_both_succeed_with_the_same_output)
{
    const scratch s;
    const fs::path& smooth = ::derivations();
    const std::string cache = "--cache '" + (s.root / "cache").string() + "'";
    const std::string one = "XDG_CACHE_HOME=/nonexistent " + std::string(IMPACT_BINARY) + " regenerate --derivations '" +
                            smooth.string() + "' " + cache + " --output ";
    const run_result r = run_command("cd '" + s.root.string() + "' && (" + one + "a > a.log 2>&1 & a=$!; " + one +
                                     "b > b.log 2>&1 & b=$!; wait $a; echo \"a $?\"; wait $b; echo \"b $?\")");
    BOOST_TEST(r.output.find("a 0") != std::string::npos, r.output << read(s.root / "a.log"));
    BOOST_TEST(r.output.find("b 0") != std::string::npos, r.output << read(s.root / "b.log"));
    const auto& by_one = cold_output();
    BOOST_TEST(by_one.count("kernels/impact/collide_line.hpp") == 1u);
    BOOST_TEST(by_one.count("report.pdf") == 1u);
    BOOST_TEST((snapshot(s.root / "a") == by_one));
    BOOST_TEST((snapshot(s.root / "b") == by_one));
    // No temporary file left behind, and every entry whole.
    for (const auto& e : fs::directory_iterator(s.root / "cache"))
        BOOST_TEST(e.path().string().find(".tmp-") == std::string::npos, e.path());
    cache::store store(s.root / "cache");
    for (const fs::path& entry : entries_in(s.root / "cache"))
        BOOST_TEST(read(entry).rfind("impact cache entry 1\n", 0) == 0u, entry);
}

BOOST_AUTO_TEST_CASE(a_cache_folder_holding_a_users_file_is_refused_in_one_line_and_nothing_is_written)
{
    const scratch s;
    fs::create_directories(s.root / "mine");
    write(s.root / "mine" / "thesis.tex", "\\documentclass{article}\n");
    const run_result r = regenerate(s.root, s.root / "output", "--cache '" + (s.root / "mine").string() + "'");
    BOOST_TEST(r.status == 2, r.output);
    BOOST_TEST(impact::testing::lines_of(r.output).size() == 1u, r.output);
    BOOST_TEST(r.output.rfind((s.root / "mine").string() + ": error: ", 0) == 0u, r.output);
    BOOST_TEST(read(s.root / "mine" / "thesis.tex") == "\\documentclass{article}\n");
    BOOST_TEST(snapshot(s.root / "mine").size() == 1u);
    BOOST_TEST(!fs::exists(s.root / "output"));
    // A file given as the cache folder: the same.
    const run_result file = regenerate(s.root, s.root / "output", "--cache '" + (s.root / "mine" / "thesis.tex").string() + "'");
    BOOST_TEST(file.status == 2, file.output);
    BOOST_TEST(file.output.find(": error: the cache folder is a file") != std::string::npos, file.output);
    BOOST_TEST(!fs::exists(s.root / "output"));
}

BOOST_AUTO_TEST_CASE(a_cache_size_given_trims_the_cache_to_it_oldest_entries_first)
{
    const scratch s;
    const fs::path cache = copy_of_a_filled_cache(s.root / "cache");
    const std::string at = "--cache '" + cache.string() + "' ";
    std::uintmax_t total = 0;
    for (const fs::path& entry : entries_in(cache))
        total += fs::file_size(entry);
    // An entry of 20 000 bytes used a day ago, the oldest by far.
    const fs::path old_entry = cache / (std::string(64, 'd') + ".entry");
    write(old_entry, std::string(20000, 'x'));
    fs::last_write_time(old_entry, fs::file_time_type::clock::now() - std::chrono::hours(24));
    // Room for what the regeneration uses, not for the old entry as well: it alone goes.
    const run_result r = regenerate(s.root, s.root / "second", at + "--cache-size " + std::to_string(total + 10000));
    BOOST_TEST_REQUIRE(r.status == 0, r.output);
    BOOST_TEST(said(r.output, "output: 1 reused, 0 computed"), r.output);
    BOOST_TEST(!fs::exists(old_entry));
    std::uintmax_t left = 0;
    for (const fs::path& entry : entries_in(cache))
        left += fs::file_size(entry);
    BOOST_TEST(left == total);
    // A limit of 1K, from the environment: every entry is beyond it.
    const run_result tiny = run_command("IMPACT_CACHE_SIZE=1K XDG_CACHE_HOME='" + s.root.string() + "' " +
                                        IMPACT_BINARY + " regenerate --derivations '" + derivations().string() +
                                        "' --output '" + (s.root / "third").string() + "' " + at);
    BOOST_TEST_REQUIRE(tiny.status == 0, tiny.output);
    BOOST_TEST(entries_in(cache).empty());
    BOOST_TEST(fs::exists(cache / "CACHEDIR.TAG"));
    BOOST_TEST((snapshot(s.root / "second") == cold_output()));
    BOOST_TEST((snapshot(s.root / "third") == cold_output()));
}

BOOST_AUTO_TEST_CASE(a_cache_size_that_is_no_size_is_refused_in_one_line_before_anything_is_done)
{
    const scratch s;
    const std::string derivations = " --derivations '" + ::derivations().string() + "'";
    const std::string output = " --output '" + (s.root / "output").string() + "'";
    const std::string cache = " --cache '" + (s.root / "cache").string() + "'";
    struct refused {
        std::string environment, arguments, said;
    };
    for (const refused& c : {
             refused{"", "regenerate --cache-size 12Q" + cache + output, "--cache-size '12Q' is not a size"},
             refused{"", "regenerate --cache-size 1.5G --no-cache" + output, "--cache-size '1.5G' is not a size"},
             refused{"IMPACT_CACHE_SIZE=lots ", "regenerate" + cache + output, "IMPACT_CACHE_SIZE 'lots' is not a size"},
             refused{"", "kernels --cache-size -3" + cache + output, "--cache-size '-3' is not a size"},
         }) {
        const run_result r = run_command(c.environment + IMPACT_BINARY + " " + c.arguments + derivations);
        BOOST_TEST(r.status == 2, c.arguments << ": " << r.output);
        BOOST_TEST(impact::testing::lines_of(r.output).size() == 1u, r.output);
        BOOST_TEST(r.output.rfind("impact: error: " + c.said + ": give a number of bytes", 0) == 0u, r.output);
        BOOST_TEST(!fs::exists(s.root / "output"));
        BOOST_TEST(!fs::exists(s.root / "cache"));
    }
    // --cache-size takes precedence over the environment.
    const run_result r = run_command("IMPACT_CACHE_SIZE=lots " + std::string(IMPACT_BINARY) +
                                     " regenerate --cache-size 12Q" + cache + output + derivations);
    BOOST_TEST(r.output.find("--cache-size '12Q'") != std::string::npos, r.output);
}

BOOST_AUTO_TEST_SUITE_END()
