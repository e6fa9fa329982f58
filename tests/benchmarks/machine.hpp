// What a benchmark prints beside its figures: the instruction set its loops were compiled
// for, the compiler, and the processor they ran on (shared by the benchmarks).
#pragma once

#include <cstdio>
#include <string>

namespace impact::benchmarks {

// The instruction set the loops were compiled for (the widest vectors decide how many
// pairs a vector holds), the compiler, and the processor they ran on.
inline std::string isa()
{
    std::string set;
#if defined(__AVX512F__)
    set = "AVX-512F";
#elif defined(__AVX2__)
    set = "AVX2";
#elif defined(__AVX__)
    set = "AVX";
#elif defined(__SSE2__)
    set = "SSE2";
#elif defined(__ARM_NEON)
    set = "NEON";
#else
    set = "no vector extension known here";
#endif
#if defined(__FMA__)
    set += " + FMA";
#endif
#if defined(__clang__)
    set += ", Clang " __clang_version__;
#elif defined(__GNUC__)
    set += ", GCC " __VERSION__;
#endif
    std::string cpu = "unknown processor";
    if (std::FILE* f = std::fopen("/proc/cpuinfo", "r")) {
        char line[256];
        while (std::fgets(line, sizeof line, f))
            if (std::string(line).rfind("model name", 0) == 0) {
                cpu = std::string(line).substr(std::string(line).find(':') + 2);
                cpu.erase(cpu.find_last_not_of("\n") + 1);
                break;
            }
        std::fclose(f);
    }
    return set + ", on " + cpu;
}

} // namespace impact::benchmarks
