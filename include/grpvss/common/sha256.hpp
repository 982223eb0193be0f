#pragma once
/// \file
/// \brief SHA-256 (FIPS 180-4) of bytes, lowercase hex: the input digests of reports and the
/// set-up cache's keys and checksums. The hashing is Nettle's (Debian nettle-dev), never
/// hand-written; Nettle rather than OpenSSL's libcrypto because every process loads the
/// library it links, and libcrypto's 21,000 relocations cost each `grpvss` run ~4 ms of its
/// start (docs/performance.md#process-start).

#include <cstddef>
#include <string>
#include <string_view>

#include <nettle/sha2.h>

namespace grpvss {

/// \brief An incremental SHA-256: update() any number of times, then hex_digest() once.
class Sha256 {
 public:
  Sha256();
  void update(const void* data, std::size_t size);
  /// The digest of everything updated so far, 64 lowercase hex digits.
  std::string hex_digest();

 private:
  sha256_ctx context_;
};

/// SHA-256 of `bytes`, lowercase hex.
std::string sha256_hex(std::string_view bytes);

}  // namespace grpvss
