/*!
\ingroup PkgMeshUntanglingConcepts
\cgalConcept

The concept `TetrahedralComplex` describes a tetrahedral mesh as
`CGAL::untangle_mesh()` reads and writes it: vertices numbered
`0 .. num_vertices(tc) - 1` with a read-write point map, and cells numbered
`0 .. num_cells(tc) - 1`, each given by the indices of its four vertices.
Unlike `CGAL::Triangulation_3`, a model must accept inverted and flat cells,
since a tangled mesh is made of them.

Each cell is untangled towards the orientation of its own target: that of
its rest cell when rest positions or target cells are given (named parameters
`rest_point_map` and `cell_target_map`), positive otherwise: without rest
geometry, list the vertices of every cell in the order that should end up
positively oriented (`CGAL::orientation()` returning `CGAL::POSITIVE`).  The untangler checks that every vertex
index is less than `num_vertices(tc)` and that no cell repeats a vertex;
vertex stars and edge fans that are not manifold are skipped by the final
invertibility check (see `CGAL::Mesh_untangling::check_local_invertibility()`).

The operations are free functions, found by argument-dependent lookup.  In the
descriptions below, `tc` is a non-const lvalue of the model type.

\cgalHasModel `CGAL::Mesh_untangling::Tetrahedral_mesh_3`

\sa `CGAL::untangle_mesh()`
*/
class TetrahedralComplex
{
public:
};

/*!
\relates TetrahedralComplex
returns the number of vertices of `tc`.
*/
std::size_t num_vertices(const TetrahedralComplex& tc);

/*!
\relates TetrahedralComplex
returns the number of cells (tetrahedra) of `tc`.
*/
std::size_t num_cells(const TetrahedralComplex& tc);

/*!
\relates TetrahedralComplex
returns the index of the `i`-th vertex of cell `c`.
\pre `c < num_cells(tc)` and `0 <= i < 4`.
*/
std::size_t cell_vertex(const TetrahedralComplex& tc, std::size_t c, int i);

/*!
\relates TetrahedralComplex
returns a model of `ReadWritePropertyMap` whose key type is `std::size_t`
(the vertex index) and whose value type is a 3D point type `Point` such that
`p[0]`, `p[1]`, `p[2]` are convertible to `double` with `CGAL::to_double()` and
`Point(x, y, z)` constructs a point from three `double`s (for example the
`Point_3` of a \cgal kernel).  The untangler reads the map through it and
writes the positions of the free vertices back with `put()`.
*/
unspecified_type get(CGAL::vertex_point_t, TetrahedralComplex& tc);
