// SHA-256 (FIPS 180-4), for naming cache entries by their inputs and checking their contents.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace impact::cache {

/// Hashes bytes given in pieces; `hex()` ends it.
class sha256 {
public:
    sha256();
    sha256& add(std::string_view bytes);
    /// The digest as 64 lowercase hexadecimal digits. The object is spent afterwards.
    std::string hex();

private:
    void block(const unsigned char* p);
    std::uint32_t h_[8];
    unsigned char buffer_[64];
    std::size_t buffered_ = 0;
    std::uint64_t length_ = 0;
};

/// The SHA-256 of `bytes`, in hexadecimal.
std::string sha256_hex(std::string_view bytes);

} // namespace impact::cache
