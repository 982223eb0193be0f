#pragma once
/// \file
/// \brief The set-up cache: a robot's link-hull offsets at one expansion radius and offset
/// shape, kept on disk between processes (docs/cache.md). An entry is a proposal only: the
/// RobotCell re-checks every offset exactly before using it, and an entry that is corrupt,
/// stale or fails the check is rebuilt and overwritten, with a note.
/// proof: proofs/offset-containment.md#lemma-cached-offset

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "grpvss/certify/robot_cell.hpp"

namespace grpvss::certify {

/// \brief Where the cache lives and which build reads it.
struct SetupCacheOptions {
  /// Directory of the entries; created (with parents) on first use.
  std::string directory;
  /// Part of every key: the program version and anything else that identifies the build
  /// (the CLI adds its executable's size and modification time). Entries written by another
  /// build are stale.
  std::string build_identity;
};

/// \brief The default directory: $XDG_CACHE_HOME/grpvss when XDG_CACHE_HOME is an absolute
/// path, else $HOME/.cache/grpvss; nullopt when neither is set. Arguments are the
/// environment variables' values (null when unset).
std::optional<std::string> default_setup_cache_directory(const char* xdg_cache_home,
                                                         const char* home);

/// \brief A LinkOffsetSource backed by one file per key in a directory. Never throws for
/// cache trouble: an unusable directory, an unreadable, corrupt, stale or rejected entry and
/// a failed write each become a one-line note (notes()) and the offsets are built. One
/// object per thread; different processes and objects may share the directory (entries are
/// published by rename, whole or not at all).
class SetupCache : public LinkOffsetSource {
 public:
  explicit SetupCache(SetupCacheOptions options);

  std::optional<std::vector<std::vector<Eigen::Vector3d>>> propose(
      const LinkOffsetInputs& inputs) override;
  void adopted(const LinkOffsetInputs& inputs,
               const std::vector<std::vector<Eigen::Vector3d>>& expanded_L,
               std::size_t rejected) override;

  /// Warnings and notes, one line each, in order ("set-up cache: ...").
  const std::vector<std::string>& notes() const { return notes_; }
  /// Whether the last propose() read a well-formed, current entry (before the re-check).
  bool loaded() const { return loaded_; }
  /// The entry file a cell with these inputs uses.
  std::string entry_path(const LinkOffsetInputs& inputs) const;

 private:
  bool usable();
  void note(const std::string& text);

  SetupCacheOptions options_;
  std::optional<bool> directory_ready_;
  bool loaded_ = false;
  std::vector<std::string> notes_;
};

}  // namespace grpvss::certify
