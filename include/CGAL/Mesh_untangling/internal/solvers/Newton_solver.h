// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The default inner solver: quasi-Newton steps preconditioned by the
// positive semi-definite part of the Hessian (per element, projected in
// Jacobian space), factorized by a sparse Cholesky factorization (of the
// lower triangle) whose symbolic analysis is done once, refreshed every few
// steps, and an Armijo backtracking line search that, from a valid map,
// starts short of the first element turning over.  The projected Hessian is
// spectrally equivalent to the finite element Laplacian, so a few steps per
// eps suffice where a first-order method needs thousands of evaluations.
// Assembly runs the elements in parallel (TBB) with results independent of
// the number of threads.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_SOLVERS_NEWTON_SOLVER_H
#define CGAL_MESH_UNTANGLING_INTERNAL_SOLVERS_NEWTON_SOLVER_H

#include <CGAL/assertions.h>
#include <CGAL/Mesh_untangling/internal/Energy.h>
#include <CGAL/Mesh_untangling/internal/solvers/LBFGS_solver.h>
#include <CGAL/Mesh_untangling/internal/parallel_loops.h>
#include <CGAL/Mesh_untangling/internal/vertex_stars.h>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#ifdef CGAL_MESH_UNTANGLING_USE_CHOLMOD
#include <Eigen/CholmodSupport>
#include <sys/mman.h>
#include <sys/resource.h>
#ifdef CGAL_MESH_UNTANGLING_CHOLMOD_OPENMP
#include <omp.h>
#endif
#endif

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <new>
#include <thread>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

/// How far predicted_factorization_flops may exceed the full analysis's
/// count (test_projection checks it within 0.8 and 1.5 times).
constexpr double prediction_excess_at_most = 1.5;

#ifdef CGAL_MESH_UNTANGLING_USE_CHOLMOD
/// Held by the supernodal factorizations and solves, the only BLAS calls:
/// Debian's serial OpenBLAS (what scripts/setup.sh installs) is built
/// without locking, so two threads in it at once share its buffers.  Four
/// calls at once from four threads gave other bits than each made alone in
/// 6 of 12 runs (issue 27); the lock costs a call made alone nothing.
inline std::mutex& blas_mutex()
{
  static std::mutex mutex;
  return mutex;
}

/// Whether BLAS has taken its work buffer in this process (set by the
/// first factorization that called it; read and set under blas_mutex).
inline bool& blas_buffer_taken()
{
  static bool taken = false;
  return taken;
}

/// Whether a factorization that calls BLAS for the first time in this
/// process, and that allocates `factor_bytes` before that call, has the room
/// it needs.  OpenBLAS maps a 128 MiB work buffer at its first call, and
/// when the address space is capped (ulimit -v) below that, it waits for one
/// forever instead of failing: a Newton run under a 400 MB cap spun in
/// blas_memory_alloc (issue 27).  So, under a cap, the room is tried first
/// (mapped and unmapped, never touched): the buffer, the factor, and for
/// each hardware thread the stack and heap of the OpenMP worker that CHOLMOD
/// starts (on a 2-core machine the run on a 20^3 cube needed 290 to 300 MiB
/// beyond what it held before, its factor being 111 MiB).  Called under
/// blas_mutex.
inline bool blas_has_room(std::size_t factor_bytes)
{
  if(blas_buffer_taken()) return true;
  rlimit cap;
  if(getrlimit(RLIMIT_AS, &cap) != 0 || cap.rlim_cur == RLIM_INFINITY) return true;
  constexpr std::size_t MiB = std::size_t(1) << 20;
  const std::size_t threads = std::max(1u, std::thread::hardware_concurrency());
  const std::size_t room = 128 * MiB + factor_bytes + 32 * MiB * threads;
  void* probe = mmap(nullptr, room, PROT_NONE, MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
  if(probe == MAP_FAILED) return false;
  munmap(probe, room);
  return true;
}

/// A supernodal factorization or solve in progress: it holds blas_mutex,
/// and runs CHOLMOD's OpenMP regions on the calling thread alone.  CHOLMOD
/// opens them with a fixed team (CHOLMOD_OMP_NUM_THREADS, 4 in Debian's
/// build) whatever the thread count asked for, and beside TBB's workers on
/// the same cores its threads mostly wait: on a 21,102-tetrahedron Newton
/// run (6 eps steps, 2 cores) the process spent 0.8 s of 2.4 s in the
/// kernel, in futex waits; with the regions serial, 0.2 s of 1.7 s, with
/// --threads 1 as with --threads 2.  The setting (max-active-levels, one
/// for the process) is put back when the call ends; blas_mutex keeps the
/// calls of several solvers from interleaving their saves and restores.
class Blas_call
{
public:
  explicit Blas_call(bool calls_blas)
  {
    if(!calls_blas) return;
    lock_ = std::unique_lock<std::mutex>(blas_mutex());
#ifdef CGAL_MESH_UNTANGLING_CHOLMOD_OPENMP
    active_levels_ = omp_get_max_active_levels();
    omp_set_max_active_levels(0);
#endif
  }
  ~Blas_call()
  {
#ifdef CGAL_MESH_UNTANGLING_CHOLMOD_OPENMP
    if(lock_.owns_lock()) omp_set_max_active_levels(active_levels_);
#endif
  }
  Blas_call(const Blas_call&) = delete;
  Blas_call& operator=(const Blas_call&) = delete;

private:
  std::unique_lock<std::mutex> lock_;
#ifdef CGAL_MESH_UNTANGLING_CHOLMOD_OPENMP
  int active_levels_ = 0;   // (only with OpenMP: an unused field is a warning under clang)
#endif
};

/// CHOLMOD's LL^T, supernodal or simplicial (see Newton_solver::analyze).
class Cholmod_factorization : public Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower>
{
public:
  /// Whether the factorization and its solves call BLAS.
  bool calls_blas() const { return m_cholmodFactor != nullptr && m_cholmodFactor->is_super; }

  /// What the numeric factorization allocates before it calls BLAS: the
  /// factor's values (CHOLMOD's work space is much smaller).
  std::size_t factor_bytes() const
  {
    return m_cholmodFactor == nullptr ? 0 : sizeof(double) * m_cholmodFactor->xsize;
  }

  /// Throws std::bad_alloc when CHOLMOD's last call ran out of memory: it
  /// reports that through its status only, and Eigen's wrapper then hands
  /// back an empty solution, which the solver took for a converged step
  /// (under a 200 MB cap, a Newton run made 116 steps that moved nothing and
  /// ended "after the iteration budget" instead of "out of memory").
  void throw_if_out_of_memory()
  {
    if(cholmod().status == CHOLMOD_OUT_OF_MEMORY) throw std::bad_alloc();
  }
};
#endif

/// The unknowns numbered 0, 1, ... in vertex order, -1 for a fixed vertex;
/// a vertex that another's unknown moves (a seam's wedge, Unknowns.h) takes
/// that one's number.
struct Free_numbering
{
  std::vector<int> index;
  int count = 0;

  template <int d>
  explicit Free_numbering(const Unknowns<d>& unknowns) : index(unknowns.number_of_vertices(), -1)
  {
    const std::size_t n = unknowns.number_of_vertices();
    for(std::size_t v = 0; v < n; ++v)
      if(unknowns.owns_unknown(v)) index[v] = count++;
    for(std::size_t v = 0; v < n; ++v)
      if(unknowns.owner(v) != v) index[v] = index[unknowns.owner(v)];
  }
};

/// Per free vertex j, the free vertices i >= j that share an element with
/// it, sorted, j itself always first (even for a vertex in no element): the
/// lower triangle of the Hessian's pattern, one entry per d x d block.
template <int d>
std::vector<std::vector<int>> lower_vertex_graph(const Untangling_problem<d>& P, const Free_numbering& free)
{
  std::vector<std::vector<int>> rows(free.count);
  const Unknowns<d> unknowns = P.unknowns();
  const Vertex_stars stars = build_vertex_stars(P.number_of_vertices, P.elements);
  for_each_vertex_chunk(P.number_of_vertices, [&](std::size_t, std::size_t first, std::size_t last) {
    for(std::size_t v = first; v < last; ++v) {
      const int j = free.index[v];
      if(j < 0 || !unknowns.owns_unknown(v)) continue;
      std::vector<int>& r = rows[j];
      r.push_back(j);
      unknowns.for_each_vertex_moved_by(v, [&](std::size_t u) {   // (a seam's representative: its wedges' stars too)
        for(std::size_t s = stars.begin(u); s < stars.end(u); ++s)
          for(std::size_t a : P.elements[stars.elements[s]])
            if(free.index[a] > j) r.push_back(free.index[a]);
      });
      std::sort(r.begin(), r.end());
      r.erase(std::unique(r.begin(), r.end()), r.end());
    }
  });
  return rows;
}

/// Sparsity of the Hessian restricted to free vertices, stored as dense
/// d x d blocks in its lower triangle only (block rows >= block column; the
/// diagonal blocks whole), which is all the Cholesky factorizations read.
/// Every element knows where its blocks go, so assembly is a plain
/// accumulation without searching, colour by colour (see
/// Untangling_problem::colour_start) without races.
template <int d>
class Hessian_pattern
{
public:
  explicit Hessian_pattern(const Untangling_problem<d>& P) : free_(P.unknowns())
  {
    const int free_count = free_.count;
    // every diagonal block is stored, even that of a free vertex in no
    // element, so that the solver can shift the diagonal in place
    const std::vector<std::vector<int>> rows = lower_vertex_graph(P, free_);
    std::vector<int> column_start(free_count + 1, 0);   // per block column, into its blocks
    for(int j = 0; j < free_count; ++j)
      column_start[j + 1] = column_start[j] + static_cast<int>(rows[j].size());

    // scalar compressed-column structure: column J*d+c holds the blocks of block column J
    const int N = d * free_count;
    matrix_.resize(N, N);
    std::vector<Eigen::Index> nnz(N);
    for(int j = 0; j < free_count; ++j)
      for(int c = 0; c < d; ++c)
        nnz[d * j + c] = d * (column_start[j + 1] - column_start[j]);
    if(N > 0) matrix_.reserve(nnz);   // Eigen reads past an empty reserve list
    for(int j = 0; j < free_count; ++j)
      for(int c = 0; c < d; ++c)
        for(int i : rows[j])
          for(int r = 0; r < d; ++r)
            matrix_.insert(d * i + r, d * j + c) = 0;
    matrix_.makeCompressed();

  }

  /// Where each element's (a, b) block lands, read off the matrix's
  /// structure.  Done on the first assembly only: a caller that only wants
  /// the cost prediction of the analysis (Solver::AUTOMATIC handing over)
  /// never pays for this table, (d + 1)^2 entries per element.
  void locate_blocks(const Untangling_problem<d>& P)
  {
    if(!targets_.empty() || P.elements.empty()) return;
    const auto* outer = matrix_.outerIndexPtr();
    const auto* inner = matrix_.innerIndexPtr();
    targets_.resize(P.elements.size() * (d + 1) * (d + 1));
    for(std::size_t k = 0; k < P.elements.size(); ++k) {
      const auto& e = P.elements[k];
      for(int a = 0; a <= d; ++a)
        for(int b = 0; b <= d; ++b) {
          const int i = free_.index[e[a]], j = free_.index[e[b]];
          if(j < 0 || i < j) continue;   // fixed vertex, or upper triangle
          // the first scalar column of block column j lists its block rows, d entries each
          const auto first = outer[d * j], blocks = (outer[d * j + 1] - first) / d;
          Eigen::Index low = 0, high = blocks;   // binary search for block row i
          while(low < high) {
            const Eigen::Index middle = (low + high) / 2;
            if(inner[first + d * middle] < d * i) low = middle + 1;
            else high = middle;
          }
          Target& t = targets_[(k * (d + 1) + a) * (d + 1) + b];
          t.offset = static_cast<int>(first + d * low);
          t.stride = static_cast<int>(d * blocks);
        }
    }
  }

  int number_of_free() const { return free_.count; }
  int free_index(std::size_t v) const { return free_.index[v]; }

  /// The diagonal block of free vertex j, where it is stored (the first of
  /// its block column: a row lists j itself first).
  Eigen::Map<Eigen::Matrix<double, d, d>, 0, Eigen::OuterStride<>> diagonal_block(int j)
  {
    const auto* outer = matrix_.outerIndexPtr();
    const Eigen::Index blocks = (outer[d * j + 1] - outer[d * j]) / d;
    return {matrix_.valuePtr() + outer[d * j], d, d, Eigen::OuterStride<>(d * blocks)};
  }
  Eigen::SparseMatrix<double>& matrix() { return matrix_; }
  const Eigen::SparseMatrix<double>& matrix() const { return matrix_; }

  /// Adds the d x d block B (d2F/dx_a dx_b) of element k where it belongs
  /// in the lower triangle, as B^T in the (b, a) block when (a, b) is in the
  /// upper one; nothing for a fixed vertex.  Called once per unordered pair
  /// {a, b}, after locate_blocks.
  template <class Block>
  void add(std::size_t k, int a, int b, const Block& B)
  {
    const Target& t = targets_[(k * (d + 1) + a) * (d + 1) + b];
    if(t.offset >= 0) {
      double* values = matrix_.valuePtr() + t.offset;
      for(int c = 0; c < d; ++c)
        for(int r = 0; r < d; ++r)
          values[c * t.stride + r] += B(r, c);
      return;
    }
    const Target& u = targets_[(k * (d + 1) + b) * (d + 1) + a];
    if(u.offset >= 0) {   // B^T is the (b, a) block, in the lower triangle
      double* values = matrix_.valuePtr() + u.offset;
      for(int c = 0; c < d; ++c)
        for(int r = 0; r < d; ++r)
          values[c * u.stride + r] += B(c, r);
    }
  }

private:
  struct Target
  {
    int offset = -1;   // of the block's (0, 0) entry in the values of matrix_; -1: not stored
    int stride = 0;    // from one column of the block to the next
  };

  Free_numbering free_;
  std::vector<Target> targets_;     // per element (in colour order) and (a, b)
  Eigen::SparseMatrix<double> matrix_;
};

/// Floating-point operations of one factorization of the Hessian, predicted
/// from the free vertices' graph: CHOLMOD's AMD analysis of that scalar
/// pattern, d^2 times smaller than the Hessian's, times d^3 for its dense
/// d x d blocks (a column count c of the graph's factor is d columns of
/// about d c entries in the Hessian's).  It lets Solver::AUTOMATIC hand
/// large grids over to L-BFGS without building the Hessian's pattern.
/// Negative without CHOLMOD: no prediction.
template <int d>
double predicted_factorization_flops(const Untangling_problem<d>& P)
{
#ifdef CGAL_MESH_UNTANGLING_USE_CHOLMOD
  const Free_numbering free(P.unknowns());
  if(free.count == 0) return 0;
  const std::vector<std::vector<int>> rows = lower_vertex_graph(P, free);
  // the compressed columns written directly: each column's rows are sorted already
  Eigen::SparseMatrix<double> graph(free.count, free.count);
  graph.makeCompressed();
  auto* start = graph.outerIndexPtr();
  start[0] = 0;
  for(int j = 0; j < free.count; ++j) start[j + 1] = start[j] + static_cast<int>(rows[j].size());
  graph.resizeNonZeros(start[free.count]);
  for_each_vertex_chunk(free.count, [&](std::size_t, std::size_t first, std::size_t last) {
    for(std::size_t j = first; j < last; ++j) {
      std::copy(rows[j].begin(), rows[j].end(), graph.innerIndexPtr() + start[j]);
      std::fill(graph.valuePtr() + start[j], graph.valuePtr() + start[j + 1], 1.);
    }
  });
  Eigen::CholmodSimplicialLLT<Eigen::SparseMatrix<double>, Eigen::Lower> analysis;
  cholmod_common& c = analysis.cholmod();
  c.nmethods = 1;
  c.method[0].ordering = CHOLMOD_AMD;
  analysis.analyzePattern(graph);
  return c.fl * d * d * d;
#else
  (void)P;
  return -1;
#endif
}

/// The first root in (0, limit] of the polynomial c[0] + c[1] t + ... + c[n-1] t^(n-1)
/// (degree 3 at most) with c[0] > 0, or infinity: the interval is cut at the
/// roots of the derivative, so that the polynomial is monotone on each piece,
/// and the first piece that ends at or below zero is bisected.
inline double first_positive_root(const double* c, int n, double limit)
{
  auto p = [&](double t) { double v = 0; for(int i = n - 1; i >= 0; --i) v = v * t + c[i]; return v; };
  double cuts[4];
  int m = 0;
  cuts[m++] = 0;
  // roots of the derivative c[1] + 2 c[2] t + 3 c[3] t^2
  const double a = n > 3 ? 3 * c[3] : 0, b = n > 2 ? 2 * c[2] : 0, q = c[1];
  double r[2];
  int roots = 0;
  if(a != 0) {
    const double discriminant = b * b - 4 * a * q;
    if(discriminant >= 0) {
      const double h = -(b + std::copysign(std::sqrt(discriminant), b)) / 2;   // no cancellation
      if(h != 0) { r[roots++] = h / a; r[roots++] = q / h; }
    }
  } else if(b != 0) {
    r[roots++] = -q / b;
  }
  if(roots == 2 && r[0] > r[1]) std::swap(r[0], r[1]);
  for(int i = 0; i < roots; ++i)
    if(r[i] > 0 && r[i] < limit) cuts[m++] = r[i];
  cuts[m++] = limit;
  for(int i = 0; i + 1 < m; ++i) {
    if(!(p(cuts[i + 1]) <= 0)) continue;
    double low = cuts[i], high = cuts[i + 1];   // p(low) > 0 >= p(high)
    for(int k = 0; k < 24; ++k) {   // (the step takes a share of it: a few digits suffice)
      const double middle = (low + high) / 2;
      (p(middle) > 0 ? low : high) = middle;
    }
    return low;
  }
  return std::numeric_limits<double>::infinity();
}

/// The coefficients of det(J + t dJ) = c[0] + c[1] t + ... + c[d] t^d:
/// det J, <cof J, dJ>, (3D: <J, cof dJ>) and det dJ.  Generic in the scalar
/// (double, or Lanes of simplices).
template <int d, class T>
EIGEN_ALWAYS_INLINE void determinant_polynomial(const T* J, const T* dJ, T* c)
{
  T C[d * d], dC[d * d];
  c[0] = determinant_and_cofactor<d>(J, C);   // as the energy computes it
  c[d] = determinant_and_cofactor<d>(dJ, dC);
  c[1] = C[0] * dJ[0];
  for(int i = 1; i < d * d; ++i) c[1] += C[i] * dJ[i];
  if constexpr(d == 3) {
    c[2] = dC[0] * J[0];
    for(int i = 1; i < d * d; ++i) c[2] += dC[i] * J[i];
  }
}

/// The step bound (see step_keeping_orientation) over the elements
/// [first, first + count), count <= W, the lanes of W-wide arithmetic (as
/// in the energy pass, a short group repeats its last element), lowered
/// from `t`; -1 when one of them is not positive at x.
template <int d, int W>
double group_step_bound(const Untangling_problem<d>& P, const double* x, const double* dx, std::size_t first,
                        int count, double t, double limit)
{
  using L = Lanes<W>;
  L X[d * (d + 1)], dX[d * (d + 1)], G[(d + 1) * d];
  gather_vertex_lanes<d, W>(P, x, first, count, X);
  gather_vertex_lanes<d, W>(P, dx, first, count, dX);
  gather_operator_lanes<d, W>(P, first, count, G);
  L J[d * d], dJ[d * d], c[d + 1];
  jacobian_from_vertices<d>(X, G, J);
  jacobian_from_vertices<d>(dX, G, dJ);
  determinant_polynomial<d>(J, dJ, c);
  if(!((c[0] > 0).all())) return -1;   // (the idle lanes repeat an element of the group)
  // An element turning over later than one already seen changes nothing;
  // most cannot turn over before: c[0] exceeds the other terms' bound.
  const double reach = std::min(t, limit);
  L others = L::Zero();
  for(int i = d; i > 0; --i) others = (others + c[i].abs()) * reach;
  if(!((others >= c[0]).any())) return t;
  // again lane by lane, since t shrinks within the group
  for(int l = 0; l < count; ++l) {
    const double lane_reach = std::min(t, limit);
    double coefficients[d + 1], sum = 0;
    for(int i = 0; i <= d; ++i) coefficients[i] = c[i][l];
    for(int i = d; i > 0; --i) sum = (sum + std::abs(coefficients[i])) * lane_reach;
    if(sum >= coefficients[0]) t = std::min(t, first_positive_root(coefficients, d + 1, lane_reach));
  }
  return t;
}

/// The largest t <= limit such that no element turns over between x and
/// x + t dx, when every element is positive at x (det J > 0); infinity
/// otherwise (a tangled map may need elements to turn).  det J is a
/// polynomial in t (determinant_polynomial), bounded in lanes of elements as
/// the energy pass runs them, so that the bound costs less than a pass.
template <int d>
double step_keeping_orientation(const Untangling_problem<d>& P, const double* x, const double* dx, double limit)
{
  const std::size_t m = P.elements.size();
  std::vector<double> partial((m + element_chunk_size - 1) / element_chunk_size);
  for_each_chunk(m, element_chunk_size, [&](std::size_t chunk, std::size_t begin, std::size_t end) {
    double t = std::numeric_limits<double>::infinity();
    for(std::size_t k = begin; k < end && t >= 0; k += energy_lanes)
      t = group_step_bound<d, energy_lanes>(P, x, dx, k, static_cast<int>(std::min<std::size_t>(energy_lanes, end - k)),
                                            t, limit);
    partial[chunk] = t;
  });
  double t = std::numeric_limits<double>::infinity();
  for(double p : partial) {
    if(p < 0) return std::numeric_limits<double>::infinity();   // some element is not positive
    t = std::min(t, p);
  }
  return t;
}

/// Doublings of an accepted full step at most (see Newton_solver::minimize).
constexpr int max_extrapolations = 4;

/// The share of the step to the first element turning over that a trial takes at most.
constexpr double step_fraction = 0.9;

/// Quasi-Newton steps per factorization of the Hessian (see Newton_solver::minimize).
constexpr int steps_per_factorization = 5;

/// Elements lighter than this share of the mean weight get a barrier in
/// the preconditioner (Newton_solver::add_light_element_barrier).  Half the
/// mean also caught the ordinary grading of a mesh, whose barrier the model
/// sees: tlcpn-surface1024 (2D) took 265 evaluations where it took 188
/// (1.389997 against 1.388958); a tenth leaves it alone, and s08c and
/// armadillo 216 keep most of the gain (161 and 94 Newton steps where half
/// the mean gave 140 and 87, and none 293 and 155).
constexpr double light_element_share = 0.1;

/// The curvature pairs (s, y) of L-BFGS, ten at most, and its two-loop
/// recursion around any initial inverse Hessian.
class Quasi_newton_pairs
{
public:
  void clear() { s_.clear(); y_.clear(); rho_.clear(); }

  /// Keeps the pair if it has positive curvature (else the update would
  /// lose positive definiteness), dropping the oldest beyond ten.
  void add(const Eigen::VectorXd& s, const Eigen::VectorXd& y)
  {
    const double sy = s.dot(y);
    if(!(sy > 1e-12 * s.norm() * y.norm())) return;
    if(s_.size() == memory) { s_.erase(s_.begin()); y_.erase(y_.begin()); rho_.erase(rho_.begin()); }
    s_.push_back(s);
    y_.push_back(y);
    rho_.push_back(1 / sy);
  }

  /// r = H^-1 g, H the L-BFGS matrix built from `initial_inverse` (H0^-1) and the pairs.
  template <class Initial_inverse>
  void apply_inverse(const Eigen::VectorXd& g, Eigen::VectorXd& q, Eigen::VectorXd& r,
                     const Initial_inverse& initial_inverse) const
  {
    q = g;
    double a[memory];
    for(std::size_t i = s_.size(); i-- > 0;) {
      a[i] = rho_[i] * s_[i].dot(q);
      q -= a[i] * y_[i];
    }
    r = initial_inverse(q);
    for(std::size_t i = 0; i < s_.size(); ++i)
      r += (a[i] - rho_[i] * y_[i].dot(r)) * s_[i];
  }

private:
  static constexpr std::size_t memory = 10;
  std::vector<Eigen::VectorXd> s_, y_;
  std::vector<double> rho_;
};

template <int d>
class Newton_solver
{
#ifdef CGAL_MESH_UNTANGLING_USE_CHOLMOD
  using Factorization = Cholmod_factorization;
#else
  using Factorization = Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower>;
#endif

  static constexpr int n = d * (d + 1);   // vertex coordinates of an element
  /// The lower triangle of an element's vertex Hessian, column by column.
  using Packed_hessian = std::array<double, n * (n + 1) / 2>;
  /// Where entry (row, col), row >= col, of the vertex Hessian sits in a Packed_hessian.
  static constexpr int packed_index(int row, int col) { return col * (2 * n - col + 1) / 2 + row - col; }

public:
  /// Builds the Hessian's pattern and its symbolic factorization, whose
  /// cost prediction (`factorization_flops`) tells the caller whether this
  /// solver pays on the problem.
  explicit Newton_solver(const Untangling_problem<d>& P)
    : pattern_(P), mean_weight_(1. / double(std::max<std::size_t>(P.elements.size(), 1))),
      has_light_elements_(std::any_of(P.weights.begin(), P.weights.end(), [this](double w) { return is_light(w); }))
  {
    if(pattern_.number_of_free() > 0) analyze(pattern_.matrix());
  }

  /// Floating-point operations of one numeric factorization, as predicted
  /// by the symbolic analysis; negative when the factorization gives no
  /// prediction (Eigen's SimplicialLDLT, without CHOLMOD).
  double factorization_flops() const { return factorization_flops_; }

  /// Minimizes F(., eps) from P.x (P.x receives the result) for at most
  /// `max_iterations` steps, until the model predicts a decrease of at most
  /// `tolerance` |F| (`converged` is then set).
  ///
  /// The steps are those of L-BFGS whose initial inverse Hessian is the
  /// factorized projected Hessian, updated every `steps_per_factorization`
  /// steps (the first step of each sequence is a projected Newton step).
  /// Assembly and factorization are what a step
  /// costs in Newton's method, ten to forty energy passes; the quasi-Newton
  /// corrections also restore the curvature the per-element projection
  /// removed, which left projected Newton converging only linearly, by about
  /// a tenth per step, near the barrier (the CuboidBlocks final stages):
  /// they now take half the time.
  Inner_statistics minimize(Untangling_problem<d>& P, double eps, double theta, int max_iterations,
                            double tolerance)
  {
    Inner_statistics stats;
    const int N = d * pattern_.number_of_free();
    if(N == 0) { stats.converged = true; return stats; }
    Step_workspace w(P.x.size(), N);
    Eigen::VectorXd g(N), direction(N), q(N);
    // Elements with det J <= 0 at P.x, as the last energy evaluation there
    // counted them: the step bound is only sought from a valid map, where it exists.
    std::size_t non_positive = 0;
    Quasi_newton_pairs pairs;
    if(P.retracts()) {   // (tangents taken anew: the Hessian's projections with them)
      P.retarget();
      cache_eps_ = -1;
    }

    double E = assemble(P, eps, theta, g, &non_positive);
    ++stats.evaluations;
    if(!std::isfinite(E)) { stats.finite = false; return stats; }
    if(!factorize()) { stats.finite = false; return stats; }
    int since_factorization = 0;

    for(int it = 0; it < max_iterations; ++it) {
      ++stats.iterations;
      pairs.apply_inverse(g, q, direction, [this](const Eigen::VectorXd& r) { return solve(r); });
      direction = -direction;
      const double slope = g.dot(direction);   // < 0: descent direction
      const double predicted = -slope / 2;     // the model's decrease
      if(!direction.allFinite()) { stats.finite = false; break; }
      if(!(slope < 0)) { stats.converged = true; break; }
      // Only a Newton step's prediction (fresh factorization, no pairs)
      // measures the distance to the minimum: the quasi-Newton model can be
      // flat along directions it has not explored yet.  That last Newton step
      // is still taken: it costs one energy pass, and near the minimum it
      // squares the error (soft modes, such as the rigid motions of a free
      // boundary, are otherwise left visibly short).
      const bool last = predicted <= tolerance * std::abs(E) && since_factorization == 0;
      if(predicted <= tolerance * std::abs(E) && !last) {
        E = assemble(P, eps, theta, g, &non_positive);
        ++stats.evaluations;
        if(!std::isfinite(E) || !factorize()) { stats.finite = false; break; }
        pairs.clear();
        since_factorization = 0;
        continue;
      }

      const bool refresh = ++since_factorization >= steps_per_factorization && !last;
      scatter_to_vertices(P, direction, w.vertex_direction);
      const double bound = non_positive == 0
                             ? step_keeping_orientation(P, P.x.data(), w.vertex_direction.data(), 1.)
                             : std::numeric_limits<double>::infinity();
      Trial t = backtrack(P, eps, theta, E, slope, std::min(1., step_fraction * bound), last, w, stats);
      if(!t.accepted) { stats.converged = last; break; }
      if(t.derivatives_at_trial && E - t.energy > 1.2 * predicted)   // (never on the last step)
        extrapolate(P, eps, theta, bound, w, t, stats);
      P.x.swap(w.trial);
      if(last) { stats.converged = true; break; }
      const double decrease = E - t.energy;
      if(!t.derivatives_at_trial) {
        t.energy = energy_and_free_gradient(P, P.x.data(), eps, theta, w.g_trial, &w.non_positive_at_trial);
        ++stats.evaluations;
        if(!std::isfinite(t.energy)) { stats.finite = false; break; }
      }
      if(refresh) {
        update_hessian(P, eps, theta, w.non_positive_at_trial == 0);
        if(!factorize()) { stats.finite = false; break; }
        pairs.clear();   // they corrected the previous factorization
        since_factorization = 0;
      } else {
        pairs.add(t.alpha * direction, w.g_trial - g);
      }
      E = t.energy;
      non_positive = w.non_positive_at_trial;
      g.swap(w.g_trial);
      if(decrease <= 1e-9 * std::abs(E)) { stats.converged = true; break; }
    }
    return stats;
  }

  /// The Hessian as last assembled: free unknowns only (vertex by vertex,
  /// `free_index`), lower triangle (and whole diagonal blocks).
  const Eigen::SparseMatrix<double>& hessian() const { return pattern_.matrix(); }
  int free_index(std::size_t v) const { return pattern_.free_index(v); }

  /// Energy and gradient (restricted to free unknowns) at P.x, and the PSD
  /// Hessian there (update_hessian).  `non_positive`, when given (the
  /// solver's own calls), receives the number of elements with det J <= 0;
  /// when there are none, the light elements get their barrier.
  double assemble(const Untangling_problem<d>& P, double eps, double theta, Eigen::VectorXd& g,
                  std::size_t* non_positive = nullptr)
  {
    const double F = energy_and_free_gradient(P, P.x.data(), eps, theta, g, non_positive);
    update_hessian(P, eps, theta, non_positive != nullptr && *non_positive == 0);
    return F;
  }

  /// The energy pass at x, its gradient restricted to the free unknowns.
  double energy_and_free_gradient(const Untangling_problem<d>& P, const double* x, double eps, double theta,
                                  Eigen::VectorXd& g, std::size_t* non_positive = nullptr)
  {
    vertex_gradient_.resize(P.x.size());
    const double F = energy<d>(P, x, eps, theta, vertex_gradient_.data(), non_positive);
    const Unknowns<d> unknowns = P.unknowns();
    for_each_chunk(P.number_of_vertices, vector_chunk_size, [&](std::size_t, std::size_t begin, std::size_t end) {
      for(std::size_t v = begin; v < end; ++v)
        if(unknowns.owns_unknown(v))
          g.template segment<d>(d * pattern_.free_index(v)) = unknowns.gradient_of_unknown(v, vertex_gradient_.data());
    });
    return F;
  }

  /// The PSD Hessian at P.x, as the sum of the element Hessians in the cache.
  ///
  /// An element whose Jacobian and determinant moved by less than
  /// reuse_tolerance since its Hessian was last computed (at this eps) keeps
  /// that Hessian: it is only the preconditioner, the quasi-Newton
  /// corrections and the exact gradient do the rest.  Projecting one costs a
  /// signed SVD and a 3 x 3 eigen-solve, 20 energy passes for a mesh.
  ///
  /// H then only receives the change of the elements recomputed (a fifth to
  /// a quarter of them once the map is valid, on the CuboidBlocks).  Summing
  /// every cached Hessian again (78 doubles per tetrahedron read from memory
  /// and scattered), with the energy and gradient computed element by
  /// element on the side, took 17 % of s08c's run; what is left, 8 %.  At a
  /// new eps (or theta) every element is recomputed and H summed afresh, so
  /// the changes' rounding only accumulates within one eps: 1e-13 to 3e-12
  /// of |H| after the hundreds of updates of s08c's and i02c's stage 2 (H is
  /// only the preconditioner).
  ///
  /// Colour by colour, the elements of one colour run in parallel chunks and
  /// add their Hessian blocks in place: no two share a free vertex, so no
  /// two write the same entry, and every entry receives its terms in colour
  /// order whatever the number of threads (through coloured_sum).
  ///
  /// `light_barrier`: from a valid map, light elements get a barrier in H
  /// (add_light_element_barrier).
  void update_hessian(const Untangling_problem<d>& P, double eps, double theta, bool light_barrier = false)
  {
    light_barrier = light_barrier && has_light_elements_;   // (else the same bits as without)
    pattern_.locate_blocks(P);
    auto& H = pattern_.matrix();
    const bool fresh = cache_.size() != P.elements.size() || cache_eps_ != eps || cache_theta_ != theta;
    // (a switch of the barrier changes the light elements' Hessians only: they alone are recomputed)
    const bool barrier_switched = !fresh && cache_light_barrier_ != light_barrier;
    if(fresh) {
      std::fill(H.valuePtr(), H.valuePtr() + H.nonZeros(), 0.);
      cache_.assign(P.elements.size(), Element_key());
      hessians_.resize(P.elements.size());
      cache_eps_ = eps;
      cache_theta_ = theta;
    }
    cache_light_barrier_ = light_barrier;
    const Simplex_energy<d> f{theta, eps};
    coloured_sum(P, [&](std::size_t k) {
      const auto J = jacobian(P, P.x.data(), k);
      Eigen::Matrix<double, d, d> C;
      const double D = determinant_and_cofactor<d>(J.data(), C.data());   // (as partials computes it)
      Element_key& key = cache_[k];
      const bool light = is_light(P.weights[k]);
      if(key.valid && !(barrier_switched && light) &&
         (J - key.J).squaredNorm() <= reuse_tolerance * reuse_tolerance * key.J.squaredNorm() &&
         std::abs(D - key.D) <= reuse_tolerance * std::abs(key.D))
        return 0.;
      Packed_hessian& cached = hessians_[k];
#if defined(__GNUC__)
      // (read below, after the projection: a miss there stalled the assembly)
      for(std::size_t line = 0; line < sizeof(Packed_hessian); line += 64)
        __builtin_prefetch(reinterpret_cast<const char*>(cached.data()) + line, 1);
#endif
      typename Simplex_energy<d>::Vertex_hessian M;
      Simplex_energy<d>::vertex_hessian(J, f.partials(J, true), P.gradient_operators[k], P.weights[k], M);
      if(light_barrier && light && D > 0) add_light_element_barrier(C, D, P.gradient_operators[k], M);
      Packed_hessian added;   // what H receives: M, or its change
      const bool replaces = key.valid;
      int i = 0;   // (packed_index(row, col), counted)
      for(int col = 0; col < n; ++col)
        for(int row = col; row < n; ++row, ++i) {
          CGAL_assertion(i == packed_index(row, col));
          const double now = M(row, col);
          added[i] = replaces ? now - cached[i] : now;
          cached[i] = now;
        }
      add_element_hessian(P, k, added);
      key.J = J;
      key.D = D;
      key.valid = true;
      return 0.;
    });
    if(fresh && !P.sliding.empty()) hold_normal_directions(P);
  }

private:
  /// A light element (its weight, the target's share of the volume, below
  /// light_element_share times the mean) barely enters the Hessian: its barrier, the
  /// size term theta / (2 D) weighted by w, stays flat in the quadratic model
  /// until the element is about to turn over, so the model's step turns it
  /// over and the step bound (step_fraction) stops the step there.  Given
  /// targets with tiny rest tetrahedra make many such elements (s08c of the
  /// CuboidBlocks: weights down to 1e-10 of the total, where the mean is
  /// 1.2e-4), and from a valid map nearly every step stopped at one of them,
  /// a different one each time, at 0.1 to 15 % of the model's step: stage 2
  /// crawled (235 of its 241 steps bounded, 33 of them by one element).
  /// Such an element gets, in the preconditioner only, the curvature of a
  /// barrier -log D weighted as an element of mean weight:
  /// mean_weight c~ c~^T / D^2, c~ = vec(C G^T) the gradient of D in the
  /// element's vertex coordinates.  Its determinant then shrinks by a bounded
  /// factor per step with every other light element's at once, and the
  /// energy, the gradient and hence the minimum are unchanged.
  void add_light_element_barrier(const Eigen::Matrix<double, d, d>& C, double D,
                                 const typename Simplex_energy<d>::Gradient_operator& G,
                                 typename Simplex_energy<d>::Vertex_hessian& M) const
  {
    const Eigen::Matrix<double, d, d + 1> CG = C * G.transpose();
    const double* c = CG.data();
    const double scale = mean_weight_ / (D * D);
    for(int col = 0; col < n; ++col)
      for(int row = col; row < n; ++row) M(row, col) += scale * c[row] * c[col];
  }

  /// (light_element_share: see add_light_element_barrier)
  bool is_light(double weight) const { return weight < light_element_share * mean_weight_; }

  /// The points that a step tries, and what was computed there.
  struct Step_workspace
  {
    std::vector<double> trial, further, vertex_direction;   // per vertex coordinate
    Eigen::VectorXd g_trial;                                // the gradient at trial (free unknowns)
    std::size_t non_positive_at_trial = 0;                  // elements with det J <= 0 there

    Step_workspace(std::size_t coordinates, int free_unknowns)
      : trial(coordinates), further(coordinates), vertex_direction(coordinates), g_trial(free_unknowns)
    {}
  };

  /// A step length that a line search settled on, and the energy there.
  struct Trial
  {
    double alpha = 0, energy = 0;
    bool accepted = false;
    bool derivatives_at_trial = false;   // Step_workspace::g_trial holds the gradient at the trial point
  };

  /// The step direction of the free unknowns, per vertex: A dy
  /// (Unknowns::to_vertex_step), zero on fixed vertices.
  void scatter_to_vertices(const Untangling_problem<d>& P, const Eigen::VectorXd& direction,
                           std::vector<double>& vertex_direction) const
  {
    const Unknowns<d> unknowns = P.unknowns();
    for(std::size_t v = 0; v < P.number_of_vertices; ++v) {
      const int f = pattern_.free_index(v);
      for(int c = 0; c < d; ++c) vertex_direction[d * v + c] = f >= 0 ? direction[d * f + c] : 0.;
      if(f >= 0) unknowns.to_vertex_step(v, &vertex_direction[d * v]);
    }
  }

  /// x + alpha * direction, into `to`, sliding vertices moved back onto
  /// their targets.
  static void move(const Untangling_problem<d>& P, const std::vector<double>& x, const std::vector<double>& direction,
                   double alpha, std::vector<double>& to)
  {
    to.resize(x.size());
    for(std::size_t i = 0; i < x.size(); ++i) to[i] = x[i] + alpha * direction[i];
    P.retract(to.data());
  }

  /// Armijo backtracking on F(., eps), finite everywhere for eps > 0, from
  /// the step `alpha`.  The first trial is nearly always accepted, and the
  /// next step needs the gradient there: the first trial computes both at
  /// once.  Shorter trials compute the energy alone.
  ///
  /// From a valid map the first trial stops short (step_fraction) of where
  /// the first element turns over.  Near the barrier (eps tiny: the last
  /// stages of the CuboidBlocks) the full step would turn some over on most
  /// steps, and halving back from there cost 4.4 energy passes per step, two
  /// thirds of all passes (i02c: 3,715 passes, now 971).
  Trial backtrack(const Untangling_problem<d>& P, double eps, double theta, double E, double slope, double alpha,
                  bool last, Step_workspace& w, Inner_statistics& stats)
  {
    Trial t;
    t.alpha = alpha;
    t.energy = E;
    for(int ls = 0; ls < 40 && !t.accepted; ++ls) {
      if(ls > 0) t.alpha /= 2;
      move(P, P.x, w.vertex_direction, t.alpha, w.trial);
      t.derivatives_at_trial = ls == 0 && !last;
      t.energy = t.derivatives_at_trial
                   ? energy_and_free_gradient(P, w.trial.data(), eps, theta, w.g_trial, &w.non_positive_at_trial)
                   : energy<d>(P, w.trial.data(), eps, theta);
      ++stats.evaluations;
      t.accepted = std::isfinite(t.energy) && t.energy <= E + 1e-4 * t.alpha * slope;
    }
    return t;
  }

  /// A full step that gained more than the model promised says that the
  /// model is too curved along it (projected element Hessians are, most
  /// near the barrier): go further along the same direction while the
  /// energy keeps decreasing, short of where an element turns over (`bound`).
  void extrapolate(const Untangling_problem<d>& P, double eps, double theta, double bound, Step_workspace& w,
                   Trial& t, Inner_statistics& stats)
  {
    for(int k = 0; k < max_extrapolations && 2 * t.alpha < step_fraction * bound; ++k) {
      move(P, P.x, w.vertex_direction, 2 * t.alpha, w.further);
      const double E_further = energy<d>(P, w.further.data(), eps, theta);
      ++stats.evaluations;
      if(!(E_further < t.energy)) break;
      t.alpha *= 2;
      t.energy = E_further;
      w.trial.swap(w.further);
      t.derivatives_at_trial = false;
    }
  }

  /// A Blas_call when the factorization calls BLAS, else nothing.
#ifdef CGAL_MESH_UNTANGLING_USE_CHOLMOD
  Blas_call lock_blas() const { return Blas_call(factorization_->calls_blas()); }
#else
  int lock_blas() const { return 0; }
#endif

  /// H^-1 r, H the Hessian as last factorized.
  Eigen::VectorXd solve(const Eigen::VectorXd& r) const
  {
    [[maybe_unused]] const auto lock = lock_blas();
    Eigen::VectorXd x = factorization_->solve(r);   // (evaluated here, under the lock)
#ifdef CGAL_MESH_UNTANGLING_USE_CHOLMOD
    factorization_->throw_if_out_of_memory();
#endif
    if(factorization_->info() != Eigen::Success) x.setConstant(std::numeric_limits<double>::quiet_NaN());
    return x;
  }

  /// The Newton step: H step = -g.
  /// Cholesky factorization of the Hessian as last assembled.
  bool factorize()
  {
    auto& H = pattern_.matrix();
    // A tiny diagonal shift keeps the system definite when nothing pins the
    // rigid motions (all vertices free); a failed factorization gets a larger
    // one.  The shift goes on H in place, and the diagonal is restored
    // afterwards: a shifted copy of H would double its memory.
    double* values = H.valuePtr();
    std::vector<double> diagonal(diagonal_position_.size());
    double trace = 0;
    for(std::size_t i = 0; i < diagonal.size(); ++i) trace += diagonal[i] = values[diagonal_position_[i]];
    trace /= std::max<std::size_t>(diagonal.size(), 1);
    [[maybe_unused]] const auto lock = lock_blas();
#ifdef CGAL_MESH_UNTANGLING_USE_CHOLMOD
    const bool calls_blas = factorization_->calls_blas();
    if(calls_blas && !blas_has_room(factorization_->factor_bytes())) throw std::bad_alloc();
#endif
    for(double shift = 1e-10; shift < 1e2; shift *= 100) {
      for(std::size_t i = 0; i < diagonal.size(); ++i) values[diagonal_position_[i]] = diagonal[i] + shift * trace;
      factorization_->factorize(H);
      for(std::size_t i = 0; i < diagonal.size(); ++i) values[diagonal_position_[i]] = diagonal[i];
#ifdef CGAL_MESH_UNTANGLING_USE_CHOLMOD
      factorization_->throw_if_out_of_memory();
      if(calls_blas) blas_buffer_taken() = true;
#endif
      if(factorization_->info() == Eigen::Success) return true;
    }
    return false;
  }

  /// Symbolic analysis, once per problem.
  void analyze(const Eigen::SparseMatrix<double>& H)
  {
    diagonal_position_.resize(H.cols());
    for(Eigen::Index j = 0; j < H.cols(); ++j) {
      const auto* begin = H.innerIndexPtr() + H.outerIndexPtr()[j];
      const auto* end = H.innerIndexPtr() + H.outerIndexPtr()[j + 1];
      diagonal_position_[j] = H.outerIndexPtr()[j] + (std::lower_bound(begin, end, j) - begin);
    }
    factorization_ = std::make_unique<Factorization>();
#ifdef CGAL_MESH_UNTANGLING_USE_CHOLMOD
    cholmod_common& c = factorization_->cholmod();
    // AMD alone, never METIS (CHOLMOD's default tries it when AMD's fill
    // looks bad): METIS draws on the C library's rand(), which the whole
    // process shares, so that calls at once, or any thread calling rand(),
    // changed its ordering and the result's bits (issue 27; with METIS
    // behind a lock, a thread calling rand() still changed 4 of 8 runs).
    // METIS's orderings factorize faster on large regular grids (AMD's
    // need 1.9 times its flops on a 200 x 200 square, 2.0 times on a 20^3
    // cube, whose Newton run took 1.3-1.4 times as long); on the data sets
    // CHOLMOD kept AMD's anyway (same bits).
    c.nmethods = 1;
    c.method[0].ordering = CHOLMOD_AMD;
    // Supernodal only where CHOLMOD's own test (flops per entry of L) finds
    // dense enough blocks: on the data sets' Hessians (a few thousand
    // unknowns) the simplicial LL^T is twice as fast, without BLAS calls or
    // OpenMP threads waking up; LL^T (not LDL^T) so that an indefinite
    // matrix is reported as such.
    c.supernodal = CHOLMOD_AUTO;
    c.final_ll = 1;
    // An indefinite matrix is expected (factorize() then shifts it), and
    // reported through info(): without this CHOLMOD prints a warning on
    // stdout for each such factorization, hundreds on a hard problem.
    c.print = 0;
    factorization_->analyzePattern(H);
    factorization_->throw_if_out_of_memory();
    factorization_flops_ = c.fl;
#else
    factorization_->analyzePattern(H);
#endif
  }

  /// Adds c (I - T_v) to the diagonal block of every sliding vertex v, c
  /// the mean of its tangent block's diagonal: the normal part of a step
  /// then solves c n = 0 apart from the tangent part (Sliding_vertices.h),
  /// at the scale of the tangent one.  Once per fresh H: the updates of
  /// update_hessian add element changes only.
  void hold_normal_directions(const Untangling_problem<d>& P)
  {
    using Matrix = Eigen::Matrix<double, d, d>;
    for(std::size_t s = 0; s < P.sliding.size(); ++s) {
      const int j = pattern_.free_index(P.sliding.vertex[s]);
      if(j < 0) continue;
      const Matrix& T = P.sliding.tangent[s];
      auto block = pattern_.diagonal_block(j);
      const double directions = T.trace(), curvature = block.trace();
      const double c = directions > 0.5 && curvature > 0 ? curvature / directions : 1.;
      block += c * (Matrix::Identity() - T);
    }
  }

  /// Adds the packed lower triangle of an element's vertex Hessian (see
  /// update_hessian) to H, block by block, each pulled back to the
  /// unknowns as A_a^T B A_b (Unknowns::pull_back_block).
  void add_element_hessian(const Untangling_problem<d>& P, std::size_t k, const Packed_hessian& lower)
  {
    const Unknowns<d> unknowns = P.unknowns();
    auto entry = [&lower](int row, int col) { return lower[packed_index(row, col)]; };
    Eigen::Matrix<double, d, d> block;
    for(int a = 0; a <= d; ++a)
      for(int b = 0; b <= a; ++b) {
        for(int c = 0; c < d; ++c)
          for(int r = 0; r < d; ++r)   // (a diagonal block mirrors its lower triangle)
            block(r, c) = a > b || r >= c ? entry(d * a + r, d * b + c) : entry(d * a + c, d * b + r);
        unknowns.pull_back_block(P.elements[k][a], P.elements[k][b], block);
        pattern_.add(k, a, b, block);
      }
  }

  Hessian_pattern<d> pattern_;
  std::unique_ptr<Factorization> factorization_;
  std::vector<Eigen::Index> diagonal_position_;   // of each diagonal entry in the values of H
  double factorization_flops_ = -1;
  std::vector<double> vertex_gradient_;           // the energy pass's, every vertex
  /// Where an element's Hessian was last computed (kept apart from the
  /// Hessians, which update_hessian reads only for the elements it recomputes).
  struct Element_key
  {
    Eigen::Matrix<double, d, d> J;
    double D = 0;
    bool valid = false;
  };
  std::vector<Element_key> cache_;
  std::vector<Packed_hessian> hessians_;          // per element, as in the assembled H
  double cache_eps_ = -1, cache_theta_ = -1;
  bool cache_light_barrier_ = false;
  const double mean_weight_;        // of the elements (the weights sum to 1)
  const bool has_light_elements_;   // (is_light)
  static constexpr double reuse_tolerance = 3e-2;   // (1e-3: no gain; 1e-1: no better)
};

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_SOLVERS_NEWTON_SOLVER_H
