# Builds and runs the outside project consumer/ against the package, as a
# CGAL user would (cmake -P):
#   MODE=install       installs the build tree BUILD_DIR (cmake --install,
#                      headers and package configuration) into a temporary
#                      prefix, moves the prefix (the configuration must be
#                      relocatable) and uses find_package(Mesh_untangling)
#   MODE=subdirectory  add_subdirectory(SOURCE_DIR) from the outside project
# Other variables: SOURCE_DIR, BUILD_DIR, WORK_DIR (emptied first), VERSION,
# EXPECT_CHOLMOD, CXX_COMPILER, GENERATOR.
foreach(variable MODE SOURCE_DIR BUILD_DIR WORK_DIR VERSION EXPECT_CHOLMOD CXX_COMPILER GENERATOR)
  if(NOT DEFINED ${variable})
    message(FATAL_ERROR "test_package_consumer.cmake: ${variable} is not given")
  endif()
endforeach()

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    string(REPLACE ";" " " command "${ARGN}")
    message(FATAL_ERROR "failed (${status}): ${command}\n${out}\n${err}")
  endif()
  set(output "${out}" PARENT_SCOPE)
endfunction()

file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
# No build type: the outside program is tiny, and unoptimized code compiles
# fastest (CGAL's assertions stay on).
set(configure ${CMAKE_COMMAND} -S ${SOURCE_DIR}/test/Mesh_untangling/consumer -B ${WORK_DIR}/build -G ${GENERATOR}
    -DCMAKE_CXX_COMPILER=${CXX_COMPILER} -DMU_EXPECTED_VERSION=${VERSION} -DMU_EXPECT_CHOLMOD=${EXPECT_CHOLMOD})
if(MODE STREQUAL "install")
  run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${WORK_DIR}/staging --component Mesh_untangling_Development)
  file(RENAME ${WORK_DIR}/staging ${WORK_DIR}/prefix)
  file(GLOB_RECURSE config_files ${WORK_DIR}/prefix/*.cmake)
  if(NOT config_files)
    message(FATAL_ERROR "cmake --install put no package configuration in the prefix")
  endif()
  foreach(file IN LISTS config_files)
    file(READ ${file} text)
    foreach(path ${WORK_DIR}/staging ${SOURCE_DIR} ${BUILD_DIR})
      string(FIND "${text}" "${path}" at)
      if(NOT at EQUAL -1)
        message(FATAL_ERROR "${file} names ${path}: the installed package is not relocatable")
      endif()
    endforeach()
  endforeach()
  run(${configure} -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix -DMU_EXPECTED_PREFIX=${WORK_DIR}/prefix)
elseif(MODE STREQUAL "subdirectory")
  run(${configure} -DMESH_UNTANGLING_SOURCE_DIR=${SOURCE_DIR})
else()
  message(FATAL_ERROR "test_package_consumer.cmake: MODE must be install or subdirectory, not '${MODE}'")
endif()
run(${CMAKE_COMMAND} --build ${WORK_DIR}/build)
run(${WORK_DIR}/build/consumer)
message("${output}")
file(REMOVE_RECURSE ${WORK_DIR})
