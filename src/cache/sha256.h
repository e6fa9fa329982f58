// SHA-256 (FIPS 180-4), for naming cache entries by their inputs and checking their contents:
// OpenSSL's (libcrypto), which uses the processor's SHA instructions where it has them
// (1.8 GB/s on the project's machine, against about 0.2 GB/s for the hand-written one it
// replaced, which took 27 % of a warm regeneration checking the 27 MB of the output's entry).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

namespace impact::cache {

/// Hashes bytes given in pieces; `hex()` ends it.
class sha256 {
public:
    sha256();
    ~sha256();
    sha256(const sha256&) = delete;
    sha256& operator=(const sha256&) = delete;
    sha256& add(std::string_view bytes);
    /// The digest as 64 lowercase hexadecimal digits. The object is spent afterwards.
    std::string hex();

private:
    struct context;
    std::unique_ptr<context> context_;
};

/// The SHA-256 of `bytes`, in hexadecimal.
std::string sha256_hex(std::string_view bytes);

} // namespace impact::cache
