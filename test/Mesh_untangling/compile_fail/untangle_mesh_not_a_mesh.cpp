// Must not compile: a triangle mesh passed without its uv map models none of
// the 3D concepts of untangle_mesh(mesh, np); the compiler must say so in
// words (static_assert), not fail inside an overload that does not apply.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/untangle_mesh.h>

int main()
{
  CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3> tm;
  return CGAL::untangle_mesh(tm).is_locally_invertible() ? 0 : 1;
}
