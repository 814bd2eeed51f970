#pragma once
// SHA-256 (FIPS 180-4) from OpenSSL's libcrypto: the one hash for everything where integrity
// matters (model cache keys, compiled-object manifests, checkpoint and results-file identities).
#include <array>
#include <cstdint>
#include <string>
#include <string_view>

namespace lrchain {

using Sha256Digest = std::array<std::uint8_t, 32>;

// SHA-256 digest of `bytes`.
Sha256Digest sha256(std::string_view bytes);
// The digest as 64 lowercase hexadecimal digits.
std::string sha256_hex(std::string_view bytes);
std::string hex_text(const Sha256Digest& digest);

// SHA-256 over several pieces, each prefixed by its length, so that ("ab", "c") and ("a", "bc")
// never collide: for keys made of several fields (file bytes, compiler, version, kind).
class Sha256Builder {
 public:
  Sha256Builder();
  ~Sha256Builder();
  Sha256Builder(const Sha256Builder&) = delete;
  Sha256Builder& operator=(const Sha256Builder&) = delete;
  // Adds one field (length-prefixed).
  Sha256Builder& field(std::string_view bytes);
  // Adds raw bytes (no prefix): for streaming one long value.
  Sha256Builder& raw(const void* data, std::size_t size);
  Sha256Digest digest();
  std::string hex() { return hex_text(digest()); }

 private:
  void* context_;
};

}  // namespace lrchain
