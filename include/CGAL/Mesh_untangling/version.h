// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The package's version: the one place it is written.  CMakeLists.txt reads
// it for the project's version (and so for Mesh_untanglingConfigVersion.cmake),
// and `untangle_mesh --version` prints it.
#ifndef CGAL_MESH_UNTANGLING_VERSION_H
#define CGAL_MESH_UNTANGLING_VERSION_H

/// \ingroup PkgMeshUntanglingRef
/// The major version of the package: a change of it may break calls that compiled.
#define CGAL_MESH_UNTANGLING_VERSION_MAJOR 1
/// \ingroup PkgMeshUntanglingRef
/// The minor version: new functionality, calls that compiled still compile.
#define CGAL_MESH_UNTANGLING_VERSION_MINOR 0
/// \ingroup PkgMeshUntanglingRef
/// The patch version: fixes only.
#define CGAL_MESH_UNTANGLING_VERSION_PATCH 0

#define CGAL_MESH_UNTANGLING_STRINGIZE_(x) #x
#define CGAL_MESH_UNTANGLING_STRINGIZE(x) CGAL_MESH_UNTANGLING_STRINGIZE_(x)

/// \ingroup PkgMeshUntanglingRef
/// The version as a string literal, "MAJOR.MINOR.PATCH".
#define CGAL_MESH_UNTANGLING_VERSION                                \
  CGAL_MESH_UNTANGLING_STRINGIZE(CGAL_MESH_UNTANGLING_VERSION_MAJOR) "." \
  CGAL_MESH_UNTANGLING_STRINGIZE(CGAL_MESH_UNTANGLING_VERSION_MINOR) "." \
  CGAL_MESH_UNTANGLING_STRINGIZE(CGAL_MESH_UNTANGLING_VERSION_PATCH)

/// \ingroup PkgMeshUntanglingRef
/// The version as one number, MAJOR * 10000 + MINOR * 100 + PATCH, for `#if`.
#define CGAL_MESH_UNTANGLING_VERSION_NR                                     \
  (CGAL_MESH_UNTANGLING_VERSION_MAJOR * 10000 + CGAL_MESH_UNTANGLING_VERSION_MINOR * 100 + \
   CGAL_MESH_UNTANGLING_VERSION_PATCH)

#endif // CGAL_MESH_UNTANGLING_VERSION_H
