#include "cache/sha256.h"

#include <openssl/evp.h>

#include <stdexcept>

namespace impact::cache {

struct sha256::context {
    EVP_MD_CTX* md = EVP_MD_CTX_new();
    ~context() { EVP_MD_CTX_free(md); }
};

sha256::sha256() : context_(std::make_unique<context>())
{
    if (!context_->md || EVP_DigestInit_ex(context_->md, EVP_sha256(), nullptr) != 1)
        throw std::runtime_error("OpenSSL cannot start a SHA-256 digest");
}

sha256::~sha256() = default;

sha256& sha256::add(std::string_view bytes)
{
    if (EVP_DigestUpdate(context_->md, bytes.data(), bytes.size()) != 1)
        throw std::runtime_error("OpenSSL cannot hash with SHA-256");
    return *this;
}

std::string sha256::hex()
{
    unsigned char digest[EVP_MAX_MD_SIZE];
    unsigned int length = 0;
    if (EVP_DigestFinal_ex(context_->md, digest, &length) != 1 || length != 32)
        throw std::runtime_error("OpenSSL cannot finish a SHA-256 digest");
    static const char digits[] = "0123456789abcdef";
    std::string out;
    out.reserve(64);
    for (unsigned int i = 0; i < length; ++i) {
        out += digits[digest[i] >> 4];
        out += digits[digest[i] & 15];
    }
    return out;
}

std::string sha256_hex(std::string_view bytes)
{
    return sha256().add(bytes).hex();
}

} // namespace impact::cache
