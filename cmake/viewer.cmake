# The 3-D report viewer (src/viewer, three.js) is bundled with esbuild at BUILD time and
# embedded into the grpvss binary as string literals (cmake/embed_viewer.cmake). The npm
# packages come from `npm ci` in src/viewer (scripts/setup.sh); without them the viewer
# cannot be built and `grpvss animate` / `verify --html` say so at run time.
set(GRPVSS_VIEWER_DIR ${CMAKE_SOURCE_DIR}/src/viewer)
set(GRPVSS_VIEWER_OUT ${CMAKE_BINARY_DIR}/viewer)
set(GRPVSS_VIEWER_BUNDLE ${GRPVSS_VIEWER_OUT}/viewer.js)
set(GRPVSS_VIEWER_ASSETS ${GRPVSS_VIEWER_OUT}/viewer_assets.cpp)
file(GLOB GRPVSS_VIEWER_SOURCES CONFIGURE_DEPENDS ${GRPVSS_VIEWER_DIR}/src/*.js)
find_program(GRPVSS_NODE node)
set(GRPVSS_ESBUILD ${GRPVSS_VIEWER_DIR}/node_modules/esbuild/package.json)
if(GRPVSS_NODE AND EXISTS ${GRPVSS_ESBUILD} AND EXISTS ${GRPVSS_VIEWER_DIR}/node_modules/three)
  set(GRPVSS_VIEWER_AVAILABLE ON)
  add_custom_command(
    OUTPUT ${GRPVSS_VIEWER_BUNDLE}
    COMMAND ${GRPVSS_NODE} ${GRPVSS_VIEWER_DIR}/build.mjs ${GRPVSS_VIEWER_BUNDLE}
    DEPENDS ${GRPVSS_VIEWER_SOURCES} ${GRPVSS_VIEWER_DIR}/build.mjs
            ${GRPVSS_VIEWER_DIR}/package-lock.json
    WORKING_DIRECTORY ${GRPVSS_VIEWER_DIR}
    COMMENT "Bundling the report viewer (three.js, esbuild)"
    VERBATIM)
else()
  set(GRPVSS_VIEWER_AVAILABLE OFF)
  message(WARNING "grpvss: src/viewer/node_modules missing (run `npm ci` in src/viewer or "
                  "scripts/setup.sh): HTML reports are disabled in this build")
  file(MAKE_DIRECTORY ${GRPVSS_VIEWER_OUT})
  file(WRITE ${GRPVSS_VIEWER_BUNDLE} "")
endif()
add_custom_command(
  OUTPUT ${GRPVSS_VIEWER_ASSETS}
  COMMAND ${CMAKE_COMMAND} -DBUNDLE=${GRPVSS_VIEWER_BUNDLE}
          -DTEMPLATE=${GRPVSS_VIEWER_DIR}/template.html -DOUTPUT=${GRPVSS_VIEWER_ASSETS}
          -P ${CMAKE_SOURCE_DIR}/cmake/embed_viewer.cmake
  DEPENDS ${GRPVSS_VIEWER_BUNDLE} ${GRPVSS_VIEWER_DIR}/template.html
          ${CMAKE_SOURCE_DIR}/cmake/embed_viewer.cmake
  COMMENT "Embedding the report viewer"
  VERBATIM)
target_sources(grpvss PRIVATE ${GRPVSS_VIEWER_ASSETS})
target_include_directories(grpvss PRIVATE ${CMAKE_SOURCE_DIR}/src/app)
