#pragma once
// What the checker has decided so far: every rejected inequality (up to a cap) and the count of
// inequalities decided exactly.

#include <cstddef>
#include <string>

#include "grpvss/checker/certificate_checker.hpp"

namespace grpvss::certify {

class CheckLedger {
 public:
  CheckLedger(CheckReport& report, std::size_t max_failures)
      : report_(report), max_failures_(max_failures) {}

  /// A rejected inequality; beyond the cap only "..." is kept.
  void fail(const std::string& message) {
    if (report_.failures.size() < max_failures_) report_.failures.push_back(message);
    else if (report_.failures.size() == max_failures_) report_.failures.push_back("...");
  }
  /// `count` more inequalities were decided.
  void decided(long long count = 1) { report_.inequalities_checked += count; }
  bool any_failure() const { return !report_.failures.empty(); }

 private:
  CheckReport& report_;
  std::size_t max_failures_;
};

}  // namespace grpvss::certify
