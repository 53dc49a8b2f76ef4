"""Type stub of the `obscura` module (the C++ extension obscura._obscura): what editors complete.
The docstrings on the module's functions say what each argument means; docs/python.md shows them
in use."""

from typing import Any, Callable, Iterable, Iterator, Literal, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

__version__: str

FloatArray = npt.NDArray[np.floating]
ArrayLike = Union[FloatArray, Sequence[float], Sequence[Sequence[float]]]
Vec3 = Tuple[float, float, float]

class Error(RuntimeError):
    """An error reported by Obscura: where (file and line, JSON path, field or option) and what
    was expected."""

class RenderInterrupted(KeyboardInterrupt):
    """Ctrl-C during render(): the image and AOVs rendered so far."""
    image: npt.NDArray[np.float32]
    aovs: dict[str, npt.NDArray[np.float32]]
    result: RenderResult

class Camera:
    """A camera: projection, pose, clipping, lens, shutter, exposure and film."""
    name: str
    width: int
    height: int
    near: float
    far: float
    exposure_ev: float
    exposure_mode: Literal["radiance", "physical"]
    iso: float
    shutter: Tuple[float, float]
    world_from_camera: npt.NDArray[np.float64]
    def __init__(self) -> None: ...
    @staticmethod
    def perspective(fov: Optional[float] = None, horizontal_fov: Optional[float] = None,
                    focal_length_mm: float = 50.0, sensor_mm: Tuple[float, float] = (36, 24),
                    sensor_fit: Literal["auto", "horizontal", "vertical"] = "auto",
                    lens_shift: Tuple[float, float] = (0, 0), f_number: float = 8.0,
                    focus_distance: Optional[float] = None, focus_breathing: bool = True,
                    width: int = 512, height: int = 512, position: Optional[Vec3] = None,
                    look_at: Optional[Vec3] = None, up: Vec3 = (0, 1, 0),
                    near: Optional[float] = None, far: Optional[float] = None,
                    exposure_ev: float = 0.0) -> Camera: ...
    @staticmethod
    def thin_lens(focus_distance: float, f_number: float = 2.8, focal_length_mm: float = 50.0,
                  sensor_mm: Tuple[float, float] = (36, 24), focus_breathing: bool = True,
                  width: int = 512, height: int = 512, position: Optional[Vec3] = None,
                  look_at: Optional[Vec3] = None, up: Vec3 = (0, 1, 0),
                  near: Optional[float] = None, far: Optional[float] = None,
                  exposure_ev: float = 0.0) -> Camera: ...
    @staticmethod
    def orthographic(view_height: float = 2.0, view_width: Optional[float] = None,
                     width: int = 512, height: int = 512, position: Optional[Vec3] = None,
                     look_at: Optional[Vec3] = None, up: Vec3 = (0, 1, 0),
                     near: Optional[float] = None, far: Optional[float] = None,
                     exposure_ev: float = 0.0) -> Camera: ...
    @staticmethod
    def spherical(width: int = 512, height: int = 512, position: Optional[Vec3] = None,
                  look_at: Optional[Vec3] = None, up: Vec3 = (0, 1, 0),
                  near: Optional[float] = None, far: Optional[float] = None,
                  exposure_ev: float = 0.0) -> Camera: ...
    @staticmethod
    def fisheye(fov: float = 180.0, width: int = 512, height: int = 512,
                position: Optional[Vec3] = None, look_at: Optional[Vec3] = None,
                up: Vec3 = (0, 1, 0), near: Optional[float] = None,
                far: Optional[float] = None, exposure_ev: float = 0.0) -> Camera: ...
    @staticmethod
    def calibrated(K: ArrayLike, distortion: str = "none",
                   coefficients: Sequence[float] = (),
                   calibration_size: Optional[Tuple[int, int]] = None,
                   max_field_angle: float = 0.0, width: int = 512, height: int = 512,
                   position: Optional[Vec3] = None, look_at: Optional[Vec3] = None,
                   up: Vec3 = (0, 1, 0), near: Optional[float] = None,
                   far: Optional[float] = None, exposure_ev: float = 0.0) -> Camera: ...
    @staticmethod
    def from_intrinsics(K: ArrayLike, width: int, height: int,
                        sensor_width_mm: float = 36.0) -> Camera: ...
    @staticmethod
    def from_calibration_file(path: str, image: str = "") -> Camera: ...
    @property
    def projection(self) -> Literal["perspective", "orthographic", "spherical", "fisheye",
                                    "calibrated"]: ...
    @property
    def fov_degrees(self) -> Tuple[float, float]: ...
    @property
    def focal_length_mm(self) -> float: ...
    @property
    def f_number(self) -> float: ...
    @property
    def lens_radius_m(self) -> float: ...
    @property
    def exposure_scale(self) -> float: ...
    @property
    def K(self) -> npt.NDArray[np.float64]: ...
    def project(self, points: ArrayLike, time: float = 0.0
                ) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]: ...
    def unproject(self, film: ArrayLike, depth: ArrayLike,
                  time: float = 0.0) -> npt.NDArray[np.float64]: ...
    def look_at(self, position: Vec3, target: Vec3, up: Vec3 = (0, 1, 0)) -> None: ...
    def set_motion(self, keys: Sequence[Tuple[float, ArrayLike]]) -> None: ...
    @property
    def motion(self) -> list[Tuple[float, npt.NDArray[np.float64]]]: ...
    def export(self, format: Literal["opencv-yaml", "opencv-json", "colmap", "nerf"],
               path: Optional[str] = None) -> Optional[str]: ...
    def validate(self) -> None: ...

class Scene:
    """Meshes placed by instances, materials, lights, an environment and cameras."""
    name: str
    camera: Camera
    @property
    def cameras(self) -> list[Camera]: ...
    @property
    def warnings(self) -> list[str]: ...
    @property
    def material_variants(self) -> list[str]: ...
    def __init__(self) -> None: ...
    def camera_named(self, name: str) -> Camera: ...
    def stats(self) -> dict[str, int]: ...
    def bounds(self) -> Tuple[Vec3, Vec3]: ...
    def validate(self) -> None: ...
    def select_variant(self, name: str) -> None: ...
    def add_material(self, kind: Literal["diffuse", "metallic-roughness", "conductor",
                                         "dielectric", "emissive"] = "diffuse",
                     color: Vec3 = (0.8, 0.8, 0.8), emission: Vec3 = (0, 0, 0),
                     roughness: float = 0.5, metallic: float = 0.0, ior: float = 1.5,
                     name: str = "") -> int: ...
    @property
    def instance_count(self) -> int: ...
    def set_motion(self, instance: int, keys: Sequence[Tuple[float, ArrayLike]]) -> None: ...
    def motion(self, instance: int) -> list[Tuple[float, npt.NDArray[np.float64]]]: ...
    def add_mesh(self, positions: ArrayLike, indices: npt.NDArray[np.integer],
                 normals: Optional[ArrayLike] = None, uvs: Optional[ArrayLike] = None,
                 material: int = 0, transform: Optional[ArrayLike] = None,
                 name: str = "") -> int: ...
    def add_point_light(self, position: Vec3, intensity: Vec3 = (1, 1, 1),
                        name: str = "") -> None: ...
    def add_spot_light(self, position: Vec3, direction: Vec3, intensity: Vec3 = (1, 1, 1),
                       inner_cone: float = 0.0, outer_cone: float = 0.7853981633974483,
                       name: str = "") -> None: ...
    def add_directional_light(self, direction: Vec3, irradiance: Vec3 = (1, 1, 1),
                              name: str = "") -> None: ...
    def set_environment(self, color: Vec3 = (1, 1, 1), intensity: float = 1.0,
                        file: Optional[str] = None) -> None: ...

class RenderResult:
    """What render() returns."""
    @property
    def image(self) -> npt.NDArray[np.float32]: ...
    @property
    def aovs(self) -> dict[str, npt.NDArray[np.float32]]: ...
    @property
    def seconds(self) -> float: ...
    @property
    def rays(self) -> float: ...
    @property
    def samples_per_pixel(self) -> int: ...
    @property
    def requested(self) -> int: ...
    @property
    def cancelled(self) -> bool: ...
    @property
    def time_limited(self) -> bool: ...
    @property
    def partial(self) -> bool: ...
    @property
    def warnings(self) -> list[str]: ...

def builtin_scenes() -> list[Tuple[str, str]]: ...
def load_scene(name_or_path: str = "", environment: str = "auto",
               environment_intensity: float = 1.0, gltf_scene: str = "",
               gltf_animation: str = "", time: Optional[float] = None,
               variant: str = "", shutter: Optional[str] = None) -> Scene: ...
class RenderSession:
    def __init__(self, scene: Scene) -> None: ...
    @property
    def scene(self) -> Scene: ...
    @property
    def compilations(self) -> int: ...
    @property
    def updates(self) -> int: ...
    def pose(self, time: float, shutter: Optional[str] = None) -> None: ...
def render(scene: Union[Scene, RenderSession], camera: Optional[Camera] = None, *,
           renderer: Literal["path", "whitted", "direct", "raster"] = "path",
           spp: Optional[int] = None,
           aovs: Sequence[Literal["albedo", "normal", "depth", "range", "id"]] = (), threads: int = 0,
           seed: Optional[int] = None, sampler: Literal["sobol", "independent"] = "sobol",
           max_depth: int = 0, time_limit: float = 0.0,
           progress: Optional[Callable[[int, int], object]] = None, msaa: Literal[1, 4, 8] = 1,
           shading: Literal["flat", "gouraud", "phong", "blinn-phong"] = "phong",
           cull: bool = False, wireframe: bool = False, shadow_map: int = 1024,
           raster_dof: Literal["off", "accumulate", "post"] = "accumulate",
           raster_samples: int = 32, spectral: Optional[bool] = None, glare: bool = False,
           glare_strength: Optional[float] = None, glare_radius: Optional[int] = None,
           flare: Optional[bool] = None) -> RenderResult: ...
def resolve_camera(scene: Scene, *, camera: Optional[str] = None, width: Optional[int] = None,
                   height: Optional[int] = None, projection: Optional[str] = None,
                   fov: Optional[float] = None, hfov: Optional[float] = None,
                   focal_length: Optional[float] = None, sensor: Optional[str] = None,
                   sensor_fit: Optional[str] = None, view_height: Optional[float] = None,
                   fstop: Optional[float] = None, focus_distance: Optional[float] = None,
                   aperture_blades: Optional[int] = None,
                   aperture_rotation: Optional[float] = None,
                   focus_breathing: Optional[bool] = None, natural_vignetting: bool = False,
                   lens_barrel: Optional[str] = None, shutter: Optional[str] = None,
                   rolling_shutter: Optional[str] = None, iso: Optional[float] = None,
                   exposure: Optional[float] = None, exposure_mode: Optional[str] = None,
                   crop: Optional[str] = None, filter: Optional[str] = None,
                   filter_radius: Optional[float] = None, near: Optional[float] = None,
                   far: Optional[float] = None, intrinsics: Optional[str] = None,
                   calibration_size: Optional[str] = None, distortion: Optional[str] = None,
                   max_field_angle: Optional[float] = None, calibration: Optional[str] = None,
                   calibration_image: Optional[str] = None, lens: Optional[str] = None,
                   lens_file: Optional[str] = None,
                   lens_coating: Optional[str] = None, time: Optional[float] = None,
                   position: Optional[Sequence[float]] = None,
                   look_at: Optional[Sequence[float]] = None,
                   up: Optional[Sequence[float]] = None) -> Camera: ...
def render_dataset(scene: Scene, views: str, output: str, *, camera: Optional[Camera] = None,
                   renderer: Literal["path", "whitted", "direct", "raster"] = "path",
                   spp: Optional[int] = None, seed: Optional[int] = None,
                   ground_truth: bool = False, aovs: bool = False, image_format: str = "png",
                   formats: Sequence[str] = ("colmap", "nerf", "opencv")) -> dict[str, Any]: ...
def render_frames(scene: str, frames: Iterable[int], *, fps: float = 24.0,
                  camera: Optional[dict[str, Any]] = None, load: Optional[dict[str, Any]] = None,
                  **render_options: Any) -> Iterator[Tuple[int, RenderResult]]: ...
def ground_truth(scene: Scene, camera: Optional[Camera] = None, *,
                 renderer: Literal["path", "whitted", "direct", "raster"] = "path",
                 flow_times: Optional[Tuple[float, float]] = None
                 ) -> dict[str, Union[npt.NDArray[np.float32], Tuple[float, float]]]: ...
def color_spaces() -> list[str]: ...
def convert(values: ArrayLike, from_space: str, to_space: str) -> FloatArray: ...
def develop(pixels: npt.NDArray[np.float32], *, exposure: float = 0.0,
            tonemap: Literal["none", "clamp", "reinhard", "aces", "hable"] = "clamp",
            reinhard_white: float = 4.0,
            display: Literal["srgb", "display-p3", "rec2020-pq"] = "srgb",
            gamut: Literal["clip", "compress"] = "clip", bits: int = 8,
            dither: Literal["none", "bayer", "blue-noise"] = "none"
            ) -> Union[npt.NDArray[np.uint8], npt.NDArray[np.uint16]]: ...
def wavelength_xyz(nm: Union[float, ArrayLike]) -> npt.NDArray[np.float64]: ...
def wavelength_lms(nm: Union[float, ArrayLike]) -> npt.NDArray[np.float64]: ...
def blackbody_xyz(kelvin: Union[float, ArrayLike]) -> npt.NDArray[np.float64]: ...
def chromaticity(xyz: ArrayLike) -> npt.NDArray[np.float64]: ...
def planck_radiance(nm: float, kelvin: float) -> float: ...
def read_image(path: str) -> npt.NDArray[np.float32]: ...
def read_exr(path: str) -> Tuple[npt.NDArray[np.float32], list[str], dict[str, str]]: ...
def write_image(path: str, pixels: ArrayLike, *, exposure: float = 0.0, tonemap: str = "clamp",
                reinhard_white: float = 4.0, display: str = "srgb", gamut: str = "clip",
                bits: int = 8, dither: str = "none") -> None: ...

# The raw sensor (docs/sensor.md): `sensor` is a dict of the JSON camera's sensor fields.
def capture_raw(film: ArrayLike, camera: Camera, sensor: Optional[dict[str, Any]] = None,
                seed: int = 0) -> dict[str, Any]: ...
def develop_raw(film: ArrayLike, camera: Camera, sensor: Optional[dict[str, Any]] = None,
                seed: int = 0, demosaic: str = "malvar") -> npt.NDArray[np.float32]: ...
def write_dng(path: str, film: ArrayLike, camera: Camera, sensor: Optional[dict[str, Any]] = None,
              seed: int = 0, linear: bool = False, demosaic: str = "malvar",
              ground_truth: bool = True) -> list[str]: ...
def meter(film: ArrayLike, mode: str = "average") -> float: ...
