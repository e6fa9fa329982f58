// Inputs that once crashed the fuzz target (tests/fuzz/regressions/), and the files of
// derivations/ within its -max_len (its seeds are the shortest of them, tests/fuzz/CMakeLists.txt),
// replayed through the fuzz target's own function in every build: each
// must be derived or refused with one line at the file, never crash (fuzz_derivation.cpp
// aborts otherwise, which fails this test).
#define BOOST_TEST_MODULE test_fuzz_regressions
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv);
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace fs = std::filesystem;

namespace {

std::vector<fs::path> files_in(const fs::path& folder)
{
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(folder))
        if (entry.is_regular_file() && entry.path().filename() != "README.md")
            files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

void replay(const fs::path& file)
{
    std::ifstream in(file, std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    const std::string input = bytes.str();
    BOOST_TEST_MESSAGE("replaying " << file.filename().string());
    BOOST_TEST(LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(input.data()), input.size()) == 0);
}

} // namespace

BOOST_AUTO_TEST_CASE(every_input_that_once_crashed_the_fuzzer_is_refused_cleanly)
{
    LLVMFuzzerInitialize(nullptr, nullptr);
    const auto files = files_in(fs::path(IMPACT_SOURCE_DIR) / "tests/fuzz/regressions");
    for (const fs::path& file : files)
        replay(file);
}

BOOST_AUTO_TEST_CASE(the_seed_corpus_is_derived_without_a_finding)
{
    LLVMFuzzerInitialize(nullptr, nullptr);
    // The files no longer than the longest input the fuzzer reads: mutations of any of them
    // are inputs it may meet.
    const auto files = files_in(fs::path(IMPACT_SOURCE_DIR) / "derivations");
    std::size_t seeds = 0;
    for (const fs::path& file : files)
        if (fs::file_size(file) <= IMPACT_FUZZ_MAX_LEN) {
            replay(file);
            ++seeds;
        }
    BOOST_TEST(seeds >= 10u);
}
