# The library's stages (docs/architecture.md): one static library per folder src/<stage>/,
# its public headers in include/grpvss/<stage>/, its internal headers beside its sources.
#
# A stage sees only the public headers of the stages it links: each stage gets its own include
# root (<build>/stage-include/<stage>/grpvss/<stage> -> include/grpvss/<stage>), and links its
# dependencies' roots through target_link_libraries. A header of a later stage is simply not
# on the compiler's path: a wrong include fails the build (tests/architecture/ shows it).

# grpvss_add_stage(<stage> [DEPENDS <stage>...] [PUBLIC_LIBS ...] [PRIVATE_LIBS ...])
# Defines the target grpvss_<stage> (alias grpvss::<stage>).
function(grpvss_add_stage stage)
  cmake_parse_arguments(ARG "" "" "DEPENDS;PUBLIC_LIBS;PRIVATE_LIBS" ${ARGN})
  file(GLOB sources CONFIGURE_DEPENDS ${GRPVSS_ROOT}/src/${stage}/*.cpp)
  set(target grpvss_${stage})
  # A stage of plain data (headers only) is an interface library.
  if(sources)
    add_library(${target} STATIC ${sources})
    set(public PUBLIC)
  else()
    add_library(${target} INTERFACE)
    set(public INTERFACE)
  endif()
  add_library(grpvss::${stage} ALIAS ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${stage})
  set(root ${CMAKE_BINARY_DIR}/stage-include/${stage})
  if(EXISTS ${GRPVSS_ROOT}/include/grpvss/${stage})
    file(MAKE_DIRECTORY ${root}/grpvss)
    file(CREATE_LINK ${GRPVSS_ROOT}/include/grpvss/${stage} ${root}/grpvss/${stage} SYMBOLIC)
    target_include_directories(${target} ${public} $<BUILD_INTERFACE:${root}>
                                                   $<INSTALL_INTERFACE:include>)
  endif()
  set(stage_deps)
  foreach(dependency IN LISTS ARG_DEPENDS)
    list(APPEND stage_deps grpvss_${dependency})
  endforeach()
  target_link_libraries(${target} ${public} ${stage_deps} ${ARG_PUBLIC_LIBS})
  # Exact arithmetic needs IEEE semantics: never let the compiler contract or reassociate.
  target_compile_options(${target} ${public} -ffp-contract=off -frounding-math)
  if(sources)
    set_target_properties(${target} PROPERTIES POSITION_INDEPENDENT_CODE ON)
    # Unity batches: most of a stage's compile time is parsing the same headers (Eigen, fmt,
    # the stage's own); CI builds the library three times on 2 cores (docs/reliability.md#ci-time).
    # Not the CGAL stage: its units are large already (~20 s, 1.5 GB each).
    if(NOT stage STREQUAL "exact")
      set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 8)
    endif()
    target_include_directories(${target} PRIVATE ${GRPVSS_ROOT}/src/${stage})
    target_link_libraries(${target} PRIVATE ${ARG_PRIVATE_LIBS})
    target_compile_options(${target} PRIVATE ${GRPVSS_WARNINGS})
  endif()
  set_property(GLOBAL APPEND PROPERTY GRPVSS_STAGES ${target})
endfunction()

# Every stage, in data-flow order; a stage may only name earlier ones in DEPENDS.
function(grpvss_add_stages)
  grpvss_add_stage(common PUBLIC_LIBS Eigen3::Eigen PkgConfig::NETTLE)
  grpvss_add_stage(model DEPENDS common)
  grpvss_add_stage(io DEPENDS model
                   PRIVATE_LIBS fmt::fmt nlohmann_json::nlohmann_json urdfdom::urdfdom_model
                                tinyxml2::tinyxml2 yaml-cpp ${CMAKE_DL_LIBS})
  # assimp is loaded when a process reads its first mesh (io/assimp_import.cpp, dlopen): its
  # headers and the name of its library, not a link (docs/performance.md#process-start).
  target_include_directories(grpvss_io SYSTEM PRIVATE
                             $<TARGET_PROPERTY:assimp::assimp,INTERFACE_INCLUDE_DIRECTORIES>)
  target_compile_definitions(grpvss_io PRIVATE GRPVSS_ASSIMP_LIBRARY="${GRPVSS_ASSIMP_SONAME}")
  grpvss_add_stage(kinematics DEPENDS model PRIVATE_LIBS fmt::fmt ${CMAKE_DL_LIBS})
  grpvss_add_stage(motion DEPENDS kinematics PRIVATE_LIBS fmt::fmt gmpxx gmp)
  grpvss_add_stage(geometry DEPENDS model)
  # The only stage that includes CGAL (each CGAL translation unit costs ~20 s and 1.5 GB).
  grpvss_add_stage(exact DEPENDS geometry PRIVATE_LIBS CGAL::CGAL gmpxx gmp)
  # A cell file (io) made into the model: URDF chains (kinematics), shapes and meshes (exact).
  grpvss_add_stage(cell DEPENDS io kinematics exact PRIVATE_LIBS fmt::fmt gmpxx gmp)
  grpvss_add_stage(evidence DEPENDS motion geometry
                   PUBLIC_LIBS nlohmann_json::nlohmann_json PRIVATE_LIBS fmt::fmt)
  # The checker sees the exact predicates, the model, the motion and the certificate format:
  # never the verifier (certify), which it re-checks.
  grpvss_add_stage(checker DEPENDS evidence exact PRIVATE_LIBS gmpxx gmp fmt::fmt)
  grpvss_add_stage(certify DEPENDS evidence exact PRIVATE_LIBS fmt::fmt)
  grpvss_add_stage(report DEPENDS certify io cell PUBLIC_LIBS fmt::fmt)
  target_compile_definitions(grpvss_report PRIVATE GRPVSS_VERSION="${PROJECT_VERSION}")
  # Many verifications on all cores, sharing each robot cell read-only (docs/batch.md).
  grpvss_add_stage(batch DEPENDS report
                   PRIVATE_LIBS fmt::fmt nlohmann_json::nlohmann_json yaml-cpp Threads::Threads)
  # Everything a user links: `find_package(grpvss)` then `target_link_libraries(x grpvss::grpvss)`.
  add_library(grpvss_all INTERFACE)
  add_library(grpvss::grpvss ALIAS grpvss_all)
  set_target_properties(grpvss_all PROPERTIES EXPORT_NAME grpvss)
  target_link_libraries(grpvss_all INTERFACE grpvss_batch grpvss_report grpvss_checker grpvss_certify
                                             grpvss_cell grpvss_io)
endfunction()
