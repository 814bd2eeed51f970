// lrchain::sha256 against the FIPS 180-4 example vectors (NIST CSRC "SHA256.pdf", the one-block
// "abc" and the two-block 448-bit message) and the empty string (its published digest), and the
// length prefix of Sha256Builder::field, which keeps fields from running into each other.
#include <doctest/doctest.h>

#include <string>

#include "lrchain/sha256.hpp"

TEST_CASE("sha256 gives the FIPS 180-4 example digests") {
  CHECK(lrchain::sha256_hex("abc") == "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  CHECK(lrchain::sha256_hex("") == "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  CHECK(lrchain::sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq") ==
        "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  // Bytes beyond ASCII, NUL included, are hashed as bytes.
  const std::string with_nul("a\0b", 3);
  CHECK(lrchain::sha256_hex(with_nul) != lrchain::sha256_hex("ab"));
}

TEST_CASE("Sha256Builder fields are length-prefixed: (ab, c) and (a, bc) differ") {
  lrchain::Sha256Builder first, second, streamed;
  first.field("ab").field("c");
  second.field("a").field("bc");
  CHECK(first.hex() != second.hex());
  // raw() without prefixes is the plain digest of the concatenation.
  streamed.raw("ab", 2).raw("c", 1);
  CHECK(streamed.hex() == lrchain::sha256_hex("abc"));
}
