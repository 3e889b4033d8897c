/*!
\ingroup PkgMeshUntanglingConcepts
\cgalConcept

The concept `DistributedSimplexSoup` describes what each process of an MPI
communicator gives `CGAL::untangle_simplex_soup_parts()`: its part of a
triangle or tetrahedral mesh that no process holds whole.  It is not a
type but a set of requirements on the ranges every process passes, as
`CGAL::untangle_simplex_soup()` takes one process's soup:

- `points`: a random access range of `Point_2` or `Point_3`, the points
  that the process's simplices use (others may be listed: they stay as
  given);
- `point_ids`: one `std::size_t` per point, its id in the whole mesh.  A
  point that several processes list has the same id on each, and the same
  position and fixed flag (`vertex_is_constrained_map`) on each;
- `simplices`: the simplices the process owns, each a random access range
  of 3 (2D) or 4 (3D) indices into `points`.  Every simplex of the mesh is
  owned by exactly one process; a process may own none;
- `simplex_ids`: one `std::size_t` per simplex, its id in the whole mesh
  (the verdict's lists name simplices by it);
- the rest points (`Mesh_untangling::parameters::rest_points`), if given,
  one per point, on every process.

The whole mesh must be one that `CGAL::untangle_simplex_soup()` accepts:
no facet shared by more than two simplices, no two simplices with the
same points.  Its boundary may be free: each process then protects the
stars of its own points with the phantoms a serial run builds.  A part that
breaks a requirement is refused on every process, with a message naming
the process, the point or the simplex.

Each process owns the points that no lower process lists, and receives the
simplices of other processes around them in one exchange: no other
overlap (ghost layer) needs to be given.

\cgalHasModel the part files that `mesh_parts split` writes and `untangle_mesh_mpi --parts` reads
(a `.vtk` or `.vtu` mesh with the point and cell fields `global_id` and the point field `fixed`).

\sa `CGAL::untangle_simplex_soup_parts()`
\sa `CGAL::untangle_simplex_soup_distributed()`
*/
class DistributedSimplexSoup
{
public:
};
