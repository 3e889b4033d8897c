# Type stubs of the Python module mesh_untangling.
from enum import Enum
from os import PathLike
from typing import Callable, Literal, Mapping, Optional, Tuple, Union

import numpy as np
import numpy.typing as npt

__version__: str

Kind = Literal["triangles", "tetrahedra", "quadrilaterals", "hexahedra", "cells"]
ArrayLike = npt.ArrayLike
Path = Union[str, PathLike]

class InvalidInputError(ValueError): ...
class ReadError(OSError): ...
class WriteError(OSError): ...

class Status(Enum):
    SUCCESS: int
    INVERTED_ELEMENTS_LEFT: int
    COVERINGS_LEFT: int
    TIME_LIMIT_REACHED: int
    STOPPED_BY_CALLBACK: int
    NUMERICAL_FAILURE: int
    INVALID_INPUT: int
    UNREPAIRABLE_DEFECTS_LEFT: int
    CANCELLED: int

class Step:
    step: int
    epsilon: float
    energy_before: float
    energy: float
    min_det: float
    non_positive: int
    inner_iterations: int
    energy_evaluations: int
    seconds: float
    stage: int
    motion: float

class Result:
    status: Status
    status_text: str
    message: str
    is_locally_invertible: bool
    number_of_vertices: int
    number_of_elements: int
    number_of_fixed_vertices: int
    degenerate_targets_replaced: int
    number_of_phantom_elements: int
    number_of_phantom_vertices: int
    incomplete_phantom_stars: int
    vertices_added: int
    inverted_before: int
    inverted_after: int
    overwound_vertices_after: int
    overwound_edges_after: int
    input_defects: int
    input_defect_stars: int
    input_returned: bool
    min_scaled_det_before: float
    min_scaled_det_after: float
    min_quality_before_optimization: float
    min_quality_after_optimization: float
    vertices_sliding_on_surfaces: int
    vertices_sliding_on_curves: int
    corner_vertices_held: int
    sliding_rounds: int
    max_distance_to_target: float
    boundary_moved_onto_target: float
    feature_edges_inside: int
    max_shape_distortion: float
    mean_shape_distortion: float
    max_volume_distortion: float
    mean_volume_distortion: float
    final_energy: float
    final_epsilon: float
    continuation_steps: int
    continuation_motion: float
    started_from_rest: bool
    outer_iterations: int
    inner_iterations: int
    energy_evaluations: int
    seconds: float
    solver: str
    elements: Optional[npt.NDArray[np.int64]]
    rest: Optional[npt.NDArray[np.float64]]
    added_parents: Optional[npt.NDArray[np.int64]]

class Verdict:
    locally_invertible: bool
    no_repairable_defect: bool
    inverted: int
    overwound_vertices: int
    overwound_edges: int
    input_defects: int
    input_defect_stars: int
    non_manifold: int
    overwound_interior_vertices: int
    overwound_boundary_vertices: int
    overwound_interior_edges: int
    overwound_boundary_edges: int
    min_covering: float
    max_covering: float
    max_boundary_covering: float
    min_scaled_jacobian: float
    inverted_elements: npt.NDArray[np.int64]
    inverted_cells: npt.NDArray[np.int64]
    overwound_vertex_ids: npt.NDArray[np.int64]
    coverings: npt.NDArray[np.float64]
    overwound_edge_ids: npt.NDArray[np.int64]
    def __bool__(self) -> bool: ...

class Mesh:
    kind: Kind
    vertices: npt.NDArray[np.float64]
    elements: npt.NDArray[np.int64]
    rest: Optional[npt.NDArray[np.float64]]
    rest_elements: Optional[npt.NDArray[np.int64]]
    fixed: Optional[npt.NDArray[np.int64]]
    edges: Optional[npt.NDArray[np.int64]]
    corners: Optional[npt.NDArray[np.int64]]
    point_fields: dict[str, npt.NDArray]
    cell_fields: dict[str, npt.NDArray]
    welded_vertex_of_file_vertex: Optional[npt.NDArray[np.int64]]
    file_vertices: Optional[npt.NDArray[np.float64]]
    file_elements: Optional[npt.NDArray[np.int64]]
    welding_note: str

Fixed = Union[None, Literal["boundary"], ArrayLike]

def untangle(vertices: ArrayLike, elements: ArrayLike, *, rest: Optional[ArrayLike] = None, fixed: Fixed = None,
             targets: Optional[Literal["rest", "regular"]] = None, theta: Optional[float] = None,
             solver: Literal["auto", "newton", "lbfgs"] = "auto", phantoms: bool = True,
             continuation: Literal["auto", "never", "always"] = "auto", continuation_steps: Optional[int] = None,
             max_iterations: Optional[int] = None, time_limit: Optional[float] = None, threads: Optional[int] = None,
             progress: Optional[Callable[[float], Optional[bool]]] = None,
             callback: Optional[Callable[[Step], Optional[bool]]] = None, refine: bool = False,
             refine_budget: Optional[int] = None, optimize_quality: bool = False, slide_boundary: bool = False,
             feature_angle: float = 35.0, feature_edges: Optional[ArrayLike] = None,
             target_surface: Optional[Tuple[ArrayLike, ArrayLike]] = None,
             kind: Optional[Kind] = None,
             rest_elements: Optional[ArrayLike] = None, seam_translations: Literal["keep", "free"] = "keep",
             out: Optional[npt.NDArray[np.float64]] = None) -> Tuple[npt.NDArray[np.float64], Result]: ...
def check_local_invertibility(vertices: ArrayLike, elements: ArrayLike, *, rest: Optional[ArrayLike] = None,
                              fixed: Fixed = None, kind: Optional[Kind] = None,
                              rest_elements: Optional[ArrayLike] = None) -> Verdict: ...
def read(path: Path, *, weld: Union[Literal["auto", "off"], float] = "auto") -> Mesh: ...
def write(path: Path, vertices: ArrayLike, elements: ArrayLike, *, rest: Optional[ArrayLike] = None, fixed: Fixed = None,
          kind: Optional[Kind] = None, rest_elements: Optional[ArrayLike] = None,
          point_fields: Optional[Mapping[str, ArrayLike]] = None,
          cell_fields: Optional[Mapping[str, ArrayLike]] = None, layout: Optional[Mesh] = None) -> None: ...
def project_on_best_fit_plane(vertices: ArrayLike, triangles: ArrayLike) -> npt.NDArray[np.float64]: ...
def integer_grid_quads(vertices: ArrayLike, elements: ArrayLike, *, rest: ArrayLike,
                       rest_elements: ArrayLike) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.int64], int]: ...
