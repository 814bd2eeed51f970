#include "lrchain/sha256.hpp"

#include <openssl/evp.h>

#include <stdexcept>

namespace lrchain {

namespace {
EVP_MD_CTX* context(void* p) { return static_cast<EVP_MD_CTX*>(p); }
}  // namespace

Sha256Builder::Sha256Builder() : context_(EVP_MD_CTX_new()) {
  if (!context_ || EVP_DigestInit_ex(context(context_), EVP_sha256(), nullptr) != 1) {
    EVP_MD_CTX_free(context(context_));
    throw std::runtime_error("SHA-256: OpenSSL could not initialise a digest");
  }
}

Sha256Builder::~Sha256Builder() { EVP_MD_CTX_free(context(context_)); }

Sha256Builder& Sha256Builder::raw(const void* data, std::size_t size) {
  if (size && EVP_DigestUpdate(context(context_), data, size) != 1) throw std::runtime_error("SHA-256: update failed");
  return *this;
}

Sha256Builder& Sha256Builder::field(std::string_view bytes) {
  const std::uint64_t n = bytes.size();
  unsigned char length[8];
  for (int i = 0; i < 8; ++i) length[i] = static_cast<unsigned char>(n >> (8 * i));
  raw(length, sizeof length);
  return raw(bytes.data(), bytes.size());
}

Sha256Digest Sha256Builder::digest() {
  Sha256Digest d{};
  unsigned int size = 0;
  if (EVP_DigestFinal_ex(context(context_), d.data(), &size) != 1 || size != d.size())
    throw std::runtime_error("SHA-256: final failed");
  return d;
}

Sha256Digest sha256(std::string_view bytes) { return Sha256Builder().raw(bytes.data(), bytes.size()).digest(); }

std::string hex_text(const Sha256Digest& digest) {
  static const char* digits = "0123456789abcdef";
  std::string out;
  out.reserve(64);
  for (std::uint8_t b : digest) {
    out += digits[b >> 4];
    out += digits[b & 15];
  }
  return out;
}

std::string sha256_hex(std::string_view bytes) { return hex_text(sha256(bytes)); }

}  // namespace lrchain
