#include "assimp_import.hpp"

#include <dlfcn.h>

#include <cstdlib>
#include <mutex>

#include <assimp/cimport.h>
#include <assimp/config.h>

#include "grpvss/common/input_error.hpp"

namespace grpvss::io {
namespace {

/// The library's file name: its SONAME from assimp's CMake package (GRPVSS_ASSIMP_LIBRARY),
/// unless GRPVSS_ASSIMP_LIBRARY names another in the environment (docs/urdf.md#meshes).
std::string library_name() {
  const char* override_name = std::getenv("GRPVSS_ASSIMP_LIBRARY");
  return override_name != nullptr && *override_name != '\0' ? override_name : GRPVSS_ASSIMP_LIBRARY;
}

/// The C functions used, resolved once per process; `failure` says why when they are not.
struct AssimpApi {
  decltype(&aiCreatePropertyStore) create_property_store = nullptr;
  decltype(&aiSetImportPropertyInteger) set_property_integer = nullptr;
  decltype(&aiImportFileExWithProperties) import_file = nullptr;
  decltype(&aiReleasePropertyStore) release_property_store = nullptr;
  decltype(&aiGetErrorString) error_string = nullptr;
  decltype(&aiReleaseImport) release_import = nullptr;
  std::string library;  ///< the file name dlopen was given
  std::string failure;  ///< why the functions are not there; empty when they are
};

template <class Function>
bool resolve(void* library, const char* name, Function& function, std::string& failure) {
  function = reinterpret_cast<Function>(dlsym(library, name));
  if (function == nullptr && failure.empty()) failure = std::string("no symbol ") + name;
  return function != nullptr;
}

AssimpApi load_api() {
  AssimpApi api;
  api.library = library_name();
  // Never unloaded: scenes are released through it until the process ends.
  void* library = dlopen(api.library.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (library == nullptr) {
    const char* reason = dlerror();
    api.failure = std::string("it cannot be loaded: ") + (reason ? reason : "no reason given");
    return api;
  }
  std::string missing;
  resolve(library, "aiCreatePropertyStore", api.create_property_store, missing);
  resolve(library, "aiSetImportPropertyInteger", api.set_property_integer, missing);
  resolve(library, "aiImportFileExWithProperties", api.import_file, missing);
  resolve(library, "aiReleasePropertyStore", api.release_property_store, missing);
  resolve(library, "aiGetErrorString", api.error_string, missing);
  resolve(library, "aiReleaseImport", api.release_import, missing);
  if (!missing.empty()) api.failure = "it has " + missing;
  return api;
}

const AssimpApi& api() {
  static const AssimpApi loaded = load_api();
  return loaded;
}

void release_scene(const aiScene* scene) {
  if (scene != nullptr) api().release_import(scene);
}

std::mutex& import_mutex() {
  static std::mutex mutex;
  return mutex;
}

}  // namespace

ImportedScene import_with_assimp(const std::string& path, unsigned int flags,
                                 bool apply_collada_up_axis) {
  const AssimpApi& assimp = api();
  if (!assimp.failure.empty()) {
    throw InputError(path, 0, "assimp (" + assimp.library + ") to read this mesh", assimp.failure);
  }
  const std::lock_guard<std::mutex> lock(import_mutex());
  aiPropertyStore* properties = assimp.create_property_store();
  assimp.set_property_integer(properties, AI_CONFIG_IMPORT_COLLADA_IGNORE_UP_DIRECTION,
                              apply_collada_up_axis ? 0 : 1);
  const aiScene* scene = assimp.import_file(path.c_str(), flags, nullptr, properties);
  assimp.release_property_store(properties);
  if (scene == nullptr) {
    throw InputError(path, 0, "a mesh assimp can read", assimp.error_string());
  }
  return ImportedScene(scene, &release_scene);
}

}  // namespace grpvss::io
