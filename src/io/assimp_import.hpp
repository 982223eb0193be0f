#pragma once
// assimp's C import API, loaded on the first mesh a process reads (dlopen) instead of linked:
// libassimp's ~44,000 relocations cost every process ~6.5 ms of its start on the CI machine,
// and most runs (thesis files, cells of boxes and cylinders) read no mesh
// (docs/performance.md#process-start). The scene structs are assimp's own headers; only the
// six C functions below come from the library, its stable C ABI.

#include <memory>
#include <string>

#include <assimp/scene.h>

namespace grpvss::io {

/// A scene assimp imported; released through the library when it goes out of scope.
using ImportedScene = std::unique_ptr<const aiScene, void (*)(const aiScene*)>;

/// Imports \p path with the post-processing \p flags (aiProcess_*); Collada up axes are
/// ignored unless \p apply_collada_up_axis. Imports run one at a time (assimp's C API keeps
/// its last error in one global string).
/// \throws InputError naming \p path when the library cannot be loaded (which library, and
///   dlerror's reason) or assimp cannot read the file (assimp's message).
ImportedScene import_with_assimp(const std::string& path, unsigned int flags,
                                 bool apply_collada_up_axis);

}  // namespace grpvss::io
