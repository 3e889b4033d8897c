# Copyright (c) 2026 Mesh_untangling contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Untangles meshes until they are locally invertible (CGAL Mesh_untangling).

The vertices of a 2D triangle or quadrilateral map, a surface
parameterization (seamless too), a tetrahedral or hexahedral mesh are moved
until no element is inverted and no vertex star or edge fan is wound twice.
Arrays in, arrays out:

    >>> import mesh_untangling as mu
    >>> mesh = mu.read("cube.input")
    >>> vertices, result = mu.untangle(mesh.vertices, mesh.elements, rest=mesh.rest, fixed=mesh.fixed)
    >>> result.status
    <Status.SUCCESS: 0>

The same run as ``untangle_mesh cube.input`` gives the same bits.  Functions:
untangle(), check_local_invertibility(), read(), write(),
project_on_best_fit_plane(), integer_grid_quads().  Errors: InvalidInputError (a ValueError),
ReadError and WriteError (OSErrors), ValueError and TypeError for arrays of
the wrong shape or type.
"""

from ._mesh_untangling import (InvalidInputError, Mesh, ReadError, Result, Status, Step, Verdict, WriteError,
                               __version__)
from . import _mesh_untangling as _core

__all__ = ["untangle", "check_local_invertibility", "read", "write", "project_on_best_fit_plane", "integer_grid_quads",
           "Result", "Status",
           "Step", "Verdict", "Mesh", "InvalidInputError", "ReadError", "WriteError", "__version__"]


def untangle(vertices, elements, *, rest=None, fixed=None, targets=None, theta=None, solver="auto", phantoms=True,
             continuation="auto", continuation_steps=None, max_iterations=None, time_limit=None, threads=None,
             progress=None, callback=None, refine=False, refine_budget=None, optimize_quality=False,
             slide_boundary=False, feature_angle=35.0, feature_edges=None, target_surface=None, kind=None,
             rest_elements=None,
             seam_translations="keep", stop="settled", out=None):
    """Moves the free vertices of a mesh until it is locally invertible.

    Returns ``(new_vertices, result)``: the map as an array of the shape of
    ``vertices`` (a new array, or ``out``), and a Result with every figure of
    the run (``result.status``, ``result.inverted_after``, ...).  The
    caller's arrays are never modified (unless passed as ``out``).

    Parameters
    ----------
    vertices : array_like, n x 2 or n x 3 float
        The map to untangle (any array numpy converts; integers are taken as
        floats).  Triangles and quadrilaterals are untangled in the plane: n x 2,
        or n x 3 with every z = 0.  Seamless maps: the texture coordinates.
    elements : array_like, m x 3, m x 4 or m x 8 int
        0-based vertex ids: triangles (3), tetrahedra (4, with n x 3 vertices),
        quadrilaterals (4, with n x 2 vertices) or hexahedra (8, VTK order);
        with ``kind="cells"``, 3D cells of mixed kinds in 8 columns, each row
        a cell's ids then -1s: tetrahedra (4), pyramids (5, the base
        counter-clockwise seen from the apex), prisms (6, Gmsh's order: the
        bottom triangle counter-clockwise seen from the top one) and
        hexahedra (8).
    rest : array_like, n x 2 or n x 3 float, optional
        Rest (target) positions of the same vertices: the shape every element
        should have, and the orientation it must have.  3D rest triangles
        make a surface parameterization (laid flat isometrically).  Default:
        regular elements, all positive.
    fixed : None, "boundary", bool mask (n) or int ids, optional
        Vertices that do not move.  Default None: none (a free boundary,
        protected by phantom elements).
    targets : None, "rest" or "regular", optional
        The energy's target shapes: the rest's (default) or regular elements
        (better conditioned; the rest still judges the orientation).
    theta : float in [0, 1], optional
        The size/shape trade-off; default 1/128 in 2D, 1/2 in 3D.
    solver : "auto", "newton" or "lbfgs"
        The inner solver; "auto" takes Newton unless its factorization would
        cost too much.
    phantoms : bool
        Protect a free boundary with phantom elements (no double covering of a
        boundary star); False is the published scheme.
    continuation : "auto", "never" or "always"
        Move the fixed vertices from their rest positions in steps when the
        direct run of a problem with a free vertex fails ("auto").
    continuation_steps : int >= 1, optional
        Equal steps the continuation starts with (a failed step is halved).
    max_iterations : int >= 1, optional
        The largest number of eps steps.
    time_limit : float >= 0, optional
        Seconds, checked after each eps step (TIME_LIMIT_REACHED, best map kept).
    threads : int >= 1, optional
        At most this many threads (default: every core).  The result is the
        same bits with any number.
    progress : callable(fraction) -> bool, optional
        Told the estimated fraction of the run done, from 0 to 1.  Returning
        False cancels: status CANCELLED and the input map handed back.
    callback : callable(Step) -> bool, optional
        Told each eps step (a Step).  Returning False stops the run there:
        status STOPPED_BY_CALLBACK, the best map so far is kept.
    refine : bool
        With every boundary vertex fixed and a rest given: split interior
        edges around the elements the fixed connectivity leaves inverted, and
        untangle again.  The map returned then has ``result.vertices_added``
        more rows, and ``result.elements``, ``result.rest`` and
        ``result.added_parents`` describe the refined mesh.
    refine_budget : int >= 1, optional
        The largest number of vertices ``refine`` may add (default 64).
    optimize_quality : bool
        When the map ends locally invertible, raise its worst element's
        quality (scaled Jacobian of cells, mean ratio of simplices) without
        leaving the locally invertible maps or moving a fixed vertex; the
        better map is returned, ``result.min_quality_before_optimization``
        and ``result.min_quality_after_optimization`` give the figures.
    stop : {"settled", "first-valid"}
        When the untangling stops: "settled" (default) goes on from the first
        locally invertible map until the energy toward the targets settles;
        "first-valid" stops at the first map with every element positive, as
        the untanglers that only untangle do: faster, but elements may be
        left nearly flat.  The verdict is the same.
    slide_boundary : bool
        The boundary vertices that are not fixed slide on the boundary as
        given: on their surface patch, or on their feature curve (an edge
        whose facets' planes meet beyond ``feature_angle``); corners where
        curves meet or end stay.  In 2D along the boundary polyline.  Every
        sliding vertex ends on its target: ``result.max_distance_to_target``.
    feature_angle : float in (0, 90]
        Degrees, with ``slide_boundary`` (default 35; 90: only the
        ``feature_edges`` are features).
    feature_edges : array_like, m x 2 int, optional
        With ``slide_boundary``: edges (vertex id pairs) that are feature
        edges besides those of the angle, as a meshing tool lists them
        (``Mesh.edges`` of a MEDIT, Gmsh or VTK file).  An edge inside the
        mesh is none: ``result.feature_edges_inside`` counts them.
    target_surface : tuple (points, triangles), optional
        With ``slide_boundary`` (3D): an n x 3 float array and an m x 3 int
        array, the triangle surface the boundary slides on instead of its
        own (a CAD model's triangulation, the boundary of the shape's
        tetrahedra); each patch, curve and corner goes to the surface's
        closest.  ``result.boundary_moved_onto_target`` says how far the
        boundary was moved onto it.
    kind : None or "triangles", "tetrahedra", "quadrilaterals", "hexahedra", "cells"
        What ``elements`` are; default from their columns and the vertices'
        ("cells", mixed 3D cells, is never the default).
    rest_elements : array_like, m x 3 int, optional
        A seamless map: the surface's triangles (ids into ``rest``), row k the
        same triangle as row k of ``elements`` (ids into the texture
        coordinates ``vertices``).  ``fixed`` is then per surface vertex.
    seam_translations : "keep" or "free"
        A seamless map keeps each seam transition's rotation, and its
        translation ("keep": cones stay) or not ("free").
    out : numpy.ndarray, optional
        A writable C-contiguous float64 array of the shape of ``vertices``
        (``vertices`` itself to untangle in place) that receives the map.

    Raises
    ------
    TypeError, ValueError
        Arrays of the wrong type or shape, ids out of range, coordinates not
        finite, options out of their range (the message names the element or
        vertex).
    InvalidInputError
        A mesh the untangler does not take (non-manifold, ...).

    Ctrl-C (KeyboardInterrupt) and any exception raised in ``progress`` or
    ``callback`` stop the run after the eps step and are raised again here.
    The GIL is released while the run works.
    """
    return _core._untangle(vertices, elements, rest=rest, rest_elements=rest_elements, kind=kind, fixed=fixed,
                           targets=targets, theta=theta, solver=solver, phantoms=phantoms, continuation=continuation,
                           continuation_steps=continuation_steps, max_iterations=max_iterations,
                           time_limit=time_limit, threads=threads, progress=progress, callback=callback,
                           refine=refine, refine_budget=refine_budget, optimize_quality=optimize_quality,
                           slide_boundary=slide_boundary, feature_angle=feature_angle,
                           feature_edges=feature_edges, target_surface=target_surface, seam_translations=seam_translations,
                           stop=stop, out=out)


def check_local_invertibility(vertices, elements, *, rest=None, fixed=None, kind=None, rest_elements=None):
    """Decides whether a map is locally invertible, with exact predicates.

    Returns a Verdict: ``locally_invertible`` (also its truth value), the
    counts (``inverted``, ``overwound_vertices``, ``overwound_edges``,
    ``input_defects``, ...), the ids of what blocks it
    (``inverted_elements``, ``overwound_vertex_ids`` with their
    ``coverings``, ``overwound_edge_ids``, cells' ``inverted_cells``) and
    the range of the stars' windings.

    ``vertices``, ``elements``, ``kind`` and ``rest_elements`` are those of
    untangle(); ``rest`` decides the orientation each element must have
    (default: positive); ``fixed`` tells which inverted elements are input
    defects (all their vertices fixed: counted apart).
    """
    return _core._check_local_invertibility(vertices, elements, rest=rest, rest_elements=rest_elements, kind=kind,
                                            fixed=fixed)


def read(path, *, weld="auto"):
    """Reads the mesh file at ``path`` (.obj, .off, .vtk, .vtu, .mesh, .msh, .input) into a Mesh.

    ``mesh.vertices`` is the map (OBJ: the vt lines; a file with one geometry:
    it), ``mesh.rest`` the rest when the file has one (OBJ: the v lines;
    .input: the rest), ``mesh.elements`` the elements, ``mesh.kind`` their
    kind, ``mesh.fixed`` the fixed vertex ids the file lists (.input handles,
    the 'fixed' point field of a .vtk or .vtu, the physical group 'fixed' of a .msh), for an OBJ with seams
    ``mesh.rest_elements`` the surface's triangles, and for a .vtk
    ``mesh.point_fields`` and ``mesh.cell_fields``: its scalars of one
    component by name (int64 for integer types, else float64; the fields
    that write() and untangle_mesh write).  Raises ReadError naming the file
    and line.

    ``weld`` (OBJ): seams written as duplicated v (one per chart at the same
    point, as quad-remeshing tools write them) are welded into one vertex
    whose corners keep their vt: ``"auto"`` when the copies are equal, the
    surface is in 3D and the welded seams are transitions (else
    ``mesh.welding_note`` says why not), ``"off"`` never, a distance: points
    that close (a weld that merges two corners of a face, or whose seams are
    no transitions, raises ReadError).  ``mesh.welded_vertex_of_file_vertex``
    then maps each v line to its vertex, ``mesh.file_vertices`` and
    ``mesh.file_elements`` are the file's own v lines and faces, and
    ``write(..., layout=mesh)`` writes them back.
    """
    return _core._read(str(path), weld)


def write(path, vertices, elements, *, rest=None, fixed=None, kind=None, rest_elements=None, point_fields=None,
          cell_fields=None, layout=None):
    """Writes a mesh file in the format of the extension (.obj, .off, .vtk, .vtu, .mesh, .msh, .input).

    ``vertices``, ``elements``, ``rest``, ``kind`` and ``rest_elements`` are
    the arrays of untangle() (OBJ writes ``rest`` as v and ``vertices`` as
    vt; a map alone is its own v); ``fixed`` is written where the format
    holds it (.input handles, a .vtk or .vtu 'fixed' field, a .msh group 'fixed').  ``point_fields`` and
    ``cell_fields`` (.vtk only) map field names to one number per vertex or
    per element.  ``layout``: the Mesh that read() returned for an OBJ whose
    seams were written as duplicated v: the OBJ is written back with that
    file's own v lines and faces (``mesh.file_vertices``,
    ``mesh.file_elements``); the elements must be the same.  The file is
    written whole or not at all: WriteError names the problem and nothing
    is left at ``path``.
    """
    _core._write(str(path), vertices, elements, rest=rest, rest_elements=rest_elements, kind=kind, fixed=fixed,
                 point_fields=point_fields, cell_fields=cell_fields, layout=layout)


def project_on_best_fit_plane(vertices, triangles):
    """The orthogonal projection of a surface on its best-fit plane: n x 3 ``vertices``
    and m x 3 ``triangles`` in, n x 2 texture coordinates out.

    A first map for a surface parameterization: untangle it with the surface
    as the rest, ``untangle(uv, triangles, rest=vertices)``.
    """
    return _core._project_on_best_fit_plane(vertices, triangles)


def integer_grid_quads(vertices, elements, *, rest, rest_elements):
    """The quad mesh that a seamless integer-grid map draws on its surface, as
    quad remeshing extracts it: ``(points, quads, open_edges)``.

    ``vertices`` (texture coordinates), ``elements``, ``rest`` (the surface's
    vertices) and ``rest_elements`` (its triangles) are a seamless map as
    read() and untangle() have them.  ``points`` (k x 3) are the integer
    points of the map placed on the surface, ``quads`` (q x 4 int64) the unit
    squares between them, counterclockwise as the triangles; a cone of angle
    k pi / 2 is a vertex of valence k.  ``open_edges`` counts the grid edges
    that leave through a boundary off the integer isolines (the squares they
    cut are left out).  Raises InvalidInputError saying why there is no quad
    mesh: a seam translation that is no integer, a cone off the integer
    grid, a triangle that is not positive, a star that turns other than once.
    """
    return _core._integer_grid_quads(vertices, elements, rest=rest, rest_elements=rest_elements)
