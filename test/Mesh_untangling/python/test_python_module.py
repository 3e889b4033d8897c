# Copyright (c) 2026 Mesh_untangling contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""The Python module against the command-line tool and against bad input.

Run by ctest with PYTHONPATH at the build's python folder and, in the
environment, MU_CLI (untangle_mesh) and MU_MAKE (make_tangled_mesh).
"""
import os
import signal
import subprocess
import sys
import tempfile
import threading
import time
import unittest

import numpy as np

import mesh_untangling as mu

CLI = os.environ["MU_CLI"]
MAKE = os.environ["MU_MAKE"]
# rewrites a shared-v OBJ with seams as one v per vt (test_cli_seams uses it too)
TO_DUPLICATED_VERTICES = os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir,
                                      "obj_seams_as_duplicated_vertices.py")


def make(kind, n, amplitude, seed, path):
    subprocess.run([MAKE, kind, str(n), str(amplitude), str(seed), path], check=True, stdout=subprocess.DEVNULL)


def tangled_square(n=12):
    """An n x n grid of the unit square, two triangles a cell, the middle vertex
    pushed across its neighbours; the boundary vertex ids."""
    xs = np.linspace(0, 1, n + 1)
    x, y = np.meshgrid(xs, xs)
    vertices = np.column_stack([x.ravel(), y.ravel()])
    j, i = np.divmod(np.arange(n * n), n)
    a = j * (n + 1) + i
    b, c, d = a + 1, a + n + 2, a + n + 1
    triangles = np.empty((2 * n * n, 3), dtype=np.int64)
    triangles[0::2] = np.column_stack([a, b, c])
    triangles[1::2] = np.column_stack([a, c, d])
    middle = (n // 2) * (n + 1) + n // 2
    vertices[middle] += [3.5 / n, 2.5 / n]
    on_boundary = (vertices[:, 0] == 0) | (vertices[:, 0] == 1) | (vertices[:, 1] == 0) | (vertices[:, 1] == 1)
    return vertices, triangles, [int(v) for v in np.flatnonzero(on_boundary)]


class Samples(unittest.TestCase):
    """The README's samples: the same bits as untangle_mesh."""

    @classmethod
    def setUpClass(cls):
        cls.dir = tempfile.TemporaryDirectory()
        make("square", 40, 2, 1, os.path.join(cls.dir.name, "square.input"))
        make("cube", 8, 1.0, 1, os.path.join(cls.dir.name, "cube.input"))

    @classmethod
    def tearDownClass(cls):
        cls.dir.cleanup()

    def same_as_cli(self, name, cli_options=(), **options):
        path = os.path.join(self.dir.name, name + ".input")
        output = os.path.join(self.dir.name, name + "-cli.input")
        cli = subprocess.run([CLI, path, "-o", output, "-q", *cli_options])
        mesh = mu.read(path)
        before = mesh.vertices.copy()
        vertices, result = mu.untangle(mesh.vertices, mesh.elements, rest=mesh.rest, fixed=mesh.fixed, **options)
        self.assertEqual(cli.returncode, 0 if result.is_locally_invertible else 1)
        written = mu.read(output)
        self.assertTrue(np.array_equal(vertices, written.vertices), name + ": not the CLI's bits")
        self.assertTrue(np.array_equal(mesh.vertices, before), "the caller's array was modified")
        return mesh, vertices, result

    def test_square_same_bits_as_cli(self):
        mesh, vertices, result = self.same_as_cli("square")
        self.assertEqual(result.status, mu.Status.SUCCESS)
        self.assertEqual((result.number_of_vertices, result.number_of_elements), (1681, 3200))
        self.assertEqual(result.number_of_fixed_vertices, 160)
        self.assertGreater(result.inverted_before, 0)
        self.assertEqual(result.inverted_after, 0)
        self.assertEqual(vertices.shape, (1681, 2))
        self.assertTrue(np.array_equal(vertices[mesh.fixed], mesh.vertices[mesh.fixed]), "a fixed vertex moved")
        verdict = mu.check_local_invertibility(vertices, mesh.elements, rest=mesh.rest)
        self.assertTrue(verdict.locally_invertible)
        self.assertEqual(len(verdict.inverted_elements), 0)

    def test_cube_same_bits_as_cli(self):
        mesh, vertices, result = self.same_as_cli("cube")
        self.assertEqual(result.status, mu.Status.SUCCESS)
        self.assertEqual(result.number_of_elements, 3072)
        self.assertEqual(result.overwound_vertices_after + result.overwound_edges_after, 0)
        before = mu.check_local_invertibility(mesh.vertices, mesh.elements, rest=mesh.rest, fixed=mesh.fixed)
        self.assertEqual(before.inverted, result.inverted_before)
        self.assertEqual(len(before.inverted_elements), before.inverted)
        self.assertFalse(before)

    def test_options_reach_the_solver_as_in_the_cli(self):
        # the published scheme's solver, regular targets, a theta: the same bits as with the CLI's options
        self.same_as_cli("square", ["--solver", "lbfgs", "--targets", "regular", "--theta", "0.25"],
                         solver="lbfgs", targets="regular", theta=0.25)

    def test_stop_at_the_first_valid_map(self):
        # the same bits as the CLI's --stop first-valid, in fewer evaluations than the settled run
        mesh, vertices, result = self.same_as_cli("cube", ["--stop", "first-valid"], stop="first-valid")
        self.assertTrue(result.is_locally_invertible)
        settled = self.same_as_cli("cube")[2]
        self.assertLess(result.energy_evaluations, settled.energy_evaluations)
        with self.assertRaisesRegex(ValueError, "stop='never': expected one of"):
            mu.untangle(mesh.vertices, mesh.elements, rest=mesh.rest, stop="never")

    def test_thread_counts_give_the_same_bits(self):
        mesh = mu.read(os.path.join(self.dir.name, "cube.input"))
        one, _ = mu.untangle(mesh.vertices, mesh.elements, rest=mesh.rest, fixed=mesh.fixed, threads=1)
        two, _ = mu.untangle(mesh.vertices, mesh.elements, rest=mesh.rest, fixed=mesh.fixed, threads=2)
        self.assertTrue(np.array_equal(one, two))

    def test_out_untangles_in_place(self):
        mesh = mu.read(os.path.join(self.dir.name, "square.input"))
        expected, _ = mu.untangle(mesh.vertices, mesh.elements, rest=mesh.rest, fixed=mesh.fixed)
        vertices = mesh.vertices.copy()
        returned, result = mu.untangle(vertices, mesh.elements, rest=mesh.rest, fixed=mesh.fixed, out=vertices)
        self.assertIs(returned, vertices)
        self.assertTrue(result.is_locally_invertible)
        self.assertTrue(np.array_equal(vertices, expected))
        with self.assertRaisesRegex(ValueError, "out must have the shape of vertices"):
            mu.untangle(mesh.vertices, mesh.elements, rest=mesh.rest, out=np.zeros((3, 2)))
        with self.assertRaisesRegex(TypeError, "float64"):
            mu.untangle(mesh.vertices, mesh.elements, rest=mesh.rest, out=np.zeros(mesh.vertices.shape, np.float32))


class Callbacks(unittest.TestCase):
    def setUp(self):
        self.vertices, self.triangles, self.boundary = tangled_square()

    def test_progress_cancel_returns_the_input(self):
        fractions = []

        def progress(fraction):
            fractions.append(fraction)
            return False

        vertices, result = mu.untangle(self.vertices, self.triangles, fixed=self.boundary, progress=progress)
        self.assertEqual(result.status, mu.Status.CANCELLED)
        self.assertTrue(result.input_returned or np.array_equal(vertices, self.vertices))
        self.assertTrue(np.array_equal(vertices, self.vertices), "a cancelled run changed the map")
        self.assertEqual(fractions, [0.0])

    def test_progress_goes_up_to_one(self):
        fractions = []
        _, result = mu.untangle(self.vertices, self.triangles, fixed=self.boundary, progress=fractions.append)
        self.assertTrue(result.is_locally_invertible)
        self.assertEqual(fractions[-1], 1.0)
        self.assertEqual(fractions, sorted(fractions))

    def test_callback_sees_steps_and_can_stop(self):
        steps = []
        _, result = mu.untangle(self.vertices, self.triangles, fixed=self.boundary, theta=0.5,
                                callback=lambda s: steps.append(s) or False)
        self.assertEqual(len(steps), 1)
        self.assertIsInstance(steps[0], mu.Step)
        self.assertEqual(steps[0].step, 0)
        if not result.is_locally_invertible:
            self.assertEqual(result.status, mu.Status.STOPPED_BY_CALLBACK)

    def test_an_exception_in_a_callback_is_raised_again(self):
        def callback(step):
            raise RuntimeError("from the callback")
        with self.assertRaisesRegex(RuntimeError, "from the callback"):
            mu.untangle(self.vertices, self.triangles, fixed=self.boundary, callback=callback)

    def test_ctrl_c_raises_keyboard_interrupt(self):
        def callback(step):
            signal.raise_signal(signal.SIGINT)
        with self.assertRaises(KeyboardInterrupt):
            mu.untangle(self.vertices, self.triangles, fixed=self.boundary, callback=callback)

    def test_the_gil_is_released_during_a_run(self):
        # another Python thread runs while the untangler works
        ticks = []
        done = threading.Event()

        def tick():
            while not done.is_set():
                ticks.append(1)
                time.sleep(0.001)

        # a grid large enough that the run lasts long enough to see the other
        # thread tick, on a fast machine too: doubled until it does
        n = 150
        while True:
            ticks.clear()
            done.clear()
            vertices, triangles, boundary = tangled_square(n)
            thread = threading.Thread(target=tick)
            thread.start()
            try:
                _, result = mu.untangle(vertices, triangles, fixed=boundary, threads=1)
            finally:
                done.set()
                thread.join()
            self.assertTrue(result.is_locally_invertible)
            if result.seconds > 0.05 or n >= 1200:
                break
            n *= 2
        self.assertGreater(result.seconds, 0.05)
        self.assertGreater(len(ticks), 5, "the other thread did not run during %.2f s" % result.seconds)


class Kinds(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.dir = tempfile.TemporaryDirectory()

    @classmethod
    def tearDownClass(cls):
        cls.dir.cleanup()

    def generated(self, kind, extension):
        path = os.path.join(self.dir.name, kind + extension)
        make(kind, 6, 0.9, 3, path)
        rest = path.replace(extension, "-rest" + extension)
        return mu.read(path), (mu.read(rest).vertices if os.path.exists(rest) else None)

    def test_hexahedra(self):
        mesh, rest = self.generated("hexcube", ".vtk")
        self.assertEqual((mesh.kind, mesh.elements.shape), ("hexahedra", (216, 8)))
        vertices, result = mu.untangle(mesh.vertices, mesh.elements, rest=rest, fixed=mesh.fixed)
        self.assertTrue(result.is_locally_invertible, result.message)
        self.assertGreater(result.inverted_before, 0)
        verdict = mu.check_local_invertibility(vertices, mesh.elements, rest=rest)
        self.assertTrue(verdict)
        self.assertGreater(verdict.min_scaled_jacobian, 0)
        tangled = mu.check_local_invertibility(mesh.vertices, mesh.elements, rest=rest)
        self.assertGreater(len(tangled.inverted_cells), 0)

    def test_mixed_cells(self):
        mesh, rest = self.generated("mixedcube", ".vtk")
        self.assertEqual((mesh.kind, mesh.elements.shape), ("cells", (468, 8)))
        sizes = np.count_nonzero(mesh.elements >= 0, axis=1)
        self.assertEqual(sorted(set(sizes)), [4, 5, 6, 8])
        self.assertTrue(all((row[size:] == -1).all() for row, size in zip(mesh.elements, sizes)))
        vertices, result = mu.untangle(mesh.vertices, mesh.elements, rest=rest, fixed=mesh.fixed, kind="cells")
        self.assertTrue(result.is_locally_invertible, result.message)
        self.assertGreater(result.inverted_before, 0)
        self.assertEqual(result.number_of_elements, 468)
        self.assertTrue(np.array_equal(vertices[mesh.fixed], mesh.vertices[mesh.fixed]))
        tangled = mu.check_local_invertibility(mesh.vertices, mesh.elements, rest=rest, kind="cells")
        self.assertEqual(len(tangled.inverted_cells), result.inverted_before)
        path = os.path.join(self.dir.name, "mixed-out.mesh")
        mu.write(path, vertices, mesh.elements, kind="cells")
        again = mu.read(path)
        self.assertEqual(again.kind, "cells")
        self.assertEqual(sorted(map(tuple, again.elements)), sorted(map(tuple, mesh.elements)))

    def test_quadrilaterals(self):
        mesh, rest = self.generated("quadsquare", ".vtk")
        self.assertEqual(mesh.kind, "quadrilaterals")
        self.assertEqual(mesh.vertices.shape[1], 2)
        vertices, result = mu.untangle(mesh.vertices, mesh.elements, rest=rest, fixed=mesh.fixed)
        self.assertTrue(result.is_locally_invertible, result.message)

    def test_seamless_torus(self):
        path = os.path.join(self.dir.name, "torus.obj")
        make("torus", 6, 0.5, 1, path)
        mesh = mu.read(path)
        self.assertIsNotNone(mesh.rest_elements)
        self.assertEqual(mesh.elements.shape, mesh.rest_elements.shape)
        uv, result = mu.untangle(mesh.vertices, mesh.elements, rest=mesh.rest, rest_elements=mesh.rest_elements)
        self.assertTrue(result.is_locally_invertible, result.message)
        output = os.path.join(self.dir.name, "torus-cli.obj")
        subprocess.run([CLI, path, "-o", output, "-q"], check=True)
        self.assertTrue(np.array_equal(uv, mu.read(output).vertices))
        # the quad mesh: the CLI's, 36 quads on a 6 x 6 torus, 36 vertices
        points, quads, open_edges = mu.integer_grid_quads(uv, mesh.elements, rest=mesh.rest,
                                                          rest_elements=mesh.rest_elements)
        self.assertEqual((points.shape, quads.shape, open_edges), ((36, 3), (36, 4), 0))
        cli_quads = os.path.join(self.dir.name, "torus-quads.obj")
        subprocess.run([CLI, path, "-o", output, "--quads", cli_quads, "-q"], check=True)
        read_back = mu.read(cli_quads)
        self.assertTrue(np.array_equal(read_back.elements, quads))
        self.assertTrue(np.allclose(read_back.vertices, points, atol=1e-12))
        with self.assertRaisesRegex(mu.InvalidInputError, "no quad mesh: the transition across seam edge .* not by "
                                    "integers"):
            mu.integer_grid_quads(uv * 1.3, mesh.elements, rest=mesh.rest, rest_elements=mesh.rest_elements)
        with self.assertRaisesRegex(ValueError, "rest_elements"):
            mu.integer_grid_quads(uv, mesh.elements, rest=mesh.rest, rest_elements=None)

    def test_seams_as_duplicated_vertices(self):
        # one v per vt (a seam vertex once per chart): welded into the torus's vertices, the same arrays
        shared = os.path.join(self.dir.name, "torus.obj")
        make("torus", 6, 0.5, 1, shared)
        duplicated = os.path.join(self.dir.name, "torus-dup.obj")
        subprocess.run([sys.executable, TO_DUPLICATED_VERTICES, shared, duplicated], check=True)
        with open(shared) as f:
            vt = [l for l in f if l.startswith("vt ")]
        a, b = mu.read(shared), mu.read(duplicated)
        self.assertIsNone(a.welded_vertex_of_file_vertex)
        self.assertEqual(len(b.welded_vertex_of_file_vertex), len(vt))
        self.assertEqual(len(b.rest), len(a.rest))
        self.assertTrue(np.array_equal(a.vertices, b.vertices))
        self.assertEqual(b.welding_note, "")
        off = mu.read(duplicated, weld="off")
        self.assertIsNone(off.welded_vertex_of_file_vertex)
        self.assertIsNone(off.rest_elements)
        self.assertEqual(len(off.rest), len(vt))
        self.assertIsNotNone(mu.read(duplicated, weld=0.0).welded_vertex_of_file_vertex)
        with self.assertRaisesRegex(ValueError, "weld must be 'auto', 'off' or a distance"):
            mu.read(duplicated, weld="yes")
        with self.assertRaisesRegex(ValueError, "0 or more"):
            mu.read(duplicated, weld=-1.0)
        with self.assertRaisesRegex(TypeError, "weld must be"):
            mu.read(duplicated, weld=[1])
        with self.assertRaisesRegex(mu.ReadError, r"torus-dup.obj:\d+: face \d+: its vertices \d+ and \d+ are welded"):
            mu.read(duplicated, weld=100.0)
        # untangled and written back with the file's own v lines and faces
        uv, result = mu.untangle(b.vertices, b.elements, rest=b.rest, rest_elements=b.rest_elements)
        self.assertTrue(result.is_locally_invertible, result.message)
        out = os.path.join(self.dir.name, "torus-dup-out.obj")
        mu.write(out, uv, b.elements, rest=b.rest, rest_elements=b.rest_elements, layout=b)
        with open(duplicated) as f, open(out) as g:
            given, written = f.read().split("\n"), g.read().split("\n")
        for prefix in ("v ", "f "):
            self.assertEqual([l for l in given if l.startswith(prefix)], [l for l in written if l.startswith(prefix)])
        again = mu.read(out)
        self.assertTrue(np.array_equal(again.vertices, uv))
        shared_out = os.path.join(self.dir.name, "torus-shared-out.obj")
        mu.write(shared_out, uv, b.elements, rest=b.rest, rest_elements=b.rest_elements)
        self.assertIsNone(mu.read(shared_out).welded_vertex_of_file_vertex)
        with self.assertRaisesRegex(TypeError, "layout must be a Mesh"):
            mu.write(shared_out, uv, b.elements, rest=b.rest, rest_elements=b.rest_elements, layout=3)
        with self.assertRaisesRegex(mu.WriteError, "do not match the mesh"):
            mu.write(shared_out, uv, b.elements[::-1], rest=b.rest, rest_elements=b.rest_elements[::-1], layout=b)

    def test_free_boundary_protected_by_phantoms(self):
        vertices, triangles, _ = tangled_square()
        new, result = mu.untangle(vertices, triangles)
        self.assertTrue(result.is_locally_invertible, result.message)
        self.assertGreater(result.number_of_phantom_elements, 0)
        self.assertEqual(result.number_of_fixed_vertices, 0)

    def test_fixed_boundary_and_mask(self):
        vertices, triangles, boundary = tangled_square()
        by_name, _ = mu.untangle(vertices, triangles, fixed="boundary")
        mask = np.zeros(len(vertices), bool)
        mask[boundary] = True
        by_mask, result = mu.untangle(vertices, triangles, fixed=mask)
        self.assertTrue(np.array_equal(by_name, by_mask))
        self.assertEqual(result.number_of_fixed_vertices, len(boundary))
        self.assertTrue(np.array_equal(by_mask[boundary], vertices[boundary]))

    def test_array_likes(self):
        vertices, triangles, boundary = tangled_square(4)
        new, result = mu.untangle(vertices.tolist(), triangles.tolist(), fixed=boundary)
        self.assertTrue(result.is_locally_invertible)
        self.assertEqual(new.dtype, np.float64)
        # float32 and Fortran order are converted; 3 columns with z = 0 are a planar map
        flat = np.zeros((len(vertices), 3), np.float32, order="F")
        flat[:, :2] = vertices
        new3, _ = mu.untangle(flat, triangles.astype(np.int32), fixed=boundary)
        self.assertEqual(new3.shape, (len(vertices), 3))
        self.assertTrue(np.all(new3[:, 2] == 0))

    def test_refinement_returns_the_refined_mesh(self):
        # one free vertex inside a fixed Z-shaped octagon whose kernel is empty
        # (test_cli's Z star): no position of it untangles its eight triangles
        angles = np.arange(8) * np.pi / 4
        rest = np.vstack([[0, 0], np.column_stack([np.cos(angles), np.sin(angles)])])
        vertices = np.array([[1.5, 1.5], [1, 0], [3, 0], [3, 1], [2, 1], [2, 3], [0, 3], [0, 2], [1, 2]], float)
        triangles = np.array([[0, i, i % 8 + 1] for i in range(1, 9)])
        fixed = np.arange(1, 9)
        _, unrefined = mu.untangle(vertices, triangles, rest=rest, fixed=fixed)
        self.assertFalse(unrefined.is_locally_invertible)
        self.assertIsNone(unrefined.elements)
        refined, result = mu.untangle(vertices, triangles, rest=rest, fixed=fixed, refine=True)
        self.assertTrue(result.is_locally_invertible, result.message)
        added = result.vertices_added
        self.assertGreater(added, 0)
        self.assertEqual(refined.shape, (9 + added, 2))
        self.assertEqual(result.rest.shape, (9 + added, 2))
        self.assertEqual(result.added_parents.shape, (added, 2))
        self.assertTrue(np.array_equal(refined[fixed], vertices[fixed]))
        self.assertTrue(mu.check_local_invertibility(refined, result.elements, rest=result.rest))

    def test_optimize_quality_raises_the_worst_element(self):
        # a valid grid of triangles whose interior vertices moved at random, its
        # own rest: untangling keeps it, the quality rung improves its worst triangle
        n = 8
        x, y = np.meshgrid(np.linspace(0, 1, n + 1), np.linspace(0, 1, n + 1))
        vertices = np.column_stack([x.ravel(), y.ravel()])
        interior = (vertices > 0).all(axis=1) & (vertices < 1).all(axis=1)
        vertices[interior] += np.random.default_rng(7).uniform(-0.3 / n, 0.3 / n, (interior.sum(), 2))
        ids = np.arange((n + 1) ** 2).reshape(n + 1, n + 1)
        a, b, c, d = ids[:-1, :-1].ravel(), ids[:-1, 1:].ravel(), ids[1:, 1:].ravel(), ids[1:, :-1].ravel()
        triangles = np.vstack([np.column_stack([a, b, c]), np.column_stack([a, c, d])])
        plain, untangled = mu.untangle(vertices, triangles, rest=vertices, fixed="boundary")
        self.assertEqual(untangled.min_quality_before_optimization, -1)
        better, result = mu.untangle(vertices, triangles, rest=vertices, fixed="boundary", optimize_quality=True)
        self.assertTrue(result.is_locally_invertible, result.message)
        self.assertGreater(result.min_quality_after_optimization, result.min_quality_before_optimization + 0.05)
        self.assertTrue(np.array_equal(better[~interior], vertices[~interior]))
        self.assertTrue(mu.check_local_invertibility(better, triangles, rest=vertices))

    def test_slide_boundary_keeps_the_square(self):
        # a grid of triangles whose boundary vertices moved along the sides far
        # enough to fold boundary triangles over: fixed, it cannot be untangled;
        # sliding, it is, every side vertex still on its side, the corners held
        n = 6
        x, y = np.meshgrid(np.linspace(0, 1, n + 1), np.linspace(0, 1, n + 1))
        rest = np.column_stack([x.ravel(), y.ravel()])
        vertices = rest.copy()
        on_side = (rest == 0) | (rest == 1)
        corner = on_side.all(axis=1)
        along = np.where(on_side[:, 0], 1, 0)   # a side x = 0 or 1 slides along y, and the other way
        sides = on_side.any(axis=1) & ~corner
        shift = np.random.default_rng(3).choice([-0.9 / n, 0.9 / n], sides.sum())
        vertices[sides, along[sides]] = np.clip(vertices[sides, along[sides]] + shift, 0.1 / n, 1 - 0.1 / n)
        ids = np.arange((n + 1) ** 2).reshape(n + 1, n + 1)
        a, b, c, d = ids[:-1, :-1].ravel(), ids[:-1, 1:].ravel(), ids[1:, 1:].ravel(), ids[1:, :-1].ravel()
        triangles = np.vstack([np.column_stack([a, b, c]), np.column_stack([a, c, d])])
        _, fixed = mu.untangle(vertices, triangles, rest=rest, fixed="boundary", time_limit=10)
        self.assertFalse(fixed.is_locally_invertible)
        slid, result = mu.untangle(vertices, triangles, rest=rest, slide_boundary=True)
        self.assertTrue(result.is_locally_invertible, result.message)
        self.assertEqual((result.vertices_sliding_on_curves, result.corner_vertices_held), (4 * (n - 1), 4))
        self.assertLessEqual(result.max_distance_to_target, 1e-12)
        self.assertTrue(np.array_equal(slid[corner], vertices[corner]))
        self.assertTrue(np.all(np.abs(slid[on_side] - rest[on_side]) <= 1e-12))
        self.assertTrue(mu.check_local_invertibility(slid, triangles, rest=rest))
        with self.assertRaisesRegex(ValueError, "feature_angle"):
            mu.untangle(vertices, triangles, slide_boundary=True, feature_angle=0)

    def test_target_surface_moves_the_cube_onto_a_box(self):
        # the tangled cube's boundary fitted to a box a little stretched and
        # moved, given as the boundary of the box's tetrahedra: every face
        # vertex ends on its face of the box, every corner on its corner
        with tempfile.TemporaryDirectory() as folder:
            make("cube", 4, 0.6, 1, os.path.join(folder, "cube.vtk"))
            mesh = mu.read(os.path.join(folder, "cube.vtk"))
            rest = mu.read(os.path.join(folder, "cube-rest.vtk")).vertices
        scale, shift = np.array([1.04, 0.96, 1.02]), np.array([0.03, -0.02, 0.01])
        box = rest * scale + shift
        faces = np.array([[0, 1, 2], [0, 1, 3], [1, 2, 3], [2, 0, 3]])
        listed = np.sort(mesh.elements[:, faces].reshape(-1, 3), axis=1)
        unique, count = np.unique(listed, axis=0, return_counts=True)
        surface = (box, unique[count == 1])
        moved, result = mu.untangle(mesh.vertices, mesh.elements, rest=rest, slide_boundary=True, target_surface=surface)
        self.assertTrue(result.is_locally_invertible, result.message)
        self.assertGreater(result.boundary_moved_onto_target, 0.02)
        on_face = (rest == 0) | (rest == 1)
        self.assertTrue(np.all(np.abs(moved[on_face] - box[on_face]) <= 1e-12))
        corner = on_face.all(axis=1)
        self.assertTrue(np.array_equal(moved[corner], box[corner]))
        with self.assertRaisesRegex(ValueError, "target_surface needs slide_boundary=True"):
            mu.untangle(mesh.vertices, mesh.elements, rest=rest, target_surface=surface)
        with self.assertRaisesRegex(ValueError, "target_surface triangle 0: point 999"):
            mu.untangle(mesh.vertices, mesh.elements, rest=rest, slide_boundary=True,
                        target_surface=(box, [[0, 1, 999]]))

    def test_feature_edges_are_curves(self):
        # the tangled cube at 90 degrees (no feature by the angle), its box's
        # edges given: they are curves, the box's corners where they meet
        with tempfile.TemporaryDirectory() as folder:
            make("cube", 4, 0.6, 1, os.path.join(folder, "cube.vtk"))
            mesh = mu.read(os.path.join(folder, "cube.vtk"))
            rest = mu.read(os.path.join(folder, "cube-rest.vtk")).vertices
        pairs = mesh.elements[:, [[0, 1], [0, 2], [0, 3], [1, 2], [1, 3], [2, 3]]].reshape(-1, 2)
        on_side = (rest == 0) | (rest == 1)
        same = rest[pairs[:, 0]] == rest[pairs[:, 1]]
        box_edges = np.unique(np.sort(pairs[((on_side[pairs[:, 0]] & same).sum(axis=1) >= 2)], axis=1), axis=0)
        slid, result = mu.untangle(mesh.vertices, mesh.elements, rest=rest, slide_boundary=True, feature_angle=90,
                                   feature_edges=box_edges)
        self.assertTrue(result.is_locally_invertible, result.message)
        self.assertEqual((result.vertices_sliding_on_curves, result.corner_vertices_held, result.feature_edges_inside),
                         (36, 8, 0))
        _, plain = mu.untangle(mesh.vertices, mesh.elements, rest=rest, slide_boundary=True, feature_angle=90)
        self.assertEqual(plain.vertices_sliding_on_curves, 0)
        with self.assertRaisesRegex(ValueError, "feature_edges needs slide_boundary=True"):
            mu.untangle(mesh.vertices, mesh.elements, rest=rest, feature_edges=box_edges)
        with self.assertRaisesRegex(ValueError, "feature_edges row 1: vertex 999"):
            mu.untangle(mesh.vertices, mesh.elements, slide_boundary=True, feature_edges=[[0, 1], [2, 999]])
        with self.assertRaisesRegex(ValueError, "feature_edges must be m x 2"):
            mu.untangle(mesh.vertices, mesh.elements, slide_boundary=True, feature_edges=[[0, 1, 2]])

    def test_a_files_edges_and_corners(self):
        with tempfile.TemporaryDirectory() as folder:
            path = os.path.join(folder, "tet.mesh")
            with open(path, "w") as f:
                f.write("MeshVersionFormatted 2\nDimension 3\nVertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n"
                        "Tetrahedra\n1\n1 2 3 4 1\nEdges\n2\n1 2 1\n2 3 1\nCorners\n1\n2\nEnd\n")
            mesh = mu.read(path)
        self.assertTrue(np.array_equal(mesh.edges, [[0, 1], [1, 2]]))
        self.assertTrue(np.array_equal(mesh.corners, [1]))


class Files(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()

    def tearDown(self):
        self.dir.cleanup()

    def path(self, name):
        return os.path.join(self.dir.name, name)

    def test_round_trip_with_fields(self):
        vertices, triangles, boundary = tangled_square(4)
        mu.write(self.path("m.vtk"), vertices, triangles, fixed=boundary,
                 point_fields={"height": vertices[:, 1]}, cell_fields={"id": np.arange(len(triangles))})
        mesh = mu.read(self.path("m.vtk"))
        self.assertEqual(mesh.kind, "triangles")
        self.assertTrue(np.array_equal(mesh.vertices, vertices))
        self.assertTrue(np.array_equal(mesh.elements, triangles))
        self.assertEqual(sorted(mesh.fixed.tolist()), boundary)
        self.assertEqual(sorted(mesh.point_fields), ["height"])
        self.assertTrue(np.array_equal(mesh.point_fields["height"], vertices[:, 1]))
        self.assertEqual(mesh.cell_fields["id"].dtype, np.int64)
        self.assertTrue(np.array_equal(mesh.cell_fields["id"], np.arange(len(triangles))))

    def test_fields_of_the_cli(self):
        # the .vtk that untangle_mesh writes: its per-element and per-vertex figures
        path = self.path("square.input")
        make("square", 6, 2, 1, path)
        subprocess.run([CLI, path, "-o", self.path("out.vtk"), "-q"], check=True)
        mesh = mu.read(self.path("out.vtk"))
        self.assertEqual(mesh.cell_fields["inverted"].sum(), 0)
        self.assertEqual(len(mesh.cell_fields["det_J"]), len(mesh.elements))
        self.assertTrue(np.all(mesh.cell_fields["det_J"] > 0))
        self.assertIn("covering", mesh.point_fields)
        self.assertEqual(len(mesh.fixed), 24)
        with open(self.path("bad.vtk"), "w") as f:
            f.write("# vtk DataFile Version 3.0\nx\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 3 double\n"
                    "0 0 0 1 0 0 0 1 0\nCELLS 1 4\n3 0 1 2\nCELL_TYPES 1\n5\nCELL_DATA 1\n"
                    "SCALARS q double\nLOOKUP_TABLE default\nabc\n")
        with self.assertRaisesRegex(mu.ReadError, r"bad\.vtk:14: SCALARS 'q' value 0 is not a number"):
            mu.read(self.path("bad.vtk"))

    def test_read_errors_name_file_and_line(self):
        with open(self.path("bad.off"), "w") as f:
            f.write("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n")
        with self.assertRaisesRegex(mu.ReadError, r"bad\.off.*line 6|bad\.off:6"):
            mu.read(self.path("bad.off"))
        with self.assertRaisesRegex(mu.ReadError, "missing.vtk"):
            mu.read(self.path("missing.vtk"))
        with self.assertRaisesRegex(mu.ReadError, "supported"):
            mu.read(self.path("mesh.xyz"))

    def test_write_errors_leave_nothing(self):
        vertices, triangles, _ = tangled_square(2)
        with self.assertRaises(mu.WriteError):
            mu.write(self.path("no/such/dir/m.vtk"), vertices, triangles)
        with self.assertRaisesRegex(mu.WriteError, "tetrahedra|rest"):
            mu.write(self.path("m.input"), vertices, triangles)   # .input needs rest positions
        self.assertEqual(os.listdir(self.dir.name), [])
        with self.assertRaisesRegex(ValueError, "fields are written to .vtk"):
            mu.write(self.path("m.obj"), vertices, triangles, point_fields={"a": vertices[:, 0]})
        with self.assertRaisesRegex(ValueError, "one value per point"):
            mu.write(self.path("m.vtk"), vertices, triangles, point_fields={"a": [1, 2]})


class BadInput(unittest.TestCase):
    def setUp(self):
        self.vertices, self.triangles, self.boundary = tangled_square(3)

    def refused(self, error, pattern, *args, **kwargs):
        before = self.vertices.copy()
        with self.assertRaisesRegex(error, pattern):
            mu.untangle(*args, **kwargs)
        self.assertTrue(np.array_equal(self.vertices, before))

    def test_shapes(self):
        self.refused(ValueError, r"n x 2 or n x 3.*\(16, 4\)", np.zeros((16, 4)), self.triangles)
        self.refused(ValueError, r"n x 2 or n x 3.*\(32,\)", np.zeros(32), self.triangles)
        self.refused(ValueError, r"one row per element.*\(54,\)", self.vertices, self.triangles.ravel())
        self.refused(ValueError, "5 columns", self.vertices, np.zeros((2, 5), int))
        self.refused(ValueError, "rest has 3 vertices, vertices 16", self.vertices, self.triangles, rest=np.zeros((3, 2)))
        self.refused(ValueError, "hexahedra need n x 3", self.vertices, np.zeros((1, 8), int) + np.arange(8))
        self.refused(ValueError, "kind='tetrahedra' has 4 vertices per element", self.vertices, self.triangles,
                     kind="tetrahedra")

    def test_mixed_cells(self):
        cube = np.array([[x, y, z] for z in (0, 1) for y in (0, 1) for x in (0, 1)], float)[[0, 1, 3, 2, 4, 5, 7, 6]]
        cells = np.array([[0, 1, 2, 3, 4, 5, 6, 7], [0, 1, 2, 3, 4, -1, -1, -1]])
        self.refused(ValueError, "kind='cells' has 8 columns, but elements has 5", cube, cells[:, :5], kind="cells")
        bad = cells.copy()
        bad[1] = [0, 1, 2, -1, 4, -1, -1, -1]
        self.refused(ValueError, "cell 1 has 4 in column 4 after its ids", cube, bad, kind="cells")
        bad[1] = [0, 1, 2, 3, 4, 5, 6, -1]
        self.refused(ValueError, r"cell 1 has 7 vertex ids, not 4 \(tetrahedron\), 5 \(pyramid\)", cube, bad, kind="cells")
        bad[1] = [0, 1, 2, 3, 3, 5, -1, -1]
        self.refused(ValueError, "elements: prism 1: vertex 3 is repeated", cube, bad, kind="cells")
        self.refused(ValueError, "cells need n x 3", cube[:, :2], cells, kind="cells")

    def test_types(self):
        self.refused(TypeError, "vertices must hold real numbers", np.full((16, 2), "a"), self.triangles)
        self.refused(TypeError, "vertices must hold real numbers", self.vertices.astype(complex), self.triangles)
        self.refused(TypeError, "elements must hold integer vertex ids, not dtype float64", self.vertices,
                     self.triangles.astype(float))
        self.refused(TypeError, "vertices: not an array", [[0, 1], [2]], self.triangles)
        self.refused(TypeError, "fixed must be a boolean mask or integer vertex ids", self.vertices, self.triangles,
                     fixed=[0.5])

    def test_values(self):
        nan = self.vertices.copy()
        nan[7, 1] = np.nan
        self.refused(ValueError, "coordinate 1 of vertex 7 is not finite", nan, self.triangles)
        bad = self.triangles.copy()
        bad[5, 2] = 16
        self.refused(ValueError, r"triangle 5: vertex index 16 is out of range \[0, 15\]", self.vertices, bad)
        bad[5, 2] = -1
        self.refused(ValueError, "triangle 5 has the vertex id -1", self.vertices, bad)
        bad[5, 2] = bad[5, 0]
        self.refused(ValueError, "triangle 5: vertex .* is repeated", self.vertices, bad)
        self.refused(ValueError, r"fixed: vertex id 99 is out of range \[0, 15\]", self.vertices, self.triangles,
                     fixed=[99])
        self.refused(ValueError, "mask of 3 flags, but there are 16", self.vertices, self.triangles,
                     fixed=[True, False, True])
        self.refused(ValueError, "fixed='all'", self.vertices, self.triangles, fixed="all")
        lifted = np.zeros((16, 3))
        lifted[:, :2] = self.vertices
        lifted[3, 2] = 1
        self.refused(mu.InvalidInputError, "vertex 3 of the map has z", lifted, self.triangles)

    def test_options(self):
        args = (self.vertices, self.triangles)
        self.refused(ValueError, "solver='fast': expected one of 'auto', 'newton', 'lbfgs'", *args, solver="fast")
        self.refused(ValueError, "continuation='sometimes'", *args, continuation="sometimes")
        self.refused(ValueError, "targets='ideal'", *args, targets="ideal")
        self.refused(ValueError, r"theta must be in \[0, 1\]", *args, theta=2)
        self.refused(ValueError, "theta must be in", *args, theta=float("nan"))
        self.refused(ValueError, "feature_angle must be in", *args, slide_boundary=True, feature_angle=float("nan"))
        self.refused(ValueError, "threads must be 1 or more, not 0", *args, threads=0)
        self.refused(ValueError, "max_iterations must be 1 or more", *args, max_iterations=-3)
        self.refused(ValueError, "time_limit must be a number of seconds", *args, time_limit=-1)
        self.refused(ValueError, "refine=True splits the edges of simplices.*quadrilaterals",
                     np.zeros((4, 2)), [[0, 1, 2, 3]], refine=True)
        self.refused(TypeError, "kind must be a string", *args, kind=3)
        self.refused(TypeError, r"threads must be a whole number, not 1.5 \(float\)", *args, threads=1.5)
        self.refused(TypeError, r"theta must be a number, not 'a' \(str\)", *args, theta="a")
        self.refused(TypeError, "time_limit must be a number of seconds, not 'x'", *args, time_limit="x")
        self.refused(TypeError, "max_iterations must be a whole number, not", *args, max_iterations=[3])

    def test_invalid_problem_names_the_defect(self):
        # two triangles sharing an edge the same way round: not an orientable surface
        vertices = np.array([[0., 0.], [1., 0.], [0., 1.], [1., 1.]])
        with self.assertRaises(mu.InvalidInputError) as caught:
            mu.untangle(vertices, [[0, 1, 2], [0, 1, 3], [0, 1, 2]])
        self.assertIsInstance(caught.exception, ValueError)
        self.assertEqual(str(caught.exception), "elements 0 and 2 have the same vertices")


class Documentation(unittest.TestCase):
    def test_every_parameter_is_documented(self):
        import inspect
        for function in (mu.untangle, mu.check_local_invertibility, mu.read, mu.write,
                         mu.project_on_best_fit_plane, mu.integer_grid_quads):
            for name in inspect.signature(function).parameters:
                self.assertIn(name, function.__doc__, "%s: %s is not documented" % (function.__name__, name))

    def test_stub_matches_the_module(self):
        stub = os.path.join(os.path.dirname(mu.__file__), "__init__.pyi")
        with open(stub) as f:
            text = f.read()
        for name in mu.__all__:
            self.assertRegex(text, r"(def|class) %s\b|%s:" % (name, name), name + " is not in the stub")
        for field in dir(mu.Result):
            if not field.startswith("_"):
                self.assertIn("    %s:" % field, text, "Result." + field + " is not in the stub")


if __name__ == "__main__":
    unittest.main()
