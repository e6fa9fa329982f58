// libFuzzer target over the derivation-file reader and the expression parser: the bytes
// are read as a derivation file (spec::parse_derivation) and derived (engine::derive, which
// parses every expression with GiNaC), with the results of derivations/ available to
// [[use]].
//
// Bad input must end in an `impact::error` printed on one line at the file: anything else
// (a crash, a sanitizer report, another exception, a message on two lines) is a finding.
// Built with -fsanitize=fuzzer by tests/fuzz/CMakeLists.txt; test_fuzz_regressions
// replays tests/fuzz/regressions/ through the same function in every build.
#include "engine/derive/derive.h"
#include "engine/library/library.h"
#include "spec/derivation.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <string>
#include <vector>

namespace {

// The derivations that files of derivations/ use ([[use]]), derived once, for fuzzed files
// (mutations of those) that use them; a derivation no file uses is not derived (its proofs
// only lengthen the fuzzer's start under the sanitizers). If derivations/ is being
// edited into a bad state, fuzzing goes on without them.
const impact::engine::derived_by_id& used()
{
    static const impact::engine::derived_by_id library = [] {
        try {
            const std::vector<impact::spec::derivation> all =
                impact::engine::read_directory(IMPACT_SOURCE_DIR "/derivations");
            std::set<std::string> ids;
            for (const impact::spec::derivation& d : all)
                for (const impact::spec::use& u : d.uses)
                    ids.insert(u.derivation.value);
            std::vector<impact::spec::derivation> wanted;
            for (const impact::spec::derivation& d : all)
                if (ids.count(d.id.value))
                    wanted.push_back(d);
            return impact::engine::derive_all(wanted).derived;
        } catch (const impact::error& e) {
            std::fprintf(stderr, "fuzz_derivation: fuzzing without derivations/ (%s)\n", e.what());
            return impact::engine::derived_by_id{};
        }
    }();
    return library;
}

} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
    used();
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string contents(reinterpret_cast<const char*>(data), size);
    try {
        impact::engine::derive(impact::spec::parse_derivation(contents, "fuzz.toml"), used());
    } catch (const impact::error& e) {
        const std::string line = e.what();
        if (line.find_first_of("\r\n") != std::string::npos || line.rfind("fuzz.toml", 0) != 0) {
            std::fprintf(stderr, "fuzz_derivation: an error not on one line at the file: %s\n", line.c_str());
            std::abort();
        }
    }
    return 0;
}
