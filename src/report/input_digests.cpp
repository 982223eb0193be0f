#include "grpvss/report/input_digests.hpp"

#include <array>
#include <fstream>
#include <memory>
#include <stdexcept>

#include <fmt/core.h>
#include <openssl/evp.h>

#include "grpvss/common/input_error.hpp"

namespace grpvss::report {

namespace {

/// An EVP SHA-256 context that frees itself.
class Sha256 {
 public:
  Sha256() : context_(EVP_MD_CTX_new(), &EVP_MD_CTX_free) {
    if (!context_ || EVP_DigestInit_ex(context_.get(), EVP_sha256(), nullptr) != 1) {
      throw std::runtime_error("OpenSSL: cannot initialise SHA-256");
    }
  }

  void update(const char* data, std::size_t size) {
    if (EVP_DigestUpdate(context_.get(), data, size) != 1) {
      throw std::runtime_error("OpenSSL: SHA-256 update failed");
    }
  }

  std::string hex_digest() {
    std::array<unsigned char, EVP_MAX_MD_SIZE> digest{};
    unsigned int length = 0;
    if (EVP_DigestFinal_ex(context_.get(), digest.data(), &length) != 1) {
      throw std::runtime_error("OpenSSL: SHA-256 final failed");
    }
    std::string hex;
    for (unsigned int i = 0; i < length; ++i) hex += fmt::format("{:02x}", digest[i]);
    return hex;
  }

 private:
  std::unique_ptr<EVP_MD_CTX, decltype(&EVP_MD_CTX_free)> context_;
};

}  // namespace

std::string sha256_hex(std::string_view bytes) {
  Sha256 hash;
  hash.update(bytes.data(), bytes.size());
  return hash.hex_digest();
}

std::string sha256_hex_of_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, "a readable input file");
  Sha256 hash;
  std::array<char, 1 << 16> buffer{};
  while (in) {
    in.read(buffer.data(), buffer.size());
    hash.update(buffer.data(), static_cast<std::size_t>(in.gcount()));
  }
  if (in.bad()) throw InputError(path, 0, "a readable input file", "a read error");
  return hash.hex_digest();
}

InputDigests digest_input_files(const std::string& robot_file,
                                const std::string& environment_file,
                                const std::string& path_file) {
  return {{robot_file, sha256_hex_of_file(robot_file)},
          {environment_file, sha256_hex_of_file(environment_file)},
          {path_file, sha256_hex_of_file(path_file)},
          /*length_unit=*/{}};
}

}  // namespace grpvss::report
