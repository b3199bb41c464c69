"""The moving sea of the display model: a height field that follows the waves around the boat.

With a sea state (:class:`~sailmujoco.options.WaveConfig`, ``hs > 0``) the display model's
flat ``sea_surface`` plane gives way to

* a MuJoCo height field (``sea_waves``: visual only, ``contype = conaffinity = 0``, the group
  and material of the sea) of half-size L around a centre that follows the boat, its heights
  set each frame from :func:`~sailmujoco.forces.waves.elevation` at its grid points
  (:func:`grid_elevation`), and
* four flat planes (``sea_far_*``) framing it: the still sea out to the horizon;
* a low sun over the bearing the waves come from, a dimmer headlight, a more opaque surface and
  a fainter texture (:func:`light_the_sea`, :func:`paint_the_sea`): the slopes, lit on the side
  facing the waves' origin and dark behind, show the crests and troughs in a still.

The centre moves in whole texture tiles (:data:`~sailmujoco.video.water.TILE_HULLS` hull
lengths, the nearest tile corner to the boat), so the sea's texture stays fixed to the world
and shows the boat's speed. L is the larger of :data:`HULLS` hull lengths and
:data:`WAVELENGTHS` peak wavelengths lambda_p = g Tp^2/(2 pi), rounded up to whole tiles; the
grid has at most :data:`MAX_SAMPLES` points a side (spacing dx = 2 L/(n - 1)), so waves longer
than 8 dx have at least 8 samples each. The outermost tile is faded to still water
(w = (1 - cos(pi s))/2, s the distance from the frame's edge in tiles, clipped to [0, 1]): there
the height field meets the flat planes without a step. Inside it the heights are exactly
``elevation``.

Storage: MuJoCo draws a height field point at z = z_geom + size[2] h, h in [0, 1]. With
A = sum_i a_i (no elevation reaches beyond it, the ramp being at most 1) the geom sits at
z = -A and size[2] = 2 A, so h = (w eta + A)/(2 A) and eta = 2 A h - A.

Without a sea (None or ``hs = 0``) nothing here is added: the display model is the flat sea.
"""

from __future__ import annotations

import math

import numpy as np

from .. import constants as c
from ..forces.waves import components, ramp

HULLS = 6.0  # half-size of the height field: at least this many hull lengths ...
WAVELENGTHS = 1.5  # ... and this many peak wavelengths (3 wavelengths across)
MAX_SAMPLES = 129  # grid points along each side, at most
SUN_ELEVATION_DEG = 10.0  # deg, the sun over the horizon where the waves come from ...
SUN_DIFFUSE = 2.4  # ... and its diffuse intensity: the slopes facing it are lit, their backs not
HEADLIGHT = (0.25, 0.45)  # the camera's light with a sea: ambient, diffuse (calm water: 0.35, 0.6)
TEXTURE_GAIN = 1.6  # the sea's texture brighter by this and its material darker by as much
SEA_ALPHA = 0.8  # opacity of the moving surface (calm water: water.SEA_ALPHA)
TEXTURE_CONTRAST = 0.35  # the wave texture's contrast on a sea: the drawn waves carry the picture
FAR = 2000.0  # m, half-size of the still sea around the height field, as the scene's plane
HFIELD, GEOM = "sea_waves", "sea_waves"
FAR_GEOMS = ("sea_far_north", "sea_far_south", "sea_far_east", "sea_far_west")


def has_sea(config) -> bool:
    """Whether ``config`` is a sea to draw (a ``WaveConfig`` with ``hs > 0``).

    Parameters
    ----------
    config : WaveConfig or None
        The sea state.
    """
    return config is not None and config.hs > 0.0


class SeaLayout:
    """The height field's size and grid for a sea and a boat.

    Parameters
    ----------
    config : WaveConfig
        The sea state (``hs > 0``).
    hull_length : float
        The boat's hull length, m.

    Attributes
    ----------
    tile : float
        Texture tile, m: the step in which the centre moves.
    half : float
        Half-size L of the height field, m (whole tiles).
    n : int
        Grid points along each side.
    dx : float
        Grid spacing, m.
    amplitude : float
        A = sum of the components' amplitudes, m: the bound of the elevation.
    """

    def __init__(self, config, hull_length: float):
        from .water import TILE_HULLS

        self.tile = TILE_HULLS * float(hull_length)
        wavelength = c.GRAVITY * config.tp**2 / (2.0 * math.pi)
        tiles = max(2, math.ceil(max(HULLS * hull_length, WAVELENGTHS * wavelength) / self.tile))
        self.half = tiles * self.tile
        per_tile = (MAX_SAMPLES - 1) // (2 * tiles)
        self.n = 2 * tiles * per_tile + 1
        self.dx = 2.0 * self.half / (self.n - 1)
        self.amplitude = float(np.sum(components(config).amplitude))

    def far_sizes(self) -> list[tuple[float, float]]:
        """Half-sizes (m) of the still sea's planes, north, south, east, west of the height field."""
        across = 0.5 * (FAR - self.half)
        return [(FAR, across), (FAR, across), (across, self.half), (across, self.half)]

    def far_offsets(self) -> list[tuple[float, float]]:
        """Centres (m) of the still sea's planes from the height field's centre, as :meth:`far_sizes`."""
        mid = 0.5 * (FAR + self.half)
        return [(0.0, mid), (0.0, -mid), (mid, 0.0), (-mid, 0.0)]


def add_sea_surface(spec, layout: SeaLayout) -> None:
    """Replace the scene's flat ``sea_surface`` by the height field and the still sea around it.

    Parameters
    ----------
    spec : mujoco.MjSpec
        The display scene (never the simulated one).
    layout : SeaLayout
        The height field's size and grid.
    """
    import mujoco

    plane = spec.geom("sea_surface")
    material, group = plane.material, plane.group
    spec.delete(plane)
    a = layout.amplitude
    spec.add_hfield(name=HFIELD, nrow=layout.n, ncol=layout.n,
                    size=[layout.half, layout.half, 2.0 * a, 0.1 * a],
                    userdata=[0.5] * (layout.n * layout.n))
    kind = dict(contype=0, conaffinity=0, group=group, material=material)
    spec.worldbody.add_geom(name=GEOM, type=mujoco.mjtGeom.mjGEOM_HFIELD, hfieldname=HFIELD,
                            pos=[0.0, 0.0, -a], **kind)
    # the GL context draws a plane at its compiled size: the sizes are final here
    for name, size in zip(FAR_GEOMS, layout.far_sizes(), strict=True):
        spec.worldbody.add_geom(name=name, type=mujoco.mjtGeom.mjGEOM_PLANE, size=[*size, 1.0], **kind)


def grid_elevation(config, time: float, xs, ys) -> np.ndarray:
    """The elevation (m) at ``time`` on the grid of columns ``xs`` by rows ``ys``, (len(ys), len(xs)).

    :func:`~sailmujoco.forces.waves.elevation` at every grid point, summed as a product of
    matrices: with theta_i = k_i (x cos beta_i + y sin beta_i) - omega_i t + phi_i,

        eta(x_j, y_m) = r(t) Re sum_i [a_i e^(i (phi_i - omega_i t))] e^(i k_i y_m sin beta_i)
                        e^(i k_i x_j cos beta_i),

    (rows x components) @ (components x columns): n (rows + columns) exponentials instead of
    n rows x columns cosines, for the same sum.

    Parameters
    ----------
    config : WaveConfig
        The sea state.
    time : float
        Time, s.
    xs, ys : array_like
        World east of the columns and north of the rows, m.
    """
    comp = components(config)
    xs, ys = np.asarray(xs, float), np.asarray(ys, float)
    weight = comp.amplitude * np.exp(1j * (comp.phase - comp.omega * time))
    along_x = np.exp(1j * np.outer(comp.k * np.cos(comp.direction_to), xs))  # components x columns
    along_y = np.exp(1j * np.outer(ys, comp.k * np.sin(comp.direction_to)))  # rows x components
    return float(ramp(config, time)) * ((along_y * weight) @ along_x).real


def light_the_sea(model, config) -> None:
    """Light the compiled display model so that the waves' slopes read in a still.

    Diffuse light on a slope s (rad) along the sun's bearing varies as sin(e + s) for a sun
    at elevation e: relative to the flat water by about s cot(e), 3.7 s at e = 15 deg, and
    0.5 s for the scene's high sun. So the scene's ``sun`` goes low (:data:`SUN_ELEVATION_DEG`)
    over the bearing the waves come from, where long-crested waves turn their full slope to
    it; the camera's headlight, which lights every slope alike, is dimmed (:data:`HEADLIGHT`);
    the surface is made less see-through (:data:`SEA_ALPHA`), since what shows through it is
    the flat deep water; and its texture's contrast is cut (:data:`TEXTURE_CONTRAST`).
    OpenGL clips the lit colour at 1 before the texture multiplies it: the sea's material
    colour 1/:data:`TEXTURE_GAIN` (and a texture as much brighter, :func:`paint_the_sea`)
    leaves the sunlit slopes that headroom, so that they stay brighter than the flat water.

    Parameters
    ----------
    model : mujoco.MjModel
        The display model, with its ``sun`` light and ``sea`` material.
    config : WaveConfig
        The sea drawn: its ``direction_from`` (compass bearing) places the sun.
    """
    from ..frames import yaw_from_heading

    sun = model.light("sun").id
    towards = yaw_from_heading(config.direction_from + math.pi)  # rad, ENU: where the light goes
    e = math.radians(SUN_ELEVATION_DEG)
    model.light_dir[sun] = (math.cos(e) * math.cos(towards), math.cos(e) * math.sin(towards), -math.sin(e))
    model.light_diffuse[sun] = SUN_DIFFUSE
    model.vis.headlight.ambient[:] = HEADLIGHT[0]
    model.vis.headlight.diffuse[:] = HEADLIGHT[1]
    model.mat_rgba[model.material("sea").id] = (*[1.0 / TEXTURE_GAIN] * 3, SEA_ALPHA)


def paint_the_sea(model, hull_length: float) -> None:
    """The wave texture of a sea: contrast :data:`TEXTURE_CONTRAST`, gain :data:`TEXTURE_GAIN`.

    Parameters
    ----------
    model : mujoco.MjModel
        The display model.
    hull_length : float
        m, the scale of the texture (:func:`sailmujoco.video.water.paint_sea`).
    """
    from .water import paint_sea

    paint_sea(model, hull_length, contrast=TEXTURE_CONTRAST, gain=TEXTURE_GAIN)


class SeaSurface:
    """The moving sea of a compiled display model: heights and placement set per frame.

    Parameters
    ----------
    model : mujoco.MjModel
        The display model, built with :func:`add_sea_surface`.
    config : WaveConfig
        The sea state drawn.
    layout : SeaLayout
        As given to :func:`add_sea_surface`.
    """

    def __init__(self, model, config, layout: SeaLayout):
        self.model, self.config, self.layout = model, config, layout
        self.hfield_id = model.hfield(HFIELD).id
        self.geom_id = model.geom(GEOM).id
        self._far = [model.geom(name).id for name in FAR_GEOMS]
        model.geom_sameframe[[self.geom_id, *self._far]] = 0  # placed each frame, not at the origin
        self._adr = int(model.hfield_adr[self.hfield_id])
        offsets = (np.arange(layout.n) - 0.5 * (layout.n - 1)) * layout.dx
        self.offsets = offsets  # m, grid points from the centre along x (columns) and y (rows)
        edge = (layout.half - np.abs(offsets)) / layout.tile
        fade = 0.5 * (1.0 - np.cos(math.pi * np.clip(edge, 0.0, 1.0)))
        self.window = fade[:, None] * fade[None, :]  # rows (y) x columns (x)
        self.centre = None

    def grid(self) -> tuple[np.ndarray, np.ndarray]:
        """World (X, Y) of the grid points, m, each (n, n): rows along y (south to north),
        columns along x (west to east), as MuJoCo stores a height field."""
        cx, cy = self.centre
        return np.meshgrid(cx + self.offsets, cy + self.offsets, indexing="xy")

    def heights(self) -> np.ndarray:
        """The decoded heights of the stored grid, m above the still water, (n, n)."""
        n, a = self.layout.n, self.layout.amplitude
        h = np.asarray(self.model.hfield_data[self._adr:self._adr + n * n], float).reshape(n, n)
        return 2.0 * a * h - a

    def update(self, time: float, position) -> None:
        """Centre the sea on the tile corner nearest ``position`` and set its heights at ``time``.

        Parameters
        ----------
        time : float
            Simulated time, s.
        position : array_like
            The boat's world position, m (x east, y north).
        """
        layout, m = self.layout, self.model
        self.centre = tuple(layout.tile * np.round(np.asarray(position[:2], float) / layout.tile))
        cx, cy = self.centre
        m.geom_pos[self.geom_id, :2] = self.centre
        for geom, (x, y) in zip(self._far, layout.far_offsets(), strict=True):
            m.geom_pos[geom] = (cx + x, cy + y, 0.0)
        eta = self.window * grid_elevation(self.config, time, cx + self.offsets, cy + self.offsets)
        a = layout.amplitude
        m.hfield_data[self._adr:self._adr + layout.n**2] = ((eta + a) / (2.0 * a)).ravel()

    def upload(self, renderer) -> None:
        """Send the heights to an offscreen ``mujoco.Renderer``'s GL context.

        Parameters
        ----------
        renderer : mujoco.Renderer
            The renderer that draws the display model.
        """
        import mujoco

        renderer._gl_context.make_current()
        mujoco.mjr_uploadHField(self.model, renderer._mjr_context, self.hfield_id)
