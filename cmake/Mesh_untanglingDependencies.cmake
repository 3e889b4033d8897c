# What the headers of Mesh_untangling need, found on the machine at hand.
# Shared by the package's own build (CMakeLists.txt) and its installed
# configuration (Mesh_untanglingConfig.cmake), so that a consumer links what
# its own configure step finds: CHOLMOD and TBB when they are there.
#
#   mesh_untangling_find_dependencies()
#     finds CGAL, Eigen 3, LBFGSpp, zlib, and (when found) TBB and CHOLMOD; sets
#     MESH_UNTANGLING_MISSING (a sentence naming what is missing, empty when
#     every required dependency was found), MESH_UNTANGLING_HAS_TBB and
#     MESH_UNTANGLING_HAS_CHOLMOD.
#   mesh_untangling_link_dependencies(TARGET)
#     gives the INTERFACE target TARGET their include directories, libraries
#     and definitions: CGAL_MESH_UNTANGLING_USE_CHOLMOD exactly when CHOLMOD
#     is linked (the headers call it then).
#
# Set before the call, to leave an optional dependency out:
#   MESH_UNTANGLING_WITH_TBB      (default ON)  parallel loops with TBB
#   MESH_UNTANGLING_WITH_CHOLMOD  (default ON)  CHOLMOD's supernodal Cholesky
# Macros, not functions: the variables and imported targets that
# find_package() defines stay visible to the caller.

macro(mesh_untangling_find_dependencies)
  set(MESH_UNTANGLING_MISSING "")
  if(NOT DEFINED MESH_UNTANGLING_WITH_TBB)
    set(MESH_UNTANGLING_WITH_TBB ON)
  endif()
  if(NOT DEFINED MESH_UNTANGLING_WITH_CHOLMOD)
    set(MESH_UNTANGLING_WITH_CHOLMOD ON)
  endif()

  if(NOT CGAL_FOUND)
    find_package(CGAL QUIET)
  endif()
  if(NOT CGAL_FOUND)
    string(APPEND MESH_UNTANGLING_MISSING " CGAL (Debian: libcgal-dev);")
  else()
    if(NOT TARGET CGAL::Eigen3_support)
      find_package(Eigen3 3.3 QUIET NO_MODULE)
      include(CGAL_Eigen3_support)
    endif()
    if(NOT TARGET CGAL::Eigen3_support)
      string(APPEND MESH_UNTANGLING_MISSING " Eigen 3.3 or later (Debian: libeigen3-dev);")
    endif()
    set(MESH_UNTANGLING_HAS_TBB OFF)
    if(MESH_UNTANGLING_WITH_TBB)
      if(NOT TARGET CGAL::TBB_support)
        find_package(TBB QUIET)
        include(CGAL_TBB_support)
      endif()
      if(TARGET CGAL::TBB_support)
        set(MESH_UNTANGLING_HAS_TBB ON)
      endif()
    endif()
  endif()

  # LBFGSpp (header-only) drives the reference L-BFGS solver.
  find_path(LBFGSPP_INCLUDE_DIR LBFGS.h PATH_SUFFIXES LBFGSpp)
  if(NOT LBFGSPP_INCLUDE_DIR)
    string(APPEND MESH_UNTANGLING_MISSING " LBFGSpp (Debian: liblbfgspp-dev);")
  endif()

  # zlib uncompresses the .vtu files that ParaView writes by default
  # (vtkZLibDataCompressor); the reader is in the headers (IO/VTU.h).
  if(NOT TARGET ZLIB::ZLIB)
    find_package(ZLIB QUIET)
  endif()
  if(NOT TARGET ZLIB::ZLIB)
    string(APPEND MESH_UNTANGLING_MISSING " zlib (Debian: zlib1g-dev);")
  endif()

  # CHOLMOD's supernodal Cholesky factorizes the Newton systems much faster
  # than Eigen's simplicial one on 3D meshes; without it the default solver
  # still works.  (The cached paths alone would keep CHOLMOD after
  # MESH_UNTANGLING_WITH_CHOLMOD is turned off: the option decides.)
  set(MESH_UNTANGLING_HAS_CHOLMOD OFF)
  if(MESH_UNTANGLING_WITH_CHOLMOD)
    find_path(CHOLMOD_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse)
    find_library(CHOLMOD_LIBRARY cholmod)
    if(CHOLMOD_INCLUDE_DIR AND CHOLMOD_LIBRARY)
      set(MESH_UNTANGLING_HAS_CHOLMOD ON)
      # The OpenMP runtime that CHOLMOD's supernodal code runs on, linked
      # (without -fopenmp) so that its factorizations can run their OpenMP
      # regions serially (Blas_call in Newton_solver.h says why).
      find_package(OpenMP COMPONENTS CXX QUIET)
    endif()
  endif()
endmacro()

macro(mesh_untangling_link_dependencies target)
  target_compile_features(${target} INTERFACE cxx_std_17)
  target_link_libraries(${target} INTERFACE CGAL::CGAL CGAL::Eigen3_support ZLIB::ZLIB)
  target_include_directories(${target} INTERFACE ${LBFGSPP_INCLUDE_DIR})
  if(MESH_UNTANGLING_HAS_TBB)
    target_link_libraries(${target} INTERFACE CGAL::TBB_support)
  endif()
  if(MESH_UNTANGLING_HAS_CHOLMOD)
    target_include_directories(${target} INTERFACE ${CHOLMOD_INCLUDE_DIR})
    target_compile_definitions(${target} INTERFACE CGAL_MESH_UNTANGLING_USE_CHOLMOD)
    target_link_libraries(${target} INTERFACE ${CHOLMOD_LIBRARY})
    if(OpenMP_CXX_FOUND)
      target_compile_definitions(${target} INTERFACE CGAL_MESH_UNTANGLING_CHOLMOD_OPENMP)
      target_link_libraries(${target} INTERFACE ${OpenMP_CXX_LIBRARIES})
    endif()
  endif()
endmacro()
